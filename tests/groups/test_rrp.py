"""The RRP dyad (:mod:`assur.groups.rrp`): the joint at ``radius`` from ``a`` on its
line — fixed, or turned from a moving link — on the side ``branch`` says (the sign
of û·(out − a)), for any geometry that closes (the plain-numpy formula)."""

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from assur.groups import SliderDyad
from tests.helpers import examples as n_examples


@settings(max_examples=n_examples(150), deadline=None)
@given(st.floats(-1, 1), st.floats(-1, 1), st.floats(-1, 1), st.floats(-1, 1),
       st.floats(-math.pi, math.pi), st.floats(0.05, 2.0), st.sampled_from((1, -1)))
def test_on_the_circle_and_the_line(ax, ay, lx, ly, beta, r, branch):
    ux, uy = math.cos(beta), math.sin(beta)
    dist = abs((ax - lx) * uy - (ay - ly) * ux)  # of a from the line
    assume(dist < r * (1 - 1e-3))
    pts = {"A": (ax, ay), "L0": (lx, ly)}
    SliderDyad("II", a="A", out="C", radius=r, line_point="L0", direction=beta,
               branch=branch).evaluate(pts, float)
    cx, cy = pts["C"]
    assert math.hypot(cx - ax, cy - ay) == pytest.approx(r, abs=1e-9)
    assert (cx - lx) * uy - (cy - ly) * ux == pytest.approx(0, abs=1e-9)  # on the line
    assert math.copysign(1, (cx - ax) * ux + (cy - ay) * uy) == branch


def test_a_line_turned_from_a_link():
    pts = {"P": (0.0, 0.0), "Q": (0.0, 2.0), "A": (0.5, 0.0)}
    # the line through Q along P → Q turned by −90°: horizontal, y = 2
    g = SliderDyad("II", a="A", out="C", radius=2.5, line_point="Q", direction=-math.pi / 2,
                   line_link=("P", "Q"))
    g.evaluate(pts, float)
    assert pts["C"][1] == pytest.approx(2.0) and pts["C"][0] == pytest.approx(2.0)
