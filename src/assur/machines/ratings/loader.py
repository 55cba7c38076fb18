"""Ratings of loaders in the manner of ISO 14397-1 and ISO 14397-2 (``[[rating]]``
types ``loader_tipping``, ``loader_breakout`` and ``loader_lift``, docs/ratings.md).

In our words:

* *static tipping load* (ISO 14397-1): the least load at the bucket's centre of
  gravity that tips the machine — lifts the axle farther from the load off the
  ground — with the machine on level ground, the loader in the standard position:
  the lift arm where the bucket's centre of gravity reaches farthest forward, the
  bucket rolled back. Here: over the positions of the model's ``[range]`` (rolled
  back is the range's business), the tipping load at each
  (:func:`assur.machines.ratings.tipping_load`, the machine's axles and weights of
  ``[machine]`` with the mechanism's own loads), and the static tipping load at the
  standard position, the position of largest reach;
* *rated operating capacity* (ISO 14397-1): a declared fraction of the static
  tipping load — ``fraction``, 0.5 by default, the standard's value for wheel
  loaders (0.35 for crawler loaders);
* *breakout force* (ISO 14397-2): the largest sustained vertical upward force the
  loader exerts 100 mm behind the tip of the bucket's cutting edge, by its lift
  cylinders (lift breakout force) or by its tilt cylinders (tilt breakout force);
  here over the positions of the range (the tilt range), the point 100 mm
  (``offset``) from the edge's tip towards a second point of the bucket (``back``),
  each force limited by the other cylinders' holding at their working pressure and
  by tipping (:func:`assur.machines.ratings.crane.holding_limit`: a vertical load at
  the point asks F_j = G·∂Y/∂q_j of cylinder j by virtual work). Both cylinders
  held at the same pressure limit both forces alike: the unlimited forces of each
  show which one governs;
* *lift capacity over the height*: the load at the bucket's centre of gravity the
  lift and tilt cylinders hold over the lift range, against the height of the
  bucket's hinge pin (the hitch's lift test, :mod:`assur.machines.hitch_lift`,
  generalised) — the load chart of :class:`assur.machines.ratings.crane.CraneChart`
  with the hinge pin's height as its abscissa.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ...core.virtual_work import virtual_work_forces
from ...errors import ModelError
from ...texts import Text, localize
from ._registry import register
from .base import (Rating, RatingResult, Series, carried_loads, number, param,
                   with_loads_of)
from .crane import CraneChart, flat, holding_limit
from .stability import tipping_load

__all__ = ["LoaderTipping", "LoaderBreakout", "LoaderLift", "coordinate_series"]


def coordinate_series(mech, kin) -> list:
    """The coordinates' :class:`~assur.machines.ratings.Series` of ``kin`` (one design).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.machines.ratings.loader import coordinate_series
    >>> m = examples.hitch_003()
    >>> [(s.symbol, s.quantity) for s in coordinate_series(m, m.solve([0.42, 0.67]))]
    [('S', 'length')]
    """
    return [Series(c, flat(kin.q(c)), "angle" if mech.coordinate_kind(c) == "angle"
                   else "length", Text(f"coordinate {c}", ru=f"координата {c}"))
            for c in kin.coordinates]


def _need_machine(mech, what):
    if mech.machine is None:
        raise ModelError(f"{mech.name}: the {what} rating needs the machine's axles and "
                         f"weights ([machine])")


@register
@dataclass(frozen=True)
class LoaderTipping(Rating):
    """The static tipping load at the bucket's centre of gravity and the rated operating
    capacity (module notes; ISO 14397-1).

    Examples
    --------
    >>> from assur.machines.ratings import rating_type
    >>> [(p.name, p.default) for p in rating_type("loader_tipping").fields][:2]
    [('point', None), ('fraction', 0.5)]
    """

    point: str = param("point", doc="the bucket's centre of gravity (where the load acts)")
    fraction: object = param("value", "number", default=0.5,
                             doc="rated operating capacity / static tipping load "
                                 "(ISO 14397-1: 0.5 wheel loaders, 0.35 crawler loaders)")
    self_weight: bool = param("flag", default=True,
                              doc="the mechanism's loads other than at the point tip it too")
    name: object = param("text", default=None, doc="the title of the table and figure")

    type_name: ClassVar[str] = "loader_tipping"
    title: ClassVar[object] = Text("Static tipping load and rated operating capacity",
                                   ru="Статическая опрокидывающая нагрузка и номинальная "
                                      "грузоподъёмность")
    standard: ClassVar[str] = "ISO 14397-1"

    def check(self, mech):
        """The rating needs ``[machine]`` and a fraction in (0, 1]: ``(parameter,
        message)`` or None.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.machines.ratings import rating_type
        >>> print(rating_type("loader_tipping")(point="S9").check(examples.loader_lab1()))
        None
        """
        if mech.machine is None:
            return "point", "a tipping load needs the machine's axles and weights ([machine])"
        share = number(mech, self.fraction)
        if not 0.0 < share <= 1.0:
            return "fraction", f"expected a share of the tipping load in (0, 1], found {share:g}"
        return None

    def evaluate(self, mech, kin) -> RatingResult:
        """The tipping load over the positions of ``kin`` and at the standard position.

        Examples
        --------
        >>> from assur import io
        >>> from assur.machines.ratings import rating_type
        >>> model = io.load(io.bundled("loader_lab1"))
        >>> m = model.mechanism
        >>> r = rating_type("loader_tipping")(point="S9").evaluate(m, m.solve(model.range))
        >>> bool(r.scalars[1].values[0] == 0.5 * r.scalars[0].values[0])   # ROC = ½ tipping
        True
        """
        _need_machine(mech, self.type_name)
        P = self.point
        carried = carried_loads(mech, P) if self.self_weight else None
        W = tipping_load(mech, kin, P, carried)
        share = number(mech, self.fraction)
        reach, height = flat(kin.x(P)), flat(kin.y(P))
        i = int(np.argmax(reach))      # the standard position: the farthest reach
        series = coordinate_series(mech, kin) + [
            Series("x", reach, "length", Text(f"reach of {P}", ru=f"вылет точки {P}")),
            Series("y", height, "length", Text(f"height of {P}", ru=f"высота точки {P}")),
            Series("W_tip", W, "force", Text(f"tipping load at {P}",
                                             ru=f"опрокидывающая нагрузка в точке {P}")),
            Series("ROC", share * W, "force", Text(
                f"{share:g} of the tipping load", ru=f"{share:g} опрокидывающей нагрузки"))]
        scalars = (Series("W_tip_static", W[i:i + 1], "force", Text(
                       "static tipping load at the farthest reach (ISO 14397-1)",
                       ru="статическая опрокидывающая нагрузка при наибольшем вылете "
                          "(ISO 14397-1)")),
                   Series("ROC_rated", share * W[i:i + 1], "force", Text(
                       "rated operating capacity (ISO 14397-1)",
                       ru="номинальная грузоподъёмность (ISO 14397-1)")),
                   Series("x_static", reach[i:i + 1], "length", Text(
                       f"the farthest reach of {P}", ru=f"наибольший вылет точки {P}")))
        return RatingResult(self, tuple(series), "x", ("W_tip", "ROC"), None, (), scalars)


@register
@dataclass(frozen=True)
class LoaderBreakout(Rating):
    """Lift and tilt breakout forces 100 mm behind the cutting edge's tip (module notes;
    ISO 14397-2).

    Examples
    --------
    >>> from assur.machines.ratings import rating_type
    >>> [p.name for p in rating_type("loader_breakout").fields][:5]
    ['edge', 'back', 'lift_cylinder', 'tilt_cylinder', 'offset']
    """

    edge: str = param("point", doc="the tip of the bucket's cutting edge")
    back: str = param("point", doc="a point of the bucket behind the edge's tip, along the edge")
    lift_cylinder: str = param("cylinder", doc="the lift (boom) cylinder")
    tilt_cylinder: str = param("cylinder", doc="the tilt (bucket) cylinder")
    offset: object = param("value", "length", default=0.1,
                           doc="how far behind the tip the force acts (ISO 14397-2: 100 mm)")
    self_weight: bool = param("flag", default=False,
                              doc="carry the mechanism's loads besides the force")
    name: object = param("text", default=None, doc="the title of the table and figure")

    type_name: ClassVar[str] = "loader_breakout"
    title: ClassVar[object] = Text("Breakout forces", ru="Вырывные усилия")
    standard: ClassVar[str] = "ISO 14397-2"

    def check(self, mech):
        """The lift and tilt cylinders must drive coordinates: ``(parameter, message)``
        or None.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.machines.ratings import rating_type
        >>> r = rating_type("loader_breakout")("S9", "09", "MPS", "MPT")
        >>> print(r.check(examples.loader_lab1()))
        None
        """
        driving = {c.name for c in mech.cylinders if c.coordinate is not None}
        for key in ("lift_cylinder", "tilt_cylinder"):
            if getattr(self, key) not in driving:
                return key, "expected a cylinder that drives a coordinate"
        return None

    def evaluate(self, mech, kin) -> RatingResult:
        """The breakout forces over the positions of ``kin`` (one design).

        Examples
        --------
        A two-link loader by hand: tests/machines/ratings/test_loader.py.

        >>> from assur.machines.ratings import rating_type
        >>> rating_type("loader_breakout").standard
        'ISO 14397-2'
        """
        cyls = {c.name: c for c in mech.cylinders if c.coordinate is not None}
        k = kin.k
        tx, ty = flat(kin.x(self.edge)), flat(kin.y(self.edge))
        bx, by = flat(kin.x(self.back)), flat(kin.y(self.back))
        span = np.hypot(bx - tx, by - ty)
        if (span == 0.0).any():
            raise ModelError(f"{mech.name}: the breakout rating's points {self.edge!r} and "
                             f"{self.back!r} coincide")
        lam = number(mech, self.offset) / span     # the point, fixed on the bucket
        px = tx + lam * (bx - tx)

        def dY(wrt):   # ∂Y/∂q of the point: T + λ·(K − T), λ constant on the body
            w = wrt if k > 1 else None
            return flat(kin.dy(self.edge, w)) + lam * (flat(kin.dy(self.back, w))
                                                       - flat(kin.dy(self.edge, w)))
        dead = None
        carried = None
        if self.self_weight:
            carried = carried_loads(mech, self.edge)
            if carried is not None:
                dead = virtual_work_forces(with_loads_of(kin, carried), g=mech.g)
        G = {}
        for name, c in cyls.items():
            fd = 0.0 if dead is None else flat(dead[c.coordinate])
            G[name] = holding_limit(mech, c, dY(c.coordinate), fd)
        series = coordinate_series(mech, kin) + [
            Series("x", px, "length", Text("reach of the point 100 mm behind the edge",
                                           ru="вылет точки в 100 мм за кромкой"))]
        series += [Series(f"G_{'_'.join(str(n).split())}", g, "force", Text(
            f"force of cylinder {localize(n, 'en')} at the point",
            ru=f"усилие цилиндра {localize(n, 'ru')} в точке"))
            for n, g in G.items()]
        tip = None
        if mech.machine is not None:
            tip = tipping_load(mech, kin, self.edge, carried, x=px)
            series.append(Series("G_stability", tip, "force", Text(
                "stability limit (tipping)", ru="предел по устойчивости (опрокидывание)")))
        for tag, own, en, ru in (("lift", self.lift_cylinder, "lift", "подъёма"),
                                 ("tilt", self.tilt_cylinder, "tilt", "поворота ковша")):
            lim = [G[own]] + [g for n, g in G.items() if n != own]
            if tip is not None:
                lim.append(tip)
            series.append(Series(f"F_{tag}", np.min(np.vstack(lim), axis=0), "force", Text(
                f"{en} breakout force (ISO 14397-2)",
                ru=f"вырывное усилие цилиндрами {ru} (ISO 14397-2)")))
        return RatingResult(self, tuple(series), kin.coordinates[-1], ("F_lift", "F_tilt"),
                            kin.coordinates[0] if k == 2 else None)


@register
@dataclass(frozen=True)
class LoaderLift(CraneChart):
    """The lift capacity at the bucket's centre of gravity over the height of its hinge
    pin (module notes; the lift test of ISO 789-2 generalised, ISO 14397-1's hydraulic
    lift capacity).

    Examples
    --------
    >>> from assur import io
    >>> from assur.machines.ratings import rating_type
    >>> model = io.load(io.bundled("loader_lab1"))
    >>> m = model.mechanism
    >>> r = rating_type("loader_lift")(point="S9", axis="01", pin="09").evaluate(
    ...     m, m.solve(model.range))
    >>> r.x, r.y
    ('pin_height', ('G',))
    """

    pin: str = param("point", default=None,
                     doc="the bucket's hinge pin: its height is the abscissa")

    type_name: ClassVar[str] = "loader_lift"
    title: ClassVar[object] = Text("Lift capacity over the height",
                                   ru="Грузоподъёмность по высоте подъёма")
    standard: ClassVar[str] = "ISO 14397-1"

    def evaluate(self, mech, kin) -> RatingResult:
        """The load chart with the hinge pin's height as its abscissa.

        Examples
        --------
        >>> from assur.machines.ratings import rating_type
        >>> rating_type("loader_lift").standard
        'ISO 14397-1'
        """
        r = CraneChart.evaluate(self, mech, kin)
        pin = self.pin or self.point
        h = flat(kin.y(pin)) - flat(kin.y(self.axis))
        s = Series("pin_height", h, "length", Text(f"height of {pin}", ru=f"высота точки {pin}"))
        return RatingResult(self, r.series + (s,), "pin_height", ("G",), r.group, r.notes)
