"""Loads and actuators of a mechanism: descriptions only (immutable dataclasses).

Sign conventions
----------------
* Forces are vectors in the mechanism's x–y frame [N]; a *weight* ``P`` at a point
  is the force ``P·u`` along the direction of gravity ``u`` — ``(0, −P)`` by default
  (``[model] gravity``, :meth:`Mechanism.with_gravity`).
* Moments are counter-clockwise positive [N·m].
* A spring between points ``a`` and ``b`` pulls them together with its tension
  ``T = preload + rate·(|ab| − free_length)`` [N] (a negative T pushes them apart)::

      a o--> T      T <--o b

* The actuator force of a cylinder (generalized coordinate = its pin-to-pin length
  S) is positive when it pushes (extends); for a crank coordinate it is the driving
  moment, counter-clockwise positive.

Every value may be a number or the name of a model parameter (so it may vary over
a batch of designs).

Each load applies itself through :meth:`apply` to a *load context* (the contract):
``value(ref)``, ``point(p)`` → (x, y), ``owner(p)``, ``force(link, point, fx, fy)``,
``couple(link, M)``, ``nonzero(L, what)``, ``spring(load, T, L)``, ``g`` [m/s²],
``gravity_unit`` (the direction of gravity, a unit vector ``(u_x, u_y)``, default
``(0, −1)``: :func:`assur.statics.gravity_unit`),
``moving`` and, when moving, ``acceleration(point)`` → (a_x, a_y) and
``angular_acceleration(link)`` → ε. The same code then serves the array evaluation
(:func:`assur.statics.applied_loads`) and the generated fused kernel
(:mod:`assur.fused`), where the values are symbols of the emitted code.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Union

import numpy as np

__all__ = ["Weight", "PointForce", "Couple", "Spring", "Mass", "Cylinder", "LOAD_TYPES"]

Ref = Union[str, float, int]


def _along_gravity(c, P):
    """The force of magnitude P along the context's direction of gravity: (fx, fy),
    an exact zero for a zero component (so the default weight is (0, −P))."""
    ux, uy = c.gravity_unit
    return (0.0 if ux == 0 else P * ux), (0.0 if uy == 0 else P * uy)


@dataclass(frozen=True)
class Weight:
    """Weight ``P`` [N] acting downward at ``point``, carried by ``link`` (by default
    the link that owns the point)."""

    point: str
    P: Ref
    link: str | None = None
    name: str | None = None

    #: the quantity of each value field (:mod:`assur.quantities`)
    quantities: ClassVar = {"P": "force"}

    def apply(self, c):
        P = c.value(self.P)
        c.force(self.link or c.owner(self.point), self.point, *_along_gravity(c, P))


@dataclass(frozen=True)
class PointForce:
    """Force ``(fx, fy)`` [N] at ``point``, carried by ``link`` (default: owner)."""

    point: str
    fx: Ref = 0.0
    fy: Ref = 0.0
    link: str | None = None
    name: str | None = None

    quantities: ClassVar = {"fx": "force", "fy": "force"}

    def apply(self, c):
        c.force(self.link or c.owner(self.point), self.point, c.value(self.fx),
                c.value(self.fy))


@dataclass(frozen=True)
class Couple:
    """Moment ``M`` [N·m], counter-clockwise positive, acting on ``link``."""

    link: str
    M: Ref
    name: str | None = None

    quantities: ClassVar = {"M": "moment"}

    def apply(self, c):
        c.couple(self.link, c.value(self.M))


@dataclass(frozen=True)
class Spring:
    """Linear spring(s) between points ``a`` and ``b`` (links ``links`` or the owners).

    Tension of one spring ``T = preload + rate·(|ab| − free_length)`` [N]; ``rate``
    [N/m], ``free_length`` [m], ``preload`` [N]. ``count`` identical springs act in
    parallel (seed 001 lab 2 eq. 4: k springs): the points are pulled together by
    ``count·T``.
    """

    name: str
    a: str
    b: str
    rate: Ref
    free_length: Ref
    preload: Ref = 0.0
    links: tuple[str, str] | None = None
    count: Ref = 1

    quantities: ClassVar = {"rate": "stiffness", "free_length": "length", "preload": "force",
                            "count": "number"}

    def tension(self, c, L):
        """Tension of one spring [N] at the length ``L`` [m] (context values)."""
        return c.value(self.preload) + c.value(self.rate) * (L - c.value(self.free_length))

    def apply(self, c):
        (ax, ay), (bx, by) = c.point(self.a), c.point(self.b)
        dx, dy = bx - ax, by - ay
        L = np.hypot(dx, dy)
        c.nonzero(L, f"spring {self.name!r}: its ends {self.a!r} and {self.b!r} coincide")
        T = self.tension(c, L)
        n = c.value(self.count)
        F = T if is_one(n) else n * T
        ux, uy = dx / L, dy / L
        la, lb = self.links or (c.owner(self.a), c.owner(self.b))
        c.force(la, self.a, F * ux, F * uy)
        c.force(lb, self.b, -F * ux, -F * uy)
        c.spring(self, T, L)


def is_one(v) -> bool:
    """True for the plain number 1 (a count that changes nothing)."""
    return isinstance(v, (int, float, np.floating, np.integer)) and float(v) == 1.0


@dataclass(frozen=True)
class Mass:
    """Mass ``m`` [kg] of a link with its centre of mass at ``point`` and moment of
    inertia ``J`` [kg·m²] about it: its weight m·g, and for a motion in time its
    inertia force −m·a and moment −J·ε (d'Alembert)."""

    link: str
    m: Ref
    point: str
    J: Ref = 0.0

    quantities: ClassVar = {"m": "mass", "J": "inertia"}

    def apply(self, c):
        m = c.value(self.m)
        c.force(self.link, self.point, *_along_gravity(c, m * c.g))
        if c.moving:
            acc_x, acc_y = c.acceleration(self.point)
            c.force(self.link, self.point, -m * acc_x, -m * acc_y)
            c.couple(self.link, -c.value(self.J) * c.angular_acceleration(self.link))


@dataclass(frozen=True)
class Cylinder:
    """Hydraulic cylinder(s) acting as the generalized coordinate ``coordinate``.

    Parameters
    ----------
    name : str
    coordinate : str
        The generalized coordinate (the cylinders' pin-to-pin length) [m].
    bore : float or str
        Piston diameter D [m].
    rod : float or str
        Rod diameter d [m] (used when ``side="rod"``).
    count : int or str
        Number of identical cylinders acting in parallel, k [-] (seed 003 k_gc = 2).
    eta_mech : float or str
        Mechanical efficiency of the linkage η_m [-]: the rod must push F/η_m
        (seed 000 km = 0.85).
    eta_hyd : float or str
        Hydraulic efficiency η_h [-]: pressure p = F/(k·A·η_h) (seed 003 η = 0.84,
        seed 000 kg = 0.96).
    p_relief : float or str
        Relief-valve setting p_relief [Pa].
    dp_throttle, dp_line : float or str
        Pressure losses at the throttle and in the line [Pa]; the largest working
        pressure is p_max = p_relief − (Δp_throttle + Δp_line) (001 lab 1 eq. 1).
    side : {"piston", "rod"}
        Which chamber is pressurised: piston area π·D²/4 or annulus π·(D² − d²)/4.
    """

    name: str
    coordinate: str
    bore: Ref
    rod: Ref = 0.0
    count: Ref = 1
    eta_mech: Ref = 1.0
    eta_hyd: Ref = 1.0
    p_relief: Ref = 0.0
    dp_throttle: Ref = 0.0
    dp_line: Ref = 0.0
    side: str = "piston"

    quantities: ClassVar = {"bore": "length", "rod": "length", "count": "number",
                            "eta_mech": "number", "eta_hyd": "number", "p_relief": "pressure",
                            "dp_throttle": "pressure", "dp_line": "pressure"}


LOAD_TYPES = {"weight": Weight, "force": PointForce, "moment": Couple, "spring": Spring,
              "mass": Mass}
