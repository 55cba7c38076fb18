"""Synthesis benchmark (issue 12): batches of designs and one differential evolution.

``make bench`` runs this file after ``run.py``. What is measured, on the design
problem of ``hitch_003_design.toml`` (the seed-003 hitch, its four frame pivots
within ±30 mm; 50 positions of S over [0.42, 0.67] m):

(e) the evaluation of M = 1e6 designs × 50 positions — the minimum and maximum
    over the stroke of the capacity reserve ΔGS65, the cylinder pressure, Y56 and
    IS6 (capacity and pressure), the constraints, feasibility and the reasons of
    the infeasible designs — by ``Problem.evaluate`` (the fused kernel's in-kernel
    reductions, chunks of 65536 designs), against a peer in the same process: the
    array pass ``Mechanism.analyze(S, params)`` + ``.reserve("S6", P6).min(axis=1)``
    and ``.pressure.max(axis=1)`` on 2000 designs that assemble (what one would write
    without the reductions). Target: ≤ 10 s for 1e6 × 50 on the 2-core machine.
(f) one differential evolution run (popsize 15, 150 generations, seed 1): its wall
    time, the designs evaluated, the batches, and the optimum's minimum reserve
    against the seed's 8.9 % (table 4.1); then the SLSQP polish of that optimum with
    exact gradients (``assur.synthesis.search.polish``): DE → polished value, iterations,
    gradient evaluations and its wall time.

Figures are printed for people to read; nothing here is a test.

Usage: ``python benchmarks/design.py [--designs 1e6]``
"""

from __future__ import annotations

import argparse
import os
import sys
import time

import numpy as np

from assur import io
from assur.io import load_problem
from assur.synthesis.search.polish import polish
from assur.synthesis.search.search import optimize

TARGET_E = 10.0  # s for 1e6 designs × 50 positions


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--designs", default="1e6")
    args = ap.parse_args(argv)
    M = int(float(args.designs))
    print(f"assur design benchmark — python {sys.version.split()[0]}, "
          f"{os.cpu_count()} CPUs, {len(os.sched_getaffinity(0))} usable")
    t0 = time.perf_counter()
    pb = load_problem(io.bundled("hitch_003_design"))
    pb.evaluate(pb.sample(64, seed=0))  # load the kernels (numba cache) once
    print(f"start-up (load the problem, first batch): {time.perf_counter() - t0:.2f} s")
    print(f"outputs reduced per design: {', '.join(pb.outputs)}; {len(pb.positions)} positions")

    # ---- (e) -----------------------------------------------------------------------
    X = pb.sample(M, seed=1)
    t = time.perf_counter()
    b = pb.evaluate(X)
    te = time.perf_counter() - t
    nfeas = int(b.feasible.sum())
    t = time.perf_counter()
    reasons = b.reasons
    tr = time.perf_counter() - t
    md = 2000
    S = pb.positions
    # the peer's array pass refuses designs that do not assemble or lift: the first md
    # designs that do
    sel = np.flatnonzero((b.status == 0) | (b.status == 4))[:md]
    md = len(sel)
    params = {v.name: X[sel, j] for j, v in enumerate(pb.variables)}
    mech = pb.mechanism
    t = time.perf_counter()
    a = mech.analyze(np.broadcast_to(S, (md, len(S))), params=params, on_failure="report")
    cyl = a.cylinder("ГЦ")
    res_min = cyl.reserve("S6", float(mech.params["P6"])).min(axis=1)
    cyl.pressure.max(axis=1)
    tp = time.perf_counter() - t
    agree = float(np.max(np.abs(res_min - b.objectives[sel, 0])))
    rate, peer = M * len(S) / te, md * len(S) / tp
    print(f"(e) {M:.0e} designs × {len(S)} positions: {te:.2f} s "
          f"({rate:.3e} designs·positions/s; target ≤ {TARGET_E:g} s: "
          f"{'yes' if te * 1e6 / M <= TARGET_E else 'no'}); {nfeas} feasible; "
          f"reasons of {M - nfeas} infeasible designs in {tr:.2f} s")
    print(f"    peer (analyze + min/max over positions, {md} designs): {peer:.3e}/s; "
          f"ratio {rate / peer:.1f}x; minimum reserve agrees to {agree:.1e} %")
    del X, b, reasons, a

    # ---- (f) -----------------------------------------------------------------------
    t = time.perf_counter()
    r = optimize(pb, popsize=15, maxiter=150, seed=1, polish=False)
    tf = time.perf_counter() - t
    print(f"(f) differential evolution (popsize 15, ≤ 150 generations): {tf:.2f} s, "
          f"{r.evaluations} designs in {r.calls} batches, {r.generations} generations; "
          f"minimum reserve {r.value:.2f} % (seed 8.9 %), feasible: {r.feasible}")
    t = time.perf_counter()
    p = polish(pb, r.x, start_batch=r.batch)
    print(f"    {p.summary()}: {time.perf_counter() - t:.2f} s, {p.nfev} evaluations of the "
          f"exact sensitivities")


if __name__ == "__main__":
    main()
