"""Checks of a solved mechanism (:mod:`assur.core.kinematic_checks`): the closure
residual is rounding for a solved hitch; a dyad's transmission angle is the angle
between its two links at the joint, from the points; the instantaneous centre of a
link is the point about which its points' velocity analogs turn."""

import numpy as np
import pytest

from assur import examples


@pytest.fixture(scope="module")
def hitch():
    m = examples.hitch_003()
    return m, m.solve(np.linspace(0.43, 0.66, 8))


def test_closure_and_transmission_angles(hitch):
    m, kin = hitch
    assert np.max(kin.closure_residual()) < 1e-12
    g = m.group("III (6,7)")
    a, b, c = kin.point(g.a), kin.point(g.b), kin.point(g.out)
    u, w = a - c, b - c
    mu = np.arccos(np.einsum("ij,ij->i", u, w) / np.hypot(*u.T) / np.hypot(*w.T))
    np.testing.assert_allclose(np.abs(np.sin(kin.transmission_angle(g.name))), np.sin(mu),
                               rtol=1e-9)


def test_the_instant_centre_is_where_the_link_turns_about(hitch):
    m, kin = hitch
    c = np.asarray(kin.instant_centre("6")).T  # (positions, 2)
    w = kin.dphi("6")
    for p in ("56", "67", "S6"):
        r = kin.point(p) - c
        v = np.stack([kin.dx(p), kin.dy(p)], -1)
        # v = ω × r: (−ω·ry, ω·rx)
        np.testing.assert_allclose(v, np.stack([-w * r[:, 1], w * r[:, 0]], -1), rtol=1e-7,
                                   atol=1e-9)
