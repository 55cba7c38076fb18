"""Seed 001 (001_4447446e88a18ffc.txt), lab 1: the mini-loader lift device with two
independent coordinates, S (boom cylinder, МПС) and S1 (traverse cylinder, МПТ) —
``loader_lab1.toml`` (illustrative dimensions: the lab prints none).

Checked here: the transmission numbers of eqs. 11–13 exactly (and where the lab's
eqs. 11 and 13 differ from the exact quantities), the capacity with the boom's own
weight (eqs. 10, 14, 14a), capacity only for the points a cylinder moves (absent
quantities with notes), the steerability limits (16), (18) against the general
stability computation, the cylinder forces by virtual work against those from the
reactions (two cylinders), and the lab's two reported results the illustrative
dimensions are chosen to give (≈ 11.5 kN at the suspension axis, ≈ 800 kg).
"""

import math

import numpy as np
import pytest
from tests.helpers import examples as n_examples
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import ModelError, examples, io
from assur.machines.capacity import farthest_reach, lifts
from assur.core.chains import link_coordinates, point_coordinates
from assur.machines.cylinders import piston_area
from assur.views.report.tables import seed_tables


@pytest.fixture(scope="module")
def model():
    return io.load(io.bundled("loader_lab1"))


@pytest.fixture(scope="module")
def analysis(model):
    return model.mechanism.analyze(model.range)


def P(model, name):
    return float(model.mechanism.params[name])


def test_grid_of_two_coordinates(model, analysis):
    """S and S1 span a full grid, S varying slowest; the boom turns through 75–80°
    (lab 1: "на угол 75-80°")."""
    nS, nS1 = len(model.ranges["S"]), len(model.ranges["S1"])
    assert model.shape == (nS, nS1) and not model.paired
    assert model.range.shape == (nS * nS1, 2)
    np.testing.assert_array_equal(model.range[:, 0].reshape(nS, nS1)[:, 0], model.ranges["S"])
    np.testing.assert_array_equal(model.range[:, 1].reshape(nS, nS1)[0], model.ranges["S1"])
    phi3 = analysis.kinematics.phi("3", degrees=True)
    assert 75.0 <= np.ptp(phi3) <= 80.0
    # the stroke is solved (Given/Find): φ3(Smin) = −2°, φ3(Smax) = 75°
    assert [s.condition.unknown for s in model.solved] == ["Smin", "Smax"]
    np.testing.assert_allclose([phi3.min(), phi3.max()], [-2.0, 75.0], atol=1e-9)
    assert np.max(analysis.kinematics.closure_residual()) <= 1e-9


def test_chains_which_coordinate_moves_what(model):
    """The boom's points move with S only; the traverse's with S and S1; the frame with
    neither (structural, from the groups)."""
    m = model.mechanism
    for p in ("09", "S3", "23", "31", "35"):
        assert point_coordinates(m, p) == {"S"}
    for p in ("45", "78", "89", "S9"):
        assert point_coordinates(m, p) == {"S", "S1"}
    assert point_coordinates(m, "01") == frozenset()
    assert link_coordinates(m, "3") == {"S"} and link_coordinates(m, "9") == {"S", "S1"}
    assert lifts(m, "S", "09") and not lifts(m, "S1", "09")
    # the structural answer agrees with the numbers: exactly zero where not moved
    kin = m.solve(model.range)
    assert np.all(kin.transmission("09", wrt="S1") == 0.0)
    assert np.all(kin.transmission("S9", wrt="S1") != 0.0)


def test_transmission_numbers_eqs_11_to_13_exact(model, analysis):
    """Lab 1 eqs. 11–13. I_S3 = φ3'·L_S3·cos(φ3 + Δφ) — the lab's eq. 11 writes Δφ1 (the
    suspension axis' angle), which gives another number; I_09 = φ3'·L_39·cos(φ3 + Δφ1)
    (eq. 12). The traverse turns with the boom, so ∂Y_S9/∂S = I_09 + φ3'·(X_S9 − X_09)
    and ∂Y_S9/∂S1 = φ5'·U97·(X_S9 − X_09) (U97 = φ9'/φ7', φ7' = φ5'): the lab's eq. 13
    adds the second to I_09, which is neither."""
    kin = analysis.kinematics
    phi3, d3 = kin.phi("3"), kin.dphi("3", "S")
    LS3, L39 = P(model, "LS3"), P(model, "L39")
    dphi, dphi1 = P(model, "dphi"), P(model, "dphi1")
    I_S3 = d3 * LS3 * np.cos(phi3 + dphi)                                        # eq. 11
    np.testing.assert_allclose(kin.transmission("S3", wrt="S"), I_S3, rtol=1e-12)
    lab11 = d3 * LS3 * np.cos(phi3 + dphi1)                     # as printed (Δφ1)
    assert np.max(np.abs(lab11 - I_S3)) > 1e-3 * np.max(np.abs(I_S3))
    I_09 = d3 * L39 * np.cos(phi3 + dphi1)                                       # eq. 12
    np.testing.assert_allclose(kin.transmission("09", wrt="S"), I_09, rtol=1e-12)
    arm = kin.x("S9") - kin.x("09")
    exact_S = I_09 + d3 * arm
    np.testing.assert_allclose(kin.transmission("S9", wrt="S"), exact_S, rtol=1e-12)
    d5 = kin.dphi("5", "S1")
    along_S1 = d5 * kin.ratio("9", "7", "S1") * arm                              # eq. 13
    np.testing.assert_allclose(kin.transmission("S9", wrt="S1"), along_S1, rtol=1e-12)
    lab13 = I_09 + along_S1
    assert np.max(np.abs(lab13 - exact_S)) > 1e-2 * np.max(np.abs(exact_S))


def test_transmissions_against_central_differences(model):
    """∂Y/∂S and ∂Y/∂S1 of the analogs equal central differences of the positions
    (O(h²), h = 1e-6 m)."""
    m = model.mechanism
    q = model.range
    kin = m.solve(q)
    h = 1e-6
    for j, c in enumerate(("S", "S1")):
        e = np.zeros(2)
        e[j] = h
        up, dn = m.solve(q + e), m.solve(q - e)
        for p in ("09", "S3", "S9", "89"):
            fd = (up.y(p) - dn.y(p)) / (2 * h)
            np.testing.assert_allclose(kin.transmission(p, wrt=c), fd, rtol=1e-6, atol=1e-7)


def test_capacity_with_the_boom_weight_eqs_10_14(model, analysis):
    """Lab 1 eq. 10: m_po·g·I_S9 + m_str·g·I_S3 = 2·F_max·η, so the boom cylinder's
    capacity G = m_po·g at S9 is (2·p_max·F_n·η − m_str·g·I_S3)/I_S9; eq. 14 with
    m_po = G/g gives the same G; without the dead load the capacity is larger."""
    g = 9.81
    kin = analysis.kinematics
    c = analysis.cylinder("MPS")
    p_max = P(model, "p_relief") - P(model, "dp_throttle") - P(model, "dp_line")
    two_F_eta = 2 * p_max * piston_area(P(model, "D")) * P(model, "eta")
    m_str = P(model, "m_str")
    I_S9, I_S3 = kin.transmission("S9", wrt="S"), kin.transmission("S3", wrt="S")
    G = c.capacity("S9")
    np.testing.assert_allclose(G * I_S9 + m_str * g * I_S3, two_F_eta, rtol=1e-12)  # eq. 10
    m_po = G / g
    eq14 = two_F_eta / (g * (I_S9 + I_S3 * m_str / m_po))                             # eq. 14
    np.testing.assert_allclose(eq14 * g, G, rtol=1e-12)
    assert np.all(c.capacity("S9", dead_loads=()) > G)
    np.testing.assert_allclose(c.capacity("S9", dead_loads=()), two_F_eta / I_S9, rtol=1e-12)
    # the same dead load named by its link
    np.testing.assert_allclose(c.capacity("S9", dead_loads=["3"]), G, rtol=1e-15)


def test_capacity_at_the_suspension_axis_about_11_5_kN(model, analysis):
    """Lab 1: "Расчетная грузоподъемность ПНУ ... на оси подвеса составила около 11,5кН"
    — the illustrative dimensions are chosen to give it: the minimum over the grid
    of the capacity at 09 with the boom's weight is 11.5 kN within 2 %; eq. 14a, the
    capacity at the farthest reach of 09, is a value of the same map."""
    G = analysis.cylinder("MPS").capacity("09")
    assert abs(np.min(G) - 11.5e3) <= 0.02 * 11.5e3
    i = farthest_reach(analysis.kinematics, "09")
    assert analysis.kinematics.x("09")[i] == np.max(analysis.kinematics.x("09"))
    assert np.min(G) <= G[i] <= np.max(G)


def test_traverse_cylinder_capacity_only_where_it_lifts(analysis):
    """The traverse cylinder S1 does not move 09 or S3: its capacity there is undefined
    (ModelError naming the coordinate and the point), not a column of inf or NaN."""
    c = analysis.cylinder("MPT")
    with pytest.raises(ModelError, match=r"S1 does not move '09'.*moved by: S"):
        c.capacity("09")
    with pytest.raises(ModelError, match="S1 does not move 'S3'"):
        c.capacity("S3")
    assert np.all(np.isfinite(c.capacity("S9")))


def test_tables_leave_out_undefined_quantities_with_notes(analysis):
    """Tables 3.1 and 4.1 over (S, S1): no column along S1 for the points and links S1
    does not move, a note saying so; every column finite."""
    tabs = {t.id: t for t in seed_tables(analysis)}
    t31, t41 = tabs["3.1"], tabs["4.1"]
    for sym in ("I09_S1", "IS3_S1", "dphi3_S1", "dphi2_S1"):
        assert sym not in t31.symbols
    for sym in ("I09_S", "IS3_S", "IS9_S", "IS9_S1", "dphi9_S1", "U97_S1"):
        assert sym in t31.symbols
    assert any("S1 does not move points 09, S3; links 2, 3" in n["en"] for n in t31.notes)
    assert any("не перемещает" in n["ru"] for n in t31.notes)
    assert "G09_S1" not in t41.symbols and "GS3_S1" not in t41.symbols
    assert {"G09_S", "GS3_S", "GS9_S", "GS9_S1"} <= set(t41.symbols)
    assert any("capacity of cylinder MPT" in n["en"] for n in t41.notes)
    assert any("minimum" in n["en"] and "G09_S" in n["en"] for n in t41.notes)
    assert any("farthest reach" in n["en"] and "14a" in n["en"] for n in t41.notes)
    assert any("dead loads" in n["en"] for n in t41.notes)
    for t in tabs.values():
        for col in t.columns:
            assert np.all(np.isfinite(col.values)), (t.id, col.symbol)


def _closed_forms(model, x):
    """Lab 1 eqs. (16) and (18) [kg] for the implement at x (measured from B)."""
    g = 9.81
    L, b, P_ues = P(model, "L"), P(model, "b"), P(model, "P_ues")
    P_gr, X_gr = P(model, "P_gr"), P(model, "X_gr")
    den = g * (5 * x - 4 * L)
    m16 = P_ues * (4 * L - 5 * b) / den                                   # eq. (16)
    m18 = (P_ues * (4 * L - 5 * b) + P_gr * (4 * L + 5 * X_gr)) / den     # eq. (18)
    return m16, m18


def test_steerability_closed_forms_16_18_equal_the_general_computation(model, analysis):
    """Lab 1 eqs. (16), (18), at the farthest reach X_09max (the implement's weight at
    the suspension axis, as the lab's 800 kg) and at every position, equal the general
    stability computation (moments about the axles, 20 % rule) of table 6.1."""
    g = 9.81
    st_ = analysis.stability
    x = analysis.kinematics.x("09")
    m16, m18 = _closed_forms(model, x)
    np.testing.assert_allclose(st_.max_implement_weight_without_counterweights / g, m16,
                               rtol=1e-12)
    np.testing.assert_allclose(st_.max_implement_weight / g, m18, rtol=1e-12)
    i = farthest_reach(analysis.kinematics, "09")
    m16_star, m18_star = _closed_forms(model, x[i])
    assert math.isclose(np.min(st_.max_implement_weight_without_counterweights) / g, m16_star,
                        rel_tol=1e-12)
    assert math.isclose(np.min(st_.max_implement_weight) / g, m18_star, rel_tol=1e-12)
    # lab 1: "грузоподъемность мини-УЭС ... составила около 800 кг" (chosen to give it)
    assert abs(m16_star - 800.0) <= 0.02 * 800.0
    assert m18_star > m16_star  # the fuel tank as a counterweight helps (eq. 18)


def test_pressures_by_virtual_work_equal_reactions_two_cylinders(analysis):
    """Both cylinders: the force by virtual work equals the force from the joint
    reactions solved group by group in reverse order, so the pressures agree."""
    st_ = analysis.statics
    for name, c in analysis.cylinders.items():
        q = c.cylinder.coordinate
        vw, rx = st_.actuator_force(q), st_.actuator_force_from_reactions(q)
        scale = np.max(np.abs(vw))
        np.testing.assert_allclose(rx, vw, rtol=0, atol=1e-9 * scale)
        p_rx = rx / c.eta_mech / (c.count * c.area * c.eta_hyd)
        np.testing.assert_allclose(p_rx, c.pressure, rtol=0, atol=1e-9 * np.max(c.pressure))


@settings(max_examples=n_examples(25), deadline=None)
@given(P9=st.floats(0.0, 2e4), P3=st.floats(0.0, 5e3), fx=st.floats(-5e3, 5e3),
       at=st.sampled_from(["S9", "89", "78", "S3", "09"]))
def test_virtual_work_equals_reactions_for_any_loads(P9, P3, fx, at):
    """Random loads on the boom and the traverse: the two routes to both cylinders'
    forces agree to 1e-9 of the loads' scale."""
    m = (examples.loader_lab1().with_loads(())
         .weight("S9", P9).weight("S3", P3).force(at, fx=fx))
    q = examples.loader_lab1_range()[::7]
    a = m.analyze(q)
    scale = max(P9, P3, abs(fx), 1.0) * 10.0
    for c in ("S", "S1"):
        np.testing.assert_allclose(a.statics.actuator_force_from_reactions(c),
                                   a.statics.actuator_force(c), rtol=0, atol=1e-9 * scale)


def test_dead_loads_errors_in_the_file():
    """[tables] dead_loads names links that carry loads; an unknown link or a link
    without a load is refused at its line."""
    text = io.bundled("loader_lab1").read_text()
    with pytest.raises(io.ModelFileError, match=r"tables.dead_loads\[0\]: unknown link \"33\""):
        io.loads(text.replace('dead_loads = ["3"]', 'dead_loads = ["33"]'), name="x.toml")
    with pytest.raises(io.ModelFileError, match=r"no load acts on link \"5\""):
        io.loads(text.replace('dead_loads = ["3"]', 'dead_loads = ["5"]'), name="x.toml")


@settings(max_examples=n_examples(40), deadline=None)
@given(s=st.floats(0.0, 1.0), s1=st.floats(0.0, 1.0),
       L7=st.floats(0.22, 0.28), LS9=st.floats(0.3, 0.9))
def test_analogs_against_central_differences_anywhere(s, s1, L7, LS9):
    """At any (S, S1) inside the range and for other arm and tool dimensions, the
    first-order analogs along each coordinate (transmission numbers, φ9') equal central
    differences of the positions to O(h²)."""
    base = examples.loader_lab1()
    m = base.with_params(L7=L7, LS9=LS9)
    lo, hi = examples.loader_lab1_range().min(axis=0), examples.loader_lab1_range().max(axis=0)
    q = (lo + np.array([s, s1]) * (hi - lo))[None, :]
    kin = m.solve(q)
    h = 1e-6
    for j, c in enumerate(("S", "S1")):
        e = np.zeros(2)
        e[j] = h
        up, dn = m.solve(q + e), m.solve(q - e)
        for p in ("S9", "09", "89"):
            fd = (up.y(p) - dn.y(p)) / (2 * h)
            np.testing.assert_allclose(kin.transmission(p, wrt=c), fd, rtol=1e-6, atol=1e-7)
        fd9 = (up.phi("9") - dn.phi("9")) / (2 * h)
        np.testing.assert_allclose(kin.dphi("9", c), fd9, rtol=1e-6, atol=1e-7)
