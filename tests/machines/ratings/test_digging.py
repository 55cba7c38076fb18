"""excavator_digging (ISO 6015) against the closed-form forces of a two-link arm."""

import numpy as np
import pytest

from assur import io
from assur.errors import ModelError
from assur.machines.ratings.digging import tangent
from tests.helpers.ratings import AREAS, ETA, P_RELIEF, hand_rates

DIG = '''
[[rating]]
type = "excavator_digging"
tip = "T"
bucket_cylinder = "c2"
bucket_pivot = "O1"
arm_cylinder = "c1"
arm_pivot = "O"
'''


def _perp(r):
    """k × r."""
    return np.array([-r[1], r[0]])


def _force(name, I):
    """The force along the tangent a cylinder sets: p·A/|I|, A of the chamber I's sign
    loads (the piston side for I > 0)."""
    piston, rod = AREAS[name]
    return P_RELIEF * (piston if I > 0 else rod) * ETA[name] / abs(I)


def test_two_link_arm_digging_forces_by_hand(arm_text):
    model = io.loads(arm_text + DIG)
    kin = model.mechanism.solve(model.range)
    r = model.ratings[0].evaluate(model.mechanism, kin)
    for i in range(len(model.range)):
        w1, w2, P = hand_rates(kin, i)
        dT1 = w1 * _perp(P["T"])                 # ∂T/∂S1: the arm about O
        dT2 = w2 * _perp(P["T"] - P["O1"])       # ∂T/∂S2: the bucket about O1
        # bucket: c2 digs retracting, the tip moving −∂T/∂S2 (tangent about O1)
        tB = -dT2 / np.linalg.norm(dT2)
        own = _force("c2", tB @ dT2)
        hold = _force("c1", tB @ dT1)
        assert r["F_B_c2"][i] == pytest.approx(own, rel=1e-9)
        assert r["H_B_c1"][i] == pytest.approx(hold, rel=1e-9)
        assert r["F_B"][i] == pytest.approx(min(own, hold), rel=1e-9)
        assert r["gov_B"][i] == (1.0 if own <= hold else 2.0)
        # ISO 6015's bucket force with no holding limit: p·A_rod·|O1T|⁻¹·(dS2/dθ2)
        assert own == pytest.approx(P_RELIEF * AREAS["c2"][1] / (
            np.linalg.norm(P["T"] - P["O1"]) * abs(w2)), rel=1e-12)
        # arm: c1 digs extending, the tip moving +∂T/∂S1 (tangent about O)
        tA = dT1 / np.linalg.norm(dT1)
        own = _force("c1", tA @ dT1)
        hold = _force("c2", tA @ dT2)
        assert r["F_A_c1"][i] == pytest.approx(own, rel=1e-9)
        assert r["H_A_c2"][i] == pytest.approx(hold, rel=1e-9)
        assert r["F_A"][i] == pytest.approx(min(own, hold), rel=1e-9)


def test_the_tangent_is_a_unit_vector_perpendicular_to_the_radius(arm_text):
    model = io.loads(arm_text + DIG)
    kin = model.mechanism.solve(model.range)
    tx, ty = tangent(kin, "T", "O1", "S2", -1.0)
    rx = kin.x("T").ravel() - kin.x("O1").ravel()
    ry = kin.y("T").ravel() - kin.y("O1").ravel()
    np.testing.assert_allclose(tx * rx + ty * ry, 0.0, atol=1e-12)
    np.testing.assert_allclose(np.hypot(tx, ty), 1.0, rtol=1e-14)
    with pytest.raises(ModelError, match="does not move along the circle"):
        tangent(kin, "C", "O1", "S2", 1.0)     # S2 does not move C


def test_a_cylinder_of_unknown_digging_direction_is_refused_at_its_key(arm_text):
    text = arm_text.replace('side = "retract"', 'side = "auto"') + DIG
    with pytest.raises(io.ModelFileError) as e:
        io.loads(text, name="arm.toml")
    assert e.value.key_path == "rating[0].bucket_cylinder"
    assert "must declare the way it digs" in str(e.value)
    assert e.value.line == text.splitlines().index('bucket_cylinder = "c2"') + 1
