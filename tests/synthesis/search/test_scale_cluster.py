"""Scale-out on a cluster of separate processes (issue 26): a ``dask scheduler`` and
``dask worker`` processes started here on 127.0.0.1 (free ports, each run bounded in
time), the workers in another working directory — the model's folder is removed
before they get any task, so they can only use the content the tasks carry.

* a sweep (a Parquet dataset of parts) and a differential evolution equal the
  in-process run, bit for bit;
* a model file edited between two runs on the same cluster gives the second run's
  results (problems are cached by content, not by path);
* a worker killed mid-run: the sweep still completes with every design exactly once;
* every worker killed: a ClusterError within the timeout, the finished parts kept;
  ``resume=True`` on new workers computes only the rest, and the whole equals an
  uninterrupted run;
* the scheduler killed: one ClusterError, no traceback.
"""

from __future__ import annotations

import os
import shutil
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from assur import io
from assur.io import load_problem
from assur.synthesis.search.scale import ClusterError, Executor, sweep_to

BIN = Path(sys.executable).parent
#: seconds a cluster may take to start (scheduler + workers registered)
START = 60.0


def _port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Cluster:
    """A scheduler and workers as separate processes, killed at the end."""

    def __init__(self, tmp: Path):
        self.tmp = tmp
        self.port = _port()
        self.address = f"tcp://127.0.0.1:{self.port}"
        self.elsewhere = tmp / "elsewhere"  # the workers' working directory
        self.elsewhere.mkdir(exist_ok=True)
        self.workers: list = []
        self.scheduler = self._spawn(["scheduler", "--host", "127.0.0.1", "--port",
                                      str(self.port), "--no-dashboard", "--dashboard-address",
                                      "127.0.0.1:0"], "scheduler")

    def _spawn(self, args, name):
        env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
        with open(self.tmp / f"{name}.log", "w") as log:  # the child keeps its own copy
            return subprocess.Popen([str(BIN / "dask"), *args], cwd=self.elsewhere, env=env,
                                    stdout=log, stderr=subprocess.STDOUT,
                                    start_new_session=True)

    def add_workers(self, n):
        for _ in range(n):
            i = len(self.workers)
            self.workers.append(self._spawn([
                "worker", self.address, "--nthreads", "1", "--no-nanny", "--no-dashboard",
                "--local-directory", str(self.tmp / f"w{i}")], f"worker{i}"))

    def wait_for(self, ex, n):
        t0 = time.monotonic()
        while ex.threads() < n:
            assert time.monotonic() - t0 < START, (self.tmp / "scheduler.log").read_text()
            time.sleep(0.2)

    @staticmethod
    def kill(p):
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait(10)

    def close(self):
        for p in self.workers + [self.scheduler]:
            self.kill(p)


@pytest.fixture
def cluster(tmp_path):
    c = Cluster(tmp_path)
    c.add_workers(2)
    yield c
    c.close()


def _model(tmp: Path, x01="30 mm") -> Path:
    """The bundled seed-003 design problem copied to a folder of its own (its base
    file too), with X01 within ``x01`` of the seed's value."""
    d = tmp / "models"
    d.mkdir(exist_ok=True)
    shutil.copy(io.bundled("hitch_003"), d / "hitch_003.toml")
    text = io.bundled("hitch_003_design").read_text(encoding="utf-8")
    assert 'X01 = { within = "30 mm" }' in text
    (d / "design.toml").write_text(text.replace('X01 = { within = "30 mm" }',
                                                f'X01 = {{ within = "{x01}" }}'),
                                   encoding="utf-8")
    return d / "design.toml"


def _frame(path):
    return pd.read_parquet(path).sort_values("design").reset_index(drop=True)


@pytest.mark.slow
def test_sweep_optimize_and_an_edited_file_on_a_cluster_of_processes(cluster, tmp_path):
    from assur.synthesis.search.search import optimize
    path = _model(tmp_path)
    pb = load_problem(path, positions=6)
    here = sweep_to(pb, tmp_path / "here.parquet", samples=6000, seed=5)
    de_here = optimize(pb, popsize=4, maxiter=4, seed=6)
    shutil.rmtree(path.parent)  # the workers cannot read the model: only its content
    with Executor(scheduler=cluster.address, chunk=700, timeout=30) as ex:
        cluster.wait_for(ex, 2)
        there = sweep_to(pb, tmp_path / "there.parquet", samples=6000, seed=5, executor=ex)
        de_there = optimize(pb, popsize=4, maxiter=4, seed=6,
                            evaluate=lambda X: ex.evaluate(pb, X))
        # the file edited (X01 within 5 mm) and run again on the same cluster
        edited = load_problem(_model(tmp_path, x01="5 mm"), positions=6)
        assert edited is not pb and edited.identity != pb.identity
        again = sweep_to(edited, tmp_path / "again.parquet", samples=6000, seed=5,
                         executor=ex)
    pd.testing.assert_frame_equal(_frame(tmp_path / "here.parquet"),
                                  _frame(tmp_path / "there.parquet"))
    assert (here.feasible, here.best) == (there.feasible, there.best)
    np.testing.assert_array_equal(de_here.x, de_there.x)
    assert de_here.evaluations == de_there.evaluations
    alone = sweep_to(edited, tmp_path / "alone.parquet", samples=6000, seed=5)
    pd.testing.assert_frame_equal(_frame(tmp_path / "again.parquet"),
                                  _frame(tmp_path / "alone.parquet"))
    assert again.feasible == alone.feasible != here.feasible
    assert _frame(tmp_path / "again.parquet")["X01"].max() < pb.x0[0] + 0.005 + 1e-12


@pytest.mark.slow
def test_a_worker_killed_mid_run(cluster, tmp_path):
    pb = load_problem(_model(tmp_path), positions=6)
    whole = sweep_to(pb, tmp_path / "whole.parquet", samples=8000, seed=2)

    def progress(done, total):
        if done >= 1000:
            cluster.kill(cluster.workers[0])

    with Executor(scheduler=cluster.address, chunk=500, timeout=30, progress=progress) as ex:
        cluster.wait_for(ex, 2)
        r = sweep_to(pb, tmp_path / "s.parquet", samples=8000, seed=2, executor=ex)
    assert cluster.workers[0].poll() is not None
    df = _frame(tmp_path / "s.parquet")
    assert df["design"].tolist() == list(range(8000))  # every design exactly once
    pd.testing.assert_frame_equal(df, _frame(tmp_path / "whole.parquet"))
    assert (r.feasible, r.best) == (whole.feasible, whole.best)


@pytest.mark.slow
def test_every_worker_killed_then_resume(cluster, tmp_path):
    pb = load_problem(_model(tmp_path), positions=6)
    out = tmp_path / "s.parquet"
    killed = []

    def progress(done, total):
        if done >= 2000 and not killed:
            killed.append(time.monotonic())
            for w in cluster.workers:
                cluster.kill(w)

    with Executor(scheduler=cluster.address, chunk=500, timeout=3, progress=progress) as ex:
        cluster.wait_for(ex, 2)
        with pytest.raises(ClusterError) as e:
            sweep_to(pb, out, samples=10000, seed=3, executor=ex)
    assert time.monotonic() - killed[0] < 3 + 10  # the timeout and the workers' departure
    msg = str(e.value)
    assert "has had no worker for 3 s" in msg and "--resume" in msg and "\n" not in msg
    parts = sorted(out.glob("part-*.parquet"))
    assert parts and (out / "_manifest.json").is_file()
    kept = len(_frame(out))
    assert 2000 <= kept < 10000
    # new workers; the rerun computes only what no part holds
    cluster.add_workers(2)
    with Executor(scheduler=cluster.address, chunk=500, timeout=30) as ex:
        cluster.wait_for(ex, 2)
        r = sweep_to(pb, out, samples=10000, seed=3, executor=ex, resume=True)
    assert (r.resumed, r.computed) == (kept, 10000 - kept)
    whole = sweep_to(pb, tmp_path / "whole.parquet", samples=10000, seed=3)
    df = _frame(out)
    assert df["design"].tolist() == list(range(10000))
    pd.testing.assert_frame_equal(df, _frame(tmp_path / "whole.parquet"))
    assert (r.feasible, r.best) == (whole.feasible, whole.best)


@pytest.mark.slow
def test_the_scheduler_killed_is_one_message(cluster, tmp_path):
    pb = load_problem(_model(tmp_path), positions=6)

    def progress(done, total):
        if done >= 1000:
            cluster.kill(cluster.scheduler)

    t0 = time.monotonic()
    with pytest.raises(ClusterError) as e:
        with Executor(scheduler=cluster.address, chunk=500, timeout=30,
                      progress=progress) as ex:
            cluster.wait_for(ex, 2)
            sweep_to(pb, tmp_path / "s.parquet", samples=20000, seed=3, executor=ex)
    msg = str(e.value)
    assert msg.startswith(f"lost the connection to Dask scheduler {cluster.address}"), msg
    assert "\n" not in msg and time.monotonic() - t0 < 60
