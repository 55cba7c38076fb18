"""How a crank turns: direction of rotation and speed, as rates over positions.

A :class:`Motion` belongs to one generalized coordinate (a crank angle φ1). It
gives, for positions ``q`` [rad], the coordinate's rate ``qdot`` = φ1' [rad/s] and
acceleration ``qddot`` = φ1'' [rad/s²] — the plain arrays the real-time quantities
take (``v = J·q̇``, ``a = J·q̈ + q̇ᵀ·H·q̇``, DESIGN.md §2), the inertia loads and the
reduced moment included.

Sign convention (BRIEF.md: angles from +x, counter-clockwise positive)::

        ccw (direction = +1): φ1 grows,   q̇ = +|ω|
         ↺
        O1 ●——— A
         ↻
        cw  (direction = −1): φ1 falls,   q̇ = −|ω|

The seeds turn their cranks clockwise (seed 002 §2.20: "звено 1 вращается по
часовой стрелке, φ1' = −1"). The *travel* of the crank is the angle turned along
the direction of rotation, ``s = direction·(q − q_start) ≥ 0``; an analog "in the
direction of rotation" (the seed's convention) is ``dφ/ds = direction·dφ/dφ1``.

Speed
-----
* constant: ``|ω|`` [rad/s] (a file writes ``"300 rpm"`` or ``"31.4 rad/s"``):
  ``qdot = direction·|ω|``, ``qddot = 0``, and the time of a position is
  ``t = s/|ω|``;
* a given ω(t): samples ``t`` [s] (increasing) and ``omega`` = |ω(t)| [rad/s]
  (positive), linear between the samples. The crank then turns by
  ``s(t) = ∫ω dt`` from ``q_start`` at ``t[0]`` (default: the first position
  asked for), exactly (ω is linear on each interval, so s is quadratic there).
  Since ω > 0, s(t) increases and is inverted position by position: on the
  interval i with ω_i = ω(t_i), slope a_i = (ω_{i+1} − ω_i)/(t_{i+1} − t_i) and
  travel S_i at t_i,

  .. math::  \\omega(s) = \\sqrt{\\omega_i^2 + 2 a_i (s - S_i)}, \\qquad
             t(s) = t_i + \\frac{2 (s - S_i)}{\\omega_i + \\omega(s)}

  and ``qdot = direction·ω(s)``, ``qddot = direction·a_i`` (at a sample, the slope of
  the interval that starts there; at the last sample, of the last interval).
  Positions outside the travel the table covers are refused (ModelError).
* a law of motion q(t): samples ``law_t`` [s] (increasing) and ``law_q`` (the
  coordinate, strictly monotonic: a rod's S(t), seed 001 lab 5 "закон движения
  поршня"), interpolated by a cubic spline (C², not-a-knot,
  :class:`scipy.interpolate.CubicSpline`), whose derivative must keep its sign on
  the whole table (checked exactly, from the roots of the derivative). A position
  q is reached at the time t(q) solving spline(t) = q (bisection on the knot
  interval, to 1e-15 of the table's duration); ``qdot = spline'(t)``,
  ``qddot = spline''(t)`` — exact for the interpolant. The direction follows the
  table (q_N > q_0: +1).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import ModelError

__all__ = ["Motion", "DIRECTIONS", "ROD_DIRECTIONS", "rod_rates"]

#: the words of a direction of rotation and its sign
DIRECTIONS = {"ccw": 1, "cw": -1}
#: the words of a rod's direction of travel (a length coordinate) and its sign
ROD_DIRECTIONS = {"extend": 1, "retract": -1}


@dataclass(frozen=True)
class Motion:
    """Direction of rotation and speed of one crank-angle coordinate.

    Parameters
    ----------
    coordinate : str
        The generalized coordinate (a crank angle) it drives.
    direction : {+1, -1} or {"ccw", "cw"} or {"extend", "retract"}, optional
        +1 (``"ccw"``, the default): counter-clockwise, the angle grows; −1
        (``"cw"``): clockwise, as in the seeds. With a law q(t), its own.
    speed : float, optional
        Constant |ω| [rad/s] (> 0).
    t : sequence of float, optional
        Times of a given ω(t) [s], strictly increasing, at least two.
    omega : sequence of float, optional
        |ω| at the times ``t`` [rad/s], each > 0.
    start : float, optional
        The coordinate at ``t[0]`` (or at t = 0 for a constant speed) [rad];
        default: the first position passed to :meth:`rates`.
    law_t, law_q : sequence of float, optional
        A law of motion q(t): times [s] and positions [m or rad] (module notes);
        then no speed, table or start, and the direction follows the law.
    kind : {"angle", "length"}
        The coordinate's kind: a crank angle (speeds in rad/s), or a length — a
        cylinder's rod (issue 10): direction ``"extend"`` (+1, S grows) or
        ``"retract"`` (−1), speed |Ṡ| [m/s], a table of |Ṡ(t)| [m/s] in ``omega``,
        ``start`` [m]; the same formulas hold with s the rod's travel [m].

    Examples
    --------
    >>> import numpy as np
    >>> m = Motion("j1", "cw", speed=300 * 2 * np.pi / 60)   # 300 rpm clockwise
    >>> qdot, qddot = m.rates(np.radians([14.679, -15.321]))
    >>> [round(float(v), 4) for v in qdot], [float(v) for v in qddot]
    ([-31.4159, -31.4159], [0.0, 0.0])
    """

    coordinate: str
    direction: int | str | None = None
    speed: float | None = None
    t: tuple = ()
    omega: tuple = ()
    start: float | None = None
    kind: str = "angle"
    law_t: tuple = ()
    law_q: tuple = ()

    def __post_init__(self):
        self._check_law()
        d = self.direction
        if d is None:
            d = 1 if not self.law_q else int(np.sign(self.law_q[-1] - self.law_q[0]))
            object.__setattr__(self, "direction", d)
        if self.kind not in ("angle", "length"):
            raise ModelError(f"motion of {self.coordinate!r}: kind must be one of: "
                             f"['angle', 'length']; got {self.kind!r}")
        words = DIRECTIONS if self.kind == "angle" else ROD_DIRECTIONS
        if isinstance(d, str):
            if d not in words:
                raise ModelError(f"motion of {self.coordinate!r} (a {self.kind} coordinate): "
                                 f"direction must be one of: {list(words)}; got {d!r}")
            object.__setattr__(self, "direction", words[d])
        elif d not in (1, -1) or isinstance(d, bool):
            raise ModelError(f"motion of {self.coordinate!r}: direction must be +1 (ccw) or "
                             f"-1 (cw), got {d!r}")
        object.__setattr__(self, "t", tuple(float(x) for x in self.t))
        object.__setattr__(self, "omega", tuple(float(x) for x in self.omega))
        where = f"motion of {self.coordinate!r}"
        if self.speed is not None and (self.t or self.omega):
            raise ModelError(f"{where}: give either a constant speed or a table t, omega, not "
                             f"both")
        if self.speed is not None:
            s = float(self.speed)
            if not (math.isfinite(s) and s > 0):
                raise ModelError(f"{where}: the speed |ω| must be a positive number [rad/s], "
                                 f"got {self.speed!r}")
            object.__setattr__(self, "speed", s)
        if self.t or self.omega:
            t, w = np.array(self.t), np.array(self.omega)
            if t.size != w.size or t.size < 2:
                raise ModelError(f"{where}: the table needs as many t as omega values, at "
                                 f"least two; got {t.size} and {w.size}")
            if not (np.all(np.isfinite(t)) and np.all(np.isfinite(w))):
                raise ModelError(f"{where}: t and omega must be finite numbers")
            if np.any(np.diff(t) <= 0):
                k = int(np.flatnonzero(np.diff(t) <= 0)[0])
                raise ModelError(f"{where}: t must increase strictly; t[{k}] = {t[k]:.6g} s, "
                                 f"t[{k + 1}] = {t[k + 1]:.6g} s")
            if np.any(w <= 0):
                k = int(np.flatnonzero(w <= 0)[0])
                raise ModelError(f"{where}: omega is the speed |ω| along the direction of "
                                 f"rotation and must be > 0 (the crank must keep turning); "
                                 f"omega[{k}] = {w[k]:.6g} rad/s")
        if self.law_q:
            sign = int(np.sign(self.law_q[-1] - self.law_q[0]))
            if self.direction != sign:
                raise ModelError(f"{where}: the law q(t) goes {'up' if sign > 0 else 'down'} "
                                 f"from {self.law_q[0]:.6g} to {self.law_q[-1]:.6g}, against "
                                 f"the direction {self.direction_name}")
        if self.start is not None and not math.isfinite(float(self.start)):
            raise ModelError(f"{where}: start must be a finite angle, got {self.start!r}")

    # ---- description -------------------------------------------------------------
    @property
    def direction_name(self) -> str:
        """``"ccw"`` or ``"cw"`` (a crank); ``"extend"`` or ``"retract"`` (a rod).

        Examples
        --------
        >>> from assur.core.motion import Motion
        >>> Motion("j1", -1).direction_name, Motion("S", -1, kind="length").direction_name
        ('cw', 'retract')
        >>> Motion("S", law_t=(0.0, 2.0), law_q=(0.5, 0.4), kind="length").direction_name
        'retract'
        """
        if self.kind == "length":
            return "extend" if self.direction > 0 else "retract"
        return "ccw" if self.direction > 0 else "cw"

    @property
    def has_speed(self) -> bool:
        """True if a speed (constant, ω(t)) or a law q(t) is given, not only a
        direction.

        Examples
        --------
        >>> from assur.core.motion import Motion
        >>> Motion("j1", "cw").has_speed, Motion("j1", "cw", speed=31.4).has_speed  # [rad/s]
        (False, True)
        """
        return self.speed is not None or bool(self.t) or bool(self.law_t)

    # ---- a law of motion q(t) ----------------------------------------------------
    def _check_law(self):
        where = f"motion of {self.coordinate!r}"
        object.__setattr__(self, "law_t", tuple(float(x) for x in self.law_t))
        object.__setattr__(self, "law_q", tuple(float(x) for x in self.law_q))
        if not (self.law_t or self.law_q):
            return
        if self.speed is not None or self.t or self.omega or self.start is not None:
            raise ModelError(f"{where}: a law q(t) gives the motion whole: give no speed, "
                             f"speed table or start with it")
        t, q = np.array(self.law_t), np.array(self.law_q)
        if t.size != q.size or t.size < 2:
            raise ModelError(f"{where}: the law q(t) needs as many t as q values, at least "
                             f"two; got {t.size} and {q.size}")
        if not (np.isfinite(t).all() and np.isfinite(q).all()):
            raise ModelError(f"{where}: the law's t and q must be finite numbers")
        if np.any(np.diff(t) <= 0):
            k = int(np.flatnonzero(np.diff(t) <= 0)[0])
            raise ModelError(f"{where}: the law's t must increase strictly; t[{k}] = "
                             f"{t[k]:.6g} s, t[{k + 1}] = {t[k + 1]:.6g} s")
        dq = np.diff(q)
        if not (np.all(dq > 0) or np.all(dq < 0)):
            raise ModelError(f"{where}: the law's q must be strictly monotonic (the "
                             f"coordinate moves one way), got {list(self.law_q)}")
        sp = self._spline()
        roots = sp.derivative().roots(extrapolate=False)
        eps = 1e-9 * (t[-1] - t[0])   # a rate of zero at an end (from rest) is fine
        inner = roots[(roots > t[0] + eps) & (roots < t[-1] - eps)]
        if inner.size:
            raise ModelError(f"{where}: the cubic spline through the law q(t) turns back at "
                             f"t = {inner[0]:.6g} s (its rate changes sign); give more or "
                             f"smoother samples")

    def _spline(self):
        from scipy.interpolate import CubicSpline
        return CubicSpline(np.array(self.law_t), np.array(self.law_q))

    def _law_time(self, q):
        """t(q) of the law, vectorized bisection on each position's knot interval."""
        t, qs = np.array(self.law_t), np.array(self.law_q)
        sp = self._spline()
        d = self.direction
        lo_q, hi_q = min(qs[0], qs[-1]), max(qs[0], qs[-1])
        tol = 1e-12 * max(abs(hi_q - lo_q), 1e-300)
        out = (q < lo_q - tol) | (q > hi_q + tol)
        if np.any(out):
            bad = q[out]
            raise ModelError(f"motion of {self.coordinate!r}: the law q(t) covers "
                             f"{qs[0]:.6g} … {qs[-1]:.6g}; {bad.size} position(s) lie outside "
                             f"it (e.g. {float(bad.reshape(-1)[0]):.6g})")
        qq = np.clip(q, lo_q, hi_q)
        i = np.clip(np.searchsorted(d * qs, d * qq, side="right") - 1, 0, len(t) - 2)
        a, b = t[i], t[i + 1]
        for _ in range(64):   # halves the interval to below 1e-15 of the table's length
            m = 0.5 * (a + b)
            below = d * (sp(m) - qq) < 0
            a, b = np.where(below, m, a), np.where(below, b, m)
        return 0.5 * (a + b), sp

    # ---- rates -------------------------------------------------------------------
    def travel(self, q) -> np.ndarray:
        """The angle turned along the direction of rotation from ``start`` (default:
        the first of ``q``), ``s = direction·(q − q_start)`` [rad], shape of ``q``.

        Examples
        --------
        Seed 002's crank turns clockwise from 14.679° in steps of 30°:

        >>> import numpy as np
        >>> from assur.core.motion import Motion
        >>> s = Motion("j1", "cw").travel(np.radians([14.679, -15.321, -45.321]))
        >>> [round(float(v), 3) for v in np.degrees(s[1:])]             # [°]
        [30.0, 60.0]
        >>> start = Motion("j1", "cw", start=np.radians(44.679))        # [rad]
        >>> round(float(np.degrees(start.travel(np.radians(14.679)))), 3)  # [°]
        30.0
        """
        q = np.asarray(q, dtype=float)
        q0 = float(self.start) if self.start is not None else float(q.reshape(-1)[0])
        return self.direction * (q - q0)

    def continuous(self, q) -> np.ndarray:
        """Positions ``q`` [rad] (e.g. wrapped to [0, 2π) as a seed prints them) made
        continuous along the direction of rotation: each position is reached from the
        one before by turning forward less than a full turn. Seed 002's list
        14.679°, 344.679°, …, 44.679°, 188.229° turning clockwise becomes 14.679°,
        −15.321°, …, −315.321°, −531.771° (its 13th position is reached by turning on).

        Parameters
        ----------
        q : array_like, shape (n,)

        Returns
        -------
        numpy.ndarray, shape (n,)

        Examples
        --------
        >>> import numpy as np
        >>> from assur.core.motion import Motion
        >>> printed = np.radians([14.679, 344.679, 314.679, 44.679, 188.229])  # [rad]
        >>> q = Motion("j1", "cw").continuous(printed)
        >>> [round(float(v), 3) for v in np.degrees(q)]                 # [°]
        [14.679, -15.321, -45.321, -315.321, -531.771]
        """
        q = np.asarray(q, dtype=float).reshape(-1)
        if q.size < 2:
            return q.copy()
        step = np.mod(self.direction * np.diff(q), 2.0 * np.pi)   # forward turn, [0, 2π)
        return np.concatenate([q[:1], q[0] + self.direction * np.cumsum(step)])

    def _table(self):
        t, w = np.array(self.t), np.array(self.omega)
        a = np.diff(w) / np.diff(t)                       # slope of ω on each interval
        S = np.concatenate([[0.0], np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(t))])
        return t, w, a, S

    def _interval(self, s):
        t, w, a, S = self._table()
        tol = 1e-12 * max(S[-1], 1.0)  # the ends of the travel, up to rounding
        out = (s < -tol) | (s > S[-1] + tol)
        if np.any(out) and self.kind == "length":
            bad = s[out]
            raise ModelError(
                f"motion of {self.coordinate!r}: the table v(t) moves the rod by "
                f"{S[-1]:.6g} m from its start ({self.direction_name}); {bad.size} "
                f"position(s) lie outside that travel (e.g. {float(bad.reshape(-1)[0]):.6g} m "
                f"of travel)")
        if np.any(out):
            bad = s[out]
            raise ModelError(
                f"motion of {self.coordinate!r}: the table ω(t) turns the crank by "
                f"{math.degrees(S[-1]):.6g}° from its start (along {self.direction_name}); "
                f"{bad.size} position(s) lie outside that travel (e.g. "
                f"{math.degrees(float(bad.reshape(-1)[0])):.6g}° of travel)")
        s = np.clip(s, 0.0, S[-1])
        i = np.clip(np.searchsorted(S, s, side="right") - 1, 0, len(a) - 1)
        return i, s, t, w, a, S

    def rates(self, q) -> tuple[np.ndarray, np.ndarray]:
        """``(qdot, qddot)`` at the positions ``q`` [rad]: the coordinate's rate
        [rad/s] and acceleration [rad/s²], each of the shape of ``q``.

        Raises
        ------
        ModelError
            Without a speed, or for positions outside a table's travel.

        Examples
        --------
        A crank speeding up linearly from 10 to 20 rad/s in 1 s has turned 15 rad
        when it reaches 20 rad/s (ω² = ω0² + 2·a·s):

        >>> from assur.core.motion import Motion
        >>> m = Motion("j1", "ccw", t=(0.0, 1.0), omega=(10.0, 20.0))   # [s], [rad/s]
        >>> qdot, qddot = m.rates([0.0, 7.5, 15.0])                     # [rad]
        >>> [round(float(v), 3) for v in qdot], [float(v) for v in qddot]  # [rad/s], [rad/s²]
        ([10.0, 15.811, 20.0], [10.0, 10.0, 10.0])
        >>> Motion("j1", "cw").rates([0.0])
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: motion of 'j1' gives only the direction (cw): give a speed (a constant |ω| or a table ω(t)) for real-time rates
        """
        q = np.asarray(q, dtype=float)
        if self.law_t:
            tq, sp = self._law_time(q)
            return sp(tq, 1), sp(tq, 2)
        if not self.has_speed:
            raise ModelError(f"motion of {self.coordinate!r} gives only the direction "
                             f"({self.direction_name}): give a speed (a constant |ω| or a "
                             f"table ω(t)) for real-time rates")
        if self.speed is not None:
            return (np.full(q.shape, self.direction * self.speed), np.zeros(q.shape))
        i, s, t, w, a, S = self._interval(self.travel(q))
        om = np.sqrt(w[i] ** 2 + 2.0 * a[i] * (s - S[i]))
        return self.direction * om, self.direction * a[i]

    def time(self, q) -> np.ndarray:
        """The time at which the crank reaches each position [s] (from ``start`` at
        t = 0 for a constant speed, at ``t[0]`` for a table), shape of ``q``.

        Examples
        --------
        >>> import math
        >>> from assur.core.motion import Motion
        >>> m = Motion("j1", "ccw", t=(0.0, 1.0), omega=(10.0, 20.0))   # [s], [rad/s]
        >>> [round(float(v), 4) for v in m.time([0.0, 15.0])]          # q [rad] → [s]
        [0.0, 1.0]
        >>> cw = Motion("j1", "cw", speed=10 * math.pi, start=0.0)      # 300 rpm [rad/s]
        >>> round(float(cw.time(-2 * math.pi)), 4)                     # one turn [s]
        0.2
        """
        if self.law_t:
            return self._law_time(np.asarray(q, dtype=float))[0]
        s = self.travel(q)
        if self.speed is not None:
            return s / self.speed
        if not self.has_speed:
            self.rates(q)  # raises: no speed
        i, s, t, w, a, S = self._interval(s)
        om = np.sqrt(w[i] ** 2 + 2.0 * a[i] * (s - S[i]))
        return t[i] + 2.0 * (s - S[i]) / (w[i] + om)

    def describe(self) -> str:
        """``"j1: cw, |ω| = 31.416 rad/s (300 rpm)"`` for reports and summaries
        (``"S: extend, |v| = 0.05 m/s"`` for a rod).

        Examples
        --------
        >>> import math
        >>> from assur.core.motion import Motion
        >>> Motion("j1", "cw", speed=10 * math.pi).describe()            # [rad/s]
        'j1: cw, |ω| = 31.4159 rad/s (300 rpm)'
        >>> Motion("S", "extend", speed=0.05, kind="length").describe()  # [m/s]
        'S: extend, |v| = 0.05 m/s'
        """
        if self.law_t:
            unit = "m" if self.kind == "length" else "rad"
            return (f"{self.coordinate}: {self.direction_name}, law q(t) given at "
                    f"{len(self.law_t)} times, {self.law_t[0]:.6g}…{self.law_t[-1]:.6g} s "
                    f"({self.law_q[0]:.6g}…{self.law_q[-1]:.6g} {unit})")
        if self.kind == "length":
            if self.speed is not None:
                sp = f", |v| = {self.speed:.6g} m/s"
            elif self.t:
                sp = (f", |v(t)| given at {len(self.t)} times, {self.t[0]:.6g}…{self.t[-1]:.6g} s "
                      f"({min(self.omega):.6g}…{max(self.omega):.6g} m/s)")
            else:
                sp = ""
            return f"{self.coordinate}: {self.direction_name}{sp}"
        if self.speed is not None:
            sp = f", |ω| = {self.speed:.6g} rad/s ({self.speed * 30 / math.pi:.6g} rpm)"
        elif self.t:
            sp = (f", |ω(t)| given at {len(self.t)} times, {self.t[0]:.6g}…{self.t[-1]:.6g} s "
                  f"({min(self.omega):.6g}…{max(self.omega):.6g} rad/s)")
        else:
            sp = ""
        return f"{self.coordinate}: {self.direction_name}{sp}"


def rod_rates(kin):
    """Rates of the coordinates from the motions of the mechanism's rods (length
    coordinates with a speed, ``[motion] S = { direction = "extend", speed = … }``).

    Parameters
    ----------
    kin : Kinematics

    Returns
    -------
    (qdot, qddot) or None
        Arrays of the kinematics' shape (k = 1) or of shape (..., k) [m/s, m/s²]
        (0 for the coordinates without such a motion); None when no rod has a
        speed. Crank motions are left to :func:`assur.analysis.add_dynamics`.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.motion import rod_rates
    >>> m = examples.hitch_003()
    >>> print(rod_rates(m.solve([0.42, 0.67])))                     # no motion given
    None
    >>> r = m.with_motion("S", "extend", speed=0.05).solve([0.42, 0.67])   # [m/s]
    >>> qdot, qddot = rod_rates(r)
    >>> qdot.tolist(), qddot.tolist()                                # [m/s], [m/s²]
    ([0.05, 0.05], [0.0, 0.0])
    """
    mech = kin.mechanism
    rods = [mo for mo in mech.motions if mo.kind == "length" and mo.has_speed]
    if not rods:
        return None
    qd = np.zeros(kin.shape + (kin.k,))
    qdd = np.zeros(kin.shape + (kin.k,))
    for mo in rods:
        j = kin.coordinates.index(mo.coordinate)
        a, b = mo.rates(kin.q(mo.coordinate))
        qd[..., j], qdd[..., j] = a, b
    if kin.k == 1:
        return qd[..., 0], qdd[..., 0]
    return qd, qdd
