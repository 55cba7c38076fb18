"""The report's figures are rendered by forked processes only from a process with no
other thread (:func:`assur.views.report.forkable`): a fork copies the locks other
threads hold at that instant (an import half done, a kernel compiling in the
background, a page's server writing) without the threads that would release them, and
a renderer that takes one waits forever — the report never ends. ``assur analyze``
keeps its process single-threaded while it writes (its progress bar is redrawn at each
step, not by a refresh thread), so its renderers still run in parallel."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import threading

from assur import io
from assur.views import report
from assur.views.report import write_report


def test_no_fork_while_another_thread_runs(tmp_path, monkeypatch):
    a = io.load(io.bundled("steering_lab4")).analyze()
    one = write_report(a, tmp_path / "one", formats=("png", "html"), frames=2, jobs=1)

    def refused():
        raise AssertionError("forked while another thread runs")

    stop = threading.Event()
    other = threading.Thread(target=stop.wait, daemon=True)
    other.start()
    try:
        assert not report.forkable()
        monkeypatch.setattr(os, "fork", refused)
        two = write_report(a, tmp_path / "two", formats=("png", "html"), frames=2, jobs=2)
    finally:
        stop.set()
        other.join()
    assert [p.name for p in one["png"]] == [p.name for p in two["png"]]
    for p, q in zip(one["png"], two["png"]):
        assert p.read_bytes() == q.read_bytes(), p.name


#: ``assur analyze`` run in this process, telling whether its report could fork
ANALYZE = """
import json, sys, threading
import assur.views.report as report
seen = []
real = report.forkable
def watched():
    seen.append([t.name for t in threading.enumerate()])
    return real()
report.forkable = watched
from assur.views.cli import app
try:
    app(["analyze", sys.argv[1], "-o", sys.argv[2], "--format", "png", "--jobs", "2"])
except SystemExit as e:
    print(json.dumps({"status": e.code, "threads": seen}))
"""


def test_assur_analyze_writes_its_report_from_one_thread(tmp_path):
    env = dict(os.environ, ASSUR_CACHE_DIR=str(tmp_path / "cache"))
    r = subprocess.run([sys.executable, "-c", ANALYZE, str(io.bundled("hitch_003")),
                        str(tmp_path / "out")], capture_output=True, text=True, env=env,
                       timeout=300)
    out = json.loads(r.stdout.strip().splitlines()[-1])
    assert out["status"] in (0, None), r.stderr
    assert out["threads"] == [["MainThread"]]
    assert len(list((tmp_path / "out").glob("fig_*.png"))) > 3


def test_a_renderer_that_dies_leaves_its_figure_to_this_process(tmp_path, monkeypatch,
                                                                 caplog):
    """A renderer killed mid-report (out of memory, a signal) is not waited for: its
    jobs are drawn here and the files equal a one-process report."""
    a = io.load(io.bundled("steering_lab4")).analyze()
    one = write_report(a, tmp_path / "one", formats=("png", "html"), frames=2, jobs=1)
    parent, real = os.getpid(), report._render

    def dying(job, **kwargs):
        if os.getpid() != parent and job[0] == "drawing":
            os._exit(9)  # as a renderer killed by the kernel ends
        return real(job, **kwargs)

    monkeypatch.setattr(report, "_render", dying)
    two = write_report(a, tmp_path / "two", formats=("png", "html"), frames=2, jobs=2)
    assert [p.name for p in one["png"]] == [p.name for p in two["png"]]
    for p, q in zip(one["png"], two["png"]):
        assert p.read_bytes() == q.read_bytes(), p.name
    assert "drawn in this process" in caplog.text
