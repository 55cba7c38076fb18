"""The bundled compact wheel loader (``frontloader_zbar.toml``, illustrative
dimensions): a boom on two lift cylinders (S, one cylinder with count = 2) and a Z-bar
tilt linkage (tilt cylinder S1 → bell crank on the boom → link → bucket), the tilt
cylinder held over the lift so that the bucket's floor stays level.

Checked here: the machine's shape (hinge pin heights, the boom's swing, the bucket on
the ground at the bottom, strokes within the cylinders' limits and plausible for their
closed lengths), assembly and closure over the path, the self-levelling (the floor
level to 1e-10 rad along the file's path and along a denser one, the held S1 against
an independent root finder, dS1/dS against central differences), and the cylinders'
forces three ways: the statics' virtual work, the joint reactions solved group by
group, and a hand sum of the weights times their transmission numbers (DESIGN.md §4).
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from assur import io
from assur.core.held import hold_path

G = 9.81  # the file's gravity (the default) [m/s²]


@pytest.fixture(scope="module")
def model():
    return io.load(io.bundled("frontloader_zbar"))


@pytest.fixture(scope="module")
def kin(model):
    return model.mechanism.solve(model.range)


@pytest.fixture(scope="module")
def analysis(model):
    return model.mechanism.analyze(model.range)


def P(model, name):
    return float(model.mechanism.params[name])


def test_a_held_path_along_the_lift_cylinders(model):
    path = model.path
    assert list(model.mechanism.coordinates) == ["S", "S1"]
    assert path is not None and model.paired and path.along == "S"
    assert [(h.coordinate, h.quantity) for h in path.holds] == [("S1", "phibucket")]
    assert model.range.shape == (13, 2)
    np.testing.assert_allclose(path.s, np.linspace(P(model, "Smin"), P(model, "Smax"), 13),
                               rtol=0, atol=1e-15)
    assert path.residual < 1e-12


def test_the_machine_looks_like_a_wheel_loader(model, kin):
    """Boom down: the hinge pin about 0.33 m up and the bucket's floor on the ground
    (heel and cutting edge at one height, under 30 mm); full lift: the hinge pin near
    2.9 m; the boom swings about 73°; the cutting edge ahead of the front axle."""
    yH = kin.y("H")
    assert 0.30 < yH[0] < 0.36 and 2.85 < yH[-1] < 3.0
    assert np.all(np.diff(yH) > 0)
    swing = math.degrees(kin.phi("boom")[-1] - kin.phi("boom")[0])
    assert 70.0 < swing < 76.0
    assert abs(kin.y("F")[0] - kin.y("W")[0]) < 1e-9 and 0.0 < kin.y("W")[0] < 0.03
    assert np.all(kin.x("W") > 1.5)
    # the payload's centre of gravity is in the bucket: above the floor, behind the edge
    assert np.all(kin.y("G") > kin.y("W")) and np.all(kin.x("G") < kin.x("W"))


def test_strokes_within_the_cylinders_and_plausible(model):
    S1 = model.range[:, 1]
    lo, hi = P(model, "S1min"), P(model, "S1max")
    assert np.all((S1 > lo) & (S1 < hi))
    assert np.all(np.diff(S1) < 0)  # the tilt cylinder retracts while the boom rises
    for a, b in (("Smin", "Smax"), ("S1min", "S1max")):
        ratio = (P(model, b) - P(model, a)) / P(model, a)
        assert 0.5 <= ratio <= 0.7, (a, b, ratio)


def test_assembles_and_closes(kin):
    assert np.max(kin.closure_residual()) <= 1e-9


def test_the_bucket_floor_stays_level_along_the_path(model, kin):
    assert np.max(np.abs(kin.phi("bucket"))) < 1e-10
    # the same along a denser path, solved again by assur.core.held
    s = np.linspace(P(model, "Smin"), P(model, "Smax"), 61)
    dense = hold_path(model.mechanism, "S", s, model.path.holds)
    k = model.mechanism.solve(dense.q)
    assert np.max(np.abs(k.phi("bucket"))) < 1e-10
    assert np.max(k.closure_residual()) <= 1e-9
    # with the tilt cylinder locked instead, the bucket rolls back as the boom rises
    # (over the first third of the lift: higher, the link and the bucket's lever would
    # come into line)
    low = s[:21]
    locked = model.mechanism.solve(np.column_stack([low, np.full_like(low, model.range[0, 1])]))
    assert np.all(np.diff(locked.phi("bucket")) > 0)
    assert math.degrees(locked.phi("bucket")[-1]) > 20.0


def _floor(mech, S, S1):
    return float(mech.solve(np.array([[S, S1]])).phi("bucket")[0])


def test_held_S1_against_an_independent_root_finder(model):
    """Brent's method on the floor's angle at each position of the path, bracketed
    ±30 mm about the held length (where the linkage assembles)."""
    mech = model.mechanism
    for S, S1 in model.range[::3]:
        root = brentq(lambda u: _floor(mech, S, u), S1 - 0.03, S1 + 0.03, xtol=1e-14)
        assert abs(root - S1) < 1e-10


def test_the_tilt_strokes_ends_roll_back_and_dump(model):
    """S1max rolls the bucket back about 40° at the ground, S1min dumps it about 45° at
    full lift."""
    q = np.array([[P(model, "Smin"), P(model, "S1max")], [P(model, "Smax"), P(model, "S1min")]])
    back, dump = np.degrees(model.mechanism.solve(q).phi("bucket"))
    assert 35.0 < back < 45.0 and -50.0 < dump < -40.0


def test_dS1_dS_against_central_differences(model):
    """The implicit-function rule (dS1/dS = −(∂φ/∂S)/(∂φ/∂S1)) against the held
    solution differenced over ±h."""
    h = 1e-5
    s = model.path.s[1:-1]
    plus = hold_path(model.mechanism, "S", s + h, model.path.holds).q[:, 1]
    minus = hold_path(model.mechanism, "S", s - h, model.path.holds).q[:, 1]
    np.testing.assert_allclose(model.path.dq[1:-1, 1], (plus - minus) / (2 * h),
                               rtol=0, atol=1e-7)
    # along the levelled path the payload rises as the hinge pin does (the bucket only
    # translates): dY_G/dS = dY_H/dS
    kin = model.mechanism.solve(model.range)
    np.testing.assert_allclose(model.path.transmission(kin, "G"),
                               model.path.transmission(kin, "H"), rtol=1e-10)


def test_forces_by_virtual_work_reactions_and_by_hand(model, analysis):
    """Both cylinders: the statics' virtual work equals the joint reactions solved group
    by group, and equals Σ W_i·∂Y_i/∂q summed here from the transmission numbers
    (masses at their centres, the payload at G; weights act downwards)."""
    st = analysis.statics
    kin = analysis.kinematics
    weights = [(P(model, "m_boom") * G, "Sk"), (P(model, "m_crank") * G, "K"),
               (P(model, "m_bucket") * G, "Sb"), (P(model, "P_load"), "G")]
    for q in ("S", "S1"):
        vw, rx = st.actuator_force(q), st.actuator_force_from_reactions(q)
        scale = np.max(np.abs(vw))
        np.testing.assert_allclose(rx, vw, rtol=0, atol=1e-9 * scale)
        hand = sum(W * kin.transmission(p, wrt=q) for W, p in weights)
        np.testing.assert_allclose(vw, hand, rtol=1e-12, atol=1e-9 * scale)
    assert np.max(np.abs(st.equilibrium_residual())) <= 1e-6


def test_lift_capacity_and_pressures(model, analysis):
    """The lift cylinders hold the payload below the relief pressure everywhere; their
    capacity at G carries the boom's and the crank's weights (dead loads) and is
    G = (F_max·η − F_dead)/I with I = ∂Y_G/∂S (the tilt cylinder locked)."""
    lift = analysis.cylinder("lift")
    p_relief = P(model, "p_relief")
    assert np.all(lift.pressure > 0) and np.all(lift.pressure < p_relief)
    area = math.pi / 4 * P(model, "D_lift") ** 2
    F_max = 2 * area * p_relief
    kin = analysis.kinematics
    F_dead = sum(m * G * kin.transmission(p, wrt="S")
                 for m, p in ((P(model, "m_boom"), "Sk"), (P(model, "m_crank"), "K")))
    expected = (F_max * P(model, "eta") - F_dead) / kin.transmission("G", wrt="S")
    np.testing.assert_allclose(lift.capacity("G"), expected, rtol=1e-12)
    assert np.all(lift.capacity("G") > P(model, "P_load"))


def test_ratings_tipping_load_by_hand(model):
    """The file's ratings (docs/ratings.md): the static tipping load at the farthest
    reach of G by moments about the front axle, summed here — the machine's weight
    behind it against the boom's, the crank's and the bucket's weights and the load
    ahead of it — and the rated operating capacity, half of it, at least the payload."""
    a = model.analyze()
    tipping, breakout, lift = a.ratings
    scalars = {s.symbol: float(s.values[0]) for s in tipping.scalars}
    kin = a.kinematics
    i = int(np.argmax(kin.x("G")))
    holding = P(model, "P_machine") * 1.25 - sum(
        P(model, m) * G * kin.x(p)[i] for m, p in (("m_boom", "Sk"), ("m_crank", "K"),
                                                   ("m_bucket", "Sb")))
    assert scalars["W_tip_static"] == pytest.approx(holding / kin.x("G")[i], rel=1e-10)
    assert scalars["ROC_rated"] == pytest.approx(0.5 * scalars["W_tip_static"], rel=1e-15)
    assert 2.2e3 * G < scalars["W_tip_static"] < 2.6e3 * G
    assert scalars["ROC_rated"] >= P(model, "P_load")
    # the lift chart's capacity never exceeds any of its limits
    G_all = np.asarray(lift["G"])
    for c in ("G_lift", "G_tilt", "G_stability"):
        assert np.all(G_all <= np.asarray(lift[c]) * (1 + 1e-12))
    assert np.all(np.asarray(breakout["F_lift"]) > 0)
