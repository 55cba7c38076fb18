"""Held outputs along a path (``assur.core.held``): the traverse cylinder S1 of the
mini-loader (seed 001 lab 1, loader_lab1_level.toml) solved at every position of the
boom cylinder S so that the traverse 9 keeps φ9; the path's analogs by the
implicit-function rule compared with complex-step derivatives of the held solution,
computed here independently (scipy's brentq on the real line, a complex Newton
iteration on the plain-numpy reference formulas for S + i·h)."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from assur import io
from assur.core.held import Hold, HeldPath, hold_path, quantity_jets
from assur.errors import AssemblyError, ModelError

TARGET = math.radians(75.0)
H = 1e-20          # the complex step [m]


@pytest.fixture(scope="module")
def mech():
    return io.load(io.bundled("loader_lab1")).mechanism


@pytest.fixture(scope="module")
def level():
    return io.load(io.bundled("loader_lab1_level"))


def _phi9(mech, S, S1):
    """φ9 by the reference formulas (any dtype; the traverse points up, 0 < φ9 < π:
    φ9 = π/2 − atan(dx/dy), analytic there)."""
    p = mech.evaluate_positions({"S": S, "S1": S1})
    dx, dy = p["89"][0] - p["09"][0], p["89"][1] - p["09"][1]
    assert np.all(np.real(dy) > 0)
    return np.pi / 2 - np.arctan(dx / dy)


def _held_real(mech, S):
    return brentq(lambda u: float(_phi9(mech, S, u)) - TARGET, 0.77, 0.98, xtol=1e-16,
                  rtol=4 * np.finfo(float).eps)


def _held_complex(mech, S):
    """S1(S + i·H) solving φ9 = target with complex arithmetic (Newton with the real
    slope: its fixed point is the complex root)."""
    u0 = _held_real(mech, S)
    slope = (float(_phi9(mech, S, u0 + 1e-7)) - float(_phi9(mech, S, u0 - 1e-7))) / 2e-7
    u = complex(u0)
    for _ in range(6):
        u -= (_phi9(mech, S + 1j * H, u) - TARGET) / slope
    return u


def _path_output(mech, S, point):
    """Y of ``point`` along the held path at complex S: (value, dY/dS by complex step)."""
    u = _held_complex(mech, S)
    y = mech.evaluate_positions({"S": S + 1j * H, "S1": u})[point][1]
    return float(np.real(y)), float(np.imag(y)) / H


def test_the_held_output_stays_at_its_target_along_the_bundled_path(level):
    kin = level.mechanism.solve(level.range)
    assert level.path is not None and level.paired
    assert level.path.along == "S" and level.range.shape == (11, 2)
    assert np.abs(kin.phi("9") - TARGET).max() < 1e-10
    assert level.path.residual < 1e-12
    # the path's parameter is the file's range of S; S1 varies (it is solved)
    np.testing.assert_allclose(level.path.s, np.linspace(level.mechanism.params["Smin"],
                                                         1.25, 11), rtol=0, atol=1e-15)
    assert np.ptp(level.range[:, 1]) > 0.1


def test_the_held_coordinate_equals_an_independent_root(mech, level):
    for S, S1 in level.range[[0, 5, -1]]:
        assert abs(S1 - _held_real(mech, S)) < 1e-12


def test_first_order_path_analogs_equal_complex_step_derivatives(mech, level):
    path = level.path
    for i in (0, 4, 10):
        S = float(path.s[i])
        u = _held_complex(mech, S)
        assert abs(u.real - path.q[i, 1]) < 1e-12
        # dS1/dS = −(∂φ9/∂S)/(∂φ9/∂S1)
        np.testing.assert_allclose(path.dq[i], [1.0, u.imag / H], rtol=1e-9, atol=0)
    kin = level.mechanism.solve(level.range)
    for point in ("S9", "89", "09"):
        I = path.transmission(kin, point)
        for i in (0, 6, 10):
            y, dy = _path_output(mech, float(path.s[i]), point)
            assert abs(kin.y(point)[i] - y) < 1e-12
            np.testing.assert_allclose(I[i], dy, rtol=1e-9, atol=1e-12)


def test_second_order_path_analogs_equal_differences_of_complex_steps(mech, level):
    """d²S1/dS² and d²Y_S9/dS² against a 4th-order central difference of the
    complex-step first derivatives at S ± d, S ± 2d (each solved by brentq)."""
    path = level.path
    kin = level.mechanism.solve(level.range)
    _, _, ddy = path.derivative(kin, "YS9")
    d = 1e-3
    w = np.array([1.0, -8.0, 8.0, -1.0]) / (12 * d)
    for i in (1, 5, 9):
        S = float(path.s[i])
        steps = [S - 2 * d, S - d, S + d, S + 2 * d]
        du = np.array([_held_complex(mech, s).imag / H for s in steps])
        dy = np.array([_path_output(mech, s, "S9")[1] for s in steps])
        np.testing.assert_allclose(path.ddq[i, 1], w @ du, rtol=1e-6)
        np.testing.assert_allclose(ddy[i], w @ dy, rtol=1e-6)
        assert path.ddq[i, 0] == 0.0


def test_the_held_output_does_not_move_along_the_path(level):
    kin = level.mechanism.solve(level.range)
    _, d1, d2 = quantity_jets(kin, "phi9")
    first, second = level.path.along_path(d1, d2)
    assert np.abs(first).max() < 1e-12 and np.abs(second).max() < 1e-9
    # while the boom turns: the partial analogs are not zero
    assert np.abs(d1).min() > 0.1


def test_rates_of_a_rod_moving_along_the_path(level):
    mech = level.mechanism.with_motion("S", "extend", speed=0.05)
    qdot, qddot, note = level.path.motion_rates(mech)
    np.testing.assert_allclose(qdot[:, 0], 0.05)
    np.testing.assert_allclose(qdot[:, 1], 0.05 * level.path.dq[:, 1])
    np.testing.assert_allclose(qddot[:, 1], 0.05 ** 2 * level.path.ddq[:, 1])
    assert "following" in str(note)
    # the real-time angular velocity of the held link is zero along the path
    kin = mech.solve(level.range)
    w9 = np.einsum("nk,nk->n", kin.dphi("9"), qdot)
    assert np.abs(w9).max() < 1e-13
    with pytest.raises(ModelError, match="give the motion of S, not of S1"):
        level.path.motion_rates(mech.with_motion("S1", "extend", speed=0.01))


def test_the_model_analyzes_with_inertia_along_the_path(level):
    import dataclasses
    mech = level.mechanism.with_motion("S", "extend", speed=0.05)
    model = dataclasses.replace(level, mechanism=mech)
    a = model.analyze()
    assert a.kinematics.path is level.path
    np.testing.assert_allclose(a.rates[0][:, 1], 0.05 * level.path.dq[:, 1])
    assert any("held path" in str(n) for n in a.notes)
    frame = a.kinematics.to_frame()
    np.testing.assert_allclose(frame["IS9_path"],
                               frame["IS9_S"] + frame["IS9_S1"] * level.path.dq[:, 1],
                               rtol=1e-12)


def test_several_held_coordinates_by_newton(mech):
    """Both S and S1 held is not a path (no parameter): refused. A path along S1 with
    S held so that the boom keeps φ3 works the same way (one hold, the other order)."""
    h3 = Hold("S", "phi3", math.radians(20.0), (1.0, 1.6))
    p = hold_path(mech, "S1", np.linspace(0.8, 0.9, 5), [h3])
    kin = mech.solve(p.q)
    assert np.abs(kin.phi("3") - math.radians(20)).max() < 1e-12
    np.testing.assert_allclose(p.dq[:, 0], 0.0, atol=1e-14)   # φ3 does not depend on S1
    with pytest.raises(ModelError, match="one coordinate given and every other one held"):
        hold_path(mech, "S", [1.0], [h3])


def test_an_unreachable_target_names_the_position_and_the_output(mech):
    h = Hold("S1", "phi9", TARGET, (0.77, 0.98), coordinate_unit=None)
    with pytest.raises(ModelError) as e:
        hold_path(mech, "S", np.linspace(1.0, 1.6, 7), [h])
    msg = str(e.value)
    assert "at S = 1.3 (position 4 of the path)" in msg
    assert "no S1 in [0.77, 0.98] reaches phi9 = 75 deg" in msg


def test_a_held_range_that_does_not_assemble_names_the_group(mech):
    h = Hold("S1", "phi9", TARGET, (0.5, 0.6))
    with pytest.raises(AssemblyError) as e:
        hold_path(mech, "S", np.linspace(1.0, 1.2, 3), [h])
    assert e.value.group == "MPT (4,5)" and e.value.position == 0
    assert "at S = 1 (position 1 of the path)" in str(e.value)
    assert "MPT (4,5)" in str(e.value)


def test_several_roots_in_the_limits_are_refused(mech):
    """φ9 turns back at the four-bar's toggle near S1 = 0.75 m: limits across it hold
    two values of S1 for the same φ9."""
    h = Hold("S1", "phi9", math.radians(50.0), (0.66, 0.98))
    with pytest.raises(ModelError, match="2 values of S1 .* reach phi9 = 50 deg; narrow "
                                         "within"):
        hold_path(mech, "S", [1.0011], [h])


def test_an_unknown_output_is_refused(mech):
    with pytest.raises(ModelError, match="unknown output 'phi99'"):
        hold_path(mech, "S", [1.0], [Hold("S1", "phi99", 0.0, (0.8, 0.9))])


def test_describe(level):
    assert isinstance(level.path, HeldPath)
    assert level.path.describe() == "path along S, 11 positions: S1 holds phi9 = 75 deg"


def test_a_levelled_traverse_translates_along_the_path(level):
    """With φ9 held, every point of link 9 moves as its pivot 09 does: the transmission
    numbers along the path of S9 and 89 equal that of 09 (on the boom, S1 does not move
    it), though their partial analogs differ."""
    kin = level.mechanism.solve(level.range)
    I09 = level.path.transmission(kin, "09")
    np.testing.assert_allclose(I09, kin.transmission("09", wrt="S"), rtol=1e-13)
    for p in ("S9", "89"):
        np.testing.assert_allclose(level.path.transmission(kin, p), I09, rtol=1e-11)
        np.testing.assert_allclose(level.path.transmission(kin, p, axis="x"),
                                   level.path.transmission(kin, "09", axis="x"), rtol=1e-11)
        assert np.abs(kin.transmission(p, wrt="S") - I09).min() > 0.1


def _arm():
    """A serial arm of three cranks (absolute angles a, b, c [rad]): its tip E held at
    a point by b and c while a turns — two held coordinates."""
    from assur import Mechanism
    from assur.groups import Crank
    m = Mechanism("arm", coordinates=("a", "b", "c")).frame("O", 0.0, 0.0)
    m = m.add(Crank(name="boom", pivot="O", out="A", radius=1.0, q="a", links=("1",)))
    m = m.add(Crank(name="stick", pivot="A", out="B", radius=0.8, q="b", links=("2",)))
    return m.add(Crank(name="bucket", pivot="B", out="E", radius=0.5, q="c", links=("3",)))


def _arm_complex(m, a, guess, xy, J):
    """(b, c) at complex ``a`` holding E at ``xy`` (Newton with the real Jacobian J)."""
    u = np.array(guess, dtype=complex)
    for _ in range(8):
        p = m.evaluate_positions({"a": a, "b": u[0], "c": u[1]})["E"]
        u = u - np.linalg.solve(J, np.array([p[0] - xy[0], p[1] - xy[1]]))
    return u


def test_two_held_coordinates_by_newton_on_the_exact_jacobian():
    m = _arm()
    k0 = m.solve([[0.4, 1.2, 0.3]])
    xy = float(k0.x("E")[0]), float(k0.y("E")[0])
    holds = [Hold("b", "XE", xy[0], (0.6, 2.0)), Hold("c", "YE", xy[1], (-1.0, 1.0))]
    path = hold_path(m, "a", np.linspace(0.3, 0.5, 5), holds)
    kin = m.solve(path.q)
    assert np.abs(kin.x("E") - xy[0]).max() < 1e-12 and np.abs(kin.y("E") - xy[1]).max() < 1e-12
    assert abs(path.q[2, 1] - 1.2) < 1e-12 and abs(path.q[2, 2] - 0.3) < 1e-12
    d = 1e-3
    w = np.array([1.0, -8.0, 8.0, -1.0]) / (12 * d)
    for i in (1, 3):
        a = float(path.s[i])
        J = np.stack([kin.dx("E")[i, 1:], kin.dy("E")[i, 1:]])
        u = _arm_complex(m, a + 1j * H, path.q[i, 1:], xy, J)
        np.testing.assert_allclose(path.dq[i, 1:], u.imag / H, rtol=1e-9)
        steps = [a - 2 * d, a - d, a + d, a + 2 * d]
        du = np.array([_arm_complex(m, s + 1j * H, path.q[i, 1:], xy, J).imag / H
                       for s in steps])
        np.testing.assert_allclose(path.ddq[i, 1:], w @ du, rtol=1e-6)
    # the tip stands still along the path, to second order
    for axis in ("x", "y"):
        _, d1, d2 = quantity_jets(kin, f"{axis.upper()}E")
        first, second = path.along_path(d1, d2)
        assert np.abs(first).max() < 1e-12 and np.abs(second).max() < 1e-9


def test_newton_leaving_the_limits_of_a_held_coordinate_is_told():
    m = _arm()
    holds = [Hold("b", "XE", 1.688615442147027, (1.25, 2.0)),
             Hold("c", "YE", 1.2828097144131012, (-1.0, 1.0))]
    with pytest.raises(ModelError, match=r"at a = 0\.4 \(position 1 of the path\) Newton's "
                                         r"method leaves b's limits \[1\.25, 2\]"):
        hold_path(m, "a", [0.4], holds)


def test_part_of_a_result_on_the_path_keeps_its_part_of_the_path(level):
    a = level.analyze()
    part = a.kinematics.positions(3, 7)
    np.testing.assert_array_equal(part.to_frame()["IS9_path"],
                                  a.kinematics.to_frame()["IS9_path"].iloc[3:7])
