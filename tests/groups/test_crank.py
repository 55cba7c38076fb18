"""Crank-driven machines (:mod:`assur.groups.crank`) at the edges: polar frame points,
parameters nothing uses, angle conventions of the tables, figures over a crank angle
(sorted, broken at a wrap, coinciding curves visible), ``--draw-at`` in degrees, crank
angles in degrees in messages. (The ``[motion]`` of a crank: tests/core/test_motion.py.)"""

import math
import textwrap

import numpy as np
import pytest
from typer.testing import CliRunner

from assur import AssemblyError, ModelError, examples, io
from assur.views.cli import app
from assur.errors import ModelWarning
from assur.views.report import figures as F
from assur.views.report.tables import seed_tables, wrap_degrees
from tests.helpers.mechanisms import FOURBAR, load_fourbar, python_fourbar

runner = CliRunner()


# ---- polar frame points --------------------------------------------------------------
def test_polar_frame_point_file_equals_python_and_follows_its_parameters():
    model = load_fourbar()
    m = python_fourbar()
    q = model.range
    a, b = model.mechanism.solve(q), m.solve(q)
    for p in ("A", "B", "P"):
        np.testing.assert_array_equal(a.x(p), b.x(p))
        np.testing.assert_array_equal(a.y(p), b.y(p))
    np.testing.assert_allclose([b.x("P")[0], b.y("P")[0]],
                               [0.45 * math.cos(math.radians(10)),
                                0.45 * math.sin(math.radians(10))], atol=1e-15)
    # evaluated per design, like any parameter: a batch of lengths and angles
    d = np.array([0.45, 0.5, 0.55])
    ang = np.radians([10.0, -20.0, 35.0])
    batch = m.solve(q, params={"d": d, "a": ang})
    np.testing.assert_allclose(batch.x("P")[:, 0], d * np.cos(ang), atol=1e-15)
    np.testing.assert_allclose(batch.y("P")[:, 5], d * np.sin(ang), atol=1e-15)
    assert np.max(batch.closure_residual()) <= 1e-12
    # the plain-numpy reference (used for complex step) places it the same way
    ref = m.evaluate_positions({"q": q})
    np.testing.assert_allclose(ref["B"][0], b.x("B"), atol=1e-12)


def test_polar_frame_point_can_be_solved_by_a_condition():
    """The length of a polar point is solved like any parameter ([[solve]])."""
    target = 0.5
    model = load_fourbar(textwrap.dedent(f"""
        [[solve]]
        unknown = "d"
        bracket = ["0.4 m", "0.6 m"]
        at = {{ q = 0 }}
        quantity = "XP"
        equals = "{target} m"
        """))
    d = model.mechanism.params["d"]
    assert d * math.cos(math.radians(10)) == pytest.approx(target, abs=1e-9)


@pytest.mark.parametrize("frame, problem", [
    ('P = { origin = "Q", length = "d", angle = "a" }', 'unknown frame point "Q"'),
    ('P = { origin = "O", length = "d" }', "needs origin, length and angle; missing angle"),
    ('P = { origin = "O", length = "d", angle = "a", x = 1 }', 'unknown key "x"'),
    ('P = { origin = "O", length = "-0.4 m", angle = "a" }', "expected a positive length"),
    ('P = { origin = "O", length = "d", angle = "0.4 m" }', "expected an angle"),
])
def test_polar_frame_point_errors_name_the_key_and_line(frame, problem):
    text = FOURBAR.format(extra="", extra_params="").replace(
        'P = { origin = "O", length = "d", angle = "a" }', frame)
    with pytest.raises(io.ModelFileError) as e:
        io.loads(text, name="fourbar.toml")
    assert problem in str(e.value)
    line = text.splitlines().index(frame) + 1
    assert e.value.line == line and str(e.value).startswith(f"fourbar.toml:{line}: frame.P")


def test_polar_frame_point_needs_a_frame_origin():
    with pytest.raises(ModelError, match="not a frame point"):
        python_fourbar().frame("Z", origin="A", length=0.1, angle=0.0)
    with pytest.raises(ModelError, match="either x and y, or origin"):
        python_fourbar().frame("Z", 0.0, 1.0, origin="O", length=0.1, angle=0.0)


# ---- parameters nothing uses ------------------------------------------------------------
def test_unused_parameter_warning_names_the_key_and_line():
    model = load_fourbar(extra_params='lx = "0.3 m"   # nothing uses it')
    assert len(model.warnings) == 1
    w = model.warnings[0]
    line = FOURBAR.format(extra="", extra_params='lx = "0.3 m"   # nothing uses it') \
        .splitlines().index('lx = "0.3 m"   # nothing uses it') + 1
    assert w.startswith(f"fourbar.toml:{line}: params.lx: the parameter 'lx' is not used")
    assert load_fourbar().warnings == ()
    # a parameter used only by a [[solve]] bracket or a formula is used
    m2 = load_fourbar(textwrap.dedent("""
        [tables]
        [[tables.formulas]]
        name = "twice"
        expr = "2*lx"
        unit = "m"
        """), extra_params='lx = "0.3 m"')
    assert m2.warnings == ()


def test_unused_parameter_warning_as_python_warning_and_in_the_cli(tmp_path):
    f = tmp_path / "fourbar.toml"
    f.write_text(FOURBAR.format(extra="", extra_params='lx = "0.3 m"'), encoding="utf-8")
    with pytest.warns(ModelWarning, match="params.lx"):
        io.load(f, warn=True)
    r = runner.invoke(app, ["check", str(f)])
    assert r.exit_code == 0, r.output
    assert "warning:" in r.output and "params.lx" in r.output


# ---- tables and figures over a crank angle ----------------------------------------------
def test_wrap_degrees():
    np.testing.assert_allclose(wrap_degrees([-15.321, 360.0, 720.5, -1e-17, 0.0]),
                               [344.679, 0.0, 0.5, 0.0, 0.0], atol=1e-12)
    assert np.all(wrap_degrees(np.linspace(-1000, 1000, 999)) < 360)


def test_angle_columns_continuous_or_wrapped():
    model = load_fourbar()
    a = model.mechanism.analyze(model.range)
    cont = seed_tables(a)[0]
    wrap = seed_tables(a, angles="wrapped")[0]
    np.testing.assert_allclose(cont["q"], np.linspace(0, 360, 25))
    assert wrap["q"][-1] == 0.0 and wrap["q"][0] == 0.0
    np.testing.assert_allclose(np.mod(cont["phi3"], 360), wrap["phi3"], atol=1e-9)
    assert any("wrapped" in n["en"] for n in wrap.notes) and not cont.notes
    with pytest.raises(ValueError, match="angles must be one of"):
        seed_tables(a, angles="radians")


def test_figure_helpers_sort_and_break():
    x = np.array([14.679, 344.679, 314.679, 188.229])
    assert list(F.plot_order(x)) == [0, 3, 2, 1]
    y = np.array([350.0, 355.0, 2.0, 8.0])
    assert list(F.wrap_breaks(y)) == [1]
    xs, ys = F.broken(np.arange(4.0), y, [1])
    assert xs.mask.tolist() == [False, False, True, False, False]
    assert ys.compressed().tolist() == y.tolist()


def _lines(fig):
    return [ln for ax in fig.axes for ln in ax.get_lines()]


def test_angle_figure_sorted_no_line_across_a_wrap_and_equal_links_visible():
    m = examples.combine_002()
    a = m.analyze(examples.combine_002_range())
    fig = F.angles(a)
    lines = {ln.get_label(): ln for ln in _lines(fig)}
    x = np.asarray(lines["φ₃"].get_xdata())
    assert np.all(np.diff(x) > 0)                       # sorted by the crank angle
    assert x.min() == pytest.approx(14.679) and x.max() == pytest.approx(344.679)
    # φ4 = φ3: drawn, dashed, labelled as equal
    l4 = next(ln for lab, ln in lines.items() if lab.startswith("φ₄"))
    assert "=" in l4.get_label() and l4.get_linestyle() == "--"
    l3 = lines["φ₃"]
    assert l3.get_linestyle() == "-" and l4.get_marker() != l3.get_marker()
    # the named distances l7, l9 have a figure of their own, sorted the same way
    figs = F.figures(a)
    assert "distances" in figs
    d = {ln.get_label(): ln for ln in _lines(figs["distances"])}
    order = np.argsort(np.mod(np.degrees(a.kinematics.q()), 360))
    np.testing.assert_allclose(d["l7"].get_ydata(), a.kinematics.length("l7")[order])
    # the full turn, wrapped: φ9 passes 360° → 0°, and no segment spans the wrap
    t = io.load(io.bundled("combine_002_turn"))
    fig = F.angles(t.mechanism.analyze(t.range))
    for ln in _lines(fig):
        y = np.ma.masked_invalid(np.ma.asarray(ln.get_ydata()))
        for seg in np.ma.clump_unmasked(y):
            assert np.all(np.abs(np.diff(y[seg])) < 180.0), ln.get_label()
    l9 = next(ln for ln in _lines(fig) if ln.get_label() == "φ₉")
    assert np.ma.count_masked(np.ma.asarray(l9.get_ydata())) >= 1


# ---- the command line and messages in degrees ---------------------------------------------
def test_check_summary_in_degrees():
    r = runner.invoke(app, ["check", str(io.bundled("combine_002"))])
    assert r.exit_code == 0, r.output
    out = " ".join(r.output.split())
    assert "14.679° … -171.771°" in out and "13 positions" in out
    assert "j1: cw" in out


def test_draw_at_in_degrees(tmp_path):
    out = tmp_path / "r"
    r = runner.invoke(app, ["analyze", str(io.bundled("combine_002")), "-o", str(out),
                            "--format", "png", "--draw-at", "14.679,188.229"])
    assert r.exit_code == 0, r.output
    assert (out / "mechanism.png").exists()
    from assur.views.cli import _positions
    a = examples.combine_002().analyze(examples.combine_002_range())
    assert _positions(a, "188.229,344.679°,-15.321") == [12, 1, 1]
    r = runner.invoke(app, ["analyze", str(io.bundled("hitch_003")), "-o", str(out),
                            "--format", "png", "--draw-at", "0.9"])
    assert r.exit_code == 1 and "outside the range" in r.output


def test_draw_at_refuses_angles_far_from_every_position(tmp_path):
    t = io.load(io.bundled("combine_002_turn"))
    m = t.mechanism
    a = m.analyze(np.radians(np.linspace(0, 40, 5)))
    import typer

    from assur.views.cli import _positions
    assert _positions(a, "20") == [2]
    with pytest.raises(typer.Exit):
        _positions(a, "200")


def test_failure_messages_give_crank_angles_in_degrees():
    m = python_fourbar().with_params(c=0.05)
    with pytest.raises(AssemblyError) as e:
        m.solve(np.radians([120.0, 150.0]))
    assert "q = 120°" in str(e.value) and "(q = 120°…150°)" in str(e.value)
