"""The reverse-order pass over arrays of positions: joint reactions by Assur groups
(seed 003 §5, DESIGN.md §4).

Each structural group, last to first, is in equilibrium under its loads and the
reactions of the groups already solved (its own
:meth:`~assur.groups.base.Group.reactions`); :class:`ReactionContext` is the pass's
context (:class:`assur.core.reactions.ReactionContextBase`) over arrays of shape
(m, n) (designs, positions). The fused kernel traces the same group code
(:mod:`assur.core.outputs`). :func:`assur.core.statics.solve` runs :func:`reverse_pass`
on blocks of positions and makes the :class:`~assur.core.statics.Statics` result;
:mod:`assur.core.statics` re-exports :class:`ReactionContext`.
"""

from __future__ import annotations

import numpy as np

from .reactions import ReactionContextBase
from .virtual_work import _values, applied_loads, virtual_work_forces

__all__ = ["ReactionContext", "reverse_pass"]


def _residual(kin, applied, joints):
    """Equilibrium of every moving link: applied loads + all joint forces on it, as
    (|ΣF|, |ΣM|) maxima over the links, arrays (m, n) (computed when asked for: a
    check, not part of the result)."""
    m, n = kin.m, kin.n
    fres = np.zeros((m, n))
    mres = np.zeros((m, n))
    for b in kin.mechanism.topology.bodies:
        if b == "0":
            continue
        fx, fy, mo = [np.broadcast_to(a, (m, n)) for a in applied[b]]
        for (i, j), (pt, rx, ry, mz) in joints.items():
            if b not in (i, j):
                continue
            sg = 1.0 if j == b else -1.0
            px, py = kin.value(pt)
            fx = fx + sg * rx
            fy = fy + sg * ry
            mo = mo + sg * (px * ry - py * rx + mz)
        fres = np.maximum(fres, np.hypot(fx, fy))
        mres = np.maximum(mres, np.abs(mo))
    return fres, mres


def _applied(kin, qdot, qddot, g):
    """The applied loads on every body as wrenches about the origin (Fx, Fy, M)."""
    r = ReactionContext(kin, set())
    forces, couples, _ = applied_loads(kin, qdot, qddot, g)
    for link, pt, fx, fy in forces:
        r.apply(link, pt, fx, fy)
    for link, M in couples:
        r.apply_moment(link, M)
    return r.W


class ReactionContext(ReactionContextBase):
    """The reverse-order pass over arrays of shape (m, n) (designs, positions).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.statics import ReactionContext
    >>> r = ReactionContext(examples.hitch_003().solve([0.42, 0.67]), set())
    >>> r.shape                              # one design, two positions
    (1, 2)
    >>> float(r.value("P6"))                  # [N]
    27500.0
    """

    def __init__(self, kin, rod_ends):
        super().__init__(kin.mechanism, rod_ends)
        self.kin = kin
        self.shape = (kin.m, kin.n)
        self._val = _values(kin)

    def point(self, p):
        """(x, y) of a point, arrays (m, n) [m].

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42, 0.67]), set())
        >>> x, y = r.point("01")                     # a frame pivot [m]
        >>> x.tolist(), y.tolist()
        ([[0.415, 0.415]], [[0.563, 0.563]])
        """
        return self.kin.value(p)

    def value(self, ref):
        """Value of a number or parameter, broadcastable to (m, n).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42]), set())
        >>> float(r.value("L3")), float(r.value(2.5)), r.value(None)   # [m], [-], none
        (0.2, 2.5, 0.0)
        """
        return self._val(ref)

    def inv(self, x):
        """1/x, and 0 where x = 0 (a degenerate, failed position).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42, 0.67]), set())
        >>> r.inv([4.0, 0.0]).tolist()
        [[0.25, 0.0]]
        """
        x = np.broadcast_to(np.asarray(x, float), self.shape)
        return np.divide(1.0, x, out=np.zeros(self.shape), where=x != 0.0)

    def record(self, i, j, pt, fx, fy, mz=0.0):
        """Record the force (and moment) of body i on body j at point ``pt``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42, 0.67]), set())
        >>> r.record("5", "6", "56", 100.0, -50.0)        # [N]
        >>> pt, fx, fy, mz = r.joints[("5", "6")]
        >>> pt, fx.tolist(), fy.tolist(), mz.tolist()     # broadcast to (m, n)
        ('56', [[100.0, 100.0]], [[-50.0, -50.0]], [[0.0, 0.0]])
        """
        self.joints[(i, j)] = (pt, np.broadcast_to(fx, self.shape),
                               np.broadcast_to(fy, self.shape), np.broadcast_to(mz, self.shape))


def reverse_pass(kin, qdot=None, qddot=None, g=None):
    """The reverse-order pass over the positions of ``kin``: each group, last to first,
    solves its own reactions (:meth:`assur.groups.base.Group.reactions`); the parts of
    a :class:`~assur.core.statics.Statics` (:func:`assur.core.statics.solve` makes it).

    Parameters
    ----------
    kin : Kinematics
        Solved with every point (the default of :meth:`assur.Mechanism.solve`).
    qdot, qddot : array_like, optional
        Coordinate rates [m/s, m/s²] for inertia loads (as for
        :func:`~assur.core.statics.solve`).
    g : float, optional
        Gravity [m/s²] for the masses' weights (default: the mechanism's).

    Returns
    -------
    forces : dict of str to ndarray
        Actuator force of each coordinate by virtual work, shape (m, n) [N or N·m].
    joints : dict
        ``{(i, j): (point, Rx, Ry, Rm)}``: force of link i on link j [N] and the
        moment at a prismatic pair or crank drive [N·m], arrays (m, n).
    actuators : dict of str to ndarray
        Actuator force of each coordinate from the joint reactions [N or N·m].
    residual : callable
        Returns ``(|ΣF|, |ΣM|)`` over the moving links, arrays (m, n) [N, N·m].

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.reverse_pass import reverse_pass
    >>> kin = examples.hitch_003().solve([0.42, 0.67])          # S [m]
    >>> forces, joints, actuators, residual = reverse_pass(kin)
    >>> [round(float(v)) for v in actuators["S"][0]]           # Fgc, table 4.1 [N]
    [129614, 135652]
    >>> pt, rx, ry, rm = joints[("5", "6")]                     # R56, table 5.1 [N]
    >>> pt, round(float(rx[0, 0])), round(float(ry[0, 0]))
    ('56', 45683, 16228)
    >>> bool(residual()[0].max() < 1e-6)                        # |ΣF| [N]
    True
    """
    g = kin.mechanism.g if g is None else g
    mech = kin.mechanism
    topo = mech.topology
    missing = [p for pts in topo.bodies.values() for p in pts if not kin.has_point(p)]
    if missing:
        raise ValueError(f"the kinematics lack points {missing}: solve without `outputs=`")
    forces, couples, _ = applied_loads(kin, qdot, qddot, g)

    def is_coord(ref):
        return isinstance(ref, str) and ref in mech.coordinates

    rod_ends = {e for g_ in mech.groups
                for e in g_.rod_ends(topo.group_links[g_.name], is_coord)}
    r = ReactionContext(kin, rod_ends)
    for link, pt, fx, fy in forces:
        r.apply(link, pt, fx, fy)
    for link, M in couples:
        r.apply_moment(link, M)
    # (apply rebinds, never mutates, so this keeps the applied loads alone)
    applied = {b: list(w) for b, w in r.W.items()}
    for g_ in reversed(mech.groups):
        r.links = topo.group_links[g_.name]
        g_.reactions(r)
    joints, act = r.joints, r.act
    vw = virtual_work_forces(kin, qdot, qddot, g)

    def residual():
        return _residual(kin, applied, joints)

    return vw, joints, act, residual
