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
``(0, −1)``: :func:`assur.core.statics.gravity_unit`), ``rate(link, coordinate)`` →
∂φ_link/∂q (the link's angular-velocity analog along a coordinate, 0 for the frame), ``moving`` and, when moving, ``acceleration(point)`` →
(a_x, a_y) and ``angular_acceleration(link)`` → ε. Each load type also declares its
model-file ``type_name``, the ``quantities`` and ``flags`` of its value fields and the
fields that name points (``point_fields``) and links (``link_fields``), and may check
itself against the mechanism (``check(mech)`` → a problem or None): validation, the
file schema's checks and the report derive from these, never from a list of types.
The same code then serves the array evaluation
(:func:`assur.core.statics.applied_loads`) and the generated fused kernel
(:mod:`assur.core.outputs`), where the values are symbols of the emitted code.
"""

from __future__ import annotations

from ._queries import centre_of_mass, dead_load_links, is_dead, load_link, masses_of, names_in
from ._registry import (FLAGS, LOAD_TYPES, ROLES, Load, load_type, on_register, param, register,
                        registry, unregister)
from ._types import Couple, Mass, PointForce, ResistingMoment, Spring, Weight

__all__ = ["Load", "param", "register", "unregister", "registry", "load_type", "on_register",
           "ROLES", "FLAGS", "Weight", "PointForce", "Couple", "ResistingMoment", "Spring",
           "Mass", "LOAD_TYPES", "names_in", "load_link", "masses_of", "dead_load_links",
           "is_dead", "centre_of_mass"]
