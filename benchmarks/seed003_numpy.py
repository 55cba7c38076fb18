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

:func:`pipeline` adds the rest of the worksheet — §4 cylinder force, pressure and
lift capacity, §5 the closed-form joint reactions of §5.1–5.3 *as printed*, §6 the
axle reactions and GS6max — with the data of §1.4–1.6 (:data:`LOAD`). Two remarks,
both about the print, not departures from it:

* §4 prints ``G56(S) := k·P·η·S_gc/IS6(S)``, the same formula as GS6; its table 4.1
  column G56 is k·P·η·S_gc/I56 (the capacity at the suspension axis), used here;
* §5.2–5.3 give R05, R34, R45 (and so R43) with the opposite sign to their names
  (the ``[[tables.signs]]`` note of ``hitch_003.toml``); they are kept as printed here, the
  comparison in ``run.py`` applies the documented sign.

The printed §5 closed forms have removable singularities inside the stroke:
R56y divides by d1 = X67 − X56, which is 0 at S = Sp (φ6 = 90°, link 6 vertical),
and R01y by b3 = X23 − X01, which changes sign near S ≈ 0.436 m (R01x carries the
factor b3, so R01y stays well conditioned). Next to d1 = 0 the printed R56y loses
digits by cancellation (relative error about 1e−16 m/|d1|, carried into R07y, R67y
and §5.2–5.3); ``run.py`` reports it. The functions are dtype-generic: ``run.py``
re-evaluates them in ``np.longdouble`` at such positions.
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

#: seed 003 §1.4–1.6 loads, hydraulics and machine data [N, m, Pa, -]
LOAD = dict(
    P6=27500.0,                       # implement weight [N]
    Dgc=0.08, Pgc_max=17.5e6,         # piston diameter [m], system pressure [Pa]
    eta=0.84, kgc=2,                  # hydraulic efficiency, number of cylinders
    a=0.6, b=1.62, L=2.960,           # ballast overhang, tractor CM, wheelbase [m]
    P_gr=8000.0, P_mcxa=56000.0,      # ballast, mini-tractor weight [N]
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


def pipeline(S, p=PARAMS, q=LOAD):
    """The whole seed-003 worksheet over the positions S: §2–§3 (:func:`hitch`),
    §4 lift capacity, §5 joint reactions, §6 machine stability.

    Every formula is the seed's, written as printed (names as in the seed; the
    seed's Cyrillic subscripts: P_гр → P_gr, P_мсха → P_mcxa).

    Returns
    -------
    dict of str to ndarray
        Everything of :func:`hitch`, and
        §4: Fgc [N], Pgc [Pa], G56, GS6 [N], dGS65 [%];
        §5: R56x, R56y, R07x, R07y, R67x, R67y, R05x, R05y, R34x, R34y, R45x, R45y,
        R03x, R03y, R01x, R01y, R23x, R23y and the magnitudes R56, R07, R67, R05,
        R34, R45, R03, R01, R23 [N] (components of R05, R34, R45 with the seed's
        printed sign);
        §6: Ra, Rb [N], dRa, dRb [%], GS6max [as printed; N·m/m − N/m, see
        ``assur.machines.stability.SEED003_GS6MAX_FLAGS``], and — not in the seed — Gmax,
        the dimensionally correct limit of the 20 % rule [N].
    """
    g = hitch(S, p)
    X01, Y01, X03, Y03, X05, Y05, X07, Y07 = (
        p[k] for k in ("X01", "Y01", "X03", "Y03", "X05", "Y05", "X07", "Y07"))
    P6, Dgc, Pgc_max, eta, kgc = (q[k] for k in ("P6", "Dgc", "Pgc_max", "eta", "kgc"))
    a, b, L, P_gr, P_mcxa = (q[k] for k in ("a", "b", "L", "P_gr", "P_mcxa"))
    X23, Y23, X34, Y34, X45, Y45 = (g[k] for k in ("X23", "Y23", "X34", "Y34", "X45", "Y45"))
    X56, Y56, X67, Y67, XS6 = (g[k] for k in ("X56", "Y56", "X67", "Y67", "XS6"))
    I56, IS6 = g["I56"], g["IS6"]
    hyp = np.hypot

    # §4 lift capacity
    S_gc = 0.25 * math.pi * Dgc ** 2
    Fgc = P6 * IS6
    Pgc = Fgc / (kgc * S_gc * eta)
    G0 = kgc * Pgc_max * eta * S_gc
    G56 = G0 / I56                      # table 4.1 (the print's formula says IS6)
    GS6 = G0 / IS6
    dGS65 = (GS6 - P6) / P6 * 100.0

    # §5.1 group I (6,7)
    a1 = Y07 - Y67
    b1 = X67 - X07
    c1 = Y67 - Y56
    d1 = X67 - X56
    e1 = XS6 - X67
    R56x = P6 * b1 * (d1 + e1) / (a1 * d1 + b1 * c1)
    R56y = -(P6 * e1 - R56x * c1) / d1
    R07x = -R56x
    R07y = P6 - R56y
    R67x = R56x
    R67y = R56y - P6
    # §5.2 group II (4,5)
    R65x = -R56x
    R65y = -R56y
    a2 = Y34 - Y45
    b2 = X34 - X45
    c2 = Y05 - Y45
    d2 = X45 - X05
    e2 = R65x * (Y45 - Y56) + R65y * (X56 - X45)
    den2 = a2 * d2 + b2 * c2
    R05x = -(b2 * e2 - R65x * a2 * d2 + R65y * b2 * d2) / den2
    R05y = -(e2 + R05x * c2) / d2
    R34x = (b2 * e2 + R65x * b2 * c2 + R65y * b2 * d2) / den2
    R34y = R34x * a2 / b2
    R45x = R34x
    R45y = R34y
    # §5.3 group I (2,3)
    R43x = -R34x
    R43y = -R34y
    a3 = Y23 - Y01
    c3 = Y03 - Y23
    b3 = X23 - X01
    d3 = X03 - X23
    e3 = R43x * (Y23 - Y34) + R43y * (X34 - X23)
    den3 = a3 * d3 - b3 * c3
    R03x = (b3 * e3 + R43x * a3 * d3 - R43y * b3 * d3) / den3
    R03y = (e3 + R03x * c3) / d3
    R01x = -(b3 * e3 + R43x * b3 * c3 - R43y * b3 * d3) / den3
    R01y = R01x * a3 / b3
    R23x = R01x
    R23y = R01y
    R34 = hyp(R34x, R34y)
    R01 = hyp(R01x, R01y)

    # §6 machine stability
    W = P6 + P_mcxa + P_gr
    Ra = (P_gr * (a + L) + P_mcxa * b - P6 * XS6) / L
    Rb = P_gr + P_mcxa + P6 - Ra
    dRa = Ra / W * 100.0
    dRb = Rb / W * 100.0
    R_amin = 0.2 * W
    GS6max = (P_mcxa * b + P_gr * (a + L) - R_amin) / XS6
    # not in the seed: the 20 % rule solved for the implement weight
    # (assur.machines.stability module notes), compared with StabilityResult.max_implement_weight
    Gmax = (P_mcxa * b + P_gr * (a + L) - 0.2 * L * (P_mcxa + P_gr)) / (XS6 + 0.2 * L)

    g.update(
        Fgc=Fgc, Pgc=Pgc, G56=G56, GS6=GS6, dGS65=dGS65,
        R56x=R56x, R56y=R56y, R56=hyp(R56x, R56y),
        R07x=R07x, R07y=R07y, R07=hyp(R07x, R07y),
        R67x=R67x, R67y=R67y, R67=hyp(R67x, R67y),
        R05x=R05x, R05y=R05y, R05=hyp(R05x, R05y),
        R34x=R34x, R34y=R34y, R34=R34,
        R45x=R45x, R45y=R45y, R45=R34,
        R03x=R03x, R03y=R03y, R03=hyp(R03x, R03y),
        R01x=R01x, R01y=R01y, R01=R01,
        R23x=R23x, R23y=R23y, R23=R01,
        Ra=Ra, Rb=Rb, dRa=dRa, dRb=dRb, GS6max=GS6max, Gmax=Gmax,
    )
    return g
