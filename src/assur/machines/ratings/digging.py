"""Digging forces of an excavator's or a backhoe's arm in the manner of ISO 6015
(``[[rating]] type = "excavator_digging"``, docs/ratings.md).

ISO 6015 rates an excavator by two forces at the bucket's tooth tip, in our words:

* the *bucket-cylinder digging force* F_B: the force the bucket cylinder, at its
  working pressure, exerts at the tooth tip along the tangent of the circle the tip
  describes about the bucket's pivot (on the arm), against the tip's motion as the
  bucket curls;
* the *arm-cylinder digging force* F_A: the same for the arm (stick) cylinder, along
  the tangent of the circle the tip describes about the arm's pivot (on the boom),
  the bucket held.

Each is taken over the working range (the model's ``[range]``) and limited by the
other cylinders' holding: the force along the same tangent at which another cylinder
would be overrun at its working pressure (its port relief valve opens).

Here, with P the tip, C the pivot, t the unit tangent of the circle about C at P
(t ⊥ CP, pointing the way the tip moves as the rated cylinder works: extends for a
``side = "extend"`` cylinder, retracts for ``"retract"``), a force F against the tip's
motion (−F·t) asks F_j = F·I_j of cylinder j by virtual work, I_j = t·∂P/∂q_j. The
force each cylinder sets is :func:`assur.machines.ratings.crane.holding_limit`, the
one capacity formula (:func:`assur.core.cylinders.capacity`) with the chamber of the
sign of I_j — the working chamber for the rated cylinder, the loaded one for a
holding cylinder; ``inf`` where a cylinder carries nothing (I_j = 0). The digging force
is the least of them, the governing cylinder named. The equipment's own weights are
left out unless ``self_weight = true`` (then carried, as by the crane chart).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ...core.virtual_work import virtual_work_forces
from ...errors import ModelError
from ...texts import Text, localize
from ._registry import register
from .base import Rating, RatingResult, Series, carried_loads, param, with_loads_of
from .crane import flat, holding_limit

__all__ = ["ExcavatorDigging", "tangent"]


def tangent(kin, point, pivot, wrt, sign):
    """The unit tangent of the circle ``point`` describes about ``pivot``, pointing the
    way ``point`` moves as the coordinate ``wrt`` changes by ``sign`` (±1), over the
    positions (one design): arrays (tx, ty) [-].

    Raises
    ------
    ModelError
        Where the point does not move along the tangent that way (it stands still,
        or the point is the pivot).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.machines.ratings.digging import tangent
    >>> kin = examples.hitch_003().solve([0.42, 0.67])
    >>> tx, ty = tangent(kin, "56", "05", None, 1.0)
    >>> bool(((tx ** 2 + ty ** 2 - 1.0) ** 2 < 1e-24).all())
    True
    """
    rx = flat(kin.x(point)) - flat(kin.x(pivot))
    ry = flat(kin.y(point)) - flat(kin.y(pivot))
    r = np.hypot(rx, ry)
    vx, vy = sign * flat(kin.dx(point, wrt=wrt)), sign * flat(kin.dy(point, wrt=wrt))
    along = -ry * vx + rx * vy            # (−ry, rx)·v: the motion along the tangent × r
    bad = (r == 0.0) | (along == 0.0)
    if bad.any():
        raise ModelError(f"{kin.mechanism.name}: {point!r} does not move along the circle "
                         f"about {pivot!r} at {int(bad.sum())} position(s)")
    s = np.sign(along) / r
    return -ry * s, rx * s


@register
@dataclass(frozen=True)
class ExcavatorDigging(Rating):
    """The bucket- and arm-cylinder digging forces at the tooth tip over the working
    range, each limited by the other cylinders' holding (module notes; ISO 6015).

    Examples
    --------
    >>> from assur.machines.ratings import rating_type
    >>> [p.name for p in rating_type("excavator_digging").fields][:5]
    ['tip', 'bucket_cylinder', 'bucket_pivot', 'arm_cylinder', 'arm_pivot']
    """

    tip: str = param("point", doc="the bucket's tooth tip")
    bucket_cylinder: str = param("cylinder", doc="the bucket cylinder (its side: the way it digs)")
    bucket_pivot: str = param("point", doc="the bucket's pivot on the arm")
    arm_cylinder: str = param("cylinder",
                              doc="the arm (stick) cylinder (its side: the way it digs)")
    arm_pivot: str = param("point", doc="the arm's pivot on the boom")
    self_weight: bool = param("flag", default=False,
                              doc="carry the model's loads other than those at the tip")
    name: object = param("text", default=None, doc="the title of the table and figure")

    type_name: ClassVar[str] = "excavator_digging"
    title: ClassVar[object] = Text("Digging forces at the tooth tip",
                                   ru="Усилия копания на кромке зуба")
    standard: ClassVar[str] = "ISO 6015"

    def check(self, mech):
        """The rated cylinders must drive coordinates and declare the way they dig
        (``side = "extend"`` or ``"retract"``): ``(parameter, message)`` or None.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.machines.ratings import rating_type
        >>> r = rating_type("excavator_digging")("S9", "MPS", "09", "MPT", "01")
        >>> print(r.check(examples.loader_lab1()))    # both push (side = "piston")
        None
        """
        cyls = {c.name: c for c in mech.cylinders}
        for key in ("bucket_cylinder", "arm_cylinder"):
            c = cyls.get(getattr(self, key))
            if c is None or c.coordinate is None:
                return key, "expected a cylinder that drives a coordinate"
            if c.side not in ("piston", "rod"):
                return key, (f"the cylinder {c.name!r} must declare the way it digs: side = "
                             f'"extend" or "retract" in its [[cylinders]] table, not {c.side!r}')
        return None

    def evaluate(self, mech, kin) -> RatingResult:
        """Both digging forces over the positions of ``kin`` (one design).

        Examples
        --------
        A ``[[rating]]`` of a two-link arm: tests/machines/ratings/test_digging.py.
        >>> from assur.machines.ratings import rating_type
        >>> rating_type("excavator_digging").standard
        'ISO 6015'
        """
        cyls = {c.name: c for c in mech.cylinders if c.coordinate is not None}
        P, k = self.tip, kin.k
        carried = carried_loads(mech, P) if self.self_weight else None
        dead = (virtual_work_forces(with_loads_of(kin, carried), g=mech.g)
                if carried is not None else None)
        series = [Series(c, flat(kin.q(c)), "angle" if mech.coordinate_kind(c) == "angle"
                         else "length", Text(f"coordinate {c}", ru=f"координата {c}"))
                  for c in kin.coordinates]
        notes, ys = [], []
        for tag, own, pivot, en, ru in (
                ("B", self.bucket_cylinder, self.bucket_pivot, "bucket", "ковша"),
                ("A", self.arm_cylinder, self.arm_pivot, "arm", "рукояти")):
            cyl = cyls.get(own)
            if cyl is None:
                raise ModelError(f"{mech.name}: the digging rating's {en} cylinder {own!r} "
                                 f"drives no coordinate")
            if cyl.side not in ("piston", "rod"):
                raise ModelError(f"{mech.name}: the {en} cylinder {own!r} must declare the way "
                                 f"it digs (side = \"extend\" or \"retract\"), not "
                                 f"{cyl.side!r}")
            sign = 1.0 if cyl.side == "piston" else -1.0
            tx, ty = tangent(kin, P, pivot, cyl.coordinate if k > 1 else None, sign)
            limits, names = [], []
            for c in [cyl] + [c for c in cyls.values() if c is not cyl]:
                wrt = c.coordinate if k > 1 else None
                I = tx * flat(kin.dx(P, wrt=wrt)) + ty * flat(kin.dy(P, wrt=wrt))
                fd = 0.0 if dead is None else flat(dead[c.coordinate])
                G = holding_limit(mech, c, I, fd)
                mine = c is cyl
                sym = (f"F_{tag}_{'_'.join(str(c.name).split())}" if mine else
                       f"H_{tag}_{'_'.join(str(c.name).split())}")
                limits.append(G)
                names.append(c.name)
                cen, cru = localize(c.name, "en"), localize(c.name, "ru")
                series.append(Series(sym, G, "force", Text(
                    f"{en} digging: force of cylinder {cen}" if mine
                    else f"{en} digging: holding limit of cylinder {cen}",
                    ru=f"копание {ru}: усилие цилиндра {cru}" if mine
                    else f"копание {ru}: предел удержания цилиндром {cru}")))
            L = np.vstack(limits)
            which = np.argmin(L, axis=0)
            F = L[which, np.arange(L.shape[1])]
            series += [Series(f"F_{tag}", F, "force", Text(
                           f"{en}-cylinder digging force (ISO 6015)",
                           ru=f"усилие копания цилиндром {ru} (ISO 6015)")),
                       Series(f"gov_{tag}", which + 1.0, "number", Text(
                           f"{en} digging: governing cylinder (key below)",
                           ru=f"копание {ru}: определяющий цилиндр (ниже)"))]
            ys.append(f"F_{tag}")
            key = {lg: "; ".join(f"{i + 1} = {localize(n, lg)}" for i, n in enumerate(names))
                   for lg in ("en", "ru")}
            notes.append(Text(f"gov_{tag}, {en} digging along the tangent about {pivot}: "
                              f"{key['en']}",
                              ru=f"gov_{tag}, копание {ru} по касательной к окружности "
                                 f"около {pivot}: {key['ru']}"))
        x = kin.coordinates[0]
        group = kin.coordinates[1] if k == 2 else None
        return RatingResult(self, tuple(series), x, tuple(ys), group, tuple(notes))
