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

from dataclasses import MISSING, dataclass, field as _dataclass_field, fields as _dataclass_fields
from types import MappingProxyType
from typing import Callable, ClassVar, Union

import numpy as np

from ..groups.base import Field
from .quantities import DEFAULT_UNITS

__all__ = ["Load", "param", "register", "unregister", "registry", "load_type", "on_register",
           "ROLES",
           "FLAGS", "Weight", "PointForce", "Couple", "ResistingMoment", "Spring", "Mass",
           "LOAD_TYPES", "names_in", "load_link", "masses_of", "dead_load_links", "is_dead",
           "centre_of_mass"]

Ref = Union[str, float, int]

#: what a field of a load type holds, by its role; the model file's ``[[loads]]`` schema,
#: the file loader's checks, the builder and the docs table follow the role
ROLES = {
    "point": "the name of a point",
    "link": 'the name of a link ("0": the frame)',
    "links": "two link names, of the ends' links in order",
    "value": "a number in the unit of its quantity, or a parameter name",
    "name": "a name (reports, messages)",
    "sign": "+1 or -1",
    "coordinate": "the name of a generalized coordinate",
}

#: what a value field must be besides a number of its quantity: ≥ 0, > 0, a count of
#: identical parts (a positive whole number)
FLAGS = ("nonneg", "positive", "count")


def param(role: str, quantity: str | None = None, flag: str | None = None, *,
          default=MISSING, doc: str = ""):
    """Declare one field of a load type — its role, the quantity and flag of a value,
    its default and one line for the docs — in the dataclass body, once.

    Parameters
    ----------
    role : str
        One of :data:`ROLES`.
    quantity : str, optional
        For a ``"value"``: what it measures, a key of
        :data:`assur.core.quantities.DEFAULT_UNITS` (``"force"`` [N], ``"moment"``
        [N·m], ``"length"`` [m], …).
    flag : str, optional
        For a ``"value"``: one of :data:`FLAGS`.
    default : object, optional
        The default when omitted (absent: required).
    doc : str
        One line for the docs table and the builder.

    Returns
    -------
    dataclasses.Field
        A dataclass field whose metadata carries the declaration (:func:`register`
        reads it into the type's :attr:`Load.fields`).

    Examples
    --------
    >>> from assur.core.loads import param
    >>> f = param("value", "force", "nonneg", doc="its magnitude [N]")
    >>> f.metadata["load"]["quantity"], f.metadata["load"]["flag"]
    ('force', 'nonneg')
    """
    return _dataclass_field(default=default, metadata={"load": {
        "role": role, "quantity": quantity, "flag": flag, "doc": doc}})


class Load:
    """Base of the load types: the contract each implements (module notes).

    A load type is a frozen dataclass subclassing :class:`Load`, each field declared
    with :func:`param`, registered with :func:`register` under its model-file
    ``type_name``. :func:`register` derives from the declarations:

    ==================  ==============================================================
    member              what it provides
    ==================  ==============================================================
    ``type_name``       registry key = model-file ``type`` = builder method name
    ``summary``         one line: what it is (docs table, builder docstring)
    ``fields``          the fields, as :class:`assur.groups.Field` (name, role,
                        quantity, flag, default, doc) in constructor order
    ``quantities``      ``{value field: quantity}`` (units of files and reports)
    ``flags``           ``{value field: flag}`` (the file's checks)
    ``point_fields``,   the fields that name points, and links
    ``link_fields``
    ``check(mech)``     a problem with the load in a mechanism (a message) or None
    ``apply(c)``        apply it to a load context (module notes)
    ==================  ==============================================================

    Examples
    --------
    >>> from assur.core.loads import Load, Weight
    >>> issubclass(Weight, Load), Weight.type_name
    (True, 'weight')
    >>> [(f.name, f.role, f.quantity) for f in Weight.fields]
    [('point', 'point', None), ('P', 'value', 'force'), ('link', 'link', None), ('name', 'name', None)]
    >>> Weight.quantities, Weight.flags, Weight.point_fields, Weight.link_fields
    ({'P': 'force'}, {'P': 'nonneg'}, ('point',), ('link',))
    """

    type_name: ClassVar[str] = ""
    summary: ClassVar[str] = ""
    fields: ClassVar[tuple] = ()
    quantities: ClassVar[dict] = {}
    flags: ClassVar[dict] = {}
    point_fields: ClassVar[tuple] = ()
    link_fields: ClassVar[tuple] = ()

    def check(self, mech) -> str | None:
        """A problem with this load in ``mech`` (a message), or None. The names it
        refers to (points, links, parameters) are checked by the mechanism from the
        declarations; a type overrides this for anything else.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import Weight
        >>> print(Weight("S6", 1000.0).check(examples.hitch_003()))
        None
        """
        return None

    def apply(self, c) -> None:
        """Apply the load to the load context ``c`` (module notes): each type
        implements it.

        Examples
        --------
        >>> from assur.core.loads import Load
        >>> Load().apply(None)
        Traceback (most recent call last):
        ...
        NotImplementedError
        """
        raise NotImplementedError


_REGISTRY: dict[str, type] = {}
_HOOKS: list = []
_UNDO: list = []


def _declared(cls) -> tuple:
    """The :class:`~assur.groups.Field` of each dataclass field of ``cls``, from its
    :func:`param` declaration (checked)."""
    out = []
    for f in _dataclass_fields(cls):
        d = f.metadata.get("load")
        where = f"load type {cls.type_name!r}: field {f.name!r}"
        if d is None:
            raise TypeError(f"{where} is not declared with assur.core.loads.param")
        if d["role"] not in ROLES:
            raise ValueError(f"{where} has the unknown role {d['role']!r} (one of: "
                             f"{', '.join(ROLES)})")
        if (d["role"] == "value") != (d["quantity"] is not None) or (
                d["quantity"] is not None and d["quantity"] not in DEFAULT_UNITS):
            raise ValueError(f"{where}: a value needs a quantity (one of: "
                             f"{', '.join(DEFAULT_UNITS)}) and only a value has one, got "
                             f"{d['quantity']!r}")
        if d["flag"] is not None and (d["flag"] not in FLAGS or d["role"] != "value"):
            raise ValueError(f"{where}: a flag is one of {FLAGS} on a value, got {d['flag']!r}")
        default = {} if f.default is MISSING else {"default": f.default}
        out.append(Field(f.name, d["role"], d["quantity"], d["flag"], doc=d["doc"], **default))
    return tuple(out)


def register(cls):
    """Class decorator: register a load type under ``cls.type_name`` and derive its
    :attr:`~Load.fields`, ``quantities``, ``flags``, ``point_fields`` and
    ``link_fields`` from its :func:`param` declarations. The builder method
    ``Mechanism.<type_name>`` and the ``[[loads]]`` schema follow (:func:`on_register`).

    Examples
    --------
    A toy load type: a downward force of ``F`` [N] at a point.

    >>> from dataclasses import dataclass
    >>> from typing import ClassVar
    >>> from assur.core.loads import Load, Weight, param, register, registry
    >>> register(Weight) is Weight              # registering again changes nothing
    True
    >>> @dataclass(frozen=True)
    ... class Push(Load):
    ...     point: str = param("point", doc="where it acts")
    ...     F: object = param("value", "force", doc="downward [N]")
    ...     type_name: ClassVar[str] = "weight"
    >>> register(Push)
    Traceback (most recent call last):
    ...
    ValueError: load type 'weight' is registered twice
    >>> @dataclass(frozen=True)
    ... class Bad(Load):
    ...     point: str = "A"
    ...     type_name: ClassVar[str] = "bad"
    >>> register(Bad)
    Traceback (most recent call last):
    ...
    TypeError: load type 'bad': field 'point' is not declared with assur.core.loads.param
    >>> "bad" in registry()
    False
    """
    name = getattr(cls, "type_name", "")
    if not (isinstance(name, str) and name.isidentifier()):
        raise ValueError(f"a load type needs a type_name (an identifier), got {name!r}")
    if name in _REGISTRY:
        if _REGISTRY[name] is not cls:
            raise ValueError(f"load type {name!r} is registered twice")
        return cls
    fields = _declared(cls)
    if not callable(getattr(cls, "apply", None)) or cls.apply is Load.apply:
        raise TypeError(f"load type {name!r} must implement apply(c)")
    cls.fields = fields
    cls.quantities = {f.name: f.quantity for f in fields if f.role == "value"}
    cls.flags = {f.name: f.flag for f in fields if f.flag is not None}
    cls.point_fields = tuple(f.name for f in fields if f.role == "point")
    cls.link_fields = tuple(f.name for f in fields if f.role in ("link", "links"))
    for hook in _HOOKS:   # e.g. the Mechanism's builder method; may refuse the name
        hook(cls)
    _REGISTRY[name] = cls
    return cls


def registry() -> dict[str, type]:
    """The registered load types by model-file ``type`` name (a copy), in the order
    they were registered.

    Examples
    --------
    >>> from assur.core.loads import registry
    >>> list(registry())
    ['weight', 'force', 'moment', 'resisting_moment', 'spring', 'mass']
    >>> registry()["spring"].quantities["rate"]
    'stiffness'
    """
    return dict(_REGISTRY)


def load_type(name: str) -> type:
    """The load type registered under the model-file ``type`` ``name``.

    Examples
    --------
    >>> from assur.core.loads import Mass, load_type
    >>> load_type("mass") is Mass
    True
    >>> load_type("gear")
    Traceback (most recent call last):
    ...
    KeyError: "unknown load type 'gear'; known: ['force', 'mass', 'moment', 'resisting_moment', 'spring', 'weight']"
    """
    try:
        return _REGISTRY[name]
    except KeyError:
        raise KeyError(f"unknown load type {name!r}; known: {sorted(_REGISTRY)}") from None


def on_register(hook: Callable[[type], None], undo: Callable[[type], None] | None = None
                ) -> Callable[[], None]:
    """Call ``hook(cls)`` for every load type registered so far and every one registered
    later (before it enters the registry: a hook may refuse it by raising), and
    ``undo(cls)`` for one that is unregistered (:func:`unregister`). The
    :class:`~assur.core.mechanism.Mechanism` adds (and removes) its builder methods this
    way. Returns a function that removes the hooks again.

    Examples
    --------
    >>> from assur.core.loads import on_register
    >>> seen = []
    >>> stop = on_register(lambda cls: seen.append(cls.type_name))
    >>> seen[:3]
    ['weight', 'force', 'moment']
    >>> stop()                       # later load types are not seen
    """
    _HOOKS.append(hook)
    if undo is not None:
        _UNDO.append(undo)
    for cls in list(_REGISTRY.values()):
        hook(cls)

    def stop():
        _HOOKS.remove(hook)
        if undo is not None:
            _UNDO.remove(undo)
    return stop


def unregister(cls) -> None:
    """Remove a load type (a test's or a plugin's own) from the registry, and what the
    registry's hooks made of it (the ``Mechanism`` builder method).

    Examples
    --------
    >>> from dataclasses import dataclass
    >>> from typing import ClassVar
    >>> from assur import Mechanism
    >>> from assur.core.loads import Load, param, register, registry, unregister
    >>> @dataclass(frozen=True)
    ... class Nudge(Load):
    ...     point: str = param("point", doc="where")
    ...     type_name: ClassVar[str] = "toy_nudge_doc"
    ...     summary: ClassVar[str] = "nothing at a point"
    ...     def apply(self, c):
    ...         pass
    >>> register(Nudge) is Nudge, hasattr(Mechanism, "toy_nudge_doc")
    (True, True)
    >>> unregister(Nudge); "toy_nudge_doc" in registry(), hasattr(Mechanism, "toy_nudge_doc")
    (False, False)
    """
    if _REGISTRY.get(cls.type_name) is not cls:
        raise KeyError(f"load type {cls.type_name!r} is not registered as {cls.__name__}")
    del _REGISTRY[cls.type_name]
    for undo in _UNDO:
        undo(cls)


def _along_gravity(c, P):
    """The force of magnitude P along the context's direction of gravity: (fx, fy),
    an exact zero for a zero component (so the default weight is (0, −P))."""
    ux, uy = c.gravity_unit
    return (0.0 if ux == 0 else P * ux), (0.0 if uy == 0 else P * uy)


@register
@dataclass(frozen=True)
class Weight(Load):
    """Weight ``P`` [N] acting along gravity at ``point`` — downward unless the model
    turns gravity (``[model] gravity``, :func:`assur.core.statics.gravity_unit`) —, carried
    by ``link`` (by default the link that owns the point).

    Examples
    --------
    1000 N at the implement's centre of mass S6 of the seed-003 hitch: the cylinder
    pushes P·IS6.

    >>> from assur import examples
    >>> from assur.core.loads import Weight
    >>> m = examples.hitch_003().with_loads([Weight("S6", 1000.0)])
    >>> [round(float(f), 1) for f in m.analyze([0.42, 0.67]).statics.actuator_force()]  # [N]
    [4713.2, 4932.8]

    The builder ``Mechanism.weight`` adds one: the seed's P6 = 27.5 kN at S6 asks
    P6·IS6 of the cylinder (seed 003 table 4.1):

    >>> m = examples.hitch_003().with_loads().weight("S6", 27500.0)
    >>> round(float(m.analyze([0.42]).statics.actuator_force("S")[0]))  # [N]
    129614
    """

    point: str = param("point", doc="the point it acts at")
    P: Ref = param("value", "force", "nonneg", doc="its magnitude, along gravity [N]")
    link: str | None = param("link", default=None,
                             doc="the link that carries it (default: the point's owner)")
    name: str | None = param("name", default=None, doc="its name in reports")

    type_name: ClassVar = "weight"
    summary: ClassVar = "a weight P along gravity (downward by default) at a point"

    def apply(self, c):
        """Apply the weight to the load context ``c``: the force P·u at the point, u
        the direction of gravity (module notes).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import Weight
        >>> from assur.core.statics import applied_loads   # calls apply with its context
        >>> m = examples.hitch_003().with_loads([Weight("S6", "P6")])
        >>> forces, _, _ = applied_loads(m.solve([0.42]))
        >>> [(link, pt, float(fx), float(fy)) for link, pt, fx, fy in forces]  # [N]
        [('6', 'S6', 0.0, -27500.0)]
        """
        P = c.value(self.P)
        c.force(self.link or c.owner(self.point), self.point, *_along_gravity(c, P))


@register
@dataclass(frozen=True)
class PointForce(Load):
    """Force ``(fx, fy)`` [N] at ``point``, carried by ``link`` (default: owner).

    Examples
    --------
    A downward 1000 N at the hitch's suspension axis 56 asks P·I56 of the cylinder:

    >>> from assur import examples
    >>> from assur.core.loads import PointForce
    >>> m = examples.hitch_003().with_loads([PointForce("56", fy=-1000.0)])
    >>> [round(float(f), 1) for f in m.analyze([0.42, 0.67]).statics.actuator_force()]  # [N]
    [4459.4, 2621.3]

    The builder ``Mechanism.force``: a downward 27.5 kN at S6 asks of the cylinder
    what the seed's weight P6 does:

    >>> m = examples.hitch_003().with_loads().force("S6", fy=-27500.0)
    >>> round(float(m.analyze([0.42]).statics.actuator_force("S")[0]))  # P6·IS6 [N]
    129614
    """

    point: str = param("point", doc="the point it acts at")
    fx: Ref = param("value", "force", default=0.0, doc="its x component [N]")
    fy: Ref = param("value", "force", default=0.0, doc="its y component [N]")
    link: str | None = param("link", default=None,
                             doc="the link that carries it (default: the point's owner)")
    name: str | None = param("name", default=None, doc="its name in reports")

    type_name: ClassVar = "force"
    summary: ClassVar = "a force (fx, fy) at a point"

    def apply(self, c):
        """Apply the force to the load context ``c`` at its point.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import PointForce
        >>> from assur.core.statics import applied_loads
        >>> m = examples.hitch_003().with_loads([PointForce("56", fx=1000.0)])
        >>> forces, _, _ = applied_loads(m.solve([0.42]))
        >>> [(link, pt, float(fx), float(fy)) for link, pt, fx, fy in forces]  # [N]
        [('5', '56', 1000.0, 0.0)]
        """
        c.force(self.link or c.owner(self.point), self.point, c.value(self.fx),
                c.value(self.fy))


@register
@dataclass(frozen=True)
class Couple(Load):
    """Moment ``M`` [N·m], counter-clockwise positive, acting on ``link``.

    Examples
    --------
    100 N·m counter-clockwise on the hitch's lever 3: the cylinder holds −M·∂φ3/∂S.

    >>> from assur import examples
    >>> from assur.core.loads import Couple
    >>> m = examples.hitch_003().with_loads([Couple("3", 100.0)])
    >>> [round(float(f), 1) for f in m.analyze([0.42, 0.67]).statics.actuator_force()]  # [N]
    [-671.9, -623.9]

    The builder ``Mechanism.moment``: by virtual work the rod force is F = −M·φ6'
    (φ6' [rad/m], seed 003 table 3.1):

    >>> a = examples.hitch_003().with_loads().moment("6", 1000.0).analyze([0.42, 0.67])
    >>> [round(float(v), 1) for v in a.statics.actuator_force("S")]   # [N]
    [-294.9, -3084.9]
    >>> [round(float(v), 3) for v in a.kinematics.dphi("6")]          # [rad/m]
    [0.295, 3.085]
    """

    link: str = param("link", doc="the link it acts on")
    M: Ref = param("value", "moment", doc="counter-clockwise positive [N·m]")
    name: str | None = param("name", default=None, doc="its name in reports")

    type_name: ClassVar = "moment"
    summary: ClassVar = "a moment M on a link, counter-clockwise positive"

    def apply(self, c):
        """Apply the moment to the load context ``c``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import Couple
        >>> from assur.core.statics import applied_loads
        >>> m = examples.hitch_003().with_loads([Couple("3", 100.0)])
        >>> _, couples, _ = applied_loads(m.solve([0.42]))
        >>> [(link, float(M)) for link, M in couples]   # [N·m]
        [('3', 100.0)]
        """
        c.couple(self.link, c.value(self.M))


@register
@dataclass(frozen=True)
class ResistingMoment(Load):
    """A moment of magnitude ``M`` [N·m] on ``link`` that opposes the link's turn
    while the coordinate ``coordinate`` travels in the direction ``travel`` — the
    resisting moment of a steered wheel (seed 001 lab 4 eq. 17: M_c turns against
    the wheel whichever way it is steered)::

        travel = +1 (q grows):  φ' > 0  →  moment −M  (clockwise)
                                φ' < 0  →  moment +M  (counter-clockwise)

    that is ``moment = −M·sign(travel·∂φ_link/∂q)``; its virtual work along the
    travel, −M·|∂φ/∂q|, is never positive. ``travel = −1`` (q shrinks: the other
    turn) flips it. Where the link stands still (∂φ/∂q = 0) its work is zero either way.

    Parameters
    ----------
    link : str
    M : float or str
        Magnitude of the resisting moment [N·m] (≥ 0).
    travel : {1, -1}
        Direction of travel of the coordinate: +1 while it grows, −1 while it shrinks.
    coordinate : str, optional
        The coordinate whose travel is meant (default: the only one).
    name : str, optional

    Examples
    --------
    The hitch's lever 3 turns counter-clockwise while S grows (∂φ3/∂S > 0), so 100 N·m
    resisting it is −100 N·m, and the cylinder must push more to overcome it:

    >>> from assur import examples
    >>> from assur.core.loads import ResistingMoment
    >>> m = examples.hitch_003().with_loads([ResistingMoment("3", 100.0)])
    >>> [round(float(f), 1) for f in m.analyze([0.42, 0.67]).statics.actuator_force()]  # [N]
    [671.9, 623.9]

    The builder ``Mechanism.resisting_moment``: link 6 turns counter-clockwise as S
    grows (φ6' > 0), so 1000 N·m resisting that travel acts clockwise and the rod must
    push (compare ``Mechanism.moment``):

    >>> m = examples.hitch_003().with_loads().resisting_moment("6", 1000.0, travel=1)
    >>> [round(float(v), 1) for v in m.analyze([0.42, 0.67]).statics.actuator_force("S")]
    [294.9, 3084.9]
    """

    link: str = param("link", doc="the link it acts on")
    M: Ref = param("value", "moment", "nonneg", doc="its magnitude [N·m]")
    travel: int = param("sign", default=1,
                        doc="1: while the coordinate grows, -1: while it shrinks")
    coordinate: str | None = param("coordinate", default=None,
                                   doc="the coordinate whose travel it resists (default: "
                                       "the only one)")
    name: str | None = param("name", default=None, doc="its name in reports")

    type_name: ClassVar = "resisting_moment"
    summary: ClassVar = ("a moment that opposes the link's turn while the coordinate "
                         "travels that way: −M·sign(travel·∂φ/∂q) (seed 001 lab 4: the "
                         "wheel's M_c, eq. 17)")

    def check(self, mech):
        """A problem with this load in ``mech`` (a message), or None.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import ResistingMoment
        >>> m = examples.hitch_003()
        >>> print(ResistingMoment("3", 100.0).check(m))
        None
        >>> ResistingMoment("3", 100.0, travel=2).check(m)
        'travel must be 1 (the coordinate grows) or -1, got 2'
        >>> ResistingMoment("3", 100.0, coordinate="L3").check(m)
        "coordinate 'L3' is not a generalized coordinate ['S']"
        """
        if self.travel not in (1, -1):
            return f"travel must be 1 (the coordinate grows) or -1, got {self.travel!r}"
        if self.coordinate is None and len(mech.coordinates) > 1:
            return (f"name the coordinate whose travel it resists, one of "
                    f"{list(mech.coordinates)}")
        if self.coordinate is not None and self.coordinate not in mech.coordinates:
            return (f"coordinate {self.coordinate!r} is not a generalized coordinate "
                    f"{list(mech.coordinates)}")
        return None

    def apply(self, c):
        """Apply the moment ``−M·sign(travel·∂φ_link/∂q)`` to the load context ``c``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import ResistingMoment
        >>> from assur.core.statics import applied_loads
        >>> for travel in (1, -1):     # S grows, then S shrinks
        ...     m = examples.hitch_003().with_loads([ResistingMoment("3", 100.0, travel)])
        ...     _, couples, _ = applied_loads(m.solve([0.42]))
        ...     print([(link, float(M.ravel()[0])) for link, M in couples])   # [N·m]
        [('3', -100.0)]
        [('3', 100.0)]
        """
        w = c.rate(self.link, self.coordinate)
        c.couple(self.link, -np.copysign(c.value(self.M), self.travel * w))


@register
@dataclass(frozen=True)
class Spring(Load):
    """Linear spring(s) between points ``a`` and ``b`` (links ``links`` or the owners).

    Tension of one spring ``T = preload + rate·(|ab| − free_length)`` [N]; ``rate``
    [N/m], ``free_length`` [m], ``preload`` [N]. ``count`` identical springs act in
    parallel (seed 001 lab 2 eq. 4: k springs): the points are pulled together by
    ``count·T``.

    Examples
    --------
    A spring along the hitch's cylinder, from 01 to 23 (its length is S): the
    cylinder must push with its tension.

    >>> from assur import examples
    >>> from assur.core.loads import Spring
    >>> s = Spring("s", "01", "23", rate=1000.0, free_length=0.5, preload=50.0)
    >>> m = examples.hitch_003().with_loads([s])
    >>> [round(float(f), 1) for f in m.analyze([0.42, 0.67]).statics.actuator_force()]  # [N]
    [-30.0, 220.0]

    The builder ``Mechanism.spring``:

    >>> from assur.core.statics import spring_states
    >>> m = examples.hitch_003().with_loads().spring("k", "07", "S6", rate=1e4,
    ...                                              free_length=1.0)  # [N/m], [m]
    >>> L, T, F = spring_states(m.solve([0.42, 0.67]))["k"]
    >>> [round(float(v), 3) for v in L], [round(float(v)) for v in T]  # [m], [N]
    ([1.674, 1.463], [6745, 4630])
    """

    name: str = param("name", doc="its name (table 5.1's columns ``L_<name>``, ``T_<name>``, "
                                  "``F_<name>``)")
    a: str = param("point", doc="one end")
    b: str = param("point", doc="the other end")
    rate: Ref = param("value", "stiffness", "nonneg", doc="of one spring [N/m]")
    free_length: Ref = param("value", "length", "nonneg", doc="[m]")
    preload: Ref = param("value", "force", default=0.0,
                         doc="tension of one spring at its free length [N]")
    links: tuple[str, str] | None = param("links", default=None,
                                          doc="[link of a, link of b] (default: the owners)")
    count: Ref = param("value", "number", "count", default=1,
                       doc="identical springs in parallel")

    type_name: ClassVar = "spring"
    summary: ClassVar = ("count identical linear springs between points a and b: the "
                         "tension of one, preload + rate·(|ab| − free_length), pulls a and "
                         "b together; the force on the points is count × tension. Table 5.1 "
                         "shows each spring's length ``L_<name>``, the tension of one spring "
                         "``T_<name>`` and the force of all ``F_<name>``")

    def tension(self, c, L):
        """Tension of one spring [N] at the length ``L`` [m] (context values).

        Examples
        --------
        ``c`` needs only ``value`` here (a parameter's value, a number as it is):

        >>> from types import SimpleNamespace
        >>> from assur.core.loads import Spring
        >>> c = SimpleNamespace(value=lambda ref: {"k": 2000.0}.get(ref, ref))
        >>> s = Spring("s", "01", "23", rate="k", free_length=0.5, preload=100.0)
        >>> round(float(s.tension(c, 0.6)), 6)    # 100 + 2000·(0.6 − 0.5) [N]
        300.0
        """
        return c.value(self.preload) + c.value(self.rate) * (L - c.value(self.free_length))

    def apply(self, c):
        """Apply the spring to the load context ``c``: ``count·T`` along a→b at ``a``,
        the opposite at ``b``, and report its tension and length (``c.spring``).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import Spring
        >>> from assur.core.statics import applied_loads
        >>> s = Spring("s", "01", "23", rate=1000.0, free_length=0.5, preload=50.0, count=2)
        >>> m = examples.hitch_003().with_loads([s])
        >>> forces, _, springs = applied_loads(m.solve([0.67]))
        >>> [(link, pt) for link, pt, _, _ in forces]      # the two ends' links
        [('0', '01'), ('3', '23')]
        >>> _, T, L = springs[0]
        >>> round(float(T.ravel()[0]), 1), round(float(L.ravel()[0]), 3)   # one spring [N], [m]
        (220.0, 0.67)
        """
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


@register
@dataclass(frozen=True)
class Mass(Load):
    """Mass ``m`` [kg] of a link with its centre of mass at ``point`` and moment of
    inertia ``J`` [kg·m²] about it: its weight m·g, and for a motion in time its
    inertia force −m·a and moment −J·ε (d'Alembert).

    Examples
    --------
    1000 kg at S6 of the hitch weighs 9810 N (g = 9.81 m/s²):

    >>> from assur import examples
    >>> from assur.core.loads import Mass
    >>> m = examples.hitch_003().with_loads([Mass("6", 1000.0, "S6")])
    >>> [round(float(f), 1) for f in m.analyze([0.42, 0.67]).statics.actuator_force()]  # [N]
    [46236.8, 48390.7]

    The builder ``Mechanism.mass``: a mass weighing the seed's P6 = 27.5 kN at rest:

    >>> m = examples.hitch_003().with_loads().mass("6", 27500.0 / 9.81, "S6")  # [kg]
    >>> round(float(m.analyze([0.42]).statics.actuator_force("S")[0]))  # [N]
    129614
    """

    link: str = param("link", doc="the link whose mass it is")
    m: Ref = param("value", "mass", "positive", doc="[kg]")
    point: str = param("point", doc="its centre of mass")
    J: Ref = param("value", "inertia", "nonneg", default=0.0,
                   doc="moment of inertia about the centre of mass [kg·m²]")

    type_name: ClassVar = "mass"
    summary: ClassVar = ("the mass of a link at its centre of mass: its weight m·g and, for "
                         "a motion in time, its inertia force −m·a and moment −J·ε")

    def apply(self, c):
        """Apply the weight m·g to the load context ``c`` and, when it is moving, the
        inertia force −m·a and moment −J·ε.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import Mass
        >>> from assur.core.statics import applied_loads
        >>> m = examples.hitch_003().with_loads([Mass("6", 1000.0, "S6", J=50.0)])
        >>> forces, couples, _ = applied_loads(m.solve([0.42]))    # static: weight only
        >>> [(link, pt, float(fx), round(float(fy), 1)) for link, pt, fx, fy in forces]  # [N]
        [('6', 'S6', 0.0, -9810.0)]
        >>> forces, couples, _ = applied_loads(m.solve([0.42]), qdot=0.1)   # S moving [m/s]
        >>> len(forces), len(couples)       # + the inertia force and moment
        (2, 1)
        """
        m = c.value(self.m)
        c.force(self.link, self.point, *_along_gravity(c, m * c.g))
        if c.moving:
            acc_x, acc_y = c.acceleration(self.point)
            c.force(self.link, self.point, -m * acc_x, -m * acc_y)
            c.couple(self.link, -c.value(self.J) * c.angular_acceleration(self.link))


#: the registry of load types by model-file ``type``, read-only (:func:`registry`)
LOAD_TYPES = MappingProxyType(_REGISTRY)


def names_in(value) -> tuple:
    """The names a point or link field holds: none (None), one (a str) or a tuple.

    Examples
    --------
    >>> from assur.core.loads import names_in
    >>> names_in(None), names_in("3"), names_in(["0", "3"])
    ((), ('3',), ('0', '3'))
    """
    if value is None:
        return ()
    return (value,) if isinstance(value, str) else tuple(value)


def load_link(mech, load):
    """The link a load acts on: its ``link``, else the owner of its ``point``; None for
    a load between two links (a spring).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.loads import load_link
    >>> m = examples.hitch_003()
    >>> m.loads[0], load_link(m, m.loads[0])        # P6 at S6, on the implement 6
    (Weight(point='S6', P='P6', link=None, name='P6'), '6')
    """
    link = getattr(load, "link", None)
    if link is not None:
        return link
    point = getattr(load, "point", None)
    return mech.owner(point) if point is not None else None


def masses_of(mech) -> tuple:
    """The :class:`Mass` loads of a mechanism on moving links.

    Examples
    --------
    >>> from assur import examples, io
    >>> from assur.core.loads import masses_of
    >>> masses_of(examples.hitch_003())      # a weight P6, no masses
    ()
    >>> ms = masses_of(io.load(io.bundled("cleaning_lab3")).mechanism)   # seed 001 lab 3
    >>> len(ms), ms[1]                       # m2, J2 are model parameters
    (9, Mass(link='2', m='m2', point='S2', J='J2'))
    """
    return tuple(ld for ld in mech.loads if type(ld) is Mass and ld.link != "0")


def dead_load_links(mech) -> tuple:
    """The links whose loads every capacity carries besides the load it lifts
    (``[tables] dead_loads``; seed 001 lab 1 eq. 14: the boom's own weight).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.loads import dead_load_links
    >>> dead_load_links(examples.loader_lab1())   # the boom 3 (seed 001 lab 1 eq. 14)
    ('3',)
    >>> dead_load_links(examples.hitch_003())     # none declared
    ()
    """
    return tuple(mech.tables.get("dead_loads", ()) or ())


def is_dead(mech, load, links=None) -> bool:
    """Whether ``load`` is a dead load: it acts on one of ``links`` (default: the
    model's :func:`dead_load_links`).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.loads import is_dead
    >>> m = examples.loader_lab1()
    >>> [(ld.point, is_dead(m, ld)) for ld in m.loads]   # the boom's mass at S3 [-]
    [('S3', True), ('S9', False)]
    """
    links = dead_load_links(mech) if links is None else tuple(links)
    return bool(links) and load_link(mech, load) in links


def centre_of_mass(masses, value, point):
    """The common centre of mass Σ m_i·r_i / Σ m_i of ``masses`` and their total mass,
    ``(x, y, M)`` [m, m, kg] in the numbers of a context — arrays, dual numbers or the
    symbols of a kernel (seed 001 lab 3; the outputs ``Xc``, ``Yc`` and
    :func:`assur.dynamics.balancing.common_centre` both call it).

    Parameters
    ----------
    masses : sequence of Mass
    value : callable
        A mass's ``m`` (a number or parameter name) → its value [kg].
    point : callable
        A point's name → its ``(x, y)`` [m].

    Examples
    --------
    >>> from assur.core.loads import Mass, centre_of_mass
    >>> ms = [Mass("1", 2.0, "A"), Mass("2", 6.0, "B")]
    >>> pts = {"A": (0.0, 0.0), "B": (1.0, 2.0)}
    >>> centre_of_mass(ms, float, pts.get)        # [m], [m], [kg]
    (0.75, 1.5, 8.0)
    """
    sx = sy = tot = 0.0
    for ld in masses:
        m = value(ld.m)
        x, y = point(ld.point)
        sx, sy, tot = sx + m * x, sy + m * y, tot + m
    return sx / tot, sy / tot, tot
