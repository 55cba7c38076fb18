"""Seed 004 (004_4ff0af19c30e8a3a.txt): the boom + stick of a forestry manipulator,
its Lagrange equations (37)–(38) against the engine's general equations of motion
(:mod:`assur.dynamics.eom`), its kinematics (45)–(59) against the engine's analogs,
and the cylinder forces F1(t), F2(t) of the whole crane on its two cylinder lengths.

The arm as the engine sees it: the boom O–O1 (length l_c) is a crank about the frame
pivot O turned by its absolute angle φ_c, the stick O1–D (l_p) a crank about O1 turned
by its absolute angle φ_p; masses: the boom m_c at the middle of O–O1 with
J = J_c − m_c·l_c²/4 about it (J_c about O, eq. 21), the stick m_p at K, the middle
of O1–D, with J_pk, the load m at D. The paper's coordinates are φ1, φ2 with
φ_c = φ1 + δ and φ_p = φ1 + φ2 + δ − α_p (eqs. 1, 2): a constant linear map
q' = T·q + c, so the paper's generalized forces are Tᵀ times the engine's.

The paper's left sides are taken with BRIEF.md's corrections (a Lagrange derivation
from T of eq. (36) gives them): in (37) the term C·(2φ̈1 + φ̈2)·φ̈2·sin(α_p − φ2) is
C·(2φ̇1 + φ̇2)·φ̇2·sin(α_p − φ2), and in (38) −C·φ̈1²·sin(α_p − φ2) is
−C·φ̇1²·sin(α_p − φ2), C = (0.5·m_p + m)·l_c·l_p. The corrected equations equal the
engine to 1e-9 at random states; the equations as printed do not.

Data: table 1, ЛВ-184А (m, m_p, m_c, l_p, δ, α_p, J_c, J_pk); l_c is not printed:
J_c = m_c·l_c²/3 gives 3.335 m (BRIEF.md). The cylinders' lever arms (F1·b1·sin β1,
F2·…) are not modelled here: the comparison is of the generalized drive forces Q1, Q2
the cylinders must supply.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from assur import Mechanism
from assur.dynamics import equations_of_motion
from tests.helpers.seed_004 import G, S01, V1, V2, Jc, Jpk, Smax1, a1, a2_, alpha_, alpha_p, b1, \
    b2_, c2_, d2_, delta, gamma1, gamma2_, l3_, lc, lp, m, mc, mp, paper_cycle, paper_forces


def build():
    from assur.groups import Crank, RigidPoint
    mech = Mechanism("ЛВ-184А arm", coordinates=("pc", "pp"))
    mech = mech.frame("O", 0.0, 0.0)
    mech = mech.add(Crank(name="boom", pivot="O", out="O1", radius=lc, q="pc", links=("1",)))
    mech = mech.add(Crank(name="stick", pivot="O1", out="D", radius=lp, q="pp", links=("2",)))
    mech = mech.add(RigidPoint(name="C", origin="O", toward="O1", out="C", length=lc / 2,
                               angle=0.0, links=("1",)))
    mech = mech.add(RigidPoint(name="K", origin="O1", toward="D", out="K", length=lp / 2,
                               angle=0.0, links=("2",)))
    mech = mech.mass("1", mc, "C", Jc - mc * lc ** 2 / 4)
    mech = mech.mass("2", mp, "K", Jpk)
    mech = mech.mass("2", m, "D", 0.0)
    return mech


T = np.array([[1.0, 0.0], [1.0, 1.0]])  # d(φc, φp)/d(φ1, φ2)


def engine_forces(q, qd, qdd):
    """Generalized drive forces (Q1, Q2) [N·m] the cylinders must supply, shape (n, 2),
    from the engine: Tᵀ·F' with F' = M'·q̈' + h' − Q' in (φc, φp)."""
    qc = q @ T.T + np.array([delta, delta - alpha_p])
    eom = equations_of_motion(build().solve(qc), g=G)
    F = eom.actuator_forces(qd @ T.T, qdd @ T.T)
    return F @ T


def random_states(n=400, seed=11):
    rng = np.random.default_rng(seed)
    q = np.stack([rng.uniform(math.radians(-31.61), math.radians(60.9), n),
                  rng.uniform(math.radians(53), math.radians(146), n)], -1)
    return q, rng.uniform(-1.0, 1.0, (n, 2)), rng.uniform(-3.0, 3.0, (n, 2))


def test_engine_equals_the_corrected_lagrange_equations():
    q, qd, qdd = random_states()
    got = engine_forces(q, qd, qdd)
    ref = paper_forces(q, qd, qdd)
    scale = np.abs(ref).max(axis=0)
    err = np.abs(got - ref).max(axis=0) / scale
    assert (err < 1e-9).all(), err


def test_the_printed_equations_disagree():
    """φ̈ where φ̇ is meant (eqs. 37, 38 as printed): off by far more than rounding."""
    q, qd, qdd = random_states(seed=5)
    got = engine_forces(q, qd, qdd)
    printed = paper_forces(q, qd, qdd, corrected=False)
    scale = np.abs(got).max(axis=0)
    assert (np.abs(got - printed).max(axis=0) / scale > 1e-3).all()


def test_static_forces_are_the_weights_moments():
    """At rest the drive forces are the weights' moments of eqs. (6), (11)."""
    q, _, _ = random_states(50, seed=3)
    z = np.zeros_like(q)
    np.testing.assert_allclose(engine_forces(q, z, z), paper_forces(q, z, z), rtol=1e-12,
                               atol=1e-9)


def boom():
    """Cylinder–lever group: A at −γ1 from +x, so that φ(OB) = Φ1."""
    from assur.groups import CylinderLever
    mech = Mechanism("ЛВ-184А boom lift", coordinates=("S",))
    mech = mech.frame("O", 0.0, 0.0).frame("A", a1 * math.cos(-gamma1), a1 * math.sin(-gamma1))
    mech = mech.add(CylinderLever(name="boom lift", base="A", pivot="O", out="B", lever=b1,
                                  s="S", branch=-1, links=("3", "1")))
    return mech.link("1", "O", "B")


def test_boom_kinematics_equal_eqs_47_to_50():
    """At the ten steps of the cycle (eq. 45, "divide the time into 10 parts") with a
    constant rod speed V1: Φ1 (eq. 47), Φ̇1 = φ'·V1 (eq. 48), Φ̈1 = φ''·V1² (eq. 49),
    β1 (eq. 50) and sin β1 (eq. 7) from the engine's exact analogs, to 1e-12."""
    t1 = (Smax1 - S01) / V1  # (45)
    t = np.linspace(0.0, t1, 11)
    S = S01 + V1 * t
    kin = boom().solve(S)
    phi, w, e = kin.phi("1"), kin.dphi("1") * V1, kin.ddphi("1") * V1 ** 2
    Phi10 = math.acos((a1 ** 2 + b1 ** 2 - S01 ** 2) / (2 * a1 * b1)) - gamma1
    Phi1 = np.arccos(np.cos(gamma1 + Phi10) - V1 * t / (a1 * b1) * (S01 + V1 * t / 2)) - gamma1
    np.testing.assert_allclose(phi, Phi1, rtol=0, atol=1e-12)  # (47)
    sg, cg = np.sin(gamma1 + Phi1), np.cos(gamma1 + Phi1)
    dPhi1 = V1 * (S01 + V1 * t) / (a1 * b1 * sg)  # (48)
    np.testing.assert_allclose(w, dPhi1, rtol=1e-12)
    ddPhi1 = (V1 ** 2 * sg - V1 * (S01 + V1 * t) * cg * dPhi1) / (a1 * b1 * sg ** 2)  # (49)
    np.testing.assert_allclose(e, ddPhi1, rtol=1e-10, atol=1e-12 * np.abs(ddPhi1).max())
    # β1 of eq. (50) is the angle at the pin B, opposite OA = a1 (the paper names it
    # ∠OAB; its formulas (7), (50) are those of ∠OBA): b1·sin β1 is the arm of F1 about O
    beta1 = np.arccos((b1 ** 2 + S ** 2 - a1 ** 2) / (2 * b1 * S))
    sin_beta1 = a1 * sg / S  # (7)
    np.testing.assert_allclose(np.sin(beta1), sin_beta1, rtol=1e-12)
    # virtual work: the rod force F1 balances Q1 when F1·dS = Q1·dΦ1, i.e. dS/dΦ1 = b1·sin β1
    np.testing.assert_allclose(1.0 / kin.dphi("1"), b1 * sin_beta1, rtol=1e-12)


def test_table1_stops_of_the_boom():
    """The table's Φ10 = −31.61° and Φ1max = 60.9° against the closed stroke S01 and the
    open one Smax1 with the table's a1, b1, γ1: −31.73° and 61.60° (the table's angles
    are ~0.1° and ~0.7° off — its lengths are rounded to mm; noted, not matched)."""
    kin = boom().solve(np.array([S01, Smax1]))
    phi = np.degrees(kin.phi("1"))
    assert phi[0] == pytest.approx(-31.73, abs=0.005)
    assert phi[1] == pytest.approx(61.60, abs=0.005)
    assert abs(phi[0] - (-31.61)) < 0.2 and abs(phi[1] - 60.9) < 0.8


# ---- an independent derivation with sympy.physics.mechanics -------------------------
def sympy_forces():
    """(q, q̇, q̈) → (Q1, Q2) by sympy.physics.mechanics' LagrangesMethod: the boom a
    rigid body about O, the stick a rigid body with its centre K, the load a particle
    at D, gravity −g·N.y; positions from eqs. (1), (2), (34), (35)."""
    sm = pytest.importorskip("sympy")
    me = pytest.importorskip("sympy.physics.mechanics")
    q1, q2 = me.dynamicsymbols("q1 q2")
    u1, u2 = me.dynamicsymbols("q1 q2", 1)
    N = me.ReferenceFrame("N")
    B = N.orientnew("B", "Axis", [q1 + delta, N.z])  # boom: φc = φ1 + δ
    P = N.orientnew("P", "Axis", [q1 + q2 + delta - alpha_p, N.z])  # stick: φp
    O = me.Point("O")
    O.set_vel(N, 0)
    C = O.locatenew("C", lc / 2 * B.x)
    O1 = O.locatenew("O1", lc * B.x)
    K = O1.locatenew("K", lp / 2 * P.x)
    D = O1.locatenew("D", lp * P.x)
    C.v2pt_theory(O, N, B)
    O1.v2pt_theory(O, N, B)
    K.v2pt_theory(O1, N, P)
    D.v2pt_theory(O1, N, P)
    boom_body = me.RigidBody("boom", C, B, mc, (me.inertia(B, 0, 0, Jc - mc * lc ** 2 / 4), C))
    stick = me.RigidBody("stick", K, P, mp, (me.inertia(P, 0, 0, Jpk), K))
    load = me.Particle("load", D, m)
    for body in (boom_body, stick, load):
        body.potential_energy = body.mass * G * body.masscenter.pos_from(O).dot(N.y)
    L = me.Lagrangian(N, boom_body, stick, load)
    lm = me.LagrangesMethod(L, [q1, q2])
    lm.form_lagranges_equations()
    a1s, a2s = sm.symbols("a1 a2")
    acc = {q1.diff(): u1, q2.diff(): u2}
    acc2 = {u1.diff(): a1s, u2.diff(): a2s}
    expr = lm.eom.subs(acc2).subs(acc)  # = d/dt ∂L/∂q̇ − ∂L/∂q = Q_drive
    x = sm.symbols("x1 x2 w1 w2")
    expr = expr.subs({u1: x[2], u2: x[3]}).subs({q1: x[0], q2: x[1]})
    return sm.lambdify([*x, a1s, a2s], [expr[0], expr[1]], "numpy")


def test_engine_equals_a_sympy_lagrange_derivation():
    f = sympy_forces()
    q, qd, qdd = random_states(200, seed=7)
    got = engine_forces(q, qd, qdd)
    ref = np.stack(f(q[:, 0], q[:, 1], qd[:, 0], qd[:, 1], qdd[:, 0], qdd[:, 1]), -1)
    err = np.abs(got - ref).max(axis=0) / np.abs(ref).max(axis=0)
    assert (err < 1e-9).all(), err


def stick_drive():
    from assur.groups import CylinderLever, Dyad
    mech = Mechanism("ЛВ-184А stick drive", coordinates=("S2",))
    mech = (mech.frame("P0", 0.0, 0.0)
            .frame("O1", d2_ * math.cos(gamma2_), d2_ * math.sin(gamma2_))
            .frame("Bc", l3_ * math.cos(math.pi - alpha_), l3_ * math.sin(math.pi - alpha_)))
    mech = mech.add(CylinderLever(name="stick drive", base="Bc", pivot="P0", out="E",
                                  lever=a2_, s="S2", branch=1, links=("cyl", "a2")))
    mech = mech.add(Dyad(name="four-bar", a="E", b="O1", out="G", ra=c2_, rb=b2_, branch=1,
                         links=("c2", "b2")))
    return mech.link("a2", "P0", "E").link("c2", "E", "G").link("b2", "O1", "G")


def test_stick_drive_equals_eqs_51_to_59():
    """The cycle between the table's angles φ1p0 = 53° and φ1pmax = 146° (the printed
    S_max2 = 2.365 m does not give 53°: S2(53°) = 2.179 m, BRIEF.md), the rod retracting
    at V2, ten steps: φ1p (51), φ̇1p (52), φ̈1p (53), e2 (15), φe2 (54), φ2 (13, 14),
    φ3 (17, 18), i41, i31, i41' (55–57), φ̇2 (58), φ̈2 (59) — all from the engine's
    exact analogs (Ṡ2 = −V2), to 1e-9."""
    def S_of(phi1p):
        return math.sqrt(a2_ ** 2 + l3_ ** 2 + 2 * a2_ * l3_ * math.cos(alpha_ + phi1p))
    S0 = S_of(math.radians(53.0))
    S1 = S_of(math.radians(146.0))
    assert S0 == pytest.approx(2.179, abs=5e-4) and S1 == pytest.approx(1.365, abs=5e-3)
    t = np.linspace(0.0, (S0 - S1) / V2, 11)
    S = S0 - V2 * t
    kin = stick_drive().solve(S)
    c0 = math.cos(alpha_ + math.radians(53.0))
    p1p = np.arccos(c0 - V2 * t / (a2_ * l3_) * (S0 - V2 * t / 2)) - alpha_  # (51)
    np.testing.assert_allclose(kin.phi("a2"), p1p, atol=1e-12)
    sa, ca = np.sin(alpha_ + p1p), np.cos(alpha_ + p1p)
    w1p = V2 * (S0 - V2 * t) / (a2_ * l3_ * sa)  # (52)
    e1p = -(V2 ** 2 * sa + V2 * (S0 - V2 * t) * ca * w1p) / (a2_ * l3_ * sa ** 2)  # (53)
    np.testing.assert_allclose(kin.dphi("a2") * -V2, w1p, rtol=1e-12)
    np.testing.assert_allclose(kin.ddphi("a2") * V2 ** 2, e1p, rtol=1e-9,
                               atol=1e-12 * np.abs(e1p).max())
    e2 = np.sqrt(a2_ ** 2 + d2_ ** 2 - 2 * a2_ * d2_ * np.cos(p1p - gamma2_))  # (15)
    pe2 = -np.arccos((d2_ * math.cos(gamma2_) - a2_ * np.cos(p1p)) / e2)  # (54)
    p2 = np.arccos((c2_ ** 2 - b2_ ** 2 - e2 ** 2) / (2 * b2_ * e2)) + pe2  # (13), (14)
    p3 = np.arccos((c2_ ** 2 + e2 ** 2 - b2_ ** 2) / (2 * c2_ * e2)) + pe2  # (17), (18)
    np.testing.assert_allclose(kin.phi("b2"), p2, atol=1e-12)
    np.testing.assert_allclose(kin.phi("c2"), p3, atol=1e-12)
    i41 = a2_ * np.sin(p1p - p3) / (b2_ * np.sin(p2 - p3))  # (55)
    i31 = -a2_ * np.sin(p1p - p2) / (c2_ * np.sin(p3 - p2))  # (56)
    di41 = (a2_ * np.cos(p1p - p3) + i31 ** 2 * c2_
            - i41 ** 2 * b2_ * np.cos(p2 - p3)) / (b2_ * np.sin(p2 - p3))  # (57)
    np.testing.assert_allclose(kin.ratio("b2", "a2"), i41, rtol=1e-12)
    np.testing.assert_allclose(kin.ratio("c2", "a2"), i31, rtol=1e-12)
    w2 = w1p * i41  # (58)
    e2dd = w1p ** 2 * di41 + e1p * i41  # (59)
    np.testing.assert_allclose(kin.dphi("b2") * -V2, w2, rtol=1e-12)
    np.testing.assert_allclose(kin.ddphi("b2") * V2 ** 2, e2dd, rtol=1e-9,
                               atol=1e-9 * np.abs(e2dd).max())


def test_eq16_puts_phi_e2_in_the_wrong_quadrant():
    """Eq. (16) (arcsin) and eq. (54) (−arccos) disagree for φ1p < 77.7° (BRIEF.md): at
    the cycle's start φ1p = 53° the engine agrees with (54)."""
    p1p = math.radians(53.0)
    e2 = math.sqrt(a2_ ** 2 + d2_ ** 2 - 2 * a2_ * d2_ * math.cos(p1p - gamma2_))
    pe16 = math.asin((d2_ * math.sin(gamma2_) - a2_ * math.sin(p1p)) / e2)
    pe54 = -math.acos((d2_ * math.cos(gamma2_) - a2_ * math.cos(p1p)) / e2)
    kin = stick_drive().solve(np.array([math.sqrt(a2_ ** 2 + l3_ ** 2 + 2 * a2_ * l3_
                                                  * math.cos(alpha_ + p1p))]))
    E, O1 = kin.point("E")[0], kin.point("O1")[0]
    engine = math.atan2(O1[1] - E[1], O1[0] - E[0])
    assert engine == pytest.approx(pe54, abs=1e-9)
    assert abs(pe16 - pe54) > 0.5


# ---- the whole crane on its two cylinder lengths: F1(t), F2(t) -----------------------
def crane():
    """ЛВ-184А boom + stick as one engine model on (S1, S2): the boom lift
    (cylinder–lever about O), the stick's drive on the boom (the cylinder an RRR dyad's
    side of length S2 from Bc to E, the four-bar E–G–O1), the stick on its arm b2
    turned by −α_p, and the masses of eqs. (20)–(23)."""
    from assur.groups import CylinderLever, Dyad, RigidPoint
    mech = Mechanism("ЛВ-184А boom and stick", coordinates=("S1", "S2"))
    mech = mech.frame("O", 0.0, 0.0).frame("A", a1 * math.cos(-gamma1), a1 * math.sin(-gamma1))
    mech = mech.add(CylinderLever(name="boom lift", base="A", pivot="O", out="B", lever=b1,
                                  s="S1", branch=-1, links=("3", "1")))

    def rigid(out, origin, toward, length, angle, link):
        return RigidPoint(name=out, origin=origin, toward=toward, out=out, length=length,
                          angle=angle, links=(link,))
    mech = mech.add(rigid("O1", "O", "B", lc, delta, "1"), rigid("C", "O", "B", lc / 2, delta, "1"),
                    rigid("P0", "O1", "O", d2_, gamma2_, "1"),
                    rigid("Bc", "P0", "O1", l3_, math.pi - alpha_ - gamma2_, "1"))
    mech = mech.add(Dyad(name="stick cylinder", a="Bc", b="P0", out="E", ra="S2", rb=a2_,
                         branch=1, links=("4", "a2")))
    mech = mech.add(Dyad(name="four-bar", a="E", b="O1", out="G", ra=c2_, rb=b2_, branch=1,
                         links=("c2", "2")))
    mech = mech.add(rigid("D", "O1", "G", lp, -alpha_p, "2"), rigid("K", "O1", "G", lp / 2,
                                                                      -alpha_p, "2"))
    mech = mech.mass("1", mc, "C", Jc - mc * lc ** 2 / 4)
    mech = mech.mass("2", mp, "K", Jpk)
    mech = mech.mass("2", m, "D", 0.0)
    return mech.link("a2", "P0", "E").link("b2", "O1", "G")


@pytest.mark.parametrize("V1_, V2_", [(0.085, 0.13), (0.17, 0.0), (0.0, 0.26)])
def test_cylinder_forces_of_the_engine_equal_the_corrected_paper(V1_, V2_):
    """F1(t), F2(t) of a cycle with constant rod speeds (combined motion at the flow
    divider's speeds, and each link alone at the separate speeds, eqs. 65–68) from the
    engine's equations of motion on (S1, S2) — F = h(q, q̇) − Q(q), q̈ = 0 — equal the
    paper's corrected eqs. (37), (38) with its kinematics (45)–(59), to 1e-9."""
    S20 = math.sqrt(a2_ ** 2 + l3_ ** 2 + 2 * a2_ * l3_ * math.cos(alpha_ + math.radians(53)))
    S2end = math.sqrt(a2_ ** 2 + l3_ ** 2 + 2 * a2_ * l3_ * math.cos(alpha_ + math.radians(146)))
    T = min((Smax1 - S01) / V1_ if V1_ else np.inf, (S20 - S2end) / V2_ if V2_ else np.inf)
    t = np.linspace(0.0, T, 41)
    q, F_paper = paper_cycle(t, V1_, V2_, S20)
    eom = equations_of_motion(crane().solve(q), g=G)
    F = eom.actuator_forces(np.broadcast_to([V1_, -V2_], q.shape),
                            np.zeros_like(q))
    scale = np.abs(F_paper).max(axis=0)
    err = np.abs(F - F_paper).max(axis=0) / scale
    assert (err < 1e-9).all(), err
