"""Masses of the links: their descriptions and values over a batch of designs.

* :class:`LinkMass` — a link's mass m [kg], its centre of mass (an existing named
  point, or a point given in the link's own frame: ``along`` its first→second point
  and ``offset`` to the left of that line [m]) and its moment of inertia J about the
  centre [kg·m²]; :func:`with_masses` adds them to a mechanism as
  :class:`assur.core.loads.Mass` loads (a centre given in the link's frame becomes a
  ``rigid_point`` group, so its motion is the engine's exact analogs);
* :func:`design_value` — a mass or an inertia of the mechanism as an array over its
  designs.

The crank machines' dynamics (:mod:`assur.dynamics.crank`), the equations of motion
(:mod:`assur.dynamics.eom`) and balancing (:mod:`assur.dynamics.balancing`) build on
these.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable

import numpy as np

from ..core.loads import LOAD_TYPES, masses_of
from ..errors import ModelError

__all__ = ["LinkMass", "with_masses", "masses_of", "design_value"]

_MASS = LOAD_TYPES["mass"]


@dataclass(frozen=True)
class LinkMass:
    """Mass properties of one link.

    Parameters
    ----------
    link : str
        The link (a body of the mechanism, e.g. ``"4"``).
    m : float
        Mass [kg] (> 0).
    J : float
        Moment of inertia about the centre of mass [kg·m²] (≥ 0).
    point : str, optional
        An existing named point that is the centre of mass. Without it the centre
        is given in the link's own frame by ``along`` and ``offset``.
    along : float
        Distance of the centre from the link's first point towards its second
        (the points that define the link's angle: a dyad's outer joint, then its
        middle joint; a crank's pivot, then its pin) [m].
    offset : float
        Distance of the centre to the left of that directed line [m].
    name : str, optional
        Name of the centre-of-mass point added for ``along``/``offset``
        (default ``"S<link>"``).

    Notes
    -----
    The centre ``S = P + along·u + offset·n`` (u the unit vector P→Q, n = u turned
    by +90°) is added as a ``rigid_point`` of length ``hypot(along, offset)`` turned
    ``atan2(offset, along)`` from P→Q: it moves with the body for any link, and its
    velocity and acceleration analogs are the engine's exact ones.

    Examples
    --------
    The hitch's implement 6 as a mass at S6 that weighs P6 = 27.5 kN (g = 9.81 m/s²):

    >>> from assur import examples
    >>> from assur.dynamics.crank import LinkMass, with_masses
    >>> m = with_masses(examples.hitch_003().with_loads(), [LinkMass("6", 27500.0 / 9.81,
    ...                                                             point="S6")])
    >>> [round(float(f)) for f in m.analyze([0.42, 0.67]).statics.actuator_force()]  # Fgc [N]
    [129614, 135652]
    """

    link: str
    m: float
    J: float = 0.0
    point: str | None = None
    along: float = 0.0
    offset: float = 0.0
    name: str | None = None


def with_masses(mech, masses: Iterable[LinkMass]):
    """A mechanism with the masses of ``masses`` added as :class:`assur.core.loads.Mass`
    loads (and their centres given in the link's frame as rigid points).

    Raises
    ------
    ModelError
        Unknown link, a non-positive mass, a negative J, a centre given both ways,
        a single-point link (a slider block) whose centre is not a named point, or a
        point name that exists already.

    Examples
    --------
    A centre of mass 0.5 m along the hitch's lower link 5 (from its pivot 05 towards
    45) becomes the new point S5:

    >>> from assur import examples
    >>> from assur.dynamics.crank import LinkMass, with_masses
    >>> m = with_masses(examples.hitch_003(), [LinkMass("5", 30.0, J=0.5, along=0.5)])
    >>> "S5" in m.points, m.loads[-1]               # [kg], [kg·m²]
    (True, Mass(link='5', m=30.0, point='S5', J=0.5))
    >>> with_masses(examples.hitch_003(), [LinkMass("5", -1.0, point="56")])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': link '5': m = -1.0 must be a finite ...
    """
    out = mech
    where = f"mechanism {mech.name!r}"
    for lm in masses:
        topo = out.topology
        if lm.link not in topo.bodies or lm.link == "0":
            raise ModelError(f"{where}: mass of unknown or fixed link {lm.link!r} (moving "
                             f"links: {sorted(b for b in topo.bodies if b != '0')})")
        for what, v, ok, rule in (("m", lm.m, lambda x: x > 0, "> 0 [kg]"),
                                  ("J", lm.J, lambda x: x >= 0, "≥ 0 [kg·m²]")):
            if not (isinstance(v, (int, float)) and math.isfinite(v) and ok(v)):
                raise ModelError(f"{where}: link {lm.link!r}: {what} = {v!r} must be a finite "
                                 f"number {rule}")
        if lm.point is not None:
            if lm.along or lm.offset:
                raise ModelError(f"{where}: link {lm.link!r}: give the centre of mass either as "
                                 f"point={lm.point!r} or by along/offset, not both")
            out = out.mass(lm.link, float(lm.m), lm.point, float(lm.J))
            continue
        pts = topo.bodies[lm.link]
        if len(pts) < 2:
            raise ModelError(f"{where}: link {lm.link!r} has the single point {pts[0]!r}; give "
                             f"its centre of mass as point=…")
        P, Q = pts[0], pts[1]
        ell = math.hypot(lm.along, lm.offset)
        if ell == 0.0:
            out = out.mass(lm.link, float(lm.m), P, float(lm.J))
            continue
        name = lm.name or f"S{lm.link}"
        if name in out.points:
            raise ModelError(f"{where}: link {lm.link!r}: the centre-of-mass point {name!r} "
                             f"exists already; name it with name=…")
        out = out.rigid_point(f"centre of mass {name}", origin=P, toward=Q, out=name,
                              length=ell, angle=math.atan2(lm.offset, lm.along),
                              links=(lm.link,))
        out = out.mass(lm.link, float(lm.m), name, float(lm.J))
    return out


def design_value(kin, ref):
    """A value of the mechanism (a number or a parameter name, e.g. a mass [kg] or
    an inertia [kg·m²]) as an array of shape (m, 1) over the designs of ``kin``.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.dynamics.crank import design_value
    >>> kin = examples.hitch_003().solve([0.42, 0.67])
    >>> design_value(kin, "P6").tolist(), design_value(kin, 2.0).tolist()   # [N], [-]
    ([[27500.0]], [[2.0]])
    >>> b = examples.hitch_003().solve([0.42, 0.67], params={"P6": [27500.0, 20000.0]})
    >>> design_value(b, "P6").tolist()                                      # [N]
    [[27500.0], [20000.0]]
    """
    v = np.asarray(kin.mechanism.value_of(ref), dtype=float)
    return np.broadcast_to(v.reshape(-1, 1), (kin.m, 1)) if v.ndim else np.full((kin.m, 1),
                                                                                float(v))
