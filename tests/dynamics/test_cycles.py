"""Seed 004's work cycles (:mod:`assur.dynamics.cycles`) on the bundled crane models
(examples/crane_lv184a.toml, crane_lv185.toml, crane_lv215.toml)."""

from __future__ import annotations

import numpy as np
import pytest

from assur import io
from assur.dynamics.cycles import SCENARIOS, Cycle, cycle, cycle_forces, sweep

CRANES = ("crane_lv184a", "crane_lv185", "crane_lv215")


def strokes(model):
    p = model.mechanism.params
    return ((float(p["S01"]), float(p["S2_53"])), (float(p["Smax1"]), float(p["S2_146"])))


@pytest.fixture(scope="module", params=CRANES)
def crane(request):
    return io.load(io.bundled(request.param), warn=True)


def test_the_file_is_the_paper_crane():
    """crane_lv184a.toml gives the forces of the corrected paper (the Python model of
    tests/helpers/seed_004.py, equal to eqs. 37–38 and 45–59) to 1e-6 (l_c is written
    to 7 digits in the file)."""
    from tests.helpers.seed_004 import paper_cycle
    model = io.load(io.bundled("crane_lv184a"))
    (s1, s2), _ = strokes(model)
    t = np.linspace(0.0, 6.0, 13)
    q, F_paper = paper_cycle(t, 0.085, 0.13, s2)
    c = Cycle("combined at the divider's speeds", 6.0, t, q,
              np.broadcast_to([0.085, -0.13], q.shape), np.zeros(13, int))
    (F, _), = cycle_forces(model.mechanism, [c], g=9.81)
    err = np.abs(F - F_paper).max(axis=0) / np.abs(F_paper).max(axis=0)
    assert (err < 1e-6).all(), err


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_cycles_arrive_and_keep_the_speeds(scenario):
    start, end = (1.0, 2.0), (1.6, 1.2)
    c = cycle(start, end, 8.0, scenario)
    np.testing.assert_allclose(c.q[0], start)
    np.testing.assert_allclose(c.q[-1], end, atol=1e-12)
    dq = np.diff(c.q, axis=0)
    dt = np.diff(c.t)[:, None]
    same = c.segment[1:] == c.segment[:-1]
    np.testing.assert_allclose(dq[same], (c.qdot[1:] * dt)[same], atol=1e-12)
    if scenario == "combined_ideal":
        assert c.t[-1] == pytest.approx(8.0)
        np.testing.assert_allclose(np.abs(c.qdot[0]), [0.6 / 8, 0.8 / 8])
    elif scenario.startswith("separate"):
        assert c.t[-1] == pytest.approx(8.0)  # (62): V = (S1 + S2)/T
        assert (np.count_nonzero(c.qdot, axis=1) == 1).all()
        first = 1 if scenario == "separate_second" else 0
        assert c.qdot[0, first] != 0
    else:  # (60): V1 = V2 = min stroke / T; the longer stroke arrives later
        np.testing.assert_allclose(np.abs(c.qdot[0]), [0.6 / 8, 0.6 / 8])
        assert c.t[-1] == pytest.approx(8.0 * 0.8 / 0.6)


def test_dynamic_parts_scale_as_one_over_T_squared(crane):
    """Constant rod speeds: F_d·T² and the static maxima do not depend on T
    (BRIEF.md), so no ratio of dynamic parts does either."""
    start, end = strokes(crane)
    df = sweep(crane.mechanism, start, end)
    assert len(df) == 17 * 4
    for s, d in df.groupby("scenario"):
        for col in ("Fd1_max", "Fd2_max"):
            x = d[col].to_numpy() * d["T"].to_numpy() ** 2
            np.testing.assert_allclose(x, x[0], rtol=1e-9)
        # at long cycles the force tends to the static one from above or below
        assert (np.diff(np.abs(d["Fd1_max"].to_numpy())) < 0).all()


def test_paper_conclusions_at_a_6_s_cycle():
    """Seed 004's conclusions against the model (ЛВ-184А, T = 6 s) on the old basis,
    max |F| against V1 = V2 (eq. 60), reported beside the verdicts' basis (the fed
    direction against eq. 61: tests/views/report/test_cycles.py) in
    docs/simulation.md: separate motion (stick first) needs a boom force ≈ 80 %
    higher than combined (paper: ≈ 90 %); the stick's force ≈ 13 % higher (paper:
    ≈ 30 %); the dynamic parts fall 5× (boom) and 8× (stick) with combined motion
    (paper: 3–8×). The boom-first order gives far smaller gains — the paper does not
    say which order its 90 % is for."""
    model = io.load(io.bundled("crane_lv184a"))
    start, end = strokes(model)
    d = sweep(model.mechanism, start, end, periods=[6]).set_index("scenario")
    comb, sep = d.loc["combined_equal"], d.loc["separate_second"]
    assert 1.7 < sep.F1_max / comb.F1_max < 1.9
    assert 1.05 < sep.F2_max / comb.F2_max < 1.2
    assert 3 < sep.Fd1_max / comb.Fd1_max < 8
    assert 3 < sep.Fd2_max / comb.Fd2_max < 9


def test_bad_scenario():
    with pytest.raises(ValueError, match="scenario must be one of"):
        cycle((1, 2), (2, 1), 6.0, "both")
    with pytest.raises(ValueError, match="period"):
        cycle((1, 2), (2, 1), 0.0, "combined_ideal")


# ---- assur cycles: tables, figures, report (verdicts: tests/views/report/test_cycles.py)


def test_the_drive_sets_the_papers_strokes():
    """The cycle runs between the drive's stops: the boom S01 → S_max1 (raise), the
    stick from Φ1p0 to Φ1pmax (its valve lowers: S2 shrinks)."""
    from assur.dynamics.cycles import strokes
    model = io.load(io.bundled("crane_lv184a"))
    start, end = strokes(model.drive)
    p = model.mechanism.params
    np.testing.assert_allclose(start, [float(p["S01"]), float(p["S2_53"])])
    np.testing.assert_allclose(end, [float(p["Smax1"]), float(p["S2_146"])])


@pytest.mark.parametrize("lang, crane", [("en", "crane_lv184a"), ("ru", "crane_lv185")])
def test_cli_cycles_writes_tables_figures_and_report(tmp_path, lang, crane):
    import pandas as pd
    from typer.testing import CliRunner

    from assur.views.cli import app
    from assur.views.report.cycles import FIGURES
    r = CliRunner().invoke(app, ["cycles", str(io.bundled(crane)), "-o", str(tmp_path),
                                 "--lang", lang])
    assert r.exit_code == 0, r.output
    # the file's units (the cranes write forces in N… or kN), the language's CSV dialect
    from assur.core.display import unit_system
    from assur.views.report.labels import unit
    from assur.views.report.tables import CSV_DIALECTS
    du = unit_system(io.load(io.bundled(crane)).mechanism)
    sep, mark, encoding = CSV_DIALECTS[lang]
    s_, n_ = unit(du["time"].text, lang), unit(du["force"].text, lang)
    for s in SCENARIOS:
        df = pd.read_csv(tmp_path / f"cycles_{s}.csv", sep=sep, decimal=mark,
                         encoding=encoding)
        assert list(df[f"T [{s_}]"]) == list(range(4, 21))
        assert {f"F1_max [{n_}]", f"Fs1_max [{n_}]", f"F2_max [{n_}]"} <= set(df.columns)
        assert (df[f"F1_max [{n_}]"] >= df[f"Fs1_max [{n_}]"] - 1e-6).all()
    for name in FIGURES:
        assert (tmp_path / f"cycles_{name}.png").stat().st_size > 0
    assert (tmp_path / "cycles.xlsx").stat().st_size > 0
    conc = pd.read_csv(tmp_path / "cycles_conclusions.csv", sep=sep, encoding=encoding)
    assert list(conc["key"]) == ["boom_excess", "stick_excess", "dynamic_fall",
                                 "effective_below", "pump_forces", "pump_dynamic"]
    page = (tmp_path / "cycles.html").read_text(encoding="utf-8")
    if lang == "ru":
        assert "согласуется" in page and "12,666e-3" in page and "S_max2" in page
        assert "3,335 м" not in page  # ЛВ-185's own notes, not ЛВ-184А's (extends)
        assert "Выводы статьи и модель" in page
    else:
        assert "does not agree" in page and "agrees" in page and "S_max2" in page
    assert "data:image/png;base64," in page and "Traceback" not in r.output


def test_cli_cycles_without_a_drive_fails_with_one_message(tmp_path):
    from typer.testing import CliRunner

    from assur.views.cli import app
    r = CliRunner().invoke(app, ["cycles", str(io.bundled("hitch_003")), "-o",
                                 str(tmp_path)])
    assert r.exit_code == 1
    assert "no hydraulic drive" in r.output and "Traceback" not in r.output




# ---- the force in the fed direction (issue 25)


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_the_fed_direction_is_the_sign_of_the_stroke(scenario):
    """σ_j is the sign of cylinder j's stroke velocity in every scenario (each rod
    moves one way), the held phases of separate motion included in the max."""
    from assur.dynamics.cycles import fed_force, fed_sense
    c = cycle((1.0, 2.0), (1.6, 1.2), 8.0, scenario, samples=5)
    assert fed_sense(c).tolist() == [1.0, -1.0]
    F = np.zeros_like(c.qdot)
    F[:, 0] = np.linspace(-3.0, 2.0, len(c.t))  # extending: the piston side pushes +F
    F[:, 1] = np.linspace(5.0, -4.0, len(c.t))  # retracting: the rod side pulls −F
    np.testing.assert_allclose(fed_force(c, F), [2.0, 4.0])
    np.testing.assert_allclose(fed_force(c, -F), [3.0, 5.0])
    # a load that drives the stroke all along: the fed chamber never pushes (< 0)
    np.testing.assert_allclose(fed_force(c, np.full_like(F, -7.0))[0], -7.0)


def test_the_fed_direction_of_a_cylinder_that_does_not_move_or_turns_fails():
    from assur.dynamics.cycles import fed_force, fed_sense
    c = cycle((1.0, 2.0), (1.6, 1.2), 8.0, "combined_ideal", samples=3)
    still = Cycle("still", 8.0, c.t, c.q, c.qdot * [1.0, 0.0], c.segment)
    with pytest.raises(ValueError, match="'still': coordinate 1 does not move"):
        fed_sense(still)
    both = Cycle("both", 8.0, c.t, c.q, c.qdot * [[1.0, 1.0], [1.0, 1.0], [-1.0, 1.0]],
                 c.segment)
    with pytest.raises(ValueError, match="'both': coordinate 0 moves both ways"):
        fed_sense(both)
    with pytest.raises(ValueError, match=r"forces of shape \(3, 1\)"):
        fed_force(c, np.zeros((3, 1)))


def test_the_sweep_reports_the_fed_force_beside_max_abs(crane):
    """The sweep's F_fed columns are fed_force of each cycle's forces; the boom
    extends (max +F1 = max |F1| on these cranes), the stick retracts (max −F2, less
    than max |F2|: the push against its motion at the start is held by the drained
    side)."""
    from assur.dynamics.cycles import strokes as drive_strokes
    a, b = drive_strokes(crane.drive)
    d = sweep(crane.mechanism, a, b, periods=[6.0]).set_index("scenario")
    for s in SCENARIOS:
        (F, Fs), = cycle_forces(crane.mechanism, [cycle(a, b, 6.0, s)])
        assert d.loc[s, "F1_fed"] == pytest.approx(F[:, 0].max(), rel=1e-12)
        assert d.loc[s, "F2_fed"] == pytest.approx((-F[:, 1]).max(), rel=1e-12)
        assert d.loc[s, "Fs2_fed"] == pytest.approx((-Fs[:, 1]).max(), rel=1e-12)
        assert d.loc[s, "F2_fed"] < d.loc[s, "F2_max"]
