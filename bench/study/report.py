#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Turns the CSV files of enteron_study into plots, markdown tables and checks.

    report.py RESULTS_DIR [--check] [--doc docs/accuracy.md] [--peers PEERS_CSV]

Reads RESULTS_DIR/*.csv (written by bench/study/enteron_study), writes RESULTS_DIR/*.png
and RESULTS_DIR/study.md. With --check it asserts what the study must show (the reference
is converged, observed orders are near the expected ones, errors fall with resolution,
absent effects never run, ...) and exits 1 naming every failed check. With --doc it
replaces the block between the markers `<!-- study:begin -->` and `<!-- study:end -->` of
that markdown file (the project's docs/accuracy.md) with the main table and the plots.

Peers (the MuJoCo rope of bench/peers, written by the study's peers part): a CSV
`peers.csv` in RESULTS_DIR (or --peers) with the columns
    peer, scene, sweep, integrator, control_points, timestep_s, t_s, us_per_ms, finite,
    steps_timed, build_s, status, axis_xyz_m
(only peer, scene, control_points, timestep_s, t_s, us_per_ms, finite and axis_xyz_m are
required) where axis_xyz_m is 201 points evenly spaced in arc length, "x y z x y z ..."
separated by spaces, or empty when the run did not reach t_s. It is compared with the
study's reference axes (mechanics_reference_axes.csv), with the same metric as ours, and
shown next to our own error and cost on the same scene, N and time step.
"""
import argparse
import csv
import math
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

INTEGRATORS = ("rk4", "symplectic_euler", "implicit_euler", "bdf2")
EXPECTED_TIME_ORDER = {"rk4": 4.0, "symplectic_euler": 1.0, "implicit_euler": 1.0, "bdf2": 2.0}
# Catmull-Rom interpolation reproduces quadratics: the axis converges as O(l^2) or better
# asymptotically; the stiff stretching (nearly inextensible) slows it before that, so the
# check accepts from 1 up (measured about 1.2 to 1.7 on the swing between N = 60 and 960).
EXPECTED_SPACE_ORDER = 2.0
SMOOTH_SCENES = ("swing", "sag")  # the drop has penalty contacts: no smooth order
BOWEL_LENGTH_M = 6.0  # of the mechanics scenes (bench/study/mechanics_scenes.h)
PEER_LABELS = {"mujoco_rope": "MuJoCo rope (Euler)", "mujoco_rope_rigid": "MuJoCo rope, rigid segments"}
# A peer that ran the swing to the end with N >= 30 and a step <= 1 ms must be within this of
# the reference (measured: about 1 cm at N = 30, t = 2 s); farther, the scenes differ (the
# rigid rope, which cannot stretch, is 0.3 m off).
PEER_ERROR_BOUND_M = 0.05
# What the library does by default (JSON and C): the settings marked in the tables.
DEFAULTS = {
    "integrator": "implicit_euler",
    "timestep_s": 1e-3,
    "control_points": 240,
    "sphere_spacing_radii": 0.5,
    "contact_stiffness_N_per_m": 500.0,
    "skin": ("convolution", "default"),
}


def source_version():
    """The commit the study was run from, and whether the tree had uncommitted changes."""
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        commit = subprocess.run(["git", "-C", here, "rev-parse", "--short", "HEAD"], capture_output=True,
                                text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", here, "status", "--porcelain", "--untracked-files=no", "--", ":/lib",
                                ":/include", ":/bench/study"], capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "an unknown commit"
    return f"commit {commit}" + (" with uncommitted changes" if dirty else "")


def read(path):
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        for key, value in row.items():
            try:
                row[key] = float(value)
            except (TypeError, ValueError):
                pass
    return rows


def fit_order(xs, ys):
    """Least-squares slope of log y against log x, over positive finite pairs."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys)
           if x > 0 and y > 0 and math.isfinite(x) and math.isfinite(y)]
    if len(pts) < 2:
        return float("nan")
    n = len(pts)
    sx = sum(p[0] for p in pts)
    sy = sum(p[1] for p in pts)
    sxx = sum(p[0] ** 2 for p in pts)
    sxy = sum(p[0] * p[1] for p in pts)
    return (n * sxy - sx * sy) / (n * sxx - sx * sx)


def rms_distance(a, b):
    """RMS distance between two axes given as flat x y z lists of the same length (NaN if not)."""
    if not a or not b or len(a) != len(b):
        return float("nan")
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)) / (len(a) / 3))


def pareto(points, *objectives):
    """Indices of the points that no other point beats on every objective (all minimised)."""
    def values(p):
        return [f(p) for f in objectives]

    def finite(p):
        return all(math.isfinite(v) for v in values(p))

    front = []
    for i, p in enumerate(points):
        if not finite(p):
            continue
        vp = values(p)
        dominated = any(j != i and finite(q) and all(a <= b for a, b in zip(values(q), vp)) and values(q) != vp
                        for j, q in enumerate(points))
        if not dominated:
            front.append(i)
    return front


def finish_axes(ax, xlabel, ylabel, title):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)


def draw_front_and_default(ax, points, front, x, y, is_default):
    """The Pareto front as a line and the library's default as a red star."""
    line = sorted((points[i] for i in front), key=x)
    ax.plot([x(r) for r in line], [y(r) for r in line], "k-", lw=1, label="Pareto front")
    for r in points:
        if is_default(r):
            ax.plot([x(r)], [y(r)], "r*", ms=14, label="library default")


def g(value, digits=3):
    if isinstance(value, str):
        return value
    if value is None or not math.isfinite(value):
        return "-"
    if value == 0:
        return "0"
    return f"{value:.{digits}g}"


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


class Report:
    def __init__(self, directory):
        self.dir = directory
        self.md = []          # study.md, section by section
        self.main_rows = []   # the main table (docs/accuracy.md)
        self.doc_notes = []
        self.failures = []
        self.notes = []       # findings to report that are not checks
        self.plots = []
        self.run = (read(os.path.join(directory, "study_run.csv")) or [{}])[0]
        self.source = source_version()
        self.peer_rows = []   # peers.csv with error_m, loaded by load_peers

    def load_peers(self, path):
        """Reads the peers' runs and measures each axis against the reference, as ours."""
        self.peers_path = path
        self.peer_rows = (read(path) if path else None) or []
        ref = {}
        for r in read(os.path.join(self.dir, "mechanics_reference_axes.csv")) or []:
            ref.setdefault((r["scene"], r["t_s"]), []).extend([r["x_m"], r["y_m"], r["z_m"]])
        for p in self.peer_rows:
            p["axis"] = [float(v) for v in str(p.get("axis_xyz_m") or "").split()]
            p["error_m"] = rms_distance(p["axis"], ref.get((p["scene"], p["t_s"])))
            p.setdefault("sweep", "N" if p["timestep_s"] == 1e-3 else "dt")
            p.setdefault("status", "ok" if p["axis"] else "no axis")

    def expect(self, condition, message):
        if not condition:
            self.failures.append(message)

    def save(self, fig, name, caption):
        path = os.path.join(self.dir, name)
        fig.tight_layout()
        fig.savefig(path, dpi=90)
        plt.close(fig)
        self.plots.append((name, caption))

    # ---------------------------------------------------------------- mechanics
    def mechanics(self):
        rows = read(os.path.join(self.dir, "mechanics.csv"))
        refs = read(os.path.join(self.dir, "mechanics_reference.csv"))
        if rows is None:
            return
        scenes = list(dict.fromkeys(r["scene"] for r in rows))
        times = sorted(set(r["t_s"] for r in rows))
        last = times[-1]
        self.md.append("## Mechanics\n")
        self.md.append(
            "Error: RMS distance between the axis and the reference's, both sampled at 201 points "
            "evenly spaced in arc length, in m and relative to the 6 m length. Cost: median wall time "
            "of `ent_scene_step` per 1 ms simulated (what a 1 kHz loop pays). Substep: simulated time / "
            "substeps; the explicit integrators never exceed their stability limit, whatever the time "
            "step asked.\n")

        # The reference and its self-convergence.
        ref_rows = []
        for r in refs or []:
            ref_rows.append([r["scene"], g(r["t_s"]), r["reference"], r["compared_with"].replace("_", " "),
                             g(r["difference_m"]), g(r["difference_rel"]), g(r["reference_wall_s"], 3)])
        self.md.append("### The reference\n")
        self.md.append(table(["scene", "t (s)", "reference", "compared with", "difference (m)",
                              "relative", "reference wall time (s)"], ref_rows) + "\n")

        # What the reference itself may be off by: the larger of its two self-differences.
        self.uncertainty = {}
        for r in refs or []:
            key = (r["scene"], r["t_s"])
            self.uncertainty[key] = max(self.uncertainty.get(key, 0.0), r["difference_m"])
        self.md.append("Errors below the reference's uncertainty (the larger of its two differences above) "
                       "are marked \"< ref\": the reference cannot rank them.\n")

        # Orders.
        space_orders, time_orders = {}, {}
        for scene in scenes:
            for t in times:
                fine = sorted((r for r in rows if r["scene"] == scene and r["sweep"] == "N_fine_dt"
                               and r["t_s"] == t), key=lambda r: r["control_points"])
                ns = [r["control_points"] for r in fine]
                diffs = [r["next_difference_m"] for r in fine]
                space_orders[(scene, t)] = -fit_order(ns, diffs)
                for integrator in INTEGRATORS:
                    dt = [r for r in rows if r["scene"] == scene and r["sweep"] == "dt" and r["t_s"] == t
                          and r["integrator"] == integrator and r["timestep_s"] > 0]
                    # Only the substeps actually taken as asked (not capped by stability), and
                    # errors above round-off (1e-12 m; the reference moves by about 1e-13 m when its own step is halved).
                    # The four smallest: an order is what the error does as the step goes to 0
                    # (at large steps the error saturates at the size of the motion).
                    usable = sorted((r for r in dt if abs(r["substep_s"] - r["timestep_s"]) <= 1e-9 * r["timestep_s"]
                                     and r["time_error_m"] > 1e-12), key=lambda r: r["substep_s"])[:4]
                    time_orders[(scene, t, integrator)] = (
                        fit_order([r["substep_s"] for r in usable], [r["time_error_m"] for r in usable]),
                        len(usable))
        order_rows = []
        for scene in scenes:
            for t in times:
                cells = [scene, g(t), f"{g(space_orders[(scene, t)], 2)} ({g(EXPECTED_SPACE_ORDER, 1)})"]
                for integrator in INTEGRATORS:
                    order, count = time_orders[(scene, t, integrator)]
                    cells.append(f"{g(order, 2)} ({g(EXPECTED_TIME_ORDER[integrator], 1)}; {count} steps)")
                order_rows.append(cells)
        self.md.append("### Observed convergence orders (expected in brackets)\n")
        self.md.append(
            "Space: slope of the distance between N and 2N control points (rk4 at the reference's time "
            "step) against N, so the reference plays no part. Time: slope of the distance to rk4 at the "
            "reference's time step with the same N, against the substep, over the time steps the "
            "integrator actually took (an explicit one caps its substep at its stability limit), the four "
            "smallest (at large steps the error saturates at the size of the motion). The "
            "drop has penalty contacts, which are not smooth: its orders are shown, not expected.\n")
        self.md.append(table(["scene", "t (s)", "space (N)", "rk4", "symplectic Euler", "implicit Euler"],
                             order_rows) + "\n")

        # Checks: the reference is converged, orders near the expected ones, errors fall with N.
        for r in refs or []:
            if r["compared_with"] == "half_dt":
                half_n = [q for q in refs if q["scene"] == r["scene"] and q["t_s"] == r["t_s"]
                          and q["compared_with"] == "half_N"][0]
                # Smooth scenes: the reference's time error must be negligible. The drop's penalty
                # contacts make every integrator about first order in time near impacts: there
                # its time error need only stay below its spatial one.
                share = 0.1 if r["scene"] in SMOOTH_SCENES else 0.5
                self.expect(r["difference_m"] <= max(share * half_n["difference_m"], 1e-9),
                            f"reference {r['scene']} t={r['t_s']}: halving its time step moves it by "
                            f"{r['difference_m']:.3g} m, more than {share} x the {half_n['difference_m']:.3g} m "
                            f"of halving N")
        for scene in SMOOTH_SCENES:
            if scene not in scenes:
                continue
            for t in times:
                p = space_orders[(scene, t)]
                self.expect(1.0 <= p <= 3.5, f"{scene} t={t}: spatial order {p:.3g} outside [1.0, 3.5]")
                fine = sorted((r for r in rows if r["scene"] == scene and r["sweep"] == "N_fine_dt"
                               and r["t_s"] == t), key=lambda r: r["control_points"])
                errors = [r["error_m"] for r in fine]
                self.expect(all(b < a for a, b in zip(errors, errors[1:])),
                            f"{scene} t={t}: the error does not fall as N grows: {errors}")
                for integrator in INTEGRATORS:
                    order, count = time_orders[(scene, t, integrator)]
                    expected = EXPECTED_TIME_ORDER[integrator]
                    band = 0.5 if expected > 2 else 0.25
                    self.expect(count >= 2 and abs(order - expected) <= band,
                                f"{scene} t={t} {integrator}: time order {order:.3g} from {count} steps, "
                                f"expected {expected} +- {band}")
        self.expect(all(r["status"] == "ok" for r in rows),
                    "failed mechanics runs: " + "; ".join(
                        f"{r['scene']} {r['integrator']} N={r['control_points']:.0f} dt={r['timestep_s']}: "
                        f"{r['status']}" for r in rows if r["status"] != "ok"))

        # Tables per scene at the last time: N sweep and dt sweep, with the Pareto front.
        for scene in scenes:
            pts = [r for r in rows if r["scene"] == scene and r["t_s"] == last and r["sweep"] in ("N", "dt")
                   and not r["at_reference_N"]]
            # The same setting may be in both sweeps (N = dt sweep's N, 1 ms): keep one.
            unique = {}
            for r in pts:
                unique.setdefault((r["integrator"], r["control_points"], r["timestep_s"]), r)
            pts = list(unique.values())
            front = set(pareto(pts, lambda r: r["us_per_ms"], lambda r: r["error_m"]))
            for i, r in enumerate(pts):
                r["front"] = i in front
            self.md.append(f"### {scene}: every setting at t = {g(last)} s (front: on the Pareto front)\n")
            out = []
            for r in sorted(pts, key=lambda r: (INTEGRATORS.index(r["integrator"]), r["control_points"],
                                                r["timestep_s"])):
                unresolved = r["error_m"] < self.uncertainty.get((scene, last), 0.0)
                out.append([r["integrator"], g(r["control_points"]), g(r["timestep_s"]), g(r["substep_s"]),
                            g(r["error_m"]) + (" (< ref)" if unresolved else ""), g(r["error_rel"]), g(r["us_per_ms"]),
                            "front" if r["front"] else "", self.is_default(r)])
            self.md.append(table(["integrator", "N", "time step (s)", "substep (s)", "error (m)", "relative",
                                  "us per 1 ms", "front", "default"], out) + "\n")

        # Main table rows: the swing (or the first scene), at the last time.
        scene = "swing" if "swing" in scenes else scenes[0]
        pts = [r for r in rows if r["scene"] == scene and r["t_s"] == last]
        front_keys = set()
        allpts = {}
        for r in pts:
            if r["sweep"] in ("N", "dt") and not r["at_reference_N"]:
                allpts.setdefault((r["integrator"], r["control_points"], r["timestep_s"]), r)
        allpts_list = list(allpts.values())
        for i in pareto(allpts_list, lambda r: r["us_per_ms"], lambda r: r["error_m"]):
            r = allpts_list[i]
            front_keys.add((r["integrator"], r["control_points"], r["timestep_s"]))
        dt_n = max((r["control_points"] for r in pts if r["sweep"] == "dt"), default=None)

        def add(knob, setting, r):
            key = (r["integrator"], r["control_points"], r["timestep_s"])
            error = f"{g(r['error_m'])} m ({g(r['error_rel'])} L)"
            if r["at_reference_N"]:
                error += ", time error only (N of the reference)"
            self.main_rows.append([f"mechanics ({scene}, t = {g(last)} s)", knob, setting, error, f"{g(r['us_per_ms'])} us/ms",
                                   "front" if key in front_keys else "", self.is_default(r)])

        for r in sorted((r for r in pts if r["sweep"] == "N" and r["integrator"] == DEFAULTS["integrator"]),
                        key=lambda r: r["control_points"]):
            add("control points N (implicit Euler, 1 ms)", g(r["control_points"]), r)
        for integrator in INTEGRATORS:
            for r in pts:
                if r["sweep"] == "dt" and r["integrator"] == integrator and r["timestep_s"] == 1e-3:
                    add(f"integrator (N = {g(dt_n)}, 1 ms)", integrator, r)
        for r in sorted((r for r in pts if r["sweep"] == "dt" and r["integrator"] == DEFAULTS["integrator"]),
                        key=lambda r: r["timestep_s"]):
            add(f"time step (implicit Euler, N = {g(dt_n)})", f"{g(r['timestep_s'])} s", r)

        # Plots: error against N, time error against substep, error against cost.
        fig, axes = plt.subplots(1, len(scenes), figsize=(5 * len(scenes), 4), squeeze=False)
        for ax, scene in zip(axes[0], scenes):
            for integrator, style in zip(INTEGRATORS, ("o-", "s-", "^-", "d-")):
                sel = sorted((r for r in rows if r["scene"] == scene and r["t_s"] == last and r["sweep"] == "N"
                              and r["integrator"] == integrator), key=lambda r: r["control_points"])
                ax.loglog([r["control_points"] for r in sel], [r["error_rel"] for r in sel], style,
                          label=f"{integrator}, 1 ms")
            sel = sorted((r for r in rows if r["scene"] == scene and r["t_s"] == last
                          and r["sweep"] == "N_fine_dt"), key=lambda r: r["control_points"])
            ax.loglog([r["control_points"] for r in sel], [r["error_rel"] for r in sel], "k--",
                      label="rk4, reference step")
            self.draw_peers(ax, scene, last, lambda p: p["control_points"], sweeps=("N",))
            finish_axes(ax, "control points N", "RMS axis error / length", f"{scene}, t = {g(last)} s")
        self.save(fig, "mechanics_error_vs_N.png", "Mechanics: error against control points")

        fig, axes = plt.subplots(1, len(scenes), figsize=(5 * len(scenes), 4), squeeze=False)
        for ax, scene in zip(axes[0], scenes):
            for integrator, style in zip(INTEGRATORS, ("o-", "s-", "^-", "d-")):
                sel = sorted((r for r in rows if r["scene"] == scene and r["t_s"] == last and r["sweep"] == "dt"
                              and r["integrator"] == integrator and r["time_error_m"] > 0),
                             key=lambda r: r["timestep_s"])
                ax.loglog([r["substep_s"] for r in sel], [r["time_error_m"] for r in sel], style,
                          label=integrator)
            finish_axes(ax, "substep actually taken (s)", "time error (m), vs rk4 at the reference step",
                        f"{scene}, t = {g(last)} s, N = {g(dt_n)}")
        self.save(fig, "mechanics_time_error_vs_substep.png", "Mechanics: time error against the substep")

        fig, axes = plt.subplots(1, len(scenes), figsize=(5 * len(scenes), 4), squeeze=False)
        for ax, scene in zip(axes[0], scenes):
            unique = {}
            for r in rows:
                if r["scene"] == scene and r["t_s"] == last and r["sweep"] in ("N", "dt") and not r["at_reference_N"]:
                    unique.setdefault((r["integrator"], r["control_points"], r["timestep_s"]), r)
            pts = list(unique.values())
            for integrator, marker in zip(INTEGRATORS, ("o", "s", "^", "d")):
                sel = [r for r in pts if r["integrator"] == integrator]
                ax.loglog([r["us_per_ms"] for r in sel], [r["error_rel"] for r in sel], marker, alpha=0.6,
                          label=integrator)
            draw_front_and_default(ax, pts, pareto(pts, lambda r: r["us_per_ms"], lambda r: r["error_m"]),
                                   lambda r: r["us_per_ms"], lambda r: r["error_rel"], self.is_default)
            self.draw_peers(ax, scene, last, lambda p: p["us_per_ms"], sweeps=("N", "dt"))
            finish_axes(ax, "wall time per 1 ms simulated (us)", "RMS axis error / length", f"{scene}, t = {g(last)} s")
        self.save(fig, "mechanics_pareto.png", "Mechanics: error against cost, every setting, Pareto front")

    def draw_peers(self, ax, scene, t, x, sweeps):
        """The peers' runs that reached t, as black (x) and grey (+) markers, error relative to L."""
        for peer, marker in (("mujoco_rope", "x"), ("mujoco_rope_rigid", "+")):
            sel = {}
            for p in self.peer_rows:
                if (p["peer"] == peer and p["scene"] == scene and p["t_s"] == t and p["sweep"] in sweeps
                        and math.isfinite(p["error_m"])):
                    sel.setdefault((p["control_points"], p["timestep_s"]), p)
            sel = sorted(sel.values(), key=x)
            if sel:
                ax.loglog([x(p) for p in sel], [p["error_m"] / BOWEL_LENGTH_M for p in sel], marker=marker, ms=8,
                          color="k" if peer == "mujoco_rope" else "0.5", ls=":" if len(sweeps) == 1 else "none",
                          label=PEER_LABELS[peer])

    def is_default(self, r):
        if (r.get("integrator") == DEFAULTS["integrator"] and r.get("timestep_s") == DEFAULTS["timestep_s"]
                and r.get("control_points") == DEFAULTS["control_points"]):
            return "default"
        return ""

    # ---------------------------------------------------------------- collision
    def collision(self):
        rows = read(os.path.join(self.dir, "collision_pile.csv"))
        if rows is None:
            return
        integrators = read(os.path.join(self.dir, "collision_pile_integrators.csv")) or []
        self.md.append("## Collision: the dense pile\n")
        self.md.append(
            "Penetration measured on the axis sampled every R/8 (not only at the collision spheres): per "
            "sample the deepest overlap with a cavity wall (R - distance) or with a fold more than pi R "
            "away along the axis (2R - distance); max over the snapshots (every 50 ms after settling) and "
            "RMS over the penetrating samples. The library's own deepest contact (at sphere centres) is "
            "beside it. Cost: median step time in that window.\n")
        front = set(pareto(rows, lambda r: r["us_per_ms"], lambda r: r["rms_penetration_m"]))
        out = []
        for i, r in enumerate(rows):
            default = (abs(r["sphere_spacing_radii"] - DEFAULTS["sphere_spacing_radii"]) < 1e-9
                       and r["contact_stiffness_N_per_m"] == DEFAULTS["contact_stiffness_N_per_m"])
            r["front"], r["default"] = i in front, default
            out.append([g(r["sphere_spacing_radii"]) + " R", g(r["contact_stiffness_N_per_m"]),
                        g(1e3 * r["max_penetration_m"]), g(1e3 * r["rms_penetration_m"]),
                        g(100 * r["rms_penetration_radii"]), g(1e3 * r["library_max_penetration_m"]),
                        g(r["contacts"]), g(r["us_per_ms"]), g(r["substeps_per_ms"]), g(r["rollbacks"]),
                        "front" if r["front"] else "", "default" if default else "", r["status"]])
        self.md.append(table(["sphere spacing", "stiffness (N/m)", "max (mm)", "RMS (mm)", "RMS (% R)",
                              "library max (mm)", "contacts", "us per 1 ms", "substeps / ms", "rollbacks",
                              "front", "default", "status"], out) + "\n")
        self.md.append("Each integrator on the default pile (spacing R/2, 500 N/m), first steps of the drop: "
                       "the contact and self-contact stiffness bound the explicit integrators' stable "
                       "substep, so they take hundreds of substeps per 1 ms step:\n")
        self.md.append(table(["integrator", "steps timed", "us per 1 ms", "substeps / ms", "status"],
                             [[r["integrator"], g(r["steps"]), g(r["us_per_ms"]), g(r["substeps_per_ms"]),
                               r["status"]] for r in integrators]) + "\n")
        for r in integrators:
            self.main_rows.append(["collision (pile)", "integrator (spacing R/2, 500 N/m)", r["integrator"],
                                   "-", f"{g(r['us_per_ms'])} us/ms ({g(r['substeps_per_ms'])} substeps)", "",
                                   "default" if r["integrator"] == DEFAULTS["integrator"] else ""])
        for r in rows:
            if abs(r["sphere_spacing_radii"] - 0.5) < 1e-9:
                self.main_rows.append(["collision (pile)", "contact stiffness (spacing R/2)",
                                       f"{g(r['contact_stiffness_N_per_m'])} N/m",
                                       f"RMS {g(1e3 * r['rms_penetration_m'])} mm, max {g(1e3 * r['max_penetration_m'])} mm",
                                       f"{g(r['us_per_ms'])} us/ms", "front" if r["front"] else "",
                                       "default" if r["default"] else ""])
        for r in rows:
            if r["contact_stiffness_N_per_m"] == DEFAULTS["contact_stiffness_N_per_m"]:
                self.main_rows.append(["collision (pile)", "sphere spacing (stiffness 500 N/m)",
                                       f"{g(r['sphere_spacing_radii'])} R",
                                       f"RMS {g(1e3 * r['rms_penetration_m'])} mm, max {g(1e3 * r['max_penetration_m'])} mm",
                                       f"{g(r['us_per_ms'])} us/ms", "front" if r["front"] else "",
                                       "default" if r["default"] else ""])
        # Checks: stiffer contact or denser spheres never let the bowel sink deeper (10 % slack
        # for the noise of a pile), and every run stayed finite.
        self.expect(all(r["status"] == "ok" for r in rows + integrators), "failed pile runs: " + "; ".join(
            r["status"] for r in rows + integrators if r["status"] != "ok"))
        spacings = sorted(set(r["sphere_spacing_radii"] for r in rows))
        stiffnesses = sorted(set(r["contact_stiffness_N_per_m"] for r in rows))
        cell = {(r["sphere_spacing_radii"], r["contact_stiffness_N_per_m"]): r for r in rows}
        for s in spacings:
            rms = [cell[(s, k)]["rms_penetration_m"] for k in stiffnesses]
            self.expect(rms[-1] < rms[0], f"spacing {s} R: RMS penetration {rms} does not fall with stiffness")
        for k in stiffnesses:
            rms = [cell[(s, k)]["rms_penetration_m"] for s in spacings]
            self.expect(rms[0] < rms[-1], f"stiffness {k}: RMS penetration {rms} does not grow with spacing")

        fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4))
        for k in stiffnesses:
            sel = [cell[(s, k)] for s in spacings]
            a1.plot(spacings, [1e3 * r["rms_penetration_m"] for r in sel], "o-", label=f"k = {g(k)} N/m")
            a1.plot(spacings, [1e3 * r["max_penetration_m"] for r in sel], "x:", color=a1.lines[-1].get_color())
        finish_axes(a1, "sphere spacing (R)", "penetration (mm): RMS (o), max (x)", "dense pile: penetration")
        for s in spacings:
            sel = [cell[(s, k)] for k in stiffnesses]
            a2.loglog([r["us_per_ms"] for r in sel], [1e3 * r["rms_penetration_m"] for r in sel], "o-",
                      label=f"spacing {g(s)} R")
        draw_front_and_default(a2, rows, front, lambda r: r["us_per_ms"], lambda r: 1e3 * r["rms_penetration_m"],
                               lambda r: r["default"])
        finish_axes(a2, "wall time per 1 ms step (us)", "RMS penetration (mm)", "dense pile: penetration against cost")
        self.save(fig, "collision_pile.png", "Collision: penetration in the dense pile")

    def tool(self):
        rows = read(os.path.join(self.dir, "collision_tool.csv"))
        if rows is None:
            self.md.append("## Collision: the tool push\n\nNot measured in this run (no collision_tool.csv).\n")
            return
        self.md.append("## Collision: the tool push\n")
        self.md.append(
            "A deterministic scene (a pile is not): a 1 m bowel (2.5 cm segments, as the 6 m default) "
            "lying straight on a floor; a vertical grasper shaft (radius 5 mm, 8 N bound) pushes it "
            "sideways across the floor by 1 cm after the first touch, then slides 3 cm along it while "
            "pressing, then holds. Penetration: overlap of the tube with the tool capsule (R + tool "
            "radius - distance from the axis to the shaft), on the axis sampled every R/8, max and RMS "
            "from the first touch. Smoothness: the step-to-step change of the force on the tool "
            "|F(k) - F(k-1)|, max and RMS (what a haptic device feels as roughness). Cost: median step "
            "time. Pareto front over all three: cost, RMS penetration, RMS force step.\n")
        # Three objectives: a stiffer contact sinks less but feels rougher.
        front = set(pareto(rows, lambda r: r["us_per_ms"], lambda r: r["rms_penetration_m"],
                           lambda r: r["force_jump_rms_N"]))
        out = []
        for i, r in enumerate(rows):
            out.append([g(r["sphere_spacing_radii"]) + " R", g(r["contact_stiffness_N_per_m"]),
                        g(1e3 * r["max_penetration_m"]), g(1e3 * r["rms_penetration_m"]), g(r["max_force_N"]),
                        g(r["force_jump_max_N"]), g(r["force_jump_rms_N"]), g(r["us_per_ms"]),
                        "front" if i in front else "", r["status"]])
        self.md.append(table(["sphere spacing", "stiffness (N/m)", "max pen. (mm)", "RMS pen. (mm)",
                              "max force (N)", "max force step (N)", "RMS force step (N)", "us per 1 ms",
                              "front", "status"], out) + "\n")
        self.expect(all(r["status"] == "ok" for r in rows), "failed tool runs: " + "; ".join(
            r["status"] for r in rows if r["status"] != "ok"))
        for r in rows:
            self.expect(r["max_force_N"] <= r["tool_max_force_N"] * (1 + 1e-9),
                        f"tool force {r['max_force_N']} N above its max_force {r['tool_max_force_N']} N")
            self.expect(r["max_force_N"] > 0, "the tool never touched the bowel")
        for r in rows:
            if abs(r["sphere_spacing_radii"] - 0.5) < 1e-9 or r["contact_stiffness_N_per_m"] == 500:
                knob = ("contact stiffness (spacing R/2)" if abs(r["sphere_spacing_radii"] - 0.5) < 1e-9
                        else "sphere spacing (stiffness 500 N/m)")
                self.main_rows.append(["collision (tool push)", knob,
                                       f"{g(r['sphere_spacing_radii'])} R, {g(r['contact_stiffness_N_per_m'])} N/m",
                                       f"RMS {g(1e3 * r['rms_penetration_m'])} mm, force step RMS {g(r['force_jump_rms_N'])} N",
                                       f"{g(r['us_per_ms'])} us/ms", "front" if rows.index(r) in front else "",
                                       "default" if abs(r["sphere_spacing_radii"] - DEFAULTS["sphere_spacing_radii"]) < 1e-9
                                       and r["contact_stiffness_N_per_m"] == DEFAULTS["contact_stiffness_N_per_m"] else ""])
        spacings = sorted(set(r["sphere_spacing_radii"] for r in rows))
        stiffnesses = sorted(set(r["contact_stiffness_N_per_m"] for r in rows))
        cell = {(r["sphere_spacing_radii"], r["contact_stiffness_N_per_m"]): r for r in rows}
        for s in spacings:
            rms = [cell[(s, k)]["rms_penetration_m"] for k in stiffnesses]
            self.expect(rms[-1] < rms[0], f"tool, spacing {s} R: RMS penetration {rms} does not fall with stiffness")
        for k in stiffnesses:
            rms = [cell[(s, k)]["rms_penetration_m"] for s in spacings]
            self.expect(rms[0] < rms[-1], f"tool, stiffness {k}: RMS penetration {rms} does not grow with spacing")
        fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4))
        for k in stiffnesses:
            sel = [cell[(s, k)] for s in spacings if (s, k) in cell]
            a1.plot([r["sphere_spacing_radii"] for r in sel], [1e3 * r["rms_penetration_m"] for r in sel], "o-",
                    label=f"k = {g(k)} N/m")
            a2.plot([r["sphere_spacing_radii"] for r in sel], [r["force_jump_rms_N"] for r in sel], "o-",
                    label=f"k = {g(k)} N/m")
        finish_axes(a1, "sphere spacing (R)", "RMS penetration into the tool (mm)", "tool push: penetration")
        finish_axes(a2, "sphere spacing (R)", "RMS step-to-step force change (N)", "tool push: force smoothness")
        self.save(fig, "collision_tool.png", "Collision: the tool push")

    # ---------------------------------------------------------------- skins
    def skin(self, file="skin.csv", pile="the settled 6 m pile", label="settled pile", picture="skin.png"):
        rows = read(os.path.join(self.dir, file))
        if rows is None:
            return
        self.md.append(f"## Skins on {pile}\n")
        self.md.append(
            "From `ent_skin_metrics`: radius error of each vertex against its own axis point (fraction of "
            "R), vertices within 1.1 R of a part of the axis more than 4 R away along it (\"blended\"; in "
            "a pile whose folds touch, the tube, which blends nothing by construction, shows how many "
            "vertices merely lie at a contact), volume error, watertightness. Cost: median "
            "`ent_skin_update`. Pareto: within each method (the tube is exact in radius by "
            "construction, so radius error does not rank the methods against each other).\n")
        # The front within each method: across methods the radius error does not rank them (the
        # tube is exact by construction; its artefacts, fold-over and interpenetration at tight
        # bends and touching folds, are not radius errors).
        front = set()
        for method in dict.fromkeys(r["method"] for r in rows):
            members = [i for i, r in enumerate(rows) if r["method"] == method]
            front |= {members[j] for j in pareto([rows[i] for i in members], lambda r: r["ms_per_update"],
                                                 lambda r: r["radius_error_rms"])}
        tube_blended = {r["resolution"]: r["blended_vertices"] for r in rows if r["method"] == "tube"}
        out = []
        for i, r in enumerate(rows):
            default = (r["method"], r["resolution"]) == DEFAULTS["skin"]
            r["front"], r["default"] = i in front, default
            out.append([r["method"], r["resolution"], g(r["triangles"]), g(100 * r["radius_error_rms"]),
                        g(100 * r["radius_error_max"]), g(100 * r["free_radius_error_rms"]), g(r["blended_vertices"]),
                        g(tube_blended.get(r["resolution"], float("nan"))), g(r["inverted_triangles"]),
                        g(100 * r["volume_error"]), "yes" if r["watertight"] else "no", g(r["ms_per_update"]),
                        "front" if r["front"] else "", "default" if default else ""])
            self.main_rows.append([f"skin ({label})", r["method"], r["resolution"],
                                   f"radius RMS {g(100 * r['radius_error_rms'])} % R, max {g(100 * r['radius_error_max'])} %",
                                   f"{g(r['ms_per_update'])} ms/update", "front" if r["front"] else "",
                                   "default" if default else ""])
        self.md.append(table(["method", "resolution", "triangles", "radius RMS (% R)", "radius max (% R)",
                              "radius RMS away from contacts (% R)",
                              "blended", "blended by the tube", "inverted", "volume error (%)", "watertight",
                              "ms / update", "front", "default"], out) + "\n")
        for r in rows:
            # Every method, point_skeleton included (its marching cubes table no longer draws
            # face diagonals that a neighbouring cell may draw too, where folds touch).
            self.expect(r["watertight"] == 1, f"skin {r['method']} {r['resolution']} is not watertight: "
                                              f"{g(r['open_edges'])} open, {g(r['nonmanifold_edges'])} non-manifold edges")
            self.expect(r["radius_error_rms"] < 0.05, f"skin {r['method']} {r['resolution']}: radius RMS "
                                                      f"{r['radius_error_rms']:.3g} R")
            # The README's claim: within 1 % RMS at the default resolution, on both piles, away
            # from contacts (where the contact surfaces flatten the skin on purpose:
            # ent_skin_metrics.free_radius_error_rms).
            if r["method"] != "tube" and r["resolution"] == "default":
                self.expect(r["free_radius_error_rms"] <= 0.01, f"skin {r['method']} default on {pile}: radius RMS "
                                                                f"away from contacts {r['free_radius_error_rms']:.3g} R, "
                                                                "above 1 %")
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for method, marker in (("tube", "o"), ("point_skeleton", "s"), ("convolution", "^")):
            sel = [r for r in rows if r["method"] == method]
            ax.semilogx([r["ms_per_update"] for r in sel], [100 * r["radius_error_rms"] for r in sel], marker + "-",
                        label=method)
            for r in sel:
                ax.annotate(r["resolution"], (r["ms_per_update"], 100 * r["radius_error_rms"]), fontsize=6)
        ax.plot([rows[i]["ms_per_update"] for i in front], [100 * rows[i]["radius_error_rms"] for i in front], "ko",
                mfc="none", ms=10, label="front of its method")
        for r in rows:
            if r["default"]:
                ax.plot([r["ms_per_update"]], [100 * r["radius_error_rms"]], "r*", ms=14, label="library default")
        finish_axes(ax, "ms per ent_skin_update", "radius error RMS (% of R)", f"skins of {pile}")
        self.save(fig, picture, f"Skins on {pile}: radius error against update time")

    # ---------------------------------------------------------------- effects
    def effects(self):
        cost = read(os.path.join(self.dir, "effects_cost.csv"))
        absent = read(os.path.join(self.dir, "effects_absent.csv"))
        if cost is None or absent is None:
            return
        self.md.append("## Only the effects a scene names\n")
        self.md.append("Cost of each effect on the settled 6 m pile, from `ent_scene_effect_stats` "
                       "(microseconds per 1 ms step; the rest of the step is the solver):\n")
        out = [[r["effect"], "yes" if r["enabled"] else "no", g(r["calls_per_step"]), g(r["us_per_step"]),
                g(100 * r["share_of_step"], 2)] for r in cost]
        out.append(["whole step (median / mean)", "", g(cost[0]["substeps_per_step"]),
                    f"{g(cost[0]['step_median_us'])} / {g(cost[0]['step_mean_us'])}", "100"])
        self.md.append(table(["effect", "named", "calls per step", "us per step", "% of the step"], out) + "\n")
        self.md.append("The same 6 m bowel three ways, stepped in interleaved rounds (ratio: median over "
                       "rounds of each variant's median step time over gravity-only's; axis difference "
                       "after the run, against gravity-only):\n")
        out = [[r["variant"].replace("_", " "), g(r["step_median_us"]), g(r["ratio_to_gravity_only"], 4),
                f"{g(r['ratio_min'], 4)} to {g(r['ratio_max'], 4)}", r["effects_called"] or "-",
                g(r["axis_difference_m"])] for r in absent]
        self.md.append(table(["variant", "us per step", "ratio", "range over rounds", "effects run",
                              "axis difference (m)"], out) + "\n")
        by = {r["variant"]: r for r in absent}
        self.expect(by["others_absent"]["effects_called"] == "gravity",
                    f"absent effects ran: {by['others_absent']['effects_called']}")
        # A zero stiffness turns the bowel's elasticity off (it has no key of its own); every
        # other effect named at zero strength still runs.
        ran = set(str(by["others_zero_strength"]["effects_called"]).split())
        elasticity = {"stretch", "bend"}
        self.expect(ran == {r["effect"] for r in cost} - elasticity,
                    f"the zero-strength variant did not run every effect but the elasticity: {' '.join(sorted(ran))}")
        self.expect(by["others_zero_strength"]["axis_difference_m"] == 0 and
                    by["others_absent"]["axis_difference_m"] == 0,
                    "the three variants did not move exactly alike")
        self.main_rows.append(["effects (6 m bowel)", "other effects absent", "gravity only named",
                               "same motion", f"x {by['others_absent']['ratio_to_gravity_only']:.3f} of gravity-only",
                               "", ""])
        self.main_rows.append(["effects (6 m bowel)", "other effects at zero strength", "all named, zero",
                               "same motion", f"x {by['others_zero_strength']['ratio_to_gravity_only']:.3f} of gravity-only",
                               "", ""])
        fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4))
        a1.barh([r["effect"] for r in cost], [r["us_per_step"] for r in cost])
        a1.set_xlabel("us per 1 ms step")
        a1.set_title("cost of each effect, settled 6 m pile")
        a2.bar([r["variant"].replace("_", "\n") for r in absent], [r["step_median_us"] for r in absent])
        a2.set_ylabel("median us per 1 ms step")
        a2.set_yscale("log")
        a2.set_title("absent effects cost nothing")
        self.save(fig, "effects.png", "Effects: what each costs; absent ones cost nothing")

    # ---------------------------------------------------------------- peers
    def peers(self):
        self.md.append("## Peers\n")
        built = str(self.run.get("peers", ""))
        if not self.peer_rows:
            if built.startswith("none"):
                text = f"Skipped: {built[len('none'):].strip(' :')}."
            else:
                text = ("No peer results in this run. A peer (the MuJoCo rope of `bench/peers`, ...) joins the "
                        "study by writing `peers.csv` into this folder (columns: see `bench/study/report.py`); its "
                        "error is measured against the same reference axes (`mechanics_reference_axes.csv`).")
                self.expect(not built.startswith("MuJoCo"),
                            f"this build has a peer ({built}) but the study wrote no {self.peers_path}")
            self.md.append(text + "\n")
            self.doc_notes.append(f"Peers: {text}")
            return
        mech = read(os.path.join(self.dir, "mechanics.csv")) or []
        times = sorted(set(p["t_s"] for p in self.peer_rows))
        last = times[-1]
        ref = [(r["x_m"], r["y_m"], r["z_m"]) for r in read(os.path.join(self.dir, "mechanics_reference_axes.csv")) or []
               if r["scene"] == "swing" and r["t_s"] == last]
        length = sum(math.dist(a, b) for a, b in zip(ref, ref[1:]))
        stretched = (f"the reference's axis is {g(length)} m long at t = {g(last)} s, "
                     f"{g(100 * (length / BOWEL_LENGTH_M - 1), 2)} % more than at rest" if ref else "several per cent")
        self.md.append(
            f"{built or 'A peer'} in the same run and process as ours, on the swing: the same length, radius, mass "
            "per length, bending stiffness, stretch stiffness and damping, drag, gravity, pinned first end, "
            "straight start at rest, N (its joint points), time step and times; its axis (201 points evenly spaced "
            "in arc length along its joint polyline) is measured against the same reference with the same metric. "
            "Cost: median `mj_step` per 1 ms simulated. MuJoCo 2.2.2 has no cable or flex element, so the "
            "peer is its composite rope, and it differs from our model in ways no setting removes:\n")
        self.md.append(
            "- *Geometry and mass*: N - 1 rigid capsules (its axis a polyline, first order in the segment length "
            "l) each carrying its mass mu l at its centre with the capsule's rotary inertia; ours a C1 cubic "
            "Catmull-Rom axis with a consistent mass matrix and no rotary inertia.\n"
            "- *Bending*: a spring EI / l on each of the two hinges between capsules (the angle over l as the "
            "curvature); ours EI/2 times the integral of the spline's squared curvature.\n"
            "- *Stretching* (`mujoco_rope`): MuJoCo's stretch joints, a slide between neighbouring capsules of "
            "stiffness EA / l and damping c / l (its soft equality that holds them near zero is turned off); the "
            "capsules keep their length and open gaps, and the last segment cannot stretch. `mujoco_rope_rigid` "
            f"has rigid segments (the collision benchmark's rope): our EA = 100 N lets the swinging bowel "
            f"lengthen ({stretched}), which it cannot follow.\n"
            "- *Drag*: MuJoCo has no drag per metre (its fluid model is per body, isotropic, on an equivalent "
            "inertia box), so -c v per metre is added through its passive-force callback: -c l v at each "
            "capsule's centre and -c l^3 / 12 omega across it.\n"
            "- *Integrator*: MuJoCo's Euler (its default): semi-implicit, joint damping implicit, springs "
            "explicit, so the stretch and bending springs bound its stable step. Ours: the three integrators "
            "of the study.\n"
            "- *Cost*: MuJoCo works in joint coordinates, where the mass matrix of a chain is dense, so its step "
            "grows like N^3 (ours like N). A setting whose whole run is projected above the study's budget "
            "is timed on a few steps only (cost, no error: \"timed only\"); one whose model build and first "
            "steps are projected above it is not run.\n")

        def ours(p, integrator):
            for r in mech:
                if (r["scene"] == p["scene"] and r["t_s"] == p["t_s"] and r["integrator"] == integrator
                        and r["control_points"] == p["control_points"] and r["timestep_s"] == p["timestep_s"]
                        and r["sweep"] in ("N", "dt")):
                    return r
            return None

        def mm(value):
            return g(1e3 * value) if value is not None else "-"

        def cell(r):
            if not r:
                return "-"
            return f"{mm(r['error_m'])} mm, {g(r['us_per_ms'])} us" + (" (N of the reference)" if r["at_reference_N"] else "")

        # Every setting at the last time; the same setting may sit in two sweeps: once.
        unique = {}
        for p in self.peer_rows:
            if p["t_s"] == last:
                unique.setdefault((p["peer"], p["control_points"], p["timestep_s"]), p)
        order = {"N": 0, "dt": 1, "dt_own": 2}
        out, doc_rows = [], []
        for p in sorted(unique.values(), key=lambda p: (p["peer"] != "mujoco_rope", order.get(p["sweep"], 3),
                                                        p["control_points"], p["timestep_s"])):
            default = ours(p, DEFAULTS["integrator"])
            ratio = p["us_per_ms"] / default["us_per_ms"] if default else float("nan")
            status = str(p.get("status", "ok"))
            finite = "-" if status.startswith("not run") else ("yes" if p["finite"] else "no") + (
                f" ({g(p['steps_timed'])} steps)" if status != "ok" and p["finite"] else "")
            out.append([p["peer"], g(p["control_points"]), g(p["timestep_s"]), mm(p["error_m"]), g(p["us_per_ms"]),
                        finite, status, cell(default), cell(ours(p, "symplectic_euler")),
                        cell(ours(p, "rk4")), g(ratio)])
            if p["peer"] == "mujoco_rope" and p["sweep"] == "N":
                doc_rows.append([g(p["control_points"]), g(p["timestep_s"]), mm(p["error_m"]), g(p["us_per_ms"]),
                               finite, cell(default), cell(ours(p, "rk4")), g(ratio)])
        self.md.append(f"### Every setting at t = {g(last)} s\n")
        self.md.append("Error: RMS distance to the reference (mm); Enteron's cells: error and us per 1 ms at the same "
                       "N and time step; ratio: the peer's cost over ours with implicit Euler (> 1: we are faster). "
                       "Finite: whether it stayed finite over the steps it ran.\n")
        self.md.append(table(["peer", "N", "time step (s)", "error (mm)", "us per 1 ms", "finite", "status",
                              "Enteron implicit Euler (default)", "Enteron symplectic Euler", "Enteron rk4",
                              "cost ratio"], out) + "\n")
        self.doc_notes.append(
            f"MuJoCo next to Enteron in the same run (swing, t = {g(last)} s; {built}'s composite rope with "
            "stretch joints, hinge springs and drag, its Euler integrator; how it differs from our model and its "
            "own convergence: [study.md, Peers](STUDY_MD#peers)):")
        self.doc_notes.append(table(["N", "time step (s)", "MuJoCo error (mm)", "MuJoCo us per 1 ms", "finite",
                                        "Enteron implicit Euler", "Enteron rk4", "MuJoCo / Enteron cost"], doc_rows))
        # The time-step sweep in one sentence: where its Euler stayed finite, and what ran to the end.
        sweep = sorted((p for p in self.peer_rows if p["t_s"] == last and p["peer"] == "mujoco_rope"
                        and p["sweep"] == "dt"),
                       key=lambda p: p["timestep_s"])
        if sweep:
            def steps(rows):
                return ", ".join(g(p["timestep_s"]) for p in rows) or "none"
            blown = [p for p in sweep if not p["finite"]]
            ended = [p for p in sweep if math.isfinite(p["error_m"])]
            timed = [p for p in sweep if p["finite"] and not math.isfinite(p["error_m"])]
            self.doc_notes.append(
                f"Time steps at N = {g(sweep[0]['control_points'])} (s): MuJoCo's Euler went non-finite at "
                f"{steps(blown)}; ran to the end at {steps(ended)}"
                + (f"; was only timed (its run too long for the study) at {steps(timed)}" if timed else "")
                + ". Every setting, and the same rope with rigid segments: `study.md`.")
        self.peer_convergence(last)
        self.peer_checks()

    def peer_convergence(self, t):
        """The rope's own convergence: is its gap to our reference discretisation or model?"""
        rows = {(p["control_points"], p["timestep_s"]): p for p in self.peer_rows
                if p["peer"] == "mujoco_rope" and p["t_s"] == t and p["axis"]}
        rigid = {p["control_points"]: p for p in self.peer_rows
                 if p["peer"] == "mujoco_rope_rigid" and p["t_s"] == t and p["timestep_s"] == 1e-3 and p["axis"]}
        sizes = sorted(n for n, h in rows if h == 1e-3)
        if len(sizes) < 2:
            return
        out, ns, diffs = [], [], []
        for n in sizes:
            p = rows[(n, 1e-3)]
            nxt = rows.get((2 * n, 1e-3))
            d = rms_distance(p["axis"], nxt["axis"]) if nxt else float("nan")
            if math.isfinite(d):
                ns.append(n)
                diffs.append(d)
            out.append([g(n), g(1e3 * p["error_m"]), g(1e3 * d),
                        g(1e3 * rigid[n]["error_m"]) if n in rigid else "-"])
        order = -fit_order(ns, diffs)  # needs two distances, so three N
        self.md.append(f"### The peer's own convergence (t = {g(t)} s)\n")
        self.md.append("In space: the distance between its axes at N and 2N (both at 1 ms), so our reference plays "
                       f"no part; observed order {g(order, 2)} (from three N or more). The rigid rope beside it, "
                       "for scale.\n")
        self.md.append(table(["N", "error vs our reference (mm)", "distance to 2N (mm)",
                              "rigid segments: error (mm)"], out) + "\n")
        # In time: at the N of its finest time step that reached t.
        steps = {}
        for (n, h), p in rows.items():
            steps.setdefault(n, []).append(h)
        n_time = max(steps, key=lambda n: (len(steps[n]), -n))
        hs = sorted(steps[n_time])
        time_error = float("nan")
        if len(hs) >= 2:
            finest = rows[(n_time, hs[0])]
            out = [[g(h), g(1e3 * rows[(n_time, h)]["error_m"]),
                    g(1e3 * rms_distance(rows[(n_time, h)]["axis"], finest["axis"]))] for h in hs[1:]]
            self.md.append(f"In time, at N = {g(n_time)}: the distance to its own finest step that ran to the end "
                           f"({g(hs[0])} s):\n")
            self.md.append(table(["time step (s)", "error vs our reference (mm)",
                                  f"distance to its {g(hs[0])} s run (mm)"], out) + "\n")
            if (n_time, 1e-3) in rows:
                time_error = rms_distance(rows[(n_time, 1e-3)]["axis"], finest["axis"])
        big, bigger = ns[-1], 2 * ns[-1]
        finding = (f"MuJoCo rope on the swing at t = {g(t)} s, 1 ms: {g(1e3 * rows[(big, 1e-3)]['error_m'])} mm from "
                   f"our reference at N = {g(big)}, {g(1e3 * rows[(bigger, 1e-3)]['error_m'])} mm at N = {g(bigger)}")
        if math.isfinite(order) and order > 0.5:
            # The gap at N -> infinity: Richardson on its two finest N, with the observed order.
            a, b = rows[(big, 1e-3)]["axis"], rows[(bigger, 1e-3)]["axis"]
            factor = 1.0 / (2.0 ** order - 1.0)
            limit = [y + (y - x) * factor for x, y in zip(a, b)]
            ref = [v for r in (read(os.path.join(self.dir, "mechanics_reference_axes.csv")) or [])
                   if r["scene"] == "swing" and r["t_s"] == t for v in (r["x_m"], r["y_m"], r["z_m"])]
            gap = rms_distance(limit, ref)
            self.md.append(
                f"Extrapolated to N -> infinity from N = {g(big)} and {g(bigger)} (Richardson with the observed order "
                f"{g(order, 2)}), its axis at 1 ms is {g(1e3 * gap)} mm from our reference: what remains once its "
                "spatial error is taken out, its time error at 1 ms plus the difference between the two models"
                + (f"; its time error at 1 ms alone is {g(1e3 * time_error)} mm (at N = {g(n_time)}, table above)"
                   if math.isfinite(time_error) else "") + ".\n")
            finding += f"; converging with order {g(order, 2)} in N, extrapolated to {g(1e3 * gap)} mm"
        self.notes.append(finding)

    def peer_checks(self):
        """The peer ran, on the same scene: checks that fail when it did not or when the scenes differ."""
        mech = read(os.path.join(self.dir, "mechanics.csv")) or []
        sizes = sorted(set(r["control_points"] for r in mech if r["scene"] == "swing" and r["sweep"] == "N"))
        times = sorted(set(r["t_s"] for r in mech if r["scene"] == "swing"))
        rope = [p for p in self.peer_rows if p["peer"] == "mujoco_rope"]
        for n in sizes:
            for t in times:
                self.expect(any(p["control_points"] == n and p["timestep_s"] == 1e-3 and p["t_s"] == t for p in rope),
                            f"peers: no mujoco_rope row for the swing at N = {g(n)}, 1 ms, t = {g(t)} s")
        for p in self.peer_rows:
            label = f"peers: {p['peer']} N = {g(p['control_points'])} dt = {g(p['timestep_s'])} t = {g(p['t_s'])}"
            status = str(p.get("status", "ok"))
            self.expect((not p["finite"]) == status.startswith("not finite"),
                        f"{label}: finite = {g(p['finite'])} but status \"{status}\"")
            if not status.startswith("not run"):
                self.expect(p["us_per_ms"] > 0, f"{label}: no cost measured ({status})")
            if status == "ok":
                self.expect(len(p["axis"]) == 3 * 201, f"{label}: ran to the end but has no axis")
            if (p["peer"] == "mujoco_rope" and status == "ok" and p["control_points"] >= 30
                    and p["timestep_s"] <= 1e-3):
                self.expect(p["error_m"] < PEER_ERROR_BOUND_M,
                            f"{label}: {g(p['error_m'])} m from our reference, more than {PEER_ERROR_BOUND_M} m: "
                            "the two scenes differ")
        for t in times:
            errors = [p["error_m"] for p in sorted(rope, key=lambda p: p["control_points"])
                      if p["timestep_s"] == 1e-3 and p["t_s"] == t and p["sweep"] == "N" and math.isfinite(p["error_m"])]
            # Runs that the study's wall-time budget left out ("timed only", "not run") depend on
            # how loaded the machine is: then there is nothing to compare, not a failure.
            budgeted = [p for p in rope if p["timestep_s"] == 1e-3 and p["t_s"] == t and p["sweep"] == "N"
                        and str(p.get("status", "ok")).startswith(("timed only", "not run"))]
            if len(errors) < 2 and budgeted:
                print(f"report.py: peers: only {len(errors)} mujoco_rope run(s) reached t = {g(t)} s at 1 ms within "
                      f"the time budget ({len(budgeted)} left out): the convergence check is not made")
                continue
            self.expect(len(errors) >= 2, f"peers: fewer than two mujoco_rope runs reached t = {g(t)} s at 1 ms")
            self.expect(all(b < a for a, b in zip(errors, errors[1:])),
                        f"peers: the MuJoCo rope's error does not fall as N grows at t = {g(t)} s: {errors}")

    # ---------------------------------------------------------------- output
    def main_table(self):
        return table(["area", "knob", "setting", "error", "cost", "Pareto", "default"], self.main_rows)

    def write(self, doc):
        header = [
            "# Accuracy study: what accuracy costs in time",
            "",
            f"Mode `{self.run.get('mode', '?')}`, run {self.run.get('date_utc', '?')} on "
            f"{self.run.get('cpu', '?')} ({g(self.run.get('cpus', float('nan')))} CPUs), library "
            f"{self.run.get('library_version', '?')}, {self.source}. Regenerate with `scripts/study` (this folder) or "
            "`scripts/study --fast`. Numbers are measured, not edited; timings are medians on a shared "
            "machine and carry its noise.",
            "",
            "## Main table",
            "",
            self.main_table(),
            "",
        ]
        plots = [f"![{caption}]({name})" for name, caption in self.plots]
        if self.notes:
            plots += ["", "## Findings", ""] + [f"- {note}" for note in self.notes]
        with open(os.path.join(self.dir, "study.md"), "w") as f:
            f.write("\n".join(header + plots + [""] + self.md))
        if doc:
            rel = os.path.relpath(self.dir, os.path.dirname(os.path.abspath(doc)))
            block = ["<!-- study:begin -->",
                     f"Measured {self.run.get('date_utc', '?')} on {self.run.get('cpu', '?')} "
                     f"(`scripts/study`, mode {self.run.get('mode', '?')}); every table of the study: "
                     f"[`{rel}/study.md`]({rel}/study.md).",
                     "", self.main_table(), ""]
            for note in self.doc_notes:
                block += [note.replace("STUDY_MD", f"{rel}/study.md"), ""]
            block += [f"![{caption}]({rel}/{name})" for name, caption in self.plots]
            block.append("<!-- study:end -->")
            with open(doc) as f:
                text = f.read()
            begin, end = text.find("<!-- study:begin -->"), text.find("<!-- study:end -->")
            if begin < 0 or end < 0:
                raise SystemExit(f"report.py: {doc} has no study:begin / study:end markers")
            text = text[:begin] + "\n".join(block) + text[end + len("<!-- study:end -->"):]
            with open(doc, "w") as f:
                f.write(text)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--doc", help="markdown file whose study:begin / study:end block to rewrite")
    parser.add_argument("--peers")
    args = parser.parse_args()
    report = Report(args.results)
    report.load_peers(args.peers or os.path.join(args.results, "peers.csv"))
    report.mechanics()
    report.collision()
    report.tool()
    report.skin()
    report.skin("skin_tight_fold.csv", "the tight-fold pile (bench/skin_piles.h: over half the axis bent "
                "under 4 R, U-turns down to 1.5 R)", "tight-fold pile", "skin_tight_fold.png")
    report.effects()
    report.peers()
    report.write(args.doc)
    print(f"report.py: wrote {os.path.join(args.results, 'study.md')} and {len(report.plots)} plots")
    for note in report.notes:
        print(f"report.py: finding: {note}")
    if args.check:
        for failure in report.failures:
            print(f"report.py: CHECK FAILED: {failure}", file=sys.stderr)
        if report.failures:
            return 1
        print("report.py: every check passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
