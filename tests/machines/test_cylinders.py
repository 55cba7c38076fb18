"""Cylinders: areas, working pressure (001 lab 1 eq. 1), and the lift capacity of a
loader boom with the boom's own weight (001 lab 1 eqs. 8–10, 14)."""

import math

import numpy as np
import pytest

from assur import Mechanism, ModelError
from assur.machines.cylinders import piston_area


def boom(m_str=120.0, **extra):
    """A loader boom (cylinder–lever group) with its centre of mass S3 and the
    suspension axis 09 at fixed angles from the lever (001 lab 1 eqs. 2–5); ``extra``
    parameters besides."""
    return (Mechanism("boom", coordinates=("S",),
                      params=dict(L3=0.35, LS3=0.9, L39=1.8, dphi=0.35, dphi1=0.2,
                                  m_str=m_str, D=0.05, p_rel=16e6, dp_thr=0.6e6,
                                  dp_line=0.4e6, eta=0.9, **extra))
            .frame("01", 0.0, 0.0).frame("03", 0.25, 0.55)
            .cylinder_lever("MPS", base="01", pivot="03", out="23", lever="L3", s="S",
                            branch=1, links=("2", "3"))
            .rigid_point("S3", origin="03", toward="23", out="S3", length="LS3", angle="dphi")
            .rigid_point("09", origin="03", toward="23", out="09", length="L39", angle="dphi1")
            .link("3", "03", "23")
            .cylinder("MPS", "S", bore="D", count=2, eta_mech="eta", p_relief="p_rel",
                      dp_throttle="dp_thr", dp_line="dp_line"))


def test_piston_area_and_rod_side():
    assert piston_area(0.1) == pytest.approx(math.pi * 0.0025)
    assert piston_area(0.1, 0.05, "rod") == pytest.approx(math.pi * (0.01 - 0.0025) / 4)
    with pytest.raises(ValueError, match="side must be one of"):
        piston_area(0.1, side="both")
    with pytest.raises(ValueError, match="rod side needs 0 < rod < bore"):
        piston_area(0.1, 0.2, "rod")


def test_p_max_is_relief_minus_losses():
    """001 lab 1 eq. 1: p_max = p_relief − (Δp_throttle + Δp_line)."""
    S = np.linspace(0.62, 0.72, 5)
    a = boom().weight("09", 5000.0).analyze(S)
    c = a.cylinder()
    assert c.p_max == pytest.approx(16e6 - 1e6)
    assert np.allclose(c.force_max, 2 * 15e6 * piston_area(0.05))


def test_capacity_with_the_boom_weight_lab1_eq10_eq14():
    """001 lab 1: m_po·g·I_S9 + m_str·g·I_S3 = 2·F_max·η (eq. 10), so the capacity at the
    suspension axis with the boom's weight carried is G = (2·F_max·η − m_str·g·I_S3)/I_09
    (eq. 14, G = 2·p·F_n·η/(g·[I_S9 + I_S3·m_str/m_po]) with m_po = G/g, is eq. 10
    rearranged). Another route to the same G: the statics of the boom carrying its own
    weight and G at 09 needs the cylinders' whole working pressure, p_max."""
    g = 9.81
    S = np.linspace(0.62, 0.72, 6)
    m = boom()
    dead = m.mass("3", "m_str", "S3")  # the boom's weight only
    a = m.analyze(S)
    c = a.cylinder()
    kin = a.kinematics
    G = c.capacity("09", dead_loads=dead)
    I9, I3 = kin.transmission("09"), kin.transmission("S3")
    F_max = 2 * 15e6 * piston_area(0.05)  # both cylinders, η_h = 1
    assert np.allclose(G * I9 + 120.0 * g * I3, F_max * 0.9, rtol=1e-12)          # eq. 10
    # G at 09 on the boom with its weight (one design per position): pressure = p_max
    loaded = boom(G=1.0).mass("3", "m_str", "S3").weight("09", "G")
    at_G = loaded.analyze(S[:, None], params={"G": G}).cylinder()
    assert np.allclose(at_G.pressure, 15e6, rtol=1e-12)
    assert np.allclose(at_G.share(), 1.0, rtol=1e-12)
    # without the boom's weight the capacity is larger (eq. 8)
    assert np.all(c.capacity("09") > G)
    assert np.allclose(c.capacity("09"), F_max * 0.9 / I9, rtol=1e-12)


def test_pressure_and_share():
    S = np.linspace(0.62, 0.72, 4)
    a = boom().weight("09", 8000.0).analyze(S)
    c = a.cylinder()
    kin = a.kinematics
    F = 8000.0 * kin.transmission("09")
    assert np.allclose(c.force, F)
    assert np.allclose(c.pressure, F / 0.9 / (2 * piston_area(0.05)))
    assert np.allclose(c.share(), c.force_required / c.force_max)
    assert np.allclose(c.share(bore=0.063), F / 0.9 / (2 * 15e6 * piston_area(0.063)))


def test_cylinder_model_errors():
    with pytest.raises(ModelError, match="not a generalized coordinate"):
        boom().cylinder("X", "S9", bore=0.05)
    with pytest.raises(ModelError, match="side must be one of"):
        Mechanism("m", coordinates=("S",)).cylinder("X", "S", bore=0.05, side="left")
    with pytest.raises(ModelError, match="two cylinder entries drive 'S'"):
        boom().cylinder("again", "S", bore=0.05)
