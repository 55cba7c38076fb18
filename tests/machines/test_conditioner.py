"""Seed 001 lab 2 (001_4447446e88a18ffc.txt, §2): the pressing device of a
mower-conditioner — spring force F_c(Y), transmission number I(Y) (eq. 5, analogs
along the spring's stroke), specific pressure p_c(Y) (eq. 4), the spring that keeps
p_c flattest, four-bar against six-bar (fig. 2.3), the rollers' grip and speed ratio
(eqs. 1–3). The bundled models are illustrative (the lab prints no dimensions)."""

import numpy as np
import pytest
from tests.helpers import examples as n_examples
from hypothesis import given, settings, strategies as st

from assur import io
from assur.machines.conditioner import (flattest_spring, grips, min_roller_diameter,
                               specific_pressure, speed_ratio, spring_stroke, wedge_angle)
from assur.errors import ModelError
from assur.views.report import seed_tables

L_ROLLER = 1.6     # Lr of the files [m]
TARGET = 20e3      # p_target [N/m]
MIN_RATE = 20e3    # the softest spring the files allow [N/m]


@pytest.fixture(scope="module", params=["conditioner_lab2", "conditioner_lab2_sixbar"])
def model(request):
    return io.load(io.bundled(request.param))


@pytest.fixture(scope="module")
def analysis(model):
    return model.mechanism.analyze(model.range)


def table(a, tid):
    return next(t for t in seed_tables(a) if t.id == tid)


def test_pressure_by_eq_4_equals_virtual_work_and_the_reactions(model, analysis):
    kin = analysis.kinematics
    I, p = specific_pressure(kin, "sp", L_ROLLER)
    st_ = analysis.statics
    # the layer's force along O–R (the actuator force of Y) per metre of roller
    np.testing.assert_allclose(p, st_.actuator_force("Y") / L_ROLLER, rtol=1e-10)
    np.testing.assert_allclose(p, st_.actuator_force_from_reactions("Y") / L_ROLLER,
                               rtol=1e-9)
    t51, t31 = table(analysis, "5.1"), table(analysis, "3.1")
    np.testing.assert_allclose(t51["p_c"], p, rtol=1e-12)
    np.testing.assert_allclose(t31["I"], I, rtol=1e-12)
    # the spring's force F_c (one spring) and k·F_c in the table
    prm = model.mechanism.params
    L, _ = spring_stroke(kin, "sp")
    Fc = prm["F0"] + prm["c"] * (L - prm["lam0"])
    np.testing.assert_allclose(t51["T_sp"], Fc, rtol=1e-12)
    np.testing.assert_allclose(t51["F_sp"], prm["k_s"] * Fc, rtol=1e-12)


def test_I_is_dY_dlambda_by_finite_differences(model):
    m = model.mechanism
    y = model.range[1:-1]
    h = 1e-6
    lam = lambda q: spring_stroke(m.solve(q), "sp")[0]   # noqa: E731
    dlam_fd = (lam(y + h) - lam(y - h)) / (2 * h)
    I, _ = specific_pressure(m.solve(y), "sp", L_ROLLER)
    np.testing.assert_allclose(I, 1 / dlam_fd, rtol=1e-6)


def test_eq_5_read_along_Y_gives_about_one_and_is_flagged(analysis):
    t31 = table(analysis, "3.1")
    np.testing.assert_allclose(t31["I_Y"], 1.0, atol=0.01)
    assert np.all(np.abs(t31["I"] - t31["I_Y"]) > 0.1)   # the two readings differ
    assert any("eq. (5)" in n["en"] for n in t31.notes)


def test_the_files_spring_is_the_flattest(model):
    m = model.mechanism
    prm = m.params
    d = flattest_spring(m, model.range, "sp", TARGET, L_ROLLER, min_rate=MIN_RATE)
    assert d.rate == pytest.approx(prm["c"], rel=1e-3)
    assert d.preload == pytest.approx(prm["F0"], rel=1e-3)


@settings(max_examples=n_examples(30), deadline=None)
@given(rate=st.floats(MIN_RATE, 2e5), preload=st.floats(0.0, 6e4))
def test_no_other_spring_keeps_p_c_closer_to_the_target(rate, preload):
    model = io.load(io.bundled("conditioner_lab2"))
    m = model.mechanism
    opt = flattest_spring(m, model.range, "sp", TARGET, L_ROLLER, min_rate=MIN_RATE)
    other = m.with_params(c=rate, F0=preload)
    _, p = specific_pressure(other.solve(model.range), "sp", L_ROLLER)
    assert np.sum((p - TARGET) ** 2) >= np.sum((opt.pressure - TARGET) ** 2) * (1 - 1e-9)


def test_the_optimum_is_flatter_than_a_reference_spring():
    model = io.load(io.bundled("conditioner_lab2"))
    m = model.mechanism
    opt = flattest_spring(m, model.range, "sp", TARGET, L_ROLLER, min_rate=MIN_RATE)
    # a reference: a stiffer spring (100 kN/m) with the preload giving the same mean
    ref = flattest_spring(m, model.range, "sp", TARGET, L_ROLLER, min_rate=1e5)
    assert ref.rate == pytest.approx(1e5)
    assert opt.spread < ref.spread
    assert np.sum((opt.pressure - TARGET) ** 2) < np.sum((ref.pressure - TARGET) ** 2)


def test_the_six_bar_keeps_p_c_flatter_than_the_four_bar():
    spreads = {}
    for name in ("conditioner_lab2", "conditioner_lab2_sixbar"):
        model = io.load(io.bundled(name))
        spreads[name] = flattest_spring(model.mechanism, model.range, "sp", TARGET, L_ROLLER,
                                        min_rate=MIN_RATE).spread
    assert spreads["conditioner_lab2_sixbar"] < 0.2 * spreads["conditioner_lab2"]


@settings(max_examples=n_examples(50), deadline=None)
@given(D=st.floats(0.1, 0.5), H=st.floats(0.01, 0.09), hfrac=st.floats(0.0, 0.99),
       phi=st.floats(0.1, 1.4))
def test_eq_2_is_eq_1_rewritten(D, H, hfrac, phi):
    h = hfrac * H
    if H - h >= D:
        return
    Dmin = min_roller_diameter(H, h, phi)
    if abs(D - Dmin) > 1e-9 * D:
        assert bool(grips(D, H, h, phi)) == bool(D > Dmin)
    # the wedge angle closes the contact geometry: D/2·(1 − cos β) = (H − h)/2
    assert D / 2 * (1 - np.cos(wedge_angle(D, H, h))) == pytest.approx((H - h) / 2, abs=1e-12)


def test_eq_3_as_printed_is_below_one():
    D, H, h = 0.2, 0.045, np.linspace(0.005, 0.04, 8)
    assert np.all(speed_ratio(D, H, h) < 1)
    inv = 1 / speed_ratio(D, H, h)
    assert inv.min() == pytest.approx(1.25) and np.any((inv >= 1.25) & (inv <= 1.35))


def test_roller_formulas_of_the_file(analysis, model):
    tf = table(analysis, "F")
    prm = model.mechanism.params
    Y = analysis.kinematics.q()
    h = Y - prm["D"]
    np.testing.assert_allclose(np.radians(tf["beta"]), wedge_angle(prm["D"], prm["H"], h),
                               rtol=1e-12)
    np.testing.assert_allclose(tf["D_min"], min_roller_diameter(prm["H"], h, prm["phi_f"]),
                               rtol=1e-12)
    np.testing.assert_allclose(tf["VB_VT"], speed_ratio(prm["D"], prm["H"], h), rtol=1e-12)
    assert np.all(tf["D_min"] < prm["D"])   # the illustrative rollers grip at every gap


def test_bad_inputs_are_refused():
    with pytest.raises(ModelError, match="H − h < D"):
        wedge_angle(0.2, 0.01, 0.02)
    with pytest.raises(ModelError, match="friction angle"):
        min_roller_diameter(0.05, 0.01, 2.0)
    m = io.load(io.bundled("conditioner_lab2")).mechanism
    with pytest.raises(ModelError, match="no spring"):
        spring_stroke(m.solve([0.21]), "spring")


def test_the_csv_files_hold_no_nan_or_inf(tmp_path, analysis):
    from assur.views.report import write_report
    files = write_report(analysis, tmp_path, formats=("csv",))
    csvs = sorted(tmp_path.glob("*.csv"))
    assert csvs and files
    for f in csvs:
        text = f.read_text(encoding="utf-8").lower()
        assert "nan" not in text and "inf" not in text, f.name


def test_distance_functions_of_formulas_are_checked():
    from assur.core.columns import Formula, FormulaError
    m = io.load(io.bundled("conditioner_lab2")).mechanism
    kin = m.solve([0.21, 0.22])
    np.testing.assert_array_equal(Formula("l", "dist(lam)").evaluate(kin), kin.length("lam"))
    np.testing.assert_array_equal(Formula("dl", "ddist(lam)").evaluate(kin),
                                  kin.dlength("lam"))
    with pytest.raises(FormulaError, match="unknown distance 'mu'"):
        Formula("x", "dist(mu)").check(m)
    with pytest.raises(FormulaError, match="takes one distance"):
        Formula("x", "dist(lam, lam)")
