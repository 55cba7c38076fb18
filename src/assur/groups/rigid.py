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
    """``R(β)(Q − P)/|Q − P|`` in plain numpy (any dtype)."""
    px, py = pts[p]
    qx, qy = pts[q]
    dx, dy = qx - px, qy - py
    r = np.sqrt(dx * dx + dy * dy)
    cb, sb = np.cos(beta), np.sin(beta)
    return (cb * dx - sb * dy) / r, (sb * dx + cb * dy) / r


def rigid_emit(E, i, row):
    """Kernel code of a rigid point; ``row = (out, P, Q, len_ref, trig_row, mode,
    base_row, opposite_row)`` with mode 1 for the triangle form."""
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
        if self.angle is None and (self.base is None or self.opposite is None):
            return "expected angle, or base, opposite and branch (the triangle)"
        if self.angle is not None and (self.base is not None or self.opposite is not None):
            return "expected either angle, or base, opposite and branch (the triangle), not both"
        return super().validate(coordinates)

    def inputs(self):
        return (self.origin, self.toward)

    def outputs(self):
        return (self.out,)

    def refs(self):
        if self.angle is not None:
            return {"length": self.length, "angle": self.angle}
        return {"length": self.length, "base": self.base, "opposite": self.opposite}

    def topology(self, t):
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
        """The turn from origin→toward [rad]."""
        if self.angle is not None:
            return val(self.angle)
        b, ell, o = val(self.base), val(self.length), val(self.opposite)
        return self.branch * np.arccos((b * b + ell * ell - o * o) / (2 * b * ell))

    def evaluate(self, pts, val):
        ux, uy = unit_eval(pts, self.origin, self.toward, self.beta(val))
        ell = val(self.length)
        px, py = pts[self.origin]
        pts[self.out] = (px + ell * ux, py + ell * uy)

    def compile(self, c):
        if self.angle is not None:
            return (c.slot(self.out), c.slot(self.origin), c.slot(self.toward),
                    c.lref(self.length), c.trig_angle(c.pref(self.angle)), 0, 0, 0)
        pl, pb, po = c.pref(self.length), c.pref(self.base), c.pref(self.opposite)
        return (c.slot(self.out), c.slot(self.origin), c.slot(self.toward), pl,
                c.trig_triangle(pb, pl, po, self.branch), 1, pb, po)

    emit = classmethod(lambda cls, E, i, row: rigid_emit(E, i, row))

    def failure(self, code, pts, v, nm):
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
        if self.angle is None:
            return None
        cx, cy = P(self.out)
        px, py = P(self.origin)
        return np.abs(np.hypot(cx - px, cy - py) - val(self.length))

    def reactions(self, r):
        if r.is_coord(self.length):
            raise ModelError(f"reactions of the telescopic arm {self.name!r} are not modelled "
                             f"(use the virtual-work forces)")
