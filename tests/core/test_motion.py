"""The motion of a generalized coordinate (:mod:`assur.core.motion`): constant speeds
and speed tables (integrated exactly), continuous positions along a rotation, the
``[motion]`` section of a model file and the Python builder's ``with_motion``, and
their errors."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from assur import Mechanism, ModelError, io
from assur.core.motion import Motion
from tests.helpers import examples as n_examples
from tests.helpers.mechanisms import load_fourbar, python_fourbar


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
    model = load_fourbar('[motion]\nq = { direction = "cw", speed = "300 rpm" }\n')
    mo = model.mechanism.motion("q")
    assert mo.direction == -1 and mo.speed == pytest.approx(10 * math.pi)
    qd, qdd = mo.rates(model.range)
    np.testing.assert_allclose(qd, -10 * math.pi)
    tab = load_fourbar('[motion]\nq = { speed = { t = ["0 s", "0.5 s"], omega = ["10 rad/s", '
               '"20 rad/s"] } }\n').mechanism.motion("q")
    assert tab.direction == 1 and tab.t == (0.0, 0.5) and tab.omega == (10.0, 20.0)
    with pytest.raises(io.ModelFileError, match="expected an angular velocity"):
        load_fourbar('[motion]\nq = { speed = "3 m" }\n')
    with pytest.raises(io.ModelFileError, match='unknown coordinate "s"'):
        load_fourbar('[motion]\ns = { direction = "cw" }\n')
    with pytest.raises(io.ModelFileError, match="motion.q.direction"):
        load_fourbar('[motion]\nq = { direction = "left" }\n')



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

