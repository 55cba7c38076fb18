"""Running generated kernels: threads, the continuity pass, angle unwrapping.

Kernels release the GIL, so large problems are split over threads. The number of
threads follows the CPUs this process may use (``os.sched_getaffinity``: ``taskset``
and container limits are honoured), or ``$ASSUR_THREADS``, or :func:`set_threads`.
"""

from __future__ import annotations

import math
import os
import sys
from concurrent.futures import ThreadPoolExecutor

from .emit import CONTINUITY_TOL
from .source import CHUNK
from .vector import LARGE, is_vector

__all__ = ["threads", "set_threads", "threads_for", "run", "check_continuity", "unwrap_rows",
           "pool", "MIN_ELEMENTS_PER_THREAD"]

#: elements a thread gets at least: below, handing work to the pool costs more than
#: it saves (a batch of 257 designs at one position, as design conditions solve,
#: runs in the calling thread)
MIN_ELEMENTS_PER_THREAD = 4096

#: columns of an unwrap below which numpy's is faster than the compiled loop's call,
#: once numba is in the process (without it: numpy up to LARGE, numba not started)
UNWRAP_NUMPY = 256

_threads: list = []
_pool: list = []


def threads() -> int:
    """Threads used for large problems (≥ 1).

    Examples
    --------
    >>> from assur.kernel import set_threads, threads
    >>> threads() >= 1                        # the CPUs this process may use, or $ASSUR_THREADS
    True
    >>> set_threads(3)
    >>> threads()
    3
    >>> set_threads(None)
    """
    if _threads:
        return _threads[0]
    env = os.environ.get("ASSUR_THREADS")
    if env:
        try:
            return max(1, int(env))
        except ValueError:
            pass
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):  # not on Linux
        return max(1, os.cpu_count() or 1)


def set_threads(n: int | None) -> None:
    """Use ``n`` threads for large problems (None: back to the CPUs available).

    Examples
    --------
    >>> from assur.kernel import set_threads, threads
    >>> set_threads(2)
    >>> threads()
    2
    >>> set_threads(None)                     # back to the CPUs available
    >>> set_threads(0)
    Traceback (most recent call last):
    ...
    ValueError: threads must be ≥ 1, got 0
    """
    if n is not None and int(n) < 1:
        raise ValueError(f"threads must be ≥ 1, got {n!r}")
    _threads[:] = [] if n is None else [int(n)]


def pool() -> ThreadPoolExecutor:
    """The process's worker threads (grown when more are asked for).

    Examples
    --------
    >>> from assur.kernel.run import pool, threads
    >>> pool().submit(sum, [1, 2, 3]).result()
    6
    >>> pool()._max_workers >= threads(), pool() is pool()   # one pool, reused
    (True, True)
    """
    n = threads()
    if not _pool or _pool[0]._max_workers < n:
        _pool[:] = [ThreadPoolExecutor(max_workers=n, thread_name_prefix="assur")]
    return _pool[0]


def threads_for(elements: int, chunks: int) -> int:
    """Threads for a kernel call over ``elements`` in ``chunks`` work items: each
    gets ≥ 8 chunks and ≥ :data:`MIN_ELEMENTS_PER_THREAD` elements (small problems
    run in the calling thread).

    Examples
    --------
    >>> from assur.kernel.run import set_threads, threads_for
    >>> threads_for(257 * 10, 11)             # 10 designs × 257 positions: small, one thread
    1
    >>> set_threads(4)
    >>> threads_for(1_000_000, 4000), threads_for(20_000, 4000)   # ≥ 4096 elements a thread
    (4, 4)
    >>> threads_for(12_000, 4000)
    2
    >>> set_threads(None)
    """
    if elements < 2 * MIN_ELEMENTS_PER_THREAD or chunks < 16:
        return 1  # without asking the OS for the CPUs (a few µs: one position is ~15 µs)
    return max(1, min(threads(), chunks // 8, elements // MIN_ELEMENTS_PER_THREAD))


def run(kernel, params, trig, q, npd, check, out, gout, status):
    """Run a generated kernel over all elements, split over threads (small problems
    run in the calling thread). Returns the sum of what the kernel returns for its
    ranges (the continuity failures of a fused kernel; 0 for a composed one).

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.kernel.run import run
    >>> m = examples.hitch_003()
    >>> prog = m.program()
    >>> kernel = prog.kernel(("56",), (), vector=True)   # any kernel of this signature
    >>> ptab, trig, _ = m.prepared(prog)
    >>> q = np.array([[0.42, 0.67]])                  # S [m]
    >>> out, amount, status = np.empty((6, 2)), np.empty(2), np.empty(2, dtype=np.int64)
    >>> run(kernel, ptab, trig, q, 2, True, out, amount, status)   # continuity failures
    0
    >>> [round(float(v), 3) for v in out[1]], [round(float(v), 3) for v in out[3]]  # Y56 [m], I56 [-]
    ([0.2, 1.043], [4.459, 2.621])
    """
    E = q.shape[1]
    nchunks = (E // npd) * ((npd + CHUNK - 1) // CHUNK)  # designs × runs per design
    # a numpy-evaluated kernel (assur.kernel.vector) takes all elements in one call
    nthreads = 1 if is_vector(kernel) else threads_for(E, nchunks)
    if nthreads <= 1:
        return kernel(params, trig, q, npd, check, out, gout, status, 0, nchunks) or 0
    per = (nchunks + nthreads - 1) // nthreads
    futs = [pool().submit(kernel, params, trig, q, npd, check, out, gout, status, i * per,
                          min(nchunks, (i + 1) * per)) for i in range(nthreads)]
    return sum(f.result() or 0 for f in futs)


def check_continuity(gout, q, npd, status, amount, codes):
    """Run :func:`continuity` over all elements, split over threads; returns the
    number of failures.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.kernel.run import check_continuity
    >>> gout = np.array([[0.01, 0.01], [-1.0, 1.0]])   # g [m²] and dg/dq [m²/m] of one dyad
    >>> q = np.array([[0.0, 0.1]])                      # two positions of one design [m]
    >>> status, amount = np.array([-1, -1]), np.zeros(2)
    >>> check_continuity(gout, q, 2, status, amount, np.array([103]))   # g dips below 0
    1
    >>> status.tolist(), round(float(amount[1]), 4)    # the dyad's code, the depth [m²]
    ([-1, 103], -0.015)
    >>> gout[1] = [-0.01, 0.01]                         # gentler slopes: stays open
    >>> status[:] = -1
    >>> check_continuity(gout, q, 2, status, amount, np.array([103])), status.tolist()
    (0, [-1, -1])
    """
    E = q.shape[1]
    fn = _continuity()
    nthreads = min(threads(), max(1, E // 65536))
    if nthreads <= 1:
        return fn(gout, q, npd, status, amount, codes, 0, E)
    per = (E + nthreads - 1) // nthreads
    futs = [pool().submit(fn, gout, q, npd, status, amount, codes, i * per,
                          min(E, (i + 1) * per)) for i in range(nthreads)]
    return sum(f.result() for f in futs)


_compiled: dict = {}
_CONT_TOL = CONTINUITY_TOL


def _continuity():
    fn = _compiled.get("continuity")
    if fn is None:
        from numba import njit

        @njit(cache=True, nogil=True, error_model="numpy")
        def continuity(gout, q, npd, status, amount, codes, e_start, e_end):
            """Cubic-Hermite check of every dyad's squared height between consecutive
            positions of each design, for the right-hand elements e_start…e_end−1;
            marks the right-hand element of a failing interval with the dyad's code
            and the depth [m²] in ``amount``. Returns the number of failures."""
            nfail = 0
            for e in range(max(e_start, 1), e_end):
                if e % npd == 0 or status[e] >= 0 or status[e - 1] >= 0:
                    continue
                h = q[0, e] - q[0, e - 1]
                for k in range(codes.shape[0]):
                    g0 = gout[2 * k, e - 1]
                    d0 = gout[2 * k + 1, e - 1]
                    g1 = gout[2 * k, e]
                    d1 = gout[2 * k + 1, e]
                    mn = min(g0, g1)
                    if mn - (4.0 / 27.0) * abs(h) * (abs(d0) + abs(d1)) > 0.0:
                        continue
                    for i in range(1, 16):
                        t = i / 16.0
                        t2 = t * t
                        t3 = t2 * t
                        v = ((2.0 * t3 - 3.0 * t2 + 1.0) * g0 + (t3 - 2.0 * t2 + t) * h * d0
                             + (-2.0 * t3 + 3.0 * t2) * g1 + (t3 - t2) * h * d1)
                        if v < mn:
                            mn = v
                    if mn < -_CONT_TOL * max(g0, g1):
                        status[e] = codes[k]
                        amount[e] = mn
                        nfail += 1
                        break
            return nfail

        fn = _compiled["continuity"] = continuity
    return fn


def unwrap_rows(sv, rows, n):
    """Make angles continuous along positions, in place: ``sv`` shape (ns, E), E = m·n;
    each run of n positions (one design) starts at its principal value [rad].

    Examples
    --------
    >>> import numpy as np
    >>> from assur.kernel.run import unwrap_rows
    >>> sv = np.array([[3.0, -3.0, -2.9, 3.1],     # an angle crossing ±π [rad]
    ...                [0.1, 0.2, 0.3, 0.4]])
    >>> unwrap_rows(sv, [0], 4)                    # row 0 is an angle, one design of 4
    >>> [round(float(v), 3) for v in sv[0]]        # continuous [rad]
    [3.0, 3.283, 3.383, 3.1]
    >>> [round(float(v), 3) for v in sv[1]]        # not an angle row: unchanged
    [0.1, 0.2, 0.3, 0.4]
    """
    if sv.shape[1] <= UNWRAP_NUMPY or ("numba" not in sys.modules and sv.shape[1] <= LARGE):
        # numpy (the same additions in the same order): a few elements, or a call
        # evaluated by numpy where numba is not started (assur.kernel.vector.LARGE)
        _unwrap_small(sv, rows, n)
        return
    fn = _compiled.get("unwrap")
    if fn is None:
        from numba import njit

        @njit(cache=True, nogil=True)
        def unwrap(sv, rows, n):
            m = sv.shape[1] // n
            two_pi = 2.0 * math.pi
            for job in range(rows.shape[0] * m):
                r = rows[job // m]
                d = job % m
                # most angles never step by more than π between positions: a
                # vectorized read-only count first, the sequential pass only if needed
                # (1-D views and a zero-based index: numba's 2-D indexing with i − 1
                # kept the loop scalar, 8× slower)
                nxt = sv[r, d * n + 1:(d + 1) * n]
                prv = sv[r, d * n:(d + 1) * n - 1]
                jumps = 0
                for i in range(nxt.shape[0]):
                    step = nxt[i] - prv[i]
                    jumps += (step > math.pi) | (step < -math.pi)
                if jumps == 0:
                    continue
                off = 0.0
                prev = sv[r, d * n]
                for i in range(d * n + 1, (d + 1) * n):
                    cur = sv[r, i]
                    step = cur - prev
                    if step > math.pi:
                        off -= two_pi
                    elif step < -math.pi:
                        off += two_pi
                    prev = cur
                    sv[r, i] = cur + off

        fn = _compiled["unwrap"] = unwrap
    fn(sv, rows, n)


def _unwrap_small(sv, rows, n):
    """:func:`unwrap_rows` in numpy, for a few elements (no numba start-up): the offset
    of each position is the running sum of the ±2π steps, as the compiled loop adds
    them."""
    import numpy as np

    two_pi = 2.0 * math.pi
    m = sv.shape[1] // n
    for r in rows:
        a = sv[r].reshape(m, n)
        step = np.diff(a, axis=1)
        jump = np.where(step > math.pi, -two_pi, np.where(step < -math.pi, two_pi, 0.0))
        a[:, 1:] += np.cumsum(jump, axis=1)
        sv[r] = a.reshape(-1)
