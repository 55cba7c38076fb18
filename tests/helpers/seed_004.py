"""Seed 004 (004_4ff0af19c30e8a3a.txt): the ЛВ-184А arm's data (table 1) and the
paper's own equations — the corrected Lagrange equations (37), (38) and the
kinematics (45)–(59) of a work cycle — against which :mod:`tests.seeds.test_crane_lagrange`
and :mod:`tests.dynamics.test_cycles` check the engine."""

from __future__ import annotations

import math

import numpy as np


G = 9.81



# table 1, ЛВ-184А
m, mp, mc = 884.0, 122.0, 311.0



lp = 2.818



delta = math.radians(11.61)



alpha_p = math.radians(95.44)



Jc, Jpk = 1153.0, 81.0



lc = math.sqrt(3 * Jc / mc)  # 3.335 m (not printed; from eq. 21)



def paper_forces(q, qd, qdd, corrected=True):
    """Q1 = F1·b1·sin β1 and Q2 = F2·b2·sin β2·sin(φ2 − φ3)/sin(φ1p − φ3) from eqs.
    (37), (38): left side + the weights' terms of the right side."""
    p1, p2 = q[:, 0], q[:, 1]
    w1, w2 = qd[:, 0], qd[:, 1]
    e1, e2 = qdd[:, 0], qdd[:, 1]
    C = (0.5 * mp + m) * lc * lp
    c, s = np.cos(alpha_p - p2), np.sin(alpha_p - p2)
    if corrected:
        # d/dt ∂T/∂φ̇1 − ∂T/∂φ1 from T of eq. (36): the cross term of (36) is
        # C·φ̇1(φ̇1 + φ̇2)·cos(α_p − φ2), whose time derivative brings +C·(2φ̇1 + φ̇2)·φ̇2·sin
        v1 = C * (2 * w1 + w2) * w2 * s
        v2 = -C * w1 ** 2 * s
    else:  # as printed: φ̈ where φ̇ is meant
        v1 = C * (2 * e1 + e2) * e2 * s
        v2 = -C * e1 ** 2 * s
    lhs1 = (Jc * e1 + Jpk * (e1 + e2) + (mp + m) * lc ** 2 * e1
            + (0.25 * mp + m) * lp ** 2 * (e1 + e2) + C * (2 * e1 + e2) * c + v1)
    lhs2 = (Jpk * (e1 + e2) + (0.25 * mp + m) * lp ** 2 * (e1 + e2) + C * e1 * c + v2)
    phc, php = p1 + delta, p2 + p1 + delta - alpha_p
    grav1 = (0.5 * mc * G * lc * np.cos(phc) + mp * G * (lc * np.cos(phc) + 0.5 * lp * np.cos(php))
             + m * G * (lc * np.cos(phc) + lp * np.cos(php)))
    grav2 = G * lp * (m + 0.5 * mp) * np.cos(php)
    return np.stack([lhs1 + grav1, lhs2 + grav2], -1)



# ---- the boom's lift mechanism, eqs. (45)–(50) and (7) --------------------------------
# table 1, ЛВ-184А: O the boom's pivot, A the cylinder's base (|OA| = a1), B its pin on
# the boom (|OB| = b1); γ1 + Φ1 is the angle AOB (eq. 47)
a1, b1 = 1.347, 0.447



gamma1 = math.radians(76.25)



S01, Smax1 = 1.075, 1.705



V1 = 0.085  # the divider's speed of the boom's rod (eq. 65) [m/s]



# ---- the stick's drive, eqs. (13)–(18) and (51)–(59) ---------------------------------
# table 1, ЛВ-184А, in the boom's frame (x1 along the boom): a2 turns about P0, the
# stick (its arm b2) about O1 = P0 + d2∠γ2, the coupler c2 joins their ends E and G;
# the cylinder (length S2) runs from P0 + l3∠(180° − α) to E, so that
# S2² = a2² + l3² + 2·a2·l3·cos(α + φ1p), which is what eq. (51) differentiates.
a2_, b2_, c2_, d2_, l3_ = 0.565, 0.211, 0.593, 0.139, 1.841



alpha_, gamma2_ = math.radians(7.02), math.radians(-30.25)



V2 = 0.13  # the divider's speed of the stick's rod (eq. 66) [m/s]



def paper_cycle(t, V1_, V2_, S20):
    """The paper's kinematics (eqs. 47–59) and forces F1, F2 of the corrected eqs.
    (37), (38) at times t: the rods at constant V1 (S1 = S01 + V1·t) and V2 (S2 = S20
    − V2·t); F = Q·dφ/dS with dΦ1/dS1 = 1/(b1·sin β1) (eqs. 7, 48) and dφ2/dS2 =
    −i41·S2/(a2·l3·sin(α + φ1p)) (eqs. 52, 55, 58)."""
    S1, S2 = S01 + V1_ * t, S20 - V2_ * t
    c10 = (a1 ** 2 + b1 ** 2 - S01 ** 2) / (2 * a1 * b1)
    P1 = np.arccos(c10 - V1_ * t / (a1 * b1) * (S01 + V1_ * t / 2)) - gamma1  # (47)
    s1, k1 = np.sin(gamma1 + P1), np.cos(gamma1 + P1)
    w1 = V1_ * S1 / (a1 * b1 * s1)  # (48)
    e1 = (V1_ ** 2 * s1 - V1_ * S1 * k1 * w1) / (a1 * b1 * s1 ** 2)  # (49)
    c20 = (S20 ** 2 - a2_ ** 2 - l3_ ** 2) / (2 * a2_ * l3_)
    p1p = np.arccos(c20 - V2_ * t / (a2_ * l3_) * (S20 - V2_ * t / 2)) - alpha_  # (51)
    sa, ca = np.sin(alpha_ + p1p), np.cos(alpha_ + p1p)
    w1p = V2_ * S2 / (a2_ * l3_ * sa)  # (52)
    e1p = -(V2_ ** 2 * sa + V2_ * S2 * ca * w1p) / (a2_ * l3_ * sa ** 2)  # (53)
    e2 = np.sqrt(a2_ ** 2 + d2_ ** 2 - 2 * a2_ * d2_ * np.cos(p1p - gamma2_))
    pe2 = -np.arccos((d2_ * math.cos(gamma2_) - a2_ * np.cos(p1p)) / e2)  # (54)
    p2 = np.arccos((c2_ ** 2 - b2_ ** 2 - e2 ** 2) / (2 * b2_ * e2)) + pe2
    p3 = np.arccos((c2_ ** 2 + e2 ** 2 - b2_ ** 2) / (2 * c2_ * e2)) + pe2
    i41 = a2_ * np.sin(p1p - p3) / (b2_ * np.sin(p2 - p3))
    i31 = -a2_ * np.sin(p1p - p2) / (c2_ * np.sin(p3 - p2))
    di41 = (a2_ * np.cos(p1p - p3) + i31 ** 2 * c2_
            - i41 ** 2 * b2_ * np.cos(p2 - p3)) / (b2_ * np.sin(p2 - p3))
    w2, e2dd = w1p * i41, w1p ** 2 * di41 + e1p * i41  # (58), (59)
    Q = paper_forces(np.stack([P1, p2], -1), np.stack([w1, w2], -1), np.stack([e1, e2dd], -1))
    sin_beta1 = a1 * s1 / S1  # (7)
    F1 = Q[:, 0] / (b1 * sin_beta1)
    F2 = Q[:, 1] * (-i41 * S2 / (a2_ * l3_ * sa))
    return np.stack([S1, S2], -1), np.stack([F1, F2], -1)

