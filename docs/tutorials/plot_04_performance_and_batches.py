"""
Performance and batches
=======================

The group sequence of a mechanism is compiled into one fused, parallel loop (numba),
generated per structure and cached on disk (``~/.cache/assur`` or
``$ASSUR_CACHE_DIR``): a structure compiles once per machine. Every quantity is an
array over ``(designs, positions)``, so a sweep of many designs is one call.
``make bench`` measures the throughput against a plain-numpy port of the seed's own
formulas (``benchmarks/README.md``); this page only shows the ways to call it.
"""

# %%
# Many positions, one design
# --------------------------
import time

import numpy as np

from assur import examples

m = examples.hitch_003()
S = np.linspace(0.42, 0.67, 200_000)
m.solve(S)  # the first call loads (or compiles) the kernel: time the second
t0 = time.perf_counter()
r = m.solve(S)
print(f"{S.size} positions with first and second analogs in {time.perf_counter() - t0:.3f} s")

# %%
# The same size again and again
# -----------------------------
# A loop that solves as many positions each time can write into the memory of the
# previous result: fresh memory costs the operating system's zeroing of every page on
# first touch. The earlier result then holds the new values; keep only the new one.
t0 = time.perf_counter()
r = m.solve(S[::-1], out=r)
print(f"again, into the same memory, in {time.perf_counter() - t0:.3f} s; "
      f"φ6 at S = {S[-1]} m: {r.phi('6', degrees=True)[0]:.2f}°")

# %%
# Only what is asked
# ------------------
# ``evaluate`` generates a kernel that writes only the named outputs — positions,
# analogs, forces, reactions, capacities — per position, in one pass:
f = m.evaluate(S, outputs=["G(ГЦ, 56)", "p(ГЦ)", "Rx(0, 5)", "Ry(0, 5)"])
for name in f.outputs:
    print(f"{name:10s} at the ends of the stroke: {np.round(f[name][[0, -1]], 1)}")

# %%
# Reductions over positions
# -------------------------
# For a sweep of designs, ``reduce=True`` keeps only the minimum and maximum of each
# output over the positions of every design (and where they occur), storing no
# positions at all; designs that cannot assemble are reported, not raised:
L5 = np.linspace(0.40, 0.56, 2000)
red = m.evaluate(np.linspace(0.42, 0.67, 50), params={"L5": L5},
                 outputs=["reserve(ГЦ, S6, P6)"], reduce=True, on_failure="report")
best = int(np.argmax(red.min("reserve(ГЦ, S6, P6)")))
print(f"{L5.size} designs; the least reserve over the stroke is largest, "
      f"{red.min('reserve(ГЦ, S6, P6)')[best]:.1f} %, at L5 = {L5[best]:.4f} m")

# %%
# Threads and chunks
# ------------------
# Threads follow the CPUs the process may use (``taskset``, containers), or
# ``$ASSUR_THREADS``, or :func:`assur.kernel.set_threads`; calls of fewer than a few
# thousand elements run in the calling thread. A large sweep is a list of independent
# chunks of designs: running them in-process, in a process pool or on a Dask cluster
# is a choice of executor, not of code path.
from assur.kernel import run  # noqa: E402

print("threads this process uses:", run.threads())
