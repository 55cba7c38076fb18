"""Rigid points (:mod:`assur.groups.rigid`): a point at ``length`` from ``origin``,
turned ``angle`` from ``origin → toward`` — or given by its triangle's three sides
and the turn's side — for any geometry; the kernel's arm 34 of the hitch keeps
φBD = 22° to the lever."""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from assur import examples
from assur.groups import RigidPoint
from tests.helpers import examples as n_examples


@settings(max_examples=n_examples(100), deadline=None)
@given(st.floats(-1, 1), st.floats(-1, 1), st.floats(-math.pi, math.pi),
       st.floats(0.1, 1.0), st.floats(0.1, 1.0), st.floats(0.2, math.pi - 0.2),
       st.sampled_from((1, -1)))
def test_by_angle_and_by_triangle(ox, oy, th, base, ell, gam, branch):
    pts = {"O": (ox, oy), "T": (ox + base * math.cos(th), oy + base * math.sin(th))}
    RigidPoint("P", origin="O", toward="T", out="P", length=ell, angle=branch * gam) \
        .evaluate(pts, float)
    px, py = pts["P"]
    assert math.hypot(px - ox, py - oy) == pytest.approx(ell, abs=1e-12)
    turned = math.atan2(py - oy, px - ox) - th
    assert math.remainder(turned - branch * gam, 2 * math.pi) == pytest.approx(0, abs=1e-9)
    opp = math.sqrt(base ** 2 + ell ** 2 - 2 * base * ell * math.cos(gam))
    assume(opp > 1e-3)
    q = {"O": pts["O"], "T": pts["T"]}
    RigidPoint("Q", origin="O", toward="T", out="Q", length=ell, base=base, opposite=opp,
               branch=branch).evaluate(q, float)
    assert q["Q"][0] == pytest.approx(px, abs=1e-7) and q["Q"][1] == pytest.approx(py, abs=1e-7)


def test_the_hitch_arm_keeps_its_angle_to_the_lever():
    m = examples.hitch_003()
    kin = m.solve(np.linspace(0.42, 0.67, 11))
    np.testing.assert_allclose(kin.phi("34") - kin.phi("3"), m.params["phiBD"], rtol=0,
                               atol=1e-12)
