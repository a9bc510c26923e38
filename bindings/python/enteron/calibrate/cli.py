# SPDX-License-Identifier: Apache-2.0
"""The command: fits an experiment's constants to a data file (docs/calibration.md).

    scripts/calibrate EXPERIMENT.json DATA.csv [options]     (from a checkout)
    enteron-calibrate EXPERIMENT.json DATA.csv [options]     (installed)
    python3 -m enteron.calibrate EXPERIMENT.json DATA.csv [options]

EXPERIMENT may also be the name of a shipped experiment (cantilever, three_point_bending,
hanging_sag, drop_on_table, lcm_journal, tensile_test). Prints the constants with their standard
deviations and the residual; --out writes everything as JSON, --scene-out the fitted scene.
Exit status: 0 fitted; 2 a bad experiment, data file or option (the message names it);
1 the fit or the engine failed.
"""
import argparse
import json
import math
import os
import sys

from . import EXPERIMENTS, experiment_path
from .data import load as load_data
from .engine import Engine, EngineError
from .experiment import CalibrationError
from .experiment import load as load_experiment
from .fit import FitError, fit


def default_cache_directory():
    """$XDG_CACHE_HOME/enteron/calibrate, or ~/.cache/enteron/calibrate."""
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "enteron", "calibrate")


def parser():
    p = argparse.ArgumentParser(
        prog="calibrate", description="Fits the constants of an Enteron experiment to measured data "
        "(CMA-ES, then bounded least squares; Hessian-based uncertainty), on Dask.",
        epilog="docs/calibration.md has the file formats and the method.")
    p.add_argument("experiment", help="experiment file (JSON), or a shipped one: " + ", ".join(EXPERIMENTS))
    p.add_argument("data", help="data file (CSV: measurement,t_s,value[,sigma])")
    p.add_argument("--journal", metavar="FILE", help="the LCM journal to replay (an experiment with \"journal\", "
                   "e.g. lcm_journal): replaces the experiment's")
    where = p.add_argument_group("where the simulations run")
    where.add_argument("--scheduler", metavar="tcp://HOST:PORT",
                       help="an existing Dask scheduler (default: an embedded LocalCluster on this machine)")
    where.add_argument("--workers", type=int, metavar="N",
                       help="LocalCluster workers (default: one per core); 0: no Dask, in this process")
    where.add_argument("--library", choices=("auto", "inherit", "upload", "installed"), default="auto",
                       help="how the workers get libenteron (default auto: inherit locally, upload to a cluster)")
    where.add_argument("--dashboard", action="store_true", help="serve Dask's dashboard (127.0.0.1:8787 locally)")
    where.add_argument("--cache", metavar="DIR", default=default_cache_directory(),
                       help="evaluations kept here; a run interrupted resumes from them (default: %(default)s)")
    where.add_argument("--no-cache", action="store_true", help="keep no evaluations on disk")
    search = p.add_argument_group("the fit (default: the experiment's \"fit\" object)")
    search.add_argument("--seed", type=int)
    search.add_argument("--max-evaluations", type=int, metavar="N", help="budget of the global search")
    search.add_argument("--population", type=int, metavar="N", help="CMA-ES population (simulations per generation)")
    search.add_argument("--no-local", action="store_true", help="skip the local refinement")
    out = p.add_argument_group("output")
    out.add_argument("--out", metavar="FILE.json", help="the result as JSON")
    out.add_argument("--scene-out", metavar="FILE.json", help="the scene with the fitted constants")
    out.add_argument("--quiet", action="store_true", help="no progress bar and no log lines")
    return p


def main(argv=None):
    args = parser().parse_args(argv)
    stream = sys.stderr

    def log(text):
        if not args.quiet:
            stream.write("calibrate: %s\n" % text)
            stream.flush()

    try:
        path = args.experiment
        if not os.path.exists(path) and path in EXPERIMENTS:
            path = experiment_path(path)
        experiment = load_experiment(path, journal=args.journal)
        data = load_data(args.data, experiment)
        for name, value in (("--workers", args.workers), ("--max-evaluations", args.max_evaluations),
                            ("--population", args.population)):
            if value is not None and value < 0:
                raise CalibrationError("%s must be >= 0, got %d" % (name, value))
        if args.scheduler is not None and args.workers is not None:
            raise CalibrationError("--workers applies to the embedded LocalCluster, not to --scheduler")
    except CalibrationError as error:
        sys.stderr.write("calibrate: %s\n" % error)
        return 2
    cache = None if args.no_cache else args.cache
    log("experiment %s (%s): %d constant(s), %d data row(s) from %s" % (
        experiment.name, experiment.file, len(experiment.parameters), len(data), args.data))
    if cache:
        log("evaluations kept in %s" % cache)
    try:
        with Engine(scheduler=args.scheduler, workers=args.workers, dashboard=args.dashboard,
                    progress=not args.quiet, library=args.library, stream=stream) as engine:
            log("simulations on %s" % engine.description)
            result = fit(experiment, data, engine, cache_directory=cache, log=log, seed=args.seed,
                         max_evaluations=args.max_evaluations, population=args.population,
                         local=False if args.no_local else None)
    except (EngineError, FitError) as error:
        sys.stderr.write("calibrate: %s\n" % error)
        return 1
    except KeyboardInterrupt:
        sys.stderr.write("calibrate: interrupted; the evaluations done so far are kept%s\n"
                         % (" in " + cache if cache else ""))
        return 130
    print(result.table())
    log("%d simulations computed, %d from the cache, %d failed; %.1f s on %s" % (
        result.simulations["computed"], result.simulations["from_cache"], result.simulations["failed"],
        result.wall_s, result.engine))
    if args.out:
        with open(args.out, "w", encoding="utf-8") as file:
            json.dump(_finite(result.to_dict()), file, indent=1)
            file.write("\n")
    if args.scene_out:
        with open(args.scene_out, "w", encoding="utf-8") as file:
            json.dump(result.scene, file, indent=1)
            file.write("\n")
    return 0


def _finite(value):
    """JSON has no inf or NaN: they become null."""
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(v) for v in value]
    return value


if __name__ == "__main__":
    sys.exit(main())
