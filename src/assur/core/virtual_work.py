"""The applied loads over arrays of positions and the actuator forces they ask for by
virtual work (DESIGN.md §4).

The loads (:mod:`assur.core.loads`) apply themselves to a *load collector*, the
contract of :mod:`assur.core.loads` over arrays of shape (m, n) (designs, positions):
it gathers their point forces, couples and springs (:func:`applied_loads`), with
d'Alembert's inertia loads when coordinate rates are given. The generalized force of
coordinate j is ``Q_j = Σ F·∂r/∂q_j + Σ M·∂φ/∂q_j`` from the exact analogs, and the
actuator must supply ``F_j = −Q_j`` (:func:`virtual_work_forces`; seed 003:
Fgc = P6·IS6). :func:`spring_states` gives the springs' lengths, tensions and forces.
:mod:`assur.core.statics` re-exports the three functions.
"""

from __future__ import annotations

import numpy as np

from ..errors import ModelError
from .gravity import gravity_unit

__all__ = ["applied_loads", "virtual_work_forces", "spring_states"]


def _values(kin):
    """A function turning a reference into an array broadcastable to (m, n)."""
    mech = kin.mechanism

    def val(ref):
        if ref is None:
            return 0.0
        v = np.asarray(mech.value_of(ref), dtype=float)
        if v.ndim == 1:
            if v.shape[0] == 1:
                return v[0]
            return v[:, None]
        return v
    return val


class _LoadCollector:
    """Load context over arrays (see :mod:`assur.core.loads`): collects the point forces,
    couples and springs of the loads, broadcastable to (m, n)."""

    def __init__(self, kin, g, qd=None, qdd=None):
        self.kin = kin
        self.mech = kin.mechanism
        self.value = _values(kin)
        self.g = g
        self.gravity_unit = gravity_unit(kin.mechanism)
        self.moving = qd is not None
        self.qd, self.qdd = qd, qdd
        self.forces, self.couples, self.springs = [], [], []

    def point(self, p):
        return self.kin.value(p)

    def owner(self, p):
        return self.mech.owner(p)

    def force(self, link, point, fx, fy):
        self.forces.append((link, point, fx, fy))

    def couple(self, link, M):
        self.couples.append((link, M))

    def spring(self, load, T, L):
        self.springs.append((load, T, L))

    def nonzero(self, L, what):
        if np.any(L == 0):
            raise ModelError(f"{what} at {int((L == 0).sum())} position(s); its direction is "
                             f"undefined there")

    def rate(self, link, coordinate=None):
        """∂φ_link/∂q of a coordinate (the only one by default), (m, n) [rad/m or rad/rad]."""
        a = 0 if coordinate is None else self.kin.coordinates.index(coordinate)
        return self.kin.body_rates(link)[0][a]

    def acceleration(self, point):
        J1 = self.kin.jacobian(point)  # (2, k, m, n)
        J2 = self.kin.hessian(point)
        acc = (np.einsum("ckmn,mnk->cmn", J1, self.qdd)
               + np.einsum("mnk,cklmn,mnl->cmn", self.qd, J2, self.qd))
        return acc[0], acc[1]

    def angular_acceleration(self, link):
        w1, w2 = self.kin.body_rates(link)
        return (np.einsum("kmn,mnk->mn", w1, self.qdd)
                + np.einsum("mnk,klmn,mnl->mn", self.qd, w2, self.qd))


def applied_loads(kin, qdot=None, qddot=None, g=None):
    """The applied loads as point forces and link moments, each with its link.

    Returns
    -------
    forces : list of (link, point, fx, fy)
        Arrays broadcastable to (m, n) [N].
    couples : list of (link, M) [N·m]
    springs : list of (Spring, T, L) with the tension T [N] and length L [m]

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.statics import applied_loads
    >>> forces, couples, springs = applied_loads(examples.hitch_003().solve([0.42]))
    >>> [(link, pt, float(fx), float(fy)) for link, pt, fx, fy in forces]  # P6 [N]
    [('6', 'S6', 0.0, -27500.0)]
    >>> couples, springs
    ([], [])
    """
    qd = qdd = None
    if qdot is not None:
        qd = np.broadcast_to(np.asarray(qdot, float).reshape(kin.shape + (-1,))
                             if kin.k > 1 else np.asarray(qdot, float)[..., None],
                             kin.shape + (kin.k,)).reshape(kin.m, kin.n, kin.k)
        if qddot is None:  # steady motion: no coordinate accelerations
            qddot = np.zeros(kin.shape + ((kin.k,) if kin.k > 1 else ()))
        qdd = np.broadcast_to(np.asarray(qddot, float)[..., None]
                              if kin.k == 1 else np.asarray(qddot, float),
                              kin.shape + (kin.k,)).reshape(kin.m, kin.n, kin.k)
    c = _LoadCollector(kin, kin.mechanism.g if g is None else g, qd, qdd)
    for ld in kin.mechanism.loads:
        ld.apply(c)
    return c.forces, c.couples, c.springs


def spring_states(kin):
    """Length, tension and force of every spring of the mechanism over the positions.

    Returns
    -------
    dict of str to (L, T, F)
        By spring name: its length |ab| [m], the tension of one spring
        ``T = preload + rate·(L − free_length)`` [N], and the force of all ``count``
        springs, ``F = count·T`` [N]; arrays of the kinematics' shape (a parameter
        over designs broadcasts).

    Examples
    --------
    Two springs along the hitch's cylinder 01–23 (length S), 1000 N/m, free length
    0.5 m, preload 50 N:

    >>> from assur import examples
    >>> from assur.core.statics import spring_states
    >>> m = examples.hitch_003().spring("s", "01", "23", rate=1000.0, free_length=0.5,
    ...                                 preload=50.0, count=2)
    >>> L, T, F = spring_states(m.solve([0.42, 0.67]))["s"]
    >>> [round(float(v), 3) for v in L]   # = S [m]
    [0.42, 0.67]
    >>> [round(float(v), 1) for v in T]   # 50 + 1000·(L − 0.5) [N]
    [-30.0, 220.0]
    >>> [round(float(v), 1) for v in F]   # 2·T [N]
    [-60.0, 440.0]
    """
    from .loads import Spring

    c = _LoadCollector(kin, 0.0)
    out = {}
    for ld in kin.mechanism.loads:
        if not isinstance(ld, Spring):
            continue
        (ax, ay), (bx, by) = c.point(ld.a), c.point(ld.b)
        L = np.hypot(bx - ax, by - ay)
        T = ld.tension(c, L)
        shape = (kin.m, kin.n)
        L, T = np.broadcast_to(L, shape), np.broadcast_to(T, shape)
        out[ld.name] = (kin.reshape(L), kin.reshape(T),
                        kin.reshape(np.broadcast_to(c.value(ld.count) * T, shape)))
    return out


def virtual_work_forces(kin, qdot=None, qddot=None, g=None):
    """Actuator forces by virtual work, ``{coordinate: F}`` with F of shape (m, n).

    ``F_j = −Q_j``, ``Q_j = Σ F·∂r/∂q_j + Σ M·∂φ/∂q_j`` (spring forces enter as the
    point forces of their tension).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.statics import virtual_work_forces
    >>> F = virtual_work_forces(examples.hitch_003().solve([0.42, 0.67]))
    >>> list(F), [round(float(v)) for v in F["S"].ravel()]   # Fgc, table 4.1 [N]
    (['S'], [129614, 135652])
    """
    forces, couples, _ = applied_loads(kin, qdot, qddot, g)
    Q = np.zeros((kin.k, kin.m, kin.n))
    for link, pt, fx, fy in forces:
        J = kin.jacobian(pt)  # (2, k, m, n)
        Q += fx * J[0] + fy * J[1]
    for link, M in couples:
        w1, _ = kin.body_rates(link)
        Q += M * w1
    return {c: -Q[j] for j, c in enumerate(kin.coordinates)}
