"""The load chart of a crane or manipulator arm: lifting capacity over the reach and
height (``[[rating]] type = "crane_chart"``, docs/ratings.md).

Makers of loader cranes and forestry manipulators publish a load chart: the load the
crane lifts at each reach of its hook, with the gross lifting moment, capacity ×
reach (ISO 4301-1 classifies cranes by it; ISO 10245-1 asks for the rated capacity to
be shown over the reach). Here, in our words, over the positions of the arm's two
coordinates (the model's ``[range]`` grid):

* the *reach* R and *height* H of the load point P, measured from a point on the
  slewing axis (``axis``): R = X_P − X_axis, H = Y_P − Y_axis [m];
* the *limit of cylinder j*: the vertical load at P that cylinder j holds at its
  largest working pressure, in the chamber that holds a load at P (the piston side
  where P rises as the cylinder extends, I_j = ∂Y_P/∂q_j > 0; the rod side where it
  rises as the cylinder retracts, I_j < 0 — the direction doing the work of lifting
  P), carrying the arm's own loads (every load of the model but those at P):
  G_j = (σ_j·F_max,j·η_m − F_dead,j)/I_j, σ_j = sign I_j, by
  :func:`assur.core.cylinders.capacity` (virtual work: a load G at P asks
  F_j = G·I_j of the cylinder); where I_j = 0 the cylinder carries nothing of the
  load and sets no limit (``inf``);
* the *stability limit* when the model describes its machine (``[machine]``): the
  load at P at which the reaction of the axle farther from it reaches zero
  (:func:`assur.machines.ratings.tipping_load`);
* the *capacity* G = min over the limits, with the *governing* limit named, and the
  *gross lifting moment* M = G·R [N·m].

The charts of the three seed-004 manipulators are illustrations of the method with
the cylinders' pressures and rods of their model files, not the makers' published
charts.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import ClassVar

import numpy as np

from ...core import cylinders as C
from ...core.virtual_work import virtual_work_forces
from ...texts import Text, localize
from ..capacity import lifts
from ._registry import register
from .base import (Rating, RatingResult, Series, carried_loads, need_cylinders, number, param,
                   with_loads_of)
from .stability import tipping_load

__all__ = ["CraneChart", "flat", "holding_limit"]


def flat(a) -> np.ndarray:
    """An array of one design as a 1-D float array over the positions.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.machines.ratings.crane import flat
    >>> flat(np.ones((1, 3))).shape
    (3,)
    """
    return np.asarray(a, float).reshape(-1)


def holding_limit(mech, cyl, I, F_dead=0.0):
    """The load a cylinder holds at its largest working pressure, G = (σ·F_max·η_m −
    F_dead)/I with σ = sign I (the chamber that holds a load along which the point
    moves I per unit of the cylinder's length; :func:`assur.core.cylinders.capacity`);
    ``inf`` where I = 0 (the load asks nothing of the cylinder).

    Parameters
    ----------
    mech : Mechanism
    cyl : assur.core.cylinders.Cylinder
    I : ndarray
        ∂s/∂q: the displacement of the load's point along the load (against it: a
        downward weight, s = Y) per unit length of the cylinder [-].
    F_dead : ndarray or float
        The actuator force of the other loads along the cylinder [N].

    Examples
    --------
    One 80 mm cylinder at 20 MPa pushing a point that rises 2 m per metre of stroke:

    >>> import numpy as np
    >>> from assur.core.cylinders import Cylinder
    >>> from assur.machines.ratings.crane import holding_limit
    >>> c = Cylinder("c", coordinate="S", bore=0.08, rod=0.04, p_relief=20e6)
    >>> holding_limit(None, c, np.array([2.0, -2.0, 0.0])).round().tolist()   # [N]
    [50265.0, 37699.0, inf]
    """
    t = C.terms(replace(cyl, side="auto"), lambda r: number(mech, r))
    I = np.asarray(I, float)
    zero = I == 0.0
    Is = np.where(zero, 1.0, I)
    G = C.capacity(t, Is, F_dead, Is, C.select_array)
    return np.where(zero, np.inf, G)


@register
@dataclass(frozen=True)
class CraneChart(Rating):
    """A crane's load chart: the lifting capacity at the load point over the reach and
    height, each cylinder's limit and the stability limit, the governing one named,
    and the gross lifting moment (module notes; ISO 4301-1, ISO 10245-1).

    Examples
    --------
    >>> from assur import io
    >>> model = io.load(io.bundled("crane_lv184a"))
    >>> r = model.ratings[0].evaluate(model.mechanism, model.mechanism.solve(model.range))
    >>> r.symbols
    ('S1', 'S2', 'reach', 'height', 'G_boom_cylinder', 'G_stick_cylinder', 'G', 'governing', 'M')
    >>> bool((r["G"] > 0).all()), bool((r["M"] == r["G"] * r["reach"]).all())
    (True, True)
    """

    point: str = param("point", doc="the load point (the hook, the grapple's axis)")
    axis: str = param("point", doc="a point on the slewing axis: reach and height are from it")
    cylinders: tuple = param("cylinders", default=None,
                             doc="the cylinders that limit (default: every one moving the point)")
    self_weight: bool = param("flag", default=True,
                              doc="carry the model's loads other than those at the point")
    name: object = param("text", default=None, doc="the title of the table and figure")

    type_name: ClassVar[str] = "crane_chart"
    title: ClassVar[object] = Text("Load chart: lifting capacity over the reach",
                                   ru="Грузовая характеристика: грузоподъёмность по вылету")
    standard: ClassVar[str] = "ISO 4301-1, ISO 10245-1"

    def check(self, mech):
        """Some cylinder of the chart must drive a coordinate that moves the load point:
        ``(parameter, message)`` or None.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.machines.ratings import rating_type
        >>> rating_type("crane_chart")(point="07", axis="01").check(examples.hitch_003())
        ('point', "no cylinder of the chart moves '07' (cylinders on coordinates: ГЦ on S)")
        """
        cyls = [c for c in mech.cylinders if c.coordinate is not None
                and (self.cylinders is None or c.name in self.cylinders)]
        if not any(lifts(mech, c.coordinate, self.point) for c in cyls):
            on = ", ".join(f"{c.name} on {c.coordinate}" for c in cyls) or "none"
            return "point", (f"no cylinder of the chart moves {self.point!r} (cylinders on "
                             f"coordinates: {on})")
        return None

    def evaluate(self, mech, kin) -> RatingResult:
        """The load chart over the positions of ``kin`` (one design; module notes).

        Examples
        --------
        >>> from assur import io
        >>> model = io.load(io.bundled("crane_lv185"))
        >>> r = model.ratings[0].evaluate(model.mechanism, model.mechanism.solve(model.range))
        >>> set(r["governing"]) <= {1.0, 2.0}, bool((r["G"] > 0).all())
        (True, True)
        """
        P, k = self.point, kin.k
        reach = flat(kin.x(P)) - flat(kin.x(self.axis))
        height = flat(kin.y(P)) - flat(kin.y(self.axis))
        carried = carried_loads(mech, P) if self.self_weight else None
        dead = (virtual_work_forces(with_loads_of(kin, carried), g=mech.g)
                if carried is not None else None)
        series = [Series(c, flat(kin.q(c)), mech.coordinate_kind(c) if
                         mech.coordinate_kind(c) == "angle" else "length",
                         Text(f"coordinate {c}", ru=f"координата {c}"))
                  for c in kin.coordinates]
        series += [Series("reach", reach, "length",
                          Text(f"reach of {P}", ru=f"вылет точки {P}")),
                   Series("height", height, "length",
                          Text(f"height of {P}", ru=f"высота точки {P}"))]
        limits, names = [], []
        for cyl in need_cylinders(mech, self.cylinders, self.type_name):
            if not lifts(mech, cyl.coordinate, P):
                continue
            I = flat(kin.transmission(P, wrt=cyl.coordinate if k > 1 else None))
            fd = 0.0 if dead is None else flat(dead[cyl.coordinate])
            G = holding_limit(mech, cyl, I, fd)
            sym = "G_" + "_".join(str(cyl.name).split())
            limits.append(G)
            names.append(cyl.name)
            series.append(Series(sym, G, "force",
                                 Text(f"limit of cylinder {localize(cyl.name, 'en')}",
                                      ru=f"предел по цилиндру {localize(cyl.name, 'ru')}")))
        if mech.machine is not None:
            G = tipping_load(mech, kin, P, carried)
            limits.append(G)
            names.append(Text("stability", ru="устойчивость"))
            series.append(Series("G_stability", G, "force",
                                 Text("stability limit (tipping)",
                                      ru="предел по устойчивости (опрокидывание)")))
        L = np.vstack(limits)
        which = np.argmin(L, axis=0)
        G = L[which, np.arange(L.shape[1])]
        series += [Series("G", G, "force", Text(f"lifting capacity at {P}",
                                                ru=f"грузоподъёмность в точке {P}")),
                   Series("governing", which + 1.0, "number",
                          Text("governing limit (key below)", ru="определяющий предел (ниже)")),
                   Series("M", G * reach, "moment", Text("gross lifting moment G·reach",
                                                         ru="грузовой момент G·вылет"))]
        key = {lg: "; ".join(f"{i + 1} = {localize(n, lg)}" for i, n in enumerate(names))
               for lg in ("en", "ru")}
        notes = (Text(f"governing limit: {key['en']}", ru=f"определяющий предел: {key['ru']}"),
                 Text(f"each cylinder at its largest working pressure, in the chamber that "
                      f"holds a load at {P}; "
                      + ("the model's other loads carried" if carried is not None
                         else "the model's other loads not carried")
                      + "; illustrative of the method, not a maker's chart",
                      ru=f"каждый цилиндр при наибольшем рабочем давлении, в полости, "
                         f"удерживающей груз в точке {P}; "
                      + ("прочие нагрузки модели учтены" if carried is not None
                         else "прочие нагрузки модели не учтены")
                      + "; иллюстрация метода, не паспортная характеристика"))
        group = kin.coordinates[0] if k > 1 else None
        return RatingResult(self, tuple(series), "reach", ("G",), group, notes)
