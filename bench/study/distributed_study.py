#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The accuracy study with its error part on Dask (docs/accuracy.md, "The distributed study").

    distributed_study.py ENTERON_STUDY OUT_DIR [--grid full|fast|tiny] [--part NAME ...]
                         [--scheduler tcp://HOST:PORT | --workers N] [--cache DIR]
                         [--timing-core CPU] [--timing-steps N]

1. The error part: every run the mechanics, collision and tool parts need
   (enteron_study --list-runs) is computed on its own (enteron_study --run NAME) as a task
   of enteron.calibrate's engine: an embedded LocalCluster by default, or the cluster of
   --scheduler (the program and the library are sent to its workers). The runs are
   deterministic, so where they ran does not change a bit of them. Each run's record is
   kept in the cache (keyed by the program's and the library's sha256, the grid and the
   run's name) as soon as it arrives: an interrupted study resumes where it stopped.
2. The engine stops (its workers leave this machine's cores).
3. The timing part, serial, on one core: enteron_study --runs OUT_DIR/runs pinned to
   --timing-core (default: the last one) reads the records, times each run's window alone
   and writes the CSV files; the parts that only time (skins, effects, peers) run there too.
   Timings measured while other runs share the cores would measure the sharing.

Exit status: 0, or the failing step's. scripts/study --dask runs this, then the report.
"""
import argparse
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bindings", "python"))

from enteron.calibrate import cache as cache_module  # noqa: E402 (after the path)
from enteron.calibrate.engine import Engine, EngineError, Program, run_program  # noqa: E402
from enteron.calibrate.simulate import library_sha256  # noqa: E402

DISTRIBUTED_PARTS = ("mechanics", "collision", "tool")


class RunStore:
    """The engine's store for run records: on disk, keyed by what makes a record what it is."""

    def __init__(self, directory, program, mode):
        self.cache = cache_module.DiskCache(directory)
        self.prefix = (program.sha256, library_sha256(), mode)

    def _key(self, arguments):
        return cache_module.key(*self.prefix, arguments[-1])

    def lookup(self, arguments):
        return self.cache.get(self._key(arguments))

    def save(self, arguments, record):
        self.cache.put(self._key(arguments), record)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("program", help="enteron_study")
    p.add_argument("out", help="the CSV files go here; the run records into OUT/runs")
    p.add_argument("--grid", choices=("full", "fast", "tiny"), default="full", help="enteron_study's grid")
    p.add_argument("--part", action="append", default=[], help="as enteron_study's (default: all)")
    p.add_argument("--scheduler", metavar="tcp://HOST:PORT", help="an existing Dask scheduler")
    p.add_argument("--workers", type=int, help="LocalCluster workers (default: one per core)")
    p.add_argument("--cache", metavar="DIR", help="run records kept here (default: OUT/run-cache)")
    p.add_argument("--timing-core", type=int, help="the CPU the timing part is pinned to (default: the last)")
    p.add_argument("--timing-steps", type=int, help="outer steps timed per mechanics run (enteron_study's default)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    args = p.parse_args(argv)
    args.mode = "--" + args.grid
    parts = [a for part in args.part for a in ("--part", part)]
    runs_dir = os.path.join(args.out, "runs")
    os.makedirs(runs_dir, exist_ok=True)

    names = []
    if not args.part or any(part in DISTRIBUTED_PARTS for part in args.part):
        wanted = [a for part in args.part if part in DISTRIBUTED_PARTS for a in ("--part", part)]
        listed = subprocess.run([args.program, args.mode, "--list-runs"] + wanted, capture_output=True, text=True,
                                stdin=subprocess.DEVNULL)
        if listed.returncode != 0:
            sys.stderr.write("distributed_study: %s --list-runs failed: %s" % (args.program, listed.stderr))
            return listed.returncode
        names = [line for line in listed.stdout.splitlines() if line]

    started = time.monotonic()
    if names:
        tasks = [[args.mode, "--run", name] for name in names]
        store = RunStore(args.cache or os.path.join(args.out, "run-cache"), Program(args.program), args.mode)
        records = [store.lookup(task) for task in tasks]
        if None in records:  # else no engine at all: everything is in the cache
            try:
                with Engine(scheduler=args.scheduler, workers=args.workers, progress=not args.quiet) as engine:
                    program = engine.program(args.program)
                    sys.stderr.write("distributed_study: %d runs of the error part on %s\n"
                                     % (len(names), engine.description))
                    records = engine.map(run_program, program, tasks, store=store, label="error part")
            except EngineError as error:
                sys.stderr.write("distributed_study: %s\n" % error)
                return 1
        for name, record in zip(names, records):
            with open(os.path.join(runs_dir, name.replace(" ", "+") + ".run"), "wb") as file:
                file.write(record)
        sys.stderr.write("distributed_study: error part done in %.1f s (%d from the cache)\n"
                         % (time.monotonic() - started, store.cache.hits))

    core = args.timing_core if args.timing_core is not None else max(os.sched_getaffinity(0))
    timing = ["taskset", "--cpu-list", str(core), args.program, args.mode, "--runs", runs_dir, "--out", args.out] + parts
    if args.timing_steps is not None:
        timing += ["--timing-steps", str(args.timing_steps)]
    load = os.getloadavg()[0]
    sys.stderr.write("distributed_study: timing part on CPU %d (load average %.2f%s): %s\n"
                     % (core, load, "; other processes share the machine, the timings will show it" if load > 1.0 else "",
                        " ".join(timing)))
    return subprocess.run(timing, stdin=subprocess.DEVNULL).returncode


if __name__ == "__main__":
    sys.exit(main())
