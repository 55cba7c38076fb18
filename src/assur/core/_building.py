"""The builder methods of :class:`~assur.core.mechanism.Mechanism`: each returns a new
mechanism (the description is immutable), through ``Mechanism._with``.

The functions here are the methods themselves (``Mechanism.add is add``): the class
lists them in its body. The per-type builders — one per registered group type
(:func:`assur.groups.registry`) and one per registered load type
(:func:`assur.core.loads.registry`) — call :func:`add_group` and :func:`add_load`.
"""

from __future__ import annotations

import inspect

from ..errors import ModelError
from ..groups import Distance, Frame, Link, registry
from . import loads as _loads
from .cylinders import Cylinder
from .motion import Motion
from .wheels import Wheel

def add(self, *groups):
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


def extended(self, groups=(), params=None):
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


def add_group(self, type_name: str, name: str, **kw):
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


def add_load(self, type_name: str, *args, **kw):
    """Add a load of the registered type ``type_name`` (the model file's ``type``,
    :func:`assur.core.loads.registry`), its fields given as the type's constructor
    takes them; a ``links`` field may be any pair (a tuple inside).

    Examples
    --------
    The builder ``m.weight("S6", P)`` is ``m.add_load("weight", "S6", P)``: the seed's
    P6 = 27.5 kN at S6 asks P6·IS6 of the cylinder (seed 003 table 4.1):

    >>> from assur import examples
    >>> m = examples.hitch_003().with_loads().add_load("weight", "S6", P=27500.0)  # [N]
    >>> round(float(m.analyze([0.42]).statics.actuator_force("S")[0]))   # [N]
    129614
    >>> m.add_load("weight", "S6", P=1.0, Q=1.0)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: weight load: got an unexpected keyword argument 'Q'; its parameters: ['point', 'P', 'link', 'name']
    >>> m.add_load("gear", "S6")
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: unknown load type 'gear'; known: ['force', 'mass', 'moment', 'resisting_moment', 'spring', 'weight']
    """
    try:
        cls = _loads.load_type(type_name)
    except KeyError as e:
        raise ModelError(e.args[0]) from None
    try:
        values = inspect.signature(cls).bind(*args, **kw).arguments
    except TypeError as e:
        raise ModelError(f"{type_name} load: {e}; its parameters: "
                         f"{[f.name for f in cls.fields]}") from None
    for f in cls.fields:
        if f.role == "links" and f.name in values:
            values[f.name] = tuple(values[f.name]) if values[f.name] else None
    return self._with(loads=self.loads + (cls(**values),))


def load_builder(cls):
    """The ``Mechanism`` builder method of the load type ``cls``: named after its
    ``type_name``, with the signature of its constructor and its docstring."""
    sig = inspect.signature(cls)

    def method(self, *args, **kw):
        return add_load(self, cls.type_name, *args, **kw)

    self_param = inspect.Parameter("self", inspect.Parameter.POSITIONAL_OR_KEYWORD)
    method.__signature__ = sig.replace(parameters=[self_param, *sig.parameters.values()],
                                       return_annotation="Mechanism")
    method.__name__ = cls.type_name
    method.__qualname__ = f"Mechanism.{cls.type_name}"
    method.load_type = cls
    keys = "; ".join(f"``{f.name}``" + (f" [{f.quantity}]" if f.quantity else "")
                     + (f": {f.doc}" if f.doc else "") for f in cls.fields)
    method.__doc__ = (f"Add {cls.summary} (:class:`{cls.__module__}.{cls.__name__}`, "
                      f"model-file ``type = \"{cls.type_name}\"``).\n\nKeywords: {keys}.\n\n"
                      + inspect.cleandoc(cls.__doc__ or ""))
    return method


def group_builder(cls):
    """The ``Mechanism`` builder method of the group type ``cls``, named after its
    ``type_name``: ``add_group(type_name, name, **kw)`` with the class's docstring."""
    def method(self, name, **kw):
        return add_group(self, cls.type_name, name, **kw)
    params = ", ".join(f.name for f in cls.fields)
    method.__name__ = cls.type_name
    method.__qualname__ = f"Mechanism.{cls.type_name}"
    # the class's docstring dedented, so that it reads as the method's own
    doc = inspect.cleandoc(cls.__doc__ or "")
    method.__doc__ = (f"Add a {cls.kind} (:class:`{cls.__module__}.{cls.__name__}`); "
                      f"keywords: {params}, links.\n\n" + doc)
    return method


def frame(self, name, x=None, y=None, *, origin=None, length=None,
          angle=None):
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


def link(self, name, tail, head):
    """Name the link whose angle φ_name is the direction ``tail → head``.

    Examples
    --------
    >>> from assur import examples
    >>> r = examples.hitch_003().solve([0.42])
    >>> round(float(r.phi("3", degrees=True)[0]), 1)   # link 3 = 03 → 23, table 2.1
    -40.2
    """
    return self._with(links=self.links + (Link(name, tail, head),))


def distance(self, name, a, b, angle=None):
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


def cylinder(self, name, coordinate=None, **kw):
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
    return self._with(cylinders=self.cylinders + (Cylinder(name, coordinate, **kw),))


def with_cylinders(self, cylinders=()):
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


def wheel(self, name, at, diameter, width, link=None, heading=0.0):
    """Add a wheel drawn centred on point ``at``, heading along ``link`` turned by
    ``heading`` [rad] (:class:`assur.core.wheels.Wheel`; ``[[wheels]]`` of a model
    file); ``diameter`` and ``width`` [m] are numbers or parameter names. It is drawing
    data: the solve and the forces do not change.

    Examples
    --------
    The seed-003 hitch's tractor: a rear wheel of 1.1 m under the frame pivot 01,
    rolling along +x:

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.views.geometry import geometry
    >>> m = examples.hitch_003().wheel("rear wheel", at="01", diameter=1.1, width=0.3)
    >>> [str(w.name) for w in m.wheels]
    ['rear wheel']
    >>> geometry(m.solve([0.42]))["wheels"][0]["length"]                # [m]
    1.1
    >>> examples.hitch_003().wheel("w", at="99", diameter=1.1, width=0.3)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': wheel 'w' is at unknown point '99' (known: ['01', '03', '05', '07', '23', '34', '45', '56', '67', 'F610', 'S6'])
    """
    return self._with(wheels=self.wheels + (Wheel(name, at, diameter, width, link=link,
                                                  heading=heading),))


def with_wheels(self, wheels=()):
    """The same mechanism with ``wheels`` (:class:`assur.core.wheels.Wheel`; none by
    default) in place of its own.

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.steering_lab4()
    >>> len(m.wheels), len(m.with_wheels(m.wheels[:1]).wheels), len(m.with_wheels().wheels)
    (2, 1, 0)
    """
    return self._with(wheels=tuple(wheels))


def with_machine(self, machine, point, weight, refs=None):
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


def with_loads(self, loads=()):
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


def with_params(self, **values):
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


def with_gravity(self, g, direction=None):
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


def with_units(self, **units):
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
                start=None, law_t=(), law_q=()):
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


def with_tables(self, **tables):
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
