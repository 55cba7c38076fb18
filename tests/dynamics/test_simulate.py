"""The lab-6 lift (seed 001 lab 6, examples/adapter_lab6.toml): hydraulic drive +
mechanism simulated in time (:mod:`assur.dynamics.simulate`, :mod:`assur.dynamics.drive`).

What is checked, and against what:

* the lab's data: Q = q·n·η0 = 32 cm³ · 1800/60 · 0.9 and the steady rod speed Q/A
  with A = π·0.125²/4 (lab 6, task 1), and the simulated rod speed against it;
* lab 6 eq. (6): the reduced mass m(S) = m6·I_v² + J6·φ6'² with I_v = φ6'·L_S6,
  from the link's angular analog (not through the equations of motion);
* the start-up: a pressure overshoot and an oscillating speed (lab 6: "the rise of
  the piston speed … is pronouncedly oscillatory");
* the energy balance W_pump = losses + mechanism + stored to 1e-3 (every method);
* the work against gravity equals m6·g·ΔY_S6 from the engine's positions;
* closed forms: the lift-off time of a closed volume filled at a constant flow
  (t = p_lift·V0/(E·Q)), and the relief valve's end pressure p_set + Δp_reg.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from assur import io
from assur.dynamics.drive import Circuit, LineLosses, registry
from assur.dynamics import simulate, simulate_model
from assur.dynamics.simulate import METHODS, ReducedTable
from assur.errors import ModelError
from assur.io import ModelFileError

# a simulation calls its mechanism's kernels thousands of times: compiled, as users run
# it (tests/conftest.py)
pytestmark = pytest.mark.compiled

#: lab 6 task 1: НШ-32 at 1800 rpm, η0 = 0.9; piston 0.125 m
Q_LAB = 32e-6 * 1800 / 60 * 0.9
A_LAB = math.pi * 0.125 ** 2 / 4
V_LAB = Q_LAB / A_LAB  # 0.0704 m/s


@pytest.fixture(scope="module")
def model():
    return io.load(io.bundled("adapter_lab6"), warn=True)


@pytest.fixture(scope="module")
def result(model):
    return simulate_model(model)


def test_the_lab_data_give_the_steady_speed(model, result):
    assert model.drive.pump_flow() == pytest.approx(Q_LAB, rel=1e-12)
    assert result.steady_speed == pytest.approx(V_LAB, rel=1e-12)
    assert round(V_LAB, 4) == 0.0704


def test_the_simulated_rod_speed_is_the_pumps_flow_over_the_area(model, result):
    """From lift-off to the end of the stroke the rod moves at Q/A on average within
    1 % (the oscillation goes on: lab 6 "most of the lift at a variable speed"); with
    a heavily damped line it settles at Q/A within 5e-3 (what is left is the oil the
    slowly rising pressure compresses)."""
    t_off, t_end = result.events["lift-off"][0], result.events["end of stroke"][0]
    assert 0.25 / (t_end - t_off) == pytest.approx(V_LAB, rel=1e-2)
    damped = Circuit(tuple(LineLosses(a2=1e8) if c.role == "line" else c
                           for c in model.drive.components))
    r = simulate(model.mechanism, damped, 3.0)
    late = (r.t > 2.0) & (r.t < 3.0)
    assert np.abs(r.qdot[late] / V_LAB - 1).max() < 5e-3
    # what is left is the compression flow V·ṗ/E of the rising pressure
    assert np.abs(r.qdot[late] / V_LAB - 1).max() <= 1.05 * np.abs(
        r.flows["compression"][late]).max() / Q_LAB + 1e-6


def test_the_start_up_overshoots(result):
    """Pressure overshoot and speed oscillation at the start of the lift."""
    moving = result.phase == "moving"
    p_load = np.median(result.load[moving]) / A_LAB  # the pressure that holds the load
    assert result.p1[moving].max() > 1.3 * p_load
    assert result.qdot.max() > 1.3 * V_LAB
    late = moving & (result.t > result.events["lift-off"][0] + 0.5)
    assert result.qdot[late].min() < 0.8 * V_LAB


@pytest.mark.parametrize("method", METHODS)
def test_energy_balance(model, method):
    r = simulate_model(model, method=method)
    assert r.status == 0, r.message
    e = r.energy
    assert abs(e["residual"]) <= 1e-3 * e["pump"], e
    assert e["relief"] > 0 and e["impact"] > 0 and e["line"] > 0


def test_work_against_gravity_is_the_rise_of_the_centre_of_mass(model, result):
    kin = model.mechanism.solve(np.array([0.55, 0.80]))
    rise = float(np.diff(kin.y("S6"))[0])
    m6 = float(model.mechanism.params["m6"])
    assert result.energy["loads"] == pytest.approx(m6 * 9.81 * rise, rel=1e-6)


def test_reduced_mass_is_lab6_eq6(model):
    """m(S) = m6·I_v² + J6·φ6'², I_v = φ6'·L_S6 (lab 6 eq. 6), and m'(S) =
    2·(m6·I_v·I_v' + J6·φ6'·φ6'') (the lab's m'(S)), from the lever's analogs."""
    S = np.linspace(0.55, 0.80, 51)
    tab = ReducedTable.from_mechanism(model.mechanism, 0.55, 0.80, 51)
    kin = model.mechanism.solve(S)
    p = model.mechanism.params
    w1, w2 = kin.dphi("3"), kin.ddphi("3")
    L, m6, J6 = float(p["LS6"]), float(p["m6"]), float(p["J6"])
    Iv, dIv = w1 * L, w2 * L
    np.testing.assert_allclose(tab.m, m6 * Iv ** 2 + J6 * w1 ** 2, rtol=1e-12)
    np.testing.assert_allclose(tab.dm, 2 * (m6 * Iv * dIv + J6 * w1 * w2), rtol=1e-10)
    # and the interpolant's derivative is m' between the nodes too
    mid = 0.5 * (S[:-1] + S[1:])
    m, dm, _ = tab(mid)
    kin_mid = model.mechanism.solve(mid)
    w1, w2 = kin_mid.dphi("3"), kin_mid.ddphi("3")
    np.testing.assert_allclose(dm, 2 * (m6 * L * L + J6) * w1 * w2, rtol=1e-4)


def test_lift_off_time_and_relief_pressure_in_closed_form(model, result):
    d = model.drive
    E, V0, Qp = d.volume.bulk_modulus, d.volume.volume, d.pump_flow()
    p_lift = result.load[0] / d.area
    assert result.events["lift-off"][0] == pytest.approx(p_lift * V0 / (E * Qp), rel=1e-6)
    rv = d.relief
    assert result.events["relief opens"] and result.events["relief opens"][0] > \
        result.events["end of stroke"][0]
    assert result.p1[-1] == pytest.approx(rv.setting + rv.regulation_range, rel=1e-3)


def test_result_table(result):
    df = result.to_frame()
    assert {"t", "S", "dS", "ddS", "p1", "p2", "dp1", "F", "Q_relief"} <= set(df.columns)
    assert np.isfinite(df.to_numpy(dtype=float)).all()
    assert len(df) == 2251


def test_bad_inputs(model):
    with pytest.raises(ValueError, match="method must be one of"):
        simulate(model.mechanism, model.drive, 1.0, method="RK45")
    with pytest.raises(ValueError, match="t_end"):
        simulate(model.mechanism, model.drive, -1.0)
    with pytest.raises(ModelError, match="role 'pump'"):
        Circuit(tuple(c for c in model.drive.components if c.role != "pump"))
    with pytest.raises(ModelError, match="eta_volumetric"):
        registry()["gear_pump"](32e-6, 188.5, 1.5)
    with pytest.raises(ModelError, match="s_min"):
        dataclasses.replace(model.drive.cylinder, s_min=0.9)


def test_malformed_drive_entries_name_the_line():
    text = io.bundled("adapter_lab6").read_text()
    bad = text.replace('displacement = "32 cm^3"', 'displacment = "32 cm^3"')
    with pytest.raises(ModelFileError, match=r"drive\[0\]\.displacment.*did you mean"):
        io.loads(bad, "adapter.toml")
    bad = text.replace('displacement = "32 cm^3"', 'displacement = "32 MPa"')
    with pytest.raises(ModelFileError, match=r":\d+: drive\[0\]\.displacement"):
        io.loads(bad, "adapter.toml")
    bad = text.replace('type = "gear_pump"', 'type = "gear_pmp"')
    with pytest.raises(ModelFileError, match="gear_pump"):
        io.loads(bad, "adapter.toml")


def test_cli_simulate_writes_tables_figures_and_report(tmp_path):
    import pandas as pd
    from typer.testing import CliRunner

    from assur.views.cli import app
    from assur.views.report.simulation import FIGURES
    r = CliRunner().invoke(app, ["simulate", str(io.bundled("adapter_lab6")), "-o",
                                 str(tmp_path), "--lang", "ru"])
    assert r.exit_code == 0, r.output
    assert "reached t_end" in r.output
    for name in FIGURES:
        assert (tmp_path / f"simulation_{name}.png").stat().st_size > 0
    from PIL import Image
    with Image.open(tmp_path / "simulation.gif") as gif:  # 0.1 s a frame over 4.5 s
        # (equal frames at rest on a stop are merged by the GIF writer)
        assert 20 < gif.n_frames <= 46
    # Russian: ";" and the decimal comma, as the analysis' CSV files
    df = pd.read_csv(tmp_path / "simulation.csv", sep=";", decimal=",", encoding="utf-8-sig")
    assert len(df) == 2251 and "p1 [MPa]" in df.columns
    text = (tmp_path / "simulation.csv").read_text(encoding="utf-8-sig")
    assert "-0,0;" not in text and "nan" not in text.lower() and "." not in text.split("\n")[1]
    page = (tmp_path / "simulation.html").read_text(encoding="utf-8")
    assert "Подъём секции косилки-плющилки" in page and "невязка баланса" in page
    # the motion in real time as vector frames: one per 0.1 s over 4.5 s, captioned
    assert page.count('<g class="frame"') == 46
    assert 'id="anim-q">t = 0 с; S = ' in page and "data:image/gif" not in page
    summary = (tmp_path / "simulation_summary.csv").read_text(encoding="utf-8-sig")
    assert "открытие предохранительного клапана" in summary


def test_cli_simulate_without_a_drive_fails_with_one_message(tmp_path):
    from typer.testing import CliRunner

    from assur.views.cli import app
    r = CliRunner().invoke(app, ["simulate", str(io.bundled("hitch_003")), "-o",
                                 str(tmp_path)])
    assert r.exit_code == 1
    assert "no hydraulic drive" in r.output and "Traceback" not in r.output


# ---- k = 1 through the general code -------------------------------------------------

def test_k1_is_the_lab6_result_of_the_one_coordinate_code():
    """The k-coordinate simulation reproduces, for lab 6, the events of the former
    one-coordinate implementation (main at cb713dc, before the generalisation; the
    trajectories agreed to 1e-14 m and 1e-6 Pa) to 1e-9."""
    r = simulate_model(io.load(io.bundled("adapter_lab6")))
    assert r.events["lift-off"][0] == pytest.approx(0.0828490749116, rel=1e-9)
    assert r.events["end of stroke"][0] == pytest.approx(3.63494141456, rel=1e-9)
    assert r.events["relief opens"][0] == pytest.approx(4.02055380189, rel=1e-9)


def test_k1_exact_equations_equal_the_table(model, result):
    """nodes=None evaluates M, ∂M/∂q, Q exactly at every state (the k > 1 path): the
    lift equals the tabulated one (801 nodes) to the table's interpolation error."""
    r = simulate(model.mechanism, model.drive, 4.5, t_eval=result.t, nodes=None)
    assert r.status == 0, r.message
    for name in ("lift-off", "end of stroke"):
        assert r.events[name][0] == pytest.approx(result.events[name][0], rel=1e-5)
    np.testing.assert_allclose(r.q, result.q, atol=1e-6 * 0.25)
    np.testing.assert_allclose(r.p1, result.p1, atol=2e-4 * result.p1.max())
    assert abs(r.energy["residual"]) <= 1e-6 * r.energy["pump"]


# ---- the crane (seed 004): two cylinders through a flow divider ----------------------

#: seed 004 (004_4ff0af19c30e8a3a.txt), after eq. (66): ЛВ-184А with the divider,
#: V1 = 0.085 m/s, V2 = 0.13 m/s (piston side), 0.22 m/s (rod side)
V1_PRINTED, V2_ROD_PRINTED = 0.085, 0.22


@pytest.fixture(scope="module")
def crane():
    return io.load(io.bundled("crane_lv184a"), warn=True)


@pytest.fixture(scope="module")
def swing(crane):
    """3 s of the swing: the stick reaches its stop at ≈ 2.6 s, the boom moves on."""
    return simulate_model(crane, t_end=3.0, t_eval=np.linspace(0.0, 3.0, 301))


def _printed(value, printed):
    digits = len(f"{printed}".split(".")[1])
    return abs(value - printed) <= 0.5 * 10 ** -digits


def test_crane_drive_is_the_papers_divider(crane):
    """Eqs. (63)–(65) with the file's bores: V1 = Q/(2·f1), V2 = Q/(2·f2m) (the stick
    fed on its rod side: S2 shrinks) at the printed precision."""
    d = crane.drive
    assert d.pump_flow() * 60e3 == pytest.approx(80.0, rel=1e-9)
    V = d.steady_speeds()
    assert V[0] > 0 > V[1]
    assert _printed(V[0], V1_PRINTED) and _printed(-V[1], V2_ROD_PRINTED)
    f1, f2m = (b.area for b in d.branches)
    assert V[0] * f1 == pytest.approx(-V[1] * f2m, rel=1e-12)  # (63): V1/V2 = f2/f1


def test_crane_energy_balance(swing):
    """k = 2: W_pump = relief + divider + lines + impacts + kinetic + loads + oil to
    1e-3 of the pump's work, through the stick's impact on its stop."""
    assert swing.status == 0, swing.message
    assert swing.q.shape == (301, 2) and swing.coordinates == ("S1", "S2")
    e = swing.energy
    assert abs(e["residual"]) <= 1e-3 * e["pump"], e
    assert e["divider"] > 0 and e["impact"] > 0 and e["loads"] > 0
    assert [c for _, name, c in swing.event_log if name == "end of stroke"][0] == "S2"
    # the pump works at the higher branch pressure
    np.testing.assert_allclose(swing.pump_pressure, swing.p1.max(axis=1))


@pytest.mark.slow
def test_crane_steady_speeds_are_the_dividers_split(crane):
    """With stiff oil (E_pr × 100: the compression flow V·ṗ/E, ≈ 5 % of a branch's
    flow at 2e8 Pa as the loads grow along the swing, becomes negligible) the
    simulated mean rod speeds over the swing's middle are the divider's split at
    the paper's printed precision: V1 = 0.085 m/s, |V2| = 0.22 m/s."""
    stiff = Circuit(tuple(dataclasses.replace(c, bulk_modulus=100 * c.bulk_modulus)
                          if c.role == "volume" else c for c in crane.drive.components))
    t = np.linspace(0.0, 2.0, 201)
    # BDF: on oil this stiff Radau's implicit stages take 3× as long (19 s against 6 s
    # here) for the same speeds to 1e-6 m/s; the default method runs the other tests
    r = simulate_model(dataclasses.replace(crane, drive=stiff), t_end=2.0, t_eval=t,
                       method="BDF")
    assert r.status == 0, r.message
    win = (t >= 0.5) & (t <= 2.0)
    i0, i1 = np.flatnonzero(win)[[0, -1]]
    V = (r.q[i1] - r.q[i0]) / (t[i1] - t[i0])
    assert _printed(V[0], V1_PRINTED), V
    assert _printed(-V[1], V2_ROD_PRINTED), V
    assert V == pytest.approx(stiff.steady_speeds(), rel=5e-3)


def test_crane_impact_acts_through_the_mass_matrix(crane):
    """A plastic impact on one coordinate: its speed becomes 0, the other's changes
    by the impulse through M + diag(a1·A) (no impulse along it), energy is lost."""
    from assur.dynamics.simulate import ExactEquations, _Machine
    mach = _Machine(ExactEquations(crane.mechanism, 9.81), crane.drive, 9.81)
    y = np.zeros(mach.n)
    y[:2] = (1.3, 1.5)
    y[2:4] = (0.08, -0.2)
    before = y.copy()
    lost = mach.impact(y, np.array([True, True]), 1)
    assert y[3] == 0.0 and lost > 0
    M, _, _ = mach.mech.mechanics(y[:2, None])
    impulse = (M[0] + mach.A1) @ (y[2:4] - before[2:4])
    assert abs(impulse[0]) < 1e-9 * abs(impulse[1])
    T = lambda v: 0.5 * v @ (M[0] + mach.A1) @ v  # noqa: E731
    assert lost == pytest.approx(T(before[2:4]) - T(y[2:4]), rel=1e-12)


def test_hold_refuses_an_overrunning_start(crane):
    """At Φ1p0 the loads pull the stick's rod in, its fed sense: p0 = "hold" cannot
    hold it (the drained side is not modelled) and says so."""
    p = crane.mechanism.params
    with pytest.raises(ModelError, match="cannot hold"):
        simulate(crane.mechanism, crane.drive, 1.0, p0="hold",
                 s0={"S2": float(p["S2_53"]) - 0.01})


def test_k_cylinders_need_a_divider_and_their_branches(crane):
    comps = crane.drive.components
    with pytest.raises(ModelError, match="flow_divider"):
        Circuit(tuple(c for c in comps if c.role != "divider"))
    with pytest.raises(ModelError, match="must name its branch"):
        Circuit(tuple(dataclasses.replace(c, coordinate=None) if c.role == "line" else c
                      for c in comps))
    with pytest.raises(ModelError, match="3 shares for 2 cylinders"):
        Circuit(tuple(dataclasses.replace(c, shares=(0.2, 0.3, 0.5))
                      if c.role == "divider" else c for c in comps))


def test_simulation_start_and_hold_in_the_file(crane):
    """[simulation] start names coordinates (an unknown one is refused at its line);
    p0 = "hold" starts every branch at the pressure that holds its rod."""
    text = io.bundled("crane_lv184a").read_text(encoding="utf-8")
    assert crane.simulation.p0 == "hold"
    assert crane.simulation.start == {"S2": pytest.approx(1.80)}
    bad = text.replace('start = { S2 = "S2_start" }', 'start = { S9 = "1.8 m" }')
    with pytest.raises(ModelFileError, match=r":\d+: simulation\.start\.S9"):
        io.loads(bad, "crane.toml")
    r = simulate_model(crane, t_end=0.05, t_eval=[0.0, 0.05])
    b = crane.drive.branches[1]  # the stick's rod held by its rod side: σ·A·p = −Q
    assert b.sense * b.area * r.p1[0, 1] == pytest.approx(r.load[0, 1], rel=1e-12)
    assert r.p1[0, 1] > 0


def test_cli_simulate_the_crane(tmp_path):
    """Two coordinates through the report: a curve per branch, per-branch columns and
    events with their coordinate, the divider's loss in the balance."""
    import pandas as pd
    from typer.testing import CliRunner

    from assur.views.cli import app
    from assur.views.report.simulation import FIGURES
    for lang, word in (("ru", "потери в делителе потока"),):
        out = tmp_path / lang
        r = CliRunner().invoke(app, ["simulate", str(io.bundled("crane_lv184a")), "-o",
                                     str(out), "--lang", lang, "--duration", "0.6"])
        assert r.exit_code == 0, r.output
        for name in FIGURES:
            assert (out / f"simulation_{name}.png").stat().st_size > 0
        df = pd.read_csv(out / "simulation.csv", sep=";", decimal=",", encoding="utf-8-sig")
        assert {"S1 [m]", "S2 [m]", "p1 S1 [MPa]", "p1 S2 [MPa]", "p_pump [MPa]",
                "Q_relief S2 [l/min]"} <= set(df.columns)
        np.testing.assert_allclose(df["p_pump [MPa]"],
                                   df[["p1 S1 [MPa]", "p1 S2 [MPa]"]].max(axis=1))
        summary = (out / "simulation_summary.csv").read_text(encoding="utf-8-sig")
        assert word in summary and "(S1)" in summary
        assert (out / "simulation.gif").stat().st_size > 0


def test_an_overrunning_load_is_reported(crane):
    """Started at rest near Φ1p0 with no pressure, the stick's load pulls its rod in:
    the fed chamber's pressure falls below zero, and the result says so."""
    r = simulate_model(crane, t_end=1.0, s0={"S2": 2.1}, p0=0.0,
                       t_eval=np.linspace(0.0, 1.0, 101))
    assert r.status == 0
    assert r.p1[:, 1].min() < 0
    assert "S2 falls to" in r.message and "overruns" in r.message
