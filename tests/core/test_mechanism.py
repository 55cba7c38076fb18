"""Behaviour of the engine beyond the seed tables: errors that name what failed,
dead points, continuity between positions, singular ratios, k = 2 coordinates,
batches, real-time quantities."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from assur import AssemblyError, Mechanism, ModelError, SingularPositionError, examples


def lever(**p):
    params = dict(L3=0.2)
    params.update(p)
    return (Mechanism("lever", coordinates=("S",), params=params)
            .frame("01", 0.415, 0.563).frame("03", 0.25, 1.112)
            .cylinder_lever("I", base="01", pivot="03", out="23", lever="L3", s="S",
                            branch=-1, links=("2", "3"))
            .link("3", "03", "23").link("2", "01", "23"))


def crank_dyad(ra=2.65, rb=0.6):
    """Crank r = 1 about the origin, dyad from the crank tip to the frame point (0, 3)."""
    return (Mechanism("crank-dyad", coordinates=("q",), params=dict(ra=ra, rb=rb))
            .frame("O", 0.0, 0.0).frame("B", 0.0, 3.0)
            .crank("crank", pivot="O", out="A", radius=1.0, q="q", links=("1",))
            .dyad("II", a="A", b="B", out="C", ra="ra", rb="rb", branch=1, links=("2", "3"))
            .link("1", "O", "A").link("2", "A", "C").link("3", "B", "C"))


# ---- model errors ---------------------------------------------------------------------
@pytest.mark.parametrize("build,fragment", [
    (lambda: Mechanism("x").frame("O", 0, 0).dyad("d", a="O", b="P", out="C", ra=1, rb=1),
     "needs point 'P'"),
    (lambda: Mechanism("x").frame("O", 0, 0).frame("O", 1, 0), "defined twice"),
    (lambda: Mechanism("x").frame("O", 0, 0).frame("P", 1, 0)
     .dyad("d", a="O", b="P", out="C", ra="La", rb=1), "'La', which is neither a parameter"),
    (lambda: Mechanism("x").frame("O", 0, 0).frame("P", 1, 0)
     .dyad("d", a="O", b="P", out="C", ra=1, rb=1, branch=0), "branch must be +1 or -1"),
    (lambda: Mechanism("x").frame("O", 0, 0).crank("c", pivot="O", out="A", radius=1,
                                                    q="phi"), "not a generalized coordinate"),
    (lambda: Mechanism("x").frame("O", 0, 0).link("1", "O", "Z"), "unknown point 'Z'"),
    (lambda: Mechanism("x", params={"L": float("nan")}), "finite"),
    (lambda: Mechanism("x", coordinates=()), "at least one generalized coordinate"),
    (lambda: lever().with_params(L9=1.0), "unknown parameter(s) ['L9']"),
])
def test_model_errors_say_what_is_wrong(build, fragment):
    with pytest.raises(ModelError) as exc:
        build()
    assert fragment in str(exc.value)


def test_unknown_output_is_named():
    with pytest.raises(ModelError, match="unknown outputs \\['99'\\]"):
        lever().solve([0.5], outputs=["99"])


# ---- assembly failures -------------------------------------------------------------------
def test_cylinder_too_long_names_group_links_values_and_first_position():
    s = np.linspace(0.5, 0.9, 9)
    with pytest.raises(AssemblyError) as exc:
        lever().solve(s)
    e = exc.value
    L13 = math.hypot(0.415 - 0.25, 0.563 - 1.112)
    assert e.group == "I" and e.links == ("2", "3")
    assert e.coordinate["S"] == pytest.approx(0.8)  # first S with S > L13 + L3 = 0.7733
    msg = str(e)
    assert "cylinder–lever group 'I' (links 2, 3)" in msg
    assert "the distance |01–03| = 0.573259 m is less than |S − L3|" in msg
    assert e.amount == pytest.approx(0.8 - 0.2 - L13)
    assert "3 of 9 positions fail (S = 0.8…0.9)" in msg


def test_cylinder_too_short():
    with pytest.raises(AssemblyError, match=r"exceeds S \+ L3 = 0\.3 \+ 0\.2 = 0\.5 m by 73\.3 mm"):
        lever().solve([0.3, 0.5])


def test_dead_point_is_an_error_not_an_infinite_analog():
    L13 = math.hypot(0.415 - 0.25, 0.563 - 1.112)
    with pytest.raises(AssemblyError, match="dead point"):
        lever().solve([0.5, L13 + 0.2], check_continuity=False)


def test_continuity_between_positions_is_checked():
    """Both samples assemble but the dyad cannot between them (|A–B| drops below
    ra − rb for q in 1.32…1.82): the engine says so instead of jumping over."""
    m = crank_dyad()
    # q is a crank angle: the message gives it in degrees (2 rad = 114.592°)
    with pytest.raises(AssemblyError,
                       match="cannot move continuously from q = 0° to q = 114.592°") as e:
        m.solve([0.0, 2.0])
    assert e.value.group == "II"
    r = m.solve([0.0, 2.0], check_continuity=False)  # scattered positions: caller's choice
    assert r.ok.all()
    with pytest.raises(AssemblyError, match="less than"):
        m.solve(np.linspace(0, math.pi, 7))


def test_continuity_passes_on_a_fine_valid_range():
    r = examples.hitch_003().solve(np.linspace(0.42, 0.67, 2001))
    assert r.ok.all()


def test_report_mode_flags_failures_and_never_returns_nan():
    L4 = np.array([0.66, 0.3, 0.66])
    r = examples.hitch_003(L4=L4).solve(np.linspace(0.42, 0.67, 30), on_failure="report")
    assert r.ok.shape == (3, 30)
    assert r.ok[0].all() and r.ok[2].all() and not r.ok[1].all()
    assert r.failures and "RRR dyad 'II (4,5)'" in r.failures[0]
    for name in r.points:
        assert np.isfinite(r.x(name)).all() and np.isfinite(r.dx(name)).all()
    assert (r.x("45")[1][~r.ok[1]] == 0).all()


def test_batch_error_names_the_design():
    L4 = np.array([0.66, 0.3, 0.66])
    with pytest.raises(AssemblyError, match="of design 1.*1 of 3 designs fail") as exc:
        examples.hitch_003(L4=L4).solve(np.linspace(0.42, 0.67, 30))
    assert exc.value.design == 1


# ---- ratios and singularities ----------------------------------------------------------------
def test_singular_ratio_is_reported_not_divided():
    m = examples.hitch_003()
    s_star = brentq(lambda s: m.solve([s]).dphi("4")[0], 0.42, 0.448, xtol=1e-15)
    s = np.array([0.42, s_star, 0.5])
    r = m.solve(s, check_continuity=False)
    with pytest.raises(SingularPositionError, match="U24"):
        r.ratio("2", "4")
    masked = r.ratio("2", "4", singular="mask")
    assert masked.mask.tolist() == [False, True, False]
    assert np.isfinite(masked.compressed()).all()


def test_ratio_derivative_matches_difference_quotient():
    m = examples.hitch_003()
    s = np.linspace(0.45, 0.65, 5)
    h = 1e-6
    r, rp, rm = m.solve(s), m.solve(s + h), m.solve(s - h)
    fd = (rp.ratio("6", "5") - rm.ratio("6", "5")) / (2 * h)
    assert np.allclose(r.dratio("6", "5"), fd, rtol=1e-7, atol=1e-8)


# ---- real time ---------------------------------------------------------------------------------
def test_velocity_and_acceleration_from_analogs():
    """v = X'·Ṡ, a = X'·S̈ + X''·Ṡ² for a motion S(t) = 0.5 + 0.05 sin t."""
    m = examples.hitch_003()
    t = np.linspace(0, 3, 7)
    s = 0.5 + 0.05 * np.sin(t)
    sd, sdd = 0.05 * np.cos(t), -0.05 * np.sin(t)
    r = m.solve(s, check_continuity=False)
    v = r.velocity("S6", sd)
    a = r.acceleration("S6", sd, sdd)
    h = 1e-5
    y = lambda tt: m.solve(0.5 + 0.05 * np.sin(tt), check_continuity=False).point("S6")
    assert np.allclose(v, (y(t + h) - y(t - h)) / (2 * h), atol=1e-8)
    assert np.allclose(a, (y(t + h) - 2 * y(t) + y(t - h)) / h**2, atol=2e-4)
    w = r.angular_velocity("6", sd)
    assert np.allclose(w, r.dphi("6") * sd)
    eps = r.angular_acceleration("6", sd, sdd)
    assert np.allclose(eps, r.dphi("6") * sdd + r.ddphi("6") * sd**2)


# ---- two coordinates --------------------------------------------------------------------------
def two_cylinders():
    """Lever turned by cylinder S; a second cylinder S2 from frame point 05 to a new
    joint C that also hangs on the lever tip by a link of 0.5 m (k = 2)."""
    return (lever().frame("05", 1.0, 0.5)
            ._with(coordinates=("S", "S2"))
            .dyad("II", a="05", b="23", out="C", ra="S2", rb=0.5, branch=1, links=("4", "5"))
            .link("5", "23", "C").distance("LC", "03", "C"))


def test_two_coordinates_shapes_and_symmetry():
    m = two_cylinders()
    q = np.array([[0.5, 0.8], [0.55, 0.85], [0.6, 0.9]])
    r = m.solve(q)
    assert r.shape == (3,)
    assert r.dphi("5").shape == (3, 2) and r.ddphi("5").shape == (3, 2, 2)
    assert r.dphi("5", wrt="S2").shape == (3,)
    H = r.ddx("C")
    assert np.array_equal(H, np.swapaxes(H, -1, -2))
    # φ3 does not depend on S2
    assert np.all(r.dphi("3")[:, 1] == 0)
    f = r.to_frame()
    assert {"dphi5_S", "dphi5_S2", "ddphi5_S2", "LC", "dLC_S2"} <= set(f.columns)


def test_two_coordinates_jacobian_against_differences():
    m = two_cylinders()
    q = np.array([[0.52, 0.82], [0.58, 0.88]])
    r = m.solve(q)
    h = 1e-6
    for j in range(2):
        dq = np.zeros(2)
        dq[j] = h
        fd = (m.solve(q + dq).phi("5") - m.solve(q - dq).phi("5")) / (2 * h)
        assert np.allclose(r.dphi("5")[:, j], fd, rtol=1e-7, atol=1e-9)


def test_transmission_angle_of_a_dyad():
    r = examples.hitch_003().solve(examples.hitch_003_range())
    mu = r.transmission_angle("II (4,5)", degrees=True)
    # angle between links 4 and 5 at joint 45: |φ4 − φ5| folded into [0, 180]
    d = np.abs(r.phi("4", True) - r.phi("5", True)) % 360
    assert np.allclose(mu, np.minimum(d, 360 - d))


def test_coordinates_must_be_real_finite_numbers():
    m = examples.hitch_003()
    with pytest.raises(ModelError, match="must be real"):
        m.solve(np.array([0.5 + 1e-3j]))
    with pytest.raises(ModelError, match="not finite"):
        m.solve([0.5, np.nan])
    with pytest.raises(ModelError, match="must be numbers"):
        m.solve(["half a metre"])


def test_reactions_of_links_without_a_joint_name_the_joints():
    """``reaction`` and ``reaction_moment`` both say which joints there are (the moment
    raised a bare ``KeyError(('2', '6'))``)."""
    st = examples.hitch_003().analyze([0.42]).statics
    for f in (st.reaction, st.reaction_moment):
        with pytest.raises(KeyError, match=r"links '6' and '2' share no joint; joints: .*'5', '6'"):
            f("6", "2")
