"""Seed 001 lab 5 (001_4447446e88a18ffc.txt, §5): the silage-spout rotation mechanism.

Table 5.1 is reproduced by the bundled spout_lab5.toml, whose dimensions the tool's
own fitting (assur.synthesis.fitting) found; the lab's φ3'' without the power 3/2 is checked
against the exact value and a finite difference of φ3'; the pressure of eq. (4) from
the inertia load M5 = J·ε5 at the file's rod motion."""

import numpy as np
import pytest

from assur import examples, io
from assur.synthesis.fitting import Target, fit_parameters
from assur.io import ModelFileError
from assur.views.report import seed_tables
from assur.views.report.tables import table_filename

# seed 001 table 5.1 (S [m], φ5 [°], φ3' [1/m], φ5' [1/m], U53 [-]), printed to 3 digits
S = np.array([0.35, 0.37, 0.39, 0.41, 0.43, 0.45, 0.47, 0.49, 0.51])
PHI5 = [43.665, 74.59, 96.732, 117.051, 137.623, 160.025, 186.316, 220.154, 268.384]
DPHI3 = [19.413, 13.037, 11.258, 10.619, 10.56, 10.975, 11.971, 14.061, 19.591]
DPHI5 = [40, 21.199, 18.123, 17.613, 18.511, 20.873, 25.516, 24.552, 50.584]
U53 = [2.06, 1.626, 1.61, 1.659, 1.753, 1.902, 2.135, 2.457, 2.582]
#: the values flagged in the model's notes: (column, S) → what the geometry gives
FLAGGED = {("dphi5", 0.49): 34.552, ("U53", 0.47): 2.1315, ("dphi3", 0.45): 10.972}
DEG = np.pi / 180


@pytest.fixture(scope="module")
def kin():
    return examples.spout_lab5().solve(S)


def columns(kin):
    return {"phi5": np.degrees(kin.phi("5")), "dphi3": kin.dphi("3"), "dphi5": kin.dphi("5"),
            "U53": kin.ratio("5", "3")}


@pytest.mark.parametrize("name,printed", [("phi5", PHI5), ("dphi3", DPHI3), ("dphi5", DPHI5),
                                          ("U53", U53)])
def test_table_5_1_is_reproduced_at_its_printed_precision(kin, name, printed):
    got = columns(kin)[name]
    for s, p, g in zip(S, printed, got):
        key = (name, round(float(s), 2))
        if key in FLAGGED:
            assert abs(g - p) > 0.0025                      # the printed value is off …
            assert g == pytest.approx(FLAGGED[key], abs=1e-3)  # … the geometry gives this
        else:
            # one unit of the last printed digit (0.001), as the table rounds
            assert abs(g - p) <= 1e-3, (name, s, p, g)


def test_the_flagged_values_follow_from_the_table_itself():
    # φ5' = φ3'·U53 (eq. 1) from the table's own columns
    assert DPHI3[7] * U53[7] == pytest.approx(34.55, abs=0.01) != DPHI5[7]
    assert DPHI5[6] / DPHI3[6] == pytest.approx(2.1315, abs=1e-4) != U53[6]


def test_swing_of_about_225_degrees(kin):
    swing = np.degrees(kin.phi("5")[-1] - kin.phi("5")[0])
    assert swing == pytest.approx(268.384 - 43.665, abs=2e-3)


def exact_ddphi3(s, L13, L3):
    """The exact φ3'' (BRIEF.md: 2·[S⁴ − (L3² − L13²)²]/D^(3/2))."""
    D = 4 * L13**2 * L3**2 - (s**2 - (L13**2 + L3**2))**2
    return 2 * (s**4 - (L3**2 - L13**2)**2) / D**1.5


def test_exact_ddphi3_equals_a_finite_difference_of_dphi3_and_the_lab_form_does_not():
    m = examples.spout_lab5()
    s = np.linspace(0.351, 0.509, 25)
    h = 1e-6
    fd = (m.solve(s + h).dphi("3") - m.solve(s - h).dphi("3")) / (2 * h)
    kin = m.solve(s)
    np.testing.assert_allclose(kin.ddphi("3"), fd, rtol=1e-6)
    L13, L3 = m.params["L13"], m.params["L3"]
    np.testing.assert_allclose(exact_ddphi3(s, L13, L3), kin.ddphi("3"), rtol=1e-10)
    D = 4 * L13**2 * L3**2 - (s**2 - (L13**2 + L3**2))**2
    lab = 2 * (s**4 - (L3**2 - L13**2)**2) / np.sqrt(D)  # as printed: no power 3/2
    assert np.all(np.abs(lab - fd) > 0.5 * np.abs(fd))


def test_table_3_1_holds_the_exact_and_the_printed_phi3_pp():
    m = examples.spout_lab5()
    a = m.analyze(examples.spout_lab5_range())
    kin = a.kinematics
    t31 = next(t for t in seed_tables(a) if t.id == "3.1")
    np.testing.assert_allclose(t31["ddphi3"], kin.ddphi("3"), rtol=1e-12)
    L13, L3, s = m.params["L13"], m.params["L3"], kin.q()
    D = 4 * L13**2 * L3**2 - (s**2 - (L13**2 + L3**2))**2
    np.testing.assert_allclose(t31["ddphi3_lab"], 2 * (s**4 - (L3**2 - L13**2)**2) / np.sqrt(D),
                               rtol=1e-12)
    h = 1e-6
    U = lambda x: m.solve(x).ratio("5", "3")   # noqa: E731
    np.testing.assert_allclose(t31["dU53"], (U(s + h) - U(s - h)) / (2 * h), rtol=1e-5)
    fd5 = (m.solve(s + h).dphi("5") - m.solve(s - h).dphi("5")) / (2 * h)
    np.testing.assert_allclose(t31["ddphi5"], fd5, rtol=1e-5)


def test_pressure_of_eq_4_from_the_inertia_of_the_spout():
    m = examples.spout_lab5()
    a = m.analyze(examples.spout_lab5_range())
    kin = a.kinematics
    v = 0.04                                        # the file's [motion] S speed [m/s]
    eps5 = kin.ddphi("5") * v**2                    # ε5 = φ5''·Ṡ² + φ5'·S̈, S̈ = 0
    M5 = 60.0 * eps5                                # J·ε5 [N·m]
    F = M5 * kin.dphi("5")                          # eq. (3)
    p = F / (np.pi * 0.05**2 / 4 * 0.9)             # eq. (4)
    np.testing.assert_allclose(a.cylinder().pressure, p, rtol=1e-9)
    assert a.rates is not None and any("rod motion" in n for n in a.notes)
    # the same by the reactions, group by group
    np.testing.assert_allclose(a.statics.actuator_force_from_reactions("S"), F, rtol=1e-9)


@pytest.mark.slow
def test_the_tool_fits_table_5_1_and_the_file_holds_such_a_fit():
    m = examples.spout_lab5()
    t3 = Target("dphi3", "dphi(3)", S, DPHI3)
    targets = [Target("phi5", "phi(5)", S, PHI5, scale=DEG, period=360),
               Target("U53", "dphi(5)/dphi(3)", S, U53),
               Target("dphi5", "dphi(5)", S, DPHI5)]
    # stage 1: the lever from φ3'(S) alone (its closed form holds L13 and L3 only)
    f1 = fit_parameters(m, {"L13": (0.05, 1.0), "L3": (0.02, 0.6)}, [t3], screen=1024,
                        starts=4)
    assert f1.params["L13"] == pytest.approx(m.params["L13"], abs=1e-6)
    assert f1.params["L3"] == pytest.approx(m.params["L3"], abs=1e-6)
    # stage 2: the rest from φ5, U53, φ5' — screened over the bounds, not started from
    # the file's values: the refinement of the 2 best of 16384 screened designs (the
    # best one alone reaches the fit; each refinement costs seconds)
    rest = {"th13": (-np.pi, np.pi), "L34": (0.02, 0.8), "phiBD": (-np.pi, np.pi),
            "X05": (-1, 1), "Y05": (-1, 1), "L4": (0.02, 1.2), "L5": (0.01, 0.5)}
    f2 = fit_parameters(m.with_params(**f1.params), rest, targets, screen=1 << 14, starts=2)
    # stage 3: all nine together
    both = {"L13": (0.05, 1.0), "L3": (0.02, 0.6), **rest}
    f3 = fit_parameters(m, both, targets + [t3], screen=16, starts=0,
                        start={**f1.params, **f2.params}, outlier=4.0)
    # the table is reproduced to one unit of its last digit but for the flagged values
    assert sorted((t, round(p, 2)) for t, p, *_ in f3.outliers) == sorted(FLAGGED)
    assert f3.max_residual() < 2.0
    # the table does not fix the dimensions uniquely (this search may land on another
    # mechanism that reproduces it as well); the file's set is a fit: refined from
    # itself, it stays where it is
    f4 = fit_parameters(m, both, targets + [t3], screen=16, starts=0, start=dict(m.params),
                        outlier=4.0)
    for name, v in f4.params.items():
        assert v == pytest.approx(m.params[name], abs=2e-4), name
    assert sorted((t, round(p, 2)) for t, p, *_ in f4.outliers) == sorted(FLAGGED)
    assert f4.max_residual() < 2.0


def test_rod_motion_in_a_file_is_checked():
    text = io.bundled("spout_lab5").read_text(encoding="utf-8")
    bad = text.replace('direction = "extend"', 'direction = "cw"')
    with pytest.raises(ModelFileError) as exc:
        io.loads(bad, name="spout.toml")
    assert exc.value.key_path == "motion.S.direction" and "extend" in exc.value.problem
    bad = text.replace('speed = "0.04 m/s"', 'speed = "3 rpm"')
    with pytest.raises(ModelFileError) as exc:
        io.loads(bad, name="spout.toml")
    assert exc.value.key_path == "motion.S.speed" and "velocity" in exc.value.problem


def test_a_rod_speed_table_gives_the_acceleration_term():
    text = io.bundled("spout_lab5").read_text(encoding="utf-8")
    table = 'speed = { t = ["0 s", "2 s", "4 s"], v = ["0.02 m/s", "0.06 m/s", "0.02 m/s"] }'
    m = io.loads(text.replace('speed = "0.04 m/s"', table), name="spout.toml")
    a = m.mechanism.analyze(m.range)
    kin = a.kinematics
    qd, qdd = a.rates
    # travel ∫v dt = 0.08 m in the first 2 s: v(s) = √(v0² + 2·a·s), a = 0.02 m/s²
    s = kin.q() - 0.35
    first = s < 0.08 - 1e-9   # (at the sample itself the next interval's slope holds)
    np.testing.assert_allclose(qd[first], np.sqrt(0.02**2 + 2 * 0.02 * s[first]), rtol=1e-12)
    np.testing.assert_allclose(qdd[first], 0.02)
    eps5 = kin.ddphi("5") * qd**2 + kin.dphi("5") * qdd
    F = 60.0 * eps5 * kin.dphi("5")
    np.testing.assert_allclose(a.statics.actuator_force("S"), F, rtol=1e-9, atol=1e-9)


def test_the_csv_files_hold_no_nan_or_inf(tmp_path):
    from assur.views.report import write_report
    a = examples.spout_lab5().analyze(examples.spout_lab5_range())
    write_report(a, tmp_path, formats=("csv",))
    csvs = sorted(tmp_path.glob("*.csv"))
    tabs = seed_tables(a)
    assert {"3.1", "4.1", "5.1"} <= {t.id for t in tabs}
    assert {table_filename(t) for t in tabs} == {f.name for f in csvs}
    for f in csvs:
        text = f.read_text(encoding="utf-8").lower()
        assert "nan" not in text and "inf" not in text, f.name


def test_a_law_of_motion_S_t_gives_the_rates_and_the_inertia():
    # S(t) = 0.35 + 0.01·t² m (a cubic spline reproduces a quadratic exactly):
    # Ṡ = 0.02·t, S̈ = 0.02 at t = √((S − 0.35)/0.01)
    text = io.bundled("spout_lab5").read_text(encoding="utf-8")
    t = [0.0, 1.0, 2.0, 3.0, 4.0]
    law = ("law = { t = [" + ", ".join(f'"{x} s"' for x in t) + "], q = ["
           + ", ".join(f'"{0.35 + 0.01 * x * x:.4f} m"' for x in t) + "] }")
    m = io.loads(text.replace('direction = "extend", speed = "0.04 m/s"', law),
                 name="spout.toml")
    a = m.mechanism.analyze(m.range)
    kin = a.kinematics
    s = kin.q()
    tt = np.sqrt((s - 0.35) / 0.01)
    qd, qdd = a.rates
    np.testing.assert_allclose(qd, 0.02 * tt, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(qdd, 0.02, rtol=1e-9)
    np.testing.assert_allclose(m.mechanism.motion("S").time(s), tt, rtol=1e-9, atol=1e-9)
    F = 60.0 * (kin.ddphi("5") * qd**2 + kin.dphi("5") * qdd) * kin.dphi("5")
    np.testing.assert_allclose(a.statics.actuator_force("S"), F, rtol=1e-9, atol=1e-9)


@pytest.mark.parametrize("law,key,message", [
    ('law = { t = ["0 s", "1 s", "2 s"], q = ["0.35 m", "0.45 m", "0.40 m"] }', "motion.S",
     "monotonic"),
    ('law = { t = ["0 s", "1 s"], q = ["0.35 m", "0.45 m"] }, speed = "1 m/s"',
     "motion.S.law", "no speed"),
    ('law = { t = ["0 s", "1 s", "2 s"], q = ["0.35 m", "0.4 m"] }', "motion.S.law",
     "as many"),
    ('law = { t = ["0 s", "1 s"], q = ["0.35 m", "35 deg"] }', "motion.S.law.q[1]",
     "expected a length"),
])
def test_a_bad_law_is_located(law, key, message):
    text = io.bundled("spout_lab5").read_text(encoding="utf-8")
    with pytest.raises(ModelFileError) as exc:
        io.loads(text.replace('direction = "extend", speed = "0.04 m/s"', law),
                 name="spout.toml")
    assert exc.value.key_path == key and message in str(exc.value), str(exc.value)


def test_a_law_beyond_the_range_is_refused():
    from assur.errors import ModelError
    m = examples.spout_lab5().with_motion("S", law_t=(0, 1), law_q=(0.36, 0.5))
    with pytest.raises(ModelError, match="outside"):
        m.analyze(examples.spout_lab5_range())


def test_a_spline_that_turns_back_is_refused():
    from assur.errors import ModelError
    from assur.core.motion import Motion
    # monotonic samples whose not-a-knot spline overshoots between them
    with pytest.raises(ModelError, match="turns back"):
        Motion("S", kind="length", law_t=(0, 1, 2, 3, 4), law_q=(0.0, 0.001, 0.002, 0.9, 1.0))
    with pytest.raises(ModelError, match="against the direction"):
        Motion("S", "retract", kind="length", law_t=(0, 1), law_q=(0.3, 0.4))
