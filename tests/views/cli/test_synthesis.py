"""The synthesis commands' Dask options (issue 27): a scheduler nobody listens on is one
message naming the address, within the connect timeout; a scheduler needs no
``--workers 0``; both together are a usage error."""

import socket
import time

import pytest
from typer.testing import CliRunner

from assur.io import bundled
from assur.views.cli import _synthesis, app

runner = CliRunner()
DESIGN = str(bundled("hitch_003_design"))


def _closed_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.mark.parametrize("command", ["sweep", "optimize"])
def test_a_scheduler_nobody_listens_on_is_one_message(command, tmp_path):
    address = f"tcp://127.0.0.1:{_closed_port()}"
    t0 = time.perf_counter()
    r = runner.invoke(app, [command, DESIGN, "--scheduler", address, "--samples" if
                            command == "sweep" else "--maxiter", "2", "-o",
                            str(tmp_path / "out")])
    assert r.exit_code == 1, r.output
    line = " ".join(r.stderr.split())
    assert line.startswith(f"error: cannot reach the Dask scheduler at {address}"), line
    assert "Traceback" not in r.output
    assert time.perf_counter() - t0 < 30


def test_the_connect_timeout_is_bounded(monkeypatch, tmp_path):
    """A port that never answers: the message comes after CONNECT_TIMEOUT seconds."""
    def silent(address, timeout):
        assert timeout == _synthesis.CONNECT_TIMEOUT == 10.0
        raise socket.timeout("timed out")
    monkeypatch.setattr(socket, "create_connection", silent)
    r = runner.invoke(app, ["sweep", DESIGN, "--scheduler", "tcp://192.0.2.1:8786", "-o",
                            str(tmp_path / "x.parquet")])
    assert r.exit_code == 1
    assert ("cannot reach the Dask scheduler at tcp://192.0.2.1:8786: no answer within 10 s"
            in " ".join(r.stderr.split()))


def test_something_that_is_not_a_scheduler(tmp_path):
    """A port that answers but speaks no Dask: one message, no traceback."""
    import threading

    srv = socket.socket()
    srv.bind(("127.0.0.1", 0))
    srv.listen(4)
    port = srv.getsockname()[1]

    def answer():
        for _ in range(4):
            try:
                c, _ = srv.accept()
            except OSError:
                return
            c.sendall(b"HTTP/1.0 400 Bad Request\r\n\r\n" * 8)
            c.close()
    threading.Thread(target=answer, daemon=True).start()
    try:
        r = runner.invoke(app, ["sweep", DESIGN, "--scheduler", f"127.0.0.1:{port}",
                                "--samples", "2", "-o", str(tmp_path / "x.parquet")])
    finally:
        srv.close()
    assert r.exit_code == 1, r.output
    line = " ".join(r.stderr.split())
    assert f"tcp://127.0.0.1:{port}" in line and "Traceback" not in r.output, line


def test_scheduler_and_workers_together_is_a_usage_error():
    r = runner.invoke(app, ["sweep", DESIGN, "--scheduler", "tcp://127.0.0.1:8786",
                            "--workers", "2"])
    assert r.exit_code == 2
    assert "either --scheduler or --workers" in " ".join(r.output.split())


def test_a_scheduler_without_workers_0(tmp_path):
    """``--scheduler`` alone runs there (it was refused: --workers defaulted to 2)."""
    from distributed import LocalCluster

    out = tmp_path / "s.parquet"
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=False, protocol="tcp://",
                      dashboard_address=":0") as cluster:
        r = runner.invoke(app, ["sweep", DESIGN, "--samples", "6", "--positions", "3",
                                "--scheduler", cluster.scheduler_address, "-o", str(out)])
    assert r.exit_code == 0, r.output
    assert f"on Dask scheduler {cluster.scheduler_address}" in " ".join(r.output.split())
    assert (out / "_manifest.json").is_file() and len(list(out.glob("part-*.parquet"))) == 1


def test_sweep_runs_in_this_process_by_default_and_logs_lines(tmp_path):
    """No --workers, no --scheduler: this process; stderr not a terminal: the phases
    and the progress as lines (percent, designs/s), the end's writing too."""
    out = tmp_path / "s.parquet"
    r = runner.invoke(app, ["sweep", DESIGN, "--samples", "2e3", "--positions", "3",
                            "--chunk", "500", "-o", str(out)])
    assert r.exit_code == 0, r.output
    text = " ".join(r.output.split())
    assert "2000 designs × 3 positions on this process" in text
    assert "designs: 100 % (2000/2000 designs)" in r.stderr and "designs/s" in r.stderr
    assert "designs: writing the manifest" in r.stderr
    import pandas as pd
    assert len(pd.read_parquet(out)) == 2000


def test_sweep_resume_on_the_command_line(tmp_path):
    out = tmp_path / "s.parquet"
    args = ["sweep", DESIGN, "--samples", "1200", "--positions", "3", "--chunk", "400",
            "-o", str(out)]
    assert runner.invoke(app, args).exit_code == 0
    first = sorted(out.glob("part-*.parquet"))
    first[-1].unlink()  # the last part lost, as if the run had been stopped there
    r = runner.invoke(app, args + ["--resume"])
    assert r.exit_code == 0, r.output
    assert "400 designs (and 800 of an earlier run)" in " ".join(r.output.split())
    assert "designs: 100 % (400/400 designs)" in r.stderr


def test_a_cluster_without_workers_ends_in_one_message(tmp_path):
    """A scheduler with no worker: after --timeout seconds, one line that says so."""
    from distributed import LocalCluster

    out = tmp_path / "s.parquet"
    with LocalCluster(n_workers=0, processes=False, protocol="tcp://",
                      dashboard_address=":0") as cluster:
        t0 = time.perf_counter()
        r = runner.invoke(app, ["sweep", DESIGN, "--samples", "100", "--positions", "3",
                                "--scheduler", cluster.scheduler_address, "--timeout", "1",
                                "-o", str(out)])
    assert r.exit_code == 1, r.output
    line = " ".join(r.stderr.split("error: ")[-1].split())  # after the phases' lines
    assert "error: " in r.stderr and "\n" not in r.stderr.split("error: ")[-1].strip()
    assert line.startswith(f"Dask scheduler {cluster.scheduler_address} has had no "
                           f"worker for 1 s"), line
    assert "Traceback" not in r.output and time.perf_counter() - t0 < 30
