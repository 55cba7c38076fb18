"""Scale-out: batches of designs as chunks on Dask (DESIGN.md §8: a choice of
executor, not of code path).

:class:`Executor` evaluates a batch of designs either in this process or as chunks
of designs mapped over a Dask cluster — a :class:`distributed.LocalCluster` of
``workers`` processes started here, or an existing scheduler (``tcp://host:8786``).
Both cluster cases run the same code: the chunks go to ``client.map``, each task
evaluates its chunk with :meth:`Problem.evaluate` (one fused-kernel batch) and
returns a :class:`~assur.synthesis.search.problem.Batch`, which the client concatenates in
order. A problem made from a model file (:func:`assur.io.load_problem`) travels
as its recipe and is rebuilt once per worker process; the workers must see the
model file at the same path (a shared disk, or a bundled model).

:func:`sweep` evaluates given or sampled designs; :func:`assur.synthesis.search.search.optimize`
takes ``evaluate=executor.evaluate`` to send each population to the cluster;
:func:`write_parquet` stores a batch as a table (pyarrow).
"""

from __future__ import annotations

import contextlib
import os

import numpy as np

from ...errors import ModelError

__all__ = ["Executor", "sweep", "write_parquet"]


def _evaluate(problem, X):
    return problem.evaluate(X)


class Executor:
    """Where batches are evaluated.

    Parameters
    ----------
    scheduler : str, optional
        Address of an existing Dask scheduler (``"tcp://host:8786"``).
    workers : int, optional
        Worker processes of a LocalCluster started here (without ``scheduler``);
        0 or None: evaluate in this process.
    chunk : int
        Designs per task at most (a batch smaller than chunk × workers is cut into one
        chunk per worker).
    progress : callable, optional
        ``progress(done, total)`` after every chunk (designs).

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

    def __init__(self, scheduler=None, workers=None, chunk=1 << 14, progress=None):
        if scheduler is not None and workers:
            raise ModelError("give either a scheduler address or a number of workers, not both")
        if workers is not None and int(workers) < 0:
            raise ModelError(f"workers must be ≥ 0, got {workers}")
        if int(chunk) < 1:
            raise ModelError(f"chunk must be ≥ 1 design, got {chunk}")
        self.scheduler, self.workers = scheduler, int(workers or 0)
        self.chunk = int(chunk)
        self.progress = progress
        self.client = None
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

    def __enter__(self):
        if self.distributed:
            from distributed import Client, LocalCluster
            if self.scheduler is not None:
                self.client = self._stack.enter_context(Client(self.scheduler))
            else:
                # registered first, so called last: after the client and the cluster closed
                started = {}
                self._stack.callback(_restore_environ, dict(os.environ), started)
                cluster = self._stack.enter_context(LocalCluster(
                    n_workers=self.workers, threads_per_worker=1, processes=True,
                    dashboard_address=None))
                started["environ"] = dict(os.environ)
                self.client = self._stack.enter_context(Client(cluster))
        return self

    def __exit__(self, *exc):
        self.client = None
        return self._stack.__exit__(*exc)

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

    def evaluate(self, problem, X):
        """:meth:`Problem.evaluate` of ``X``, shape (m, number of variables), chunk by
        chunk (on the cluster: one task per chunk, in parallel); returns one Batch.

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
        from .problem import Batch
        X = np.atleast_2d(np.asarray(X, float))
        size = self.chunk
        if self.client is not None:  # a small batch (a population) still fills the workers
            nw = max(1, len(self.client.scheduler_info().get("workers", {})))
            size = max(1, min(size, -(-len(X) // nw)))
        starts = list(range(0, len(X), size)) or [0]
        chunks = [X[i:i + size] for i in starts]
        total, done = len(X), 0
        if self.client is None:
            if self.distributed:
                raise ModelError("use the Executor in a `with` block to start its cluster")
            parts = []
            for c in chunks:
                parts.append(problem.evaluate(c))
                done += len(c)
                if self.progress:
                    self.progress(done, total)
        else:
            from distributed import as_completed
            futs = self.client.map(_evaluate, [problem] * len(chunks), chunks, pure=False)
            index = {f.key: i for i, f in enumerate(futs)}
            parts = [None] * len(chunks)
            for f in as_completed(futs):
                i = index[f.key]
                parts[i] = f.result()
                done += len(chunks[i])
                if self.progress:
                    self.progress(done, total)
        return parts[0] if len(parts) == 1 else Batch.concat(problem, parts)


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
    """Evaluate designs ``X`` [SI] (or ``samples`` drawn uniformly within the bounds).

    Parameters
    ----------
    problem : Problem
    X : array_like, shape (m, number of variables), optional
    samples : int, optional
        Draw this many designs instead of ``X``.
    seed : int, optional
    executor : Executor, optional
        Default: this process.

    Returns
    -------
    Batch

    Examples
    --------
    200 designs of the seed-003 hitch drawn with its pivots within ±30 mm (the
    bundled design problem): one meets every constraint.

    >>> from assur import io
    >>> from assur.io import load_problem
    >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
    >>> from assur.synthesis.search.scale import sweep
    >>> b = sweep(pb, samples=200, seed=1)
    >>> len(b), int(b.feasible.sum()), b.best()
    (200, 1, 172)
    >>> round(float(b.objective()[172]), 3)  # its min capacity reserve at S6 [%]
    5.157
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
        X = problem.sample(samples, seed)
    return ex.evaluate(problem, X)


def write_parquet(batch, path):
    """Write a batch as a Parquet table (one row per design; the columns of
    :meth:`Batch.to_frame`, SI units); returns the path.

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
    >>> df.shape, list(df.columns[:2]), df["status"].tolist() == b.status.tolist()
    ((20, 17), ['X01', 'Y01'], True)
    """
    batch.to_frame().to_parquet(path, engine="pyarrow", index=False)
    return path
