"""Positions and exact analogs by name (:mod:`assur.core.analogs`) on the seed-003
hitch: every first analog is the central difference of its position, every second
analog that of the first — points, link angles and named lengths — and the
transmission number is the vertical analog."""

import numpy as np
import pytest

from assur import examples

S = np.linspace(0.43, 0.66, 7)
H = 1e-6


@pytest.fixture(scope="module")
def three():
    m = examples.hitch_003()
    return m, m.solve(S - H), m.solve(S), m.solve(S + H)


def fd(lo, hi):
    return (hi - lo) / (2 * H)


def test_first_and_second_analogs_are_differences(three):
    m, lo, kin, hi = three
    for p in m.points:
        for f, df in (("x", "dx"), ("y", "dy"), ("dx", "ddx"), ("dy", "ddy")):
            want = fd(getattr(lo, f)(p), getattr(hi, f)(p))
            np.testing.assert_allclose(getattr(kin, df)(p), want, rtol=1e-6,
                                       atol=1e-6 * (1 + np.abs(want).max()), err_msg=(p, f))
        np.testing.assert_array_equal(kin.transmission(p), kin.dy(p))
    for link in m.links:
        for f, df in (("phi", "dphi"), ("dphi", "ddphi")):
            want = fd(getattr(lo, f)(link.name), getattr(hi, f)(link.name))
            np.testing.assert_allclose(getattr(kin, df)(link.name), want, rtol=1e-6,
                                       atol=1e-6 * (1 + np.abs(want).max()))


def test_values_and_points_agree():
    m = examples.hitch_003()
    kin = m.solve(S)
    for p in m.points:
        np.testing.assert_array_equal(kin.point(p), np.stack([kin.x(p), kin.y(p)], -1))
    with pytest.raises(KeyError):
        kin.x("nowhere")
