"""The flywheel of a crank mechanism (:mod:`assur.dynamics.flywheel`; seed 001 lab 3):
J_f(δ) by Wittenbauer's tangents, then δ(J_f) by Brent's method on T0, gives δ back;
Brent's method on J_f of δ(J_f) (the brief's route) gives the tangents' J_f; the
classical approximation converges as δ → 0; the kinetostatics repeated with the
flywheel's motion needs a constant driving moment; an analytic case; the periodic
integral; the errors. On the bundled ``cleaning_lab3.toml`` (tests/dynamics/conftest.py)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

from assur.dynamics.crank import LinkMass, crank_dynamics, with_masses
from assur.dynamics.flywheel import flywheel, periodic_integral


@pytest.mark.parametrize("delta", [0.1, 0.02, 0.005])
def test_flywheel_both_directions_agree(example, delta):
    _, kin = example
    dyn = crank_dynamics(kin, qdot=-30.0)
    fw = dyn.flywheel(delta=delta)
    assert fw.J_flywheel > 0
    back = dyn.flywheel(J_flywheel=fw.J_flywheel)
    assert back.delta == pytest.approx(delta, rel=1e-9)
    assert back.T0 == pytest.approx(fw.T0, rel=1e-9)
    assert (back.omega_max + back.omega_min) / 2 == pytest.approx(30.0, rel=1e-12)
    # the brief's route: Brent's method on J_f of δ(J_f) (bracketed by a factor 4
    # either side: below some J_f the crank would stop, and δ(J_f) is undefined)
    Jf = brentq(lambda J: dyn.flywheel(J_flywheel=J).delta - delta, fw.J_flywheel / 4,
                4 * fw.J_flywheel, xtol=1e-13, rtol=1e-14)
    assert Jf == pytest.approx(fw.J_flywheel, rel=1e-9)



def test_flywheel_classical_approximation_converges_for_small_delta(example):
    """J_f ≈ swing(ΔE − ½J_red·ω_m²)/(δ·ω_m²) − mean J_red: relative error O(δ)
    (measured: below 0.1·δ here); the plain ΔE_max/(δ·ω_m²) ignores the links'
    own varying inertia, which dominates this mechanism's energy swing."""
    _, kin = example
    dyn = crank_dynamics(kin, qdot=-30.0)
    errs = []
    for delta in (0.04, 0.01, 0.0025):
        fw = dyn.flywheel(delta=delta)
        err = abs(fw.J_mertsalov - fw.J_flywheel) / fw.J_flywheel
        assert err < 0.1 * delta
        errs.append(err)
    assert errs[0] > errs[1] > errs[2]
    assert fw.J_classical < 0.2 * fw.J_flywheel



def test_kinetostatics_with_the_flywheel_motion_needs_a_constant_driving_moment(example):
    """Seed 001 lab 3: "for a known flywheel the irregularity is found, then the
    kinetostatic analysis is repeated". With the crank's motion ω(φ), ε(φ) of the
    energy equation and the flywheel J_f on the crank, the driving moment from the
    joint reactions is the constant M_d = −mean(M_c) (it is algebraically, if
    J_red and J_red' are the mechanism's own inertia)."""
    model, kin = example
    dyn = crank_dynamics(kin, qdot=-30.0)
    fw = dyn.flywheel(delta=0.05)
    mech = with_masses(model.mechanism, [LinkMass("1", 50.0, fw.J_flywheel, point="O1")])
    kin2 = mech.solve(model.range)
    qd, qdd = fw.rates(-1)
    dyn2 = crank_dynamics(kin2, qd, qdd)
    scale = np.abs(dyn2.power_terms()).sum(0).max() / 30.0
    assert np.allclose(dyn2.driving_moment_from_reactions, fw.driving_moment, rtol=0,
                       atol=1e-9 * scale)
    assert fw.driving_moment == pytest.approx(-15.0, rel=1e-12)  # the file's Mc = 15 N·m
    assert np.all(qd < 0) and fw.omega_min > 0



def test_flywheel_analytic_case():
    """Constant J_red = J0 and M_c = A·sin φ: ΔE = A(1 − cos φ) swings by 2A between
    φ = 0 and π, and ω_max² − ω_min² = 4A/I with ω_max + ω_min = 2ω_m gives
    I = J0 + J_f = 2A/(δ·ω_m²) exactly, for any δ (the positions hold 0 and π)."""
    q = np.radians(np.arange(0.0, 360.0, 1.0))
    J0, A, wm = 2.0, 50.0, 10.0
    for delta in (0.1, 0.3):
        fw = flywheel(q, np.full_like(q, J0), A * np.sin(q), wm, delta=delta)
        assert fw.J_flywheel == pytest.approx(2 * A / (delta * wm ** 2) - J0, rel=1e-12)
        assert fw.J_classical == pytest.approx(2 * A / (delta * wm ** 2), rel=1e-12)
        assert fw.driving_moment == pytest.approx(0.0, abs=1e-12)
        assert np.allclose(fw.energy, A * (1 - np.cos(q)), rtol=0, atol=1e-12)
        assert fw.omega.max() == pytest.approx(wm * (1 + delta / 2), rel=1e-12)



def test_periodic_integral_is_exact_for_resolved_modes():
    q = np.linspace(0, 2 * np.pi, 64, endpoint=False) + 0.3
    f = 2.0 + np.cos(3 * q) - 2 * np.sin(q)
    E, mean = periodic_integral(f, q[1] - q[0])
    assert mean == pytest.approx(2.0, rel=1e-14)
    exact = np.sin(3 * q) / 3 + 2 * np.cos(q)
    assert np.allclose(E, exact - exact[0], rtol=0, atol=1e-14)
    # a decreasing turn integrates the same function of φ
    E2, _ = periodic_integral(f[::-1], -(q[1] - q[0]))
    assert np.allclose(E2, (exact - exact[-1])[::-1], rtol=0, atol=1e-14)



def test_flywheel_errors():
    q = np.linspace(0, 2 * np.pi, 72, endpoint=False)
    J = 1 + 0.5 * np.cos(q)
    M = np.sin(q)
    with pytest.raises(ValueError, match="exactly one of delta and J_flywheel"):
        flywheel(q, J, M, 10.0)
    with pytest.raises(ValueError, match="one turn"):
        flywheel(q[:-5], J[:-5], M[:-5], 10.0, delta=0.1)
    with pytest.raises(ValueError, match="not resolved"):
        flywheel(q, J, np.sign(np.sin(7 * q)), 10.0, delta=0.1)
    with pytest.raises(ValueError, match="no flywheel is needed"):
        flywheel(q, np.full_like(q, 100.0), M, 10.0, delta=0.5)
    with pytest.raises(ValueError, match="would stop"):
        flywheel(q, J, 1e4 * M, 1.0, J_flywheel=0.0)
    with pytest.raises(ValueError, match="zero at φ = 180°"):
        flywheel(q, 1 + np.cos(q), M, 10.0, J_flywheel=0.0)

