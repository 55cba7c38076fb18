"""Every output quantity's formula (:mod:`assur.core.outputs`): the
:class:`OutputContext` over a reverse-pass context, evaluated in the context's kind of
number — symbols of the fused kernel's generated code, the dual numbers of
:mod:`assur.synthesis.sensitivity`, the design criteria's.
"""

from __future__ import annotations

import numpy as np

from ...errors import ModelError
from .. import cylinders as C
from ..gravity import gravity_unit
from ..loads import centre_of_mass, is_dead, masses_of
from ..reactions import ReactionContextBase
from ._notation import formula_of

class OutputContext(ReactionContextBase):
    """The outputs of :data:`OUTPUT_UNITS` as formulas of a reverse-pass context: one
    home for them, shared by the fused kernel's symbols (:class:`_Fused`) and the dual
    numbers of :mod:`assur.synthesis.sensitivity`.

    Subclasses provide, besides :class:`~assur.core.statics.ReactionContextBase`'s needs,
    ``jet(p, a)`` (the analogs ∂(X, Y)/∂q_a of a point), ``has_point(p)`` and
    ``select(x, a, b)`` (``a`` where x ≥ 0, else ``b``, in the context's numbers).
    :meth:`apply_loads` fills ``vw`` (the generalized forces of the loads, one per
    coordinate [N or N·m]) and ``vw_dead`` (those of the dead loads).

    Examples
    --------
    :func:`assur.synthesis.sensitivity.jet_context` gives the context over dual numbers (its
    ``plain`` turns a value into arrays); the fused kernel's is the same over symbols:

    >>> from assur import examples
    >>> from assur.synthesis.sensitivity import jet_context
    >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67])   # S [m]
    >>> F, _ = ctx.plain(ctx.output("F", ("S",)))               # Fgc [N], table 4.1
    >>> [round(float(v)) for v in F[0]]
    [129614, 135652]
    """

    def __init__(self, mech, rod_ends):
        super().__init__(mech, rod_ends)
        self.gravity_unit = gravity_unit(mech)
        self.moving = False
        self.k = len(mech.coordinates)
        self.vw = [0.0] * self.k
        #: the generalized forces of the dead loads alone (``[tables] dead_loads``)
        self.vw_dead = [0.0] * self.k
        self._dead = False
        self._frame = frozenset(mech.frame_points)

    def apply_loads(self):
        """Apply the mechanism's loads (:mod:`assur.core.loads`): their wrenches on the
        bodies, their generalized forces ``vw`` and, for the dead loads, ``vw_dead``.

        Examples
        --------
        The loader of seed 001 lab 1 carries the boom's own mass as a dead load:

        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.loader_lab1(), [[1.0, 0.9]], reactions=False)  # S, S1 [m]
        >>> F, _ = ctx.plain(-ctx.vw[0])            # all the loads along S [N]
        >>> Fd, _ = ctx.plain(-ctx.vw_dead[0])      # the boom's weight alone [N]
        >>> bool(0 < Fd[0, 0] < F[0, 0])
        True
        """
        for ld in self.mech.loads:
            self._dead = is_dead(self.mech, ld)
            ld.apply(self)
        self._dead = False

    def select(self, x, a, b):
        """``a`` where x ≥ 0, else ``b``, in this context's numbers (a subclass's).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.hitch_003(), [0.42])
        >>> float(ctx.select(-2.0, 1.0, -1.0))
        -1.0
        """
        raise NotImplementedError

    def has_point(self, p):
        """Whether the mechanism has point ``p`` (a subclass's; the outputs check it).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67])   # S [m], table 2.1
        >>> ctx.has_point("56"), ctx.has_point("99")
        (True, False)
        """
        raise NotImplementedError

    def cylinder_terms(self, name):
        """The constants of cylinder ``name`` in this context's numbers
        (:func:`assur.core.cylinders.terms`); raises :class:`ModelError` naming the
        cylinders for an unknown one.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67])   # S [m], table 2.1
        >>> t = ctx.cylinder_terms("ГЦ")
        >>> t.cylinder.name, round(float(t.area_piston) * 1e4, 2)  # [cm²]
        ('ГЦ', 50.27)
        """
        cyls = {c.name: c for c in self.mech.cylinders}
        if name not in cyls:
            raise ModelError(f"output …({name}): no cylinder {name!r}; cylinders: "
                             f"{sorted(cyls)}")
        return C.terms(cyls[name], self.value)

    def record(self, i, j, pt, fx, fy, mz=0.0):
        """Keep the force (fx, fy) [N] and moment mz [N·m] of link ``i`` on link ``j``
        at point ``pt`` (a group's reactions call it; ``Rx(i, j)`` reads it).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67])   # S [m], table 2.1
        >>> ctx.record("9", "8", "56", 1.0, 2.0)
        >>> ctx.joints[("9", "8")]
        ('56', 1.0, 2.0, 0.0)
        """
        self.joints[(i, j)] = (pt, fx, fy, mz)

    # loads (assur.core.loads contract): the wrench on the body and the virtual work ------
    def force(self, link, point, fx, fy):
        """A load's force (fx, fy) [N] on ``link`` at ``point``: into the link's wrench
        and, through the point's analogs, into the generalized forces ``vw``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67])   # S [m], table 2.1
        >>> before, _ = ctx.plain(ctx.vw[0])
        >>> ctx.force("5", "56", 0.0, -1000.0)          # 1 kN down at the axis 56
        >>> after, _ = ctx.plain(ctx.vw[0])
        >>> I, _ = ctx.plain(ctx.output("I", ("56",)))  # dY56/dS [m/m], table 3.1
        >>> bool(abs((after - before)[0, 0] + 1000.0 * I[0, 0]) < 1e-6)
        True
        """
        self.apply(link, point, fx, fy)
        if point not in self._frame:  # a frame point does not move: no work
            for a in range(self.k):
                jx, jy = self.jet(point, a)
                w = fx * jx + fy * jy
                self.vw[a] = self.vw[a] + w
                if self._dead:
                    self.vw_dead[a] = self.vw_dead[a] + w

    def couple(self, link, M):
        """A load's couple M [N·m] on ``link``: into its wrench and, through the link's
        angular analog, into ``vw``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67])   # S [m], table 2.1
        >>> before, _ = ctx.plain(ctx.vw[0])
        >>> ctx.couple("3", 100.0)
        >>> after, _ = ctx.plain(ctx.vw[0])
        >>> w, _ = ctx.plain(ctx.omega("3", 0))            # dφ3/dS [rad/m]
        >>> bool(abs((after - before)[0, 0] - 100.0 * w[0, 0]) < 1e-9)
        True
        """
        self.apply_moment(link, M)
        for a in range(self.k):
            w = M * self.omega(link, a)
            self.vw[a] = self.vw[a] + w
            if self._dead:
                self.vw_dead[a] = self.vw_dead[a] + w

    def spring(self, load, T, L):
        """A spring's tension T [N] at length L [m] (its forces come through
        :meth:`force`); nothing more is needed by the outputs.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67])   # S [m], table 2.1
        >>> ctx.spring(None, 10.0, 0.3) is None
        True
        """

    def rate(self, link, coordinate=None):
        """∂φ/∂q of a link along a coordinate (the only one by default) [rad/m or
        rad/rad].

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67])   # S [m], table 2.1
        >>> w, _ = ctx.plain(ctx.rate("3"))
        >>> [round(float(v), 3) for v in w[0]]
        [6.719, 6.239]
        """
        a = 0 if coordinate is None else self.mech.coordinates.index(coordinate)
        return self.omega(link, a)

    def omega(self, body, a):
        """Angular analog ∂φ/∂q_a of a body (0 for the frame) [rad/m or rad/rad].

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67])   # S [m], table 2.1
        >>> w, _ = ctx.plain(ctx.omega("3", 0))
        >>> [round(float(v), 3) for v in w[0]], ctx.omega("0", 0)
        ([6.719, 6.239], 0.0)
        """
        pq = self.mech.topology.angle_points(body)
        if pq is None:
            return 0.0
        (px, py), (qx, qy) = self.point(pq[0]), self.point(pq[1])
        (pxa, pya), (qxa, qya) = self.jet(pq[0], a), self.jet(pq[1], a)
        dx, dy = qx - px, qy - py
        return (dx * (qya - pya) - dy * (qxa - pxa)) / (dx * dx + dy * dy)

    # outputs ------------------------------------------------------------------------
    def coord_index(self, args, fn):
        """Index of the coordinate an analog output names (``dY(p, S)``), or 0 with
        one coordinate; raises :class:`ModelError` otherwise.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67])   # S [m], table 2.1
        >>> ctx.coord_index(("56",), "dY"), ctx.coord_index(("56", "S"), "dY")
        (0, 0)
        >>> ctx.coord_index(("56", "T"), "dY")
        Traceback (most recent call last):
            ...
        assur.errors.ModelError: output dY('56', 'T'): 'T' is not a coordinate ('S',)
        """
        if len(args) > 1:
            if args[1] not in self.mech.coordinates:
                raise ModelError(f"output {fn}{args}: {args[1]!r} is not a coordinate "
                                 f"{self.mech.coordinates}")
            return self.mech.coordinates.index(args[1])
        if self.k > 1:
            raise ModelError(f"output {fn}({args[0]}): name the coordinate, e.g. "
                             f"{fn}({args[0]}, {self.mech.coordinates[0]})")
        return 0

    def angle_points(self, link):
        """The two points whose direction is the angle of ``link`` (a named link of
        ``[links]``, else a body of the topology).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67])   # S [m], table 2.1
        >>> ctx.angle_points("3")
        ('03', '23')
        """
        for lk in self.mech.links:
            if lk.name == link:
                return lk.tail, lk.head
        pq = self.mech.topology.angle_points(link) if link in self.mech.topology.bodies \
            else None
        if pq is None:
            raise ModelError(f"no link {link!r} with an angle; links: "
                             f"{[l.name for l in self.mech.links]} and bodies "
                             f"{[b for b in self.mech.topology.bodies if b != '0']}")
        return pq

    def formula_terms(self):
        """The kinematic quantities of a :class:`assur.core.columns.Formula` as this
        context's values (the outputs ``X``, ``Y``, ``I``, ``phi``, ``dphi``,
        ``length``, ``dlength``; second analogs are not in the fused kernel).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.outputs import formula_of
        >>> from assur.synthesis.sensitivity import jet_context
        >>> m = examples.hitch_003()
        >>> ctx = jet_context(m, [0.42])
        >>> v = formula_of(m, "GS6max").compute(ctx.formula_terms())
        >>> round(float(ctx.plain(v)[0][0, 0]))         # [N], seed 003 table 6.1
        50645
        """
        def out(fn):
            return lambda ref: self.output(fn, (ref,))

        def second(ref):
            raise ModelError(f"ddphi({ref}): second analogs are not outputs of the fused "
                             f"kernel; a formula with ddphi is a report column only")
        return {"X": out("X"), "Y": out("Y"), "I": out("I"), "phi": out("phi"),
                "dphi": out("dphi"), "ddphi": second, "dist": out("length"),
                "ddist": out("dlength"), "name": self.value}

    def output(self, fn, args):
        """The value of output ``fn(args)`` (the module docstring's table) in this
        context's kind of number [SI].

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67])   # S [m], table 2.1
        >>> G, _ = ctx.plain(ctx.output("G", ("ГЦ", "S6")))   # GS6 [N], table 4.1
        >>> [round(float(v)) for v in G[0]]
        [31354, 29959]
        """
        if fn in ("X", "Y", "dX", "dY", "I") and not self.has_point(args[0]):
            raise ModelError(f"output {fn}({', '.join(args)}): unknown point {args[0]!r}")
        if fn in ("X", "Y"):
            return self.point(args[0])[fn == "Y"]
        if fn in ("dX", "dY", "I"):
            return self.jet(args[0], self.coord_index(args, fn))[fn != "dX"]
        if fn in ("phi", "dphi"):
            P, Q = self.angle_points(args[0])
            (px, py), (qx, qy) = self.point(P), self.point(Q)
            if fn == "phi":
                return np.arctan2(qy - py, qx - px)
            a = self.coord_index(args, fn)
            (pxa, pya), (qxa, qya) = self.jet(P, a), self.jet(Q, a)
            dx, dy = qx - px, qy - py
            return (dx * (qya - pya) - dy * (qxa - pxa)) / (dx * dx + dy * dy)
        if fn in ("length", "dlength"):
            dd = [x for x in self.mech.distances if x.name == args[0]]
            if not dd:
                raise ModelError(f"no distance {args[0]!r}; distances: "
                                 f"{[x.name for x in self.mech.distances]}")
            (ax, ay), (bx, by) = self.point(dd[0].a), self.point(dd[0].b)
            L = np.hypot(bx - ax, by - ay)
            if fn == "length":
                return L
            a = self.coord_index(args, fn)
            (axa, aya), (bxa, bya) = self.jet(dd[0].a, a), self.jet(dd[0].b, a)
            return ((bx - ax) * (bxa - axa) + (by - ay) * (bya - aya)) / L
        if fn in ("Xc", "Yc"):  # 001 lab 3: r_c = Σ m_i·r_i / Σ m_i (assur.dynamics.balancing)
            masses = masses_of(self.mech)
            if not masses:
                raise ModelError(f"output {fn}: mechanism {self.mech.name!r} has no masses "
                                 f"on moving links ([[loads]] of type \"mass\")")
            return centre_of_mass(masses, self.value, self.point)[fn == "Yc"]
        if fn == "formula":
            return formula_of(self.mech, args[0]).compute(self.formula_terms())
        if fn == "Fdead":  # internal (no output's text names it): W's first pass
            return -self.vw_dead[self.mech.coordinates.index(args[0])]
        if fn in ("F", "Fr"):
            if args[0] not in self.mech.coordinates:
                raise ModelError(f"output {fn}({args[0]}): not a coordinate "
                                 f"{self.mech.coordinates}")
            if fn == "F":
                return -self.vw[self.mech.coordinates.index(args[0])]
            return self.act.get(args[0], 0.0)
        if fn in ("Rx", "Ry", "R", "Rm"):
            key = (args[0], args[1])
            if key not in self.joints:
                raise ModelError(f"output {fn}({args[0]}, {args[1]}): no joint of link "
                                 f"{args[0]!r} on link {args[1]!r}; joints: "
                                 f"{sorted(self.joints)}")
            _, fx, fy, mz = self.joints[key]
            return {"Rx": fx, "Ry": fy, "Rm": mz}.get(fn) if fn != "R" else np.hypot(fx, fy)
        return self.cylinder_output(fn, args)

    def cylinder_output(self, fn, args):
        """``p``, ``G`` or ``reserve`` of a cylinder: the formulas of
        :mod:`assur.core.cylinders` on this context's actuator and dead-load forces
        and transmission numbers.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.hitch_003(), [0.42, 0.67])   # S [m], table 2.1
        >>> p, _ = ctx.plain(ctx.cylinder_output("p", ("ГЦ",)))     # Pgc, table 4.1 [MPa]
        >>> [round(float(v) / 1e6, 2) for v in p[0]]
        [15.35, 16.06]
        """
        t = self.cylinder_terms(args[0])
        c = t.cylinder
        if c.supply is not None:
            if fn != "p":
                raise ModelError(f"output {fn}({', '.join(args)}): cylinder {c.name!r} shares "
                                 f"the supply line {c.supply!r}: its capacity at one point is "
                                 f"not defined (the line's pressure is)")
            return self.line_pressure(c.supply)
        j = self.mech.coordinates.index(c.coordinate)
        F = -self.vw[j]
        if fn == "p":
            return C.pressure(t, F, self.select)  # seed 003: Pgc = Fgc/(k_gc·S_gc·η)
        if not self.has_point(args[1]):
            raise ModelError(f"output {fn}(…): unknown point {args[1]!r}")
        # in the working direction of the stroke: W decides side = "auto"'s chamber once
        # per stroke (assur.core.cylinders.stroke_work)
        W = self.stroke_load(c) if c.side == "auto" else 1.0
        G = C.capacity(t, W, -self.vw_dead[j], self.jet(args[1], j)[1],
                       self.select)  # seed 003 G56, GS6
        if fn == "G":
            return G
        return C.reserve(G, self.value(args[2] if not _is_float(args[2]) else float(args[2])))

    def stroke_load(self, cyl):
        """W of a ``side = "auto"`` cylinder ``cyl``: its payload's actuator force summed
        over the positions of each design's stroke [N]
        (:func:`assur.core.cylinders.stroke_work`), one value per design — a
        subclass's: the fused kernel reads it from its parameter table (computed by a
        first pass over the positions), the dual numbers sum their values.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> m = examples.steering_lab4_modern()
        >>> ctx = jet_context(m, [0.0, 0.02])                # S [m]
        >>> ctx.stroke_load(m.cylinders[0]).shape            # one per design
        (1, 1)
        """
        raise NotImplementedError

    def line_pressure(self, line):
        """Pressure of supply line ``line`` [Pa] (:func:`assur.core.cylinders.line_pressure`,
        the passive cylinders' ∂L/∂q from their distances' analogs).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.sensitivity import jet_context
        >>> ctx = jet_context(examples.steering_lab4(), [0.51, 0.662])   # S1 [m]
        >>> p, _ = ctx.plain(ctx.line_pressure("P"))                       # [MPa]
        >>> [round(float(v) / 1e6, 3) for v in p[0]]
        [6.353, 8.294]
        """
        cyls = [c for c in self.mech.cylinders if c.supply == line]
        driver = next(c for c in cyls if c.coordinate is not None)
        j = self.mech.coordinates.index(driver.coordinate)
        wrt = (driver.coordinate,) if self.k > 1 else ()
        members = [(self.cylinder_terms(c.name),
                    1.0 if c is driver else self.output("dlength", (c.distance,) + wrt))
                   for c in cyls]
        return C.line_pressure(members[cyls.index(driver)][0], -self.vw[j], members)


def _is_float(s):
    try:
        float(s)
        return True
    except ValueError:
        return False
