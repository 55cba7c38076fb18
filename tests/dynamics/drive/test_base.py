"""Hydraulic components (:mod:`assur.dynamics.drive`): the contract of the registry, the
line's loss coefficients against independent formulas, and seed 004's flow-divider
speeds (eqs. 63–68) at the paper's printed precision."""

from __future__ import annotations

import dataclasses
import math
import re

import numpy as np
import pytest

from assur.dynamics.drive import FlowDivider, Line, registry
from assur.dynamics.drive.base import ROLES
from assur.errors import ModelError
from tests.helpers import ROOT


def test_every_component_follows_the_contract():
    """type_name, role, quantities naming fields, a numpydoc Parameters section that
    documents every field with a unit in brackets, and a row in docs/simulation.md."""
    doc = (ROOT / "docs" / "simulation.md").read_text(encoding="utf-8")
    from assur.io._drive import KINDS
    for name, cls in registry().items():
        assert cls.type_name == name and cls.role in ROLES
        fields = {f.name for f in dataclasses.fields(cls)}
        assert set(cls.quantities) <= fields, name
        assert all(q in KINDS for q in cls.quantities.values()), name
        text = cls.__doc__
        assert "Parameters" in text, name
        for f in fields - {"name"}:
            m = re.search(rf"^\s+(\w+, )*{f}(, \w+)* :.*$", text, re.M)
            assert m, f"{name}.{f} undocumented"
            if f in cls.quantities:
                block = text[m.end():].split(" : ", 1)[0]
                assert re.search(r"\[[^\]]+\]", block), f"{name}.{f}: no unit in brackets"
        assert f"`{name}`" in doc, f"{name} missing from docs/simulation.md"


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


def test_components_refuse_bad_values():
    with pytest.raises(ModelError, match="diameter"):
        Line(length=5.0, diameter=0.0)
    # an unnamed component's message has no stray space before the colon
    with pytest.raises(ModelError, match=r"^line: diameter = 0\.0 must be a finite number > 0$"):
        Line(length=5.0, diameter=0.0)
    with pytest.raises(ModelError, match="regulation_range"):
        registry()["relief_valve"](16e6, 0.0)
    with pytest.raises(ModelError, match="position must be one of"):
        registry()["directional_valve"]("float")
    with pytest.raises(ModelError, match="shares"):
        FlowDivider((0.7, 0.7))
    with pytest.raises(ValueError, match="component type must be one of"):
        from assur.dynamics.drive import component_type
        component_type("gear_pmp")


# seed 004 (004_4ff0af19c30e8a3a.txt), text after eq. (66) and (68): Q_h = 80 l/min,
# written 1,33·10⁻³ m³/s (the paper computes with this rounded value); the piston areas
# f1 (boom), f2 (stick) and the stick's rod-side area f2m [m²]
Q_H = 1.33e-3
CRANES = {
    # crane: (f1, f2, f2m), divider V1, V2, (V2 rod side); separate V1, V2, (V2 rod side)
    "ЛВ-184А": ((7.85e-3, 5.024e-3, 3.062e-3), (0.085, 0.13, 0.22), (0.17, 0.26, 0.43)),
    # f2 = 12.666e-3 printed: a digit swap of 12.266e-3 (bore 125 mm, BRIEF.md)
    "ЛВ-185/215": ((15.7e-3, 12.266e-3, 9.15e-3), (0.042, 0.054, 0.072), (0.085, 0.11, 0.15)),
}


def _printed(value, printed):
    """|value − printed| within half a unit of the printed last digit."""
    digits = len(f"{printed}".split(".")[1])
    return abs(value - printed) <= 0.5 * 10 ** -digits + 1e-12


@pytest.mark.parametrize("crane", list(CRANES))
def test_seed004_flow_divider_speeds(crane):
    """Eqs. (63)–(66): a divider feeding both cylinders equal flows (V1/V2 = f2/f1,
    Q = V1·f1 + V2·f2) gives V1 = Q/(2f1), V2 = Q/(2f2); eqs. (67)–(68): separate
    motion, the whole flow to one cylinder, V = Q/f."""
    (f1, f2, f2m), combined, separate = CRANES[crane]
    div = FlowDivider((0.5, 0.5))
    V1, V2 = div.speeds(Q_H, (f1, f2))
    assert V1 / V2 == pytest.approx(f2 / f1, rel=1e-12)  # (63)
    assert V1 * f1 + V2 * f2 == pytest.approx(Q_H, rel=1e-12)  # (64)
    V2m = div.speeds(Q_H, (f1, f2m))[1]
    got = (V1, V2, V2m)
    for g, p, what in zip(got, combined, ("V1", "V2", "V2 rod side")):
        if crane == "ЛВ-185/215" and what == "V2 rod side":
            # printed 0.072; Q/(2·f2m) = 0.0727 reads 0.073: the paper's last digit is
            # one low (truncated) — reported, not matched
            assert abs(g - p) < 1e-3 and not _printed(g, p)
            continue
        assert _printed(g, p), f"{crane} combined {what}: {g:.4f} vs printed {p}"
    for g, p, what in zip((Q_H / f1, Q_H / f2, Q_H / f2m), separate, ("V1", "V2", "V2m")):
        assert _printed(g, p), f"{crane} separate {what}: {g:.4f} vs printed {p}"


def test_seed004_printed_f2_is_a_digit_swap():
    """With the printed f2 = 12.666e-3 m² the combined V2 would read 0.053, not the
    paper's 0.054; 12.266e-3 m² is π·0.125²/4 = 12.27e-3 m² (bore 125 mm)."""
    V2_printed_f2 = Q_H / (2 * 12.666e-3)
    assert not _printed(V2_printed_f2, 0.054)
    assert math.pi * 0.125 ** 2 / 4 == pytest.approx(12.266e-3, rel=1e-3)
    assert np.isclose(FlowDivider((0.5, 0.5)).speeds(Q_H, (15.7e-3, 12.266e-3))[1], 0.0542,
                      atol=1e-4)
