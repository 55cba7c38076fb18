"""Streaming stores (:mod:`assur.kernel.stream`, issue 7's code-generation speed-ups
change no answer): a solve large enough to stream its outputs (rows × positions ≥
STREAM_MIN) equals, bitwise, the same positions solved in small pieces with ordinary
stores — with row starts at every alignment (an odd number of positions) and several
designs of a length that is not a multiple of a work item."""

from __future__ import annotations

import numpy as np
import pytest

from assur import examples as bundled_examples
from assur.kernel import stream as KST
from tests.helpers import by_numpy


@pytest.mark.parametrize("designs", [1, 3])
def test_streamed_outputs_equal_small_solves(designs):
    """The hitch over enough positions to stream (63 rows × ≥ 16 651 positions ≥
    STREAM_MIN) equals the same positions solved 997 at a time, bitwise: positions,
    analogs, angles (unwrapped) and status, for one design and for three designs of
    an odd number of positions (every row start at another alignment)."""
    m = by_numpy(bundled_examples.hitch_003)
    n = 16651 if designs == 1 else 5557
    assert 63 * n * designs >= KST.STREAM_MIN   # the kernel streams its outputs
    S = np.linspace(0.42, 0.67, n)
    params = None if designs == 1 else {"L3": np.array([0.258, 0.26, 0.262])}
    q = S if designs == 1 else np.tile(S, (designs, 1))
    big = m.solve(q, params=params)
    for d in range(designs):
        for a in range(0, n, 997):
            b = min(n, a + 997)
            sub = {"L3": params["L3"][d]} if params else None
            small = m.solve(S[a:b], params=sub)
            for p in ("23", "45", "56", "S6"):
                for fn in ("x", "y", "dx", "dy", "ddx", "ddy"):
                    want = getattr(small, fn)(p)
                    got = getattr(big, fn)(p)
                    got = got[a:b] if designs == 1 else got[d, a:b]
                    assert np.array_equal(got, want.reshape(got.shape)), (p, fn, d, a)
            for k in ("3", "4", "5", "6", "7"):
                for fn in ("phi", "dphi", "ddphi"):
                    got = getattr(big, fn)(k)
                    got = got[a:b] if designs == 1 else got[d, a:b]
                    want = getattr(small, fn)(k).reshape(got.shape)
                    if fn == "phi":   # unwrapped from another start: equal up to 2π·j
                        want = want + 2 * np.pi * np.round((got[0] - want[0]) / (2 * np.pi))
                    assert np.array_equal(got, want), (k, fn, d, a)

