"""The verdicts of seed 004's cycle report (:mod:`assur.views.report.cycles`): each of
the paper's conclusions is judged from the sweep's numbers — changing the numbers, or
the claim, changes the verdict; the pump's verdicts rest on the drive's own speeds."""

import numpy as np
import pytest

from assur import io
from assur.dynamics.cycles import sweep


@pytest.fixture(scope="module")
def lv184a_sweep():
    from assur.dynamics.cycles import strokes
    model = io.load(io.bundled("crane_lv184a"))
    return sweep(model.mechanism, *strokes(model.drive))



def test_verdicts_follow_the_numbers(lv184a_sweep):
    """Each verdict is computed from the sweep: claim 1's excess is the ratio of the
    max forces in the fed direction at 6 s against ideal combined motion (eq. 61),
    max |F| and V1 = V2 (eq. 60) beside it; changing the numbers (or the claim)
    changes the verdict."""
    from assur.views.report.cycles import ABOUT, BASIS, EQUAL, conclusions
    assert (BASIS, EQUAL) == ("combined_ideal", "combined_equal")
    df = lv184a_sweep
    v = {x.key: x for x in conclusions(df)}
    at6 = df[df["T"] == 6.0].set_index("scenario")
    for j, key in ((1, "boom_excess"), (2, "stick_excess")):
        for name, kind, base in (("excess", "fed", BASIS), ("max", "max", BASIS),
                                 ("fed_equal", "fed", EQUAL), ("max_equal", "max", EQUAL)):
            for s in ("separate_second", "separate_first"):
                ex = at6.loc[s, f"F{j}_{kind}"] / at6.loc[base, f"F{j}_{kind}"] - 1
                assert v[key].numbers[name][s] == pytest.approx(ex, rel=1e-12)
        target = v[key].numbers["target"]
        assert v[key].agrees == any(abs(e - target) <= ABOUT * target
                                    for e in v[key].numbers["excess"].values())
        assert v[key].numbers["basis"] == "combined_ideal"
        assert v[key].model.startswith("eq. 61, ideal combined motion, force in the fed "
                                       "direction: ")
        assert "max |F|" in v[key].model and "V1 = V2 (eq. 60" in v[key].model
    assert v["boom_excess"].agrees and v["stick_excess"].agrees  # +89 %, +25 %
    # the old basis (max |F| against eq. 60: +13 %) would not agree: the why says so
    assert "would not agree" in v["stick_excess"].why and "7.8 s" in v["stick_excess"].why
    assert "would" not in v["boom_excess"].why  # +79 % agrees on either basis
    assert v["dynamic_fall"].agrees and v["dynamic_fall"].numbers["spread"] < 1e-9
    # the stick's fed force of separate motion 30 % lower: +25 % → −12 %, no longer ≈ 30 %
    changed = df.copy()
    sep = changed["scenario"].isin(["separate_second", "separate_first"])
    changed.loc[sep, "F2_fed"] *= 0.7
    assert not {x.key: x for x in conclusions(changed)}["stick_excess"].agrees
    # a claim of +50 % for the boom is not what the model gives
    paper = {"period": 6.0, "excess": (0.5, 0.3), "dynamic": (3.0, 8.0),
             "effective_below": 9.0}
    v2 = {x.key: x for x in conclusions(df, paper=paper)}
    assert not v2["boom_excess"].agrees
    assert v2["effective_below"].agrees == (abs(v["effective_below"].numbers["T_star"] - 9.0)
                                            <= 1.0)


def test_the_stick_at_6_s_in_the_fed_direction_against_eq_61_is_the_papers_route(
        lv184a_sweep):
    """Issue 25: ЛВ-184А's stick at T_c = 6 s (the crane of the paper's "about 30 %"),
    the force in the fed direction (the stick's rod retracts: the rod side is fed, so
    max of −F2), separate motion (a) ÷ ideal combined motion (eq. 61) − 1, equals the
    same definition computed without the engine: the corrected paper's own kinematics
    and Lagrange equations (eqs. 37–38, 47–59: tests/helpers/seed_004.py) at the
    cycle's sampled times, between the file's strokes (table 1: S01, S_max1; the
    stick's lengths at Φ1p = 53° and 146° by eq. 51, as the file rounds them). It is
    the +25 % that agrees with the paper's ≈ 30 %; max |F| against V1 = V2 (eq. 60)
    gave +13 %. Both routes agree to 1e-6 (the file writes l_c to 7 digits)."""
    import math

    from assur.views.report.cycles import conclusions
    from tests.helpers import seed_004 as p
    T, n = 6.0, 41  # the sweep's samples per segment

    def S2(phi_deg):  # eq. 51: the stick cylinder's length at the table's angle Φ1p
        return math.sqrt(p.a2_ ** 2 + p.l3_ ** 2 + 2 * p.a2_ * p.l3_
                         * math.cos(p.alpha_ + math.radians(phi_deg)))

    q = io.load(io.bundled("crane_lv184a")).mechanism.params
    S20, S2e = float(q["S2_53"]), float(q["S2_146"])
    assert abs(S20 - S2(53.0)) < 1e-4 and abs(S2e - S2(146.0)) < 1e-4
    assert (float(q["S01"]), float(q["Smax1"])) == (p.S01, p.Smax1)
    dS1, dS2 = p.Smax1 - p.S01, S20 - S2e
    # eq. 61: both rods from the start, V_j = ΔS_j/T_c, both arrive at T_c
    _, F_ideal = p.paper_cycle(np.linspace(0.0, T, n), dS1 / T, dS2 / T, S20)
    # eq. 62 (a): V = (ΔS1 + ΔS2)/T_c, the stick alone, then the boom (the stick held)
    V = (dS1 + dS2) / T
    _, F_stick = p.paper_cycle(np.linspace(0.0, dS2 / V, n), 0.0, V, S20)
    _, F_boom = p.paper_cycle(np.linspace(0.0, dS1 / V, n), V, 0.0, S2e)
    F_sep = np.concatenate([F_stick, F_boom])

    def fed(F):  # the rod side of the retracting stick pulls: −F2 > 0
        return float(np.max(-F[:, 1]))

    expected = fed(F_sep) / fed(F_ideal) - 1
    v = {x.key: x for x in conclusions(lv184a_sweep)}["stick_excess"]
    assert v.numbers["basis"] == "combined_ideal"
    assert v.numbers["excess"]["separate_second"] == pytest.approx(expected, rel=1e-6)
    assert 0.24 < expected < 0.26 and v.agrees  # the paper: about 30 % (±25 % of it)
    # max |F| counts the push against the stick's motion at t = 0, held by the drained side
    by_abs = np.abs(F_sep[:, 1]).max() / np.abs(F_ideal[:, 1]).max() - 1
    assert v.numbers["max"]["separate_second"] == pytest.approx(by_abs, rel=1e-6)
    assert np.argmax(np.abs(F_ideal[:, 1])) == 0 and F_ideal[0, 1] > 0


def test_every_crane_states_the_basis_in_both_languages():
    """The verdicts of every crane name their basis (eq. 61, the fed direction) in
    English and Russian; the report's criteria state it once."""
    from assur.dynamics.cycles import strokes
    from assur.views.report._cycles_text import _t
    from assur.views.report.cycles import conclusions
    for crane in ("crane_lv184a", "crane_lv185", "crane_lv215"):
        model = io.load(io.bundled(crane))
        df = sweep(model.mechanism, *strokes(model.drive), periods=[6.0, 11.0, 20.0])
        for lang, basis in (("en", "eq. 61, ideal combined motion, force in the fed "
                                   "direction"),
                            ("ru", "ур. 61, идеальное совмещение, усилие в направлении "
                                   "питаемой полости")):
            vs = conclusions(df, lang)
            for v in vs[:2] + vs[3:]:
                assert v.model.startswith(basis + ": "), (crane, v.key, v.model)
            assert ("ур. 61" if lang == "ru" else "eq. 61") in vs[2].model
    assert "fed direction" in _t("criteria", "en", 25, 10, "")
    assert "питаемой полости" in _t("criteria", "ru", 25, 10, "")


def test_pump_verdicts_follow_the_drives_speeds():
    """The paper's conclusion 3: the standard pump with the divider (V = Q/(2f))
    against the whole flow to one cylinder at a time (V = Q/f). The cycles run at the
    drive's speeds, and the verdicts rest on their forces' ratios."""
    from assur.dynamics.cycles import drive_cycles
    from assur.views.report.cycles import drive_sweep, pump_conclusions
    model = io.load(io.bundled("crane_lv184a"))
    cs = drive_cycles(model.drive)
    Q = model.drive.pump_flow()
    speeds = [Q / (2 * b.area) for b in model.drive.branches]
    np.testing.assert_allclose(np.abs(cs["divider"].qdot[0]), speeds, rtol=1e-12)
    assert np.count_nonzero(cs["pump_first"].qdot[0]) == 1
    assert abs(cs["pump_first"].qdot[0, 0]) == pytest.approx(2 * speeds[0], rel=1e-12)
    dd = drive_sweep(model)
    v = {x.key: x for x in pump_conclusions(dd)}
    d = dd.set_index("scenario")
    for j in (1, 2):  # the forces in the fed direction, max |F| beside
        r = d.loc["pump_second", f"F{j}_fed"] / d.loc["divider", f"F{j}_fed"]
        assert v["pump_forces"].numbers["ratios"]["pump_second"][j - 1] == pytest.approx(
            r, rel=1e-12)
        r = d.loc["pump_second", f"F{j}_max"] / d.loc["divider", f"F{j}_max"]
        assert v["pump_forces"].numbers["ratios_max"]["pump_second"][j - 1] == pytest.approx(
            r, rel=1e-12)
    # the fed direction: the boom extends (max +F1), the stick retracts (max −F2)
    from assur.dynamics.cycles import cycle_forces
    (F, _), = cycle_forces(model.mechanism, [cs["divider"]])
    assert d.loc["divider", "F1_fed"] == pytest.approx(F[:, 0].max(), rel=1e-12)
    assert d.loc["divider", "F2_fed"] == pytest.approx((-F[:, 1]).max(), rel=1e-12)
    assert v["pump_forces"].agrees == any(all(1.16 <= round(x, 2) <= 2.0 for x in rs)
                                          for rs in v["pump_forces"].numbers["ratios"].values())
    # a claimed fall of 10 times is not what the model gives
    paper = {"pump_forces": (1.16, 2.0), "pump_dynamic": 10.0}
    assert not {x.key: x for x in pump_conclusions(dd, paper=paper)}["pump_dynamic"].agrees

