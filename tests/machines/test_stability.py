"""Machine stability (``assur.machines.stability``): seed 003 §6 table 6.1, seed 001 lab 1
eqs. (15)–(18), the balance of forces and moments, limits and input checks.

Seed 003 (``003_b1551261b108abd1.txt``, §1.6 and §6): a = 0.6 m, b = 1.62 m,
L = 2.960 m, P_гр = 8000 N, P_мсха = 56000 N, P6 = 27500 N. Its moment equation
R_A·L = P_гр·(a + L) + P_мсха·b − P6·XS6 places the rear axle B at the origin of the
hitch frame, the steered front axle A at x = −L, the tractor at x = −b, the ballast
at x = −(a + L) and the implement at x = XS6(S).
"""

import math

import numpy as np
import pytest
from tests.helpers import examples as n_examples
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import examples
from assur.core.columns import formulas_of
from assur.machines.stability import Machine, axle_reactions

from tests.helpers.seed_tables import T003_6_1, assert_printed, table


A, B, L = 0.6, 1.62, 2.960            # seed 003 §1.6 [m]
P_GR, P_MSHA, P6 = 8000.0, 56000.0, 27500.0   # [N]


def seed003_machine():
    return Machine({"A": -L, "B": 0.0}, steered="A",
                   weights=[("tractor", P_MSHA, -B)],
                   counterweights=[("ballast", P_GR, -(A + L))])


@pytest.fixture(scope="module")
def xs6():
    s = examples.hitch_003_range()
    assert np.allclose(np.round(s, 3), table(T003_6_1)["S"])
    return examples.hitch_003().solve(s).x("S6")


@pytest.fixture(scope="module")
def seed003(xs6):
    return axle_reactions(seed003_machine(), P6, xs6)


def test_table_6_1_reactions_and_shares(seed003):
    """Seed 003, table 6.1: Ra, Rb [N] (printed to 1 N) and ΔRa, ΔRb [%] (to 0.1 %)
    from the general two-axle balance with the seed's geometry."""
    assert_printed(seed003.reaction("A"), T003_6_1, "Ra")
    assert_printed(seed003.reaction("B"), T003_6_1, "Rb")
    assert_printed(seed003.share("A"), T003_6_1, "dRa")
    assert_printed(seed003.share("B"), T003_6_1, "dRb")
    assert np.all(seed003.steerable)
    assert np.array_equal(seed003.steered_share, seed003.share("A"))


def test_table_6_1_to_frame(seed003, xs6):
    """Seed 003, table 6.1 as a frame: columns Ra, Rb, dRa, dRb like the seed."""
    f = seed003.to_frame(index=np.round(examples.hitch_003_range(), 3))
    assert list(f.columns[:5]) == ["Ra", "Rb", "dRa", "dRb", "G_max"]
    assert f.index.name == "S"
    for c in ["Ra", "Rb", "dRa", "dRb"]:
        assert_printed(f[c].to_numpy(), T003_6_1, c)


def seed003_gs6max(xs6):
    """Seed 003 §6 as printed: R_amin := 0.2·(P6 + P_мсха + P_гр),
    GS6max(S) := (P_мсха·b + P_гр·(a + L) − R_amin)/XS6(S) [its label: N]."""
    r_amin = 0.2 * (P6 + P_MSHA + P_GR)
    return (P_MSHA * B + P_GR * (A + L) - r_amin) / xs6


def test_table_6_1_gs6max_is_the_seeds_flagged_formula(xs6):
    """Seed 003, table 6.1, GS6max [N] (printed to 1 N): the seed's own formula,
    transcribed above, reproduces the print; the model file declares the same formula
    as an extra column of table 6.1 (``[[tables.formulas]]``) with flags saying it
    subtracts a force from a moment."""
    assert_printed(seed003_gs6max(xs6), T003_6_1, "GS6max")
    (f,) = formulas_of(examples.hitch_003())
    assert (f.name, f.table, f.unit, f.scale) == ("GS6max", "6.1", "N", 1.0)
    assert f.names == {"P_mcxa", "P_gr", "P6", "a", "b", "L"} and f.points == {"S6"}
    assert any("force" in x and "moment" in x for x in f.flags)
    assert any("max_implement_weight" in x for x in f.flags)


def test_table_6_1_correct_limit_beside_the_seeds(seed003, xs6):
    """Seed 003 §6: the correct limit (M0 − 0.2·L·W0)/(XS6 + 0.2·L) differs from the
    printed GS6max; at the correct limit the steered share is 20 % to 1e-9, at the
    seed's GS6max it is far below 20 %."""
    g_ok = seed003.max_implement_weight
    m0, w0 = P_MSHA * B + P_GR * (A + L), P_MSHA + P_GR
    np.testing.assert_allclose(g_ok, (m0 - 0.2 * L * w0) / (xs6 + 0.2 * L), rtol=1e-12)
    g_seed = seed003_gs6max(xs6)
    assert np.all(np.abs(g_ok - g_seed) > 10_000.0)            # 31075…34679 vs 49835…57569 N

    at_ok = axle_reactions(seed003_machine(), g_ok, xs6)
    np.testing.assert_allclose(at_ok.steered_share, 20.0, rtol=0, atol=1e-9)
    at_seed = axle_reactions(seed003_machine(), g_seed, xs6)
    assert np.all(np.abs(at_seed.steered_share - 20.0) > 10.0)  # ≈ 5 %
    assert not np.any(at_seed.steerable)

    # the ballast helps: without it the limit is (P_мсха·b − 0.2·L·P_мсха)/(XS6 + 0.2·L)
    g_bare = seed003.max_implement_weight_without_counterweights
    np.testing.assert_allclose(g_bare, P_MSHA * (B - 0.2 * L) / (xs6 + 0.2 * L), rtol=1e-12)
    assert np.all(g_bare < g_ok) and np.all(P6 < g_ok)


# --- seed 001, lab 1, eqs. (15)–(18) ------------------------------------------------

G = 9.81  # [m/s²]; the closed forms and the general limit use the same g


def lab1_machine(L, b, p_ues, x_gr=None, p_gr=0.0):
    """Seed 001 lab 1, eq. (15): R_B = (P_УЭС·(L − b) − P_po·(X_S9max − L))/L, the moments
    about the support wheel A. The arms are measured from A: P_УЭС at L − b on B's side,
    the implement at X_S9max − L on the far side; eq. (17) adds the ballast at L + X_гр
    on B's side. So every coordinate of the lab is measured from the steered axle B
    toward A: B at x = 0, A at x = L, P_УЭС at x = b, the implement at x = X_S9max > L,
    the ballast at x = −X_гр (behind B). (A at 0 and B at L would give P_УЭС the arm b,
    not L − b.)"""
    cw = [] if x_gr is None else [("tank", p_gr, -x_gr)]
    return Machine({"A": L, "B": 0.0}, steered="B", weights=[("ues", p_ues, b)],
                   counterweights=cw)


lengths = st.floats(1.0, 4.0)
fractions = st.floats(0.05, 0.95)
weights = st.floats(1e3, 1e5)


@settings(max_examples=n_examples(150), deadline=None)
@given(L=lengths, bf=fractions, reach=st.floats(0.05, 3.0), p_ues=weights,
       x_gr=st.floats(0.0, 2.0), p_gr=st.floats(0.0, 3e4))
def test_lab1_eq16_eq18_agree_with_general_limit(L, bf, reach, p_ues, x_gr, p_gr):
    """Seed 001 lab 1: eq. (16) m_po ≤ P_УЭС(4L − 5b)/(g(5X_S9max − 4L)) and eq. (18)
    m_po* ≤ (P_УЭС(4L − 5b) + P_гр(4L + 5X_гр))/(g(5X_S9max − 4L)) equal the general
    limit / g (clipped at 0 when the machine alone fails the rule), to 1e-9 relative to
    the size of the terms of the numerator."""
    b, x = bf * L, L + reach
    den = G * (5 * x - 4 * L)
    m16 = p_ues * (4 * L - 5 * b) / den                                    # eq. (16)
    m18 = (p_ues * (4 * L - 5 * b) + p_gr * (4 * L + 5 * x_gr)) / den      # eq. (18)
    scale16 = abs(p_ues * (4 * L - 5 * b)) / den + p_ues * L / den
    scale18 = scale16 + p_gr * (4 * L + 5 * x_gr) / den

    r = axle_reactions(lab1_machine(L, b, p_ues, x_gr, p_gr), 0.0, x)
    assert abs(r.max_implement_weight_without_counterweights / G - max(m16, 0.0)) <= 1e-9 * scale16
    assert abs(r.max_implement_weight / G - max(m18, 0.0)) <= 1e-9 * scale18

    # eq. (15)/(17): the steered reaction at the limit is exactly 20 % of the total
    if m18 > 0:
        at = axle_reactions(lab1_machine(L, b, p_ues, x_gr, p_gr), m18 * G, x)
        rb = (p_ues * (L - b) - m18 * G * (x - L) + p_gr * (L + x_gr)) / L  # eq. (17)
        assert math.isclose(float(at.reaction("B")), rb, rel_tol=1e-9, abs_tol=1e-9 * p_ues)
        assert math.isclose(float(at.steered_share), 20.0, rel_tol=1e-9)


@settings(max_examples=n_examples(100), deadline=None)
@given(xa=st.floats(-5, 5), gap=st.floats(0.3, 5), steer=st.sampled_from(["front", "rear"]),
       # weights of at least 1 mN or none (a subnormal weight, 5e-324 N, has no physical
       # meaning and defeats any relative tolerance)
       parts=st.lists(st.tuples(st.one_of(st.just(0.0), st.floats(1e-3, 5e4)),
                                st.floats(-8, 8)), min_size=1, max_size=4),
       p=st.floats(0, 5e4), x=st.floats(-8, 8))
def test_balance_of_forces_and_moments(xa, gap, steer, parts, p, x):
    """Any two-axle machine: ΣR = ΣP and ΣR·x = ΣP·x (moments about the origin), to
    1e-9 relative to the size of the terms."""
    parts = [(f"w{i}", pi, xi) for i, (pi, xi) in enumerate(parts)]
    if sum(pi for _, pi, _ in parts) == 0:
        parts[0] = ("w0", 1.0, parts[0][2])
    m = Machine({"front": xa, "rear": xa + gap}, steered=steer, weights=parts)
    r = axle_reactions(m, p, x)
    rf, rr = float(r.reaction("front")), float(r.reaction("rear"))
    w = sum(pi for _, pi, _ in parts) + p
    span = max(abs(xa), abs(xa + gap), abs(x), *(abs(xi) for _, _, xi in parts))
    big = w * span / gap                                   # size of a reaction term [N]
    assert abs(rf + rr - w) <= 1e-9 * big
    mom = sum(pi * xi for _, pi, xi in parts) + p * x
    assert abs(rf * xa + rr * (xa + gap) - mom) <= 1e-9 * big * span
    assert math.isclose(float(r.total_weight), w)


# --- limits that are not finite ------------------------------------------------------

def test_limit_unbounded_when_implement_loads_the_steered_axle():
    """c = ∂R_s/∂P ≥ min_share: no upper limit (np.inf), and a huge implement is fine."""
    m = Machine({"A": 0.0, "B": 2.0}, steered="B", weights=[("body", 10000.0, 1.0)])
    r = axle_reactions(m, 0.0, [0.4, 1.0, 2.5])      # c = 0.2, 0.5, 1.25
    assert np.all(np.isinf(r.max_implement_weight))
    big = axle_reactions(m, 1e9, [0.4, 1.0, 2.5])
    assert np.all(big.steerable)


def test_limit_zero_when_machine_alone_fails():
    """The machine alone puts 10 % on the steered axle and the implement unloads it:
    no admissible weight, the limit is 0 and even P = 0 is not steerable."""
    m = Machine({"A": 0.0, "B": 2.0}, steered="B", weights=[("body", 10000.0, 0.2)])
    r = axle_reactions(m, 0.0, [-1.0, 0.0])
    assert np.array_equal(r.max_implement_weight, [0.0, 0.0])
    assert not np.any(r.steerable)
    np.testing.assert_allclose(r.steered_share, 10.0, rtol=1e-12)
    # with the implement far over the steered axle the heavy implement rescues it
    r2 = axle_reactions(m, [0.0, 1e5], 3.0)
    assert np.isinf(r2.max_implement_weight).all()
    assert list(r2.steerable) == [False, True]


# --- broadcasting ----------------------------------------------------------------------

def test_broadcast_designs_by_positions(xs6):
    """implement_weight over designs (3, 1) × implement_x over positions (10,) → (3, 10);
    each row equals the scalar computation."""
    m = seed003_machine()
    p = np.array([[10000.0], [27500.0], [40000.0]])
    r = axle_reactions(m, p, xs6)
    for arr in [r.reaction("A"), r.reaction("B"), r.share("A"), r.steered_share,
                r.steerable, r.total_weight, r.max_implement_weight,
                r.max_implement_weight_without_counterweights]:
        assert arr.shape == (3, 10)
    for i in range(3):
        ri = axle_reactions(m, float(p[i, 0]), xs6)
        np.testing.assert_array_equal(r.reaction("A")[i], ri.reaction("A"))
        np.testing.assert_array_equal(r.max_implement_weight[i], ri.max_implement_weight)
    assert list(r.steerable.all(axis=1)) == [True, True, False]
    with pytest.raises(ValueError, match=r"one axis.*\(3, 10\)"):
        r.to_frame()
    x2 = np.stack([xs6, xs6 + 0.1])                  # (2, 10): positions of two designs
    assert axle_reactions(m, P6, x2).reaction("B").shape == (2, 10)
    assert axle_reactions(m, P6, 2.0).reaction("A").shape == ()


# --- input checks ------------------------------------------------------------------------

def test_unknown_steered_axle_lists_the_axles():
    with pytest.raises(ValueError, match=r"steered must be one of: \['A', 'B'\]; got 'C'"):
        Machine({"A": 0.0, "B": 2.0}, steered="C", weights=[("w", 1.0, 1.0)])


@pytest.mark.parametrize("kwargs,match", [
    (dict(axles={"A": 0.0}), r"exactly two axles.*got 1: \['A'\]"),
    (dict(axles={"A": 0.0, "B": 1.0, "C": 2.0}), r"exactly two axles.*got 3"),
    (dict(axles={"A": 1.0, "B": 1.0}), r"different x.*x = 1.0 m"),
    (dict(axles={"A": 0.0, "B": math.nan}), r"x of axle 'B' \[m\] must be a finite number"),
    (dict(weights=[("body", -5.0, 1.0)]), r"must be ≥ 0.*'body' has weight -5.0 N"),
    (dict(weights=[("body", math.inf, 1.0)]), r"weight of weights 'body' \[N\] must be a finite"),
    (dict(weights=[("body", 5.0)]), r"tuple \(name, weight \[N\], x \[m\]\); item 0"),
    (dict(weights=[("w", 5.0, 1.0)], counterweights=[("w", 1.0, -1.0)]), r"unique.*\['w'\]"),
    (dict(weights=[("w", 0.0, 1.0)]), r"positive total weight"),
    (dict(min_share=1.2), r"0 ≤ min_share < 1; got 1.2"),
])
def test_machine_validation(kwargs, match):
    base = dict(axles={"A": 0.0, "B": 2.0}, steered="A", weights=[("w", 1.0, 1.0)])
    base.update(kwargs)
    with pytest.raises(ValueError, match=match):
        Machine(**base)


def test_inputs_and_picks_validated(seed003):
    m = seed003_machine()
    with pytest.raises(ValueError, match=r"implement_weight.*≥ 0 N; smallest is -1.0 N"):
        axle_reactions(m, [-1.0, 5.0], 1.0)
    with pytest.raises(ValueError, match=r"implement_x \[m\] must be finite"):
        axle_reactions(m, 1.0, [1.0, math.nan])
    with pytest.raises(ValueError, match=r"axle must be one of: \['A', 'B'\]; got 'C'"):
        seed003.reaction("C")
    with pytest.raises(ValueError, match=r"index must have shape \(10,\)"):
        seed003.to_frame(index=[1, 2])


def test_table_6_1_from_the_model_analysis(hitch_analysis):
    """Seed 003 table 6.1 through ``examples.hitch_003().analyze(...)``: the model
    carries its machine (axles, tractor, ballast) and the implement P6 at S6; the
    analysis gives the correct limit and, beside it, the seed's GS6max (the model's
    extra formula), flagged."""
    a = hitch_analysis
    st = a.stability
    assert_printed(st.reaction("A"), T003_6_1, "Ra")
    assert_printed(st.reaction("B"), T003_6_1, "Rb")
    assert_printed(st.share("A"), T003_6_1, "dRa")
    assert_printed(st.share("B"), T003_6_1, "dRb")
    gs6max = a.formula("GS6max")
    assert_printed(gs6max, T003_6_1, "GS6max")
    (f,) = formulas_of(a.mechanism)
    assert "subtracts a force" in f.flags[0]
    assert np.all(st.max_implement_weight < gs6max - 1e4)


def test_machine_follows_the_parameters():
    """The model file ties the axles and weights to L, a, b, P_mcxa, P_gr
    (``x = ["-a", "-L"]`` is −(a + L)): perturbed parameters move them, per design in a
    batch, and R_A is the seed's closed form R_A = (P_гр·(a + L) + P_мсха·b − P6·XS6)/L."""
    s = examples.hitch_003_range()
    L = np.array([2.96, 3.2])
    a = examples.hitch_003(L=L, b=1.7, a=0.5, P_gr=9000.0).analyze(s)
    xs6 = a.kinematics.x("S6")
    for d in range(2):
        ra = (9000.0 * (0.5 + L[d]) + 56000.0 * 1.7 - 27500.0 * xs6[d]) / L[d]
        assert np.allclose(a.stability.reaction("A")[d], ra, rtol=1e-12)
    assert a.stability.max_implement_weight.shape == (2, 10)


@pytest.mark.parametrize("x", [np.array([-1.0]), np.array([[0.0]]), np.array(3.0),
                               np.array([1.0]), np.array([2.5])])
def test_one_position_equals_the_array_path(x):
    """One position (a number path in axle_reactions) gives what the same position
    gives among others (the array path), field by field, shapes included: bounded,
    unbounded (np.inf) and zero limits."""
    m = Machine({"A": 0.0, "B": 2.0}, steered="B", weights=[("body", 10000.0, 0.2)],
                counterweights=[("ballast", 3000.0, 2.6)])
    one = axle_reactions(m, 5000.0, x)
    many = axle_reactions(m, 5000.0, np.stack([x.reshape(-1)[0] + np.zeros(x.shape),
                                               np.full(x.shape, 0.7)]))
    for f in ("total_weight", "steered_share", "steerable", "max_implement_weight",
              "max_implement_weight_without_counterweights"):
        a, b = getattr(one, f), getattr(many, f)[0]
        assert a.shape == x.shape and a.dtype == b.dtype, f
        assert np.array_equal(a, b), f
    for n in ("A", "B"):
        assert np.array_equal(one.reactions[n], many.reactions[n][0])
        assert np.array_equal(one.shares[n], many.shares[n][0])
    with pytest.raises(ValueError, match="implement_x"):
        axle_reactions(m, 5000.0, np.full(x.shape, np.nan))
