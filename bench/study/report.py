#!/usr/bin/python3
"""Turns the CSV files of enteron_study into plots, markdown tables and checks.

    report.py RESULTS_DIR [--check] [--readme README.md] [--peers PEERS_CSV]

Reads RESULTS_DIR/*.csv (written by bench/study/enteron_study), writes RESULTS_DIR/*.png
and RESULTS_DIR/study.md. With --check it asserts what the study must show (the reference
is converged, observed orders are near the expected ones, errors fall with resolution,
absent effects never run, ...) and exits 1 naming every failed check. With --readme it
replaces the block between the markers `<!-- study:begin -->` and `<!-- study:end -->` of
that file with the main table and the plots.

Peers (a MuJoCo rope, ...): a CSV `peers.csv` in RESULTS_DIR (or --peers) with the columns
    peer, scene, control_points, timestep_s, t_s, us_per_ms, finite, axis_xyz_m
where axis_xyz_m is 201 points evenly spaced in arc length, "x y z x y z ..." separated by
spaces, is compared with the study's reference axes (mechanics_reference_axes.csv) and
shown next to our own error on the same scene, N and time step.
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

INTEGRATORS = ("rk4", "symplectic_euler", "implicit_euler")
EXPECTED_TIME_ORDER = {"rk4": 4.0, "symplectic_euler": 1.0, "implicit_euler": 1.0}
# Catmull-Rom interpolation reproduces quadratics: the axis converges as O(l^2) or better
# asymptotically; the stiff stretching (nearly inextensible) slows it before that, so the
# check accepts from 1 up (measured about 1.2 to 1.7 on the swing between N = 60 and 960).
EXPECTED_SPACE_ORDER = 2.0
SMOOTH_SCENES = ("swing", "sag")  # the drop has penalty contacts: no smooth order
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
        self.main_rows = []   # the main table (README)
        self.readme_notes = []
        self.failures = []
        self.notes = []       # findings to report that are not checks
        self.plots = []
        self.run = (read(os.path.join(directory, "study_run.csv")) or [{}])[0]
        self.source = source_version()

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
            for integrator, style in zip(INTEGRATORS, ("o-", "s-", "^-")):
                sel = sorted((r for r in rows if r["scene"] == scene and r["t_s"] == last and r["sweep"] == "N"
                              and r["integrator"] == integrator), key=lambda r: r["control_points"])
                ax.loglog([r["control_points"] for r in sel], [r["error_rel"] for r in sel], style,
                          label=f"{integrator}, 1 ms")
            sel = sorted((r for r in rows if r["scene"] == scene and r["t_s"] == last
                          and r["sweep"] == "N_fine_dt"), key=lambda r: r["control_points"])
            ax.loglog([r["control_points"] for r in sel], [r["error_rel"] for r in sel], "k--",
                      label="rk4, reference step")
            finish_axes(ax, "control points N", "RMS axis error / length", f"{scene}, t = {g(last)} s")
        self.save(fig, "mechanics_error_vs_N.png", "Mechanics: error against control points")

        fig, axes = plt.subplots(1, len(scenes), figsize=(5 * len(scenes), 4), squeeze=False)
        for ax, scene in zip(axes[0], scenes):
            for integrator, style in zip(INTEGRATORS, ("o-", "s-", "^-")):
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
            for integrator, marker in zip(INTEGRATORS, ("o", "s", "^")):
                sel = [r for r in pts if r["integrator"] == integrator]
                ax.loglog([r["us_per_ms"] for r in sel], [r["error_rel"] for r in sel], marker, alpha=0.6,
                          label=integrator)
            draw_front_and_default(ax, pts, pareto(pts, lambda r: r["us_per_ms"], lambda r: r["error_m"]),
                                   lambda r: r["us_per_ms"], lambda r: r["error_rel"], self.is_default)
            finish_axes(ax, "wall time per 1 ms simulated (us)", "RMS axis error / length", f"{scene}, t = {g(last)} s")
        self.save(fig, "mechanics_pareto.png", "Mechanics: error against cost, every setting, Pareto front")

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
    def skin(self):
        rows = read(os.path.join(self.dir, "skin.csv"))
        if rows is None:
            return
        self.md.append("## Skins on the settled 6 m pile\n")
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
                        g(100 * r["radius_error_max"]), g(r["blended_vertices"]),
                        g(tube_blended.get(r["resolution"], float("nan"))), g(r["inverted_triangles"]),
                        g(100 * r["volume_error"]), "yes" if r["watertight"] else "no", g(r["ms_per_update"]),
                        "front" if r["front"] else "", "default" if default else ""])
            self.main_rows.append(["skin (settled pile)", r["method"], r["resolution"],
                                   f"radius RMS {g(100 * r['radius_error_rms'])} % R, max {g(100 * r['radius_error_max'])} %",
                                   f"{g(r['ms_per_update'])} ms/update", "front" if r["front"] else "",
                                   "default" if default else ""])
        self.md.append(table(["method", "resolution", "triangles", "radius RMS (% R)", "radius max (% R)",
                              "blended", "blended by the tube", "inverted", "volume error (%)", "watertight",
                              "ms / update", "front", "default"], out) + "\n")
        for r in rows:
            # Every method, point_skeleton included (its marching cubes table no longer draws
            # face diagonals that a neighbouring cell may draw too, where folds touch).
            self.expect(r["watertight"] == 1, f"skin {r['method']} {r['resolution']} is not watertight: "
                                              f"{g(r['open_edges'])} open, {g(r['nonmanifold_edges'])} non-manifold edges")
            self.expect(r["radius_error_rms"] < 0.05, f"skin {r['method']} {r['resolution']}: radius RMS "
                                                      f"{r['radius_error_rms']:.3g} R")
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
        finish_axes(ax, "ms per ent_skin_update", "radius error RMS (% of R)", "skins of the settled 6 m pile")
        self.save(fig, "skin.png", "Skins: radius error against update time")

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
        self.expect(len(str(by["others_zero_strength"]["effects_called"]).split()) == len(cost),
                    f"the zero-strength variant did not run every effect: {by['others_zero_strength']['effects_called']}")
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
    def peers(self, path):
        self.md.append("## Peers\n")
        peers = read(path) if path else None
        axes = read(os.path.join(self.dir, "mechanics_reference_axes.csv"))
        if not peers:
            self.md.append(
                "No peer results in this run. A peer (the MuJoCo rope of `bench/peers`, ...) joins the "
                "study by writing `peers.csv` into this folder (columns: peer, scene, control_points, "
                "timestep_s, t_s, us_per_ms, finite, axis_xyz_m with 201 points evenly spaced in arc length); "
                "its error is measured against the same reference axes (`mechanics_reference_axes.csv`).\n")
            return
        ref = {}
        for r in axes or []:
            ref.setdefault((r["scene"], r["t_s"]), []).extend([r["x_m"], r["y_m"], r["z_m"]])
        mech = read(os.path.join(self.dir, "mechanics.csv")) or []
        out = []
        for p in peers:
            xyz = [float(v) for v in str(p["axis_xyz_m"]).split()] if p.get("axis_xyz_m") else []
            reference = ref.get((p["scene"], p["t_s"]))
            err = float("nan")
            if reference and len(xyz) == len(reference):
                err = math.sqrt(sum((a - b) ** 2 for a, b in zip(xyz, reference)) / (len(xyz) / 3))
            ours = [r for r in mech if r["scene"] == p["scene"] and r["t_s"] == p["t_s"]
                    and r["control_points"] == p["control_points"] and r["timestep_s"] == p["timestep_s"]
                    and r["sweep"] in ("N", "dt")]
            ours_text = "; ".join(f"{r['integrator']} {g(r['error_m'])} m, {g(r['us_per_ms'])} us"
                                  for r in {r["integrator"]: r for r in ours}.values())
            out.append([p["peer"], p["scene"], g(p["control_points"]), g(p["timestep_s"]), g(p["t_s"]),
                        g(p["us_per_ms"]), "yes" if p["finite"] else "no", g(err), ours_text or "-"])
        self.md.append(table(["peer", "scene", "N", "time step (s)", "t (s)", "us per 1 ms", "finite",
                              "error (m)", "Enteron, same scene, N and step"], out) + "\n")

    # ---------------------------------------------------------------- output
    def main_table(self):
        return table(["area", "knob", "setting", "error", "cost", "Pareto", "default"], self.main_rows)

    def write(self, readme):
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
        if readme:
            rel = os.path.relpath(self.dir, os.path.dirname(os.path.abspath(readme)))
            block = ["<!-- study:begin -->",
                     f"Measured {self.run.get('date_utc', '?')} on {self.run.get('cpu', '?')} "
                     f"(`scripts/study`, mode {self.run.get('mode', '?')}); every table of the study: "
                     f"[`{rel}/study.md`]({rel}/study.md).",
                     "", self.main_table(), ""]
            block += [f"![{caption}]({rel}/{name})" for name, caption in self.plots]
            block.append("<!-- study:end -->")
            with open(readme) as f:
                text = f.read()
            begin, end = text.find("<!-- study:begin -->"), text.find("<!-- study:end -->")
            if begin < 0 or end < 0:
                raise SystemExit(f"report.py: {readme} has no study:begin / study:end markers")
            text = text[:begin] + "\n".join(block) + text[end + len("<!-- study:end -->"):]
            with open(readme, "w") as f:
                f.write(text)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--readme")
    parser.add_argument("--peers")
    args = parser.parse_args()
    report = Report(args.results)
    report.mechanics()
    report.collision()
    report.tool()
    report.skin()
    report.effects()
    report.peers(args.peers or os.path.join(args.results, "peers.csv"))
    report.write(args.readme)
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
