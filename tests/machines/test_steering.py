"""Seed 001 lab 4 (steering of the steered axle of УЭС-2-250А): the bundled models
steering_lab4.toml (base drive, two cylinders in one closed chain, eqs. 1–17) and
steering_lab4_modern.toml (slider-crank drive, one double-rod cylinder, eqs. 16–25),
and the general pieces they use: passive cylinders and supply lines, double-rod
cylinders, resisting moments, signed parameter references, assur.machines.steering."""

from __future__ import annotations

import math

import numpy as np
import pytest
from tests.helpers import examples
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import Mechanism, io
from assur.core import statics as S
from assur.machines import steering
from assur.errors import ModelError
from assur.machines.cylinders import supply_pressure_from_reactions

SEED = "seed 001_4447446e88a18ffc.txt, lab 4"


@pytest.fixture(scope="module")
def base():
    m = io.load(io.bundled("steering_lab4"))
    return m, m.mechanism.analyze(m.range)


@pytest.fixture(scope="module")
def modern():
    m = io.load(io.bundled("steering_lab4_modern"))
    return m, m.mechanism.analyze(m.range)


# ---- the lab's numbers and slips ---------------------------------------------------------
def test_resisting_moment_eq17_and_the_printed_slip(base):
    """Seed 001 lab 4 eq. 17: 0.05·27560/(1 + 70/500)·(500/200)·(0.8/0.7); the lab
    prints 2932 N·m, its inputs give 3453.6 N·m (BRIEF.md)."""
    mc = steering.resisting_moment(27560.0, 0.070, 0.500, 0.8)
    assert mc == pytest.approx(0.05 * 27560 / 1.14 * 2.5 * 0.8 / 0.7, rel=1e-15)
    assert round(mc, 1) == 3453.6
    assert abs(mc - 2932) > 500  # the printed value does not follow
    m, a = base
    assert np.allclose(a.formula("Mc17"), mc, rtol=1e-14)
    assert float(np.ravel(a.formula("Mc_lab"))[0]) == 2932.0
    # the model's Mc is eq. 17's value (to its 0.1 N·m)
    assert abs(float(m.mechanism.params["Mc"]) - mc) < 0.05
    flags = [f for f in m.mechanism.tables["formulas"] if f.name == "Mc_lab"][0].flags
    assert flags and "3453.6" in str(flags[0])


def test_ctg_check_computed_both_ways(base):
    """Lab 4 §4.5: ctg 34° − ctg 51° = 0.673 (printed 0.538), A/L = 1456/2534 = 0.575."""
    computed = 1 / math.tan(math.radians(34)) - 1 / math.tan(math.radians(51))
    assert round(computed, 3) == 0.673
    assert round(1456 / 2534, 3) == 0.575
    dev = steering.ackermann_deviation(math.radians(51), math.radians(34), 1.456, 2.534)
    assert float(dev) == pytest.approx(computed - 1456 / 2534, rel=1e-14)
    m, a = base
    assert np.allclose(a.formula("ctg_check"), computed, rtol=1e-14)
    assert float(np.ravel(a.formula("ctg_lab"))[0]) == 0.538
    flags = [f for f in m.mechanism.tables["formulas"] if f.name == "ctg_lab"][0].flags
    assert flags and "0.673" in str(flags[0])


def test_modernised_force_slip(modern):
    """Lab 4 §4.7: F = 290/67e-3 + 290/190e-3 is printed with the results 43280 +
    15260 = 58540 N of 2900/0.067 + 2900/0.19 (the '290' is a slip)."""
    m, a = modern
    intended = 2900 / 0.067 + 2900 / 0.19
    assert round(2900 / 0.067, -1) == 43280 and round(2900 / 0.19, -1) == 15260
    assert abs(intended - 58540) < 10
    assert np.allclose(a.formula("F_lab"), intended, rtol=1e-14)
    assert np.allclose(a.formula("F_290"), intended / 10, rtol=1e-14)
    flags = [f for f in m.mechanism.tables["formulas"] if f.name == "F_290"][0].flags
    assert flags and "58547" in str(flags[0])


# ---- Ackermann ----------------------------------------------------------------------------
@settings(max_examples=examples(200), deadline=None)
@given(alpha=st.floats(0.01, 1.5), track=st.floats(0.5, 3.0), base_=st.floats(1.0, 6.0))
def test_perfect_ackermann_gives_zero_deviation(alpha, track, base_):
    """Wheels turned exactly as eq. 11 asks: ctg β − ctg α − A/L = 0 and β − β* = 0;
    their axes meet on the line of the axle that does not steer."""
    beta = steering.ideal_outer_angle(alpha, track, base_)
    assert abs(float(steering.ackermann_deviation(alpha, beta, track, base_))) <= \
        1e-9 * (1 + 1 / math.tan(beta))
    assert float(steering.outer_angle_error(alpha, beta, track, base_)) == 0.0
    # the axes of the wheels (kingpins at x = ∓A/2) cross the line y = −L at one point
    xi = -track / 2 - base_ / math.tan(alpha)
    xo = track / 2 - base_ / math.tan(beta)
    assert xi == pytest.approx(xo, rel=1e-9, abs=1e-9)
    # eq. 12: R = L·ctg α + a
    assert float(steering.turning_radius(alpha, track, base_)) == pytest.approx(-xi, rel=1e-12)


def test_a_linkage_that_steers_by_ackermann_has_zero_deviation():
    """On the bundled trapezoid's inner angles α, the outer angles β* = arcctg(ctg α +
    A/L) give zero deviation; the trapezoid's own β gives the model's columns."""
    m = io.load(io.bundled("steering_lab4"))
    kin = m.mechanism.solve(m.range)
    alpha = kin.phi("w3") - np.pi / 2
    A, L = (float(m.mechanism.params[k]) for k in ("A", "L"))
    beta_star = steering.ideal_outer_angle(alpha, A, L)
    assert np.max(np.abs(steering.ackermann_deviation(alpha, beta_star, A, L))) < 1e-9
    # and the trapezoid itself is not perfect: its deviation is what the table shows
    beta = kin.phi("w5") - np.pi / 2
    a = m.mechanism.analyze(m.range)
    assert np.allclose(a.formula("ack_dev"), steering.ackermann_deviation(alpha, beta, A, L),
                       rtol=1e-12, atol=1e-12)
    assert np.allclose(a.formula("R"), steering.turning_radius(alpha, A, L), rtol=1e-12)


def test_straight_ahead_is_refused_by_ctg():
    with pytest.raises(ModelError, match="straight ahead"):
        steering.ackermann_deviation(0.0, 0.1, 1.456, 2.534)


# ---- S2(S1): the lab's closed chain (eqs. 1–10) ---------------------------------------
def _lab_chain(p, S1):
    """Lab 4 eqs. 2–10 in plain numpy, independent of the engine: φ3 from the
    cylinder–lever triangle (eq. 3), φ34 = φ3 + Δφ1 (eq. 4), the dyad L4–L5 by the
    diagonal |34–05| (eqs. 5–7), φ6 = φ5 + Δφ2 (eq. 8), 76 (eq. 9) and S2 (eq. 10)."""
    x01, y01, x03, y03 = -0.228, 0.200, -p["a_half"], 0.0
    x05, y05, x07, y07 = p["a_half"], 0.0, 0.228, 0.200
    L13 = math.hypot(x01 - x03, y01 - y03)
    phi13 = math.atan2(y01 - y03, x01 - x03)
    # eq. 3 (the branch of the model: the lever counter-clockwise of 03→01)
    phi3 = phi13 + np.arccos((L13**2 + p["L3"] ** 2 - S1**2) / (2 * L13 * p["L3"]))
    x23, y23 = x03 + p["L3"] * np.cos(phi3), y03 + p["L3"] * np.sin(phi3)
    phi34 = phi3 + p["dphi1"]  # eq. 4
    x34, y34 = x03 + p["L34"] * np.cos(phi34), y03 + p["L34"] * np.sin(phi34)
    dx, dy = x05 - x34, y05 - y34
    D = np.hypot(dx, dy)  # the diagonal of eq. 5
    phis = np.arctan2(dy, dx)  # eq. 6
    # eq. 7: the tie rod's direction (the branch below the diagonal)
    phi4 = phis - np.arccos((p["L4"] ** 2 + D**2 - p["L34"] ** 2) / (2 * p["L4"] * D))
    x45, y45 = x34 + p["L4"] * np.cos(phi4), y34 + p["L4"] * np.sin(phi4)
    phi5 = np.arctan2(y45 - y05, x45 - x05)
    phi6 = phi5 + p["dphi2"]  # eq. 8
    x76, y76 = x05 + p["L6"] * np.cos(phi6), y05 + p["L6"] * np.sin(phi6)  # eq. 9
    S2 = np.hypot(x76 - x07, y76 - y07)  # eq. 10
    return dict(x23=x23, y23=y23, x45=x45, y45=y45, S2=S2, phi3=phi3, phi5=phi5, x76=x76,
                y76=y76, x01=x01, y01=y01, x05=x05, y05=y05)


def test_s2_of_s1_closes_both_loops(base):
    """The lab's two geometry checks (X23 = X′23 through the cylinder and the lever;
    X45 = X′45 through the tie rod and the arm 5) and S2(S1) of eq. 10, against the
    engine, to 1e-9 m."""
    m, a = base
    kin = a.kinematics
    p = {k: float(v) for k, v in m.mechanism.params.items()}
    S1 = kin.q("S1")
    lab = _lab_chain(p, S1)
    # check 1: X'23 = X01 + S1·cos φ12 with the cylinder's direction from the engine
    x23, y23 = kin.value("23")
    phi12 = np.arctan2(y23 - lab["y01"], x23 - lab["x01"])
    assert np.max(np.abs(lab["x01"] + S1 * np.cos(phi12) - lab["x23"])) < 1e-9
    assert np.max(np.abs(lab["y01"] + S1 * np.sin(phi12) - lab["y23"])) < 1e-9
    # check 2: X45 via 03, L3·… L4 equals X'45 = X05 + L5·cos φ5
    assert np.max(np.abs(lab["x45"] - (lab["x05"] + p["L34"] * np.cos(lab["phi5"])))) < 1e-9
    x45, y45 = kin.value("45")
    assert np.max(np.hypot(x45 - lab["x45"], y45 - lab["y45"])) < 1e-9
    # S2(S1), eq. 10
    assert np.max(np.abs(kin.length("S2") - lab["S2"])) < 1e-9
    # and the third check of §4.2: the angle of lever 6 against the base 75 both ways
    x07, y07 = 0.228, 0.200
    L75 = math.hypot(x07 - lab["x05"], y07 - lab["y05"])
    cos_s2 = (L75**2 + p["L6"] ** 2 - lab["S2"] ** 2) / (2 * L75 * p["L6"])
    phi6 = np.arctan2(lab["y76"] - lab["y05"], lab["x76"] - lab["x05"])
    phi75 = math.atan2(y07 - lab["y05"], x07 - lab["x05"])
    assert np.max(np.abs(np.arccos(cos_s2) - np.abs(phi6 - phi75))) < 1e-9
    # the same checks as the model's columns of table 2.1 (what the report shows)
    for col in ("dX23", "dY23", "dX45", "dY45", "dphiS2"):
        assert np.max(np.abs(a.formula(col))) < 1e-9, col
    # the right cylinder follows the left one: S1 extends, S2 shortens
    assert np.all(np.diff(kin.length("S2")) < 0)


# ---- pressure: virtual work and reactions ------------------------------------------------
def test_two_cylinders_on_one_line_virtual_work_equals_reactions(base):
    """Eq. 15 with the exact analogs: p·(A1 − A2r·dS2/dS1) = F; the same pressure
    from the reverse-order pass with the passive cylinder's push as a load."""
    m, a = base
    kin = a.kinematics
    c1, c2 = a.cylinders["ГЦ1"], a.cylinders["ГЦ2"]
    assert np.array_equal(c1.pressure, c2.pressure)
    p_rx = supply_pressure_from_reactions(kin, "P")
    assert np.allclose(c1.pressure, p_rx, rtol=1e-9, atol=1e-3)
    # by hand: the loads' demand Mc·(|φ3′| + |φ5′|) over the line's effective area
    A1 = math.pi * 0.063**2 / 4
    A2 = math.pi * (0.063**2 - 0.032**2) / 4
    Mc = float(m.mechanism.params["Mc"])
    F = Mc * (np.abs(kin.dphi("3")) + np.abs(kin.dphi("5")))
    p_hand = F / (A1 - A2 * kin.dlength("S2"))
    assert np.allclose(c1.pressure, p_hand, rtol=1e-12)
    # eq. 15 as the lab writes it (each lever's analog along its own cylinder,
    # π·(2R² − r²)): the model's column p15, here from the engine's dS2/dS1
    p15 = Mc * (np.abs(kin.dphi("3")) + np.abs(kin.dphi("5") / kin.dlength("S2"))) / (A1 + A2)
    assert np.allclose(a.formula("p15"), p15, rtol=1e-12)
    # the rods' forces: the left pushes, the right (rod side) pulls
    assert np.all(c1.force > 0) and np.all(c2.force < 0)
    # power: p·(A1·dS1 − A2·dS2) is the work against both resisting moments
    assert np.allclose(c1.force + c2.force * kin.dlength("S2"), F, rtol=1e-12)


@settings(max_examples=examples(30), deadline=None)
@given(D=st.floats(0.04, 0.12), ratio=st.floats(0.3, 0.8), Mc=st.floats(100.0, 1e4),
       L6=st.floats(0.17, 0.23), travel=st.sampled_from([1, -1]))
def test_supply_line_virtual_work_equals_reactions_random(D, ratio, Mc, L6, travel):
    """Two cylinders on one line, random bores, moment, lever 6 and direction: the
    line's pressure by virtual work equals the one from the reactions."""
    mech = io.load(io.bundled("steering_lab4")).mechanism
    mech = mech.with_params(D_cyl=D, d_rod=ratio * D, Mc=Mc, L6=L6)
    mech = mech.with_loads([type(ld)(ld.link, ld.M, travel, None, ld.name)
                            for ld in mech.loads])
    q = np.linspace(0.52, 0.64, 7)
    a = mech.analyze(q)
    p = a.cylinders["ГЦ1"].pressure
    assert np.sign(p).tolist() == [travel] * 7  # the line pushes back on the other turn
    assert np.allclose(supply_pressure_from_reactions(a.kinematics, "P"), p, rtol=1e-9,
                       atol=1e-6 * np.max(np.abs(p)))


@pytest.mark.parametrize("bore,rod", [(0.05, 0.025), (0.063, 0.032), (0.08, 0.05)])
def test_one_cylinder_virtual_work_equals_reactions(bore, rod):
    """One cylinder on its own line: the line's pressure, by both routes, is the
    cylinder's F/(k·A·η)."""
    text = io.bundled("steering_lab4").read_text(encoding="utf-8")
    text = text[:text.index('[[cylinders]]\nname = "ГЦ2"')] + text[text.index("[tables]"):]
    text = text.replace('bore = "D_cyl"\nrod = "d_rod"',
                        f'bore = {bore}\nrod = {rod}\neta_hyd = 0.9\neta_mech = 0.95', 1)
    m = io.loads(text, name="one.toml")
    one = m.mechanism
    a = one.analyze(m.range)
    p = a.cylinders["ГЦ1"].pressure
    F = a.statics.actuator_force("S1")
    assert np.allclose(p, F / 0.95 / (math.pi * bore**2 / 4 * 0.9), rtol=1e-12)
    assert np.allclose(supply_pressure_from_reactions(a.kinematics, "P"), p, rtol=1e-9)


def test_double_rod_cylinder(modern):
    """One double-rod cylinder on two rod ends (two slider inputs on S): the forces
    of the ends add (eq. 22), equal Mc·(|φ3′| + |φ4′|) = M/h_Л + M/h_П, the chamber
    is the annulus that pushes, and reactions agree with virtual work."""
    m, a = modern
    kin = a.kinematics
    c = a.cylinder()
    F = a.statics.actuator_force("S")
    assert np.allclose(a.statics.actuator_force_from_reactions("S"), F, rtol=1e-9)
    assert np.allclose(F, a.formula("F_arms"), rtol=1e-12)
    fused = S.solve(kin, method="fused")  # the two rod ends' forces add in the kernel too
    assert np.allclose(fused.actuator_force("S"), F, rtol=1e-12)
    assert np.allclose(fused.actuator_force_from_reactions("S"), F, rtol=1e-9)
    area = math.pi * (0.1**2 - 0.04**2) / 4
    assert np.allclose(c.area, area, rtol=1e-14)
    assert np.allclose(c.pressure, F / area, rtol=1e-12)
    # the other turn: the moments flip, the rod side pressurised, the pressure ≥ 0
    flipped = m.mechanism.with_loads([type(ld)(ld.link, ld.M, -1, None, ld.name)
                                      for ld in m.mechanism.loads])
    b = flipped.analyze(m.range)
    cb = b.cylinder()
    assert np.allclose(b.statics.actuator_force("S"), -F, rtol=1e-12)
    assert np.all(cb.sign == -1.0) and np.all(cb.pressure > 0)
    assert np.allclose(cb.pressure, F / area, rtol=1e-12)  # both rods are 40 mm
    # eqs. 24–25: Q from the power balance equals A·v
    v = float(m.mechanism.params["v_rod"])
    Mc = float(m.mechanism.params["Mc"])
    q = steering.power_flow([Mc, Mc], [kin.dphi("3"), kin.dphi("4")], v, c.pressure)
    assert np.allclose(q, steering.rod_flow(c.area, v), rtol=1e-12)
    assert np.allclose(a.formula("Q"), q, rtol=1e-12)


# ---- the resisting moment ----------------------------------------------------------------
def test_resisting_moment_opposes_the_travel(base):
    """Its virtual work is −M·|φ′| whichever way the link turns, and travel = −1
    flips it; the fused kernel gives the same actuator force as the arrays."""
    m, a = base
    mech = m.mechanism
    kin = a.kinematics
    Mc = float(mech.params["Mc"])
    F = a.statics.actuator_force("S1")
    assert np.allclose(F, Mc * (np.abs(kin.dphi("3")) + np.abs(kin.dphi("5"))), rtol=1e-12)
    assert np.all(F > 0)
    back = mech.with_loads([type(ld)(ld.link, ld.M, -1, None, ld.name) for ld in mech.loads])
    assert np.allclose(S.solve(back.solve(m.range), method="array").actuator_force("S1"), -F,
                       rtol=1e-12)
    fused = S.solve(kin, method="fused")
    assert np.allclose(fused.actuator_force("S1"), F, rtol=1e-9)
    assert np.allclose(fused.actuator_force_from_reactions("S1"), F, rtol=1e-9)
    # a link turning the other way along the range gets the opposite moment
    one = mech.with_loads([type(mech.loads[0])("3", Mc)])
    w = one.solve(m.range).dphi("3")
    assert np.all(w > 0)
    f1 = S.solve(one.solve(m.range), method="array").actuator_force("S1")
    assert np.allclose(f1, Mc * w, rtol=1e-12)


def test_resisting_moment_checks():
    mech = Mechanism("t", coordinates=("S", "T"), params={"M": 1.0}).frame("0a", 0, 0) \
        .slider_input("s", origin="0a", out="A", s="S").slider_input("t", origin="0a", out="B",
                                                                      s="T", direction=90)
    with pytest.raises(ModelError, match="name the coordinate"):
        mech.resisting_moment("s:a", "M")
    with pytest.raises(ModelError, match="travel must be"):
        mech.resisting_moment("s:a", "M", travel=2, coordinate="S")


# ---- signed parameter references ----------------------------------------------------------
_SIGNED = """
[model]
name = "signed"
coordinates = ["S"]
[params]
a = "0.2 m"
M = "100 N*m"
L3 = "0.3 m"
[frame]
"01" = ["{x01}", 0]
"03" = [0.3, 0.1]
[[groups]]
type = "cylinder_lever"
name = "I"
base = "01"
pivot = "03"
out = "23"
lever = "L3"
s = "S"
branch = 1
links = ["2", "3"]
[[loads]]
type = "moment"
link = "3"
M = "{M}"
[range]
S = {{ from = 0.35, to = 0.45, count = 5 }}
"""


def test_signed_parameter_references():
    """ "-a" and "-M" are −a and −M wherever a value is accepted (a frame point, a
    moment), in the arrays and in the fused kernel, and follow with_params."""
    neg = io.loads(_SIGNED.format(x01="-a", M="-M"), name="neg.toml")
    pos = io.loads(_SIGNED.format(x01="-0.2 m", M="-100 N*m"), name="pos.toml")
    kn, kp = neg.mechanism.solve(neg.range), pos.mechanism.solve(pos.range)
    assert np.array_equal(kn.value("23")[0], kp.value("23")[0])
    for method in ("array", "fused"):
        fn = S.solve(kn, method=method).actuator_force()
        fp = S.solve(kp, method=method).actuator_force()
        assert np.allclose(fn, fp, rtol=1e-14)
    moved = neg.mechanism.with_params(a=0.25, M=200.0)
    km = moved.solve(neg.range)
    assert np.allclose(km.value("01")[0], -0.25)
    ref = io.loads(_SIGNED.format(x01="-0.25 m", M="-200 N*m"), name="r.toml").mechanism
    assert np.allclose(S.solve(km, method="array").actuator_force(),
                       S.solve(ref.solve(neg.range), method="array").actuator_force(),
                       rtol=1e-14)
    assert neg.warnings == ()  # a and M are used (through their signed references)


def test_signed_reference_errors():
    bad = _SIGNED.format(x01="-b", M="-M")
    with pytest.raises(io.ModelFileError, match='"b" is not a parameter'):
        io.loads(bad, name="bad.toml")
    # a key that must be positive takes no minus
    text = _SIGNED.format(x01="-a", M="-M").replace('lever = "L3"', 'lever = "-L3"')
    with pytest.raises(io.ModelFileError, match="positive"):
        io.loads(text, name="bad2.toml")


# ---- the examples analyze: tests/models/test_models.py writes every bundled model's report
# (CSV and HTML) and holds its CSV tables to finite numbers (tests.helpers.reports)


# ---- cylinders: what a model may not say ------------------------------------------------
def _base_text():
    return io.bundled("steering_lab4").read_text(encoding="utf-8")


@pytest.mark.parametrize("old,new,match", [
    ('distance = "S2"\nsupply = "P"', 'distance = "S2"', "needs the supply line"),
    ('distance = "S2"', 'distance = "S3"', 'unknown distance "S3"'),
    ('distance = "S2"', 'coordinate = "S1"\ndistance = "S2"', "not both"),
    ('side = "rod"', 'side = "auto"', "not \\\"auto\\\""),
    ('name = "ГЦ2"\ndistance = "S2"', 'name = "ГЦ2"\ndistance = "S2"\nrod2 = "-d_rod"',
     "non-negative"),
])
def test_cylinder_errors(old, new, match):
    text = _base_text()
    assert old in text
    with pytest.raises(io.ModelFileError, match=match):
        io.loads(text.replace(old, new, 1), name="bad.toml")


def test_a_line_needs_one_driving_cylinder():
    m = io.load(io.bundled("steering_lab4")).mechanism
    with pytest.raises(ModelError, match="exactly one cylinder that drives .* found 0"):
        m.cylinder("passive only", distance="S2", bore=0.05, supply="Q")
    with pytest.raises(ModelError, match="two cylinder entries drive 'S1'"):
        m.cylinder("another", "S1", bore=0.05, supply="P")


def test_fused_outputs_name_the_line():
    """The fused kernel gives the line's pressure (the one formula of
    assur.core.cylinders); a capacity at one point of a line's cylinder is undefined."""
    m = io.load(io.bundled("steering_lab4"))
    p = m.mechanism.evaluate(m.range, outputs=["p(ГЦ1)", "p(ГЦ2)"])
    a0 = m.mechanism.analyze(m.range)
    for name in ("ГЦ1", "ГЦ2"):
        assert np.allclose(p[f"p({name})"], a0.cylinders[name].pressure, rtol=1e-12, atol=0)
    with pytest.raises(ModelError, match="supply line"):
        m.mechanism.evaluate(m.range, outputs=["G(ГЦ1, 3L)"])
    # the forces themselves come from the fused kernel as from the arrays
    f = m.mechanism.evaluate(m.range, outputs=["F(S1)", "Fr(S1)"])
    a = m.mechanism.analyze(m.range)
    assert np.allclose(f["F(S1)"], a.statics.actuator_force("S1"), rtol=1e-9)
    assert np.allclose(f["Fr(S1)"], a.statics.actuator_force("S1"), rtol=1e-9)


def test_share_of_a_double_rod_cylinder(modern):
    """share(bore) of an auto-side cylinder uses the chamber of each position's sign:
    a bigger bore, a smaller share, in the ratio of the annuli."""
    _, a = modern
    c = a.cylinder()
    ratio = c.share(0.12) / c.share()
    assert np.allclose(ratio, (0.1**2 - 0.04**2) / (0.12**2 - 0.04**2), rtol=1e-12)


def test_signed_reference_in_a_pose():
    """A pose ``at = { S = "-Sback" }`` with Sback = −10 mm is the pose at S = 10 mm."""
    t = io.bundled("steering_lab4_modern").read_text(encoding="utf-8")
    a = io.loads(t.replace('at = { S = 0 }', 'at = { S = "-Sback" }')
                 .replace('Smin = "0 mm"', 'Smin = "0 mm"\nSback = "-10 mm"'), name="a.toml")
    b = io.loads(t.replace('at = { S = 0 }', 'at = { S = "10 mm" }'), name="b.toml")
    pa, pb = a.mechanism.solve(a.range).phi("w3"), b.mechanism.solve(b.range).phi("w3")
    assert np.array_equal(pa, pb)
    assert not np.allclose(pa, io.load(io.bundled("steering_lab4_modern")).mechanism
                           .solve(a.range).phi("w3"))
