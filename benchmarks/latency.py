"""Latency of a new model (issue 28): what a user waits for, as whole processes.

    .venv/bin/python benchmarks/latency.py          # make bench runs it last

On a fresh cache directory (kernels, numba's cache, the solve cache: a temporary
``ASSUR_CACHE_DIR`` and ``NUMBA_CACHE_DIR``), for a new structure — the seed-003 hitch
with two more points (9 groups: ``tests/helpers/new_structure.py``), a structure no
cache holds — and for the bundled hitch, each figure the median of R fresh processes
(hyperfine-like; the wall time of the whole process, Python's start included):

* ``assur check`` **cold**: every run on caches of its own, empty (the first check of
  a new structure on a new machine);
* ``assur check`` **warm**: on the shared caches, after one run;
* ``assur analyze`` **csv**: the tables alone, warm; **every format**: CSV, XLSX, the
  HTML report with its figures, PNG, SVG and the GIF, warm;
* the page's **first export**: a new server process (as ``assur serve`` starts it: the
  model warmed in the background, then compiled kernels), its first answer, then the
  first CSV and XLSX export at 101 positions asked for at once — the export's own time
  (after the first answer, while the warming goes on) and the process's from its start;
  and in other processes the first and the second XLSX export once the page is warm
  (as a user who looks at the page before exporting): the same time;

and, without a model, ``python -c 'import assur'`` and ``assur --version``. Each is
printed with the issue's target (cold check ≤ 2 s, warm check ≤ 0.3 s, every format
≤ 3 s, first export ≤ 2 s, ``import assur`` ≤ 0.2 s) and whether it is met. Nothing
is asserted; the machine's load moves single figures.
"""

from __future__ import annotations

import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
R = 5
TARGETS = {"check cold": 2.0, "check warm": 0.3, "analyze every format": 3.0,
           "first export": 2.0, "import assur": 0.2}

EXPORT = r"""
import json, sys, time, urllib.request
t0 = time.perf_counter()
from assur.views.page.server import create_app, running
def post(url, path, body):
    req = urllib.request.Request(url + path, data=json.dumps(body).encode(),
                                 headers={"Content-Type": "application/json"})
    with urllib.request.urlopen(req, timeout=600) as r:
        r.read()
def export(url, fmt):
    t = time.perf_counter()
    post(url, "/api/export/" + fmt, {"positions": 101})
    return time.perf_counter() - t
app = create_app(sys.argv[1], compiled=True)  # as `assur serve` makes it
with running(app) as url:
    post(url, "/api/analyze", {"params": {}, "positions": 101})
    if sys.argv[2] == "at once":  # the exports asked for right after the first answer
        csv, xlsx = export(url, "csv"), export(url, "xlsx")
        print(json.dumps({"csv": csv, "xlsx": xlsx, "process": time.perf_counter() - t0}))
    else:  # asked for once the page is warm, as a user who looks at the page first
        app.state.warming.join()
        warm = time.perf_counter() - t0
        first, second = export(url, "xlsx"), export(url, "xlsx")
        print(json.dumps({"warm": warm, "first": first, "second": second}))
"""


def _env(cache):
    env = {k: v for k, v in os.environ.items()
           if k not in ("ASSUR_KERNELS", "PYTHONDONTWRITEBYTECODE")}
    env.update(ASSUR_CACHE_DIR=str(cache / "assur"), NUMBA_CACHE_DIR=str(cache / "numba"),
               MPLBACKEND="Agg")
    return env


def _wall(cmd, env, cwd):
    t0 = time.perf_counter()
    r = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=cwd)
    dt = time.perf_counter() - t0
    if r.returncode != 0:
        raise SystemExit(f"{' '.join(map(str, cmd))} failed:\n{r.stdout}{r.stderr}")
    return dt, r.stdout


def _line(label, times, target=None):
    med = statistics.median(times)
    tail = ""
    if target is not None:
        tail = f"   target ≤ {target:g} s  {'yes' if med <= target else 'no'}"
    print(f"    {label:<34} median {med:6.2f} s  (best {min(times):5.2f}, "
          f"worst {max(times):5.2f}){tail}", flush=True)
    return med


def model_section(label, model, work):
    assur = [sys.executable, "-m", "assur"]  # as the console script `assur`
    print(f"  {label} ({model.name}):")
    work.mkdir(parents=True, exist_ok=True)
    shared = work / "shared"
    env = _env(shared)
    cold = []
    for i in range(R):
        fresh = work / f"cold-{i}"
        cold.append(_wall(assur + ["check", str(model)], _env(fresh), work)[0])
        shutil.rmtree(fresh, ignore_errors=True)
    _line("assur check, cold", cold, TARGETS["check cold"])
    _wall(assur + ["check", str(model)], env, work)
    _line("assur check, warm", [_wall(assur + ["check", str(model)], env, work)[0]
                                for _ in range(R)], TARGETS["check warm"])
    every = "csv,xlsx,html,png,svg,gif"
    runs = {"csv": [], every: []}
    for fm in runs:  # warm-up: the kernels, the solve cache, matplotlib's font cache
        _wall(assur + ["analyze", str(model), "-o", str(work / "out"), "--format", fm], env,
              work)
    for _ in range(R):
        for fm in runs:
            runs[fm].append(_wall(assur + ["analyze", str(model), "-o", str(work / "out"),
                                           "--format", fm], env, work)[0])
    csv = _line("assur analyze --format csv", runs["csv"])
    allf = _line("assur analyze, every format", runs[every], TARGETS["analyze every format"])
    print(f"    {'every format / csv':<34} {allf / csv:6.2f}×   (issue 23: ≤ 2×)")
    exports = [json.loads(_wall([sys.executable, "-c", EXPORT, str(model), "at once"], env,
                                work)[1]) for _ in range(R)]
    _line("page: first CSV export, at once", [e["csv"] for e in exports],
          TARGETS["first export"])
    _line("page: first XLSX export, at once", [e["xlsx"] for e in exports],
          TARGETS["first export"])
    _line("page: process start → XLSX", [e["process"] for e in exports])
    later = [json.loads(_wall([sys.executable, "-c", EXPORT, str(model), "warm"], env,
                              work)[1]) for _ in range(R)]
    _line("page: process start → warm", [e["warm"] for e in later])
    _line("page: first XLSX export, warm", [e["first"] for e in later],
          TARGETS["first export"])
    _line("page: second XLSX export", [e["second"] for e in later])


def main():
    sys.path.insert(0, str(ROOT))
    from tests.helpers.new_structure import new_structure_model

    from assur import io

    print(f"latency (issue 28): whole processes, median of {R}, on a fresh cache directory")
    with tempfile.TemporaryDirectory() as d:
        work = Path(d)
        env = _env(work / "none")
        _line("python -c 'import assur'",
              [_wall([sys.executable, "-c", "import assur"], env, work)[0] for _ in range(R)],
              TARGETS["import assur"])
        _line("assur --version",
              [_wall([sys.executable, "-m", "assur", "--version"], env, work)[0]
               for _ in range(R)])
        new = new_structure_model(work, extra=2, seed=int(time.time()) % 1000)
        model_section("a new structure, 9 groups", new, work / "new")
        model_section("the seed-003 hitch", io.bundled("hitch_003"), work / "hitch")


if __name__ == "__main__":
    main()
