"""The PRP dyad (:mod:`assur.groups.prp`, two sliders joined by a pin): the pin is on
line a through ``a`` and on line b through ``b`` — absolute directions, or turned from
a moving link — for any pair of lines that cross (the plain-numpy formula)."""

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from assur.groups import DoubleSliderDyad
from tests.helpers import examples as n_examples


def _on_line(p, q, beta):
    return (p[0] - q[0]) * math.sin(beta) - (p[1] - q[1]) * math.cos(beta)


@settings(max_examples=n_examples(150), deadline=None)
@given(st.floats(-1, 1), st.floats(-1, 1), st.floats(-1, 1), st.floats(-1, 1),
       st.floats(-math.pi, math.pi), st.floats(-math.pi, math.pi))
def test_the_pin_is_on_both_lines(ax, ay, bx, by, ta, tb):
    assume(abs(math.sin(ta - tb)) > 0.05)
    pts = {"A": (ax, ay), "B": (bx, by)}
    DoubleSliderDyad("II", a="A", b="B", out="C", direction_a=ta, direction_b=tb) \
        .evaluate(pts, float)
    tol = 1e-9 / abs(math.sin(ta - tb))
    assert _on_line(pts["C"], pts["A"], ta) == pytest.approx(0, abs=tol)
    assert _on_line(pts["C"], pts["B"], tb) == pytest.approx(0, abs=tol)


def test_a_line_turned_from_a_link():
    # line a through A along P → Q (vertical) turned by +90°: horizontal through A
    pts = {"P": (0.0, 0.0), "Q": (0.0, 1.0), "A": (0.3, 0.5), "B": (1.0, 0.0)}
    DoubleSliderDyad("II", a="A", b="B", out="C", direction_a=math.pi / 2,
                     direction_b=math.pi / 2, line_link_a=("P", "Q")).evaluate(pts, float)
    assert pts["C"] == (pytest.approx(1.0), pytest.approx(0.5))
