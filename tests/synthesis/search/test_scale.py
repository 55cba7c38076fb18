"""Scale-out (:mod:`assur.synthesis.search.scale`, issue 12): a sweep on a Dask
LocalCluster of 2 workers gives the same results as the in-process run, and the
cluster leaves the calling process's environment as it found it."""

import os

import numpy as np
import pytest

from assur import io
from assur.io import load_problem
from assur.synthesis.search.scale import Executor, sweep


@pytest.mark.slow
def test_local_cluster_equals_in_process():
    pb = load_problem(io.bundled("hitch_003_design"))
    X = pb.sample(3000, seed=4)
    X[::7, pb.names.index("X03")] += 0.8  # some designs that do not assemble
    here = sweep(pb, X)
    seen = []
    from assur.synthesis.search.search import optimize
    de_here = optimize(pb, popsize=5, maxiter=8, seed=6)
    with Executor(workers=2, chunk=700, progress=lambda d, t: seen.append(d)) as ex:
        there = sweep(pb, X, executor=ex)
        # differential evolution with its populations on the cluster: the same search
        de_there = optimize(pb, popsize=5, maxiter=8, seed=6,
                            evaluate=lambda Xp: ex.evaluate(pb, Xp))
        # an existing cluster by its scheduler's address: the same code path
        with Executor(scheduler=ex.client.scheduler.address, chunk=500) as ex2:
            assert ex2.describe().startswith("Dask scheduler tcp://")
            remote = sweep(pb, X[:1000], executor=ex2)
    assert remote.reasons == here.reasons[:1000]
    np.testing.assert_array_equal(de_here.x, de_there.x)
    assert de_here.evaluations == de_there.evaluations
    assert len(X) in seen  # the progress of the sweep reached every design
    np.testing.assert_array_equal(here.status, there.status)
    np.testing.assert_array_equal(here.objectives, there.objectives)
    np.testing.assert_array_equal(here.values, there.values)
    assert here.reasons == there.reasons
    assert (~here.feasible).sum() >= len(X) // 7


def test_a_local_cluster_leaves_the_environment_as_it_was():
    """Dask's nannies set OMP_NUM_THREADS=1 (and MKL_NUM_THREADS, OPENBLAS_NUM_THREADS,
    MALLOC_TRIM_THRESHOLD_, PYTHONHASHSEED …) in the process that starts them: the
    Executor puts back what its cluster's start changed when the cluster closes, and
    leaves what the caller set meanwhile."""
    pb = load_problem(io.bundled("hitch_003_design"))
    before = dict(os.environ)
    with Executor(workers=1) as ex:
        changed = {k for k in set(before) | set(os.environ) if before.get(k) != os.environ.get(k)}
        os.environ["ASSUR_TEST_SET_INSIDE"] = "kept"
        b = sweep(pb, samples=8, seed=1, executor=ex)
    assert len(b) == 8
    assert "OMP_NUM_THREADS" in changed or before.get("OMP_NUM_THREADS") == "1"  # Dask did
    assert os.environ.pop("ASSUR_TEST_SET_INSIDE") == "kept"
    assert dict(os.environ) == before


def _kernel_threads_in_a_task():
    from assur.kernel import threads
    from assur.synthesis.search import scale
    with scale._worker_threads():
        return threads()


@pytest.mark.parametrize("nthreads", [1, 3])
def test_the_kernel_threads_follow_the_worker_threads(nthreads, monkeypatch):
    """A worker of n threads running one task: its kernel on n threads (it was the
    CPUs of the machine whatever --nthreads); $ASSUR_THREADS still wins; this
    process's own setting is back after the task."""
    from distributed import Client, LocalCluster

    from assur.kernel import threads
    monkeypatch.delenv("ASSUR_THREADS", raising=False)
    mine = threads()
    with LocalCluster(n_workers=1, threads_per_worker=nthreads, processes=False,
                      dashboard_address=":0") as cluster, Client(cluster) as client:
        assert client.submit(_kernel_threads_in_a_task, pure=False).result() == nthreads
        monkeypatch.setenv("ASSUR_THREADS", "5")
        assert client.submit(_kernel_threads_in_a_task, pure=False).result() == 5
    assert threads() == 5
    monkeypatch.delenv("ASSUR_THREADS")
    assert threads() == mine


def test_a_worker_that_raises_sends_its_message_back():
    """A design problem's own error on a worker reaches the client as in this process:
    the same type, the same message (not a Dask error, not a hang)."""
    from distributed import LocalCluster

    from assur.errors import ModelError
    pb = load_problem(io.bundled("hitch_003_design"), positions=4)
    X = pb.sample(6, seed=1)
    X[4, 2] = np.nan
    with pytest.raises(ModelError) as here:
        Executor(chunk=3).evaluate(pb, X)
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                      dashboard_address=":0") as cluster:
        with Executor(scheduler=cluster.scheduler_address, chunk=3) as ex:
            with pytest.raises(ModelError) as there:
                ex.evaluate(pb, X)
    assert "has a value that is not finite" in str(here.value)
    assert str(there.value) == str(here.value)


def test_another_assur_version_on_a_worker_is_one_message(monkeypatch):
    """At connect, every worker's assur version is asked (another one: a message
    naming the worker); each task checks it again (a worker that joins later)."""
    from distributed import LocalCluster

    import assur
    from assur.synthesis.search import scale
    from assur.synthesis.search.scale import Chunk, ClusterError, run_chunk
    pb = load_problem(io.bundled("hitch_003_design"), positions=4)
    with pytest.raises(ClusterError, match=r"this Dask worker runs assur .*, the client "
                                           r"assur 0\.0\.1: install the same version"):
        run_chunk(pb, Chunk(0, 2, seed=1, version="0.0.1"))
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=False, protocol="tcp://",
                      dashboard_address=":0") as cluster:
        monkeypatch.setattr(scale, "_versions", lambda: "0.0.1")
        with pytest.raises(ClusterError) as e:
            with Executor(scheduler=cluster.scheduler_address):
                pass
    assert (f"the client runs assur {assur.__version__}, but tcp://127.0.0.1:"
            in str(e.value)) and "runs 0.0.1: install the same version" in str(e.value)
