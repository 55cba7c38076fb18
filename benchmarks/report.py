"""Timing of the documents (issue 23 target: ``assur analyze`` with every format, warm,
within 3 s on the 2-core machine and at most 2× the CSV-only run). ``make bench`` runs
it after page.py.

For each model below, the whole of ``assur analyze`` — the file loaded (its
conditions solved), analysed over its range, the report written — is timed warm (after
a first run: matplotlib, jinja2 and openpyxl imported, kernels compiled) for

* **csv**: the tables as CSV files only (the peer),
* **all**: every default format — CSV, XLSX, the HTML report with its figures,
  drawing and animation, PNG and SVG figures, the GIF,
* **html**: the HTML report alone,

interleaved, each the median of N runs; printed as seconds and as the ratio to the
CSV-only run of the same model in the same process. Nothing is asserted.
"""

from __future__ import annotations

import statistics
import tempfile
import time
from pathlib import Path

from assur import io
from assur.views.report import DEFAULT_FORMATS, write_report

N = 3
TARGET_S = 3.0
TARGET_RATIO = 2.0
MODELS = ("hitch_003", "loader_lab1", "steering_lab4", "cleaning_lab3")
#: runs per format (the cleaning mechanism's 361 positions take the longest)
RUNS = {"csv": ("csv",), "html": ("html",), "all": DEFAULT_FORMATS}


def _time(name, formats, out):
    t0 = time.perf_counter()
    analysis = io.load(io.bundled(name)).analyze()
    write_report(analysis, out, formats=formats, frames=30)
    return time.perf_counter() - t0


def main():
    print(f"assur analyze (load, analyze, write_report), warm, median of {N} interleaved "
          f"runs (target: every format ≤ "
          f"{TARGET_S:g} s and ≤ {TARGET_RATIO:g}× CSV alone)")
    print(f"{'model':<16}{'positions':>10}{'csv [s]':>10}{'html [s]':>10}{'all [s]':>10}"
          f"{'all/csv':>10}")
    for name in MODELS:
        n = io.load(io.bundled(name)).analyze().kinematics.n
        times = {k: [] for k in RUNS}
        with tempfile.TemporaryDirectory() as d:
            for k, fm in RUNS.items():  # warm-up: imports, fonts, caches
                _time(name, fm, Path(d) / f"w-{k}")
            for i in range(N):
                for k, fm in RUNS.items():
                    times[k].append(_time(name, fm, Path(d) / f"{k}-{i}"))
        med = {k: statistics.median(v) for k, v in times.items()}
        print(f"{name:<16}{n:>10}{med['csv']:>10.3f}{med['html']:>10.3f}"
              f"{med['all']:>10.3f}{med['all'] / med['csv']:>10.1f}")


if __name__ == "__main__":
    main()
