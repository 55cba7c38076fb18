"""Crank-driven machines at the edges: [motion] (direction and speed), polar frame
points, parameters nothing uses, angle conventions of the tables, figures over a
crank angle (sorted, broken at a wrap, coinciding curves visible), ``--draw-at`` in
degrees, crank angles in degrees in messages."""

import math
import textwrap

import numpy as np
import pytest
from tests.helpers import examples as n_examples
from hypothesis import example, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from assur import AssemblyError, Mechanism, ModelError, examples, io
from assur.views.cli import app
from assur.errors import ModelWarning
from assur.core.motion import Motion
from assur.views.report import figures as F
from assur.views.report.tables import seed_tables, wrap_degrees

runner = CliRunner()

#: a four-bar driven by a crank, its fixed pivot placed by length and angle
BASE = """
[model]
name = "fourbar"
coordinates = ["q"]

[params]
r = "0.1 m"
c = "0.5 m"
k = "0.3 m"
d = "0.45 m"
a = "10 deg"
{extra_params}

[range]
q = {{ from = 0, to = 360, count = 25 }}

[frame]
O = [0, 0]
P = {{ origin = "O", length = "d", angle = "a" }}

[[groups]]
type = "crank"
name = "crank"
pivot = "O"
out = "A"
radius = "r"
q = "q"
links = ["1"]

[[groups]]
type = "dyad"
name = "II"
a = "A"
b = "P"
out = "B"
ra = "c"
rb = "k"
branch = 1
links = ["2", "3"]

[links]
"3" = ["P", "B"]

{extra}
"""


def load(extra="", extra_params=""):
    return io.loads(BASE.format(extra=extra, extra_params=extra_params), name="fourbar.toml")


def python_fourbar(**kw):
    return (Mechanism("fourbar", coordinates=("q",),
                      params=dict(r=0.1, c=0.5, k=0.3, d=0.45, a=math.radians(10)))
            .frame("O", 0, 0).frame("P", origin="O", length="d", angle="a")
            .crank("crank", pivot="O", out="A", radius="r", q="q", links=("1",))
            .dyad("II", a="A", b="P", out="B", ra="c", rb="k", branch=1, links=("2", "3"))
            .link("3", "P", "B"))


# ---- polar frame points --------------------------------------------------------------
def test_polar_frame_point_file_equals_python_and_follows_its_parameters():
    model = load()
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
    model = load(textwrap.dedent(f"""
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
    text = BASE.format(extra="", extra_params="").replace(
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
    model = load(extra_params='lx = "0.3 m"   # nothing uses it')
    assert len(model.warnings) == 1
    w = model.warnings[0]
    line = BASE.format(extra="", extra_params='lx = "0.3 m"   # nothing uses it') \
        .splitlines().index('lx = "0.3 m"   # nothing uses it') + 1
    assert w.startswith(f"fourbar.toml:{line}: params.lx: the parameter 'lx' is not used")
    assert load().warnings == ()
    # a parameter used only by a [[solve]] bracket or a formula is used
    m2 = load(textwrap.dedent("""
        [tables]
        [[tables.formulas]]
        name = "twice"
        expr = "2*lx"
        unit = "m"
        """), extra_params='lx = "0.3 m"')
    assert m2.warnings == ()


def test_unused_parameter_warning_as_python_warning_and_in_the_cli(tmp_path):
    f = tmp_path / "fourbar.toml"
    f.write_text(BASE.format(extra="", extra_params='lx = "0.3 m"'), encoding="utf-8")
    with pytest.warns(ModelWarning, match="params.lx"):
        io.load(f, warn=True)
    r = runner.invoke(app, ["check", str(f)])
    assert r.exit_code == 0, r.output
    assert "warning:" in r.output and "params.lx" in r.output


# ---- [motion] ---------------------------------------------------------------------------
def test_constant_speed_rates_and_times():
    m = Motion("q", "cw", speed=300 * 2 * math.pi / 60)
    q = np.radians([30.0, 0.0, -90.0])
    qd, qdd = m.rates(q)
    np.testing.assert_allclose(qd, -10 * math.pi)
    np.testing.assert_array_equal(qdd, 0.0)
    np.testing.assert_allclose(m.time(q), [0.0, math.radians(30) / (10 * math.pi),
                                           math.radians(120) / (10 * math.pi)])
    assert Motion("q").direction == 1 and Motion("q", -1).direction_name == "cw"


@settings(max_examples=n_examples(50), deadline=None)
@given(st.lists(st.floats(0.5, 50.0), min_size=2, max_size=6),
       st.lists(st.floats(0.05, 1.0), min_size=5, max_size=5),
       st.sampled_from([1, -1]))
@example([1.0, 1.0, 2.0], [0.25, 0.05, 0.05, 0.05, 0.05], 1)  # a sample 3e-17 s off a knot
def test_speed_table_integrates_exactly(omegas, dts, direction):
    """ω(t) linear between samples: q(t) is its exact integral. Checked against an
    independent sampling of t: q(t) by the trapezoid rule on a fine grid of each
    interval (exact for a linear ω), then rates(q(t)) must give ω(t), the slope,
    and time(q(t)) must give t back."""
    t = np.concatenate([[0.0], np.cumsum(dts[:len(omegas) - 1])])
    w = np.array(omegas)
    q0 = 0.3
    m = Motion("q", direction, t=t, omega=w, start=q0)
    ts = np.linspace(t[0], t[-1], 97)
    ws = np.interp(ts, t, w)
    # exact travel: cumulative integral of the piecewise-linear ω, knots included
    grid = np.union1d(ts, t)
    wg = np.interp(grid, t, w)
    sg = np.concatenate([[0.0], np.cumsum(0.5 * (wg[1:] + wg[:-1]) * np.diff(grid))])
    s = np.interp(ts, grid, sg)
    q = q0 + direction * s
    qd, qdd = m.rates(q)
    np.testing.assert_allclose(qd, direction * ws, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(m.time(q), ts, rtol=0, atol=1e-9 * max(1.0, t[-1]))
    slope = np.diff(w) / np.diff(t)
    inside = (ts > t[0]) & (ts < t[-1]) & ~np.isin(ts, t)
    k = np.searchsorted(t, ts[inside]) - 1
    np.testing.assert_allclose(qdd[inside], direction * slope[k], rtol=1e-12, atol=1e-12)
    # the derivative of the rate along the positions: qddot = qdot · d(qdot)/dq
    # (a central difference straddling a knot of the table sees the jump of the slope
    # there: keep the samples at least 10 h from every knot)
    h = 1e-6
    knots = q0 + direction * np.interp(t, grid, sg)
    away = inside & (np.min(np.abs(q[:, None] - knots[None, :]), axis=1) > 10 * h)
    mid = q[away]
    qd_p, _ = m.rates(mid + direction * h)
    qd_m, _ = m.rates(mid - direction * h)
    fd = qd[away] * (qd_p - qd_m) / (2 * direction * h)
    np.testing.assert_allclose(qdd[away], fd, rtol=1e-4, atol=1e-4 * np.max(np.abs(slope)))


def test_continuous_positions_along_the_rotation():
    """Seed 002's positions as it prints them (wrapped), made continuous clockwise."""
    printed = [14.679] + [344.679 - 30 * k for k in range(11)] + [188.229]
    got = np.degrees(Motion("j1", "cw").continuous(np.radians(printed)))
    want = [14.679 - 30 * k for k in range(12)] + [-315.321 - 216.45]
    np.testing.assert_allclose(got, want, atol=1e-9)
    assert np.all(np.diff(got) < 0)
    ccw = np.degrees(Motion("j1", "ccw").continuous(np.radians([350.0, 10.0, 5.0])))
    np.testing.assert_allclose(ccw, [350.0, 370.0, 725.0], atol=1e-9)


def test_speed_table_refuses_positions_beyond_its_travel_and_bad_tables():
    m = Motion("q", "ccw", t=(0.0, 1.0), omega=(1.0, 1.0))
    with pytest.raises(ModelError, match="outside that travel"):
        m.rates(np.array([0.0, 2.0]))
    with pytest.raises(ModelError, match="must be > 0"):
        Motion("q", t=(0, 1), omega=(1.0, 0.0))
    with pytest.raises(ModelError, match="increase strictly"):
        Motion("q", t=(0, 0), omega=(1.0, 1.0))
    with pytest.raises(ModelError, match="direction must be one of"):
        Motion("q", "clockwise")
    with pytest.raises(ModelError, match="gives only the direction"):
        Motion("q", "cw").rates([0.0])


def test_motion_section_in_a_file():
    model = load('[motion]\nq = { direction = "cw", speed = "300 rpm" }\n')
    mo = model.mechanism.motion("q")
    assert mo.direction == -1 and mo.speed == pytest.approx(10 * math.pi)
    qd, qdd = mo.rates(model.range)
    np.testing.assert_allclose(qd, -10 * math.pi)
    tab = load('[motion]\nq = { speed = { t = ["0 s", "0.5 s"], omega = ["10 rad/s", '
               '"20 rad/s"] } }\n').mechanism.motion("q")
    assert tab.direction == 1 and tab.t == (0.0, 0.5) and tab.omega == (10.0, 20.0)
    with pytest.raises(io.ModelFileError, match="expected an angular velocity"):
        load('[motion]\nq = { speed = "3 m" }\n')
    with pytest.raises(io.ModelFileError, match='unknown coordinate "s"'):
        load('[motion]\ns = { direction = "cw" }\n')
    with pytest.raises(io.ModelFileError, match="motion.q.direction"):
        load('[motion]\nq = { direction = "left" }\n')


def test_motion_in_the_python_builder_and_real_time_velocities():
    m = python_fourbar().with_motion("q", "cw", speed=2.0)
    assert m.motion().direction == -1
    q = np.radians(np.arange(0, 360, 30.0))
    kin = m.solve(q)
    qd, qdd = m.motion().rates(q)
    v = kin.velocity("B", qd)
    np.testing.assert_allclose(v[:, 0], kin.dx("B") * -2.0)
    assert m.with_params(r=0.11).motion() == m.motion()      # data, kept by copies
    # a length coordinate moves by extending or retracting, not turning (issue 10)
    with pytest.raises(ModelError, match=r"direction must be one of: \['extend', 'retract'\]"):
        (Mechanism("s", ("S",)).frame("O", 0, 0)
         .slider_input("in", origin="O", out="A", s="S").with_motion("S", "cw", 1.0))


# ---- tables and figures over a crank angle ----------------------------------------------
def test_wrap_degrees():
    np.testing.assert_allclose(wrap_degrees([-15.321, 360.0, 720.5, -1e-17, 0.0]),
                               [344.679, 0.0, 0.5, 0.0, 0.0], atol=1e-12)
    assert np.all(wrap_degrees(np.linspace(-1000, 1000, 999)) < 360)


def test_angle_columns_continuous_or_wrapped():
    model = load()
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
    x = np.asarray(lines[r"$\varphi_{\mathrm{3}}$"].get_xdata())
    assert np.all(np.diff(x) > 0)                       # sorted by the crank angle
    assert x.min() == pytest.approx(14.679) and x.max() == pytest.approx(344.679)
    # φ4 = φ3: drawn, dashed, labelled as equal
    l4 = next(ln for lab, ln in lines.items() if lab.startswith(r"$\varphi_{\mathrm{4}}$"))
    assert "=" in l4.get_label() and l4.get_linestyle() == "--"
    l3 = lines[r"$\varphi_{\mathrm{3}}$"]
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
    l9 = next(ln for ln in _lines(fig) if ln.get_label() == r"$\varphi_{\mathrm{9}}$")
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
