"""The bundled excavator front (``backhoe_arm.toml``, illustrative dimensions): boom
(cylinder S1), arm (cylinder S2) and the bucket through its four-bar (bucket cylinder
S3 → side link and guide link → bucket), three coordinates on a full grid.

Checked here: the grid of three coordinates, assembly and closure at every position,
each cylinder moving only its own part (the boom with S1, the arm relative to the boom
with S2, the bucket relative to the arm with S3), the machine's shape (digging depth,
reach, the bucket's turn, strokes within plausible limits, transmission angles of the
bucket linkage), the exact analogs against central differences, and the cylinders'
forces three ways: the statics' virtual work, the joint reactions solved group by
group, and a hand sum of the weights times their transmission numbers (DESIGN.md §4).
"""

import math

import numpy as np
import pytest

from assur import io

G = 9.81  # the file's gravity (the default) [m/s²]


@pytest.fixture(scope="module")
def model():
    return io.load(io.bundled("backhoe_arm"))


@pytest.fixture(scope="module")
def analysis(model):
    return model.mechanism.analyze(model.range)


def P(model, name):
    return float(model.mechanism.params[name])


def test_three_coordinates_on_a_full_grid(model):
    assert list(model.mechanism.coordinates) == ["S1", "S2", "S3"]
    assert model.shape == (5, 5, 5) and not model.paired and model.path is None
    assert model.range.shape == (125, 3)
    for j, c in enumerate(("S1", "S2", "S3")):
        np.testing.assert_array_equal(np.unique(model.range[:, j]), model.ranges[c])


def test_assembles_and_closes(analysis):
    assert np.max(analysis.kinematics.closure_residual()) <= 1e-9


def _rel(kin, a, b):
    """The angle of link a relative to link b [rad], wrapped to (−π, π]."""
    return np.angle(np.exp(1j * (kin.phi(a) - kin.phi(b))))


def test_each_cylinder_moves_its_own_part(model, analysis):
    """On the grid (S1 slowest): the boom's angle depends on S1 alone, the arm's angle
    relative to the boom on S2 alone, the bucket's relative to the arm on S3 alone."""
    kin = analysis.kinematics
    boom = kin.phi("boom").reshape(5, 5, 5)
    arm = _rel(kin, "arm", "boom").reshape(5, 5, 5)
    bucket = _rel(kin, "bucket", "arm").reshape(5, 5, 5)
    np.testing.assert_allclose(boom, boom[:, :1, :1] + 0 * boom, rtol=0, atol=1e-12)
    np.testing.assert_allclose(arm, arm[:1, :, :1] + 0 * arm, rtol=0, atol=1e-12)
    np.testing.assert_allclose(bucket, bucket[:1, :1, :] + 0 * bucket, rtol=0, atol=1e-12)
    # and the exact analogs say so: ∂φ_boom/∂S2 = ∂φ_boom/∂S3 = 0, ∂φ_bucket/∂S3 ≠ 0
    assert np.max(np.abs(kin.dphi("boom", wrt="S2"))) == 0.0
    assert np.max(np.abs(kin.dphi("boom", wrt="S3"))) == 0.0
    assert np.min(np.abs(kin.dphi("bucket", wrt="S3"))) > 0.5


def test_the_machine_looks_like_an_excavator(model):
    """Over a finer grid of the strokes: the tooth tip digs about 2.8 m below the
    ground and reaches about 6 m; the boom swings from about −34° to +44°; the bucket
    turns through about 137° relative to the arm; every stroke is 0.5–0.75 of its
    cylinder's closed length."""
    s = [np.linspace(P(model, f"{c}min"), P(model, f"{c}max"), 9) for c in ("S1", "S2", "S3")]
    q = np.stack(np.meshgrid(*s, indexing="ij"), axis=-1).reshape(-1, 3)
    kin = model.mechanism.solve(q)
    assert -3.0 < kin.y("tip").min() < -2.5
    assert 5.8 < np.hypot(kin.x("tip"), kin.y("tip")).max() < 6.5
    assert 3.5 < kin.y("tip").max() < 4.5
    boom = np.degrees(kin.phi("boom"))
    assert -36 < boom.min() < -32 and 42 < boom.max() < 46
    turn = np.degrees(np.ptp(np.unwrap(_rel(kin, "bucket", "arm"))))
    assert 130 < turn < 145
    for c in ("S1", "S2", "S3"):
        ratio = (P(model, f"{c}max") - P(model, f"{c}min")) / P(model, f"{c}min")
        assert 0.5 <= ratio <= 0.75, (c, ratio)


def test_bucket_linkage_transmission_angles(model):
    """Along the bucket cylinder's whole stroke the side link is driven at 25° or more
    from the cylinder's line, and the guide link meets the bucket's lever at 25° or
    more (the angles at J and K from the points, here)."""
    S3 = np.linspace(P(model, "S3min"), P(model, "S3max"), 101)
    q = np.column_stack([np.full_like(S3, 1.6), np.full_like(S3, 1.6), S3])
    kin = model.mechanism.solve(q)

    def angle(p, a, b):  # the angle at p between p→a and p→b [deg], folded to 0–90°
        u = np.stack([kin.x(a) - kin.x(p), kin.y(a) - kin.y(p)])
        v = np.stack([kin.x(b) - kin.x(p), kin.y(b) - kin.y(p)])
        s = np.abs(u[0] * v[1] - u[1] * v[0]) / np.hypot(*u) / np.hypot(*v)
        return np.degrees(np.arcsin(s))

    assert angle("J", "E", "N").min() >= 25.0
    assert angle("K", "J", "Q").min() >= 25.0


def test_analogs_against_central_differences(model):
    """The tooth tip's and the bucket's first analogs along each coordinate."""
    q0 = np.array([1.55, 1.62, 0.93])
    h = 1e-6
    kin = model.mechanism.solve(q0[None, :])
    for j, c in enumerate(("S1", "S2", "S3")):
        dq = np.zeros(3)
        dq[j] = h
        kp, km = (model.mechanism.solve((q0 + s * dq)[None, :]) for s in (1, -1))
        for f, name in ((lambda k: k.x("tip"), "dx"), (lambda k: k.y("tip"), "dy")):
            fd = (f(kp) - f(km)) / (2 * h)
            exact = getattr(kin, name)("tip", wrt=c)
            np.testing.assert_allclose(exact, fd, rtol=0, atol=1e-7)
        fd = (kp.phi("bucket") - km.phi("bucket")) / (2 * h)
        np.testing.assert_allclose(kin.dphi("bucket", wrt=c), fd, rtol=0, atol=1e-7)


def test_forces_by_virtual_work_reactions_and_by_hand(model, analysis):
    """All three cylinders at every position: the statics' virtual work equals the
    joint reactions solved group by group, and Σ W_i·∂Y_i/∂q summed here from the
    transmission numbers (the masses at their centres, the soil at the bucket's)."""
    st, kin = analysis.statics, analysis.kinematics
    weights = [(P(model, "m_boom") * G, "Sb"), (P(model, "m_arm") * G, "Sa"),
               (P(model, "m_bucket") * G + P(model, "P_soil"), "Sk")]
    for q in ("S1", "S2", "S3"):
        vw, rx = st.actuator_force(q), st.actuator_force_from_reactions(q)
        scale = np.max(np.abs(vw))
        np.testing.assert_allclose(rx, vw, rtol=0, atol=1e-9 * scale)
        hand = sum(W * kin.transmission(p, wrt=q) for W, p in weights)
        np.testing.assert_allclose(vw, hand, rtol=0, atol=1e-9 * scale)
    # the boom cylinder carries the front everywhere below the relief pressure
    boom = analysis.cylinder("boom")
    assert np.all(boom.pressure > 0) and np.all(boom.pressure < P(model, "p_relief"))


def test_a_cylinders_pressure_from_its_force(model, analysis):
    """Each cylinder declares the piston side (the default): p = F/(η·A_piston) at
    every position, computed here from the bores; a negative p is a pull the piston
    side cannot give (the report's verdicts say so)."""
    for name, c in (("boom", "S1"), ("arm", "S2"), ("bucket", "S3")):
        F = analysis.statics.actuator_force(c)
        area = math.pi / 4 * P(model, f"D_{name}") ** 2
        np.testing.assert_allclose(analysis.cylinder(name).pressure,
                                   F / (P(model, "eta") * area), rtol=1e-12)


def test_ratings_digging_force_by_hand(model):
    """The file's ISO 6015 rating (docs/ratings.md): the bucket cylinder's own digging
    force at the tooth tip is its force at the relief pressure over the tip's travel
    per unit stroke, F·η/|∂tip/∂S3| (the tip turns about Q: its tangent is along
    ∂tip/∂S3); the rated force is at most that; a 5–8 t excavator's 30–50 kN."""
    a = model.analyze()
    digging, chart = a.ratings
    kin = a.kinematics
    F = math.pi / 4 * P(model, "D_bucket") ** 2 * P(model, "p_relief") * P(model, "eta")
    travel = np.hypot(kin.dx("tip", wrt="S3"), kin.dy("tip", wrt="S3"))
    np.testing.assert_allclose(digging["F_B_bucket"], F / travel, rtol=1e-10)
    assert np.all(np.asarray(digging["F_B"]) <= np.asarray(digging["F_B_bucket"]) * (1 + 1e-12))
    assert 30e3 < np.max(digging["F_B_bucket"]) < 50e3
    assert 25e3 < np.max(digging["F_A_arm"]) < 45e3
    # the lift chart at the bucket pivot: reach from the swing axis
    np.testing.assert_allclose(chart["reach"], kin.x("Q"), rtol=0, atol=1e-12)
