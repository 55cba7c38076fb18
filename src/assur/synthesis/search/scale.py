"""Scale-out: batches of designs as chunks on Dask (DESIGN.md §8: a choice of
executor, not of code path).

:class:`Executor` evaluates designs either in this process (the default) or as
chunks on a Dask cluster — a :class:`distributed.LocalCluster` of ``workers``
processes started here, or an existing scheduler (``tcp://host:8786``, ``tls://…``,
or a scheduler file). Every chunk is one task of :func:`run_chunk`, the same
function in this process and on a worker:

* a task is self-contained: the problem travels as its recipe — the model's
  content with its ``extends`` chain and the variables, never a path
  (:func:`assur.io.load_problem`) — and a worker rebuilds it once per content hash;
  the task also carries the client's assur version, which the worker checks;
* a sweep's task is a range of design indices: the worker draws its designs from
  (seed, range) (:meth:`Problem.draw`), so the task graph stays small, and returns
  the chunk's Parquet part and summary (:mod:`.dataset`); the client writes each
  part as it arrives and releases its future, so its memory does not grow with the
  number of designs (:func:`sweep_to`);
* the chunk size follows the cluster's threads at each submission (a cluster that
  grows is used as it grows), a window of about two tasks per thread is in flight;
* faults: the tasks of a worker that is lost are recomputed by Dask (at most
  ``distributed.scheduler.allowed-failures`` times, then one message); a worker that
  raises sends its error back (a :class:`~assur.errors.ModelError` stays one); no
  worker for ``timeout`` seconds, a lost scheduler, any other Dask error end in a
  :class:`ClusterError` that says what happened and what to do (the finished parts
  of a sweep stay on disk: ``resume=True`` continues);
* the kernel's threads on a worker follow the worker's ``nthreads`` (divided by the
  tasks it runs at once; ``$ASSUR_THREADS`` wins), and a LocalCluster puts back the
  environment variables its start changed in this process.

:func:`sweep` evaluates given or sampled designs and returns one
:class:`~assur.synthesis.search.problem.Batch` (in memory);
:func:`assur.synthesis.search.search.optimize` takes ``evaluate=executor.evaluate`` to
send each population to the cluster; :func:`write_parquet` stores a batch as a table.
"""

from __future__ import annotations

import contextlib
import gc
import os
import time
from dataclasses import dataclass

import numpy as np

from ...errors import ModelError

__all__ = ["Executor", "ClusterError", "SweepResult", "sweep", "sweep_to", "write_parquet",
           "run_chunk", "Chunk"]

#: seconds without any worker before a cluster run ends with a message
TIMEOUT = 60.0

#: resubmissions of a chunk the scheduler forgot (Dask itself recomputes the chunks of
#: a lost worker, up to distributed.scheduler.allowed-failures times)
RETRIES = 3


class ClusterError(ModelError):
    """A Dask cluster could not finish the work: no worker for too long, the scheduler
    lost, a chunk that killed its workers, another version of assur on a worker.

    Examples
    --------
    >>> from assur.synthesis.search.scale import ClusterError
    >>> raise ClusterError("lost the Dask scheduler at tcp://host:8786")
    Traceback (most recent call last):
    ...
    assur.synthesis.search.scale.ClusterError: lost the Dask scheduler at tcp://host:8786
    """


@dataclass(frozen=True)
class Chunk:
    """One task: designs ``start`` … ``stop − 1`` — given (``X``) or drawn by the worker
    from ``seed`` (:meth:`Problem.draw`) — and what to return: ``"batch"`` (the
    :class:`Batch`) or ``"part"`` (Parquet bytes and summary, :func:`.dataset.part_bytes`).

    Examples
    --------
    >>> from assur.synthesis.search.scale import Chunk
    >>> Chunk(0, 100, seed=1, out="part").size
    100
    """

    start: int
    stop: int
    seed: int | None = None
    X: object = None
    out: str = "batch"
    version: str = ""

    @property
    def size(self) -> int:
        """Designs in the chunk.

        Examples
        --------
        >>> from assur.synthesis.search.scale import Chunk
        >>> Chunk(10, 25).size
        15
        """
        return self.stop - self.start


def run_chunk(problem, chunk):
    """Evaluate one chunk (in this process or as a Dask task): the designs drawn or
    given, one :meth:`Problem.evaluate`, the batch or its Parquet part.

    On a Dask worker, the kernel runs on the worker's threads (``nthreads`` divided by
    the tasks it runs at once), unless ``$ASSUR_THREADS`` says otherwise.

    Examples
    --------
    >>> from assur import io
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.scale import Chunk, run_chunk
    >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
    >>> b = run_chunk(pb, Chunk(0, 40, seed=1))
    >>> len(b), bool((b.X == pb.draw(1, 0, 40)).all())
    (40, True)
    """
    from ... import __version__
    if chunk.version and chunk.version != __version__:
        raise ClusterError(f"this Dask worker runs assur {__version__}, the client assur "
                           f"{chunk.version}: install the same version on every worker")
    with _worker_threads():
        X = chunk.X if chunk.X is not None else problem.draw(chunk.seed, chunk.start,
                                                              chunk.stop)
        batch = problem.evaluate(X)
    # a chunk's mechanism and its kernels' plans form reference cycles that the
    # young generations hold: collected now, else they pile up (1e7 designs: 0.45 →
    # 1.4 GB) until a full collection; 3 ms a chunk
    gc.collect(1)
    if chunk.out == "part":
        from .dataset import part_bytes
        return part_bytes(batch, chunk.start)
    return batch


@contextlib.contextmanager
def _worker_threads():
    """On a Dask worker: the kernel's threads for this task (the worker's threads over
    the tasks it executes now), unless $ASSUR_THREADS is set."""
    if os.environ.get("ASSUR_THREADS"):
        yield
        return
    try:
        from distributed import get_worker
        worker = get_worker()
    except (ImportError, ValueError):  # not on a worker
        yield
        return
    from ...kernel import set_threads
    state = worker.state
    set_threads(max(1, state.nthreads // max(1, state.executing_count)))
    try:
        yield
    finally:
        set_threads(None)


def _versions():
    from ... import __version__
    return __version__


class Executor:
    """Where batches are evaluated.

    Parameters
    ----------
    scheduler : str, optional
        Address of an existing Dask scheduler (``"tcp://host:8786"``, ``"tls://…"``
        with Dask's TLS configuration), or the path of a scheduler file
        (``dask scheduler --scheduler-file``).
    workers : int, optional
        Worker processes of a LocalCluster started here (without ``scheduler``);
        0 or None: evaluate in this process.
    chunk : int
        Designs per task at most.
    progress : callable, optional
        ``progress(done, total)`` after every chunk (designs).
    phase : callable, optional
        ``phase(text)`` when the run enters a phase (connecting, waiting for workers,
        the first chunk — the kernel's compilation —, …).
    timeout : float
        Seconds without any worker after which a cluster run ends with a
        :class:`ClusterError` [s].

    Use as a context manager: the cluster started is closed on exit, and the
    environment variables its start set in this process (Dask's nannies set
    ``OMP_NUM_THREADS=1`` and others before they spawn their workers) are put back.

    Examples
    --------
    Without a scheduler or workers the batches run in this process, here in chunks
    of two designs of the bundled seed-003 design problem:

    >>> from assur import io
    >>> from assur.io import load_problem
    >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
    >>> from assur.synthesis.search.scale import Executor
    >>> with Executor(chunk=2, progress=lambda done, total: print(f"{done}/{total}")) as ex:
    ...     b = ex.evaluate(pb, pb.sample(5, seed=1))
    2/5
    4/5
    5/5
    >>> len(b), ex.describe()
    (5, 'this process')
    >>> Executor(scheduler="tcp://host:8786", workers=2)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: give either a scheduler address or a number of workers, not both
    """

    def __init__(self, scheduler=None, workers=None, chunk=1 << 14, progress=None,
                 phase=None, timeout=TIMEOUT):
        if scheduler is not None and workers:
            raise ModelError("give either a scheduler address or a number of workers, not both")
        if workers is not None and int(workers) < 0:
            raise ModelError(f"workers must be ≥ 0, got {workers}")
        if int(chunk) < 1:
            raise ModelError(f"chunk must be ≥ 1 design, got {chunk}")
        if not float(timeout) > 0:
            raise ModelError(f"timeout must be > 0 s, got {timeout}")
        self.scheduler, self.workers = scheduler, int(workers or 0)
        self.chunk = int(chunk)
        self.progress = progress
        self.phase = phase
        self.timeout = float(timeout)
        self.client = None
        self._phases: set = set()
        self._stack = contextlib.ExitStack()

    @property
    def distributed(self) -> bool:
        """Whether the batches go to a Dask cluster (a scheduler or workers given).

        Examples
        --------
        >>> from assur.synthesis.search.scale import Executor
        >>> Executor().distributed, Executor(workers=2).distributed
        (False, True)
        """
        return self.scheduler is not None or self.workers > 0

    def _phase(self, text):
        if self.phase is not None and text not in self._phases:  # each phase said once
            self._phases.add(text)
            self.phase(text)

    def __enter__(self):
        if self.distributed:
            try:
                self._start()
            except BaseException:  # no `with` body, no __exit__: close what was opened
                self.client = None
                self._stack.close()
                raise
        return self

    def _start(self):
        from distributed import Client, LocalCluster
        if self.scheduler is not None:
            self._phase(f"connecting to {self.describe()}")
            if "://" not in self.scheduler and os.path.isfile(self.scheduler):
                self.client = self._stack.enter_context(Client(scheduler_file=self.scheduler))
            else:
                self.client = self._stack.enter_context(Client(self.scheduler))
        else:
            self._phase(f"starting {self.describe()}")
            # registered first, so called last: after the client and the cluster closed
            started = {}
            self._stack.callback(_restore_environ, dict(os.environ), started)
            cluster = self._stack.enter_context(LocalCluster(
                n_workers=self.workers, threads_per_worker=1, processes=True,
                dashboard_address=":0"))  # its HTTP server on a free port
            started["environ"] = dict(os.environ)
            self.client = self._stack.enter_context(Client(cluster))
        self._check_versions()

    def __exit__(self, *exc):
        client, self.client = self.client, None
        try:
            return self._stack.__exit__(*exc)
        except Exception as e:  # closing a client whose scheduler is gone
            if exc[0] is None:
                raise ClusterError(f"{self.describe()}: {_words(e)}") from None
            return False
        finally:
            del client

    def _check_versions(self):
        """Every worker connected runs this assur version (else one message)."""
        from ... import __version__
        try:
            seen = self.client.run(_versions)
        except Exception as e:  # a worker that cannot even import assur
            raise ClusterError(f"{self.describe()}: cannot ask the workers for their assur "
                               f"version: {_words(e)} (is assur installed on every "
                               f"worker?)") from None
        other = {w: v for w, v in seen.items() if v != __version__}
        if other:
            listed = ", ".join(f"{w} runs {v}" for w, v in sorted(other.items())[:4])
            raise ClusterError(f"{self.describe()}: the client runs assur {__version__}, "
                               f"but {listed}: install the same version on every worker")

    def describe(self) -> str:
        """Where the batches run, in words (no cluster is started to say it).

        Examples
        --------
        >>> from assur.synthesis.search.scale import Executor
        >>> Executor().describe()
        'this process'
        >>> Executor(workers=2).describe()
        'Dask LocalCluster of 2 worker processes'
        >>> Executor(scheduler="tcp://host:8786").describe()
        'Dask scheduler tcp://host:8786'
        """
        if self.scheduler is not None:
            return f"Dask scheduler {self.scheduler}"
        if self.workers:
            return f"Dask LocalCluster of {self.workers} worker processes"
        return "this process"

    # ---- the cluster's size ------------------------------------------------------------
    def threads(self) -> int:
        """Threads of the workers connected now (1 in this process).

        Examples
        --------
        >>> from assur.synthesis.search.scale import Executor
        >>> Executor().threads()
        1
        """
        if self.client is None:
            return 1
        info = self.client.scheduler_info(n_workers=-1)
        return sum(int(w.get("nthreads", 1)) for w in info.get("workers", {}).values())

    # ---- evaluation --------------------------------------------------------------------
    def evaluate(self, problem, X):
        """:meth:`Problem.evaluate` of ``X``, shape (m, number of variables), chunk by
        chunk (on the cluster: one task per chunk, as many chunks as the workers have
        threads, in parallel); returns one Batch.

        Examples
        --------
        Three chunks of the bundled seed-003 design problem, concatenated in order:

        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> from assur.synthesis.search.scale import Executor
        >>> X = pb.sample(5, seed=1)
        >>> b = Executor(chunk=2).evaluate(pb, X)
        >>> len(b), bool((b.X == X).all()), b.status.tolist() == pb.evaluate(X).status.tolist()
        (5, True, True)
        >>> Executor(workers=2).evaluate(pb, X)  # a cluster is started by `with` only
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: use the Executor in a `with` block to start its cluster
        """
        X = np.atleast_2d(np.asarray(X, float))
        return self._batch(problem, len(X), lambda a, b: Chunk(a, b, X=X[a:b]))

    def sample(self, problem, samples, seed):
        """The :class:`Batch` of designs 0 … samples − 1 drawn from ``seed``
        (:meth:`Problem.draw`; on a cluster, each worker draws its chunk).

        Examples
        --------
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> from assur.synthesis.search.scale import Executor
        >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
        >>> b = Executor(chunk=16).sample(pb, 40, seed=2)
        >>> len(b), bool((b.X == pb.draw(2, 0, 40)).all())
        (40, True)
        """
        seed = int(seed)
        return self._batch(problem, int(samples), lambda a, b: Chunk(a, b, seed=seed))

    def _batch(self, problem, total, make):
        from .problem import Batch
        if self.client is None and self.distributed:
            raise ModelError("use the Executor in a `with` block to start its cluster")
        parts = {}
        self.run(problem, [(0, total)], make, lambda c, r: parts.__setitem__(c.start, r),
                 split=self.client is not None)
        parts = [parts[k] for k in sorted(parts)]
        return parts[0] if len(parts) == 1 else Batch.concat(problem, parts)

    def run(self, problem, ranges, make, handle, split=False):
        """Evaluate the designs of ``ranges`` (``[(start, stop), …]``) chunk by chunk:
        ``make(a, b)`` gives the :class:`Chunk` of designs a … b − 1 and
        ``handle(chunk, result)`` takes each result as it comes (in this process: in
        order; on a cluster: as the chunks complete), after which it is released.

        ``split``: cut the ranges into at least one chunk per thread of the cluster
        (a population smaller than chunk × threads still fills the workers).

        Raises
        ------
        ClusterError
            No worker for :attr:`timeout` seconds, the scheduler lost, a chunk that
            killed its workers, or another Dask error — with what to do.

        Examples
        --------
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> from assur.synthesis.search.scale import Chunk, Executor
        >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
        >>> seen = []
        >>> Executor(chunk=4).run(pb, [(0, 6), (10, 12)], lambda a, b: Chunk(a, b, seed=1),
        ...                       lambda c, b: seen.append((c.start, c.stop, len(b))))
        >>> seen
        [(0, 4, 4), (4, 6, 2), (10, 12, 2)]
        """
        total = sum(b - a for a, b in ranges)
        if self.client is None:
            done = 0
            self._phase("first chunk (a new kernel compiles)")
            for a, b in ranges:
                for s in range(a, b, self.chunk):
                    c = make(s, min(b, s + self.chunk))
                    result = run_chunk(problem, c)
                    self._phase("evaluating")
                    handle(c, result)
                    done += c.size
                    if self.progress:
                        self.progress(done, total)
            return
        _Run(self, problem, ranges, make, handle, split).loop()


class _Run:
    """One cluster run: the submission window, the results as they complete, the
    faults turned into messages."""

    def __init__(self, ex, problem, ranges, make, handle, split):
        from ... import __version__
        self.ex, self.problem, self.make, self.handle = ex, problem, make, handle
        self.version = __version__
        self.todo = [list(r) for r in ranges if r[1] > r[0]]
        self.total = sum(b - a for a, b in self.todo)
        self.split = split
        self.done = 0
        self.inflight: dict = {}  # future key -> (future, chunk)
        self.nthreads = 0
        self.checked = 0.0
        self.no_workers_since = None
        self.retries: dict = {}  # chunk start -> resubmissions

    def _size(self, remaining):
        """Designs of the next chunk: at most --chunk, and the rest shared by the
        threads so that the last chunks end together."""
        n = max(1, self.nthreads)
        share = -(-remaining // n)
        if self.split:
            return max(1, min(self.ex.chunk, share))
        return max(1, min(self.ex.chunk, max(256, share)))

    def _threads(self):
        now = time.monotonic()
        if now - self.checked >= 0.5:
            self.checked = now
            self.nthreads = self.ex.threads()
        return self.nthreads

    def _submit(self):
        remaining = sum(b - a for a, b in self.todo)
        window = max(2, 2 * self.nthreads)
        plan = []
        while self.todo and len(self.inflight) + len(plan) < window:
            a, b = self.todo[0]
            size = self._size(remaining)
            stop = min(b, a + size)
            plan.append(self.make(a, stop))
            remaining -= stop - a
            if stop >= b:
                self.todo.pop(0)
            else:
                self.todo[0][0] = stop
        for c in plan:
            c = Chunk(c.start, c.stop, c.seed, c.X, c.out, self.version)
            f = self.ex.client.submit(run_chunk, self.problem, c, pure=False)
            self.inflight[f.key] = (f, c)

    def loop(self):
        from distributed import wait
        ex = self.ex
        first = True
        self._threads()
        ex._phase("first chunks (the workers build the problem; a new kernel compiles)")
        try:
            while self.todo or self.inflight:
                self._threads()
                self._watch_workers()
                self._submit()
                futures = [f for f, _ in self.inflight.values()]
                try:
                    done, _ = wait(futures, timeout=1.0, return_when="FIRST_COMPLETED")
                except TimeoutError:
                    continue
                for f in done:
                    _, c = self.inflight.pop(f.key)
                    if f.status in ("cancelled", "lost") and self._resubmit(f, c):
                        continue
                    result = self._result(f, c)
                    f.release()
                    if first:
                        ex._phase("evaluating")
                        first = False
                    self.handle(c, result)
                    del result
                    self.done += c.size
                    if ex.progress:
                        ex.progress(self.done, self.total)
        except ClusterError:
            raise
        except (ModelError, ValueError, MemoryError):
            raise
        except Exception as e:  # the scheduler lost, a comm closed: one message
            raise ClusterError(self._lost(e)) from None
        finally:
            for f, _ in self.inflight.values():
                with contextlib.suppress(Exception):
                    f.release()
            self.inflight.clear()

    def _resubmit(self, f, c):
        """A chunk the scheduler forgot while it still runs (a worker's data lost, a
        restart): submitted again, at most :data:`RETRIES` times; False when the
        scheduler is gone or the retries are spent."""
        if self.ex.client.status != "running":
            return False
        n = self.retries.get(c.start, 0)
        if n >= RETRIES:
            return False
        self.retries[c.start] = n + 1
        f.release()
        g = self.ex.client.submit(run_chunk, self.problem, c, pure=False)
        self.inflight[g.key] = (g, c)
        return True

    def _watch_workers(self):
        ex = self.ex
        if ex.client.status not in ("running", "connecting", "newly-created"):
            raise ClusterError(self._lost(None))
        if self.nthreads:
            self.no_workers_since = None
            return
        now = time.monotonic()
        if self.no_workers_since is None:
            self.no_workers_since = now
            ex._phase(f"waiting for workers ({ex.describe()} has none now)")
        elif now - self.no_workers_since > ex.timeout:
            raise ClusterError(
                f"{ex.describe()} has had no worker for {ex.timeout:g} s "
                f"({self.done} of {self.total} designs done): start workers "
                f"(dask worker {ex.scheduler or 'ADDRESS'}) and run again"
                + (" with --resume" if any(c.out == "part" for _, c in
                                             self.inflight.values()) else ""))

    def _lost(self, e):
        why = f" ({type(e).__name__})" if e is not None else ""
        return (f"lost the connection to {self.ex.describe()}{why} after {self.done} of "
                f"{self.total} designs; check that the scheduler runs, then run again")

    def _result(self, f, c):
        from distributed import CancelledError
        if f.status == "finished":
            try:
                return f.result()
            except Exception as e:  # the result could not come (the scheduler lost)
                raise ClusterError(self._lost(e)) from None
        if f.status == "error":
            exc = f.exception()
            if type(exc).__name__ == "KilledWorker":
                raise ClusterError(
                    f"designs {c.start} … {c.stop - 1} were on Dask workers that died "
                    f"{_allowed_failures() + 1} times (out of memory? a crash? see the "
                    f"workers' logs); make the chunks smaller (--chunk) or the workers "
                    f"larger") from None
            if isinstance(exc, (ModelError, ValueError, MemoryError)):
                raise exc
            raise ClusterError(f"a Dask worker failed on designs {c.start} … {c.stop - 1}: "
                               f"{type(exc).__name__}: {_words(exc)}") from None
        # cancelled or lost: the scheduler forgot it (it restarted, or we lost it)
        if self.ex.client.status != "running":
            raise ClusterError(self._lost(None))
        raise ClusterError(self._lost(CancelledError()))


def _allowed_failures() -> int:
    import dask
    return int(dask.config.get("distributed.scheduler.allowed-failures", 3))


def _words(e) -> str:
    text = " ".join(str(e).split())[:300]
    return text or type(e).__name__


def _restore_environ(before, started):
    """Undo what starting a LocalCluster changed in ``os.environ``: every variable
    whose value differs between ``before`` and ``started["environ"]`` (the environment
    right after the start; all differences from ``before`` if the start failed) and
    still has the value the start gave it — a variable changed since by the caller
    is left as it is."""
    after = started.get("environ", dict(os.environ))
    for key in set(before) | set(after):
        old, new = before.get(key), after.get(key)
        if old == new or os.environ.get(key) != new:
            continue
        if old is None:
            os.environ.pop(key, None)
        else:
            os.environ[key] = old


def sweep(problem, X=None, *, samples=None, seed=None, executor=None):
    """Evaluate designs ``X`` [SI] (or ``samples`` drawn uniformly within the bounds,
    :meth:`Problem.draw`) and return them as one Batch (in memory; for a sweep too
    large for memory, :func:`sweep_to`).

    Parameters
    ----------
    problem : Problem
    X : array_like, shape (m, number of variables), optional
    samples : int, optional
        Draw this many designs instead of ``X``.
    seed : int, optional
        Default 0.
    executor : Executor, optional
        Default: this process.

    Returns
    -------
    Batch

    Examples
    --------
    2000 designs of the seed-003 hitch drawn with its pivots within ±30 mm (the
    bundled design problem) checked at 10 positions: 40 meet every constraint.

    >>> from assur import io
    >>> from assur.io import load_problem
    >>> pb = load_problem(io.bundled("hitch_003_design"), positions=10)  # pivots ±30 mm
    >>> from assur.synthesis.search.scale import sweep
    >>> b = sweep(pb, samples=2000, seed=1)
    >>> len(b), int(b.feasible.sum()), b.best()
    (2000, 40, 1072)
    >>> round(float(b.objective()[1072]), 3)  # its min capacity reserve at S6 [%]
    13.997
    >>> sweep(pb)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: sweep: give the designs X or a number of samples
    """
    if (X is None) == (samples is None):
        raise ModelError("sweep: give the designs X or a number of samples")
    ex = executor or Executor()
    if X is None:  # the designs, and one task over them, must fit before they are drawn
        problem.check_memory(samples, f"sweep: samples = {float(samples):.4g}",
                             "the samples (--samples)", chunk=ex.chunk,
                             per_design=8 * len(problem.variables))
        return ex.sample(problem, int(samples), 0 if seed is None else seed)
    return ex.evaluate(problem, X)


@dataclass
class SweepResult:
    """What :func:`sweep_to` did: the designs, the feasible ones, the best one, the
    reasons counted, the dataset folder and the time taken.

    Examples
    --------
    >>> from assur.synthesis.search.scale import SweepResult
    >>> SweepResult("s.parquet", 100, 100, 0, 3, (17, 11.2), {}, 1.5).computed
    100
    """

    path: str
    samples: int
    computed: int
    resumed: int
    feasible: int
    best: tuple | None
    reasons: dict
    seconds: float


def sweep_to(problem, path, *, samples, seed=0, executor=None, resume=False):
    """Evaluate ``samples`` designs drawn from ``seed`` and write them, chunk by
    chunk, as a Parquet dataset of parts with its manifest (:mod:`.dataset`); the
    memory of this process does not grow with ``samples``.

    Parameters
    ----------
    problem : Problem
    path : str or os.PathLike
        The dataset's folder.
    samples : int
    seed : int
    executor : Executor, optional
        Default: this process.
    resume : bool
        Keep the parts an earlier run of the same problem, seed and samples finished
        there, and compute only the rest.

    Returns
    -------
    SweepResult

    Examples
    --------
    >>> import tempfile
    >>> import pandas as pd
    >>> from assur import io
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.scale import Executor, sweep, sweep_to
    >>> pb = load_problem(io.bundled("hitch_003_design"), positions=10)  # pivots ±30 mm
    >>> with tempfile.TemporaryDirectory() as d:
    ...     r = sweep_to(pb, f"{d}/s.parquet", samples=2000, seed=1,
    ...                  executor=Executor(chunk=512))
    ...     df = pd.read_parquet(f"{d}/s.parquet")
    >>> r.feasible, r.best[0], len(df), df["design"].is_monotonic_increasing
    (40, 1072, 2000, True)
    """
    from .dataset import Dataset
    ex = executor or Executor()
    samples = int(samples)
    problem.check_memory(min(samples, ex.chunk), f"sweep: chunk of {min(samples, ex.chunk)} "
                         f"designs", "the designs per task (--chunk)", chunk=ex.chunk)
    t0 = time.perf_counter()
    ds = Dataset(path, problem, samples, seed, resume=resume).open()
    resumed = ds.done
    missing = ds.missing()
    seed = int(seed)
    if missing:
        ex.run(problem, missing, lambda a, b: Chunk(a, b, seed=seed, out="part"),
               lambda c, r: ds.write(*r))
    if ex.phase is not None:
        ex.phase("writing the manifest")
    ds.close(time.perf_counter() - t0)
    return SweepResult(str(path), samples, samples - resumed, resumed, ds.feasible(),
                       ds.best(), ds.reasons(), time.perf_counter() - t0)


def write_parquet(batch, path):
    """Write a batch as a Parquet table (one row per design: its index, the variables,
    criteria [SI; a reserve in %], ``feasible``, ``status`` as named categories …;
    units and descriptions in the schema, :func:`.dataset.part_table`); returns the
    path.

    Examples
    --------
    A sweep of the bundled seed-003 design problem stored and read back:

    >>> import os
    >>> import tempfile
    >>> import pandas as pd
    >>> from assur import io
    >>> from assur.io import load_problem
    >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
    >>> from assur.synthesis.search.scale import sweep, write_parquet
    >>> b = sweep(pb, samples=20, seed=1)
    >>> with tempfile.TemporaryDirectory() as d:
    ...     df = pd.read_parquet(write_parquet(b, os.path.join(d, "sweep.parquet")))
    >>> df.shape, list(df.columns[:3]), str(df["status"].dtype)
    ((20, 18), ['design', 'X01', 'Y01'], 'category')
    """
    from .dataset import part_table, write_table
    write_table(part_table(batch), path)
    return path

