"""Tables and maps of mechanisms of two generalized coordinates
(:mod:`assur.views.report.tables`, :mod:`assur.views.report.figures`): the grid and
paired paths of ``[range]``, the capacity map table G, maps over two coordinates (never
against a position index), ``assur check``'s grid shape, and the report of the bundled
loader (seed 001 lab 1)."""

import re

import numpy as np
import pytest
from typer.testing import CliRunner

from assur import io
from assur.views.cli import app
from assur.views.report import figures as F
from assur.views.report.tables import grid_of, seed_tables
from tests.helpers.reports import assert_csvs_clean

runner = CliRunner()
LOADER = io.bundled("loader_lab1")
PAIRED = f'''extends = "{LOADER}"

[model]
name = "loader_paired"

[range]
paired = true
S = {{ from = "Smin", to = "Smax", count = 7 }}
S1 = {{ from = "S1max", to = "S1min", count = 7 }}
'''


@pytest.fixture(scope="module")
def grid_analysis():
    m = io.load(LOADER)
    q = m.range
    return m.mechanism.analyze(q)


@pytest.fixture(scope="module")
def paired():
    return io.loads(PAIRED, name="paired.toml")


def test_grid_of_recognises_a_full_grid_only():
    u1, u2 = np.array([1.0, 2.0, 3.0]), np.array([0.5, 0.7])
    q1, q2 = (a.ravel() for a in np.meshgrid(u1, u2, indexing="ij"))
    got = grid_of(q1, q2)
    np.testing.assert_array_equal(got[0], u1)
    np.testing.assert_array_equal(got[1], u2)
    np.testing.assert_array_equal(u1[got[2]], q1)
    np.testing.assert_array_equal(u2[got[3]], q2)
    assert grid_of(u1, np.array([0.5, 0.6, 0.7])) is None          # a path
    assert grid_of(q1[:-1], q2[:-1]) is None                       # a grid with a hole
    assert grid_of(np.r_[q1[:-1], q1[0]], np.r_[q2[:-1], q2[0]]) is None  # a repeat


def test_paired_paths_move_together(paired):
    """``[range] paired = true``: position i of S with position i of S1, shape (n, 2)."""
    assert paired.paired and paired.shape == (7,)
    np.testing.assert_allclose(paired.range[:, 0], paired.ranges["S"])
    np.testing.assert_allclose(paired.range[:, 1], paired.ranges["S1"])
    assert paired.ranges["S1"][0] > paired.ranges["S1"][-1]  # S1 retracts as S extends
    a = paired.mechanism.analyze(paired.range)
    assert a.kinematics.n == 7
    t21 = seed_tables(a)[0]
    assert any("move together" in n["en"] for n in t21.notes)


@pytest.mark.parametrize("bad, match", [
    ("paired = 1", r"range.paired: expected true or false, found 1"),
    ('paired = true\nS = { from = "Smin", to = "Smax", count = 5 }',
     r"range.paired: paired paths need the same number of positions for every coordinate, "
     r"found S: 5, S1: 7"),
])
def test_paired_paths_errors(bad, match):
    text = PAIRED.replace('paired = true\nS = { from = "Smin", to = "Smax", count = 7 }', bad)
    with pytest.raises(io.ModelFileError, match=match) as e:
        io.loads(text, name="paired.toml")
    assert e.value.line is not None


def test_paired_needs_two_coordinates():
    text = io.bundled("hitch_003").read_text().replace(
        "[range]\n", "[range]\npaired = true\n")
    with pytest.raises(io.ModelFileError, match="paired paths need two or more coordinates"):
        io.loads(text, name="hitch.toml", source=io.bundled("hitch_003"))


def test_maps_have_the_coordinates_on_their_axes(grid_analysis):
    """Every diagram over the grid (S, S1) is a set of maps: x the first coordinate,
    y the second, in their units; no axis is a position index. The panels share
    their axes: the names (and tick values) are printed on the bottom row and the
    left column only, every other panel sharing both axes with a named one."""
    figs = F.figures(grid_analysis, "en")
    assert {"angles", "analogs", "transmission", "capacity", "force", "pressure",
            "reactions", "stability"} <= set(figs)
    for name, fig in figs.items():
        if name == "hodograph":
            continue
        maps = [ax for ax in fig.axes if ax.get_label() != "<colorbar>"]
        assert maps, name
        assert {ax.get_xlabel() for ax in maps} <= {"S [m]", ""}, name
        assert {ax.get_ylabel() for ax in maps} <= {"S1 [m]", ""}, name
        assert maps[-1].get_xlabel() == "S [m]" and maps[0].get_ylabel() == "S1 [m]", name
        for ax in maps:
            if ax.get_xlabel() == "":  # a panel below it, sharing the axis, names it
                assert not ax.xaxis.get_tick_params()["labelbottom"], name
                assert any(ax.get_shared_x_axes().joined(ax, b) for b in maps
                           if b.get_xlabel()), name
            if ax.get_ylabel() == "":
                assert not ax.yaxis.get_tick_params()["labelleft"], name
                assert any(ax.get_shared_y_axes().joined(ax, b) for b in maps
                           if b.get_ylabel()), name
    for fig in figs.values():
        for ax in fig.axes:
            assert "position" not in ax.get_xlabel().lower()
    # the capacity of the traverse cylinder is drawn only at the point it moves (S9)
    titles = [ax.get_title() for ax in figs["capacity"].axes if ax.get_title()]
    assert len([t for t in titles if "MPT" in t]) == 1 and "S9" in \
        [t for t in titles if "MPT" in t][0]
    # a map panel shows the values of its quantity over the grid
    ru = F.figures(grid_analysis, "ru", names=["stability"])["stability"]
    assert ru.axes[0].get_xlabel() == "S [м]"


def test_paired_paths_are_drawn_against_a_coordinate(paired):
    a = paired.mechanism.analyze(paired.range)
    fig = F.figures(a, "en", names=["capacity"])["capacity"]
    ax = fig.axes[0]
    assert ax.get_xlabel().startswith("cylinder length S [m]")
    assert "S1 moves with it" in ax.get_xlabel()
    x = ax.get_lines()[0].get_xdata()
    np.testing.assert_allclose(np.sort(np.asarray(x, float)), paired.ranges["S"])


def test_check_reports_the_grid_shape():
    r = runner.invoke(app, ["check", str(LOADER)])
    assert r.exit_code == 0, r.output
    m = io.load(LOADER)
    nS, nS1 = len(m.ranges["S"]), len(m.ranges["S1"])
    assert f"grid S × S1: {nS} × {nS1} = {nS * nS1} positions" in r.output
    assert f"({nS} positions)" in r.output and f"({nS1} positions)" in r.output


def test_check_reports_paired_paths(tmp_path):
    f = tmp_path / "paired.toml"
    f.write_text(PAIRED)
    r = runner.invoke(app, ["check", str(f)])
    assert r.exit_code == 0, r.output
    assert "paired paths S, S1: 7 positions" in r.output


def test_check_says_what_a_held_path_holds():
    r = runner.invoke(app, ["check", str(io.bundled("loader_lab1_level"))])
    assert r.exit_code == 0, r.output
    m = io.load(io.bundled("loader_lab1_level"))
    assert f"path along S, {len(m.range)} positions: S1 holds phi9 = 75 deg" in r.output


#: the bundled loader on a grid of 5 × 4 positions (its report's code, 20 frames of
#: animation instead of 104)
SMALL_GRID = f'''extends = "{LOADER}"

[range]
S = {{ from = "Smin", to = "Smax", count = 5 }}
S1 = {{ from = "S1min", to = "S1max", count = 4 }}
'''


@pytest.mark.slow
def test_analyze_writes_the_loader_report(tmp_path):
    """``assur analyze`` of the bundled loader over a grid of 5 × 4 writes its Russian
    report (maps, an animation of every position) and tables — no CSV holds NaN, inf or
    -0.0, nor a header twice (the checks of every bundled report,
    tests/models/test_models.py, which writes the loader's CSV tables over its whole
    grid)."""
    small = tmp_path / "loader_small.toml"
    small.write_text(SMALL_GRID, encoding="utf-8")
    # the whole grid's CSV files and workbook in every unit system and language:
    # tests/models/test_models_documents.py
    for lang, model, fmts in (("ru", small, "csv,html"),):
        out = tmp_path / lang
        r = runner.invoke(app, ["analyze", str(model), "-o", str(out), "--lang", lang,
                                "--format", fmts])
        assert r.exit_code == 0, r.output
        assert (out / "report.html").stat().st_size > 0
        csvs = assert_csvs_clean(out, f"loader_lab1 ({lang})", lang)
        # numbered by the report, named by what they hold (table_4_cylinders.csv)
        held = {re.sub(r"^table_\d+_", "", p.name)[:-4] for p in csvs}
        assert held >= {"link_angles", "analogs", "cylinders", "reactions", "axle_loads"}
    html = (tmp_path / "ru" / "report.html").read_text()
    assert "карта по S и S1" in html
    assert re.search(r"S = [0-9,]+ м, S1 = [0-9,]+ м", html)  # positions in Russian units


def test_capacity_map_table_g(grid_analysis):
    """Table G arranges each capacity of table 4.1 as the map G(S, S1): a row per S, a
    column per value of S1 — the same numbers."""
    tabs = {t.id: t for t in seed_tables(grid_analysis)}
    t41, tg = tabs["4.1"], tabs["G"]
    S, S1 = t41["S"], t41["S1"]
    uS, uS1 = np.unique(S), np.unique(S1)
    np.testing.assert_array_equal(tg["S"], uS)
    for sym in ("G09_S", "GS9_S", "GS9_S1"):
        for val in uS1:
            col = tg[f"{sym}@S1={val:.6g}"]
            want = t41[sym][S1 == val][np.argsort(S[S1 == val])]
            np.testing.assert_array_equal(col, want)
    assert not any(s.startswith("G09_S1") for s in tg.symbols)  # S1 does not lift 09
    assert tg.title("ru").startswith("Карты грузоподъёмности")


def test_no_map_table_for_paired_paths(paired):
    a = paired.mechanism.analyze(paired.range)
    assert "G" not in [t.id for t in seed_tables(a)]




def test_a_cranks_velocities_and_accelerations_are_the_time_derivatives_at_its_speed():
    """Table V (issue 24): ω, ε of each link and |v|, |a| of each point at the crank's
    speed of [motion] (cleaning_lab3: 30 rad/s clockwise), against central differences
    of the positions in time (q = q0 + q̇·t)."""
    import numpy as np

    from assur import io
    from assur.views.report.tables import seed_tables
    model = io.load(io.bundled("cleaning_lab3"))
    a = model.mechanism.analyze(np.radians([10.0, 100.0, 250.0]))
    from assur.analysis import add_dynamics
    import dataclasses
    add_dynamics(a, dataclasses.replace(model.dynamics, counter_masses=(), delta=None,
                                        flywheel=None))  # three positions: no flywheel
    t = {tab.id: tab for tab in seed_tables(a)}["V"]
    qd = float(np.ravel(a.dynamics.qdot)[0])
    assert qd == pytest.approx(-30.0)                      # [rad/s], clockwise
    assert np.allclose(np.ravel(a.dynamics.qddot), 0.0)    # a steady turn
    dt = 1e-5                                              # [s]
    q = np.radians([10.0, 100.0, 250.0])
    k = [model.mechanism.solve(q + s * qd * dt) for s in (-1, 0, 1)]
    for link in k[1].links:
        phi = [np.unwrap(np.array([np.ravel(r.phi(link)) for r in k]), axis=0)[i] for i in range(3)]
        w = (phi[2] - phi[0]) / (2 * dt)
        e = (phi[2] - 2 * phi[1] + phi[0]) / dt ** 2
        assert np.allclose(t[f"omega{link}"], w, rtol=1e-6, atol=1e-6)
        assert np.allclose(t[f"eps{link}"], e, rtol=1e-3, atol=1e-1)
    for p in ("A", "S6", "C6"):
        xy = [np.stack([np.ravel(r.x(p)), np.ravel(r.y(p))]) for r in k]
        v = np.hypot(*((xy[2] - xy[0]) / (2 * dt)))
        acc = np.hypot(*((xy[2] - 2 * xy[1] + xy[0]) / dt ** 2))
        assert np.allclose(t[f"v{p}"], v, rtol=1e-6)
        assert np.allclose(t[f"a{p}"], acc, rtol=1e-3)
    assert t["vA"] == pytest.approx(30.0 * 0.040)          # ω·L1, L1 = 40 mm [m/s]


def test_a_held_path_tabulates_its_analogs_along_the_path():
    """Table 3.1 of the self-levelling loader: beside the partial analogs, those along
    the path — dY/dS = ∂Y/∂S + ∂Y/∂S1·S1' with S1' = −(∂φ9/∂S)/(∂φ9/∂S1) from the
    table's own partial columns; the held φ9 stands still and the levelled traverse
    translates (dY_S9/dS = dY_09/dS)."""
    from assur.views.report.tables import seed_tables

    a = io.load(io.bundled("loader_lab1_level")).analyze()
    t = next(t for t in seed_tables(a) if t.id == "3.1")
    col = {c.symbol: np.asarray(c.values, float) for c in t.columns}
    s1 = -col["dphi9_S"] / col["dphi9_S1"]
    np.testing.assert_allclose(col["IS9_path"], col["IS9_S"] + col["IS9_S1"] * s1,
                               rtol=1e-9)
    np.testing.assert_allclose(col["dphi9_path"], 0.0, atol=1e-9)
    np.testing.assert_allclose(col["IS9_path"], col["I09_path"], rtol=1e-9)
    label = next(c.label for c in t.columns if c.symbol == "IS9_path")
    assert label["en"].endswith("along the held path (S1: phi9 = 75 deg)")
