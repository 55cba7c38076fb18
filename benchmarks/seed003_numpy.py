"""Plain-numpy peer: the formulas of seed 003 (``003_b1551261b108abd1.txt``), vectorised.

This is the benchmark's reference peer, written the way an engineer would port
the Mathcad worksheet to numpy: every seed function (φ3(S), φ12, φ34, S1, φS1,
φ41, φ51, φ4, φ5, X45 … IS6) becomes one array expression over all positions,
each evaluated once and reused (no deliberate pessimisation, no numba). It does
not use ``assur`` at all, so agreement with ``assur`` is an independent check.

Two deliberate departures from the worksheet, both also made by
``assur.examples.hitch_003`` (so the two sides compute the same mechanism):

* the cylinder angle: the seed's φ12 = φ13 − acos(…) is not the direction 01 → 23
  (its check X23s, Y23s is off by up to 0.37 m); here φ12 = π − φ13 − acos(…);
* L4, L7 and Sp are the exact roots of the seed's three Find blocks (the
  worksheet prints them rounded to 4 digits).

The seed has no second-order analogs for the hitch; only group I (φ3'') gets one
here, from seed 001 lab 5 (verified against a finite difference in ``run.py``).
"""

from __future__ import annotations

import math

import numpy as np

#: seed 003 §1 input data [m, rad]; L4, L7, Sp: exact roots of the seed's Find blocks
PARAMS = dict(
    X01=0.415, Y01=0.563, X03=0.250, Y03=1.112, X05=0.135, Y05=0.480,
    X07=0.415, Y07=0.895,
    L3=0.200, L5=0.480, L6=0.595 - 0.08, L34=0.325, L56=1.035,
    phiBD=math.radians(22.0),
    L4=0.661283167, L7=0.752169525, Sp=0.469356940,
    X6=0.857, Y6=0.156,
)


def _lever_constants(p):
    """Seed 003 §2.1: L13 and φ13 of the frame line 01–03."""
    L13 = math.hypot(p["X01"] - p["X03"], p["Y01"] - p["Y03"])
    phi13 = math.atan((p["Y03"] - p["Y01"]) / (p["X01"] - p["X03"]))
    return L13, phi13


def lever_phi3(S, p=PARAMS):
    """Group I (2,3) alone: φ3, φ3' and φ3'' over the cylinder length S [m].

    φ3(S)   = acos((L3² + L13² − S²)/(2·L3·L13)) − φ13              (seed 003 §2.1)
    φ3'(S)  = 2S / sqrt(4·L13²·L3² − (S² − L13² − L3²)²)            (seed 003 §3.1, dφ3)
    φ3''(S) = 2·[S⁴ − (L3² − L13²)²] / (4·L13²·L3² − [S² − (L13² + L3²)]²)^(3/2)
                                                                      (seed 001 lab 5)

    Returns
    -------
    phi3, dphi3, ddphi3 : ndarray, shape of ``S`` [rad, rad/m, rad/m²]
    """
    L3 = p["L3"]
    L13, phi13 = _lever_constants(p)
    a2, b = L3 * L3, L13 * L13
    S2 = S * S
    phi3 = np.arccos((a2 + b - S2) / (2.0 * L3 * L13)) - phi13
    t = S2 - b - a2
    D = 4.0 * b * a2 - t * t
    sD = np.sqrt(D)
    dphi3 = 2.0 * S / sD
    ddphi3 = 2.0 * (S2 * S2 - (a2 - b) ** 2) / (D * sD)
    return phi3, dphi3, ddphi3


def _phi6_at(S, p, c):
    """φ6 at the positions S (the chain φ3 → … → φ6 only); used for φS6 at Sp."""
    g = _positions(np.asarray(S, dtype=float), p, c, upto6=True)
    return g["phi6"]


def _constants(p):
    L13, phi13 = _lever_constants(p)
    L35 = math.hypot(p["X03"] - p["X05"], p["Y03"] - p["Y05"])
    delta1 = math.pi - math.acos((p["X03"] - p["X05"]) / L35)
    L57 = math.hypot(p["X07"] - p["X05"], p["Y07"] - p["Y05"])
    delta2 = math.pi - math.acos((p["X07"] - p["X05"]) / L57)
    return dict(L13=L13, phi13=phi13, L35=L35, delta1=delta1, L57=L57, delta2=delta2)


def _positions(S, p, c, upto6=False):
    """Seed 003 §2: all angles and point coordinates (one array expression each)."""
    X03, Y03, X05, Y05, X07, Y07 = (p[k] for k in ("X03", "Y03", "X05", "Y05", "X07", "Y07"))
    L3, L4, L5, L6, L7, L34, L56 = (p[k] for k in ("L3", "L4", "L5", "L6", "L7", "L34", "L56"))
    L13, phi13, L35, d1, L57, d2 = (c[k] for k in ("L13", "phi13", "L35", "delta1", "L57",
                                                   "delta2"))
    S2 = S * S
    # §2.1 group I (2,3)
    phi3 = np.arccos((L3 * L3 + L13 * L13 - S2) / (2.0 * L3 * L13)) - phi13
    phi34 = phi3 + p["phiBD"]
    # §2.2 group II (4,5)
    phi341 = phi34 + d1
    S1sq = L35 * L35 + L34 * L34 - 2.0 * L35 * L34 * np.cos(phi341)
    S1 = np.sqrt(S1sq)
    phiS1 = np.arccos((L35 * L35 + S1sq - L34 * L34) / (2.0 * L35 * S1))
    phi41 = np.arccos((L4 * L4 + S1sq - L5 * L5) / (2.0 * L4 * S1)) - phiS1
    phi51 = math.pi - np.arccos((L5 * L5 + S1sq - L4 * L4) / (2.0 * L5 * S1)) - phiS1
    phi4 = phi41 - d1
    phi5 = phi51 - d1
    c5, s5 = np.cos(phi5), np.sin(phi5)
    X56 = X05 + L56 * c5
    Y56 = Y05 + L56 * s5
    # §2.3 group III (6,7)
    L53sq = (X07 - X56) ** 2 + (Y07 - Y56) ** 2
    L53 = np.sqrt(L53sq)
    phi53 = np.arccos((L53sq + L57 * L57 - L56 * L56) / (2.0 * L53 * L57))
    phi61 = math.pi - np.arccos((L6 * L6 + L53sq - L7 * L7) / (2.0 * L6 * L53)) + phi53
    phi6 = phi61 - d2
    if upto6:
        return dict(phi6=phi6)
    phi71 = np.arccos((L7 * L7 + L53sq - L6 * L6) / (2.0 * L7 * L53)) + phi53
    phi7 = phi71 - d2
    # cylinder direction 01 → 23 (the seed's φ12 = φ13 − acos(…) corrected, see module doc)
    phi12 = math.pi - phi13 - np.arccos((S2 + L13 * L13 - L3 * L3) / (2.0 * S * L13))
    return dict(
        S1=S1, phiS1=phiS1, phi12=phi12, phi3=phi3, phi34=phi34, phi4=phi4, phi5=phi5,
        phi6=phi6, phi7=phi7, L53=L53, phi53=phi53,
        X23=X03 + L3 * np.cos(phi3), Y23=Y03 + L3 * np.sin(phi3),
        X34=X03 + L34 * np.cos(phi34), Y34=Y03 + L34 * np.sin(phi34),
        X45=X05 + L5 * c5, Y45=Y05 + L5 * s5,
        X56=X56, Y56=Y56,
        X67=X07 + L7 * np.cos(phi7), Y67=Y07 + L7 * np.sin(phi7),
    )


def hitch(S, p=PARAMS):
    """The whole seed-003 pipeline: §2 geometry and §3 first-order kinematics.

    Parameters
    ----------
    S : ndarray, shape (n,)
        Cylinder lengths [m].

    Returns
    -------
    dict of str to ndarray
        Angles phi12, phi3, phi34, phi4, phi5, phi6, phi7 [rad]; points X/Y 23, 34,
        45, 56, 67, S6 [m]; ratios U43, U53, U65, U75 [-]; analogs dphi3 and
        dphi4 … dphi7 (the seed's φ41 … φ71 of §3.1) [rad/m]; I56, IS6 [m/m].
        φS6 and LS6 are derived at the working stroke Sp inside the call.
    """
    c = _constants(p)
    L3, L4, L5, L6, L7, L34, L56 = (p[k] for k in ("L3", "L4", "L5", "L6", "L7", "L34", "L56"))
    L13 = c["L13"]
    X6, Y6 = p["X6"], p["Y6"]
    # §2.3: the implement's centre of mass, fixed by its offset at S = Sp
    phiS6 = 2.0 * math.pi + math.atan(Y6 / X6) - float(_phi6_at(np.array([p["Sp"]]), p, c)[0])
    LS6 = math.hypot(X6, Y6)
    g = _positions(S, p, c)
    phi34, phi4, phi5, phi6, phi7 = g["phi34"], g["phi4"], g["phi5"], g["phi6"], g["phi7"]
    a6 = phiS6 + phi6
    g["XS6"] = g["X56"] + LS6 * np.cos(a6)
    g["YS6"] = g["Y56"] + LS6 * np.sin(a6)
    # §3.1 transfer ratios
    s45 = np.sin(phi4 - phi5)
    s67 = np.sin(phi6 - phi7)
    U43 = L34 * np.sin(phi5 - phi34) / (L4 * s45)
    U53 = L34 * np.sin(phi34 - phi4) / (L5 * -s45)
    U65 = L56 * np.sin(phi7 - phi5) / (L6 * s67)
    U75 = L56 * np.sin(phi5 - phi6) / (L7 * -s67)
    # §3.1 angular-velocity analogs
    t = S * S - L13 * L13 - L3 * L3
    dphi3 = 2.0 * S / np.sqrt(4.0 * L13 * L13 * L3 * L3 - t * t)
    dphi5 = dphi3 * U53
    dphi6 = dphi5 * U65
    I56 = dphi5 * L56 * np.cos(phi5)
    IS6 = I56 + dphi6 * LS6 * np.cos(a6)
    g.update(U43=U43, U53=U53, U65=U65, U75=U75, dphi3=dphi3, dphi4=dphi3 * U43,
             dphi5=dphi5, dphi6=dphi6, dphi7=dphi5 * U75, I56=I56, IS6=IS6,
             phiS6=phiS6, LS6=LS6)
    return g
