"""The criterion kinds behind one contract (:class:`_Kind`) and their registry
:data:`CRITERIA`: bound, capacity, pressure, transmission angle, box — each one's
outputs, value, position and exact gradient (:mod:`assur.synthesis.search.criteria`)."""

from __future__ import annotations

import math

import numpy as np

from ...core.outputs import output_unit, resolve_output
from ...errors import ModelError
from ._reductions import REDUCTIONS

__all__ = ["CRITERIA"]


class _Kind:
    """The contract of a criterion kind."""

    name = ""
    quantity = None  # the unit family of its values ("length", "force", …)

    def make(self, args: dict, mech) -> tuple:
        """``(name, outputs, distances, quantity)`` of a criterion of this kind."""
        raise NotImplementedError

    def value(self, c, red):
        raise NotImplementedError

    def where(self, c, red):
        return np.full(len(next(iter(red.mins.values()))), -1)

    def default_limit(self, c, red):
        raise ModelError(f"{c.kind} {c.name}: give at_least or at_most")

    def limit_ref(self, c):
        """The number or parameter behind :meth:`default_limit` (for its gradient)."""
        return None

    #: ``gradient(c, sens, red)`` → d(value)/d(variables) at one design (see
    #: :attr:`Criterion.gradient`), or None for a kind without an exact gradient
    gradient = None


def _active(sens, red, output, how):
    """∂output/∂(variables) at the position where ``output`` takes its ``how``
    (``min`` or ``max``) over the positions, shape (variables,) [SI]: the gradient of
    the active piece of a min/max (Danskin), one design."""
    i = int(np.asarray(red.where(output, how)).reshape(-1)[0])
    return np.array(sens.gradient(output)[i], float)


def _check_output(text, mech):
    return resolve_output(mech, text)


_QUANTITY = {"m": "length", "rad": "angle", "N": "force", "Pa": "pressure", "N·m": "moment",
             "%": "number"}


class _Bound(_Kind):
    name = "bound"

    def make(self, args, mech):
        q = args.get("quantity")
        how = args.get("of", "min")
        if not isinstance(q, str):
            raise ModelError("a bound needs quantity = an output, e.g. \"Y(56)\"")
        if how not in REDUCTIONS:
            raise ModelError(f"bound of {q}: of must be one of {list(REDUCTIONS)}, got {how!r}")
        fn, _ = _check_output(q, mech)
        return f"{how} {q}", (q,), (), _QUANTITY.get(output_unit(mech, q))

    def value(self, c, red):
        return red.of(c.args["quantity"], c.args.get("of", "min"))

    def where(self, c, red):
        how = c.args.get("of", "min")
        if how == "span":
            return super().where(c, red)
        return red.where(c.args["quantity"], how)

    def gradient(self, c, sens, red):
        """d(min, max or span of the quantity)/d(variables): the sensitivity at the
        arg-min / arg-max position (the span: at the arg-max less at the arg-min)
        [quantity unit / variable unit]."""
        q, how = c.args["quantity"], c.args.get("of", "min")
        if how == "span":
            return _active(sens, red, q, "max") - _active(sens, red, q, "min")
        return _active(sens, red, q, how)


class _Capacity(_Kind):
    name = "capacity"

    def make(self, args, mech):
        cyl, point = _cylinder(args, mech), args.get("point")
        if not isinstance(point, str):
            raise ModelError("a capacity needs point = the point the load hangs at")
        q = f"G({cyl}, {point})"
        return f"min {q}", (q,), (), "force"

    def value(self, c, red):
        return red.mins[c.outputs[0]]

    def where(self, c, red):
        return red.argmins[c.outputs[0]]

    def gradient(self, c, sens, red):
        """d(min G(cylinder, point))/d(variables): the capacity's sensitivity at the
        weakest position [N / variable unit]."""
        return _active(sens, red, c.outputs[0], "min")


class _Pressure(_Kind):
    name = "pressure"

    def make(self, args, mech):
        cyl = _cylinder(args, mech)
        q = f"p({cyl})"
        return f"max {q}", (q,), (), "pressure"

    def value(self, c, red):
        return red.maxs[c.outputs[0]]

    def where(self, c, red):
        return red.argmaxs[c.outputs[0]]

    def default_limit(self, c, red):
        return np.asarray(red.param(c.args["relief"]), float)

    def limit_ref(self, c):
        return c.args["relief"]

    def gradient(self, c, sens, red):
        """d(max p(cylinder))/d(variables): the pressure's sensitivity at the position
        of the peak [Pa / variable unit]."""
        return _active(sens, red, c.outputs[0], "max")


class _TransmissionAngle(_Kind):
    """μ between two rigid links i, j meeting at a joint, from the distance d between
    their far ends (law of cosines, d² = a² + b² − 2ab·cos μ): μ grows with d, so the
    smallest and largest μ over the range come from the smallest and largest d, which
    the kernel reduces without storing the positions. The criterion's value is
    min(μ_min, 180° − μ_max), the angle's worst distance from a straight line."""

    name = "transmission_angle"

    def make(self, args, mech):
        links = args.get("links")
        if not (isinstance(links, (list, tuple)) and len(links) == 2):
            raise ModelError("a transmission angle needs links = [two links meeting at a joint]")
        byname = {lk.name: lk for lk in mech.links}
        for ln in links:
            if ln not in byname:
                raise ModelError(f"transmission angle: no link {ln!r}; links: {sorted(byname)}")
        la, lb = byname[links[0]], byname[links[1]]
        common = {la.tail, la.head} & {lb.tail, lb.head}
        if len(common) != 1:
            raise ModelError(f"transmission angle: links {la.name!r} ({la.tail}–{la.head}) and "
                             f"{lb.name!r} ({lb.tail}–{lb.head}) do not meet at one joint")
        j = common.pop()
        fa = la.head if la.tail == j else la.tail
        fb = lb.head if lb.tail == j else lb.tail
        tag = f"__mu_{la.name}_{lb.name}"
        dists = ((tag + "_a", fa, j), (tag + "_b", fb, j), (tag + "_d", fa, fb))
        outs = tuple(f"length({d[0]})" for d in dists)
        return f"transmission angle {la.name}–{lb.name} at {j}", outs, dists, "angle"

    def value(self, c, red):
        oa, ob, od = c.outputs
        a, b = red.mins[oa], red.mins[ob]
        for o, v in ((oa, a), (ob, b)):
            if not np.allclose(red.maxs[o], v, rtol=1e-9, atol=1e-12):
                raise ModelError(f"{c.name}: a link changes length over the range (a cylinder "
                                 f"or a slider): the transmission angle needs two rigid links")
        # |cos μ| ≤ 1 wherever the joint assembled; clip the rounding only
        cmin = np.clip((a * a + b * b - red.mins[od] ** 2) / (2 * a * b), -1.0, 1.0)
        cmax = np.clip((a * a + b * b - red.maxs[od] ** 2) / (2 * a * b), -1.0, 1.0)
        mu_min, mu_max = np.arccos(cmin), np.arccos(cmax)
        return np.minimum(mu_min, math.pi - mu_max)

    def gradient(self, c, sens, red):
        """d(min(μ_min, 180° − μ_max))/d(variables) [rad / variable unit]: of the two
        pieces the smaller, through μ = arccos(ĉ), ĉ = (a² + b² − d²)/(2ab), with d
        the smallest (largest) distance between the far ends at its own position and
        the link lengths a, b at that position (rigid: the same at all):
        dμ = −(∂ĉ/∂a·da + ∂ĉ/∂b·db + ∂ĉ/∂d·dd)/√(1 − ĉ²),
        ∂ĉ/∂a = (a² − b² + d²)/(2a²b), ∂ĉ/∂b = (b² − a² + d²)/(2ab²), ∂ĉ/∂d = −d/(ab).

        Raises
        ------
        ModelError
            The links are in line (|ĉ| = 1 to within 1e-12) at the active position:
            the angle has no derivative there.
        """
        oa, ob, od = c.outputs
        a, b = float(red.mins[oa][0]), float(red.mins[ob][0])
        pieces = []
        for how, sign in (("min", 1.0), ("max", -1.0)):
            d = float(red.mins[od][0] if how == "min" else red.maxs[od][0])
            cc = (a * a + b * b - d * d) / (2 * a * b)
            mu = float(np.arccos(np.clip(cc, -1.0, 1.0)))
            pieces.append((mu if how == "min" else math.pi - mu, how, d, cc, sign))
        _, how, d, cc, sign = min(pieces, key=lambda t: t[0])
        i = int(red.where(od, how)[0])
        if 1.0 - abs(cc) <= 1e-12:
            raise ModelError(f"{c.name}: the links are in line at position {i}: the "
                             f"transmission angle has no derivative there")

        def jac(o):
            return np.array(sens.gradient(o)[i], float)
        dc = ((a * a - b * b + d * d) / (2 * a * a * b) * jac(oa)
              + (b * b - a * a + d * d) / (2 * a * b * b) * jac(ob)
              - d / (a * b) * jac(od))
        return -sign * dc / math.sqrt(1.0 - cc * cc)


class _Box(_Kind):
    name = "box"

    def make(self, args, mech):
        p = args.get("point")
        if not isinstance(p, str):
            raise ModelError("a box needs point = a point of the model")
        if args.get("x") is None and args.get("y") is None:
            raise ModelError(f"box of {p}: give x = [low, high] and/or y = [low, high]")
        outs = tuple(f"{ax.upper()}({p})" for ax in ("x", "y") if args.get(ax) is not None)
        return f"box of {p}", outs, (), "length"

    def value(self, c, red):
        m = None
        for o in c.outputs:
            lo, hi = c.args[o[0].lower()]
            mm = np.minimum(red.mins[o] - lo, hi - red.maxs[o])
            m = mm if m is None else np.minimum(m, mm)
        return m

    def default_limit(self, c, red):
        return np.zeros_like(self.value(c, red))

    def limit_ref(self, c):
        return 0.0

    def gradient(self, c, sens, red):
        """d(smallest distance inside the box)/d(variables): of the four pieces
        ``min X − low``, ``high − max X`` (and Y's) the smallest, its sensitivity at
        its own arg-min / arg-max position (a frame pivot: the same at every
        position) [m / variable unit]."""
        best, grad = None, None
        for o in c.outputs:
            lo, hi = c.args[o[0].lower()]
            for v, g in ((float(red.mins[o][0]) - lo, lambda o=o: _active(sens, red, o, "min")),
                         (hi - float(red.maxs[o][0]), lambda o=o: -_active(sens, red, o, "max"))):
                if best is None or v < best:
                    best, grad = v, g
        return grad()


def _cylinder(args, mech):
    names = [c.name for c in mech.cylinders]
    cyl = args.get("cylinder")
    if cyl is None:
        if len(names) != 1:
            raise ModelError(f"name the cylinder (cylinder = one of {names})")
        cyl = names[0]
    if cyl not in names:
        raise ModelError(f"no cylinder {cyl!r}; cylinders: {names}")
    return cyl


#: the criterion kinds by their ``type``
CRITERIA = {k.name: k for k in (_Bound(), _Capacity(), _Pressure(), _TransmissionAngle(),
                                 _Box())}
