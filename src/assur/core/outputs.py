"""The fused kinematics + statics kernel: only the outputs asked for, reductions over
positions in the kernel (DESIGN.md §10).

:func:`evaluate` (``Mechanism.evaluate``, or ``Mechanism.analyze(..., outputs=…)``)
generates one kernel per structure and set of outputs. For every element (design,
position) it runs the groups' position and jet code (forward), the loads and the
actuator forces by virtual work, the joint reactions group by group in reverse order
(each group's own :meth:`~assur.groups.base.Group.reactions`, traced into the kernel
by :mod:`assur.kernel.sym`, the same code that the array pass of :mod:`assur.core.statics`
runs), and writes only the requested outputs — or, with ``reduce``, only their
minimum/maximum and where they occur over the positions of each design, so that a
sweep of millions of designs stores no positions at all.

Outputs are written as function calls (units SI):

=======================  ==============================================================
``X(p)``, ``Y(p)``       coordinates of point p [m]
``dX(p)``, ``dY(p)``     first analogs ∂x/∂q, ∂y/∂q (``dY(p, S)`` for k > 1) [m/m, m/rad]
``I(p)``                 transmission number dY/dq of p (= ``dY(p)``)
``phi(l)``               angle of link l in (−π, π] (unwrapped along stored positions) [rad]
``dphi(l)``              its analog dφ/dq [rad/m or rad/rad]
``length(d)``            a named distance [m]; ``dlength(d)`` its analog dd/dq [m/m, m/rad]
``F(c)``                 actuator force of coordinate c by virtual work [N or N·m]
``Fr(c)``                the same from the joint reactions [N or N·m]
``Rx(i, j)``, ``Ry``     force of link i on link j [N]; ``R(i, j)`` its magnitude,
                         ``Rm(i, j)`` the moment at a prismatic pair or crank drive [N·m]
``p(cyl)``               pressure of cylinder ``cyl``, σ·F/(η_m·k·A·η_h), or of its
                         supply line [Pa]
``G(cyl, p)``            lift capacity at point p, (σ·k·p_max·A·η_h·η_m − F_dead)/I(p)
                         [N]
``reserve(cyl, p, P)``   capacity reserve (G − P)/P·100 for a load P (number or
                         parameter) [%]
``Xc``, ``Yc``           the common centre of mass of the masses on moving links,
                         Σ m_i·r_i / Σ m_i (001 lab 3, :mod:`assur.dynamics.balancing`) [m]
``name``                 a formula of the model's ``[[tables.formulas]]`` by its name
                         (:class:`assur.core.columns.Formula`), e.g. ``p_c`` [SI of its unit]
=======================  ==============================================================

The cylinder outputs are the formulas of :mod:`assur.core.cylinders` (the one home of
a cylinder's quantities: the chamber of ``side``, ``"auto"`` included, double rods,
counts, supply lines, the model's dead loads ``[tables] dead_loads``), evaluated in
the context's kind of number; the reports' :class:`assur.machines.cylinders.CylinderResult`
calls the same formulas over arrays.

Static loads only (weights, forces, moments, springs, the weights of masses); the
fused kernel does not check continuity between positions (``solve`` does).
"""

from __future__ import annotations

import dataclasses
import functools
import re

import numpy as np

from . import diagnostics
from ..errors import ModelError
from ..groups import group_type
from ..groups.base import is_number
from . import cylinders as C
from .loads import centre_of_mass, dead_load_links, is_dead, masses_of
from ..kernel import run as KR
from ..kernel.cache import helpers_tag, load_source
from ..kernel.emit import Emitter
from ..kernel.select import branchless
from ..kernel.fold import fold
from ..kernel.source import BUF_ROW, CHUNK, chunk_loop, copy_out, hoisted, status_out
from ..kernel.stream import STREAM_MIN
from ..kernel.sym import Sym, Tracer, code
from .gravity import GRAVITY, gravity_unit
from .reactions import ReactionContextBase

__all__ = ["evaluate", "Fused", "OutputContext", "OUTPUT_UNITS", "REDUCTIONS", "parse_output",
           "resolve_output", "output_unit", "display_unit", "formula_of"]

FORMAT = "8"
REDUCTIONS = ("min", "max", "argmin", "argmax")
#: unit of each output function (SI; "q" stands for the coordinate's unit)
OUTPUT_UNITS = {"X": "m", "Y": "m", "dX": "m/q", "dY": "m/q", "I": "m/q", "phi": "rad",
                "dphi": "rad/q", "length": "m", "dlength": "m/q", "F": "N", "Fr": "N",
                "Rx": "N", "Ry": "N", "R": "N", "Rm": "N·m", "p": "Pa", "G": "N",
                "reserve": "%", "Xc": "m", "Yc": "m", "formula": "SI"}
_ARITY = {"X": (1,), "Y": (1,), "dX": (1, 2), "dY": (1, 2), "I": (1, 2), "phi": (1,),
          "dphi": (1, 2), "length": (1,), "dlength": (1, 2), "F": (1,), "Fr": (1,),
          "Rx": (2,), "Ry": (2,), "R": (2,), "Rm": (2,), "p": (1,), "G": (2,),
          "reserve": (3,), "Xc": (0,), "Yc": (0,)}
_CALL = re.compile(r"^\s*([A-Za-z]+)\s*\((.*)\)\s*$")
_NAME = re.compile(r"^\s*([^\W\d]\w*)\s*$")


@functools.lru_cache(maxsize=4096)
def parse_output(text: str) -> tuple:
    """``"Rx(0, 5)"`` → ``("Rx", ("0", "5"))``, ``"Xc"`` → ``("Xc", ())``, the name of
    a formula ``"p_c"`` → ``("formula", ("p_c",))`` (whether the model has it is checked
    where the mechanism is known); raises :class:`ModelError`.

    Examples
    --------
    >>> from assur.core.outputs import parse_output
    >>> parse_output("Rx(0, 5)"), parse_output("Xc"), parse_output("p_c")
    (('Rx', ('0', '5')), ('Xc', ()), ('formula', ('p_c',)))
    >>> parse_output("Q(56)")
    Traceback (most recent call last):
        ...
    assur.errors.ModelError: unknown output 'Q(56)': expected one of X(…), Y(…), dX(…), dY(…), I(…), phi(…), dphi(…), length(…), dlength(…), F(…), Fr(…), Rx(…), Ry(…), R(…), Rm(…), p(…), G(…), reserve(…), Xc, Yc or the name of a formula of the model's [[tables.formulas]]
    """
    bare = _NAME.match(str(text))
    if bare:
        name = bare.group(1)
        return (name, ()) if _ARITY.get(name) == (0,) else ("formula", (name,))
    m = _CALL.match(str(text))
    if not m or m.group(1) not in _ARITY:
        raise ModelError(f"unknown output {text!r}: expected one of "
                         f"{', '.join(f + ('' if _ARITY[f] == (0,) else '(…)') for f in _ARITY)}"
                         f" or the name of a formula of the model's [[tables.formulas]]")
    args = tuple(a.strip().strip("'\"") for a in m.group(2).split(",")) if m.group(2).strip() \
        else ()
    if len(args) not in _ARITY[m.group(1)]:
        raise ModelError(f"output {text!r}: {m.group(1)} takes "
                         f"{' or '.join(map(str, _ARITY[m.group(1)]))} argument(s)")
    return m.group(1), args


def formula_of(mech, name):
    """The :class:`assur.core.columns.Formula` of ``mech`` named ``name``; raises
    :class:`ModelError` naming the formulas it has.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.outputs import formula_of
    >>> formula_of(examples.hitch_003(), "GS6max").unit          # seed 003 table 6.1
    'N'
    """
    from .columns import formulas_of
    fs = formulas_of(mech)
    for f in fs:
        if f.name == name:
            return f
    raise ModelError(f"unknown output {name!r}: model {mech.name!r} has no formula of that "
                     f"name (its [[tables.formulas]]: {[f.name for f in fs] or 'none'}); "
                     f"the outputs are " + ", ".join(
                         f + ("" if _ARITY[f] == (0,) else "(…)") for f in _ARITY))


def resolve_output(mech, text) -> tuple:
    """:func:`parse_output` of ``text`` for ``mech``: a formula's name becomes
    ``("formula", (name, expression))`` — the expression is part of the kernel's key —
    after checking that ``mech`` has it and that its names exist.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.outputs import resolve_output
    >>> m = examples.hitch_003()
    >>> resolve_output(m, "G(ГЦ, S6)")
    ('G', ('ГЦ', 'S6'))
    >>> resolve_output(m, "GS6max")[1][1]                       # the expression: its key
    '(P_mcxa*b + P_gr*(a + L) - 0.2*(P6 + P_mcxa + P_gr)) / X(S6)'
    """
    fn, args = text if isinstance(text, tuple) else parse_output(text)
    if fn == "formula":
        f = formula_of(mech, args[0])
        f.check(mech)
        return fn, (f.name, f.expr)
    return fn, args


def output_unit(mech, text) -> str:
    """The SI unit of an output's values: ``"q"`` of :data:`OUTPUT_UNITS` becomes the
    coordinate's unit (``m`` for a cylinder, ``rad`` for a crank), ``F``/``Fr`` of an
    angle coordinate are moments [N·m]; a formula's own unit when its scale is 1,
    else ``"SI"``.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.outputs import output_unit
    >>> m = examples.hitch_003()
    >>> output_unit(m, "p(ГЦ)"), output_unit(m, "dY(56)"), output_unit(m, "GS6max")
    ('Pa', 'm/m', 'N')
    >>> output_unit(examples.combine_002(), "F(j1)")      # the crank's driving moment
    'N·m'
    """
    fn, args = resolve_output(mech, text)
    if fn == "formula":
        f = formula_of(mech, args[0])
        return f.unit if f.scale == 1.0 else "SI"
    u = OUTPUT_UNITS[fn]
    if "q" in u:
        c = args[1] if len(args) > 1 else mech.coordinates[0]
        u = u.replace("q", "rad" if mech.coordinate_kind(c) == "angle" else "m")
    if fn in ("F", "Fr") and mech.coordinate_kind(args[0]) == "angle":
        u = "N·m"
    return u


def display_unit(mech, text):
    """The :class:`assur.core.quantities.Unit` to show an output in: a formula's own unit
    and scale (``p_c`` in kN/m if the formula says so), else :func:`output_unit`.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.outputs import display_unit
    >>> m = examples.hitch_003()
    >>> display_unit(m, "GS6max").text, display_unit(m, "dY(56)").text
    ('N', 'm/m')
    """
    from .quantities import Unit
    fn, args = resolve_output(mech, text)
    if fn == "formula":
        f = formula_of(mech, args[0])
        return Unit(f.unit, f.scale)
    return Unit(output_unit(mech, (fn, args)))


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
        G = C.capacity(t, F, -self.vw_dead[j], self.jet(args[1], j)[1],
                       self.select)  # seed 003 G56, GS6
        if fn == "G":
            return G
        return C.reserve(G, self.value(args[2] if not _is_float(args[2]) else float(args[2])))

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



class _Fused(OutputContext):
    """Load and reaction context whose values are symbols of the generated code."""

    def __init__(self, mech, prog, tracer, rod_ends, literal_rows):
        super().__init__(mech, rod_ends)
        self.prog, self.t = prog, tracer
        self.literal_rows = literal_rows
        self.g = self.value(_G)

    # values ------------------------------------------------------------------------
    def point(self, p):
        s = self.prog.slot[p]
        return self.t.sym(f"x{s}"), self.t.sym(f"y{s}")

    def jet(self, p, a):
        s = self.prog.slot[p]
        return self.t.sym(f"x{s}_{a}"), self.t.sym(f"y{s}_{a}")

    def value(self, ref):
        """A coordinate, a parameter, or a number: the numbers of loads and cylinders are
        rows of the parameter table too (:func:`_literals`), so one kernel serves any
        of their values."""
        if isinstance(ref, str):
            if ref in self.mech.coordinates:
                return self.t.sym(f"q[{self.mech.coordinates.index(ref)}, e]")
            if ref == _G:
                return self.t.sym(f"params[{self.literal_rows[_G]}, d]")
            return self.t.sym(f"params[{self.prog.param_row(ref)}, d]")
        v = float(ref)
        if v in self.literal_rows:  # a number of the loads (first: rows fixed by them)
            return self.t.sym(f"params[{self.literal_rows[v]}, d]")
        if v in self.prog.literals:
            return self.t.sym(f"params[{self.prog.param_row(v)}, d]")
        return v   # a number of an output's text (a reserve's load): part of its key

    def inv(self, x):
        if isinstance(x, Sym):
            return self.t.new(f"1.0 / {x.name} if {x.name} != 0.0 else 0.0")
        return 1.0 / x if x != 0 else 0.0

    def nonzero(self, L, what):
        """Coincident spring ends give a non-finite element, caught after the kernel."""

    def has_point(self, p):
        return p in self.prog.slot

    def select(self, x, a, b):
        if not isinstance(x, Sym):
            return a if x >= 0 else b
        return self.t.new(f"{code(a)} if {x.name} >= 0.0 else {code(b)}")


_G = "__gravity__"


def _valued(mech):
    """The loads and cylinders of a mechanism: the descriptions whose numbers are rows
    of the fused kernel's parameter table."""
    return tuple(mech.loads) + tuple(mech.cylinders)


def _literals(mech, g, n0):
    """Rows (from ``n0``) of gravity and of every number the loads and cylinders give,
    and their values: ``({value or _G: row}, [values])`` in a fixed order."""
    rows, values = {_G: n0}, [float(g)]
    for ld in _valued(mech):
        for f in dataclasses.fields(ld):
            v = getattr(ld, f.name)
            if is_number(v) and float(v) not in rows:
                rows[float(v)] = n0 + len(values)
                values.append(float(v))
    return rows, values


def _load_signature(mech):
    """The loads and cylinders with each number replaced by the index of its value among
    their distinct numbers (the kernel's structure: which rows it reads, not their
    values)."""
    seen: dict = {}
    out = []
    for ld in _valued(mech):
        sig = [type(ld).__name__]
        for f in dataclasses.fields(ld):
            v = getattr(ld, f.name)
            sig.append(("#", seen.setdefault(float(v), len(seen))) if is_number(v) else v)
        out.append(tuple(sig))
    return tuple(out)


def joint_list(mech):
    """The joints of a mechanism's reverse-order pass, ``((i, j, point), …)`` (force of
    link i on link j at the point), traced once and kept with the mechanism."""
    return mech.memo(("outputs", "joints"), lambda: tuple(
        (i, j, pt) for (i, j), (pt, *_r) in _trace_reactions(mech).joints.items()))


def has_actuator(mech, c):
    """True if the reverse pass gives an actuator force for coordinate ``c``."""
    return c in mech.memo(("outputs", "actuators"), lambda: frozenset(_trace_reactions(mech).act))


def _trace_reactions(mech):
    """The reaction context after tracing the loads and the reverse pass (into a
    throw-away emitter: only its joints and actuators are read)."""
    prog = mech.program()
    n0 = len(prog.param_names) + len(prog.literals) + prog.n_derived
    literal_rows, _ = _literals(mech, GRAVITY, n0)
    topo = mech.topology

    def is_coord(ref):
        return isinstance(ref, str) and ref in mech.coordinates

    rod_ends = {e for g_ in mech.groups for e in g_.rod_ends(topo.group_links[g_.name],
                                                               is_coord)}
    ctx = _Fused(mech, prog, Tracer(Emitter(prog.k, order=1)), rod_ends, literal_rows)
    ctx.apply_loads()
    for g_ in reversed(mech.groups):
        ctx.links = topo.group_links[g_.name]
        g_.reactions(ctx)
    return ctx


def _is_float(s):
    try:
        float(s)
        return True
    except ValueError:
        return False


_KERNELS: dict = {}


def _source(mech, prog, specs, reduce, g):
    """Source of the fused kernel (see the module docstring)."""
    K = prog.k
    E = Emitter(K, order=1)  # the outputs need first-order analogs at most
    for i, row in enumerate(prog.rows):
        group_type(row[0]).emit(E, i, tuple(row[1:]))
    n0 = len(prog.param_names) + len(prog.literals) + prog.n_derived
    literal_rows, _ = _literals(mech, g, n0)
    tracer = Tracer(E)
    topo = mech.topology

    def is_coord(ref):
        return isinstance(ref, str) and ref in mech.coordinates

    rod_ends = {e for g_ in mech.groups for e in g_.rod_ends(topo.group_links[g_.name],
                                                               is_coord)}
    ctx = _Fused(mech, prog, tracer, rod_ends, literal_rows)
    fns = {fn for fn, _ in specs}
    if fns & {"F", "Fr", "Rx", "Ry", "R", "Rm", "p", "G", "reserve"}:
        ctx.apply_loads()
    if fns & {"Fr", "Rx", "Ry", "R", "Rm"}:
        for g_ in reversed(mech.groups):
            ctx.links = topo.group_links[g_.name]
            g_.reactions(ctx)
    for k_, (fn, args) in enumerate(specs):
        E(f"o{k_} = {code(ctx.output(fn, args))}")
    body_lines, pre = hoisted(fold(E.lines))
    body = "\n".join(body_lines)
    ind = " " * 16
    nout = len(specs)
    # the status is staged in a local buffer like the outputs (see assur.kernel.source)
    post = [ind + "j = e - e0", ind + "sbuf[j] = st", ind + "ok_ = st < 0"]
    after = [status_out(" " * 12).rstrip("\n")]
    # the element loop stages the outputs in a chunk buffer (branch-free, vectorized);
    # stored: copied out row by row; reduced: one scalar pass over the buffer per chunk
    post += [branchless(ind + f"buf[{k_}, j] = o{k_} if ok_ else 0.0") for k_ in range(nout)]
    if reduce:
        post.append(branchless(ind + f"buf[{nout}, j] = 1.0 if ok_ else 0.0"))
        after += [f"            for r in range({nout}):",
                  "                mn = math.inf",
                  "                mx = -math.inf",
                  "                amn = -1.0",
                  "                amx = -1.0",
                  "                for jj in range(e1 - e0):",
                  f"                    if buf[{nout}, jj] > 0.0:",
                  "                        v = buf[r, jj]",
                  "                        if v < mn:",
                  "                            mn = v",
                  "                            amn = float(e0 + jj - d * npd)",
                  "                        if v > mx:",
                  "                            mx = v",
                  "                            amx = float(e0 + jj - d * npd)",
                  "                red[4 * r, c] = mn",
                  "                red[4 * r + 1, c] = mx",
                  "                red[4 * r + 2, c] = amn",
                  "                red[4 * r + 3, c] = amx"]
    else:
        after.append(copy_out(str(nout), indent=" " * 12).rstrip("\n"))
    src = f'''"""Generated by assur.core.outputs (format {FORMAT}, helpers {helpers_tag()}); do not edit."""
import math
import numpy as np
from numba import njit
from assur.kernel.select import sel as _sel
from assur.kernel.stream import store_fence as _fence, stream_copy as _stream


@njit(cache=True, error_model="numpy", nogil=True)
def kernel(params, trig, q, npd, out, red, status, c_start, c_end):
    """Fused kernel: chunks c_start…c_end−1 (runs of ≤ {CHUNK} positions of one
    design); out: ({nout}, E) outputs or red: (4·{nout}, chunks) min, max, argmin,
    argmax per chunk."""
    buf = np.empty(({nout + 1}, {BUF_ROW}))  # constant shape (see assur.kernel.source)
    sbuf = np.empty({CHUNK}, dtype=np.int64)
    stream = out.shape[0] * out.shape[1] >= {STREAM_MIN}  # streaming stores
{chunk_loop(pre)}{body}
''' + "\n".join(post) + "\n" + "\n".join(after) + "\n    if stream:\n        _fence()\n"
    return src


def _kernel(mech, prog, specs, reduce, g):
    """The compiled fused kernel of a structure, its loads and outputs (cached)."""
    key = (prog.rows, tuple(prog.slot.items()), _load_signature(mech), mech.links,
           mech.distances, dead_load_links(mech), specs, bool(reduce), prog.param_names,
           prog.literals)
    try:
        hit = _KERNELS.get(key)
    except TypeError:  # an unhashable value in a load: trace every time
        key, hit = None, None
    if hit is None:
        hit = load_source(_source(mech, prog, specs, reduce, g))
        if key is not None:
            _KERNELS[key] = hit
    return hit


class Fused:
    """Outputs of :func:`evaluate`: arrays shaped like the coordinates (or, reduced,
    one value per design), with their units.

    Attributes
    ----------
    outputs : tuple of str
        The outputs as asked for.
    ok : ndarray of bool
        Where the mechanism assembled, shape (m, n) — or per design when reduced
        (all positions assembled).
    failures : int ndarray
        Number of failed positions per design.

    Examples
    --------
    >>> from assur import examples
    >>> f = examples.hitch_003().evaluate([0.42, 0.67], outputs=["p(ГЦ)", "Y(56)"])
    >>> [round(float(v) / 1e6, 2) for v in f["p(ГЦ)"]], f.units["p(ГЦ)"]   # table 4.1 [MPa]
    ([15.35, 16.06], 'Pa')
    >>> f.ok.tolist(), f.failures.tolist()
    ([True, True], [0])
    """

    def __init__(self, outputs, units, values, reduced, ok, failures, shape):
        self.outputs = tuple(outputs)
        self.units = dict(units)
        self._values = values
        self._reduced = reduced
        self.ok = ok
        self.failures = failures
        self.shape = shape

    def __getitem__(self, name):
        if self._reduced is not None:
            raise KeyError(f"the outputs were reduced over the positions: use .min({name!r}), "
                           f".max(…), .argmin(…) or .argmax(…)")
        return self._values[self._key(name)]

    def _key(self, name):
        key = name if name in self.outputs else None
        if key is None:
            norm = {o.replace(" ", ""): o for o in self.outputs}
            key = norm.get(str(name).replace(" ", ""))
        if key is None:
            raise KeyError(f"{name!r} is not an output; outputs: {list(self.outputs)}")
        return key

    def _red(self, name, op):
        if self._reduced is None:
            raise KeyError("evaluate(..., reduce=True) computes reductions over positions")
        return self._reduced[op][self._key(name)]

    def min(self, name):
        """Smallest value over the positions of each design that assembled, shape (m,).

        Examples
        --------
        >>> from assur import examples
        >>> S = [0.42, 0.5, 0.6, 0.67]                   # cylinder lengths [m]
        >>> r = examples.hitch_003().evaluate(S, outputs=["reserve(ГЦ, S6, P6)"],
        ...                                    reduce=True)
        >>> [round(float(v), 1) for v in r.min("reserve(ГЦ, S6, P6)")]   # ΔGS65 [%]
        [8.9]
        """
        return self._red(name, "min")

    def max(self, name):
        """Largest value over the positions of each design, shape (m,).

        Examples
        --------
        >>> from assur import examples
        >>> S = [0.42, 0.5, 0.6, 0.67]                   # cylinder lengths [m]
        >>> r = examples.hitch_003().evaluate(S, outputs=["reserve(ГЦ, S6, P6)"],
        ...                                    reduce=True)
        >>> [round(float(v), 1) for v in r.max("reserve(ГЦ, S6, P6)")]   # [%]
        [21.4]
        """
        return self._red(name, "max")

    def argmin(self, name):
        """Position index of the smallest value per design (−1: none assembled).

        Examples
        --------
        >>> from assur import examples
        >>> S = [0.42, 0.5, 0.6, 0.67]                   # cylinder lengths [m]
        >>> r = examples.hitch_003().evaluate(S, outputs=["reserve(ГЦ, S6, P6)"],
        ...                                    reduce=True)
        >>> r.argmin("reserve(ГЦ, S6, P6)").tolist()      # at S = 0.67 m, table 4.1
        [3]
        """
        return self._red(name, "argmin")

    def argmax(self, name):
        """Position index of the largest value per design (−1: none assembled).

        Examples
        --------
        >>> from assur import examples
        >>> S = [0.42, 0.5, 0.6, 0.67]                   # cylinder lengths [m]
        >>> r = examples.hitch_003().evaluate(S, outputs=["reserve(ГЦ, S6, P6)"],
        ...                                    reduce=True)
        >>> r.argmax("reserve(ГЦ, S6, P6)").tolist()      # at S = 0.5 m
        [1]
        """
        return self._red(name, "argmax")

    def __repr__(self):
        return f"Fused({list(self.outputs)}, shape={self.shape}, reduced={self._reduced is not None})"


def _plan(mech, specs, reduce, g):
    """The kernel, the full parameter table (with the cylinders' constants and the loads'
    numbers), the trig table and the pre-pass failures of a mechanism's own values."""
    prog = mech.program()
    ptab, trig, pose_failures = mech.prepared(prog)
    kern = _kernel(mech, prog, specs, reduce, g)
    extra = [np.array([v]) for v in _literals(mech, g, ptab.shape[0])[1]]
    if extra:
        md = max([ptab.shape[1]] + [v.shape[0] for v in extra])
        ptab = np.concatenate([np.broadcast_to(ptab, (ptab.shape[0], md))]
                              + [np.broadcast_to(v, (md,))[None] for v in extra])
        trig = np.broadcast_to(trig, (trig.shape[0], md))
    ptab = np.ascontiguousarray(ptab, dtype=float)
    trig = np.ascontiguousarray(trig)
    return kern, ptab, trig, pose_failures


def evaluate(mech, q, params=None, outputs=(), *, reduce=False, on_failure="raise", g=None):
    """Selected outputs of the fused kinematics + statics kernel.

    Parameters
    ----------
    mech : Mechanism
    q : array_like
        Coordinates as for :meth:`Mechanism.solve` [m or rad].
    params : mapping, optional
        Parameter overrides (arrays over designs make a batch).
    outputs : sequence of str
        What to compute (see the module docstring), e.g. ``["G(ГЦ, 56)", "Rx(0, 5)"]``.
    reduce : bool
        Reduce each output over the positions of each design (min, max, argmin,
        argmax) in the kernel instead of storing it.
    on_failure : {"raise", "report"}
        As for :meth:`Mechanism.solve`; with ``"report"`` failed elements are left
        out of the outputs (0) and of the reductions, and counted in ``failures``.
    g : float, optional
        Gravity [m/s²] for masses (default: the model's).

    Returns
    -------
    Fused

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.outputs import evaluate
    >>> m = examples.hitch_003()
    >>> f = evaluate(m, [0.42, 0.67], outputs=["G(ГЦ, S6)", "reserve(ГЦ, S6, P6)"])
    >>> [round(float(v)) for v in f["G(ГЦ, S6)"]]              # GS6 [N], table 4.1
    [31354, 29959]
    >>> [round(float(v), 1) for v in f["reserve(ГЦ, S6, P6)"]]  # ΔGS65 [%], table 4.1
    [14.0, 8.9]
    >>> [round(float(v)) for v in evaluate(m, [0.42], outputs=["GS6max"])["GS6max"]]
    [50645]
    """
    from . import inputs

    if on_failure not in ("raise", "report"):
        raise ValueError("on_failure must be one of: ['raise', 'report']")
    if not outputs:
        raise ModelError("evaluate: name at least one output, e.g. outputs=['Y(56)']")
    specs = tuple(resolve_output(mech, o) for o in outputs)
    inputs.check_params(mech, params)
    m_ = mech.with_params(**params) if params else mech
    g = m_.g if g is None else float(g)
    plan = m_.memo(("outputs", "plan", specs, bool(reduce), g), lambda: _plan(m_, specs, reduce, g))
    per_pos = 8.0 * (m_.program().k + 2 + (0 if reduce else len(specs)))
    qarr, shape, m, n = m_.coordinate_array(q, plan[1].shape[1], per_pos)
    out, red, status, ptab = _run(m_, plan, qarr, m, n, len(specs), reduce)
    E = qarr.shape[1]
    cpd = (n + CHUNK - 1) // CHUNK
    failed = status >= 0
    if failed.any() and on_failure == "raise":
        raise diagnostics.assembly_error(m_, m_.program(), ptab, qarr, status, np.zeros(E), n,
                                         ~failed.reshape(m, n))
    nfail = failed.reshape(m, n).sum(axis=1)
    units = {o: output_unit(mech, s_) for o, s_ in zip(outputs, specs)}
    if reduce:
        r = red.reshape(len(specs), 4, m, cpd)
        res = {op: {} for op in REDUCTIONS}
        for k_, o in enumerate(outputs):
            mn, mx = r[k_, 0], r[k_, 1]
            imn, imx = np.argmin(mn, axis=1), np.argmax(mx, axis=1)
            rows = np.arange(m)
            res["min"][o] = mn[rows, imn]
            res["max"][o] = mx[rows, imx]
            res["argmin"][o] = r[k_, 2][rows, imn].astype(np.int64)
            res["argmax"][o] = r[k_, 3][rows, imx].astype(np.int64)
        _check_finite(res["min"], "minimum", nfail < n)
        _check_finite(res["max"], "maximum", nfail < n)
        return Fused(outputs, units, None, res, nfail == 0, nfail, (m,))
    vals = {}
    for k_, (o, (fn, _)) in enumerate(zip(outputs, specs)):
        v = out[k_]
        if fn == "phi" and n > 1:
            v = np.unwrap(v.reshape(m, n), axis=1)
        vals[o] = v.reshape(shape)
    if not np.isfinite(out).all():  # one pass; name the output only when one is not
        _check_finite(vals, "value")
    return Fused(outputs, units, vals, None, ~failed.reshape(shape), nfail, shape)


def _run(mech, plan, qarr, m, n, nspecs, reduce=False):
    """Run a planned fused kernel (:func:`_plan`) over checked coordinates ``qarr``
    (k, m·n): returns ``(out, red, status, ptab)`` — outputs (nspecs, m·n), 0 at failed
    elements (status ≥ 0), or the per-chunk reductions. Raises the failure of a
    pre-pass pose when every element assembled."""
    kern, ptab, trig, pose_failures = plan
    if ptab.shape[1] == 1 and m > 1:
        ptab, trig = np.repeat(ptab, m, axis=1), np.repeat(trig, m, axis=1)
    elif ptab.shape[1] != m:
        raise ModelError(f"mechanism {mech.name!r}: parameters describe {ptab.shape[1]} "
                         f"designs but the coordinates {m}")
    E = qarr.shape[1]
    nchunks = m * ((n + CHUNK - 1) // CHUNK)
    out = np.empty((0 if reduce else nspecs, E))
    red = np.empty((4 * nspecs if reduce else 0, nchunks))
    status = np.empty(E, dtype=np.int64)
    nthreads = KR.threads_for(E, nchunks)
    if nthreads <= 1:
        kern(ptab, trig, qarr, n, out, red, status, 0, nchunks)
    else:
        per = (nchunks + nthreads - 1) // nthreads
        futs = [KR.pool().submit(kern, ptab, trig, qarr, n, out, red, status, i * per,
                                 min(nchunks, (i + 1) * per)) for i in range(nthreads)]
        for f in futs:
            f.result()
    if pose_failures and not (status >= 0).any():
        raise pose_failures[0]
    return out, red, status, ptab


def statics_outputs(kin, g):
    """The static joint reactions and actuator forces of every position of ``kin``
    from the fused kernel: ``(joints, specs, out)`` with ``joints`` the mechanism's
    ``(i, j, point)`` (:func:`joint_list`), ``specs`` the outputs — Rx, Ry, Rm of each
    joint, then F, Fr of each coordinate — and ``out`` their values, shape
    (len(specs), m, n) [N, N·m], 0 where the mechanism did not assemble. The
    coordinates are those ``kin`` was solved at (checked then); the plan — kernel,
    parameter table, output list — is made once per mechanism (what does not depend
    on the positions)."""
    mech = kin.mechanism

    def make():
        joints_ = joint_list(mech)
        specs = [(f, (i, j)) for i, j, _ in joints_ for f in ("Rx", "Ry", "Rm")]
        specs += [(f, (c,)) for c in mech.coordinates for f in ("F", "Fr")]
        specs = tuple(specs)
        return joints_, specs, _plan(mech, specs, False, g)

    joints_, specs, plan = mech.memo(("outputs", "statics", g), make)
    m, n = kin.m, kin.n
    qarr = kin.q_table()
    out = _run(mech, plan, qarr, m, n, len(specs))[0]
    if not np.isfinite(out).all():  # one pass; name the output only when one is not
        _check_finite({f"{f}{tuple(a)}": v for (f, a), v in zip(specs, out)}, "value")
    return joints_, specs, out.reshape(len(specs), m, n)


def _check_finite(values, what, where=None):
    """Never return NaN or inf: name the output that is not finite (``where``: the
    designs that count, e.g. those with an assembled position)."""
    for name, v in values.items():
        v = np.asarray(v)
        bad = ~np.isfinite(v)
        if where is not None:
            bad &= np.asarray(where)
        if bad.any():
            idx = tuple(int(i) for i in np.argwhere(bad)[0])
            raise ModelError(f"output {name}: {what} at {idx} is not finite ({v[idx]!r}): "
                             f"a singular position (e.g. a transmission number of 0)")
