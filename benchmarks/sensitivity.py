"""Timing of the exact sensitivities and of the tolerance Monte Carlo (issue 12).

(a) ``assur.synthesis.sensitivity.sensitivities`` of the seed-003 pipeline — capacity at 56 and
S6, pressure, Y of 56 and S6, the reactions R05 (x, y) and R56 — with respect to all
29 numeric parameters of hitch_003.toml, per position, against the peer in the same
process: complex step of the same pipeline (``jet_outputs`` with one parameter given
an imaginary step, one pass per parameter, as the tests use it), and central
differences of the compiled fused kernel (two batched kernel calls per parameter).
The three are checked to agree first. (b) The Monte Carlo of
hitch_003_tolerances.toml (18 tolerances): machines per second over the 10 positions
of its range, one batch through the fused kernel, and the first-order stack-up
beside it. ``make bench`` runs it after run.py. Figures: best of five warm calls.
"""

from __future__ import annotations

import time

import numpy as np

from assur import examples, io
from assur.synthesis.sensitivity import numeric_parameters, sensitivities
from assur.synthesis.sensitivity.cstep import complex_step
from assur.synthesis.tolerance import monte_carlo

OUTPUTS = ["G(ГЦ, 56)", "G(ГЦ, S6)", "p(ГЦ)", "Y(56)", "Y(S6)", "Rx(0, 5)", "Ry(0, 5)",
           "R(5, 6)"]


def _best(fn, k=5):
    best = float("inf")
    for _ in range(k):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main():
    m = examples.hitch_003()
    params = numeric_parameters(m)
    print(f"sensitivities of the seed-003 pipeline: {len(OUTPUTS)} outputs × {len(params)} "
          f"parameters")
    for n in (10, 1000):
        q = np.linspace(0.425, 0.665, n)

        def exact():
            return sensitivities(m, q, params=params, outputs=OUTPUTS).jacobian

        def cstep():
            return complex_step(m, q, params, OUTPUTS)

        whole = {c.count for c in m.cylinders}  # counts are whole numbers: no ± h
        stepped = [i for i, p in enumerate(params) if p not in whole]

        def central():
            cols = []
            for i in stepped:
                v0 = float(m.params[params[i]])
                h = 1e-6 * max(abs(v0), 1.0)
                fz = m.evaluate(q, {params[i]: np.array([v0 + h, v0 - h])}, outputs=OUTPUTS)
                cols.append(np.stack([(fz[o][0] - fz[o][1]) / (2 * h) for o in OUTPUTS], -1))
            return np.stack(cols, -1)

        a, b, c = exact(), cstep(), central()
        scale = np.abs(b).max(axis=(0, 2), keepdims=True)
        e_cs = float((np.abs(a - b) / scale).max())
        e_cd = float((np.abs(a[..., stepped] - c) / scale).max())
        ta, tb, tc = _best(exact), _best(cstep), _best(central)
        print(f"  n = {n:5d}: exact {ta * 1e3:8.1f} ms ({ta / n * 1e6:7.1f} µs/position)"
              f"   complex step {tb * 1e3:8.1f} ms (×{tb / ta:4.1f})"
              f"   kernel central differences {tc * 1e3:8.1f} ms (×{tc / ta:4.1f}, "
              f"{len(stepped)} parameters);"
              f"  agreement {e_cs:.1e} (cs), {e_cd:.1e} (cd)")

    model = io.load(io.bundled("hitch_003_tolerances"))
    monte_carlo(model, None, model.tolerances, samples=100, seed=0)  # warm (compile)
    for N in (10_000, 100_000):
        t = _best(lambda: monte_carlo(model, None, model.tolerances, samples=N, seed=0), 3)
        print(f"Monte Carlo, {len(model.tolerances)} tolerances, {len(model.range)} positions:"
              f" {N} machines in {t:.2f} s = {N / t:,.0f} machines/s "
              f"({N * len(model.range) / t:,.0f} positions/s, with the stack-up)")


if __name__ == "__main__":
    main()
