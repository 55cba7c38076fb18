"""The reverse-order pass's context: what a structural group's reactions work with.

:class:`ReactionContextBase` is the contract between the groups'
:meth:`~assur.groups.base.Group.reactions` and whoever evaluates them: the array pass
of :mod:`assur.core.statics` (:class:`~assur.core.statics.ReactionContext`), the
outputs contract and its fused kernel (:mod:`assur.core.outputs`) and the dual
numbers of :mod:`assur.synthesis.sensitivity` all subclass it, so one implementation
of each group's statics serves every kind of number.
"""

from __future__ import annotations

__all__ = ["ReactionContextBase"]


class ReactionContextBase:
    """What a group's :meth:`~assur.groups.base.Group.reactions` works with, in the
    reverse-order pass: the loads accumulated on every body (as wrenches about the
    origin), the joint reactions recorded so far and the actuator forces.

    The group code is plain arithmetic and numpy ufuncs on what the context gives, so
    that one implementation serves both :class:`ReactionContext` (arrays over designs
    and positions) and the generated fused kernel (:mod:`assur.core.outputs`, symbols).
    Subclasses provide ``point``, ``value``, ``record``, ``inv`` and ``shape``.

    Attributes
    ----------
    links : tuple of str
        The links of the group being solved (:attr:`assur.core.topology.Topology.group_links`).
    shape : tuple of int
        ``(m, n)``: designs and positions.

    Examples
    --------
    The concrete context over arrays, :class:`ReactionContext`, on the hitch:

    >>> from assur import examples
    >>> from assur.core.statics import ReactionContext
    >>> r = ReactionContext(examples.hitch_003().solve([0.42]), set())
    >>> r.apply("6", "S6", 0.0, -27500.0)          # P6 at S6 [N]
    >>> fx, fy, mo = r.wrench("6")
    >>> float(fy), round(float(mo[0, 0]))          # [N], about the origin [N·m]
    (-27500.0, -54788)
    """

    def __init__(self, mech, rod_ends):
        self.mech = mech
        self.links = ()
        self.W = {b: [0.0, 0.0, 0.0] for b in mech.topology.bodies}
        self.joints = {}
        self.act = {}
        self._rod_ends = rod_ends
        self._at = {}  # (link, point) -> loads applied there, for a cylinder's axial force

    def owner(self, p):
        """The body that owns a point.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42]), set())
        >>> r.owner("S6"), r.owner("45")   # 45: the outer joint of dyad II (4,5)
        ('6', '5')
        """
        return self.mech.owner(p)

    def is_coord(self, ref):
        """True if ``ref`` names a generalized coordinate.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42]), set())
        >>> r.is_coord("S"), r.is_coord("L3"), r.is_coord(0.2)
        (True, False, False)
        """
        return isinstance(ref, str) and ref in self.mech.coordinates

    def wrench(self, body):
        """Loads on a body: (Fx, Fy, moment about the origin) [N, N·m].

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42]), set())
        >>> r.wrench("3")                        # nothing applied yet
        (0.0, 0.0, 0.0)
        >>> r.apply_moment("3", 10.0)            # [N·m]
        >>> r.wrench("3")
        (0.0, 0.0, 10.0)
        """
        return tuple(self.W[body])

    def about(self, body, cx, cy):
        """Loads on a body: (Fx, Fy, moment about the point c).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42]), set())
        >>> r.apply("6", "S6", 0.0, -27500.0)                # P6 at S6 [N]
        >>> x, y = r.point("S6")
        >>> round(float(r.about("6", x, y)[2][0, 0]), 6)     # about S6 itself [N·m]
        0.0
        >>> round(float(r.about("6", 0.0, y)[2][0, 0]))      # = −P6·XS6 [N·m]
        -54788
        """
        fx, fy, mo = self.W[body]
        return fx, fy, mo - (cx * fy - cy * fx)

    def apply(self, body, pt, fx, fy):
        """Add the force (fx, fy) at point ``pt`` to ``body``'s loads.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42]), set())
        >>> r.apply("6", "S6", 0.0, -27500.0)      # P6 at S6 [N]
        >>> x, _ = r.point("S6")
        >>> round(float(x[0, 0]), 3)                # XS6 [m]
        1.992
        >>> round(float(r.wrench("6")[2][0, 0]))    # −P6·XS6 about the origin [N·m]
        -54788
        """
        px, py = self.point(pt)
        w = self.W[body]
        w[0] = w[0] + fx
        w[1] = w[1] + fy
        w[2] = w[2] + px * fy - py * fx
        if (body, pt) in self._rod_ends:
            f = self._at.setdefault((body, pt), [0.0, 0.0])
            f[0] = f[0] + fx
            f[1] = f[1] + fy

    def apply_moment(self, body, M):
        """Add a moment M [N·m] to ``body``'s loads.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42]), set())
        >>> r.apply_moment("3", 10.0)
        >>> r.apply_moment("3", -4.0)
        >>> r.wrench("3")[2]                     # [N·m]
        6.0
        """
        self.W[body][2] = self.W[body][2] + M

    def axial(self, cyl, end, fx, fy, ux, uy):
        """A cylinder's push from the force (fx, fy) its rod end ``end`` exerts on the
        next link, less what the loads applied at that end to the cylinder take.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42]), {("2", "23")})
        >>> float(r.axial("2", "23", 300.0, 400.0, 0.6, 0.8))   # (300, 400)·u [N]
        500.0
        >>> r.apply("2", "23", 100.0, 0.0)      # a load on the cylinder at its rod end [N]
        >>> float(r.axial("2", "23", 300.0, 400.0, 0.6, 0.8))   # (200, 400)·u [N]
        440.0
        """
        lx, ly = self._at.get((cyl, end), (0.0, 0.0))
        return (fx - lx) * ux + (fy - ly) * uy

    def actuator(self, coordinate, F):
        """Add the generalized force F of an actuator of ``coordinate`` [N or N·m]
        (several actuators of one coordinate — a double-rod cylinder — add up).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42]), set())
        >>> r.actuator("S", 100.0)
        >>> r.actuator("S", 50.0)    # a second actuator of S [N]
        >>> r.act
        {'S': 150.0}
        """
        prev = self.act.get(coordinate)
        self.act[coordinate] = F if prev is None else prev + F
