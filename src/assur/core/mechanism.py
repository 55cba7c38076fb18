"""The :class:`Mechanism`: frame points, an ordered list of structural groups,
named links, loads and cylinders, and the parameters they refer to — an immutable
description.

Building returns new mechanisms: the generic builders and ``with_*`` copies
(:mod:`assur.core._building`), one builder method per registered group type, named
after its model-file ``type`` (:func:`assur.groups.registry`), and one per registered
load type (:func:`assur.core.loads.registry`). What the description refuses is
checked on construction (:mod:`assur.core._checks`). Solving compiles the
description into a :class:`~assur.core.program.Program` (kept with the mechanism,
:mod:`assur.core.memo`), runs it and returns a
:class:`~assur.core.kinematics.Kinematics` result (:mod:`assur.core._solving`);
:meth:`Mechanism.analyze` hands over to :mod:`assur.analysis`. Every parameter may be
a scalar or an array over designs, shape ``(m,)``; generalized coordinates are arrays
of shape ``(n,)`` (one design) or ``(m, n)`` (a batch of designs), see DESIGN.md
§1–2.
"""

from __future__ import annotations

from types import MappingProxyType
from typing import Iterable, Mapping

from . import _building, _checks, _solving, inputs
from . import loads as _loads
from ..errors import ModelError
from ..groups import Distance, Group, Link, registry
from .gravity import GRAVITY
from .memo import Memo
from .topology import Topology

__all__ = ["Mechanism"]


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
    display : mapping, optional
        How results are shown (:mod:`assur.core.display`): ``units`` (the unit
        system: ``"file"``, ``"engineering"``, ``"si"``, ``"imperial"``), ``lang``
        (``"en"``, ``"ru"`` or None) and ``given`` (the :class:`Unit` of each value a
        model file writes with a unit, which the ``"file"`` system follows).
    wheels : sequence of Wheel, optional
        Wheels drawn on the mechanism (:class:`assur.core.wheels.Wheel`; a model
        file's ``[[wheels]]``): drawing data only, see :meth:`wheel`.

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
                 display: Mapping | None = None, wheels: Iterable = (),
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
        #: how results are shown: ``units`` (system), ``lang``, ``given`` (the file's units)
        self.display = MappingProxyType(dict(display or {}))
        self.groups = tuple(groups)
        self.links = tuple(links)
        self.distances = tuple(distances)
        #: what :meth:`Kinematics.to_frame` tabulates: ``ratios`` (pairs), ``transmissions``
        self.tables = MappingProxyType(dict(tables or {}))
        #: notes on seed slips resolved in this model (shown in reports)
        self.notes = tuple(notes)
        #: applied loads (:mod:`assur.core.loads`): weights, forces, moments, springs, masses
        self.loads = tuple(loads)
        #: hydraulic cylinders (:class:`assur.core.cylinders.Cylinder`)
        self.cylinders = tuple(cylinders)
        #: wheels drawn on the mechanism (:class:`assur.core.wheels.Wheel`): drawing data,
        #: no part of the kinematics or the forces
        self.wheels = tuple(wheels)
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
        #: values derived from this (immutable) mechanism (:meth:`memo`)
        self._memo = Memo()
        _checks.check_gravity(self)
        _checks.validate(self, check_params=not _params_checked)
        _checks.check_motions(self)

    # ---- copies (each returns a new mechanism) -----------------------------------
    #: attributes a copy may change without validating the structure again
    _DATA_ONLY = frozenset({"params", "title", "tables", "notes", "gravity", "units",
                            "motions", "gravity_direction", "display"})

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
            new._memo = self._memo.structural()
            for k, v in kw.items():
                setattr(new, k, MappingProxyType(dict(v))
                        if k in ("params", "tables", "units", "display")
                        else tuple(v) if k in ("notes", "motions") else v)
            if "params" in kw:
                changed = {n: v for n, v in kw["params"].items() if v is not self.params[n]}
                _checks.check_params_of(new, changed)
                inputs.mark_checked(self, new, changed)
            if "gravity" in kw or "gravity_direction" in kw:
                _checks.check_gravity(new)
            if "motions" in kw:
                _checks.check_motions(new)
            return new
        d = dict(name=self.name, coordinates=self.coordinates, params=self.params,
                 title=self.title, groups=self.groups, links=self.links,
                 distances=self.distances, tables=self.tables, notes=self.notes,
                 loads=self.loads, cylinders=self.cylinders, machine=self.machine,
                 gravity=self.gravity, units=self.units, motions=self.motions,
                 gravity_direction=self.gravity_direction, display=self.display,
                 wheels=self.wheels, _params_checked="params" not in kw)
        d.update(kw)
        return Mechanism(**d)

    # ---- building: each returns a new mechanism (assur.core._building) -----------
    add = _building.add
    extended = _building.extended
    add_group = _building.add_group
    add_load = _building.add_load
    frame = _building.frame
    link = _building.link
    distance = _building.distance
    cylinder = _building.cylinder
    with_cylinders = _building.with_cylinders
    wheel = _building.wheel
    with_wheels = _building.with_wheels
    with_machine = _building.with_machine
    with_loads = _building.with_loads
    with_params = _building.with_params
    with_gravity = _building.with_gravity
    with_units = _building.with_units
    with_motion = _building.with_motion
    motion = _building.motion
    with_tables = _building.with_tables
    # the builders of the group and load types follow the class (one per registered type)

    # ---- solving: delegate to the program, kinematics, outputs (assur.core._solving) --
    value_of = _solving.value_of
    evaluate_positions = _solving.evaluate_positions
    solve = _solving.solve
    evaluate = _solving.evaluate
    program = _solving.program
    prepared = _solving.prepared
    prepare = _solving.prepare
    coordinate_array = _solving.coordinate_array

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

    def memo(self, key, make):
        """A value derived from this (immutable) mechanism, made once by ``make()`` and
        kept with it (programs, prepared tables, fused kernels' plans…). ``key`` is a
        tuple ``(owner, *items)`` whose owner is registered in
        :data:`assur.core.memo.OWNERS`: the contract of :mod:`assur.core.memo`.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003().with_params(L4=0.65)          # [m]
        >>> prog = m.program(["45"])          # kept under ("program", ("45",))
        >>> m.memo(("program", ("45",)), lambda: 1 / 0) is prog   # kept: make not called
        True
        >>> m.memo(("L4 in mm",), lambda: 650.0)
        Traceback (most recent call last):
        ...
        KeyError: "memo owner 'L4 in mm' is not registered (assur.core.memo.register_owner); owners: ['capacity', 'chains', 'cylinders', 'outputs', 'prepared', 'program', 'roles', 'stability', 'statics']"
        """
        return self._memo.get(key, make)

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

    def _repr_html_(self):
        """The model summary in a notebook (:mod:`assur.views.notebook`)."""
        from ..views.notebook import mechanism_html
        return mechanism_html(self)

    def __repr__(self):
        return (f"Mechanism({self.name!r}, coordinates={self.coordinates}, "
                f"{len(self.groups)} groups, {len(self.links)} links)")


for _f in vars(Mechanism).values():    # the methods defined in the modules above
    if callable(_f) and getattr(_f, "__module__", "") in (_building.__name__,
                                                        _solving.__name__):
        _f.__qualname__ = f"Mechanism.{_f.__name__}"
        if _f.__module__ == _building.__name__ and _f.__name__ != "motion":
            _f.__annotations__["return"] = "Mechanism"   # a builder: a new mechanism

for _cls in registry().values():
    if _cls.type_name != "frame" and not hasattr(Mechanism, _cls.type_name):
        setattr(Mechanism, _cls.type_name, _building.group_builder(_cls))


def _add_load_builder(cls):
    """Give ``Mechanism`` the builder of the load type ``cls`` (called for every type
    registered, now and later: :func:`assur.core.loads.on_register`)."""
    name = cls.type_name
    old = getattr(Mechanism, name, None)
    if old is not None and getattr(old, "load_type", None) is None:
        raise ValueError(f"load type {name!r}: Mechanism.{name} exists already (a method "
                         f"or a group type's builder); choose another type_name")
    setattr(Mechanism, name, _building.load_builder(cls))


def _remove_load_builder(cls):
    """Take the builder of an unregistered load type off ``Mechanism``."""
    if getattr(getattr(Mechanism, cls.type_name, None), "load_type", None) is cls:
        delattr(Mechanism, cls.type_name)


_loads.on_register(_add_load_builder, _remove_load_builder)
