"""Timing of the lab-6 lift (seed 001 lab 6, examples/adapter_lab6.toml): 4 s of
motion simulated with each stiff-capable method, with the number of right-hand-side
evaluations (issue 11 target: ≤ 0.2 s); and of seed 004's sweep (17 cycle times × 4
scenarios × 3 cranes, :func:`assur.dynamics.cycles.sweep`; target ≤ 5 s), with the
number of positions whose equations of motion it evaluates (it integrates no ODE:
constant rod speeds); and of the crane's swing (examples/crane_lv184a.toml: two
cylinders through a flow divider, 8.5 s, the mechanism solved at every state).
``make bench`` runs it after run.py.

The mechanism's table (its kernel loaded or compiled, m, m', Q at 801 nodes) is
built by the first call, reported as "start-up"; the figures are the best of five
warm calls. Before timing, the energy balance of each run is checked (< 1e-3).
"""

from __future__ import annotations

import time

from assur import io
from assur.dynamics import simulate_model
from assur.dynamics.simulate import METHODS

TARGET = 0.2  # [s]


def main():
    model = io.load(io.bundled("adapter_lab6"))
    t0 = time.perf_counter()
    simulate_model(model, t_end=4.0)
    print(f"lab-6 lift, 4 s of motion: start-up {time.perf_counter() - t0:.2f} s")
    for method in METHODS:
        best = float("inf")
        for _ in range(5):
            t0 = time.perf_counter()
            r = simulate_model(model, t_end=4.0, method=method)
            best = min(best, time.perf_counter() - t0)
        assert r.success, r.message
        rel = abs(r.energy["residual"]) / r.energy["pump"]
        assert rel < 1e-3, rel
        print(f"  {method:6s} {best * 1e3:8.1f} ms  nfev = {r.nfev:5d}  njev = {r.njev:3d}  "
              f"energy residual {rel:.1e}  (target ≤ {TARGET * 1e3:.0f} ms)")

    from assur.dynamics.cycles import strokes, sweep
    cranes = [io.load(io.bundled(n)) for n in ("crane_lv184a", "crane_lv185", "crane_lv215")]

    def run():
        n = 0
        for c in cranes:
            df = sweep(c.mechanism, *strokes(c.drive))
            n += len(df)
        return n
    t0 = time.perf_counter()
    rows = run()
    cold = time.perf_counter() - t0
    best = min(_timed(run) for _ in range(3))
    positions = sum(82 if s.startswith(("separate", "combined_equal")) else 41
                    for s in ("combined_equal", "combined_ideal", "separate_second",
                              "separate_first")) * 17 * 3
    print(f"seed-004 sweep: {rows} cycles (17 T × 4 scenarios × 3 cranes), {positions} "
          f"positions, start-up {cold:.2f} s, best {best * 1e3:.1f} ms (target ≤ 5000 ms)")

    crane = cranes[0]
    t0 = time.perf_counter()
    r = simulate_model(crane)
    wall = time.perf_counter() - t0
    assert r.success, r.message
    rel = abs(r.energy["residual"]) / r.energy["pump"]
    assert rel < 1e-3, rel
    print(f"crane swing (ЛВ-184А, 2 cylinders, 8.5 s, Radau): {wall:.2f} s  nfev = {r.nfev}  "
          f"njev = {r.njev}  energy residual {rel:.1e}  ({wall / r.nfev * 1e3:.2f} ms an "
          f"evaluation)")


def _timed(f):
    t0 = time.perf_counter()
    f()
    return time.perf_counter() - t0


if __name__ == "__main__":
    main()
