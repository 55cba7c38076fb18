"""The crank dynamics in the whole pipeline (issue 9): ``add_dynamics`` from the model
file's ``[motion]`` and ``[dynamics]``, the tables 5.2 (reactions with inertia) and D
(reduced moment of inertia, reduced moments, driving moment, common centre of mass),
the dynamics figures and the report's summary — for the bundled cleaning ten-bar."""

import html
import re

import numpy as np
import pytest
from typer.testing import CliRunner

from assur import io
from assur.analysis import add_dynamics
from assur.views.cli import app
from assur.errors import ModelError
from assur.dynamics.crank import crank_dynamics
from assur.views.report import seed_tables
from assur.views.report.html import render_html


@pytest.fixture(scope="module")
def cleaning():
    model = io.load(io.bundled("cleaning_lab3"))
    a = model.mechanism.analyze(model.range)
    return model, add_dynamics(a, model.dynamics)


def test_speed_and_direction_come_from_the_motion_section(cleaning):
    model, a = cleaning
    mo = model.mechanism.motion("j1")
    assert mo.direction == -1 and mo.speed == pytest.approx(30.0)
    np.testing.assert_allclose(a.dynamics.qdot, -30.0)  # clockwise, as the seeds turn
    np.testing.assert_allclose(a.dynamics.qddot, 0.0)
    # the same as calling the dynamics by hand with those rates
    ref = crank_dynamics(a.kinematics, -30.0)
    np.testing.assert_array_equal(a.dynamics.driving_moment, ref.driving_moment)


def test_flywheel_and_balancing_follow_the_dynamics_section(cleaning):
    model, a = cleaning
    assert model.dynamics.delta == 0.05
    assert a.flywheel.delta == pytest.approx(0.05, rel=1e-9)
    assert a.flywheel.J_flywheel > 0
    assert a.balancing.after.amplitude_x < a.balancing.before.amplitude_x
    assert {m.link for m in a.balancing.masses} <= {"1", "3"}


def test_tables_5_2_and_d(cleaning):
    _, a = cleaning
    tabs = {t.id: t for t in seed_tables(a)}
    assert "5.2" in tabs and "D" in tabs
    d = tabs["D"]
    np.testing.assert_array_equal(d["J_red"], a.dynamics.reduced_inertia)
    np.testing.assert_array_equal(d["M_d"], -d["M_red"])
    np.testing.assert_allclose(d["M_red"], d["M_red_loads"] + d["M_red_inertia"], rtol=0,
                               atol=1e-9 * np.abs(d["M_red"]).max())
    np.testing.assert_array_equal(d["Xc"], a.dynamics.centre.x)
    assert d.column("omega_fw").unit == "rad/s"
    # 5.2 holds the reactions with inertia: they differ from the static ones of 5.1
    r51, r52 = tabs["5.1"]["R01"], tabs["5.2"]["R01"]
    assert np.abs(r52 - r51).max() > 100.0
    np.testing.assert_array_equal(r52, np.hypot(*a.dynamics.reaction("0", "1").T))


def test_report_summary_and_figures(cleaning):
    _, a = cleaning
    page = html.unescape(render_html(a, lang="ru", figures={}, animation=False))
    assert "Динамика (силы инерции, маховик, уравновешивание)" in page
    # in the file's units (lengths in mm), with the decimal comma
    assert re.search(r"маховик \(метод энергомасс\): δ = 0,05, J_м = [0-9,]+ кг·м²", page)
    assert re.search(r"общий центр масс [0-9,]+ кг: A_x = 3,\d{3} мм", page)
    en = html.unescape(render_html(a, lang="en", figures={}, animation=False))
    assert "Mertsalov" in en and "crank j1: mean |ω| = 30 rad/s" in en


def test_masses_without_a_speed_are_noted_not_guessed(cleaning):
    model, _ = cleaning
    mech = model.mechanism._with(motions=())
    a = add_dynamics(mech.analyze(model.range))
    assert a.dynamics is None
    assert any("no speed" in n for n in a.notes)
    with pytest.raises(ModelError, match=r"needs the speed of the crank j1.*\[motion\]"):
        add_dynamics(mech.analyze(model.range), model.dynamics)


def test_a_mechanism_without_masses_is_left_as_it_is():
    model = io.load(io.bundled("hitch_003"))
    a = add_dynamics(model.mechanism.analyze(model.range))
    assert a.dynamics is None and a.notes == []
    assert "5.2" not in {t.id for t in seed_tables(a)}


@pytest.mark.slow
def test_cli_analyze_writes_the_dynamics(tmp_path):
    r = CliRunner().invoke(app, ["analyze", str(io.bundled("cleaning_lab3")), "-o",
                                 str(tmp_path), "--format", "csv,png"])
    assert r.exit_code == 0, r.output
    names = {p.name for p in tmp_path.iterdir()}
    # the tables numbered by the report, named by what they hold (table_5_crank_dynamics.csv)
    held = {re.sub(r"^table_\d+_", "", n)[:-4] for n in names if n.endswith(".csv")}
    assert {"reactions_with_inertia", "crank_dynamics"} <= held, names
    for f in ("fig_centre_of_mass.png", "fig_hodographs.png", "fig_reduced_moment.png",
              "fig_reduced_inertia.png", "fig_energy_mass.png"):
        assert f in names, f
