"""A spring pressing device: the roller pressure of a mower-conditioner (seed 001 lab 2).

The upper roller of a conditioner is pressed onto the lower one by ``k`` springs
through a linkage (a four-bar: the spring on the roller's rocker; or a six-bar: the
spring on a lever driving the rocker through a link). The generalized coordinate is
Y, the distance between the rollers' centres, which the crop layer sets.

Lab 2 (001_4447446e88a18ffc.txt, §2) writes the specific pressure (force per metre of
roller) as

.. math::  p_c(Y) = \\frac{k \\cdot F_c(Y)}{I(Y) \\cdot L}  \\qquad (4)

with F_c the tension of one spring, L the roller length and the transmission number
I(Y) of eq. (5), φ3'·U53·L55·cos φ5. For (4) to be the virtual work of the springs,
``k·F_c·dλ = p_c·L·dY`` (λ the spring's length), the analogs in (5) are taken
**along the spring's stroke**: I = dY/dλ = 1/λ'(Y) (BRIEF.md: read along Y, (5)
gives I ≈ 1). :func:`specific_pressure` computes that from the spring's own
points; it equals the actuator force along Y by virtual work divided by L (the test
holds them equal, and to the reactions).

The spring that keeps p_c as constant as possible (:func:`flattest_spring`): with the
free length fixed, p_c is linear in the preload F0 and the rate c,
``p_c·L = k·[F0 + c·(λ − λ0)]·λ'``, so the least-squares deviation from a target
pressure over the range is a linear least-squares problem in (F0, c) with c ≥ 0,
solved exactly (:func:`scipy.optimize.lsq_linear`).

The rollers' grip (eqs. 1–3): the crop layer of thickness H entering the gap h
between two rollers of diameter D meets each roller at the wedge angle β,
cos β = 1 − (H − h)/D; the rollers grip when the friction angle φ > β (eq. 1),
i.e. D > (H − h)/(1 − cos φ) (eq. 2: 1/√(1 + tg²φ) = cos φ).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ModelError
from ..core.loads import Spring

__all__ = ["wedge_angle", "grips", "min_roller_diameter", "speed_ratio", "spring_stroke",
           "specific_pressure", "SpringDesign", "flattest_spring"]


def wedge_angle(D, H, h):
    """Wedge angle β between a roller and the crop layer at first contact [rad].

    Parameters
    ----------
    D : float or array_like
        Roller diameter [m].
    H : float or array_like
        Thickness of the incoming layer [m].
    h : float or array_like
        Gap between the rollers [m], h ≤ H < h + D.

    Returns
    -------
    float or numpy.ndarray
        β = acos(1 − (H − h)/D) [rad] (seed 001 lab 2, fig. 2.1).

    Raises
    ------
    ModelError
        If the layer does not touch the rollers (H < h) or is thicker than a roller
        can take (H − h ≥ D).

    Examples
    --------
    A 45 mm layer entering a 5 mm gap between 200 mm rollers:

    >>> import numpy as np
    >>> from assur.machines.conditioner import wedge_angle
    >>> round(float(np.degrees(wedge_angle(0.200, 0.045, 0.005))), 2)  # β [deg]
    36.87
    >>> wedge_angle(0.200, 0.003, 0.005)  # the layer is thinner than the gap
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: wedge angle: need 0 ≤ H − h < D; got D = 0.2, H = 0.003, h = 0.005 m
    """
    D, H, h = (np.asarray(x, dtype=float) for x in (D, H, h))
    if np.any(H < h) or np.any(H - h >= D) or np.any(D <= 0):
        raise ModelError(f"wedge angle: need 0 ≤ H − h < D; got D = {D}, H = {H}, h = {h} m")
    return np.arccos(1.0 - (H - h) / D)


def grips(D, H, h, friction_angle):
    """True where the rollers grip the layer: φ > β (lab 2 eq. 1).

    Parameters
    ----------
    D, H, h : float or array_like
        Roller diameter, layer thickness, gap [m].
    friction_angle : float or array_like
        Friction angle φ of the crop on the roller [rad].

    Examples
    --------
    The 200 mm rollers meet a 45 mm layer at β = 36.87° (gap 5 mm): a friction angle
    of 40° grips it, 35° does not.

    >>> import numpy as np
    >>> from assur.machines.conditioner import grips
    >>> grips(0.200, 0.045, 0.005, np.radians([40.0, 35.0])).tolist()
    [True, False]
    """
    return np.asarray(friction_angle) > wedge_angle(D, H, h)


def min_roller_diameter(H, h, friction_angle):
    """The smallest roller diameter that grips the layer (lab 2 eq. 2) [m]:
    D > (H − h)/(1 − 1/√(1 + tg²φ)) = (H − h)/(1 − cos φ).

    Parameters
    ----------
    H, h : float or array_like
        Layer thickness and gap [m].
    friction_angle : float or array_like
        Friction angle φ [rad], 0 < φ < π/2.

    Examples
    --------
    A 45 mm layer, 5 mm gap, friction angle 40°: the rollers need D > 171 mm.

    >>> import numpy as np
    >>> from assur.machines.conditioner import min_roller_diameter
    >>> round(float(min_roller_diameter(0.045, 0.005, np.radians(40))), 4)  # [m]
    0.171
    """
    phi = np.asarray(friction_angle, dtype=float)
    if np.any(phi <= 0) or np.any(phi >= np.pi / 2):
        raise ModelError(f"the friction angle must be in (0°, 90°), got {np.degrees(phi)}°")
    return (np.asarray(H, dtype=float) - np.asarray(h, dtype=float)) / (1.0 - np.cos(phi))


def speed_ratio(D, H, h):
    """V_B/V_T = D/(D + H + h), lab 2 eq. (3) as printed [-].

    The lab states that the ratio "determined by (3)" should be 1.25…1.35, but the
    printed expression is below 1 for any positive D, H, h; its reciprocal
    (D + H + h)/D falls in that range for usual rollers. Both are shown by the
    bundled model (flagged); this function returns the printed form.

    Examples
    --------
    200 mm rollers, a 45 mm layer, a 5 mm gap: the printed form gives 0.8, its
    reciprocal the lab's 1.25.

    >>> from assur.machines.conditioner import speed_ratio
    >>> r = speed_ratio(0.200, 0.045, 0.005)
    >>> round(float(r), 4), round(1 / float(r), 4)  # [-], [-]
    (0.8, 1.25)
    """
    D = np.asarray(D, dtype=float)
    return D / (D + np.asarray(H, dtype=float) + np.asarray(h, dtype=float))


def _spring(mech, name):
    for ld in mech.loads:
        if isinstance(ld, Spring) and ld.name == name:
            return ld
    names = [ld.name for ld in mech.loads if isinstance(ld, Spring)]
    raise ModelError(f"mechanism {mech.name!r} has no spring {name!r}; springs: {names}")


def spring_stroke(kin, spring):
    """Length λ of a spring and its analog λ' = dλ/dq along the (single) coordinate.

    Parameters
    ----------
    kin : Kinematics
    spring : str
        The spring's name.

    Returns
    -------
    (L, dL) : numpy.ndarray
        [m] and [m/m], the kinematics' shape; λ' = u·(r_b' − r_a'), u the unit vector
        a → b (exact, from the analogs of its ends).

    Examples
    --------
    The bundled conditioner of lab 2 (four-bar, spring ``sp``) over its eight gaps
    Y = 0.205 … 0.240 m: the spring stretches by about half of Y's change.

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.machines.conditioner import spring_stroke
    >>> kin = examples.conditioner_lab2().solve(examples.conditioner_lab2_range())
    >>> lam, dlam = spring_stroke(kin, "sp")
    >>> np.round(lam[[0, -1]], 4).tolist()  # λ at Ymin, Ymax [m]
    [0.3922, 0.4096]
    >>> np.round(dlam[[0, -1]], 4).tolist()  # λ' [m/m]
    [0.4872, 0.509]
    """
    if kin.k != 1:
        raise ModelError("spring_stroke: one generalized coordinate is needed")
    sp = _spring(kin.mechanism, spring)
    (ax, ay), (bx, by) = kin.value(sp.a), kin.value(sp.b)
    Ja, Jb = kin.jacobian(sp.a), kin.jacobian(sp.b)
    dx, dy = bx - ax, by - ay
    L = np.hypot(dx, dy)
    dL = (dx * (Jb[0, 0] - Ja[0, 0]) + dy * (Jb[1, 0] - Ja[1, 0])) / L
    return kin.reshape(np.broadcast_to(L, (kin.m, kin.n))), \
        kin.reshape(np.broadcast_to(dL, (kin.m, kin.n)))


def specific_pressure(kin, spring, roller_length):
    """Transmission number I = dY/dλ and specific pressure p_c (lab 2 eqs. 4–5).

    Parameters
    ----------
    kin : Kinematics
        One coordinate Y (the distance between the roller centres).
    spring : str
        The pressing spring(s) (``count`` = k of eq. 4).
    roller_length : float
        L [m].

    Returns
    -------
    (I, p) : numpy.ndarray
        I = 1/λ'(Y) [-] and p_c = k·F_c/(I·L) [N/m], the kinematics' shape.

    Raises
    ------
    ModelError
        Where λ' = 0 (the spring does not stretch as Y changes: I is undefined).

    Examples
    --------
    The bundled conditioner of lab 2 (two springs, rollers L = 1.6 m) at its
    smallest and largest gap:

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.machines.conditioner import specific_pressure
    >>> kin = examples.conditioner_lab2().solve(examples.conditioner_lab2_range())
    >>> I, p = specific_pressure(kin, "sp", 1.6)
    >>> np.round(I[[0, -1]], 3).tolist()  # I at Ymin, Ymax [-]
    [2.053, 1.965]
    >>> np.round(p[[0, -1]], -1).tolist()  # p_c [N/m]
    [19440.0, 20540.0]
    """
    from ..core.statics import spring_states
    L, dL = spring_stroke(kin, spring)
    if np.any(dL == 0):
        raise ModelError(f"spring {spring!r} does not stretch with the coordinate at "
                         f"{int((dL == 0).sum())} position(s): I = dY/dλ is undefined")
    _, T, F = spring_states(kin)[spring]
    return 1.0 / dL, F * dL / roller_length


@dataclass(frozen=True)
class SpringDesign:
    """Result of :func:`flattest_spring`.

    Attributes
    ----------
    preload : float
        F0, the tension of one spring at its free length [N].
    rate : float
        c [N/m].
    pressure : numpy.ndarray
        p_c(Y) with that spring [N/m].
    spread : float
        (max − min)/mean of p_c over the range [-].

    Examples
    --------
    The design :func:`flattest_spring` finds for the bundled conditioner of lab 2:

    >>> from assur import examples
    >>> from assur.machines.conditioner import flattest_spring
    >>> m = examples.conditioner_lab2()
    >>> d = flattest_spring(m, examples.conditioner_lab2_range(), "sp", 20000.0, 1.6)
    >>> round(d.preload, -1), round(d.spread, 3)  # F0 [N], spread [-]
    (32110.0, 0.044)
    >>> d.pressure.shape  # one p_c per position
    (8,)
    """

    preload: float
    rate: float
    pressure: np.ndarray
    spread: float


def flattest_spring(mech, q, spring, target, roller_length, min_rate=0.0):
    """The preload and rate of ``spring`` that keep p_c closest to ``target`` over ``q``
    in the least-squares sense, its free length and count as they are.

    Parameters
    ----------
    mech : Mechanism
        One coordinate; the spring's ``rate`` and ``preload`` are replaced.
    q : array_like, shape (n,)
        The range of the coordinate [m].
    spring : str
    target : float
        The specific pressure to hold [N/m].
    roller_length : float
        L [m].
    min_rate : float
        The softest spring allowed [N/m] (a real spring has a rate; 0 allows a
        constant-force one).

    Returns
    -------
    SpringDesign

    Examples
    --------
    Hold 20 kN/m on the bundled conditioner of lab 2 (rollers L = 1.6 m): the best is
    a constant-force spring (rate 0) with F0 ≈ 32.1 kN, p_c within 4.4 %; a real
    spring of at least 20 kN/m spreads it more.

    >>> from assur import examples
    >>> from assur.machines.conditioner import flattest_spring
    >>> m, Y = examples.conditioner_lab2(), examples.conditioner_lab2_range()
    >>> d = flattest_spring(m, Y, "sp", 20000.0, 1.6)
    >>> round(d.preload, -1), round(d.rate, 1), round(d.spread, 3)  # [N], [N/m], [-]
    (32110.0, 0.0, 0.044)
    >>> stiff = flattest_spring(m, Y, "sp", 20000.0, 1.6, min_rate=20000.0)
    >>> round(stiff.rate, 1), round(stiff.spread, 3)  # [N/m], [-]
    (20000.0, 0.055)
    """
    from scipy.optimize import lsq_linear

    kin = mech.solve(q)
    sp = _spring(mech, spring)
    lam, dlam = (np.asarray(a, dtype=float).reshape(-1) for a in spring_stroke(kin, spring))
    k = float(mech.value_of(sp.count))
    free = float(mech.value_of(sp.free_length))
    # p·L = k·[F0·λ' + c·(λ − λ0)·λ']  (eq. 4 with I = 1/λ')
    A = k / roller_length * np.column_stack([dlam, (lam - free) * dlam])
    sol = lsq_linear(A, np.full(lam.shape, float(target)),
                     bounds=([-np.inf, float(min_rate)], [np.inf, np.inf]))
    F0, c = (float(x) for x in sol.x)
    p = A @ sol.x
    return SpringDesign(F0, c, p, float((p.max() - p.min()) / p.mean()))
