"""The registry of structural group types, keyed by the model file's ``type``: the
builder methods, the file schema, the docs table and the kernel's table of operations
(:mod:`assur.kernel.ops`) derive from it (docs/adding-a-group.md)."""

from __future__ import annotations

from ..kernel import ops

__all__ = ["register", "unregister", "registry", "group_type"]

_REGISTRY: dict[str, type] = {}


def register(cls):
    """Class decorator: register a group type under ``cls.type_name`` and give it its
    op code (its index in the kernel's table of operations, :mod:`assur.kernel.ops`).

    Examples
    --------
    Registering a type again changes nothing; another class under a taken name is
    refused:

    >>> from dataclasses import dataclass
    >>> from typing import ClassVar
    >>> from assur.groups import Crank, Group, register
    >>> register(Crank) is Crank, register(Crank).op == Crank.op
    (True, True)
    >>> @dataclass(frozen=True)
    ... class MyCrank(Group):
    ...     type_name: ClassVar[str] = "crank"
    >>> register(MyCrank)
    Traceback (most recent call last):
    ...
    ValueError: group type 'crank' is registered twice
    """
    name = cls.type_name
    if name in _REGISTRY and _REGISTRY[name] is not cls:
        raise ValueError(f"group type {name!r} is registered twice")
    if name not in _REGISTRY:
        cls.op = ops.add(cls)
        _REGISTRY[name] = cls
    return cls


def unregister(cls) -> None:
    """Remove a group type registered last (a test's or a plugin's own).

    Examples
    --------
    >>> from dataclasses import dataclass
    >>> from typing import ClassVar
    >>> from assur.groups import Dyad, register, registry, unregister
    >>> @dataclass(frozen=True)
    ... class ToyDyad(Dyad):
    ...     type_name: ClassVar[str] = "toy_dyad_doc"
    >>> "toy_dyad_doc" in registry(), register(ToyDyad) is ToyDyad
    (False, True)
    >>> unregister(ToyDyad); "toy_dyad_doc" in registry()
    False
    """
    if _REGISTRY.get(cls.type_name) is not cls:
        raise KeyError(f"group type {cls.type_name!r} is not registered as {cls.__name__}")
    ops.discard(cls)
    del _REGISTRY[cls.type_name]


def registry() -> dict[str, type]:
    """The registered group types by model-file ``type`` name (a copy).

    Examples
    --------
    >>> from assur.groups import registry
    >>> types = registry()
    >>> len(types), sorted(types)[:4]
    (10, ['crank', 'cylinder_lever', 'dyad', 'frame'])
    >>> types["crank"].kind, types["crank"].driver_kind
    ('crank', 'angle')
    """
    return dict(_REGISTRY)


def group_type(op_or_name) -> type:
    """The group type of an op code or a ``type`` name.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.groups import Crank, group_type
    >>> group_type("crank") is Crank, group_type(Crank.op) is Crank
    (True, True)
    >>> rows = examples.combine_002().program().rows    # each row starts with its op code
    >>> [group_type(row[0]).type_name for row in rows]
    ['frame', 'frame', 'frame', 'crank', 'dyad', 'rigid_point', 'dyad']
    >>> group_type("gear")
    Traceback (most recent call last):
    ...
    KeyError: 'gear'
    """
    if isinstance(op_or_name, str):
        return _REGISTRY[op_or_name]
    return ops.op(op_or_name)
