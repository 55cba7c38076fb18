"""The :class:`Mechanism`: frame points, an ordered list of structural groups,
named links, and the parameters they refer to — an immutable description.

Building returns new mechanisms (one builder method per registered group type,
named after its model-file ``type``: :func:`assur.groups.registry`). Solving
compiles the description into a :class:`~assur.core.program.Program` (cached per
structure), runs it and returns a :class:`~assur.core.kinematics.Kinematics` result.
Every parameter may be a scalar or an array over designs, shape ``(m,)``;
generalized coordinates are arrays of shape ``(n,)`` (one design) or ``(m, n)``
(a batch of designs), see DESIGN.md §1–2.
"""

from __future__ import annotations

import inspect
import math
from types import MappingProxyType
from typing import Iterable, Mapping

import numpy as np

from . import diagnostics, inputs
from ..errors import AssemblyError, ModelError
from ..groups import Distance, Frame, Group, Link, registry
from ..groups.base import is_number, ref_value, signed_name
from .gravity import GRAVITY
from .kinematics import Kinematics
from .program import compile_program, execute, trig_table
from .topology import Topology, build_topology

__all__ = ["Mechanism"]


class _Values:
    """Reference values for the plain-numpy evaluation: ``val(ref)``, and the
    positions of the groups before one at other coordinates (``positions_at``)."""

    def __init__(self, mech, q, params):
        self.mech, self.q, self.params = mech, q, params

    def __call__(self, ref):
        if ref is None:
            return None
        if is_number(ref):
            return float(ref)
        if ref in self.q:
            return self.q[ref]
        return ref_value(self.params, ref)

    def positions_at(self, group, qvals):
        i = self.mech.groups.index(group)
        q = dict(zip(self.mech.coordinates, qvals))
        return self.mech.evaluate_positions(q, self.params, upto=i)


class Mechanism:
    """A planar linkage: frame points, structural groups in solving order, links.

    Parameters
    ----------
    name : str
        Name of the machine (e.g. ``"hitch_003"``).
    coordinates : sequence of str
        Names of the k generalized coordinates (cylinder lengths [m] or crank
        angles [rad]), e.g. ``("S",)``.
    params : mapping of str to float or array_like, shape (m,)
        Named parameters [SI units: m, rad]. Arrays make a batch of ``m`` designs.
    title : str, optional
        Human title for reports (a :class:`assur.texts.Text` may carry translations).
    units : mapping of str to Unit, optional
        How to show each parameter to the user (:class:`assur.core.quantities.Unit`: the
        unit a model file gave it, e.g. kN, MPa, mm, deg). Parameters without one are
        shown in the SI unit of their quantity (angles in degrees).

    Examples
    --------
    >>> from assur import Mechanism
    >>> m = Mechanism("fourbar", coordinates=("S",), params={"L3": 0.2})
    >>> m = m.frame("01", 0.415, 0.563).frame("03", 0.25, 1.112)
    >>> m = m.cylinder_lever("lever", base="01", pivot="03", out="23", lever="L3",
    ...                      s="S", branch=-1, links=("2", "3"))
    >>> r = m.solve([0.42, 0.67])
    >>> [round(float(v), 1) for v in r.phi("3", degrees=True)]
    [-40.2, 37.2]
    """

    def __init__(self, name: str, coordinates: Iterable[str] = ("S",),
                 params: Mapping[str, object] | None = None, title: str | None = None,
                 groups: Iterable = (), links: Iterable[Link] = (),
                 distances: Iterable[Distance] = (), tables: Mapping | None = None,
                 notes: Iterable[str] = (), loads: Iterable = (), cylinders: Iterable = (),
                 machine=None, gravity: float | None = None, units: Mapping | None = None,
                 motions: Iterable = (), gravity_direction: float | None = None,
                 _params_checked: bool = False):
        self.name = name
        self.title = title or name
        self.coordinates = tuple(coordinates)
        if not self.coordinates:
            raise ModelError(f"mechanism {name!r}: at least one generalized coordinate is needed")
        if len(set(self.coordinates)) != len(self.coordinates):
            raise ModelError(f"mechanism {name!r}: duplicate coordinate names {self.coordinates}")
        self.params = MappingProxyType(dict(params or {}))
        #: display unit of each parameter (:class:`assur.core.quantities.Unit`), as given
        self.units = MappingProxyType(dict(units or {}))
        self.groups = tuple(groups)
        self.links = tuple(links)
        self.distances = tuple(distances)
        #: what :meth:`Kinematics.to_frame` tabulates: ``ratios`` (pairs), ``transmissions``
        self.tables = MappingProxyType(dict(tables or {}))
        #: notes on seed slips resolved in this model (shown in reports)
        self.notes = tuple(notes)
        #: applied loads (:mod:`assur.core.loads`): weights, forces, moments, springs, masses
        self.loads = tuple(loads)
        #: hydraulic cylinders acting as generalized coordinates (:class:`assur.core.loads.Cylinder`)
        self.cylinders = tuple(cylinders)
        #: machine data for stability (:class:`assur.machines.stability.Machine`) or None
        self.machine = machine
        #: acceleration of gravity for the masses' weights [m/s²] as given (None: the
        #: default :data:`assur.core.gravity.GRAVITY`; :attr:`g` is the value used)
        self.gravity = gravity
        #: direction of gravity from +x [rad] (None: straight down, −π/2); see
        #: :func:`assur.core.gravity.gravity_unit`
        self.gravity_direction = gravity_direction
        #: direction of rotation and speed of crank coordinates (:class:`assur.core.motion.Motion`)
        self.motions = tuple(motions)
        #: programs and prepared tables of this (immutable) mechanism
        self._cache: dict = {}
        self._check_gravity()
        self._validate(check_params=not _params_checked)
        self._check_motions()

    # ---- building (each returns a new mechanism) -------------------------------
    #: attributes a copy may change without validating the structure again
    _DATA_ONLY = frozenset({"params", "title", "tables", "notes", "gravity", "units",
                            "motions", "gravity_direction"})

    def _with(self, **kw):
        if kw and set(kw) <= self._DATA_ONLY and ("params" not in kw
                                                  or set(kw["params"]) == set(self.params)):
            # same structure and parameter names: reuse the validated topology, check
            # only the values that changed (solving conditions calls this many times)
            new = object.__new__(Mechanism)
            new.__dict__.update(self.__dict__)
            # same structure: the programs hold; the prepared tables do not
            if "params" in kw:   # one program and one set of roles for every variant
                self.program()
            new._cache = {k: v for k, v in self._cache.items() if k[0] in ("program", "roles")}
            for k, v in kw.items():
                setattr(new, k, MappingProxyType(dict(v)) if k in ("params", "tables", "units")
                        else tuple(v) if k in ("notes", "motions") else v)
            if "params" in kw:
                changed = {n: v for n, v in kw["params"].items() if v is not self.params[n]}
                new._check_params(changed)
                inputs.mark_checked(self, new, changed)
            if "gravity" in kw or "gravity_direction" in kw:
                new._check_gravity()
            if "motions" in kw:
                new._check_motions()
            return new
        d = dict(name=self.name, coordinates=self.coordinates, params=self.params,
                 title=self.title, groups=self.groups, links=self.links,
                 distances=self.distances, tables=self.tables, notes=self.notes,
                 loads=self.loads, cylinders=self.cylinders, machine=self.machine,
                 gravity=self.gravity, units=self.units, motions=self.motions,
                 gravity_direction=self.gravity_direction,
                 _params_checked="params" not in kw)
        d.update(kw)
        return Mechanism(**d)

    def add(self, *groups) -> "Mechanism":
        """Return a mechanism with ``groups`` appended (solved after the existing ones).

        Examples
        --------
        >>> from assur import Mechanism
        >>> from assur.groups import Frame
        >>> m = Mechanism("m", coordinates=("j1",)).frame("O1", 0.0, 0.0)
        >>> m.add(Frame(name="O3", x=1.209, y=0.0)).frame_points     # x, y [m]
        ('O1', 'O3')
        """
        return self._with(groups=self.groups + tuple(groups))

    def extended(self, groups=(), params=None) -> "Mechanism":
        """Return a mechanism with ``groups`` appended and ``params`` added (new
        parameter names; :meth:`with_params` changes existing ones).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups import Frame
        >>> m = examples.hitch_003().extended([Frame(name="09", x="X09", y=0.2)],
        ...                                   params={"X09": 1.5})     # [m]
        >>> m.frame_points, float(m.params["X09"])
        (('01', '03', '05', '07', '09'), 1.5)
        >>> m.extended(params={"L4": 0.7})
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: mechanism 'hitch_003': parameters ['L4'] exist already; change them with with_params
        """
        p = dict(self.params)
        clash = sorted(set(params or {}) & set(p))
        if clash:
            raise ModelError(f"mechanism {self.name!r}: parameters {clash} exist already; "
                             f"change them with with_params")
        p.update(params or {})
        return self._with(params=p, groups=self.groups + tuple(groups))

    def add_group(self, type_name: str, name: str, **kw) -> "Mechanism":
        """Add a group of the registered type ``type_name`` (the model file's ``type``).

        Examples
        --------
        The builder ``m.dyad("II", …)`` is ``m.add_group("dyad", "II", …)``; a seed
        003-like four-bar, lengths [m]:

        >>> from assur import Mechanism
        >>> m = (Mechanism("m", coordinates=("S",), params={"L3": 0.2})
        ...      .frame("01", 0.415, 0.563).frame("03", 0.25, 1.112).frame("05", 0.135, 0.48)
        ...      .add_group("cylinder_lever", "I", base="01", pivot="03", out="23",
        ...                 lever="L3", s="S", branch=-1, links=["2", "3"])
        ...      .add_group("dyad", "II", a="23", b="05", out="45", ra=0.6, rb=0.48,
        ...                 branch=1, links=["4", "5"]))
        >>> m.group("II").links, m.owner("45")
        (('4', '5'), '5')
        >>> m.add_group("gear", "G")
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: unknown group type 'gear'; known: ['crank', 'cylinder_lever', 'dyad', 'frame', 'pose_point', 'prp_dyad', 'rigid_point', 'rpr_dyad', 'slider_dyad', 'slider_input']
        """
        types = registry()
        if type_name not in types:
            raise ModelError(f"unknown group type {type_name!r}; known: {sorted(types)}")
        cls = types[type_name]
        roles = {f.name: f.role for f in cls.fields}
        for f in cls.fields:
            if f.role == "coordinate" and f.name != "angle" and "angle" in kw and \
                    "angle" not in roles:
                raise ModelError(f"{cls.kind} {name!r}: its coordinate is given as "
                                 f"{f.name}=…, not angle=… (angle is a fixed angle in every "
                                 f"group that has one)")
        for k, v in list(kw.items()):
            if k == "links" or roles.get(k) == "line":
                kw[k] = tuple(v) if v is not None else (() if k == "links" else None)
            elif roles.get(k) == "position":
                kw[k] = tuple(v) if isinstance(v, (tuple, list)) else (v,)
        try:
            g = cls(name=name, **kw)
        except TypeError as e:
            allowed = ["links"] + [f.name for f in cls.fields]
            raise ModelError(f"{cls.kind} {name!r}: {e}; its parameters: {allowed}") from None
        return self.add(g)

    def frame(self, name, x=None, y=None, *, origin=None, length=None,
              angle=None) -> "Mechanism":
        """Add a frame pivot at ``(x, y)`` [m] — or at ``origin + length∠angle`` from
        the frame point ``origin`` (``length`` [m], ``angle`` [rad] from +x; seed 002:
        ``.frame("O3", origin="O1", length="l10", angle="j10")``). Values are numbers
        or parameter names; the polar form is evaluated per design, like any
        parameter (:class:`assur.groups.Frame`).

        Examples
        --------
        >>> from assur import Mechanism
        >>> m = (Mechanism("m", coordinates=("j1",), params={"l10": 1.209, "j10": -0.124})
        ...      .frame("O1", 0.0, 0.0).frame("O3", origin="O1", length="l10", angle="j10"))
        >>> m.frame_points
        ('O1', 'O3')
        """
        return self.add(Frame(name=name, x=x, y=y, origin=origin, length=length, angle=angle))

    def link(self, name, tail, head) -> "Mechanism":
        """Name the link whose angle φ_name is the direction ``tail → head``.

        Examples
        --------
        >>> from assur import examples
        >>> r = examples.hitch_003().solve([0.42])
        >>> round(float(r.phi("3", degrees=True)[0]), 1)   # link 3 = 03 → 23, table 2.1
        -40.2
        """
        return self._with(links=self.links + (Link(name, tail, head),))

    def distance(self, name, a, b, angle=None) -> "Mechanism":
        """Name the distance |a–b| [m] (e.g. a dependent cylinder length); ``angle``
        also names its direction a → b (an angle φ_angle, as a link of that name).

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003().distance("d57", "05", "67", angle="57")
        >>> r = m.solve([0.42, 0.67])                                  # S [m]
        >>> [round(float(v), 3) for v in r.length("d57")]             # |05–67| [m]
        [1.037, 1.253]
        >>> [round(float(v), 1) for v in r.phi("57", degrees=True)]   # its angle [°]
        [13.1, 56.6]
        """
        links = self.links + ((Link(angle, a, b),) if angle is not None else ())
        return self._with(distances=self.distances + (Distance(name, a, b, angle),),
                          links=links)

    def distance_angle(self, name):
        """The name of the link angle of the distance ``name`` (None if it has none).

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003().distance("d57", "05", "67", angle="57")
        >>> m.distance_angle("d57")
        '57'
        >>> print(m.distance("d07", "07", "56").distance_angle("d07"))
        None
        """
        for d in self.distances:
            if d.name == name:
                return d.angle
        raise KeyError(f"no distance {name!r} in mechanism {self.name!r}; distances: "
                       f"{[d.name for d in self.distances]}")

    # ---- loads and actuators ---------------------------------------------------
    def weight(self, point, P, link=None, name=None) -> "Mechanism":
        """Add a weight ``P`` [N] acting downward at ``point`` (see :mod:`assur.core.loads`).

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003().with_loads().weight("S6", 27500.0)
        >>> round(float(m.analyze([0.42]).statics.actuator_force("S")[0]))  # P6·IS6 [N]
        129614
        """
        from .loads import Weight
        return self._with(loads=self.loads + (Weight(point, P, link, name),))

    def force(self, point, fx=0.0, fy=0.0, link=None, name=None) -> "Mechanism":
        """Add a force ``(fx, fy)`` [N] at ``point``.

        Examples
        --------
        A downward force of 27.5 kN at S6 asks of the cylinder what the seed's weight
        P6 does:

        >>> from assur import examples
        >>> m = examples.hitch_003().with_loads().force("S6", fy=-27500.0)
        >>> round(float(m.analyze([0.42]).statics.actuator_force("S")[0]))  # P6·IS6 [N]
        129614
        """
        from .loads import PointForce
        return self._with(loads=self.loads + (PointForce(point, fx, fy, link, name),))

    def moment(self, link, M, name=None) -> "Mechanism":
        """Add a moment ``M`` [N·m] (counter-clockwise positive) on ``link``.

        Examples
        --------
        By virtual work the rod force is F = −M·φ6' (φ6' [rad/m], seed 003 table 3.1):

        >>> from assur import examples
        >>> a = examples.hitch_003().with_loads().moment("6", 1000.0).analyze([0.42, 0.67])
        >>> [round(float(v), 1) for v in a.statics.actuator_force("S")]   # [N]
        [-294.9, -3084.9]
        >>> [round(float(v), 3) for v in a.kinematics.dphi("6")]          # [rad/m]
        [0.295, 3.085]
        """
        from .loads import Couple
        return self._with(loads=self.loads + (Couple(link, M, name),))

    def spring(self, name, a, b, rate, free_length, preload=0.0, links=None,
               count=1) -> "Mechanism":
        """Add ``count`` identical springs between points ``a`` and ``b`` (rate [N/m],
        free length [m], preload [N] of one spring); tension pulls the points
        together.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import spring_states
        >>> m = examples.hitch_003().with_loads().spring("k", "07", "S6", rate=1e4,
        ...                                              free_length=1.0)  # [N/m], [m]
        >>> L, T, F = spring_states(m.solve([0.42, 0.67]))["k"]
        >>> [round(float(v), 3) for v in L], [round(float(v)) for v in T]  # [m], [N]
        ([1.674, 1.463], [6745, 4630])
        """
        from .loads import Spring
        links = tuple(links) if links else None
        return self._with(loads=self.loads + (Spring(name, a, b, rate, free_length, preload,
                                                     links, count),))

    def mass(self, link, m, point, J=0.0) -> "Mechanism":
        """Give ``link`` a mass ``m`` [kg] at ``point`` and inertia ``J`` [kg·m²].

        Examples
        --------
        A mass weighing the seed's P6 = 27.5 kN (g = 9.81 m/s²) at rest:

        >>> from assur import examples
        >>> m = examples.hitch_003().with_loads().mass("6", 27500.0 / 9.81, "S6")  # [kg]
        >>> round(float(m.analyze([0.42]).statics.actuator_force("S")[0]))  # [N]
        129614
        """
        from .loads import Mass
        return self._with(loads=self.loads + (Mass(link, m, point, J),))

    def resisting_moment(self, link, M, travel=1, coordinate=None, name=None) -> "Mechanism":
        """Add a moment of magnitude ``M`` [N·m] on ``link`` that opposes its turn while
        the coordinate travels in the direction ``travel`` (±1;
        :class:`assur.core.loads.ResistingMoment`).

        Examples
        --------
        Link 6 turns counter-clockwise as S grows (φ6' > 0), so 1000 N·m resisting
        that travel acts clockwise and the rod must push (compare :meth:`moment`):

        >>> from assur import examples
        >>> m = examples.hitch_003().with_loads().resisting_moment("6", 1000.0, travel=1)
        >>> [round(float(v), 1) for v in m.analyze([0.42, 0.67]).statics.actuator_force("S")]
        [294.9, 3084.9]
        """
        from .loads import ResistingMoment
        return self._with(loads=self.loads + (ResistingMoment(link, M, travel, coordinate,
                                                              name),))

    def cylinder(self, name, coordinate=None, **kw) -> "Mechanism":
        """Add hydraulic cylinder data for a coordinate, or a passive cylinder on a named
        distance (``distance=…``, ``supply=…``; see :class:`assur.core.loads.Cylinder`).

        Examples
        --------
        Two cylinders of 80 mm bore lifting 10 kN at the lever's pin 23:

        >>> from assur import Mechanism
        >>> m = (Mechanism("lift", coordinates=("S",), params={"L3": 0.2})
        ...      .frame("01", 0.415, 0.563).frame("03", 0.25, 1.112)
        ...      .cylinder_lever("lever", base="01", pivot="03", out="23", lever="L3",
        ...                      s="S", branch=-1, links=("2", "3"))
        ...      .weight("23", 10000.0)                                   # [N]
        ...      .cylinder("C", "S", bore=0.08, count=2))                 # bore [m]
        >>> c = m.analyze([0.42]).cylinder("C")
        >>> round(float(c.force[0])), round(float(c.pressure[0] / 1e6), 3)  # [N], [MPa]
        (10259, 1.02)
        """
        from .cylinders import Cylinder
        return self._with(cylinders=self.cylinders + (Cylinder(name, coordinate, **kw),))

    def with_cylinders(self, cylinders=()) -> "Mechanism":
        """The same mechanism with ``cylinders`` (:class:`assur.core.cylinders.Cylinder`;
        none by default) in place of its own — e.g. one cylinder's data changed with
        :func:`dataclasses.replace`.

        Examples
        --------
        The seed-003 hitch's cylinders fed on their rod side (d = 40 mm): they pull,
        while its implement needs a push — the pressure is negative (the chamber cannot
        hold the loads), larger in the ratio of the areas, A_p/A_r = 4/3:

        >>> import dataclasses
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> c = dataclasses.replace(m.cylinders[0], side="rod", rod=0.04)   # rod [m]
        >>> p0 = m.analyze([0.42]).cylinder().pressure[0]                    # [Pa]
        >>> p1 = m.with_cylinders([c]).analyze([0.42]).cylinder().pressure[0]
        >>> round(float(p1 / p0), 6)
        -1.333333
        """
        return self._with(cylinders=tuple(cylinders))

    def with_machine(self, machine, point, weight, refs=None) -> "Mechanism":
        """Carry the implement (weight [N] at ``point``) on a machine for the stability
        analysis (:class:`assur.machines.stability.Machine`, :class:`assur.machines.stability.Carrying`);
        ``refs`` ties the machine's positions and weights to parameters.

        Examples
        --------
        The seed 003 tractor carrying half the implement's weight: the share of the
        front axle A (seed table 6.1 prints 23.8 % with the whole 27.5 kN) grows:

        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> half = m.with_machine(m.machine.machine, "S6", 13750.0)       # [N]
        >>> round(float(m.analyze([0.42]).stability.share("A")[0]), 1)     # [%]
        23.8
        >>> round(float(half.analyze([0.42]).stability.share("A")[0]), 1)  # [%]
        39.9
        """
        return self._with(machine=machine.carry(point, weight, refs))

    def with_loads(self, loads=()) -> "Mechanism":
        """The same mechanism with ``loads`` (:mod:`assur.core.loads` objects; none by
        default) in place of its own, e.g. a subset of them (the dead loads of a
        capacity, :func:`assur.machines.capacity.dead_load_mechanism`; one load at a time, to
        see what each asks of the actuators).

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> m.loads[0].point, m.with_loads().loads
        ('S6', ())
        >>> a = m.with_loads().analyze([0.42])        # no load: no rod force [N]
        >>> float(a.statics.actuator_force("S")[0]) == 0.0
        True
        """
        return self._with(loads=tuple(loads))

    def with_params(self, **values) -> "Mechanism":
        """Return a copy with some parameters replaced (scalars or arrays over designs).

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003().with_params(L4=0.6613)   # the printed, rounded root
        >>> float(m.params["L4"])
        0.6613
        """
        unknown = sorted(set(values) - set(self.params))
        if unknown:
            raise ModelError(f"mechanism {self.name!r}: unknown parameter(s) {unknown}; "
                             f"known: {sorted(self.params)}")
        p = dict(self.params)
        p.update(values)
        return self._with(params=p)

    def with_gravity(self, g, direction=None) -> "Mechanism":
        """Return a copy whose masses weigh m·g along ``direction``.

        Parameters
        ----------
        g : float or "none"
            The acceleration of gravity [m/s²] ≥ 0; ``"none"`` (or 0) for a mechanism
            drawn in a horizontal plane (seed 001 lab 5's spout, lab 4's steering):
            its masses then have inertia but no weight, and a ``weight`` load is
            refused.
        direction : float, optional
            Direction of gravity from +x, counter-clockwise [rad]; default −π/2
            (straight down, −y). Weights (``weight`` loads, masses) act along it.

        Examples
        --------
        A mass of 1000 kg at S6 weighs m·g:

        >>> from assur import examples
        >>> m = examples.hitch_003().with_loads().mass("6", 1000.0, "S6")   # [kg]
        >>> F = [round(float(mm.analyze([0.42]).statics.actuator_force("S")[0]))
        ...      for mm in (m, m.with_gravity(1.62))]     # Earth, Moon [m/s²] → [N]
        >>> F                                         # 9810 N, 1620 N × IS6 = 4.713
        [46237, 7635]
        >>> m.with_gravity("none").weight("S6", 100.0)
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: mechanism 'hitch_003' has no gravity (a mechanism in a horizontal plane) but a weight load at point 'S6': give the load as a force, or give gravity
        """
        if isinstance(g, str):
            if g != "none":
                raise ModelError(f"mechanism {self.name!r}: gravity must be a number [m/s²] "
                                 f"or \"none\", got {g!r}")
            g = 0.0
        return self._with(gravity=float(g),
                          gravity_direction=None if direction is None else float(direction))

    @property
    def g(self) -> float:
        """The acceleration of gravity of the mechanism's weights [m/s²]: the model's own
        (:attr:`gravity`, ``[model] gravity`` of a model file), else
        :data:`assur.core.gravity.GRAVITY` (9.81). Every computation that turns a mass
        into a weight reads it.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().g                          # the default [m/s²]
        9.81
        >>> examples.hitch_003().with_gravity(9.80665).g    # the model's own [m/s²]
        9.80665
        """
        return float(GRAVITY if self.gravity is None else self.gravity)

    def with_units(self, **units) -> "Mechanism":
        """Return a copy that shows parameters in the given units
        (:class:`assur.core.quantities.Unit`, e.g. ``P=Unit("kN", 1e3)``).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.quantities import Unit
        >>> m = examples.hitch_003()
        >>> m.units["Dgc"].text                          # the model file's unit
        'mm'
        >>> u = m.with_units(Dgc=Unit("in", 0.0254)).units["Dgc"]     # [m per in]
        >>> u.text, round(u.of(float(m.params["Dgc"])), 3)   # the 80 mm bore [in]
        ('in', 3.15)
        """
        u = dict(self.units)
        u.update(units)
        return self._with(units=u)
    def with_motion(self, coordinate, direction=None, speed=None, *, t=(), omega=(),
                    start=None, law_t=(), law_q=()) -> "Mechanism":
        """Return a copy whose crank coordinate ``coordinate`` turns in ``direction``
        (``"ccw"``/+1, ``"cw"``/−1) at a constant ``speed`` |ω| [rad/s], or at a given
        |ω(t)|: ``t`` [s], ``omega`` [rad/s] (see :class:`assur.core.motion.Motion`);
        replaces an earlier motion of that coordinate. For a length coordinate (a
        cylinder's rod) ``direction`` is ``"extend"``/+1 or ``"retract"``/−1, ``speed``
        |Ṡ| [m/s] and ``omega`` the table |Ṡ(t)| [m/s]; or a law of motion q(t) at the
        times ``law_t`` [s], ``law_q`` [m or rad]; :func:`assur.analysis.analyze` then
        includes the inertia loads of a rod's motion. ``direction`` defaults to
        counter-clockwise / extending, or the law's.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003().with_motion("S", "extend", speed=0.05)   # [m/s]
        >>> m.motion("S").describe()
        'S: extend, |v| = 0.05 m/s'
        >>> m.with_motion("j1", "cw")
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: mechanism 'hitch_003': a motion is given for 'j1', which is not a generalized coordinate ['S']
        """
        from .motion import Motion
        if coordinate not in self.coordinates:
            raise ModelError(f"mechanism {self.name!r}: a motion is given for {coordinate!r}, "
                             f"which is not a generalized coordinate {list(self.coordinates)}")
        kind = "angle" if self.coordinate_kind(coordinate) == "angle" else "length"
        mo = Motion(coordinate, direction, speed, tuple(t), tuple(omega), start, kind,
                    tuple(law_t), tuple(law_q))
        return self._with(motions=tuple(x for x in self.motions if x.coordinate != coordinate)
                          + (mo,))

    def motion(self, coordinate=None):
        """The :class:`assur.core.motion.Motion` of a coordinate (default: the only one),
        or None when none is given.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> print(m.motion())
        None
        >>> m.with_motion("S", "retract", speed=0.02).motion().describe()   # [m/s]
        'S: retract, |v| = 0.02 m/s'
        """
        if coordinate is None:
            if len(self.coordinates) != 1:
                raise ModelError(f"mechanism {self.name!r} has {len(self.coordinates)} "
                                 f"coordinates {self.coordinates}: name the one whose motion "
                                 f"you want")
            coordinate = self.coordinates[0]
        return next((x for x in self.motions if x.coordinate == coordinate), None)

    def _check_motions(self):
        from .motion import Motion
        seen = set()
        for mo in self.motions:
            if not isinstance(mo, Motion):
                raise ModelError(f"mechanism {self.name!r}: motions must be "
                                 f"assur.core.motion.Motion, got {mo!r}")
            if mo.coordinate not in self.coordinates:
                raise ModelError(f"mechanism {self.name!r}: a motion is given for "
                                 f"{mo.coordinate!r}, which is not a generalized coordinate "
                                 f"{list(self.coordinates)}")
            if (self.coordinate_kind(mo.coordinate) == "angle") != (mo.kind == "angle"):
                raise ModelError(f"mechanism {self.name!r}: the motion of {mo.coordinate!r} "
                                 f"is for a {mo.kind} coordinate; {mo.coordinate!r} is a "
                                 f"{self.coordinate_kind(mo.coordinate)} coordinate")
            if mo.coordinate in seen:
                raise ModelError(f"mechanism {self.name!r}: two motions of {mo.coordinate!r}")
            seen.add(mo.coordinate)

    def with_tables(self, **tables) -> "Mechanism":
        """Return a copy with some of its :attr:`tables` replaced: what
        :meth:`Kinematics.to_frame <assur.core.kinematics.Kinematics.to_frame>` and the
        reports tabulate (``ratios``: pairs of links, ``transmissions``: points, …).

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003().with_tables(ratios=[("6", "3")], transmissions=["67"])
        >>> f = m.solve([0.42]).to_frame()
        >>> [c for c in f.columns if c[0] in "UI"]          # U63 [-], I67 [m/m]
        ['U63', 'I67']
        """
        t = dict(self.tables)
        t.update(tables)
        return self._with(tables=t)

    # ---- introspection ---------------------------------------------------------
    @property
    def points(self) -> tuple[str, ...]:
        """Names of all points in solving order (frame points first as declared).

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().points
        ('01', '03', '05', '07', '23', '34', '45', '56', '67', 'S6', 'F610')
        """
        return tuple(p for g in self.groups for p in g.outputs())

    @property
    def frame_points(self) -> tuple[str, ...]:
        """Names of the frame pivots.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().frame_points
        ('01', '03', '05', '07')
        """
        return tuple(self.topology.bodies["0"])

    def group(self, name) -> Group:
        """The group named ``name``.

        Examples
        --------
        >>> from assur import examples
        >>> g = examples.hitch_003().group("II (4,5)")
        >>> g.kind, g.a, g.b, g.out, g.ra, g.rb
        ('RRR dyad', '34', '05', '45', 'L4', 'L5')
        >>> examples.hitch_003().group("IV")
        Traceback (most recent call last):
        ...
        KeyError: "no group 'IV' in mechanism 'hitch_003'"
        """
        for g in self.groups:
            if g.name == name:
                return g
        raise KeyError(f"no group {name!r} in mechanism {self.name!r}")

    def defining_index(self, point) -> int:
        """Index of the group that adds ``point``.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> i = m.defining_index("45")
        >>> i, m.groups[i].name
        (6, 'II (4,5)')
        """
        for i, g in enumerate(self.groups):
            if point in g.outputs():
                return i
        raise KeyError(point)

    def coordinate_kind(self, c) -> str:
        """How a generalized coordinate reads: ``"angle"`` (a crank angle [rad]),
        ``"slider"`` (a prismatic input's travel [m]) or ``"length"`` (a cylinder
        length [m], also for coordinates no input group declares).

        Examples
        --------
        >>> from assur import Mechanism, examples
        >>> examples.hitch_003().coordinate_kind("S")
        'length'
        >>> m = (Mechanism("crank", coordinates=("j1",)).frame("O1", 0.0, 0.0)
        ...      .crank("c", pivot="O1", out="A", radius=0.1, q="j1"))  # radius [m]
        >>> m.coordinate_kind("j1")
        'angle'
        """
        for g in self.groups:
            if c in g.coordinates_driven() and g.driver_kind:
                return g.driver_kind
        return "length"

    @property
    def topology(self) -> Topology:
        """The mechanism's bodies, owners and group links (:class:`assur.core.topology.Topology`).

        Examples
        --------
        >>> from assur import examples
        >>> t = examples.hitch_003().topology
        >>> t.bodies["6"], t.group_links["III (6,7)"], sorted(t.variable)
        (('56', '67', 'S6', 'F610'), ('6', '7'), ['2'])
        """
        return self._topology

    def owner(self, point):
        """The link that owns ``point``: loads at the point and later groups attached
        there act on it. Frame points belong to "0"; an RRR dyad's middle joint to
        its second link (an RRP dyad's slider joint to its first; each group type
        says, :meth:`~assur.groups.base.Group.topology`); a rigid point to its link;
        a crank or slider end to the crank or slider.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> m.owner("01"), m.owner("45"), m.owner("S6")   # frame, dyad II's link 5, link 6
        ('0', '5', '6')
        """
        return self._topology.owner[point]

    @property
    def bodies(self):
        """Rigid bodies: ``{name: {"points": [...], "variable": bool}}``; the frame is "0".

        Derived from the groups (:attr:`topology`); links not named in a group get the
        name ``"<group>:a"``/``":b"``.

        Examples
        --------
        >>> from assur import examples
        >>> b = examples.hitch_003().bodies
        >>> b["5"], b["2"]["variable"]      # link 5; the cylinder 2 changes length
        ({'points': ['05', '45', '56'], 'variable': False}, True)
        """
        t = self._topology
        return {k: {"points": list(v), "variable": k in t.variable} for k, v in t.bodies.items()}

    def _validate(self, check_params=True):
        known: set[str] = set()
        names: set[str] = set()
        where = f"mechanism {self.name!r}"
        for g in self.groups:
            if g.type_name != "frame" and g.name in names:
                raise ModelError(f"{where}: duplicate group name {g.name!r}")
            names.add(g.name)
            for p in g.inputs():
                if p not in known:
                    raise ModelError(
                        f"{where}: {g.kind} {g.name!r} needs point {p!r}, which "
                        f"no earlier group defines (known: {sorted(known)})")
            for p in g.outputs():
                if p in known:
                    raise ModelError(f"{where}: point {p!r} is defined twice "
                                     f"(again by {g.kind} {g.name!r})")
                known.add(p)
            for role, ref in g.refs().items():
                self._check_ref(g, role, ref)
            problem = g.validate(self.coordinates)
            if problem:
                raise ModelError(f"{where}: {g.kind} {g.name!r}: {problem}")
        for obj in self.links + self.distances:
            ends = (obj.tail, obj.head) if isinstance(obj, Link) else (obj.a, obj.b)
            for p in ends:
                if p not in known:
                    raise ModelError(f"{where}: link/distance {obj.name!r} refers "
                                     f"to unknown point {p!r} (known: {sorted(known)})")
        self._topology = build_topology(self.name, self.coordinates, self.groups)
        self._validate_loads(known)
        lnames = [l.name for l in self.links] + [d.name for d in self.distances]
        dup = {n for n in lnames if lnames.count(n) > 1}
        if dup:
            raise ModelError(f"{where}: duplicate link/distance names {sorted(dup)}")
        if check_params:
            self._check_params(self.params)

    def _check_params(self, params):
        for n, v in params.items():
            a = np.asarray(v, dtype=float)
            if a.ndim > 1 or not np.all(np.isfinite(a)):
                raise ModelError(f"mechanism {self.name!r}: parameter {n!r} must be a finite "
                                 f"number or a 1-D array over designs, got {v!r}")

    def _check_gravity(self):
        from .loads import Weight
        g = self.gravity
        if g is not None and not (math.isfinite(float(g)) and float(g) >= 0):
            raise ModelError(f"mechanism {self.name!r}: gravity must be a number ≥ 0 [m/s²] "
                             f"(0: none), got {g!r}")
        d = self.gravity_direction
        if d is not None and not math.isfinite(float(d)):
            raise ModelError(f"mechanism {self.name!r}: the direction of gravity must be a "
                             f"finite angle, got {d!r}")
        if g is not None and float(g) == 0:
            w = [ld for ld in self.loads if isinstance(ld, Weight)]
            if w:
                raise ModelError(f"mechanism {self.name!r} has no gravity (a mechanism in a "
                                 f"horizontal plane) but a weight load at point "
                                 f"{w[0].point!r}: give the load as a force, or give gravity")

    def _validate_loads(self, known):
        from .cylinders import Cylinder
        from .loads import names_in
        where = f"mechanism {self.name!r}"

        def ref_ok(what, ref):
            if is_number(ref):
                if not math.isfinite(float(ref)):
                    raise ModelError(f"{where}: {what} = {ref!r} is not finite")
            elif not (isinstance(ref, str) and (signed_name(ref) or ref) in self.params):
                raise ModelError(f"{where}: {what} refers to {ref!r}, which is not a parameter "
                                 f"{sorted(self.params)}")

        def point_ok(what, p):
            if p not in known:
                raise ModelError(f"{where}: {what} is at unknown point {p!r} (known: "
                                 f"{sorted(known)})")

        def link_ok(what, l):
            if l is not None and l not in self.topology.bodies:
                raise ModelError(f"{where}: {what} acts on unknown link {l!r} (links: "
                                 f"{sorted(self.topology.bodies)})")

        for ld in self.loads:
            if not (hasattr(ld, "apply") and hasattr(ld, "quantities")
                    and hasattr(ld, "point_fields") and hasattr(ld, "link_fields")):
                raise ModelError(f"{where}: unknown load {ld!r} (a load declares quantities, "
                                 f"point_fields, link_fields and apply; assur.core.loads)")
            what = f"{ld.type_name} {getattr(ld, 'name', None) or ''}".rstrip()
            for f in ld.point_fields:
                for p in names_in(getattr(ld, f)):
                    point_ok(what, p)
            for f in ld.link_fields:
                for l in names_in(getattr(ld, f)):
                    link_ok(what, l)
            for f in ld.quantities:
                ref_ok(f"{what}: {f}", getattr(ld, f))
            check = getattr(ld, "check", None)  # a load's own check against the mechanism
            if check is not None:
                problem = check(self)
                if problem:
                    raise ModelError(f"{where}: {what}: {problem}")
        if self.machine is not None:
            point_ok("the machine's implement", self.machine.point)
            for t in self.machine.ref_names():
                ref_ok("the machine's data", t)
            ref_ok("the machine's implement weight", self.machine.weight)
        seen = set()
        distances = {d.name for d in self.distances}
        for c in self.cylinders:
            if not isinstance(c, Cylinder):
                raise ModelError(f"{where}: cylinders must be assur.core.loads.Cylinder, got {c!r}")
            if (c.coordinate is None) == (c.distance is None):
                raise ModelError(f"{where}: cylinder {c.name!r}: give either the coordinate it "
                                 f"drives or, for a passive cylinder, the distance that is its "
                                 f"length (not both)")
            if c.distance is not None:
                if c.distance not in distances:
                    raise ModelError(f"{where}: passive cylinder {c.name!r}: {c.distance!r} is "
                                     f"not a named distance {sorted(distances)}")
                if c.supply is None:
                    raise ModelError(f"{where}: passive cylinder {c.name!r} (length "
                                     f"{c.distance!r}) needs the supply line it shares with a "
                                     f"cylinder that drives a coordinate (supply = …)")
            elif c.coordinate not in self.coordinates:
                raise ModelError(f"{where}: cylinder {c.name!r} drives {c.coordinate!r}, which is "
                                 f"not a generalized coordinate {list(self.coordinates)}")
            elif c.coordinate in seen:
                raise ModelError(f"{where}: two cylinder entries drive {c.coordinate!r}")
            if c.coordinate is not None:
                seen.add(c.coordinate)
            if c.side not in ("piston", "rod", "auto"):
                raise ModelError(f"{where}: cylinder {c.name!r}: side must be one of: "
                                 f"['piston', 'rod', 'auto'], got {c.side!r}")
            for f in ("bore", "rod", "rod2", "count", "eta_mech", "eta_hyd", "p_relief",
                      "dp_throttle", "dp_line"):
                ref_ok(f"cylinder {c.name!r}: {f}", getattr(c, f))
        lines = {}
        for c in self.cylinders:
            if c.supply is not None:
                lines.setdefault(c.supply, []).append(c)
        for line, cyls in lines.items():
            active = [c for c in cyls if c.coordinate is not None]
            if len(active) != 1:
                raise ModelError(f"{where}: supply line {line!r}: expected exactly one cylinder "
                                 f"that drives a coordinate, found {len(active)} "
                                 f"({', '.join(c.name for c in active) or 'none'}); the others "
                                 f"are passive (distance = …)")
            if len(cyls) > 1 and any(c.side == "auto" for c in cyls):
                raise ModelError(f"{where}: supply line {line!r}: with several cylinders on "
                                 f"one line, give each cylinder's pressurised side "
                                 f"(\"piston\" or \"rod\"), not \"auto\"")

    def _check_ref(self, g, role, ref):
        if ref is None:
            return
        if is_number(ref):
            if not math.isfinite(float(ref)):
                raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r}: {role} = {ref!r} "
                                 f"is not finite")
            return
        if isinstance(ref, str):
            if (signed_name(ref) or ref) in self.params or ref in self.coordinates:
                return
            raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r}: {role} refers to "
                             f"{ref!r}, which is neither a parameter {sorted(self.params)} nor a "
                             f"coordinate {list(self.coordinates)}")
        raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r}: {role} must be a "
                         f"number or a name, got {ref!r}")

    # ---- evaluation --------------------------------------------------------------
    def value_of(self, ref, params=None):
        """Value of a reference (number or parameter name) as a float array over designs.

        Examples
        --------
        >>> from assur import examples
        >>> round(float(examples.hitch_003().value_of("L4")), 4)   # solved L4 [m], printed 0.6613
        0.6613
        >>> examples.hitch_003(L4=[0.6, 0.66]).value_of("L4").tolist()   # two designs [m]
        [0.6, 0.66]
        >>> examples.hitch_003().value_of("-X05").tolist()    # a signed name [m]
        -0.135
        """
        p = self.params if params is None else params
        return np.asarray(ref_value(p, ref), dtype=float)

    def evaluate_positions(self, q, params=None, upto=None):
        """Point positions by the plain-numpy formulas of the groups (any dtype).

        This is the reference implementation used to check the compiled kernel
        (complex-step differentiation in the tests) and to explain failures. It does
        not check assembly.

        Parameters
        ----------
        q : mapping of coordinate name to array_like
            Generalized coordinate values [m or rad] (may be complex).
        params : mapping, optional
            Parameter values overriding the mechanism's (may be complex).
        upto : int, optional
            Evaluate only the groups before this index.

        Returns
        -------
        dict of str to (x, y) tuples of arrays [m]

        Examples
        --------
        >>> from assur import examples
        >>> pts = examples.hitch_003().evaluate_positions({"S": 0.42})     # S [m]
        >>> [round(float(v), 3) for v in pts["56"]]     # X56, Y56 [m], seed 003 table 2.2
        [1.131, 0.2]
        >>> sorted(examples.hitch_003().evaluate_positions({"S": 0.42}, upto=5))
        ['01', '03', '05', '07', '23']
        """
        p = dict(self.params)
        p.update(params or {})
        val = _Values(self, q, p)
        pts: dict = {}
        for g in self.groups[:upto]:
            g.evaluate(pts, val)
        return pts

    def solve(self, q, params: Mapping | None = None, *, outputs=None, on_failure="raise",
              check_continuity=True, out=None):
        """Positions and exact kinematic analogs over the generalized coordinate(s).

        Parameters
        ----------
        q : array_like, shape (n,) or (m, n) for k = 1; shape (..., k) for k > 1
            Values of the generalized coordinate(s) [m or rad]. A 2-D array (k = 1)
            holds one row of positions per design.
        params : mapping, optional
            Parameter overrides; array values of shape (m,) make a batch.
        outputs : iterable of str, optional
            Point, link and distance names to return (default: all). Asking for
            fewer makes large sweeps faster (only those are written to memory).
        on_failure : {"raise", "report"}
            ``"raise"`` (default) raises :class:`AssemblyError` at the first
            position that cannot assemble; ``"report"`` returns the result with
            its ``ok`` mask and ``failures`` (values at failed elements are 0,
            never NaN).
        check_continuity : bool
            For k = 1, check that no dyad opens or passes a dead point *between*
            consecutive positions (cubic Hermite of the squared triangle height).
        out : Kinematics, optional
            An earlier result of this mechanism with the same ``outputs`` and as many
            designs × positions: this solve writes into its memory instead of new
            memory (a sweep of one size repeated many times; fresh memory costs the
            OS's zeroing of every page on first touch). The earlier result then
            holds this solve's values; keep using only the one returned.

        Returns
        -------
        Kinematics

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> r = m.solve(np.linspace(0.42, 0.67, 10))      # S [m]
        >>> np.round(r.phi("6", degrees=True)[[0, -1]], 1)  # seed 003 table 2.1 [°]
        array([ 88.5, 110.3])
        >>> np.round(r.transmission("56")[[0, -1]], 3)     # I56 = dY56/dS, table 3.1
        array([4.459, 2.621])

        A batch of designs, and failures reported instead of raised:

        >>> b = m.solve([0.42, 0.67], params={"L4": [0.60, 0.66, 0.95]}, on_failure="report")
        >>> b.ok
        array([[ True,  True],
               [ True,  True],
               [False,  True]])
        >>> print(b.failures[0].split(":")[0])  # the first failure: group, links, where
        RRR dyad 'III (6,7)' (links 6, 7) cannot assemble at position 0 (S = 0.42) of design 2
        """
        if on_failure not in ("raise", "report"):
            raise ValueError("on_failure must be one of: ['raise', 'report']")
        inputs.check_params(self, params)
        mech = self.with_params(**params) if params else self
        prog = mech.program(outputs)
        ptab, trig, pose_failures = mech.prepared(prog)
        qarr, shape, m, n = mech.coordinate_array(q, ptab.shape[1])
        if ptab.shape[1] == 1 and m > 1:
            ptab, trig = np.repeat(ptab, m, axis=1), np.repeat(trig, m, axis=1)
        elif ptab.shape[1] != m:
            raise ModelError(f"mechanism {self.name!r}: parameters describe {ptab.shape[1]} "
                             f"designs but the coordinates {m}")
        check = bool(check_continuity and len(self.coordinates) == 1 and n > 1)
        buf = None
        if out is not None:
            if not isinstance(out, Kinematics):
                raise ValueError(f"out must be a result of Mechanism.solve (Kinematics), got "
                                 f"{type(out).__name__}")
            if out.output_buffer is None:
                raise ValueError("out must be a whole result of Mechanism.solve, not a part "
                                 "of one (Kinematics.positions)")
            buf = out.output_buffer
        res = execute(prog, ptab, qarr, n, check, trig=trig, out_buffer=buf)
        status = res["status"]
        ok = (status < 0).reshape(m, n)   # a status ≥ 0 is a failure's code
        all_ok = bool(ok.all())
        if pose_failures and all_ok:
            raise pose_failures[0]
        kin = Kinematics(mech, prog, qarr.reshape((len(self.coordinates), m, n)), res, shape,
                         ok=ok, params=ptab)
        if not all_ok:
            if on_failure == "raise":
                raise diagnostics.assembly_error(mech, prog, ptab, qarr, status, res["amount"],
                                                 n, ok)
            kin.failures = diagnostics.describe_failures(mech, prog, ptab, qarr, status,
                                                         res["amount"], n)
        return kin

    def analyze(self, q, params=None, *, qdot=None, qddot=None, outputs=None, reduce=False,
                **kw):
        """Kinematics, actuator forces, joint reactions, cylinders and stability in one
        call; returns :class:`assur.analysis.Analysis` (see :func:`assur.analysis.analyze`).

        With ``outputs=[…]`` only those are computed, by the fused kinematics + statics
        kernel, and a :class:`assur.core.outputs.Fused` is returned (see :meth:`evaluate`).

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> a = examples.hitch_003().analyze(np.linspace(0.42, 0.67, 10))
        >>> cyl = a.cylinder("ГЦ")
        >>> round(float(cyl.force[0])), round(float(cyl.capacity("56")[0]))  # table 4.1 [N]
        (129614, 33139)
        >>> np.round(a.stability.share("A")[[0, -1]], 1)                   # table 6.1 [%]
        array([23.8, 26.2])
        """
        if outputs is not None:
            if qdot is not None or qddot is not None:
                raise ModelError("analyze(outputs=…) computes static loads only; leave out "
                                 "qdot and qddot, or omit outputs for the full analysis")
            return self.evaluate(q, params, outputs=outputs, reduce=reduce, **kw)
        from ..analysis import analyze
        return analyze(self, q, params=params, qdot=qdot, qddot=qddot, **kw)

    def evaluate(self, q, params=None, *, outputs, reduce=False, on_failure="raise", g=None):
        """Only the ``outputs`` asked for (e.g. ``["G(ГЦ, 56)", "Rx(0, 5)", "F(S)"]``),
        computed by one fused kinematics + statics kernel per structure; with
        ``reduce=True`` their minimum, maximum and where over the positions of each
        design, without storing the positions. See :mod:`assur.core.outputs` for the
        output functions and their units.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> f = examples.hitch_003().evaluate(np.linspace(0.42, 0.67, 10),
        ...                                   outputs=["G(ГЦ, 56)", "p(ГЦ)"])
        >>> round(float(f["G(ГЦ, 56)"][0]))      # lift capacity at 56 [N]
        33139
        >>> round(float(f["p(ГЦ)"][-1] / 1e6), 2)  # pressure [MPa]
        16.06
        """
        from .outputs import evaluate
        return evaluate(self, q, params, outputs, reduce=reduce, on_failure=on_failure, g=g)

    def memo(self, key, make):
        """A value derived from this (immutable) mechanism, made once by ``make()`` and
        kept with it (programs, prepared tables, fused kernels).

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003().with_params(L4=0.65)
        >>> calls = []
        >>> def make():
        ...     calls.append(1)
        ...     return float(m.params["L4"]) * 1000     # L4 [mm]
        >>> m.memo(("L4 in mm",), make), m.memo(("L4 in mm",), make), len(calls)
        (650.0, 650.0, 1)
        """
        v = self._cache.get(key)
        if v is None:
            v = self._cache[key] = make()
        return v

    def program(self, outputs=None):
        """The compiled :class:`~assur.core.program.Program` writing ``outputs`` (cached).

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> prog = m.program(["56", "6"])
        >>> prog.out_pts, prog.out_sca, m.program(["56", "6"]) is prog
        (('56',), ('6',), True)
        >>> len(m.program().out_pts), m.program().k    # all moving points; one coordinate
        (7, 1)
        """
        key = None if outputs is None else tuple(outputs)
        prog = self._cache.get(("program", key))
        if prog is None:
            prog = self._cache[("program", key)] = compile_program(self, key)
        return prog

    def prepared(self, prog):
        """The parameter table of this mechanism's values for ``prog``, shape (rows, m),
        its fixed angles' cos/sin table and the failures of its pre-passes (cached: the
        mechanism is immutable): callers must not write to them.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003(L4=[0.60, 0.66])            # two designs
        >>> prog = m.program()
        >>> ptab, trig, failures = m.prepared(prog)
        >>> [round(float(v), 2) for v in ptab[prog.param_row("L4")]], failures  # L4 [m]
        ([0.6, 0.66], [])
        >>> m.prepared(prog)[0] is ptab                        # cached
        True
        """
        hit = self._cache.get(("prepared", id(prog)))
        if hit is None or hit[0] is not prog:
            ptab = np.ascontiguousarray(prog.param_table(self.params))
            failures = self.prepare(prog, ptab)
            trig = trig_table(prog, ptab)
            hit = self._cache[("prepared", id(prog))] = (prog, ptab, trig, failures)
        return hit[1], hit[2], hit[3]

    def prepare(self, prog, ptab):
        """Run the groups' pre-passes (derived per-design rows, e.g. a point fixed at
        a pose). Returns the :class:`AssemblyError` of poses that cannot assemble
        (their rows stay 0); the caller raises them unless the main range fails
        earlier, which gives the more useful message.

        Examples
        --------
        Seed 003's centre of mass S6 is given by its offset (X6, Y6) from 56 at the
        pose S = Sp; the pre-pass turns it into a length and an angle on link 6:

        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> prog = m.program()
        >>> ptab = prog.param_table(m.params)
        >>> gi, data = prog.prepares[0]
        >>> m.groups[gi].name, float(ptab[data[1], 0])            # before: 0
        ('centre of mass S6', 0.0)
        >>> m.prepare(prog, ptab)                                  # no failure
        []
        >>> round(float(ptab[data[1], 0]), 3)           # |56–S6| = hypot(X6, Y6) [m]
        0.871
        """
        failures = []
        for gi, data in prog.prepares:
            g = self.groups[gi]

            def positions_at(qpose, points, gi=gi, g=g):
                res = execute(prog, ptab, np.ascontiguousarray(qpose), 1, False,
                              rows=prog.rows[:gi], out_pts=points)
                st = res["status"]
                if (st >= 0).any():
                    e = int(np.flatnonzero(st >= 0)[0])
                    msg, _, _ = diagnostics.failure_message(self, prog, ptab, qpose, st,
                                                            res["amount"], 1, e)
                    at = {c: float(v) for c, v in zip(self.coordinates, qpose[:, e])}
                    pose = ", ".join(diagnostics.coordinate_text(self, c, v)
                                     for c, v in at.items())
                    failures.append(AssemblyError(
                        f"{g.kind} {g.name!r} is defined at the pose {pose}, where the "
                        f"mechanism cannot assemble: {msg}", group=g.name,
                        links=g.group_links(), coordinate=at, design=e))
                return {p: (res["pv"][j, 0], res["pv"][j, 1])
                        for j, p in enumerate(res["out_pts"])}

            g.prepare(data, ptab, positions_at)
        return failures

    # ---- coordinates ---------------------------------------------------------------
    def coordinate_array(self, q, m_params, per_position=None):
        """The coordinates ``q`` as a (k, m·n) array, their result shape, m and n;
        checked (:func:`assur.core.inputs.coordinates_array`) before anything is allocated.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> qa, shape, m_, n = m.coordinate_array([0.42, 0.67], 3)   # S [m], 3 designs
        >>> qa.shape, shape, m_, n
        ((1, 6), (3, 2), 3, 2)
        >>> m.coordinate_array([0.42, float("nan")], 1)
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: mechanism 'hitch_003': the generalized coordinate value at index (1,) is not finite (nan)
        """
        k = len(self.coordinates)
        if (k == 1 and m_params == 1 and type(q) is np.ndarray and q.ndim == 1
                and q.dtype == np.float64 and 0 < q.size <= 4096 and q.flags.c_contiguous
                and inputs.all_finite(q)):
            return q.reshape(1, q.size), q.shape, 1, q.size   # the common small case
        # real, finite floats of a size that fits in memory, or a ModelError
        a = inputs.coordinates_array(q, self, m_params, per_position)
        if k == 1:
            if a.ndim == 0:
                a = a[None]
            shape = a.shape
            if a.ndim == 1:
                a2 = np.broadcast_to(a, (m_params, a.shape[0])) if m_params > 1 else a[None]
                if m_params > 1:
                    shape = a2.shape
            elif a.ndim == 2:
                a2 = a
            else:
                raise ModelError(f"coordinates must have shape (n,) or (m, n), got {a.shape}")
            m, n = a2.shape
            return np.ascontiguousarray(a2.reshape(1, m * n)), shape, m, n
        if a.shape[-1] != k:
            raise ModelError(f"mechanism {self.name!r} has {k} coordinates {self.coordinates}: "
                             f"q must have a trailing axis of length {k}, got shape {a.shape}")
        if a.ndim == 1:
            a = a[None]
        shape = a.shape[:-1]
        if a.ndim == 2:
            a = np.broadcast_to(a, (m_params,) + a.shape) if m_params > 1 else a[None]
            if m_params > 1:
                shape = a.shape[:-1]
        m, n = a.shape[0], a.shape[1]
        qa = np.moveaxis(a, -1, 0).reshape(k, m * n)
        return np.ascontiguousarray(qa), shape, m, n

    def _repr_html_(self):
        """The model summary in a notebook (:mod:`assur.views.notebook`)."""
        from ..views.notebook import mechanism_html
        return mechanism_html(self)

    def __repr__(self):
        return (f"Mechanism({self.name!r}, coordinates={self.coordinates}, "
                f"{len(self.groups)} groups, {len(self.links)} links)")


def _builder(cls):
    def method(self, name, **kw):
        return self.add_group(cls.type_name, name, **kw)
    params = ", ".join(f.name for f in cls.fields)
    method.__name__ = cls.type_name
    method.__qualname__ = f"Mechanism.{cls.type_name}"
    # the class's docstring dedented, so that it reads as the method's own
    doc = inspect.cleandoc(cls.__doc__ or "")
    method.__doc__ = (f"Add a {cls.kind} (:class:`{cls.__module__}.{cls.__name__}`); "
                      f"keywords: {params}, links.\n\n" + doc)
    return method


for _cls in registry().values():
    if _cls.type_name != "frame" and not hasattr(Mechanism, _cls.type_name):
        setattr(Mechanism, _cls.type_name, _builder(_cls))
