"""The same calls timed in several fresh processes (issue 7: "the same call's timing
does not jump 2× between processes").

Each process imports assur, makes one warm-up call of each function (numba loads
its cached kernels) and keeps the best of its repetitions; the parent prints, per
call, the minimum, median and maximum over the processes and max/min. A spread
well above the noise of a shared machine points at something that differs between
processes (thread start-up, first-call loading, the placement of arrays in memory):
``python benchmarks/spread.py --child`` prints one process's figures as JSON.

Usage: ``python benchmarks/spread.py [--procs 5] [--budget 0.3]``
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
S_MIN, S_MAX = 0.42, 0.67


def calls():
    """name -> (callable, positions per call)."""
    import numpy as np

    sys.path.insert(0, HERE)
    import run as bench
    import seed003_numpy as peer

    import assur
    from assur import examples
    from assur.kernel import vector

    # the compiled kernels from the first call: the numpy evaluation of a process's
    # first small calls (assur.kernel.vector) is what the start-up section measures
    vector.set_calls(0)
    hitch = examples.hitch_003()
    lever = bench.lever_mechanism(assur, peer.PARAMS)
    q1 = np.array([0.5])
    S5 = np.linspace(S_MIN, S_MAX, 10**5)
    outs = bench.fused_outputs()
    return {
        "solve, 1 position": (lambda: hitch.solve(q1), 1),
        "analyze, 1 position": (lambda: hitch.analyze(q1), 1),
        "evaluate, 1 position": (lambda: hitch.evaluate(q1, outputs=["G(ГЦ, 56)"]), 1),
        "(a) lever solve, 1e5": (lambda: bench.solve_lever(lever, S5), 10**5),
        "(b) hitch solve, 1e5": (lambda: hitch.solve(S5), 10**5),
        "(c') evaluate 25 outputs, 1e5": (lambda: hitch.evaluate(S5, outputs=outs), 10**5),
    }


def child(budget):
    """Best time of each call in this process [s], as JSON on stdout."""
    import gc

    res = {}
    for name, (f, _) in calls().items():
        f()  # warm-up: numba loads the cached kernel
        best, spent, reps = float("inf"), 0.0, 0
        gc.collect()
        gc.disable()
        try:
            while reps < 5 or (spent < budget and reps < 2000):
                t0 = time.perf_counter()
                r = f()
                dt = time.perf_counter() - t0
                del r
                best, spent, reps = min(best, dt), spent + dt, reps + 1
        finally:
            gc.enable()
        res[name] = best
    print(json.dumps(res))


def table(procs=5, budget=0.3, out=print):
    """Run ``procs`` fresh processes one after the other and print the spread."""
    runs = []
    for _ in range(procs):
        p = subprocess.run([sys.executable, os.path.abspath(__file__), "--child",
                            "--budget", str(budget)], capture_output=True, text=True,
                           check=True)
        runs.append(json.loads(p.stdout.strip().splitlines()[-1]))
    out(f"{'call':<32} {'min':>10} {'median':>10} {'max':>10}  {'max/min':>7}")
    worst = 1.0
    for name in runs[0]:
        v = sorted(r[name] for r in runs)
        unit, scale = ("µs", 1e6) if v[-1] < 1e-3 else ("ms", 1e3)
        ratio = v[-1] / v[0]
        worst = max(worst, ratio)
        out(f"{name:<32} {v[0] * scale:>7.1f} {unit} {statistics.median(v) * scale:>7.1f} "
            f"{unit} {v[-1] * scale:>7.1f} {unit}  {ratio:>6.2f}x")
    return worst


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--procs", type=int, default=5)
    ap.add_argument("--budget", type=float, default=0.3,
                    help="seconds per call and process spent repeating (best kept)")
    ap.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.child:
        child(args.budget)
        return 0
    table(args.procs, args.budget)
    return 0


if __name__ == "__main__":
    sys.exit(main())
