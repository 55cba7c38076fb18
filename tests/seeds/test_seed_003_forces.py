"""Seed 003 (``003_b1551261b108abd1.txt``) §4–5: cylinder force, pressure, lift
capacity (Таблица 4.1) and joint reactions by Assur groups (Таблица 5.1), at the
printed precision, from ``examples.hitch_003()``.

Convention: assur's ``reaction(i, j)`` is the force of link i on link j. The seed
prints the x, y components of R05, R34 and R45 with the opposite sign to its own
naming (R05 + R34 − R65 = 0 in §5.2 with R65 already the force of 6 on 5, repeated
by R43 := −R34 in §5.3); their magnitudes, and R01, R03, R23, R56, R07, Fgc, are
right. The tests match the printed components up to that documented sign.
"""

import numpy as np
import pytest

from assur import examples
from assur.core.columns import column_signs, signs_of

from tests.helpers.seed_tables import T003_4_1, T003_5_1, assert_printed


def test_table_4_1_force_pressure_capacity(hitch_analysis):
    c = hitch_analysis.cylinder("ГЦ")
    assert_printed(c.force, T003_4_1, "Fgc")           # Fgc = P6·IS6 [N]
    assert_printed(c.pressure, T003_4_1, "Pgc")        # Pgc = Fgc/(k·S_gc·η), to 1 Pa
    assert_printed(c.capacity("56"), T003_4_1, "G56")  # k·p·η·S_gc/I56
    assert_printed(c.capacity("S6"), T003_4_1, "GS6")  # k·p·η·S_gc/IS6
    assert_printed(c.reserve("S6", 27500.0), T003_4_1, "dGS65")


def test_fgc_is_p6_times_is6(hitch_analysis):
    kin = hitch_analysis.kinematics
    f = hitch_analysis.statics.actuator_force("S")
    assert np.allclose(f, 27500.0 * kin.transmission("S6"), rtol=1e-13)


@pytest.mark.parametrize("name,pair,sign", [
    ("R56", ("5", "6"), 1), ("R07", ("0", "7"), 1), ("R23", ("2", "3"), 1),
    ("R03", ("0", "3"), 1), ("R01", ("0", "2"), 1),
    ("R05", ("0", "5"), -1), ("R34", ("3", "4"), -1), ("R45", ("4", "5"), -1),
])
def test_table_5_1_reactions(hitch_analysis, name, pair, sign):
    r = hitch_analysis.statics.reaction(*pair)
    assert_printed(sign * r[:, 0], T003_5_1, name + "x")
    assert_printed(sign * r[:, 1], T003_5_1, name + "y")
    assert_printed(hitch_analysis.statics.reaction_magnitude(*pair), T003_5_1, name)


def test_table_5_1_fgc_equals_r23(hitch_analysis):
    """R23 = Fgc: the cylinder force from the reactions equals the virtual-work force."""
    st = hitch_analysis.statics
    assert_printed(st.actuator_force_from_reactions("S"), T003_5_1, "Fgc")
    assert np.allclose(st.actuator_force_from_reactions("S"), st.actuator_force("S"),
                       rtol=1e-12)
    assert np.allclose(st.reaction_magnitude("2", "3"), st.actuator_force("S"), rtol=1e-12)


def test_every_link_is_in_equilibrium(hitch_analysis):
    f, m = hitch_analysis.statics.equilibrium_residual()
    assert f.max() <= 1e-6 and m.max() <= 1e-6


def test_seed_sign_slip_is_flagged_and_seed_frame_matches_print(hitch_analysis):
    """The model file's sign map names the six printed components and explains the
    slip; ``to_frame(printed_signs=True)`` then matches the print."""
    st = hitch_analysis.statics
    (m,) = signs_of(hitch_analysis.mechanism)
    assert m.sign == -1 and "R05 + R34 − R65 = 0" in m.note
    assert set(column_signs(hitch_analysis.mechanism)) == {"R05x", "R05y", "R34x", "R34y", "R45x",
                                                     "R45y"}
    assert st.named_reactions()["R05"] == ("0", "5")
    printed = st.to_frame(printed_signs=True)
    ours = st.to_frame()
    for col in ["R05x", "R34y", "R45x", "R56x", "R01y"]:
        assert_printed(printed[col].to_numpy(), T003_5_1, col)
    assert np.allclose(ours["R05x"], -printed["R05x"])
    assert np.allclose(ours["R56x"], printed["R56x"])


def test_two_force_brace_4(hitch_analysis):
    """Link 4 carries no load: the force of 3 on 4 equals the force of 4 on 5 and lies
    along the brace (34 → 45)."""
    st, kin = hitch_analysis.statics, hitch_analysis.kinematics
    r34, r45 = st.reaction("3", "4"), st.reaction("4", "5")
    assert np.allclose(r34, r45, atol=1e-7)
    d = kin.point("45") - kin.point("34")
    assert np.allclose(d[:, 0] * r34[:, 1] - d[:, 1] * r34[:, 0], 0, atol=1e-6)


def test_batch_of_designs_forces(hitch_analysis):
    """Parameters as arrays over designs: forces per design equal single solves."""
    s = examples.hitch_003_range()
    P6 = np.array([20000.0, 27500.0])
    a = examples.hitch_003(P6=P6).analyze(s)
    assert a.statics.actuator_force().shape == (2, 10)
    one = hitch_analysis
    assert np.allclose(a.statics.actuator_force()[1], one.statics.actuator_force())
    assert np.allclose(a.statics.reaction("0", "5")[0], one.statics.reaction("0", "5") * 20000
                       / 27500)


def test_blocked_reverse_pass_equals_the_whole(monkeypatch):
    """Large ranges are solved in blocks of positions: the blocks give the same
    reactions, forces and residuals as one pass (static and with inertia, batch too)."""
    from assur.core import statics
    s = np.linspace(0.42, 0.67, 11)
    m = examples.hitch_003(P6=np.array([20000.0, 27500.0])).mass("6", 2800.0, "S6", J=900.0)
    kin = m.solve(s)
    qd, qdd = 0.05 * np.cos(s), -0.05 * np.sin(s)
    whole = [statics.solve(kin), statics.solve(kin, qdot=qd, qddot=qdd)]
    monkeypatch.setattr(statics, "BLOCK", 4)
    blocked = [statics.solve(kin), statics.solve(kin, qdot=qd, qddot=qdd)]
    for w, b in zip(whole, blocked):
        assert {j[1:] for j in w.joints} == {j[1:] for j in b.joints}
        for _, i, j in w.joints:
            assert np.array_equal(w.reaction(i, j), b.reaction(i, j))
        assert np.array_equal(w.actuator_force("S"), b.actuator_force("S"))
        assert np.array_equal(w.actuator_force_from_reactions("S"),
                              b.actuator_force_from_reactions("S"))
        assert b.equilibrium_residual()[0].shape == (2, 11)
        assert b.equilibrium_residual()[0].max() <= 1e-6
