"""The RRR dyad (:mod:`assur.groups.rrr`): its position formula puts the joint at
both radii from the outer joints, on the side of a → b its branch says, for any
triangle that closes; the closure residual is zero there and the size of a
displacement off it; the kernel agrees on the seed-003 hitch."""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from assur import examples
from assur.groups import Dyad
from assur.groups.base import ref_value
from assur.groups.rrr import dyad_position
from tests.helpers import examples as n_examples

coord = st.floats(-2.0, 2.0)


@settings(max_examples=n_examples(200), deadline=None)
@given(coord, coord, coord, coord, st.floats(0.05, 2.0), st.floats(0.05, 2.0),
       st.sampled_from((1, -1)))
def test_the_joint_is_at_both_radii_on_the_branch_side(ax, ay, bx, by, ra, rb, branch):
    L = math.hypot(bx - ax, by - ay)
    assume(L > 1e-3 and abs(ra - rb) + 1e-6 < L < ra + rb - 1e-6)
    pts = {"A": (ax, ay), "B": (bx, by)}
    cx, cy = dyad_position(pts, "A", "B", ra, rb, branch)
    tol = 1e-9 * (1 + ra + rb) / min(1.0, (ra + rb - L) * (L - abs(ra - rb)) / L ** 2)
    assert math.hypot(cx - ax, cy - ay) == pytest.approx(ra, abs=tol)
    assert math.hypot(cx - bx, cy - by) == pytest.approx(rb, abs=tol)
    side = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)  # > 0: C left of A → B
    assert np.sign(side) == branch
    g = Dyad("II", a="A", b="B", out="C", ra=ra, rb=rb, branch=branch)
    g.evaluate(pts, float)
    assert float(g.closure(pts.get, float)) <= tol
    pts["C"] = (pts["C"][0] + 0.01, pts["C"][1])
    assert float(g.closure(pts.get, float)) > 1e-4


def test_the_kernel_agrees_with_the_formula_on_the_hitch():
    m = examples.hitch_003()
    S = np.linspace(0.42, 0.67, 6)
    kin = m.solve(S)
    val = lambda ref: ref_value({**m.params, "S": S}, ref)  # noqa: E731
    pts = m.evaluate_positions({"S": S})
    for g in m.groups:
        if type(g) is Dyad:
            want = dyad_position(pts, g.a, g.b, val(g.ra), val(g.rb), g.branch)
            np.testing.assert_allclose(kin.point(g.out), np.stack(want, -1), rtol=0,
                                       atol=1e-12)
