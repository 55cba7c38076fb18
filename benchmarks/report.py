"""Timing of the documents (issue 23 target: ``assur analyze`` with every format, warm,
within 3 s on the 2-core machine and at most 2× the CSV-only run). ``make bench`` runs
it after page.py.

For each model below, ``assur analyze FILE -o DIR --format F`` is run as the user runs
it — a new process: Python started, assur imported, the file loaded (its conditions
solved), analysed over its range, the report written — warm (after a first run of
each: compiled kernels and the solve cache on disk, fonts cached), for

* **csv**: the tables as CSV files only (the peer),
* **html**: the HTML report alone,
* **all**: every default format — CSV, XLSX, the HTML report with its figures,
  drawing and animation, PNG and SVG figures, the GIF,

interleaved, each the median of N runs; printed as seconds and as the ratio to the
CSV-only run of the same model. Then, in this process (assur imported, warm), where
the every-format run spends its time: the report's steps (``write_report``'s
``progress``), and the floor of any schedule of that work on this machine's cores —
the CSV run, then matplotlib's import (timed in a new process), then the figures',
drawing's and animation's CPU time shared by every core — as seconds and as a ratio
to the CSV run: the 2× of issue 23 is out of reach while that floor is above it.
Nothing is asserted.
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from assur import io
from assur.views.report import DEFAULT_FORMATS, write_report

N = 3
TARGET_S = 3.0
TARGET_RATIO = 2.0
MODELS = tuple(os.environ.get("ASSUR_BENCH_MODELS", "hitch_003,loader_lab1,steering_lab4,cleaning_lab3").split(","))
RUNS = {"csv": "csv", "html": "html", "all": ",".join(DEFAULT_FORMATS)}
ASSUR = [sys.executable, "-m", "assur"]  # as the console script `assur`


def _cli(name, formats, out):
    """Seconds of one ``assur analyze`` process."""
    t0 = time.perf_counter()
    r = subprocess.run(ASSUR + ["analyze", str(io.bundled(name)), "-o", str(out), "--format",
                                formats], capture_output=True, text=True,
                       env=dict(os.environ, MPLBACKEND="Agg"))
    dt = time.perf_counter() - t0
    if r.returncode != 0:
        raise SystemExit(f"assur analyze {name} --format {formats} failed:\n{r.stdout}{r.stderr}")
    return dt


def _steps(name, out):
    """Seconds per step of ``write_report`` with every default format, warm."""
    analysis = io.load(io.bundled(name)).analyze()
    write_report(analysis, out / "warm", formats=DEFAULT_FORMATS)
    spent, last = {}, [None, time.perf_counter()]

    def progress(step):
        now = time.perf_counter()
        if last[0] is not None:
            spent[last[0]] = spent.get(last[0], 0.0) + now - last[1]
        last[0], last[1] = step, now

    write_report(analysis, out / "steps", formats=DEFAULT_FORMATS, progress=progress)
    progress(None)
    return spent


MPL_IMPORT = ("import time; t = time.perf_counter(); import matplotlib.figure, "
              "matplotlib.backends.backend_agg; print(time.perf_counter() - t)")


def _mpl_import():
    """Seconds of matplotlib's import in a new process (median of N)."""
    return statistics.median(float(subprocess.run([sys.executable, "-c", MPL_IMPORT],
                                                  capture_output=True, text=True,
                                                  check=True).stdout) for _ in range(N))


def main():
    print(f"assur analyze as a process, warm, median of {N} interleaved runs (target: every "
          f"format ≤ {TARGET_S:g} s and ≤ {TARGET_RATIO:g}× CSV alone)")
    print(f"{'model':<16}{'positions':>10}{'csv [s]':>10}{'html [s]':>10}{'all [s]':>10}"
          f"{'all/csv':>10}")
    mpl = _mpl_import()
    for name in MODELS:
        n = io.load(io.bundled(name)).analyze().kinematics.n
        times = {k: [] for k in RUNS}
        with tempfile.TemporaryDirectory() as d:
            for k, fm in RUNS.items():  # warm-up: kernels, solve cache, font cache
                _cli(name, fm, Path(d) / f"w-{k}")
            for i in range(N):
                for k, fm in RUNS.items():
                    times[k].append(_cli(name, fm, Path(d) / f"{k}-{i}"))
            med = {k: statistics.median(v) for k, v in times.items()}
            print(f"{name:<16}{n:>10}{med['csv']:>10.3f}{med['html']:>10.3f}"
                  f"{med['all']:>10.3f}{med['all'] / med['csv']:>10.1f}", flush=True)
            steps = _steps(name, Path(d))
            print(" " * 16 + "every format, in process: " + ", ".join(
                f"{k} {v:.2f} s" for k, v in steps.items()), flush=True)
            cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else 1
            drawn = sum(steps.get(k, 0.0) for k in ("figures", "drawing", "animation"))
            floor = med["csv"] + mpl + drawn / cores
            print(" " * 16 + f"floor on {cores} core(s): csv {med['csv']:.2f} + matplotlib "
                  f"import {mpl:.2f} + drawing {drawn:.2f}/{cores} = {floor:.2f} s "
                  f"({floor / med['csv']:.1f}× csv)", flush=True)


if __name__ == "__main__":
    main()
