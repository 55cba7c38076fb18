"""Running kernels (:mod:`assur.kernel.run`): the fast paths of issue 7's speed work
give the same answers as the paths they replace — the continuity check inside the
fused kernel (across work items and designs) against the separate pass of composed
kernels; small kernel calls stay in the calling thread. (The fused statics a
mechanism switches to after a few small analyses: tests/core/test_outputs.py; the
element loop's stores: tests/kernel/test_source.py.)"""

from __future__ import annotations

import numpy as np

from assur import examples
from assur.core import program as P
from assur.kernel import compose
from assur.kernel import emit as KE
from assur.kernel import run as KR
from assur.kernel.source import CHUNK
from tests.helpers import by_numpy
from tests.helpers.mechanisms import crank_dyad


def _run(mech, q, n, path, monkeypatch):
    monkeypatch.setattr(compose, "THRESHOLD", 10**9 if path == "fused" else 0)
    monkeypatch.setattr(P, "_KERNELS", {})
    monkeypatch.setattr(P, "_PROGRAMS", {})
    monkeypatch.setattr(P, "REFINE_DEPTH", 0)  # the raw flags of both checks
    prog = P.compile_program(mech)
    m = q.shape[1] // n
    ptab = np.ascontiguousarray(np.repeat(prog.param_table(mech.params), m, axis=1))
    return P.execute(prog, ptab, np.ascontiguousarray(q), n, True)


def test_in_kernel_continuity_equals_the_separate_pass(monkeypatch):
    """Two designs of 2·CHUNK + 1 positions; the dyad opens between samples at the
    end of a work item (the interval CHUNK − 1 → CHUNK spans two work items), inside
    one, at the last position, and between the designs (not an interval)."""
    n = 2 * CHUNK + 1
    q1 = np.empty(n)
    q1[:CHUNK] = np.linspace(0.0, 1.25, CHUNK)
    q1[CHUNK:] = np.linspace(1.9, 2.5, n - CHUNK)   # jumps over the gap at CHUNK
    q1[100] = 1.9                                    # and back at 100 → 101
    q2 = np.linspace(2.5, 2.0, n)
    q2[-1] = 1.0                                     # the last interval
    q = np.concatenate([q1, q2])[None, :]
    fused = _run(crank_dyad(), q, n, "fused", monkeypatch)
    composed = _run(crank_dyad(), q, n, "composed", monkeypatch)
    code = 3 * KE.CODES_PER_OP + KE.FAIL_CONTINUITY
    flagged = np.flatnonzero(fused["status"] == code)
    assert set(flagged) >= {CHUNK, 100, 2 * n - 1}
    assert n not in flagged  # the first position of the second design
    assert np.array_equal(fused["status"], composed["status"])
    assert np.array_equal(fused["amount"][flagged], composed["amount"][flagged])
    assert (fused["amount"][flagged] < 0).all()


def test_small_kernel_calls_stay_in_the_calling_thread(monkeypatch):
    def no_pool():
        raise AssertionError("a small problem went to the thread pool")

    monkeypatch.setattr(KR, "pool", no_pool)
    monkeypatch.setattr(KR, "threads", lambda: 2)
    assert KR.threads_for(257, 257) == 1  # a condition's scan: 257 designs, 1 position
    m = by_numpy(examples.hitch_003)
    m.solve(np.linspace(0.42, 0.67, 1000))
    m.solve(np.full((257, 1), 0.5), params={"L5": np.linspace(0.47, 0.49, 257)})
    assert KR.threads_for(10**6, 10**6 // CHUNK) == 2


