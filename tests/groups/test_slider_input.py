"""The slider input (:mod:`assur.groups.slider_input`): the slider sits at
``s + offset`` along its line through ``origin`` — the two rod ends of seed 001 lab
4's double-rod cylinder move with S, ∂x/∂S = 1, and stay 2·h_rod apart."""

import numpy as np
import pytest

from assur import examples
from assur.groups import SliderInput
from assur.groups.base import ref_value


def test_rod_ends_of_the_double_rod_cylinder():
    m = examples.steering_lab4_modern()
    S = examples.steering_lab4_modern_range()
    kin = m.solve(S)
    ends = [g for g in m.groups if isinstance(g, SliderInput)]
    assert len(ends) == 2
    for g in ends:
        off = ref_value(m.params, g.offset)  # a signed reference: "-h_rod"
        u = np.array([np.cos(g.direction), np.sin(g.direction)])
        want = kin.point(g.origin) + (S + off)[:, None] * u
        np.testing.assert_allclose(kin.point(g.out), want, rtol=0, atol=1e-12)
        np.testing.assert_allclose(kin.dx(g.out), np.cos(g.direction), rtol=0, atol=1e-12)
    a, b = (kin.point(g.out) for g in ends)
    np.testing.assert_allclose(np.hypot(*(b - a).T), 2 * m.params["h_rod"], rtol=1e-12)
    assert ends[0].coordinates_driven() == ("S",)
    assert sorted(ref_value(m.params, g.offset) for g in ends) == \
        pytest.approx([-m.params["h_rod"], m.params["h_rod"]])
