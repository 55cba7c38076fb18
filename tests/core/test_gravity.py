"""Gravity as a model setting: a value and a direction, or none (issue 10; seed 001
lab 5's spout and lab 4's steering are drawn in a horizontal plane)."""

import re

import numpy as np
import pytest

from assur import io
from assur.errors import ModelError
from assur.io import ModelFileError
from tests.helpers.mechanisms import LIFT

MASS = '[[loads]]\ntype = "mass"\nlink = "5"\nm = "100 kg"\npoint = "56"\n'
BASE = LIFT.replace("[[cylinders]]", MASS + "\n[[cylinders]]")
NO_WEIGHT = re.sub(r'(?ms)^\[\[loads\]\]\ntype = "weight".*?(?=^\[)', "", BASE)


def model(gravity, text=NO_WEIGHT):
    return io.loads(text.replace("notes = [", f"gravity = {gravity}\nnotes = ["), name="g.toml")


def mass_force(m, method=None):
    """The actuator force of the mass alone [N] (the lift has no other load here)."""
    kin = m.mechanism.solve(m.range)
    from assur.core import statics
    return kin, statics.solve(kin, g=m.mechanism.g, method=method).actuator_force("S")


def test_the_default_direction_is_straight_down_exactly():
    _, f0 = mass_force(io.loads(NO_WEIGHT, name="a.toml"))
    _, f1 = mass_force(model('{ value = "9.81 m/s^2", direction = -90 }'))
    np.testing.assert_array_equal(f0, f1)
    assert np.all(f0 != 0)


@pytest.mark.parametrize("direction", [0.0, 30.0, -90.0, 135.0])
def test_a_mass_weighs_m_g_along_the_direction(direction):
    kin, f = mass_force(model(f'{{ value = "9.8 m/s^2", direction = {direction} }}'))
    d = np.radians(direction)
    J = kin.jacobian("56")  # (2, k, m, n): dX/dS, dY/dS
    # virtual work: F = −Q = −m·g·(cos d·dX/dS + sin d·dY/dS), independent of statics
    expected = -100.0 * 9.8 * (np.cos(d) * J[0, 0] + np.sin(d) * J[1, 0])
    np.testing.assert_allclose(f, kin.reshape(expected), rtol=1e-12, atol=1e-9)


def test_the_fused_kernel_follows_the_direction():
    m = model('{ value = "9.8 m/s^2", direction = 30 }')
    _, fa = mass_force(m, method="array")
    _, ff = mass_force(m, method="fused")
    np.testing.assert_allclose(ff, fa, rtol=1e-12, atol=1e-9)


def test_reactions_balance_with_a_direction():
    m = model('{ value = "9.8 m/s^2", direction = 200 }')
    a = m.mechanism.analyze(m.range)
    force, moment = a.statics.equilibrium_residual()
    assert force.max() < 1e-6 and moment.max() < 1e-6
    np.testing.assert_allclose(a.statics.actuator_force_from_reactions("S"),
                               a.statics.actuator_force("S"), rtol=1e-9, atol=1e-6)


def test_no_gravity_leaves_the_masses_weightless():
    m = model('"none"')
    assert m.mechanism.gravity == 0.0
    _, f = mass_force(m)
    np.testing.assert_array_equal(f, 0.0)


def test_no_gravity_with_inertia_keeps_the_inertia():
    m = model('"none"')
    a = m.mechanism.analyze(m.range, qdot=0.1, qddot=0.2)
    assert np.all(np.abs(a.statics.actuator_force("S")) > 0)


def test_a_weight_load_without_gravity_is_refused():
    with pytest.raises(ModelFileError) as exc:
        model('"none"', BASE)
    assert "weight load at point '56'" in str(exc.value)
    m = model('"none"')
    with pytest.raises(ModelError, match="no gravity"):
        m.mechanism.weight("56", 100.0)


@pytest.mark.parametrize("value,key,message", [
    ('{ value = "9.81 m/s^2", dir = 0 }', "model.gravity", "dir"),
    ('{ direction = "9 m" }', "model.gravity.direction", "expected an angle"),
    ('{ value = "-1 m/s^2" }', "model.gravity.value", "positive"),
    ('"nothing"', "model.gravity", "parameter"),
])
def test_bad_gravity_is_located(value, key, message):
    with pytest.raises(ModelFileError) as exc:
        model(value)
    assert exc.value.key_path == key and message in str(exc.value)


def test_python_api():
    m = io.loads(NO_WEIGHT, name="a.toml").mechanism
    assert m.with_gravity("none").gravity == 0.0
    assert m.with_gravity(9.8, np.radians(-90)).gravity_direction == pytest.approx(-np.pi / 2)
    with pytest.raises(ModelError, match="none"):
        m.with_gravity("zero")
    with pytest.raises(ModelError, match="≥ 0"):
        m.with_gravity(-1.0)
