"""Cold compile time of the kinematics kernel against the number of groups.

    .venv/bin/python benchmarks/compile_time.py            # table, one subprocess per N
    .venv/bin/python benchmarks/compile_time.py KIND N     # one measurement (JSON line)

Each measurement runs in a fresh process with a fresh kernel cache
(``ASSUR_CACHE_DIR``) and numba cache (``NUMBA_CACHE_DIR``): the time is that of
the first ``solve`` of a new structure (source generation, numba typing, LLVM),
less that of a second, warm one. The group functions of composed kernels are shared
by all structures (cached on disk): the first composed structure of a process here
compiles them cold, as on a new machine. ``generate`` is the time of the fused
kernel's source and ``lines`` its length (for comparison; a composed structure does
not compile it). KIND is ``rigid`` (the seed-003 hitch plus rigid
points) or ``chain`` (a chain of RRR dyads, each with its own frame point).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
SIZES = (5, 10, 20, 50, 100, 200)


def measure(kind: str, n: int, threshold=None) -> dict:
    sys.path.insert(0, str(HERE))
    import numpy as np

    try:
        from assur.kernel import compose
    except ImportError:  # a version without composed kernels (for comparisons)
        compose = None
    if threshold is not None:
        compose.THRESHOLD = threshold

    from structures import with_groups

    from assur.kernel import source
    from assur.core.program import compile_program

    m = with_groups(kind, n)
    q = np.linspace(0.50, 0.55, 3)
    # compile the helper kernels (continuity, unwrapping) on a small mechanism first
    with_groups("chain", 7).solve(q)
    prog = compile_program(m)
    t0 = time.perf_counter()
    src = source.generate(prog.rows, prog.measures, prog.k,
                          tuple(prog.slot[p] for p in prog.out_pts),
                          tuple(prog.scal[s] for s in prog.out_sca))
    t_gen = time.perf_counter() - t0
    t0 = time.perf_counter()
    m.solve(q, on_failure="report")
    t_first = time.perf_counter() - t0
    t0 = time.perf_counter()
    m.solve(q, on_failure="report")
    t_warm = time.perf_counter() - t0
    rss = float("nan")
    try:  # this process's own peak (ru_maxrss would include the parent's at fork)
        with open("/proc/self/status") as f:
            rss = next(int(v.split()[1]) for v in f if v.startswith("VmHWM:")) / 1024
    except (OSError, StopIteration):
        pass
    return dict(kind=kind, n=n, groups=len(prog.rows), lines=src.count("\n"),
                composed=compose is not None
                and len(prog.rows) + len(prog.measures) > compose.THRESHOLD,
                generate=t_gen, compile=t_first - t_warm, rss_mb=rss)


def run_one(kind: str, n: int, timeout: float = 600, threshold=None) -> dict:
    """``measure`` in a fresh process with fresh caches."""
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, ASSUR_CACHE_DIR=tmp, NUMBA_CACHE_DIR=tmp)
        try:
            p = subprocess.run([sys.executable, str(Path(__file__).resolve()), kind, str(n)]
                               + ([] if threshold is None else [str(threshold)]),
                               env=env, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return dict(kind=kind, n=n, error=f"timeout after {timeout:.0f} s")
        if p.returncode:
            last = (p.stderr.strip().splitlines() or ["?"])[-1]
            return dict(kind=kind, n=n, error=last[:80])
        return json.loads(p.stdout.strip().splitlines()[-1])


def table(kinds=("rigid", "chain"), sizes=SIZES, timeout=600, out=print):
    out(f"{'structure':<10} {'N':>5} {'groups':>6} {'kernel':>8} {'lines':>7} "
        f"{'generate s':>10} {'compile s':>10} {'s/group':>8} {'max RSS MB':>10}")
    for kind in kinds:
        for n in sizes:
            r = run_one(kind, n, timeout)
            if "error" in r:
                out(f"{kind:<10} {n:>5}  failed: {r['error']}")
                continue
            path = "composed" if r["composed"] else "fused"
            out(f"{kind:<10} {n:>5} {r['groups']:>6} {path:>8} {r['lines']:>7} "
                f"{r['generate']:>10.3f} "
                f"{r['compile']:>10.2f} {r['compile'] / r['groups']:>8.3f} {r['rss_mb']:>10.0f}")


if __name__ == "__main__":
    if len(sys.argv) in (3, 4):
        th = int(sys.argv[3]) if len(sys.argv) == 4 else None
        print(json.dumps(measure(sys.argv[1], int(sys.argv[2]), th)))
    else:
        sizes = tuple(int(s) for s in sys.argv[1].split(",")) if len(sys.argv) == 2 else SIZES
        table(sizes=sizes)
