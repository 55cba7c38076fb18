"""The report's figures rendered by processes forked from this one (``jobs`` > 1, as
``assur analyze`` does): the same files as one process; only from a process with no
other thread (:func:`assur.views.report.forkable`) — a fork copies the locks other
threads hold at that instant (an import half done, a kernel compiling in the
background, a page's server writing) without the threads that would release them, and
a renderer that takes one waits forever; a renderer that dies leaves its jobs to this
process. ``assur analyze`` keeps its process single-threaded while it writes (its
progress bar is redrawn at each step, not by a refresh thread), so its renderers still
run in parallel.

The forking cases run in processes of their own: a test process may hold threads other
tests left (a Dask client's loop, a page's server), and then nothing is forked."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import threading
from pathlib import Path

from assur import io
from assur.views import report
from assur.views.report import write_report

#: the steering drive's report by one process and by ``jobs`` = 2 in a process with no
#: other thread (argv: output folder, "die" to kill the renderer of the drawing);
#: prints whether it forked and what the report logged
FORKED = """
import json, logging, os, sys
from pathlib import Path
from assur import io
from assur.views import report
out, die = Path(sys.argv[1]), sys.argv[2] == "die"
logs = []
class Keep(logging.Handler):
    def emit(self, record):
        logs.append(record.getMessage())
logging.getLogger("assur.report").addHandler(Keep())
a = io.load(io.bundled("steering_lab4")).analyze()
formats = ("png", "svg", "html")
one = report.write_report(a, out / "one", formats=formats, frames=3, jobs=1)
parent, real, forked = os.getpid(), report._render, []
def render(job, **kwargs):
    if os.getpid() != parent:
        forked.append(job)  # in a renderer's copy: seen through its files only
        if die and job[0] == "drawing":
            os._exit(9)  # as a renderer killed by the kernel ends
    return real(job, **kwargs)
report._render = render
alone = report.forkable()
two = report.write_report(a, out / "two", formats=formats, frames=3, jobs=2)
print(json.dumps({"alone": alone, "logs": logs,
                  "files": {f: [[str(p), str(q)] for p, q in zip(one[f], two[f])]
                            for f in formats},
                  "names": {f: [[p.name for p in one[f]], [p.name for p in two[f]]]
                            for f in formats}}))
"""


def _forked(tmp_path, how):
    env = dict(os.environ, ASSUR_CACHE_DIR=str(tmp_path / "cache"))
    r = subprocess.run([sys.executable, "-c", FORKED, str(tmp_path), how],
                       capture_output=True, text=True, env=env, timeout=300)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout.strip().splitlines()[-1])


def _same(out):
    for fmt, (one, two) in out["names"].items():
        assert one == two and one, fmt
    for p, q in out["files"]["png"] + out["files"]["html"]:
        assert Path(p).read_bytes() == Path(q).read_bytes(), p
    assert all(os.path.getsize(q) > 0 for _, q in out["files"]["svg"])


def test_figures_rendered_by_forked_processes_are_the_same(tmp_path):
    """``jobs=2``: the same files, the same PNG bytes and the same HTML report as one
    process."""
    out = _forked(tmp_path, "live")
    assert out["alone"] and out["logs"] == []
    _same(out)


def test_a_renderer_that_dies_leaves_its_figure_to_this_process(tmp_path):
    """A renderer killed mid-report (out of memory, a signal) is not waited for: its
    jobs are drawn here, said in the log, and the files equal a one-process report."""
    out = _forked(tmp_path, "die")
    assert out["alone"]
    assert any("drawn in this process" in m for m in out["logs"]), out["logs"]
    _same(out)


def test_no_fork_while_another_thread_runs(tmp_path, monkeypatch):
    """With another thread alive, ``jobs=2`` draws every figure in this process."""
    a = io.load(io.bundled("steering_lab4")).analyze()

    def refused():
        raise AssertionError("forked while another thread runs")

    stop = threading.Event()
    other = threading.Thread(target=stop.wait, daemon=True)
    other.start()
    try:
        assert not report.forkable()
        monkeypatch.setattr(os, "fork", refused)
        files = write_report(a, tmp_path, formats=("png", "html"), frames=2, jobs=2)
    finally:
        stop.set()
        other.join()
    assert "mechanism.png" in {p.name for p in files["png"]} and len(files["png"]) > 3
    assert all(p.stat().st_size > 0 for p in files["png"] + files["html"])


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
