"""A point fixed on a rigid link (a ternary link's third joint, an arm at a fixed
angle): seed 003 φ34 = φ3 + φBD, seed 000's bell-crank triangle L3, L4, L34."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..errors import ModelError
from ..kernel.emit import FAIL_TRIANGLE, d, dd, emit_unit, fail, length_ref, pt
from .base import Failure, Field, Group, Ref, fmt, register

__all__ = ["RigidPoint", "unit_eval", "rigid_emit"]


def unit_eval(pts, p, q, beta):
    """``R(β)(Q − P)/|Q − P|`` in plain numpy (any dtype).

    Examples
    --------
    >>> import numpy as np
    >>> from assur.groups.rigid import unit_eval
    >>> pts = {"P": (0.0, 0.0), "Q": (2.0, 0.0)}                      # [m]
    >>> [round(float(v), 3) for v in unit_eval(pts, "P", "Q", np.pi / 2)]   # β = 90°
    [0.0, 1.0]
    >>> ux, uy = unit_eval(pts, "P", "Q", np.radians([0.0, 22.0]))   # two turns [rad]
    >>> [round(float(v), 4) for v in uy]
    [0.0, 0.3746]
    """
    px, py = pts[p]
    qx, qy = pts[q]
    dx, dy = qx - px, qy - py
    r = np.sqrt(dx * dx + dy * dy)
    cb, sb = np.cos(beta), np.sin(beta)
    return (cb * dx - sb * dy) / r, (sb * dx + cb * dy) / r


def rigid_emit(E, i, row):
    """Kernel code of a rigid point; ``row = (out, P, Q, len_ref, trig_row, mode,
    base_row, opposite_row)`` with mode 1 for the triangle form.

    Examples
    --------
    The bell-crank arm 46 of seed 000's header (illustrative L4 = 0.652 m), given by
    its triangle: the kernel checks the three triangle inequalities first:

    >>> from assur import examples
    >>> from assur.groups.rigid import rigid_emit
    >>> from assur.kernel.emit import Emitter
    >>> row = examples.header_000_fixed().program().rows[4]
    >>> row[1:]          # out 46, origin 03, toward 23, row of L4, trig row, mode, L3, L34
    (4, 1, 3, 7, 0, 1, 6, 8)
    >>> E = Emitter(K=1, order=1)
    >>> rigid_emit(E, 4, row[1:])
    >>> for line in E.lines[:4]:
    ...     print(line.strip())
    t4l = params[7, d]
    t4b = params[6, d]
    t4o = params[8, d]
    st = 67 if ((st < 0) & (t4l > t4b + t4o)) else st
    """
    o, P, Q, lref, trow, mode, pb, po = row
    K = E.K
    x, y = pt(o)
    px, py = pt(P)
    ell, dell = length_ref(lref, K)
    t = f"t{i}"
    E(f"{t}l = {ell}")
    if mode == 1:
        E(f"{t}b = params[{pb}, d]")
        E(f"{t}o = params[{po}, d]")
        fail(E, i, FAIL_TRIANGLE, f"{t}l > {t}b + {t}o")
        fail(E, i, FAIL_TRIANGLE, f"{t}b > {t}l + {t}o")
        fail(E, i, FAIL_TRIANGLE, f"{t}o > {t}l + {t}b")
    emit_unit(E, i, P, Q, f"trig[{trow}, d]", f"trig[{trow + 1}, d]")
    E(f"{x} = {px} + {t}l * u{i}x")
    E(f"{y} = {py} + {t}l * u{i}y")
    for a in range(K):
        for c, pc in (("x", px), ("y", py)):
            E(f"{d(c + str(o), a)} = {d(pc, a)} + {t}l * u{i}{c}_{a}"
              + (f" + {dell[a]} * u{i}{c}" if dell[a] != "0.0" else ""))
    for a, b in E.pairs:
        for c, pc in (("x", px), ("y", py)):
            extra = ""
            if dell[a] != "0.0":
                extra += f" + {dell[a]} * u{i}{c}_{b}"
            if dell[b] != "0.0":
                extra += f" + {dell[b]} * u{i}{c}_{a}"
            E(f"{dd(c + str(o), a, b)} = {dd(pc, a, b)} + {t}l * "
              f"{dd(f'u{i}{c}', a, b)}{extra}")


@register
@dataclass(frozen=True)
class RigidPoint(Group):
    """A point at ``length`` from ``origin``, turned ``angle`` from the direction
    ``origin → toward`` (both points of the same link).

    Either ``angle`` [rad] is given (003: φ34 = φ3 + φBD, φBD = 22°), or the three
    sides of the link's triangle: ``base`` = |origin–toward|, ``length`` =
    |origin–out| and ``opposite`` = |toward–out| with ``branch`` = ±1 the side of
    the turn (000: DELFI = acos((L3² + L4² − L34²)/(2·L3·L4))). A triangle that
    cannot close fails with the violated inequality.

    ``links = (name,)`` optionally names the existing link that carries the point
    (checked); by default it is the one rigid link holding both ``origin`` and
    ``toward``. A ``length`` that is a generalized coordinate makes a telescopic arm.

    Examples
    --------
    Seed 003's lever arm 34, at φBD = 22° from the lever 03 → 23:

    >>> import numpy as np
    >>> from assur import examples
    >>> m = examples.hitch_003()
    >>> g = m.group("arm 34")
    >>> g.origin, g.toward, g.out, g.length, g.angle
    ('03', '23', '34', 'L34', 'phiBD')
    >>> r = m.solve([0.42, 0.67])                                     # S [m]
    >>> np.round(r.phi("34", degrees=True) - r.phi("3", degrees=True), 3).tolist()   # φBD [deg]
    [22.0, 22.0]

    Seed 000's bell-crank arm 46, given by the triangle L3, L4, L34 (illustrative
    L4 = 0.652 m):

    >>> m = examples.header_000_fixed()
    >>> g = m.group("arm 46")
    >>> g.base, g.length, g.opposite, g.branch
    ('L3', 'L4', 'L34', -1)
    >>> p = m.solve([0.7]).point                                      # S [m]
    >>> round(float(np.hypot(*(p("46")[0] - p("23")[0]))), 4)        # |23–46| = L34 [m]
    0.4804
    """

    origin: str = ""
    toward: str = ""
    out: str = ""
    length: Ref = 0.0
    angle: Ref | None = None
    base: Ref | None = None
    opposite: Ref | None = None
    branch: int = 1
    links: tuple[str, ...] = ()

    type_name: ClassVar[str] = "rigid_point"
    kind: ClassVar[str] = "rigid point"
    kind_ru: ClassVar[str] = "точка жёсткого звена"
    link_roles: ClassVar = None
    fields: ClassVar = (
        Field("origin", "point", doc="a point of the carrying link"),
        Field("toward", "point", doc="another point of the same link (the reference direction)"),
        Field("out", "point", doc="the point it adds"),
        Field("length", "value", "length", "positive", True, doc="|origin–out| [m]"),
        Field("angle", "value", "angle", default=None,
              doc="turn from origin→toward [°] (or the triangle below)"),
        Field("base", "value", "length", "positive", default=None, doc="|origin–toward| [m]"),
        Field("opposite", "value", "length", "positive", default=None, doc="|toward–out| [m]"),
        Field("branch", "branch", default=None, doc="side of the triangle's turn, ±1"),
    )

    @classmethod
    def check_fields(cls, given):
        """A message unless ``given`` holds ``angle`` or the triangle ``base``,
        ``opposite``, ``branch`` (not both), else None.

        Examples
        --------
        >>> from assur.groups import RigidPoint
        >>> print(RigidPoint.check_fields({"origin", "toward", "out", "length", "angle"}))
        None
        >>> RigidPoint.check_fields({"length", "angle", "base"})
        'expected either angle, or base, opposite and branch (the triangle), not both: remove base'
        >>> RigidPoint.check_fields({"length", "base"})
        'expected angle, or base, opposite and branch (the triangle); missing branch, opposite'
        """
        if "angle" in given:
            extra = sorted(set(given) & {"base", "opposite", "branch"})
            if extra:
                return ("expected either angle, or base, opposite and branch (the triangle), "
                        "not both: remove " + ", ".join(extra))
        elif not {"base", "opposite", "branch"} <= set(given):
            missing = sorted({"base", "opposite", "branch"} - set(given))
            return ("expected angle, or base, opposite and branch (the triangle); missing "
                    + ", ".join(missing))
        return None

    def validate(self, coordinates):
        """A message unless the point is given by ``angle`` or by the triangle (and
        ``branch`` is ±1), else None.

        Examples
        --------
        >>> import dataclasses
        >>> from assur import examples
        >>> from assur.groups import RigidPoint
        >>> RigidPoint("arm", origin="03", toward="23", out="34", length=0.325).validate(("S",))
        'expected angle, or base, opposite and branch (the triangle)'
        >>> arm = examples.header_000_fixed().group("arm 46")
        >>> print(arm.validate(("S",)))
        None
        >>> dataclasses.replace(arm, branch=2).validate(("S",))
        'branch must be +1 or -1, got 2'
        """
        if self.angle is None and (self.base is None or self.opposite is None):
            return "expected angle, or base, opposite and branch (the triangle)"
        if self.angle is not None and (self.base is not None or self.opposite is not None):
            return "expected either angle, or base, opposite and branch (the triangle), not both"
        return super().validate(coordinates)

    def inputs(self):
        """``origin`` and ``toward``.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().group("arm 34").inputs()
        ('03', '23')
        """
        return (self.origin, self.toward)

    def outputs(self):
        """The point it adds.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().group("arm 34").outputs()
        ('34',)
        """
        return (self.out,)

    def refs(self):
        """``length`` [m] and ``angle`` [rad], or ``length``, ``base``, ``opposite`` [m]
        of the triangle form.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().group("arm 34").refs()
        {'length': 'L34', 'angle': 'phiBD'}
        >>> examples.header_000_fixed().group("arm 46").refs()
        {'length': 'L4', 'base': 'L3', 'opposite': 'L34'}
        """
        if self.angle is not None:
            return {"length": self.length, "angle": self.angle}
        return {"length": self.length, "base": self.base, "opposite": self.opposite}

    def topology(self, t):
        """Put the point on the one link that holds ``origin`` and ``toward``; a
        telescopic arm (``length`` a coordinate) is a new variable link
        ``"<name>:arm"``.

        Examples
        --------
        >>> import dataclasses
        >>> from assur import examples
        >>> from assur.core.topology import TopologyBuilder
        >>> m = examples.hitch_003()
        >>> t = TopologyBuilder(m.name, m.coordinates)
        >>> for g in m.groups[:5]:                 # the frame points and group I (2,3)
        ...     _ = g.topology(t)
        >>> arm = m.group("arm 34")
        >>> arm.topology(t), t.bodies["3"]
        (('3',), ['03', '23', '34'])
        >>> tele = dataclasses.replace(arm, name="tele", out="P", length="S")
        >>> tele.topology(t), "tele:arm" in t.variable
        (('tele:arm',), True)
        """
        b = t.carrier(self, self.origin, self.toward, self.group_links())
        if t.is_coord(self.length):
            # a telescopic arm: the new point is on a link of its own
            arm = f"{self.name}:arm"
            t.new(self, arm, (self.origin, self.out), variable=True)
            t.own(self.out, arm)
            return (arm,)
        t.attach(b, self.out)
        return (b,)

    def beta(self, val):
        """The turn from origin→toward [rad].

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> from assur.groups.base import ref_value
        >>> m = examples.hitch_003()
        >>> beta = m.group("arm 34").beta(lambda ref: ref_value(m.params, ref))
        >>> round(float(np.degrees(beta)), 3)        # φBD, seed 003 §1.2 [deg]
        22.0
        >>> m = examples.header_000_fixed()        # −acos((L3² + L4² − L34²)/(2·L3·L4))
        >>> beta = m.group("arm 46").beta(lambda ref: ref_value(m.params, ref))
        >>> round(float(np.degrees(beta)), 3)        # [deg]
        -3.093
        """
        if self.angle is not None:
            return val(self.angle)
        b, ell, o = val(self.base), val(self.length), val(self.opposite)
        return self.branch * np.arccos((b * b + ell * ell - o * o) / (2 * b * ell))

    def evaluate(self, pts, val):
        """Add ``out = origin + length·R(β)(toward − origin)/|toward − origin|``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups.base import ref_value
        >>> m = examples.hitch_003()
        >>> pts = m.evaluate_positions({"S": 0.42}, upto=5)     # the groups before arm 34
        >>> m.group("arm 34").evaluate(pts, lambda ref: ref_value(m.params, ref))
        >>> [round(float(v), 4) for v in pts["34"]]              # [m]
        [0.5587, 1.0103]
        """
        ux, uy = unit_eval(pts, self.origin, self.toward, self.beta(val))
        ell = val(self.length)
        px, py = pts[self.origin]
        pts[self.out] = (px + ell * ux, py + ell * uy)

    def compile(self, c):
        """``(slot of out, of origin, of toward, length reference, trig row, mode, base
        row, opposite row)``: mode 0 with a fixed angle, 1 with the triangle (its angle
        in the trig table).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.program import CompileContext
        >>> m = examples.header_000_fixed()
        >>> c = CompileContext(m.coordinates, tuple(m.params))
        >>> for g in m.groups[:4]:                 # 01, 03, 05 and group I (2,3)
        ...     _ = g.compile(c)
        >>> m.group("arm 46").compile(c)   # 46 in slot 4; L4, L3, L34 in rows 7, 6, 8
        (4, 1, 3, 7, 0, 1, 6, 8)
        >>> c.trig[0]                      # branch −1
        ('triangle', 6, 7, 8, -1)
        """
        if self.angle is not None:
            return (c.slot(self.out), c.slot(self.origin), c.slot(self.toward),
                    c.lref(self.length), c.trig_angle(c.pref(self.angle)), 0, 0, 0)
        pl, pb, po = c.pref(self.length), c.pref(self.base), c.pref(self.opposite)
        return (c.slot(self.out), c.slot(self.origin), c.slot(self.toward), pl,
                c.trig_triangle(pb, pl, po, self.branch), 1, pb, po)

    @classmethod
    def emit(cls, E, i, row):
        """The point's jets from those of origin and toward (:func:`rigid_emit`).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups import RigidPoint
        >>> from assur.kernel.emit import Emitter
        >>> row = examples.hitch_003().program().rows[5]      # arm 34: 34 in slot 5
        >>> E = Emitter(K=1, order=1)
        >>> RigidPoint.emit(E, 5, row[1:])
        >>> [s for s in (line.strip() for line in E.lines) if s.startswith(("x5 ", "y5 "))]
        ['x5 = x1 + t5l * u5x', 'y5 = y1 + t5l * u5y']
        """
        rigid_emit(E, i, row)

    def failure(self, code, pts, v, nm):
        """The triangle that cannot close, by how much [m], in the words of the model;
        other codes as :meth:`Group.failure <assur.groups.base.Group.failure>`.

        Examples
        --------
        Seed 000's printed L4 = 0.657 m is longer than L3 + L34:

        >>> from assur import examples
        >>> from assur.groups.base import ref_value
        >>> from assur.kernel.emit import FAIL_TRIANGLE
        >>> m = examples.header_000()
        >>> f = m.group("arm 46").failure(FAIL_TRIANGLE, {}, lambda r: ref_value(m.params, r), str)
        >>> print(f.text)
        the triangle L3 = 0.17194, L34 = 0.4804, L4 = 0.657 m cannot close: L4 exceeds L3 + L34 = 0.65234 m by 4.66 mm
        >>> round(f.amount, 5), f.verb                           # [m]
        (0.00466, 'fails')
        """
        if code != FAIL_TRIANGLE:
            return super().failure(code, pts, v, nm)
        names = {"base": self.base, "length": self.length, "opposite": self.opposite}
        vals = {k: v(r) for k, r in names.items()}
        sides = ", ".join(f"{nm(names[k])} = {fmt(vals[k])}" for k in
                          ("base", "opposite", "length"))
        for k in ("length", "base", "opposite"):
            o1, o2 = [x for x in ("base", "length", "opposite") if x != k]
            if vals[k] > vals[o1] + vals[o2]:
                amt = vals[k] - vals[o1] - vals[o2]
                return Failure(amt, f"the triangle {sides} m cannot close: {nm(names[k])} "
                                    f"exceeds {nm(names[o1])} + {nm(names[o2])} = "
                                    f"{fmt(vals[o1] + vals[o2])} m by {amt * 1e3:.3g} mm",
                               "fails")
        return Failure(0.0, f"the triangle {sides} m cannot close", "fails")

    def closure(self, P, val):
        """``abs(|out − origin| − length)`` [m] with a fixed angle; None for the triangle
        form (built exactly from its sides).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups.base import ref_value
        >>> m = examples.hitch_003()
        >>> pts = m.evaluate_positions({"S": 0.42})
        >>> arm = m.group("arm 34")
        >>> round(float(arm.closure(pts.get, lambda ref: ref_value(m.params, ref))), 12)  # [m]
        0.0
        >>> longer = {**m.params, "L34": 0.326}                 # L34 1 mm longer [m]
        >>> round(float(arm.closure(pts.get, lambda ref: ref_value(longer, ref))), 6)    # [m]
        0.001
        >>> print(examples.header_000_fixed().group("arm 46").closure(pts.get, None))
        None
        """
        if self.angle is None:
            return None
        cx, cy = P(self.out)
        px, py = P(self.origin)
        return np.abs(np.hypot(cx - px, cy - py) - val(self.length))

    def reactions(self, r):
        """A point on a link: nothing to solve (the loads at the point stay on the
        link). A telescopic arm's reactions are not modelled.

        Examples
        --------
        >>> import dataclasses
        >>> from assur import examples
        >>> from assur.core import statics
        >>> m = examples.hitch_003()
        >>> r = statics.ReactionContext(m.solve([0.42]), set())
        >>> arm = m.group("arm 34")
        >>> arm.reactions(r)
        >>> r.joints
        {}
        >>> dataclasses.replace(arm, length="S").reactions(r)
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: reactions of the telescopic arm 'arm 34' are not modelled (use the virtual-work forces)
        """
        if r.is_coord(self.length):
            raise ModelError(f"reactions of the telescopic arm {self.name!r} are not modelled "
                             f"(use the virtual-work forces)")
