"""Steering geometry: the Ackermann relation, the turning radius, the wheel's
resisting moment and the flow of a steering drive (seed 001 lab 4; BRIEF.md row 11).

Conventions (SI, radians inside): a wheel's steering angle is its turn from
straight ahead, positive for both wheels in the sense of the turn; the *inner*
wheel (angle α) is the one nearer the centre of the turn and turns more than the
*outer* one (β). ``track`` A is the distance between the kingpin axes (2a of eq. 11),
``wheelbase`` L the distance to the axle that does not steer::

        centre of the turn               inner α     outer β
              o . . . . . . . . . . . . . . /  <- A ->  /
              :   L·ctg α, L·ctg β          kingpins of the steered axle
              :
              o======== axle that does not steer (at L) ========

Rolling without side slip needs ctg β − ctg α = A/L (eqs. 11, 16); the turning
radius is R = L·ctg α + a (eq. 12), its minimum R_min at the largest inner angle.
The functions take arrays (over positions, designs) and return arrays of their
broadcast shape; ctg is not finite straight ahead, where the ctg forms refuse
(:func:`outer_angle_error` is the form defined there too).
"""

from __future__ import annotations

import numpy as np

from ..errors import ModelError

__all__ = ["ackermann_deviation", "ideal_outer_angle", "outer_angle_error", "turning_radius",
           "resisting_moment", "rod_flow", "power_flow"]


def _angles(*a):
    out = [np.asarray(x, dtype=float) for x in a]
    for x in out:
        if np.any(x <= 0) or np.any(x >= np.pi / 2):
            raise ModelError(f"steering angles must be in (0°, 90°), got "
                             f"{np.degrees(x).ravel()[:5]}° …: ctg is not finite at 0° "
                             f"(straight ahead)")
    return out


def ackermann_deviation(inner, outer, track, wheelbase):
    """ctg β − ctg α − A/L [-]: zero for an exact Ackermann linkage (seed 001 lab 4
    eqs. 11, 16).

    Parameters
    ----------
    inner, outer : array_like
        Steering angles α of the inner and β of the outer wheel [rad], in (0, π/2).
    track : float
        Distance between the kingpin axes A = 2a [m].
    wheelbase : float
        Wheelbase L [m].

    Examples
    --------
    The lab's own check (seed 001 lab 4, §4.5): α = 51°, β = 34°, A = 1456 mm,
    L = 2534 mm: ctg 34° − ctg 51° = 0.673 (the lab prints 0.538), A/L = 0.575.

    >>> round(float(ackermann_deviation(np.radians(51), np.radians(34), 1.456, 2.534)), 4)
    0.0982
    """
    a, b = _angles(inner, outer)
    return 1.0 / np.tan(b) - 1.0 / np.tan(a) - track / wheelbase


def ideal_outer_angle(inner, track, wheelbase):
    """The outer wheel's angle that Ackermann asks for, β* = arcctg(ctg α + A/L)
    = atan(tan α / (1 + (A/L)·tan α)) [rad] (eq. 11); 0 straight ahead.

    Parameters
    ----------
    inner : array_like
        Inner wheel's angle α [rad], in [0, π/2).
    track, wheelbase : float
        A and L [m].

    Examples
    --------
    The lab's axle (seed 001 lab 4, §4.5: A = 1456 mm, L = 2534 mm) with the inner
    wheel at 51°: Ackermann asks 35.84° of the outer one (the lab's linkage gives 34°).

    >>> import numpy as np
    >>> from assur.machines.steering import ideal_outer_angle
    >>> round(float(np.degrees(ideal_outer_angle(np.radians(51), 1.456, 2.534))), 2)  # [deg]
    35.84
    >>> float(ideal_outer_angle(0.0, 1.456, 2.534))  # straight ahead [rad]
    0.0
    """
    t = np.tan(np.asarray(inner, dtype=float))
    return np.arctan(t / (1.0 + track / wheelbase * t))


def outer_angle_error(inner, outer, track, wheelbase):
    """β − β* [rad]: how far the outer wheel is from the Ackermann angle; unlike
    :func:`ackermann_deviation` it is defined straight ahead too (0 there).

    Examples
    --------
    The lab's check (seed 001 lab 4, §4.5): α = 51°, β = 34°, A = 1456 mm,
    L = 2534 mm; the outer wheel lags the Ackermann angle by 1.84°:

    >>> import numpy as np
    >>> from assur.machines.steering import outer_angle_error
    >>> err = outer_angle_error(np.radians(51), np.radians(34), 1.456, 2.534)
    >>> round(float(np.degrees(err)), 2)  # [deg]
    -1.84
    >>> float(outer_angle_error(0.0, 0.0, 1.456, 2.534))  # straight ahead [rad]
    0.0
    """
    return np.asarray(outer, dtype=float) - ideal_outer_angle(inner, track, wheelbase)


def turning_radius(inner, track, wheelbase):
    """Turning radius R = L·ctg α + a [m] (seed 001 lab 4 eq. 12; a = A/2), the
    minimum R_min at the largest inner angle α_max.

    Examples
    --------
    The lab's axle (seed 001 lab 4: A = 1456 mm, L = 2534 mm) at α_max = 51°:

    >>> import numpy as np
    >>> from assur.machines.steering import turning_radius
    >>> round(float(turning_radius(np.radians(51), 1.456, 2.534)), 3)  # R_min [m]
    2.78

    Straight ahead ctg α is not finite, and the function refuses:

    >>> turning_radius(0.0, 1.456, 2.534)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: steering angles must be in (0°, 90°), got [0.]° …: ctg is not finite at 0° (straight ahead)
    """
    (a,) = _angles(inner)
    return wheelbase / np.tan(a) + track / 2.0


def resisting_moment(wheel_load, kingpin_offset, tyre_width, friction):
    """Moment resisting the turn of a steered wheel standing still [N·m]
    (seed 001 lab 4 eq. 17):

    .. math:: M_c = 0.05·R_k·\\frac{1}{1 + e/B}·\\frac{B}{200\\,mm}·\\frac{μ}{0.7}

    Parameters
    ----------
    wheel_load : float
        Load on the wheel R_k [N].
    kingpin_offset : float
        Offset of the kingpin e [m].
    tyre_width : float
        Tyre width B [m] (the lab's B/200 takes B in mm: B/0.2 m here).
    friction : float
        Tyre–road friction coefficient μ [-].

    Examples
    --------
    The lab's inputs R_k = 27560 N, e = 70 mm, B = 500 mm, μ = 0.8 give 3453.6 N·m;
    the lab prints 2932 N·m (BRIEF.md: a slip).

    >>> round(float(resisting_moment(27560, 0.070, 0.500, 0.8)), 1)
    3453.6
    """
    return (0.05 * wheel_load / (1.0 + kingpin_offset / tyre_width) * tyre_width / 0.2
            * friction / 0.7)


def rod_flow(area, rod_speed):
    """Flow into a cylinder Q = A·v [m³/s] for the pressurised area A [m²] and the
    rod speed v [m/s] (seed 001 lab 4 eq. 25 by continuity).

    Examples
    --------
    A 40 mm bore pushed at 50 mm/s takes 3.77 l/min (the sign of v does not matter):

    >>> import numpy as np
    >>> from assur.machines.steering import rod_flow
    >>> area = np.pi * 0.040**2 / 4  # [m²]
    >>> round(float(rod_flow(area, -0.05)) * 60e3, 3)  # [l/min]
    3.77
    """
    return np.asarray(area, dtype=float) * np.abs(np.asarray(rod_speed, dtype=float))


def power_flow(moments, rates, rod_speed, pressure):
    """Flow from the power balance Σ M·ω = p·Q (seed 001 lab 4 eqs. 24–25):
    Q = Σ M_i·|φ_i′|·|v| / p [m³/s].

    Parameters
    ----------
    moments : sequence of float
        Resisting moments M_i [N·m] (magnitudes).
    rates : sequence of array_like
        The wheels' angular analogs φ_i′ = dφ_i/dS [rad/m] along the rod's travel.
    rod_speed : float
        Rod speed v [m/s]: ω_i = φ_i′·v.
    pressure : array_like
        The line's pressure p [Pa] (not 0).

    Examples
    --------
    Two wheels each resisting 3453.6 N·m (:func:`resisting_moment` of the lab's
    inputs), turning at 5 and 4 rad per metre of rod travel, rod at 50 mm/s, 10 MPa:

    >>> from assur.machines.steering import power_flow
    >>> q = power_flow([3453.6, 3453.6], [5.0, -4.0], 0.05, 10e6)  # [m³/s]
    >>> round(float(q) * 60e3, 3)  # [l/min]
    9.325
    >>> power_flow([3453.6], [5.0], 0.05, 0.0)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: the flow from the power balance needs a non-zero pressure
    """
    p = np.asarray(pressure, dtype=float)
    if np.any(p == 0):
        raise ModelError("the flow from the power balance needs a non-zero pressure")
    work = sum(float(m) * np.abs(np.asarray(r, dtype=float)) for m, r in zip(moments, rates))
    return work * abs(float(rod_speed)) / p
