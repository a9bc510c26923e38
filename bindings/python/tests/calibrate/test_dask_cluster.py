# SPDX-License-Identifier: Apache-2.0
"""A real Dask cluster on this machine: a dask-scheduler and two dask-worker processes,
started here, listening on 127.0.0.1 only (checked: every socket they listen on is on the
loopback), with a clean environment (no PYTHONPATH, no ENTERON_LIBRARY: the engine sends
them this package and the library, as it would to another machine). The fit run through
them gives the result of the fit in this process bit for bit; a second fit, during which
one worker is killed (SIGKILL) while it computes, still finishes, with the same result.
The figures (tasks, workers, time, the killed worker) are printed. bench/study's program,
sent to the workers the same way, gives the records it gives here. About 30 s."""
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import unittest

import calibrate_support as support
from enteron import calibrate

DASK_BIN = os.path.dirname(shutil.which("dask-scheduler") or "/usr/bin/dask-scheduler")


def free_port():
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def listening_addresses(pids):
    """The local addresses of the TCP sockets the processes pids listen on (ss -ltnp)."""
    output = subprocess.run(["ss", "-ltnpH"], capture_output=True, text=True, check=True).stdout
    found = []
    for line in output.splitlines():
        owners = {int(pid) for pid in re.findall(r"pid=(\d+)", line)}
        if owners & set(pids):
            found.append(line.split()[3])
    return found


class DaskCluster(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if shutil.which("ss") is None:
            raise unittest.SkipTest("ss (iproute2) is needed to check the listening addresses")
        cls.directory = tempfile.mkdtemp(prefix="calibrate-cluster-")
        cls.address = "tcp://127.0.0.1:%d" % free_port()
        clean = {key: value for key, value in os.environ.items() if key not in ("PYTHONPATH", "ENTERON_LIBRARY")}
        cls.processes = {}

        def start(name, argv):
            log = open(os.path.join(cls.directory, name + ".log"), "w")
            cls.processes[name] = subprocess.Popen(argv, env=clean, cwd=cls.directory, stdout=log, stderr=log,
                                                   stdin=subprocess.DEVNULL, start_new_session=True)

        start("scheduler", [sys.executable, os.path.join(DASK_BIN, "dask-scheduler"), "--host", "127.0.0.1", "--port",
                            cls.address.rsplit(":", 1)[1], "--dashboard-address", "127.0.0.1:0", "--no-dashboard",
                            "--no-show"])
        for name in ("worker-1", "worker-2"):
            start(name, [sys.executable, os.path.join(DASK_BIN, "dask-worker"), cls.address, "--name", name,
                         "--host", "127.0.0.1", "--nthreads", "1", "--nworkers", "1", "--no-nanny",
                         "--dashboard-address", "127.0.0.1:0", "--no-dashboard", "--death-timeout", "60",
                         "--local-directory", os.path.join(cls.directory, name)])
        from distributed import Client
        with Client(cls.address, timeout="60s") as client:
            client.wait_for_workers(2, timeout=60)
        cls.experiment, cls.data = support.small_fit_problem()
        with calibrate.Engine(workers=0, progress=False) as engine:
            cls.local = calibrate.fit(cls.experiment, cls.data, engine)

    @classmethod
    def tearDownClass(cls):
        for process in cls.processes.values():
            if process.poll() is None:
                os.killpg(process.pid, signal.SIGTERM)
        for process in cls.processes.values():
            try:
                process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()
        shutil.rmtree(cls.directory, ignore_errors=True)

    def test_1_listens_on_the_loopback_only(self):
        addresses = listening_addresses([p.pid for p in self.processes.values()])
        self.assertGreaterEqual(len(addresses), 3, addresses)  # the scheduler and both workers
        for address in addresses:
            self.assertTrue(address.startswith("127.0.0.1:"), address)

    def test_2_the_cluster_gives_the_local_result_bit_for_bit(self):
        started = time.monotonic()
        with calibrate.Engine(scheduler=self.address, progress=False) as engine:
            self.assertEqual(engine.library, "upload")
            self.assertEqual(engine.worker_count, 2)
            result = calibrate.fit(self.experiment, self.data, engine)
            tasks = engine.tasks
        support.print_table("Dask cluster: the fit through the scheduler", [
            ["tasks", "workers", "wall s", "same bits as in one process"],
            [str(tasks), "2", "%.1f" % (time.monotonic() - started),
             str(support.result_bits(result) == support.result_bits(self.local))]])
        self.assertEqual(support.result_bits(result), support.result_bits(self.local))
        self.assertEqual(tasks, self.local.simulations["computed"])

    def test_3_a_worker_killed_mid_run_and_the_fit_still_finishes(self):
        victim = self.processes["worker-2"]
        killed = {}

        def kill_once(done, total):
            if not killed and engine.tasks >= 30:
                os.kill(victim.pid, signal.SIGKILL)
                killed.update(after_tasks=engine.tasks, done_in_batch=done, batch=total)

        started = time.monotonic()
        with calibrate.Engine(scheduler=self.address, progress=False, on_progress=kill_once) as engine:
            workers_before = engine.worker_count
            result = calibrate.fit(self.experiment, self.data, engine)
            tasks = engine.tasks
            workers_after = engine.worker_count
        wall = time.monotonic() - started
        victim.wait(timeout=10)
        support.print_table("Dask cluster: worker-2 killed (SIGKILL) mid-run", [
            ["tasks", "workers at the start", "at the end", "killed", "wall s", "same bits"],
            [str(tasks), str(workers_before), str(workers_after),
             "worker-2 (pid %d) after %d tasks were submitted, %d of a batch of %d done"
             % (victim.pid, killed["after_tasks"], killed["done_in_batch"], killed["batch"]),
             "%.1f" % wall, str(support.result_bits(result) == support.result_bits(self.local))]])
        self.assertTrue(killed)
        self.assertLess(killed["done_in_batch"], killed["batch"], "killed while its batch was in flight")
        self.assertEqual(victim.returncode, -signal.SIGKILL)
        self.assertEqual((workers_before, workers_after), (2, 1))
        self.assertEqual(support.result_bits(result), support.result_bits(self.local))


    def test_4_a_program_sent_to_the_workers_gives_the_same_bytes(self):
        # bench/study's enteron_study, uploaded with the library: its runs (the distributed
        # study's error part) give the records this machine gives.
        program_path = os.environ.get("ENTERON_STUDY", "")
        if not os.path.exists(program_path):
            self.skipTest("ENTERON_STUDY (bench/study's enteron_study) is not built")
        from enteron.calibrate.engine import Program, run_program
        tasks = [["--tiny", "--run", name] for name in ("mechanics swing rk4 15 0.001", "mechanics drop bdf2 30 0.0001")]
        local = [run_program(Program(program_path), task) for task in tasks]
        with calibrate.Engine(scheduler=self.address, progress=False) as engine:
            program = engine.program(program_path)
            self.assertIsNotNone(program.uploaded_as)
            remote = engine.map(run_program, program, tasks)

        def without_wall_time(record):  # the one timing a record holds: how long the run took
            return [line for line in record.splitlines() if not line.startswith(b"wall_s ")]

        self.assertEqual([without_wall_time(r) for r in remote], [without_wall_time(r) for r in local])
        self.assertIn(b"axes ", local[0])


if __name__ == "__main__":
    unittest.main()
