"""The hydraulic line (:mod:`assur.dynamics.drive.line`): its loss coefficients against
independent formulas — Hagen–Poiseuille in laminar flow, the Darcy factor of the
Colebrook equation in turbulent flow."""

from __future__ import annotations

import math

import pytest

from assur.dynamics.drive import Line


def test_line_laminar_is_hagen_poiseuille():
    """Δp = 128·μ·L·Q/(π·d⁴) (μ = ρν) at the laminar working flow."""
    line = Line(length=5.0, diameter=0.016, density=870.0, viscosity=46e-6)
    A, Q = 0.0122718, 8.64e-4
    a1, a2, a3 = line.loss_coefficients(A, Q)
    assert line.reynolds(Q) < 2000
    v = Q / A
    dp = 128 * 870.0 * 46e-6 * 5.0 * Q / (math.pi * 0.016 ** 4)
    assert a2 * v == pytest.approx(dp, rel=1e-12)
    assert a3 == 0.0
    # the oil column's inertia: ρ·L·du/dt with u = (A/A_h)·Ṡ
    assert a1 == pytest.approx(870.0 * 5.0 * A / (math.pi * 0.016 ** 2 / 4), rel=1e-12)



def test_line_turbulent_uses_the_darcy_factor():
    """At Re ≈ 2e4 the turbulent a3 equals f·(L/d)·(ρ/2)·(A/A_h)² with f from the
    Colebrook equation (another method than the default Clamond) to 1e-9."""
    from fluids.friction import Colebrook
    line = Line(length=4.0, diameter=0.012, density=870.0, viscosity=10e-6, roughness=5e-6,
                fittings=3.0)
    A, Q = 0.0122718, 2.0e-3
    Re = line.reynolds(Q)
    assert Re > 1e4
    a1, a2, a3 = line.loss_coefficients(A, Q)
    r = A / line.area
    f = Colebrook(Re, 5e-6 / 0.012)
    assert a2 == 0.0
    assert a3 == pytest.approx((f * 4.0 / 0.012 + 3.0) * 870.0 / 2 * r ** 2, rel=1e-9)

