"""The registry of load types: the contract every load type declares itself by
(:class:`Load`, :func:`param`) and :func:`register` (docs/adding-a-load.md)."""

from __future__ import annotations

from dataclasses import MISSING, field as _dataclass_field, fields as _dataclass_fields
from types import MappingProxyType
from typing import Callable, ClassVar, Union

from ...groups.base import Field
from ..quantities import DEFAULT_UNITS

__all__ = ["Ref", "ROLES", "FLAGS", "param", "Load", "register", "unregister", "registry",
           "load_type", "on_register", "LOAD_TYPES"]

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


#: the load types by their model-file ``type`` (a read-only view of the registry, in the
#: order they were registered)
LOAD_TYPES = MappingProxyType(_REGISTRY)
