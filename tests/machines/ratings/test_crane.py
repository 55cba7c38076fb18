"""crane_chart against the closed-form limits of a two-link arm, and the seed-004
cranes' charts."""

import math

import numpy as np
import pytest

from assur import io
from assur.machines.ratings.crane import holding_limit
from tests.helpers.ratings import hand_limit, hand_rates

CHART = '''
[[rating]]
type = "crane_chart"
point = "T"
axis = "O"
'''


def test_two_link_arm_cylinder_limits_by_hand(arm_text):
    model = io.loads(arm_text + CHART)
    kin = model.mechanism.solve(model.range)
    r = model.ratings[0].evaluate(model.mechanism, kin)
    n = len(model.range)
    assert n == 12
    for i in range(n):
        w1, w2, P = hand_rates(kin, i)
        # a vertical load at T: ∂Y_T/∂S1 = (x_T − x_O)·dθ1/dS1 (the whole arm turns
        # about O), ∂Y_T/∂S2 = (x_T − x_O1)·dθ2/dS2 (the bucket about O1)
        I1 = P["T"][0] * w1
        I2 = (P["T"][0] - P["O1"][0]) * w2
        dead1 = 5000.0 * P["C"][0] * w1   # the 5 kN weight at C on link 1 (not at T)
        g1 = hand_limit("c1", I1, dead1)
        g2 = hand_limit("c2", I2, 0.0)
        assert r["G_c1"][i] == pytest.approx(g1, rel=1e-9, abs=1e-9)
        assert r["G_c2"][i] == pytest.approx(g2, rel=1e-9, abs=1e-9)
        assert r["G"][i] == pytest.approx(min(g1, g2), rel=1e-9)
        assert r["governing"][i] == (1.0 if g1 < g2 else 2.0)
        assert r["reach"][i] == P["T"][0] and r["height"][i] == P["T"][1]
    np.testing.assert_array_equal(r["M"], r["G"] * r["reach"])


def test_without_self_weight_the_dead_load_is_left_out(arm_text):
    model = io.loads(arm_text + CHART + "self_weight = false\n")
    kin = model.mechanism.solve(model.range)
    r = model.ratings[0].evaluate(model.mechanism, kin)
    w1, _, P = hand_rates(kin, 0)
    assert r["G_c1"][0] == pytest.approx(hand_limit("c1", P["T"][0] * w1, 0.0), rel=1e-9)


def test_holding_limit_is_infinite_where_the_cylinder_carries_nothing():
    from assur.core.cylinders import Cylinder
    c = Cylinder("c", coordinate="S", bore=0.1, rod=0.05, p_relief=10e6, side="extend")
    G = holding_limit(None, c, np.array([0.0, 1.0, -1.0]))
    assert G[0] == np.inf
    assert G[1] == pytest.approx(10e6 * math.pi * 0.01 / 4, rel=1e-12)
    assert G[2] == pytest.approx(10e6 * math.pi * (0.01 - 0.0025) / 4, rel=1e-12)


@pytest.mark.parametrize("name", ["crane_lv184a", "crane_lv185", "crane_lv215"])
def test_seed_004_charts_are_sane(name):
    a = io.load(io.bundled(name)).analyze()
    (r,) = a.ratings
    assert r.rating.type_name == "crane_chart"
    assert (r["G"] > 0).all() and np.isfinite(r["G"]).all()
    np.testing.assert_array_equal(r["M"], r["G"] * r["reach"])
    np.testing.assert_array_equal(r["G"], np.minimum(r["G_boom_cylinder"], r["G_stick_cylinder"]))
    assert (r["reach"] > 0).any()
    # the heavier load of ЛВ-215 is the payload the chart replaces: the same chart as ЛВ-185

