# SPDX-License-Identifier: Apache-2.0
"""Where evaluations run: in this process, on an embedded Dask LocalCluster (the default),
or on an existing Dask cluster, without another line of the caller changing.

    with Engine() as engine:                                  # LocalCluster, one worker per core
    with Engine(scheduler="tcp://10.0.0.5:8786") as engine:   # a cluster that is already running
    with Engine(workers=0) as engine:                         # no Dask: in this process
        results = engine.map(function, shared, items, store)  # function(shared, item), in item order

Order. map returns the results in the order of items, whatever order they finished in, so
a caller that decides from them (the search) decides the same on 1 worker or 100.

The library on the workers (library=):
  "inherit"  the LocalCluster's workers are this machine's processes: they get this
             process's ENTERON_LIBRARY (the library it loaded) and PYTHONPATH (this package).
  "upload"   for a cluster elsewhere: this package (as a zip) and the library this process
             loaded are sent to every worker, also to those that join later (Dask worker
             plugins), and the workers import them from there. They need Python 3 with
             numpy and the same Dask, and a CPU and C library that can run the build.
  "installed" the workers import their own enteron (python3-enteron, a shared file system).
  "auto"     inherit for the LocalCluster, upload for a scheduler address.
Every result carries the sha256 of the library that computed it; the caller refuses a
result from another build (it would not be bit-identical).

Progress: a bar on stderr (done, from the cache, failed, workers, elapsed); Dask's
dashboard when dashboard=True (it needs bokeh >= 2.4.2, < 3, which Debian 12 does not
package: without it Dask serves a page that says so, and the bar is what there is).
Everything listens on 127.0.0.1 only, unless scheduler= names another address.
"""
import hashlib
import logging
import os
import sys
import tempfile
import time
import warnings
import zipfile

_PACKAGE_DIRECTORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # .../enteron


class EngineError(RuntimeError):
    """The engine cannot start or reach its workers (the message says what to check)."""


class Progress:
    """A one-line progress bar on a stream: redrawn in place on a terminal, a line every
    few seconds otherwise (a CI log). on_update(done, total) is called at every change."""

    last_line = 0.0  # when the last line went to a log (shared: one fit draws many bars)

    def __init__(self, stream=None, enabled=True, on_update=None, interval_s=5.0):
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = enabled
        self.on_update = on_update
        self.interval_s = interval_s
        self.tty = hasattr(self.stream, "isatty") and self.stream.isatty()

    def start(self, label, total, cached, workers):
        self.label, self.total, self.cached, self.workers = label, total, cached, workers
        self.done, self.failed = cached, 0
        self.started = time.monotonic()
        self._draw()

    def advance(self, failed=False):
        self.done += 1
        self.failed += int(failed)
        if self.on_update is not None:
            self.on_update(self.done, self.total)
        self._draw()

    def _draw(self):
        if not self.enabled or self.total == 0:
            return
        now = time.monotonic()
        if not self.tty:  # a log: a line every interval_s at most, across bars
            if now - Progress.last_line < self.interval_s:
                return
            Progress.last_line = now
        width = 30
        filled = int(width * self.done / self.total)
        text = "%s [%s%s] %d/%d (%d from the cache, %d failed) on %s, %.1f s" % (
            self.label, "#" * filled, "." * (width - filled), self.done, self.total, self.cached, self.failed,
            self.workers, now - self.started)
        if self.tty:
            self.stream.write("\r" + text + ("\n" if self.done == self.total else ""))
        else:
            self.stream.write(text + "\n")
        self.stream.flush()


class Engine:
    """Runs function(shared, item) for many items, in this process or on Dask workers
    (see the module's comment). A context manager: closing it stops an embedded cluster."""

    def __init__(self, scheduler=None, workers=None, dashboard=False, progress=True, library="auto",
                 on_progress=None, stream=None):
        if library not in ("auto", "inherit", "upload", "installed"):
            raise ValueError("library must be one of auto, inherit, upload, installed, got %r" % (library,))
        self.progress = Progress(stream, progress, on_progress)
        self.stream = self.progress.stream
        self.client = None
        self.cluster = None
        self._shared = {}
        self.tasks = 0
        self.library = None  # how the workers get the library (see the module's comment); None: no workers
        if scheduler is None and workers == 0:
            self.description = "this process"
            return
        # Tornado 6.2 (Debian 12) warns about an event-loop call that Dask 2022.12 makes: not ours to fix.
        warnings.filterwarnings("ignore", category=DeprecationWarning, module="tornado")
        try:
            import distributed
        except ImportError:
            raise EngineError("Dask's distributed scheduler is not installed (Debian: python3-distributed; "
                              "scripts/install-deps); use workers=0 (--workers 0) to evaluate in this process") from None
        if scheduler is None:
            self._start_local_cluster(distributed, workers, dashboard)
            library = "inherit" if library == "auto" else library
        else:
            try:
                self.client = distributed.Client(scheduler, timeout="30s")
            except (OSError, TimeoutError) as error:
                raise EngineError("cannot reach the Dask scheduler at %s: %s" % (scheduler, error)) from None
            library = "upload" if library == "auto" else library
            if dashboard:
                self._say("Dask's dashboard (the scheduler's): %s" % self.client.dashboard_link)
        if library == "inherit" and self.cluster is None:
            raise ValueError("library='inherit' applies to the embedded LocalCluster only")
        if library == "upload":
            self._upload_package()
        if library in ("upload", "installed"):
            from .simulate import library_sha256
            self._check_workers(library_sha256())
        self.library = library
        self.description = self._describe()

    # ---- starting ---------------------------------------------------------------------------
    def _start_local_cluster(self, distributed, workers, dashboard):
        import enteron
        # The workers are spawned processes: they inherit this environment.
        os.environ["ENTERON_LIBRARY"] = os.path.abspath(enteron.library_path)
        parent = os.path.dirname(_PACKAGE_DIRECTORY)
        paths = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]
        if parent not in paths:
            os.environ["PYTHONPATH"] = os.pathsep.join([parent] + paths)
        if dashboard and not _has_bokeh():
            self._say("Dask's dashboard needs bokeh >= 2.4.2, < 3 (not packaged in Debian 12): the page at "
                      "http://127.0.0.1:8787/status says so, and the progress bar is what there is")
        count = workers if workers is not None else (os.cpu_count() or 1)
        try:
            self.cluster = distributed.LocalCluster(
                n_workers=count, threads_per_worker=1, processes=True, host="127.0.0.1",
                dashboard_address="127.0.0.1:8787" if dashboard else "127.0.0.1:0",
                silence_logs=logging.ERROR)
        except Exception as error:  # Dask raises many kinds here (ports, spawn, timeouts)
            raise EngineError("cannot start a Dask LocalCluster of %d worker(s): %s" % (count, error)) from None
        self.client = distributed.Client(self.cluster)
        if dashboard:
            self._say("Dask's dashboard: %s" % self.client.dashboard_link)

    def _upload_package(self):
        """Sends this package (a zip) and the library this process loaded to every worker,
        present and future, as Dask worker plugins; the zip's _install.py points the package
        at the library beside it in the worker's directory. Not when every worker already
        runs this library: a plugin registered again rewrites its files, and rewriting a
        loaded library in place crashes the process that maps it."""
        import enteron
        from distributed.diagnostics.plugin import UploadFile

        from .simulate import library_sha256
        digest = library_sha256()
        try:
            if set(self.client.run(library_sha256).values()) == {digest}:
                return  # they have it (an earlier upload, which also reaches workers that join later)
        except Exception:  # a worker that cannot import enteron: the upload is what it needs
            pass
        library_name = "libenteron-%s.so" % digest[:16]
        package_name = "enteron-%s.zip" % digest[:16]
        with tempfile.TemporaryDirectory(prefix="enteron-upload-") as directory:
            library_copy = os.path.join(directory, library_name)
            with open(enteron.library_path, "rb") as source, open(library_copy, "wb") as target:
                target.write(source.read())
            package_zip = os.path.join(directory, package_name)
            with zipfile.ZipFile(package_zip, "w", zipfile.ZIP_DEFLATED) as archive:
                for folder, subfolders, files in os.walk(_PACKAGE_DIRECTORY):
                    subfolders[:] = [s for s in subfolders if s != "__pycache__"]
                    for name in files:
                        if name.endswith(".py") and name != "_install.py":
                            path = os.path.join(folder, name)
                            archive.write(path, os.path.join("enteron", os.path.relpath(path, _PACKAGE_DIRECTORY)))
                # worker directory/enteron-<digest>.zip/enteron -> worker directory/libenteron-<digest>.so
                archive.writestr("enteron/_install.py", "LIBRARY_RELATIVE_PATH = %r\n" % ("../../" + library_name))
            # The library first: importing the zip (at its upload) loads it.
            for path, name in ((library_copy, "enteron-library"), (package_zip, "enteron-package")):
                try:
                    self.client.register_worker_plugin(UploadFile(path), name=name)
                except Exception as error:
                    raise EngineError("cannot send %s to the Dask workers: %s (they need Python 3 with numpy; "
                                      "library='installed' uses their own enteron)" % (os.path.basename(path), error)) from None

    def _check_workers(self, digest):
        from .simulate import library_sha256
        try:
            found = self.client.run(library_sha256)
        except Exception as error:
            raise EngineError("a Dask worker cannot import enteron: %s" % error) from None
        for worker, worker_digest in sorted(found.items()):
            if worker_digest != digest:
                raise EngineError("Dask worker %s runs another libenteron (sha256 %s, this process: %s): results "
                                  "would not be bit-identical; restart the workers that had imported another enteron, "
                                  "or use library='upload'" % (worker, worker_digest, digest))

    def _describe(self):
        workers = len(self.client.scheduler_info().get("workers", {}))
        where = "a LocalCluster" if self.cluster is not None else self.client.scheduler.address
        return "%d Dask worker(s) (%s)" % (workers, where)

    def _say(self, text):
        self.stream.write("engine: %s\n" % text)
        self.stream.flush()

    def program(self, path):
        """An executable the workers can run with run_program (bench/study's enteron_study): on
        this machine's workers, path itself; for library="upload", sent to every worker (a
        Dask worker plugin, like the library, which it finds beside it)."""
        program = Program(path)
        if self.client is not None and self.library == "upload":
            from distributed.diagnostics.plugin import UploadFile
            program.uploaded_as = "%s-%s" % (os.path.basename(program.path), program.sha256[:16])
            with tempfile.TemporaryDirectory(prefix="enteron-upload-") as directory:
                copy = os.path.join(directory, program.uploaded_as)
                with open(program.path, "rb") as source, open(copy, "wb") as target:
                    target.write(source.read())
                self.client.register_worker_plugin(UploadFile(copy), name="enteron-program-" + program.sha256[:16])
        return program

    # ---- running ----------------------------------------------------------------------------
    @property
    def worker_count(self):
        if self.client is None:
            return 0
        return len(self.client.scheduler_info().get("workers", {}))

    def map(self, function, shared, items, store=None, label="evaluations"):
        """[function(shared, item) for item in items], in order. store, if given, has
        lookup(item) -> result or None and save(item, result): results found are not computed
        again, and each computed one is saved as soon as it arrives (an interrupted map keeps
        them). function and shared must pickle (function by reference: a module's function)."""
        results = [store.lookup(item) if store is not None else None for item in items]
        missing = [i for i, result in enumerate(results) if result is None]
        self.progress.start(label, len(items), len(items) - len(missing), self.description)
        if self.client is None:
            for i in missing:
                results[i] = function(shared, items[i])
                self._finished(store, items[i], results[i])
            return results
        from distributed import as_completed
        shared_future = self._scatter(shared)
        futures = {}
        for i in missing:
            futures[self.client.submit(function, shared_future, items[i], pure=False, retries=1)] = i
        self.tasks += len(futures)
        try:
            for future in as_completed(list(futures)):
                i = futures[future]
                results[i] = future.result()
                self._finished(store, items[i], results[i])
        except BaseException:
            self.client.cancel(list(futures))
            raise
        return results

    def _finished(self, store, item, result):
        if store is not None:
            store.save(item, result)
        self.progress.advance(failed=getattr(result, "failure", None) is not None)

    def _scatter(self, shared):
        key = id(shared)
        if key not in self._shared or self._shared[key][0] is not shared:
            future = self.client.scatter(shared, broadcast=True, hash=False)
            self._shared[key] = (shared, future)
        return self._shared[key][1]

    # ---- lifetime ---------------------------------------------------------------------------
    def close(self):
        self._shared.clear()
        if self.client is not None:
            self.client.close()
            self.client = None
        if self.cluster is not None:
            self.cluster.close()
            self.cluster = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False


def _has_bokeh():
    try:
        import distributed.dashboard.scheduler  # noqa: F401 (what Dask itself tries)
        return True
    except ImportError:
        return False



class Program:
    """An executable for the workers (Engine.program): its path here, its sha256 (part of
    any cache key made from its output), and the name it was uploaded as, if it was."""

    def __init__(self, path):
        self.path = os.path.abspath(path)
        with open(self.path, "rb") as file:
            self.sha256 = hashlib.sha256(file.read()).hexdigest()
        self.uploaded_as = None


def run_program(program, arguments):
    """Worker side: runs program with arguments (a list of str) and returns its standard
    output (bytes); RuntimeError with the end of its standard error if it fails. An
    uploaded program runs from the worker's directory, with the library uploaded beside it
    found as libenteron.so.0 (LD_LIBRARY_PATH)."""
    import subprocess
    path, environment = program.path, None
    if program.uploaded_as is not None:
        from distributed import get_worker

        from .simulate import library_sha256
        directory = get_worker().local_directory
        path = os.path.join(directory, program.uploaded_as)
        os.chmod(path, 0o755)
        libraries = os.path.join(directory, "enteron-lib-" + library_sha256()[:16])
        os.makedirs(libraries, exist_ok=True)
        link = os.path.join(libraries, "libenteron.so.0")
        if not os.path.exists(link):
            os.symlink(os.path.join(directory, "libenteron-%s.so" % library_sha256()[:16]), link)
        environment = dict(os.environ, LD_LIBRARY_PATH=libraries)
    done = subprocess.run([path] + list(arguments), capture_output=True, env=environment, stdin=subprocess.DEVNULL)
    if done.returncode != 0:
        raise RuntimeError("%s %s failed (status %d): %s" % (os.path.basename(path), " ".join(arguments),
                                                             done.returncode, done.stderr.decode(errors="replace")[-2000:]))
    return done.stdout
