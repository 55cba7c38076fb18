"""The RPR dyad (:mod:`assur.groups.rpr`, the slotted lever): the rod pinned at ``a``
passes through the sleeve at ``b`` at the signed offset ``e`` (b on the left of the
rod for e > 0), the sleeve ahead of the pin for branch +1, and ``out`` is at ``length``
along the rod — for any geometry (the plain-numpy formula)."""

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from assur.groups import SleeveDyad
from tests.helpers import examples as n_examples


@settings(max_examples=n_examples(150), deadline=None)
@given(st.floats(-1, 1), st.floats(-1, 1), st.floats(-1, 1), st.floats(-1, 1),
       st.floats(-1.0, 1.0), st.floats(0.1, 2.0), st.sampled_from((1, -1)))
def test_the_rod_passes_the_sleeve_at_its_offset(ax, ay, bx, by, e_share, ell, branch):
    D = math.hypot(bx - ax, by - ay)
    assume(D > 1e-2)
    e = 0.9 * e_share * D
    pts = {"A": (ax, ay), "B": (bx, by)}
    SleeveDyad("II", a="A", b="B", out="E", length=ell, offset=e, branch=branch) \
        .evaluate(pts, float)
    ex, ey = pts["E"]
    ux, uy = (ex - ax) / ell, (ey - ay) / ell
    assert math.hypot(ex - ax, ey - ay) == pytest.approx(ell, abs=1e-9)
    wx, wy = bx - ax, by - ay
    assert ux * wy - uy * wx == pytest.approx(e, abs=1e-9)  # û × (B − A) = e
    assert math.copysign(1, ux * wx + uy * wy) == branch  # the sleeve ahead for +1


def test_the_documented_slotted_lever():
    pts = {"A": (0.0, 0.12), "B": (0.16, 0.0)}
    SleeveDyad("II", a="A", b="B", out="E", length=0.55).evaluate(pts, float)
    assert pts["E"][0] == pytest.approx(0.44) and pts["E"][1] == pytest.approx(-0.21)
