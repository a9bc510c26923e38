# SPDX-License-Identifier: Apache-2.0
"""CMA-ES, the covariance matrix adaptation evolution strategy: the derivative-free global
search of a fit. The (mu/mu_w, lambda)-CMA-ES with rank-one and rank-mu updates and
cumulative step-size adaptation, as in N. Hansen, "The CMA Evolution Strategy: A Tutorial"
(arXiv:1604.00772, 2016), section "Algorithm Summary", with its default constants; the
comments below name each of its steps.

    search = CMAES(mean, sigma, seed=1)
    while not search.stop():
        candidates = search.ask()                 # population x dimension
        search.tell(candidates, [f(x) for x in candidates])

Deterministic: the samples come from numpy's PCG64 seeded with `seed`, the ranking is a
stable sort (ties keep the candidates' order), and nothing depends on when or where the
fitnesses were computed. A failed evaluation is +inf: it ranks last.

Two choices of ours: the population is at least 6 (the tutorial's 4 + 3 ln n gives 4 for
one parameter, which makes one-dimensional searches erratic); and the search works in an
unbounded space whose points the caller folds into the box (calibrate.fit: reflection at
the bounds), so CMA-ES itself has no bounds to handle.
"""
import math

import numpy as np


class CMAES:
    def __init__(self, mean, sigma, seed=1, population=0, max_evaluations=1000, tolerance_x=1e-3):
        self.mean = np.array(mean, dtype=np.float64)
        n = self.dimension = len(self.mean)
        self.sigma = float(sigma)
        self.random = np.random.Generator(np.random.PCG64(seed))
        self.population = population or max(6, 4 + int(3 * math.log(n)))
        self.max_evaluations = max_evaluations
        self.tolerance_x = tolerance_x
        # Selection and recombination: positive weights of the mu best.
        mu = self.mu = self.population // 2
        weights = math.log(mu + 0.5) - np.log(np.arange(1, mu + 1))
        self.weights = weights / weights.sum()
        self.mu_eff = 1.0 / np.sum(self.weights ** 2)
        # Step-size control (tutorial's defaults).
        self.c_sigma = (self.mu_eff + 2) / (n + self.mu_eff + 5)
        self.d_sigma = 1 + 2 * max(0.0, math.sqrt((self.mu_eff - 1) / (n + 1)) - 1) + self.c_sigma
        # Covariance matrix adaptation.
        self.c_c = (4 + self.mu_eff / n) / (n + 4 + 2 * self.mu_eff / n)
        self.c_1 = 2 / ((n + 1.3) ** 2 + self.mu_eff)
        self.c_mu = min(1 - self.c_1, 2 * (self.mu_eff - 2 + 1 / self.mu_eff) / ((n + 2) ** 2 + self.mu_eff))
        self.expected_norm = math.sqrt(n) * (1 - 1 / (4 * n) + 1 / (21 * n * n))  # E|N(0, I)|
        self.p_sigma = np.zeros(n)
        self.p_c = np.zeros(n)
        self.C = np.eye(n)
        self.B = np.eye(n)
        self.D = np.ones(n)
        self.evaluations = 0
        self.generations = 0
        self.best = (math.inf, self.mean.copy())
        self.history = []  # best fitness of each generation
        self._stop = None

    def ask(self):
        """The next population: population x dimension points, x = m + sigma B D z, z ~ N(0, I)."""
        z = self.random.standard_normal((self.population, self.dimension))
        return self.mean + self.sigma * (z * self.D) @ self.B.T

    def tell(self, candidates, fitnesses):
        candidates = np.asarray(candidates, dtype=np.float64)
        fitnesses = np.asarray(fitnesses, dtype=np.float64)
        n = self.dimension
        self.evaluations += len(fitnesses)
        self.generations += 1
        order = np.argsort(fitnesses, kind="stable")
        if fitnesses[order[0]] < self.best[0]:
            self.best = (float(fitnesses[order[0]]), candidates[order[0]].copy())
        self.history.append(float(fitnesses[order[0]]))
        selected = candidates[order[:self.mu]]
        old_mean = self.mean
        self.mean = self.weights @ selected  # selection and recombination
        y_w = (self.mean - old_mean) / self.sigma
        inverse_sqrt_C = self.B @ np.diag(1 / self.D) @ self.B.T
        self.p_sigma = ((1 - self.c_sigma) * self.p_sigma
                        + math.sqrt(self.c_sigma * (2 - self.c_sigma) * self.mu_eff) * inverse_sqrt_C @ y_w)  # the step-size's evolution path
        norm_p_sigma = np.linalg.norm(self.p_sigma)
        h_sigma = (norm_p_sigma / math.sqrt(1 - (1 - self.c_sigma) ** (2 * self.generations))
                   < (1.4 + 2 / (n + 1)) * self.expected_norm)
        # the covariance's evolution path, stalled while the step size is growing (h_sigma)
        self.p_c = (1 - self.c_c) * self.p_c + h_sigma * math.sqrt(self.c_c * (2 - self.c_c) * self.mu_eff) * y_w
        steps = (selected - old_mean) / self.sigma
        delta_h = (1 - h_sigma) * self.c_c * (2 - self.c_c)
        self.C = ((1 - self.c_1 - self.c_mu) * self.C
                  + self.c_1 * (np.outer(self.p_c, self.p_c) + delta_h * self.C)
                  + self.c_mu * (steps.T * self.weights) @ steps)  # rank-one and rank-mu updates
        self.sigma *= math.exp((self.c_sigma / self.d_sigma) * (norm_p_sigma / self.expected_norm - 1))  # step size
        self.C = 0.5 * (self.C + self.C.T)
        eigenvalues, self.B = np.linalg.eigh(self.C)
        self.D = np.sqrt(np.maximum(eigenvalues, 1e-300))
        self._stop = self._stopping_reason(fitnesses)

    def _stopping_reason(self, fitnesses):
        if self.evaluations >= self.max_evaluations:
            return "max_evaluations (%d)" % self.max_evaluations
        if self.sigma * self.D.max() < self.tolerance_x:
            return "tolerance_x: the search's spread is below %g of the bounds" % self.tolerance_x
        finite = fitnesses[np.isfinite(fitnesses)]
        window = 10 + int(math.ceil(30 * self.dimension / self.population))
        if len(self.history) >= window and finite.size:
            recent = self.history[-window:] + list(finite)
            if max(recent) - min(recent) <= 1e-12 * max(abs(min(recent)), 1e-300):
                return "tolerance_f: the fitness no longer changes"
        if self.D.max() > 1e7 * self.D.min():
            return "condition: the covariance matrix is degenerate (a parameter the data does not determine?)"
        return None

    def stop(self):
        """None while the search goes on, else why it stopped."""
        return self._stop
