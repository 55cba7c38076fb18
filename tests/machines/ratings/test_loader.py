"""Loader ratings (ISO 14397-1/-2) on a lever loader whose tipping load and breakout
forces follow by hand: the two-link arm of tests.helpers.ratings as boom (c1) and
bucket (c2), on a machine with two axles."""

import numpy as np
import pytest

from assur import io
from tests.helpers.ratings import hand_limit, hand_rates

MACHINE = '''
[[groups]]
name = "bucket back K"
type = "rigid_point"
origin = "T"
toward = "O1"
out = "K"
length = "0.4 m"
angle = "10 deg"
links = ["2"]

[machine]
axles = { near = "-0.1 m", far = "2.0 m" }
steered = "far"
weights = [{ name = "body", P = "60 kN", x = "1.2 m" }]
counterweights = [{ name = "ballast", P = "8 kN", x = "2.4 m" }]
implement = { point = "T", weight = "10 kN" }
'''

TIPPING = '''
[[rating]]
type = "loader_tipping"
point = "T"
fraction = 0.5
'''

BREAKOUT = '''
[[rating]]
type = "loader_breakout"
edge = "T"
back = "K"
lift_cylinder = "c1"
tilt_cylinder = "c2"
'''

X_NEAR = -0.1
FIXED = [(60000.0, 1.2), (8000.0, 2.4)]     # the machine's weights [N], their x [m]


def test_tipping_load_and_rated_operating_capacity_by_hand(arm_text):
    model = io.loads(arm_text + MACHINE + TIPPING)
    kin = model.mechanism.solve(model.range)
    r = model.ratings[0].evaluate(model.mechanism, kin)
    xT = kin.x("T").ravel()
    xC = kin.x("C").ravel()
    assert (xT < X_NEAR).all()          # the load ahead of the near axle: it tips about it
    # moments about the near axle: W·(x_n − x_T) = Σ P_i·(x_i − x_n), the 5 kN weight at C
    # on the boom among them (the model's other load), the load at T replaced by W
    hand = (sum(P * (x - X_NEAR) for P, x in FIXED) + 5000.0 * (xC - X_NEAR)) / (X_NEAR - xT)
    np.testing.assert_allclose(r["W_tip"], hand, rtol=1e-9)
    np.testing.assert_allclose(r["ROC"], 0.5 * hand, rtol=1e-9)
    np.testing.assert_array_equal(r["ROC"], 0.5 * r["W_tip"])
    i = int(np.argmax(xT))   # the standard position: the farthest reach of T
    static, roc, x_static = r.scalars
    assert static.values[0] == pytest.approx(hand[i], rel=1e-9)
    assert roc.values[0] == pytest.approx(0.5 * hand[i], rel=1e-9)
    assert x_static.values[0] == xT[i]


def test_the_fraction_is_a_parameter(arm_text):
    model = io.loads(arm_text + MACHINE + TIPPING.replace("0.5", "0.35"))
    kin = model.mechanism.solve(model.range)
    r = model.ratings[0].evaluate(model.mechanism, kin)
    np.testing.assert_allclose(r["ROC"], 0.35 * r["W_tip"], rtol=1e-15)


def test_breakout_forces_by_hand(arm_text):
    model = io.loads(arm_text + MACHINE + BREAKOUT)
    kin = model.mechanism.solve(model.range)
    r = model.ratings[0].evaluate(model.mechanism, kin)
    for i in range(len(model.range)):
        w1, w2, P = hand_rates(kin, i)
        T, K = P["T"], np.array([kin.x("K").ravel()[i], kin.y("K").ravel()[i]])
        Q = T + 0.1 * (K - T) / np.linalg.norm(K - T)     # 100 mm behind the edge's tip
        I1 = Q[0] * w1                   # ∂Y_Q/∂S1: the boom about O
        I2 = (Q[0] - P["O1"][0]) * w2    # ∂Y_Q/∂S2: the bucket about O1
        g1, g2 = hand_limit("c1", I1, 0.0), hand_limit("c2", I2, 0.0)
        # tipping about the near axle with the force at Q: W·(x_n − x_Q) = Σ P_i·(x_i − x_n)
        tip = sum(P_ * (x - X_NEAR) for P_, x in FIXED) / (X_NEAR - Q[0])
        assert r["G_c1"][i] == pytest.approx(g1, rel=1e-9)
        assert r["G_c2"][i] == pytest.approx(g2, rel=1e-9)
        assert r["G_stability"][i] == pytest.approx(tip, rel=1e-9)
        assert r["x"][i] == pytest.approx(Q[0], rel=1e-12)
        assert r["F_lift"][i] == pytest.approx(min(g1, g2, tip), rel=1e-9)
        assert r["F_tilt"][i] == pytest.approx(min(g1, g2, tip), rel=1e-9)


def test_the_lift_capacity_over_the_height(arm_text):
    model = io.loads(arm_text + MACHINE + '''
[[rating]]
type = "loader_lift"
point = "T"
axis = "O"
pin = "O1"
''')
    a = model.analyze()
    (r,) = a.ratings
    np.testing.assert_array_equal(r["pin_height"], a.kinematics.y("O1").ravel())
    np.testing.assert_array_equal(
        r["G"], np.minimum.reduce([r["G_c1"], r["G_c2"], r["G_stability"]]))


def test_a_tipping_rating_without_a_machine_is_refused_at_its_key(arm_text):
    text = arm_text + TIPPING
    with pytest.raises(io.ModelFileError) as e:
        io.loads(text, name="arm.toml")
    assert e.value.key_path == "rating[0].point"
    assert "[machine]" in str(e.value)


def test_a_fraction_outside_0_1_is_refused_at_its_key(arm_text):
    text = arm_text + MACHINE + TIPPING.replace("fraction = 0.5", "fraction = 1.5")
    with pytest.raises(io.ModelFileError) as e:
        io.loads(text, name="arm.toml")
    assert e.value.key_path == "rating[0].fraction" and "(0, 1]" in str(e.value)
    assert e.value.line == text.splitlines().index("fraction = 1.5") + 1
