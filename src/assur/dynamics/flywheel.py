"""The flywheel of a crank mechanism by the energy–mass method (Wittenbauer), exact.

Seed 001 lab 3: "the inertia of the flywheel stabilises the crank's angular
velocity over a cycle. For a given flywheel the coefficient of irregularity of the
crank's motion is found, after which the kinetostatic analysis is repeated".

Model and assumptions
---------------------
* One degree of freedom: the crank angle φ; the links' inertia is the reduced
  moment of inertia J_red(φ) (:func:`assur.dynamics.crank.reduced_inertia`), the
  flywheel adds a constant J_f on the crank.
* Steady periodic motion over one turn. The loads other than inertia (weights,
  technological resistance, springs …) act through their reduced moment
  M_c(φ) (:attr:`assur.dynamics.crank.CrankDynamics.reduced_moment_without_inertia`); the
  drive supplies a **constant** moment M_d equal to the mean resisting moment,
  ``M_d = −mean(M_c)``, so the work over a turn is zero and the motion repeats.
* Energy equation (exact for this model)::

      ½·(J_red(φ) + J_f)·ω(φ)² = T0 + ΔE(φ),   ΔE(φ) = ∫_{φ0}^{φ} (M_c + M_d) dφ

  T0 is the kinetic energy at φ0, fixed by the mean speed.
* Mean speed and irregularity as the classical definitions:
  ``ω_m = (ω_max + ω_min)/2``, ``δ = (ω_max − ω_min)/ω_m``.

Both directions are solved exactly on the sampled turn:

* **J_f for a target δ** — Wittenbauer's energy–mass diagram ΔE against J_red:
  the lines of slopes ``ω_max²/2`` and ``ω_min²/2``, ω_max,min = ω_m(1 ± δ/2),
  tangent to the curve from above and from below, meet at (−J_f, −T0)::

      b₁ = max(ΔE − s₁·J_red),  b₂ = min(ΔE − s₂·J_red),
      J_f = (b₁ − b₂)/(s₁ − s₂),  T0 = s₁·J_f − b₁

* **δ for a given J_f** — T0 such that (ω_max + ω_min)/2 = ω_m, by Brent's
  method (ω_max + ω_min increases with T0), then δ.

The classical approximation for small δ is ``J_f ≈ ΔE_max/(δ·ω_m²)`` with ΔE_max
the largest swing of the work of the loads (exact when J_red is constant, less
the mean J_red); :attr:`Flywheel.J_classical` is that value and
:attr:`Flywheel.J_mertsalov` the better one that takes the swing of
``ΔE − ½·J_red·ω_m²`` (the energy left to the flywheel) minus the mean J_red.

ΔE is integrated spectrally (the positions are one uniform turn, so the trapezoid
rule's periodic form — exact for the sampled Fourier modes — applies); a turn too
coarse for its loads (the upper quarter of the spectrum not negligible) is an
error naming the resolution.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..errors import ModelError  # too few positions: the user's to change (a ValueError)

__all__ = ["Flywheel", "flywheel", "turn_grid", "periodic_integral", "periodic_derivative",
           "speed_of"]

#: largest |Fourier coefficient| of the upper quarter of the spectrum, relative to the
#: largest, for a turn to count as resolved
RESOLUTION = 1e-7


def turn_grid(q):
    """Check that ``q`` [rad] is one uniform turn, increasing or decreasing, with or
    without its end point (q0 ± 2π).

    Returns
    -------
    n : int
        The positions of the periodic grid (the end point, if given, dropped).
    h : float
        The signed step [rad], n·|h| = 2π.

    Raises
    ------
    ValueError
        Fewer than 9 positions, not uniform, or not exactly one turn.

    Examples
    --------
    37 angles 10° apart with the end point, or 36 without, are the same grid:

    >>> import numpy as np
    >>> from assur.dynamics.flywheel import turn_grid
    >>> q = np.radians(np.arange(0, 361, 10))
    >>> n, h = turn_grid(q)
    >>> n, round(float(np.degrees(h)), 6)  # positions, step [deg]
    (36, 10.0)
    >>> turn_grid(q[:-1])[0], round(float(np.degrees(turn_grid(-q)[1])), 6)  # a clockwise turn
    (36, -10.0)
    >>> turn_grid(q[:19])
    Traceback (most recent call last):
    ...
    ValueError: the crank angles must cover exactly one turn: 19 positions at 10° span 190° without the end point, 180° with it
    """
    q = np.asarray(q, dtype=float)
    if q.ndim != 1 or q.size < 9:
        raise ModelError(f"the flywheel needs the crank angles of one turn, at least 9 "
                         f"positions, as a 1-D array; got shape {q.shape}")
    steps = np.diff(q)
    h = float(np.mean(steps))
    if not np.allclose(steps, h, rtol=0, atol=1e-9 * 2 * math.pi):
        raise ValueError(f"the crank angles must be uniformly spaced (steps from "
                         f"{math.degrees(steps.min()):.6g}° to {math.degrees(steps.max()):.6g}°)")
    n = q.size
    for n_, what in ((n, "without"), (n - 1, "with")):
        if abs(abs(h) * n_ - 2 * math.pi) <= 1e-9 * 2 * math.pi:
            return n_, h
    raise ValueError(f"the crank angles must cover exactly one turn: {n} positions at "
                     f"{math.degrees(h):.6g}° span {math.degrees(h * n):.6g}° without the end "
                     f"point, {math.degrees(h * (n - 1)):.6g}° with it")


def _spectrum(f, what):
    F = np.fft.fft(f)
    n = f.size
    k = np.fft.fftfreq(n, 1.0 / n)
    top = np.abs(F[np.abs(k) >= n / 4]).max(initial=0.0)
    scale = np.abs(F).max()
    if scale > 0 and top > RESOLUTION * scale:
        raise ModelError(f"{what} is not resolved by {n} positions per turn (its upper "
                         f"spectrum is {top / scale:.2g} of its largest mode > {RESOLUTION:g}): "
                         f"use more positions")
    return F, k


def periodic_integral(f, h, what="the integrand"):
    """∫_{φ0}^{φ_j} f dφ at the positions of a uniform turn for a periodic f of
    zero mean (its mean is removed and returned).

    Returns
    -------
    E : ndarray, shape (n,)
        E[0] = 0.
    mean : float

    Examples
    --------
    The integral of 2 + cos φ less its mean 2 is sin φ, exactly at the positions:

    >>> import numpy as np
    >>> from assur.dynamics.flywheel import periodic_integral
    >>> q = np.radians(np.arange(0, 360, 10))  # one turn without the end point [rad]
    >>> E, mean = periodic_integral(2 + np.cos(q), q[1] - q[0])
    >>> round(mean, 12), round(float(E[9]), 12)  # mean, ∫ at φ = 90°
    (2.0, 1.0)
    >>> bool(np.allclose(E, np.sin(q), rtol=0, atol=1e-12))
    True
    """
    f = np.asarray(f, dtype=float)
    n = f.size
    F, k = _spectrum(f - f.mean(), what)
    s = 1.0 if h > 0 else -1.0
    G = np.zeros_like(F)
    keep = (k != 0) & (np.abs(k) < n / 2)
    # φ_j − φ0 = s·2πj/n: the mode e^{ik·2πj/n} integrates to (e^{…} − 1)/(i·k·s)
    G[keep] = F[keep] / (1j * k[keep] * s)
    E = np.real(np.fft.ifft(G))
    return E - E[0], float(f.mean())


def periodic_derivative(f, h, what="the function"):
    """df/dφ at the positions of a uniform turn (spectral).

    Examples
    --------
    d(sin φ)/dφ = cos φ, exact for a resolved mode; a clockwise turn (h < 0) flips
    the sign:

    >>> import numpy as np
    >>> from assur.dynamics.flywheel import periodic_derivative
    >>> q = np.radians(np.arange(0, 360, 10))  # [rad]
    >>> d = periodic_derivative(np.sin(q), q[1] - q[0])
    >>> bool(np.allclose(d, np.cos(q), rtol=0, atol=1e-12))
    True
    >>> round(float(periodic_derivative(np.sin(q), -(q[1] - q[0]))[0]), 12)  # at φ = 0
    -1.0
    """
    f = np.asarray(f, dtype=float)
    n = f.size
    F, k = _spectrum(f, what)
    s = 1.0 if h > 0 else -1.0
    keep = np.abs(k) < n / 2
    G = np.where(keep, 1j * k * s * F, 0.0)
    return np.real(np.fft.ifft(G))


def speed_of(T0, energy, inertia):
    """ω(φ) = √(2(T0 + ΔE)/I) [rad/s] (magnitude).

    Examples
    --------
    50 J in 1 kg·m² is 10 rad/s; 25 J more make it √150:

    >>> import numpy as np
    >>> from assur.dynamics.flywheel import speed_of
    >>> np.round(speed_of(50.0, np.array([0.0, 25.0]), 1.0), 4).tolist()  # [rad/s]
    [10.0, 12.2474]
    """
    return np.sqrt(2.0 * (T0 + energy) / inertia)


@dataclass(frozen=True)
class Flywheel:
    """The flywheel and the crank's motion with it over one turn.

    Arrays are over the positions given (the end point included if it was).

    Attributes
    ----------
    q : ndarray
        Crank angle φ [rad].
    J_flywheel : float
        Flywheel moment of inertia J_f on the crank [kg·m²].
    delta : float
        Coefficient of speed irregularity δ = (ω_max − ω_min)/ω_m [-].
    omega_mean, omega_max, omega_min : float
        [rad/s] (magnitudes; ω_m = (ω_max + ω_min)/2).
    omega : ndarray
        |ω(φ)| [rad/s].
    epsilon : ndarray
        The crank's angular acceleration φ̈ [rad/s²] from Lagrange's equation
        ``(J_red + J_f)·φ̈ + ½·J_red'·φ̇² = M_c + M_d``: the same for either
        direction of rotation (φ̇² and the energy do not depend on it).
    T0 : float
        Kinetic energy at φ0 [J].
    energy : ndarray
        ΔE(φ), the work of the loads and the drive from φ0 [J].
    reduced_inertia, reduced_inertia_derivative : ndarray
        J_red [kg·m²], dJ_red/dφ [kg·m²/rad].
    reduced_moment : ndarray
        M_c(φ), the reduced moment of the loads without inertia [N·m].
    driving_moment : float
        The constant M_d = −mean(M_c) [N·m].
    energy_swing : float
        ΔE_max = max ΔE − min ΔE [J].
    J_classical, J_mertsalov : float
        The approximations ΔE_max/(δω_m²) and swing(ΔE − ½J_red·ω_m²)/(δω_m²) −
        mean(J_red) [kg·m²] for the same δ.

    Examples
    --------
    A crank of constant J_red = 0.5 kg·m² loaded by M_c = 100·sin φ N·m at
    ω_m = 10 rad/s, δ = 0.05: the loads' work swings by 2·100 J, the speed between
    ω_m(1 ± δ/2):

    >>> import numpy as np
    >>> from assur.dynamics.flywheel import flywheel
    >>> q = np.radians(np.arange(0, 361, 10))  # [rad]
    >>> fw = flywheel(q, np.full(q.shape, 0.5), 100 * np.sin(q), 10.0, delta=0.05)
    >>> round(fw.energy_swing, 9), round(fw.omega_max, 9), round(fw.omega_min, 9)  # [J], [rad/s]
    (200.0, 10.25, 9.75)
    >>> round(fw.J_classical, 9), round(fw.J_mertsalov, 9)  # [kg·m²]
    (40.0, 39.5)
    """

    q: np.ndarray
    J_flywheel: float
    delta: float
    omega_mean: float
    omega_max: float
    omega_min: float
    omega: np.ndarray
    epsilon: np.ndarray
    T0: float
    energy: np.ndarray
    reduced_inertia: np.ndarray
    reduced_inertia_derivative: np.ndarray
    reduced_moment: np.ndarray
    driving_moment: float
    energy_swing: float
    J_classical: float
    J_mertsalov: float

    def rates(self, direction):
        """(q̇, q̈) over the positions for a crank turning counter-clockwise
        (``direction`` = +1) or clockwise (−1), to repeat the kinetostatics with
        this motion (:func:`assur.dynamics.crank.crank_dynamics`).

        Examples
        --------
        The crank of J_red = 0.5 kg·m², M_c = 100·sin φ N·m with its flywheel for
        δ = 0.05 at 10 rad/s, turning clockwise:

        >>> import numpy as np
        >>> from assur.dynamics.flywheel import flywheel
        >>> q = np.radians(np.arange(0, 361, 10))  # [rad]
        >>> fw = flywheel(q, np.full(q.shape, 0.5), 100 * np.sin(q), 10.0, delta=0.05)
        >>> qdot, qddot = fw.rates(-1)
        >>> round(float(qdot[0]), 9), round(float(qddot[9]), 6)  # [rad/s], [rad/s²] at 90°
        (-9.75, 2.5)
        >>> fw.rates(0)
        Traceback (most recent call last):
        ...
        ValueError: direction must be one of: [1, -1]
        """
        if direction not in (1, -1):
            raise ValueError("direction must be one of: [1, -1]")
        return direction * self.omega, self.epsilon


def _delta_of(T0, energy, inertia, omega_mean):
    w = speed_of(T0, energy, inertia)
    return (w.max() - w.min()) / omega_mean, w


def flywheel(q, J_red, M_c, omega_mean, delta=None, J_flywheel=None, dJ_red=None):
    """The flywheel for a target δ, or δ for a given flywheel (module docstring).

    Parameters
    ----------
    q : array_like, shape (n,)
        Crank angles of one uniform turn [rad] (with or without the end point).
    J_red : array_like, shape (n,)
        Reduced moment of inertia of the links [kg·m²].
    M_c : array_like, shape (n,)
        Reduced moment of the loads without inertia [N·m] (counter-clockwise positive).
    omega_mean : float
        Mean angular speed ω_m > 0 [rad/s].
    delta : float, optional
        Target coefficient of irregularity, 0 < δ < 2 [-] (give this or J_flywheel).
    J_flywheel : float, optional
        A given flywheel's moment of inertia ≥ 0 [kg·m²].
    dJ_red : array_like, optional
        dJ_red/dφ [kg·m²/rad] (default: the spectral derivative of J_red).

    Returns
    -------
    Flywheel

    Raises
    ------
    ValueError
        Not one uniform turn, a turn too coarse, both or neither of delta and
        J_flywheel, a δ that the mechanism reaches without a flywheel, or a mean
        speed the crank cannot keep (it would stop).

    Examples
    --------
    Constant J_red = J0 and M_c = A·sin φ have the exact flywheel
    J_f = 2A/(δ·ω_m²) − J0: 2·100/(0.05·10²) − 0.5 = 39.5 kg·m². Given that
    flywheel, the irregularity comes back:

    >>> import numpy as np
    >>> from assur.dynamics.flywheel import flywheel
    >>> q = np.radians(np.arange(0, 361, 10))  # one turn with its end point [rad]
    >>> J_red, M_c = np.full(q.shape, 0.5), 100 * np.sin(q)  # [kg·m²], [N·m]
    >>> fw = flywheel(q, J_red, M_c, 10.0, delta=0.05)
    >>> round(fw.J_flywheel, 9)  # [kg·m²]
    39.5
    >>> round(flywheel(q, J_red, M_c, 10.0, J_flywheel=39.5).delta, 9)  # [-]
    0.05
    >>> flywheel(q, J_red, M_c, 10.0)
    Traceback (most recent call last):
    ...
    ValueError: give exactly one of delta and J_flywheel
    """
    if (delta is None) == (J_flywheel is None):
        raise ValueError("give exactly one of delta and J_flywheel")
    if not (math.isfinite(omega_mean) and omega_mean > 0):
        raise ValueError(f"omega_mean must be a positive speed [rad/s], got {omega_mean!r}")
    q = np.asarray(q, dtype=float)
    n, h = turn_grid(q)
    J_red = np.asarray(J_red, dtype=float)
    M_c = np.asarray(M_c, dtype=float)
    if J_red.shape != q.shape or M_c.shape != q.shape:
        raise ValueError(f"J_red and M_c must have the shape of q {q.shape}, got "
                         f"{J_red.shape} and {M_c.shape}")
    Jp, Mp = J_red[:n], M_c[:n]
    dJ = (periodic_derivative(Jp, h, "J_red") if dJ_red is None
          else np.asarray(dJ_red, dtype=float)[:n])
    E, mean_Mc = periodic_integral(Mp, h, "the reduced moment")
    M_d = -mean_Mc
    wm = float(omega_mean)
    swing = float(E.max() - E.min())
    if delta is not None:
        if not (0 < delta < 2):
            raise ValueError(f"delta must be in (0, 2), got {delta!r}")
        s1 = 0.5 * (wm * (1 + delta / 2)) ** 2
        s2 = 0.5 * (wm * (1 - delta / 2)) ** 2
        b1 = float(np.max(E - s1 * Jp))
        b2 = float(np.min(E - s2 * Jp))
        Jf = (b1 - b2) / (s1 - s2)
        if Jf <= 0:
            d0 = flywheel(q, J_red, M_c, omega_mean, J_flywheel=0.0, dJ_red=dJ_red).delta
            raise ValueError(f"the mechanism alone runs with δ = {d0:.4g} ≤ {delta:g} at "
                             f"ω_m = {wm:g} rad/s: no flywheel is needed")
        T0 = s1 * Jf - b1
        d = float(delta)
    else:
        Jf = float(J_flywheel)
        if not (math.isfinite(Jf) and Jf >= 0):
            raise ValueError(f"J_flywheel must be ≥ 0 [kg·m²], got {J_flywheel!r}")
        inertia = Jp + Jf
        if inertia.min() <= 0:
            i = int(np.argmin(inertia))
            raise ValueError(f"the reduced moment of inertia J_red + J_f is zero at "
                             f"φ = {math.degrees(q[i]):.6g}°: give the crank (or the "
                             f"flywheel) a moment of inertia")

        def excess(T0):
            w = speed_of(T0, E, inertia)
            return 0.5 * (w.max() + w.min()) - wm

        lo = -float(E.min())
        if excess(lo) >= 0:
            raise ValueError(f"the crank cannot keep the mean speed ω_m = {wm:g} rad/s with "
                             f"J_f = {Jf:g} kg·m²: it would stop (the loads' energy swing "
                             f"{swing:.4g} J is too large for its inertia)")
        hi = lo + inertia.max() * wm ** 2
        while excess(hi) <= 0:
            hi = lo + 2 * (hi - lo)
        T0 = brentq(excess, lo, hi, xtol=1e-14 * max(abs(lo), abs(hi), 1e-300), rtol=1e-15,
                    maxiter=500)
        d = None
    inertia = Jp + Jf
    w = speed_of(T0, E, inertia)
    if d is None:
        d = float((w.max() - w.min()) / wm)
    eps = (Mp + M_d - 0.5 * dJ * w ** 2) / inertia

    def full(a):  # back onto the positions given (the end point repeats the start)
        return np.concatenate([a, a[:1]]) if q.size == n + 1 else a

    Estar = E - 0.5 * Jp * wm ** 2
    return Flywheel(
        q=q, J_flywheel=float(Jf), delta=float(d), omega_mean=wm, omega_max=float(w.max()),
        omega_min=float(w.min()), omega=full(w), epsilon=full(eps), T0=float(T0),
        energy=full(E), reduced_inertia=J_red, reduced_inertia_derivative=full(dJ),
        reduced_moment=M_c, driving_moment=float(M_d), energy_swing=swing,
        J_classical=swing / (d * wm ** 2),
        J_mertsalov=float(Estar.max() - Estar.min()) / (d * wm ** 2) - float(Jp.mean()))
