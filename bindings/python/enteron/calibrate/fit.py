# SPDX-License-Identifier: Apache-2.0
"""The fit: which constants make the experiment reproduce the data, and how well the data
determines them (docs/calibration.md, "How the fit works").

1. The residuals. For data row i, r_i = (simulated_i - measured_i) / sigma_i, and the cost
   is S = 1/2 sum r_i^2. sigma_i is the row's sigma (data column, or the measurement's
   "sigma" in the experiment); when no sigma is given anywhere, sigma_i = 1 in the
   measurement's unit and the noise level is estimated from the fit (step 4).
2. The global search: CMA-ES (cmaes.py) on the parameters' unit coordinates (0 at the lower
   bound, 1 at the upper one, on each parameter's scale, linear or log), started at the
   scene's own values with a spread of sigma0. A sampled point outside [0, 1] is reflected
   back in (u -> -u, 1 + (1 - u)), so every evaluation respects the bounds and the search
   itself is unbounded. Each generation is one batch of simulations, run in parallel.
3. The local refinement: a trust-region least-squares solver (scipy.optimize.least_squares,
   method "trf", which honours the bounds) from the best point found, with the Jacobian by
   central differences (step 1e-4 in unit coordinates, one-sided at a bound), whose 2p
   simulations run in parallel.
4. The uncertainty, Hessian-based: the Gauss-Newton approximation of the cost's Hessian at
   the optimum, H = J^T J (J = dr/dtheta), gives the covariance of the constants
   Cov = s^2 H^-1, with s^2 = 1 when the sigmas are given, else s^2 = 2 S / (n - p) (the
   residual variance: n data, p constants). The standard deviations are the square roots of
   its diagonal (one standard deviation, 68 % for a Gaussian), the correlations its
   normalised off-diagonal terms. The approximation holds where the simulation is close to
   linear in the constants over +-1 standard deviation: the fit checks it by simulating each
   constant at +-1 standard deviation (the others fixed) and comparing the cost's rise with
   the one H predicts ("linearity", 1 when exact).

Every decision above is made from results in the order they were asked for, never in the
order they arrived, so the fit is bit-identical on any number of workers.
"""
import json
import math
import time

import numpy as np

from . import cache as cache_module
from .cmaes import CMAES
from .experiment import CalibrationError
from .simulate import Plan, Result, evaluate, library_sha256

FINITE_DIFFERENCE_STEP = 1e-4  # in unit coordinates (a fraction of the bounds on each parameter's scale)
_FAILED_RESIDUAL = 1e8          # what a failed simulation's residuals are to the local solver: far worse than any fit


class FitError(RuntimeError):
    """The fit cannot go on (every simulation failed, the workers run another library...)."""


def fold(u):
    """Reflects unit coordinates into [0, 1] (a triangle wave of period 2)."""
    u = np.mod(np.asarray(u, dtype=np.float64), 2.0)
    return np.where(u > 1.0, 2.0 - u, u)


class Objective:
    """The experiment against the data: values -> simulation Result -> residuals and cost,
    each simulation computed once (memory, then the disk cache) and run through the engine."""

    def __init__(self, experiment, data, engine, cache_directory=None):
        self.experiment = experiment
        self.data = data
        self.engine = engine
        self.plan = Plan(experiment, data.requests())
        self.sigmas = data.sigmas if data.sigmas is not None else np.ones(len(data))
        self.library = library_sha256()
        requests = json.dumps(data.requests(), separators=(",", ":"))
        self._key_prefix = (experiment.identity(), self.library, requests)
        self.cache = cache_module.DiskCache(cache_directory)
        self.memory = {}
        self.computed = 0
        self.failed = 0

    # ---- the store the engine looks results up in ------------------------------------------
    def _record_key(self, values):
        return cache_module.key(*self._key_prefix, np.asarray(values, dtype="<f8").tobytes())

    def lookup(self, values):
        bits = np.asarray(values, dtype="<f8").tobytes()
        if bits in self.memory:
            return self.memory[bits]
        record = self.cache.get(self._record_key(values))
        if record is None:
            return None
        result = Result.from_bytes(record, self.library)
        self.memory[bits] = result
        return result

    def save(self, values, result):
        if result.library_sha256 != self.library:
            raise FitError("a worker computed with another libenteron (sha256 %s; this process: %s): its results "
                           "would not be bit-identical" % (result.library_sha256, self.library))
        self.memory[np.asarray(values, dtype="<f8").tobytes()] = result
        self.cache.put(self._record_key(values), result.to_bytes())
        self.computed += 1
        self.failed += result.failure is not None

    # ---- evaluations -------------------------------------------------------------------------
    def values_of(self, u):
        return np.array([p.from_unit(float(x)) for p, x in zip(self.experiment.parameters, u)])

    def run(self, unit_points, label):
        """Results for a batch of points in unit coordinates, in order."""
        values = [self.values_of(u) for u in unit_points]
        return self.engine.map(evaluate, self.plan, values, store=self, label=label)

    def residuals(self, result):
        if result.failure is not None:
            return None
        return (result.predictions - self.data.values) / self.sigmas

    def cost(self, result):
        r = self.residuals(result)
        return math.inf if r is None else 0.5 * float(r @ r)


def _global_search(objective, options, log):
    parameters = objective.experiment.parameters
    start = np.array([p.to_unit(p.start) for p in parameters])
    search = CMAES(start, options["sigma0"], seed=options["seed"], population=options["population"],
                   max_evaluations=options["max_evaluations"], tolerance_x=options["tolerance"])
    first_failure = None
    while search.stop() is None:
        samples = search.ask()
        results = objective.run(fold(samples), "global search, generation %d" % (search.generations + 1))
        costs = [objective.cost(result) for result in results]
        if first_failure is None:
            first_failure = next((r.failure for r in results if r.failure is not None), None)
        if search.generations == 0 and not any(math.isfinite(c) for c in costs):
            raise FitError("every simulation of the first generation failed; the first: %s" % first_failure)
        search.tell(samples, costs)
    log("global search: %d generations, %d simulations (population %d), stopped by %s; best cost %.6g"
        % (search.generations, search.evaluations, search.population, search.stop(), search.best[0]))
    return fold(search.best[1]), search


def _jacobian(objective, u, label):
    """dr/du by central differences (one-sided at a bound): 2 simulations per parameter, in parallel."""
    points, steps = [], []
    for j in range(len(u)):
        up, down = u.copy(), u.copy()
        up[j] = min(1.0, u[j] + FINITE_DIFFERENCE_STEP)
        down[j] = max(0.0, u[j] - FINITE_DIFFERENCE_STEP)
        points += [up, down]
        steps.append(up[j] - down[j])
    results = objective.run(points, label)
    columns = []
    for j in range(len(u)):
        r_up, r_down = objective.residuals(results[2 * j]), objective.residuals(results[2 * j + 1])
        if r_up is None or r_down is None:
            failure = results[2 * j].failure or results[2 * j + 1].failure
            raise FitError("a simulation next to the optimum failed (parameter %s): %s"
                           % (objective.experiment.parameters[j].name, failure))
        columns.append((r_up - r_down) / steps[j])
    return np.column_stack(columns)


def _local_refinement(objective, u0, log):
    from scipy.optimize import least_squares

    def residuals(u):
        r = objective.residuals(objective.run([u], "local refinement")[0])
        return np.full(len(objective.data), _FAILED_RESIDUAL) if r is None else r

    solution = least_squares(residuals, u0, jac=lambda u: _jacobian(objective, u, "local refinement, Jacobian"),
                             bounds=(0.0, 1.0), method="trf", xtol=1e-10, ftol=1e-12, gtol=1e-12, max_nfev=60)
    log("local refinement: %s (%d residual and %d Jacobian evaluations); cost %.6g"
        % (solution.message, solution.nfev, solution.njev, solution.cost))
    return np.clip(solution.x, 0.0, 1.0), solution


class FitResult:
    """What a fit found. parameters: one dict per constant (name, path, value, std (one
    standard deviation, same unit), relative_std, lower, upper, start, at_bound, linearity);
    covariance and correlation (p x p numpy arrays); cost (1/2 sum r^2), chi2 (2 cost),
    data (n), dof (n - p), noise ("given" or "estimated"), noise_scale (s), residuals_rms (per
    measurement, in its unit); simulations (computed, from_cache, failed), global_search and
    local_refinement (what they did); scene (the experiment's scene with the fitted values);
    engine (where it ran) and wall_s."""

    def __init__(self, **fields):
        self.__dict__.update(fields)

    def values(self):
        return np.array([p["value"] for p in self.parameters])

    def to_dict(self):
        out = dict(self.__dict__)
        out["covariance"] = self.covariance.tolist()
        out["correlation"] = self.correlation.tolist()
        return out

    def table(self):
        """The result as text: one line per constant, then the residual."""
        lines = ["%-34s %14s %12s %9s   %s" % ("constant", "value", "std", "rel. std", "bounds")]
        for p in self.parameters:
            note = "  at its %s bound" % p["at_bound"] if p["at_bound"] else ""
            lines.append("%-34s %14.6g %12.3g %8.2f %%   [%g, %g]%s" % (p["name"], p["value"], p["std"],
                                                                           100 * p["relative_std"], p["lower"],
                                                                           p["upper"], note))
        lines.append("cost %.6g (chi2 %.6g over %d data, %d dof; noise %s, s = %.4g)" % (
            self.cost, self.chi2, self.data, self.dof, self.noise, self.noise_scale))
        for name, rms in self.residuals_rms.items():
            lines.append("  residual RMS of %-20s %.4g %s" % (name, rms["rms"], rms["unit"]))
        return "\n".join(lines)


def _uncertainty(objective, u, cost, log):
    """Covariance in the constants' units from the Gauss-Newton Hessian at u (module's step 4)."""
    parameters = objective.experiment.parameters
    n, p = len(objective.data), len(parameters)
    J = _jacobian(objective, u, "uncertainty, Jacobian")
    values = objective.values_of(u)
    chain = np.array([q.value_per_unit(v) for q, v in zip(parameters, values)])  # d value / d u
    J_values = J / chain                                                          # dr / d value
    H = J_values.T @ J_values
    if objective.data.sigmas is not None:
        noise, s2 = "given", 1.0
    else:
        noise, s2 = "estimated", (2.0 * cost / (n - p) if n > p else math.inf)
    eigenvalues, eigenvectors = np.linalg.eigh(H)
    if eigenvalues.min() <= 1e-12 * max(eigenvalues.max(), 1e-300):
        weakest = np.argmax(np.abs(eigenvectors[:, 0]))
        log("uncertainty: the data barely determine %s (the Hessian is singular along it): its standard deviation "
            "is infinite" % parameters[weakest].name)
        covariance = np.full((p, p), math.inf)
        covariance_u = covariance
    else:
        covariance = s2 * np.linalg.inv(H)
        covariance_u = covariance / np.outer(chain, chain)
    std = np.sqrt(np.abs(np.diag(covariance)))
    with np.errstate(invalid="ignore", divide="ignore"):
        correlation = covariance / np.outer(std, std)
    return covariance, correlation, std, np.sqrt(np.abs(np.diag(covariance_u))), H, chain, noise, s2


def _linearity(objective, u, cost, std_u, H, chain):
    """For each constant, the cost's rise at +-1 standard deviation (others fixed) over the
    rise the Gauss-Newton Hessian predicts: near 1 when the Hessian-based uncertainty holds."""
    points, predicted = [], []
    for j, step in enumerate(std_u):
        if not math.isfinite(step) or step <= 0:
            points += [u, u]
            predicted.append(math.nan)
            continue
        up, down = u.copy(), u.copy()
        up[j], down[j] = min(1.0, u[j] + step), max(0.0, u[j] - step)
        points += [up, down]
        predicted.append(0.5 * H[j, j] * (step * chain[j]) ** 2)
    results = objective.run(points, "uncertainty, linearity check")
    ratios = []
    for j, expected in enumerate(predicted):
        rises = [objective.cost(results[2 * j + k]) - cost for k in (0, 1)]
        ratios.append(float(np.mean(rises) / expected) if expected and math.isfinite(expected) else math.nan)
    return ratios


def fit(experiment, data, engine, cache_directory=None, log=None, **overrides):
    """Fits experiment.parameters to data on engine (an Engine; workers=0 for this process).
    overrides: seed, max_evaluations, population, sigma0, local, tolerance (else the
    experiment's "fit" object, else FIT_DEFAULTS). Returns a FitResult."""
    log = log or (lambda text: None)
    options = dict(experiment.fit_options)
    for key, value in overrides.items():
        if key not in options:
            raise CalibrationError("unknown fit option %r (expected one of: %s)" % (key, ", ".join(options)))
        if value is not None:
            options[key] = value
    started = time.monotonic()
    objective = Objective(experiment, data, engine, cache_directory)
    u, search = _global_search(objective, options, log)
    refinement = None
    if options["local"]:
        u, solution = _local_refinement(objective, u, log)
        refinement = {"message": solution.message, "residual_evaluations": int(solution.nfev),
                      "jacobian_evaluations": int(solution.njev or 0)}
    best = objective.run([u], "optimum")[0]
    if best.failure is not None:
        raise FitError("the simulation at the optimum failed: %s" % best.failure)
    cost = objective.cost(best)
    covariance, correlation, std, std_u, H, chain, noise, s2 = _uncertainty(objective, u, cost, log)
    linearity = _linearity(objective, u, cost, std_u, H, chain)
    values = objective.values_of(u)
    parameters = []
    for j, parameter in enumerate(experiment.parameters):
        at_bound = "lower" if u[j] <= 1e-6 else "upper" if u[j] >= 1 - 1e-6 else ""
        parameters.append({"name": parameter.name, "path": parameter.path, "value": float(values[j]),
                           "std": float(std[j]), "relative_std": float(std[j] / abs(values[j])) if values[j] else math.inf,
                           "lower": parameter.lower, "upper": parameter.upper, "scale": parameter.scale,
                           "start": parameter.start, "at_bound": at_bound, "linearity": linearity[j]})
    residuals = best.predictions - data.values
    rms = {}
    for name in experiment.measurements:
        mask = np.array([n == name for n in data.names])
        if mask.any():
            rms[name] = {"rms": float(np.sqrt(np.mean(residuals[mask] ** 2))), "unit": experiment.measurements[name].unit,
                         "data": int(mask.sum())}
    n, p = len(data), len(parameters)
    return FitResult(
        experiment=experiment.name, parameters=parameters, covariance=covariance, correlation=correlation,
        cost=cost, chi2=2 * cost, data=n, dof=n - p, noise=noise, noise_scale=math.sqrt(s2),
        residuals_rms=rms, predictions=best.predictions.tolist(),
        simulations={"computed": objective.computed, "from_cache": objective.cache.hits, "failed": objective.failed},
        global_search={"generations": search.generations, "simulations": search.evaluations,
                       "population": search.population, "stopped_by": search.stop(), "seed": options["seed"]},
        local_refinement=refinement, scene=experiment.scene_with(values), engine=engine.description,
        wall_s=time.monotonic() - started, options=options)
