# SPDX-License-Identifier: Apache-2.0
"""enteron.calibrate: fits the constants of a scene to measurements (docs/calibration.md).

    from enteron import calibrate
    experiment = calibrate.load_experiment("cantilever.json")      # or calibrate.experiment_path("cantilever")
    data = calibrate.load_data("measured.csv", experiment)
    with calibrate.Engine() as engine:                               # Dask LocalCluster; scheduler="tcp://..."
        result = calibrate.fit(experiment, data, engine, cache_directory="fit-cache")
    print(result.table())

An experiment is a scene, a script of what its tools and obstacles do, what is measured
(axis points, a tool's force, a sag) and which of the scene's numbers may change (JSON
paths with bounds); the data are the measured values with their times. The fit is a
CMA-ES global search, then a bounded least-squares refinement, then a Hessian-based
uncertainty; its simulations run on Dask (one process per core by default, or any cluster),
bit-identical whatever the number of workers, and kept on disk so that an interrupted fit
resumes. The command: scripts/calibrate (enteron-calibrate when installed).
"""
import os

from .data import Data
from .data import load as load_data
from .data import write as write_data
from .engine import Engine, EngineError
from .experiment import CalibrationError, Experiment
from .experiment import from_dict as experiment_from_dict
from .experiment import load as load_experiment
from .fit import FitError, FitResult, fit
from .simulate import Plan, SimulationFailed

#: The experiments that ship with the package (EXPERIMENTS: their names).
EXPERIMENTS_DIRECTORY = os.path.join(os.path.dirname(os.path.abspath(__file__)), "experiments")
EXPERIMENTS = ("cantilever", "three_point_bending", "hanging_sag", "drop_on_table", "lcm_journal", "tensile_test")


def experiment_path(name):
    """The path of a shipped experiment's file, by name (EXPERIMENTS)."""
    if name not in EXPERIMENTS:
        raise CalibrationError("no shipped experiment %r (they are: %s)" % (name, ", ".join(EXPERIMENTS)))
    return os.path.join(EXPERIMENTS_DIRECTORY, name + ".json")


def synthesize(experiment, requests, values, noise=0.0, seed=0):
    """Data made by the library: the experiment simulated with values (one per parameter) at
    requests [(measurement, t_s), ...], plus Gaussian noise of standard deviation noise (in
    each measurement's unit; 0: none) drawn from numpy's PCG64(seed). The rows carry
    sigma = noise when noise > 0. For testing what an experiment can identify."""
    import numpy as np
    predictions = Plan(experiment, requests).predict(values)
    sigmas = None
    if noise > 0:
        predictions = predictions + np.random.Generator(np.random.PCG64(seed)).normal(0.0, noise, len(predictions))
        sigmas = np.full(len(predictions), float(noise))
    names = [name for name, _ in requests]
    return Data(names, [t for _, t in requests], predictions, sigmas, list(range(len(names))), "<synthesized>")


__all__ = ["CalibrationError", "Data", "EXPERIMENTS", "EXPERIMENTS_DIRECTORY", "Engine", "EngineError", "Experiment",
           "FitError", "FitResult", "Plan", "SimulationFailed", "experiment_from_dict", "experiment_path", "fit",
           "load_data", "load_experiment", "synthesize", "write_data"]
