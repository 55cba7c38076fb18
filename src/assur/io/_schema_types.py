"""The ``[[groups]]`` and ``[[loads]]`` tables of a model file, derived from the
registries: one pydantic model per registered group type (:func:`assur.groups.registry`)
and per registered load type (:func:`assur.core.loads.registry`), built from the
type's declared fields with :func:`pydantic.create_model`. Nothing here lists a type.
"""

from __future__ import annotations

import typing
from collections.abc import Mapping
from typing import Optional

from pydantic import StrictStr, create_model, model_validator
from pydantic_core import PydanticCustomError

from ._schema_values import Branch, Name, ShownName, Value, _Table


# ---- [[groups]] ---------------------------------------------------------------------
class _Group(_Table):
    type: StrictStr
    #: a string, or { en = "…", ru = "…" } (the report shows the language's)
    name: ShownName
    links: list[Name] = []


#: the annotation of a group field by its role (see :class:`assur.groups.Field`)
_ROLE_TYPES = {"point": Name, "line": Optional[tuple[Name, Name]], "value": Value,
               "coordinate": Name, "position": dict[str, Value], "branch": Branch}


def group_spec(cls) -> type[_Group]:
    """The pydantic model of one registered group type's ``[[groups]]`` table, derived
    from its :attr:`~assur.groups.Group.fields`: ``type``, ``name``, ``links``, then
    each field with the annotation of its role, required unless it has a default.
    The type's :meth:`~assur.groups.Group.check_fields` is its cross-key check."""
    fields = {}
    for f in cls.fields:
        if f.role not in _ROLE_TYPES:
            raise ValueError(f"group type {cls.type_name!r}: field {f.name!r} has the unknown "
                             f"role {f.role!r} (one of: {', '.join(_ROLE_TYPES)})")
        if f.role in ("value", "coordinate") and f.quantity not in ("length", "angle"):
            raise ValueError(f"group type {cls.type_name!r}: field {f.name!r} needs a quantity "
                             f"(length or angle), has {f.quantity!r}")
        fields[f.name] = (_ROLE_TYPES[f.role], ... if f.required else f.default)

    def _check_fields(self):
        problem = cls.check_fields(set(self.model_fields_set) - {"type", "name", "links"})
        if problem:
            raise PydanticCustomError("group", problem)
        return self

    return create_model(f"{cls.__name__}Spec", __base__=_Group,
                        __validators__={"_check_fields": model_validator(mode="after")(
                            _check_fields)},
                        __module__=__name__, **fields)


_SPECS: dict = {}


def group_types() -> Mapping[str, type[_Group]]:
    """The ``[[groups]]`` table models by ``type``, one per registered group type (the
    frame, which is the ``[frame]`` section, excluded), in the order the package
    :mod:`assur.groups` lists them (its ``__all__``; registration order follows the
    modules' imports), then any type registered elsewhere."""
    from .. import groups
    listed = {name: k for k, name in enumerate(groups.__all__)}
    reg = groups.registry()
    order = sorted(reg, key=lambda n: (listed.get(reg[n].__name__, len(listed)),
                                       list(reg).index(n)))
    types = {n: reg[n] for n in order if n != "frame"}
    key = tuple(types.items())
    if _SPECS.get("key") != key:
        _SPECS.update(key=key, specs=_Specs(types))
    return _SPECS["specs"]


class _Specs(Mapping):
    """The group types' table models by name, each made by :func:`group_spec` when
    first asked for (a file names a few of the types; making a model costs ~1 ms)."""

    def __init__(self, types):
        self._types, self._made = types, {}

    def __getitem__(self, name):
        if name not in self._made:
            self._made[name] = group_spec(self._types[name])
        return self._made[name]

    def __iter__(self):
        return iter(self._types)

    def __len__(self):
        return len(self._types)


# ---- [[loads]] ----------------------------------------------------------------------
class _Load(_Table):
    type: StrictStr


#: the annotation of a load field by its role (:data:`assur.core.loads.ROLES`)
_LOAD_ROLE_TYPES = {"point": Name, "link": Name, "links": tuple[Name, Name], "value": Value,
                    "name": ShownName, "sign": typing.Literal[1, -1], "coordinate": Name}


def load_spec(cls) -> type[_Load]:
    """The pydantic model of one registered load type's ``[[loads]]`` table, derived
    from its :attr:`~assur.core.loads.Load.fields`: ``type``, then each field with the
    annotation of its role (optional when its default is None), required unless it has
    a default.

    Examples
    --------
    >>> from assur.core.loads import Spring
    >>> from assur.io._schema_types import load_spec
    >>> spec = load_spec(Spring)
    >>> list(spec.model_fields)
    ['type', 'name', 'a', 'b', 'rate', 'free_length', 'preload', 'links', 'count']
    >>> [n for n, f in spec.model_fields.items() if f.is_required()]
    ['type', 'name', 'a', 'b', 'rate', 'free_length']
    """
    fields = {}
    for f in cls.fields:
        if f.role not in _LOAD_ROLE_TYPES:
            raise ValueError(f"load type {cls.type_name!r}: field {f.name!r} has the unknown "
                             f"role {f.role!r} (one of: {', '.join(_LOAD_ROLE_TYPES)})")
        t = _LOAD_ROLE_TYPES[f.role]
        if not f.required and f.default is None:
            t = Optional[t]
        fields[f.name] = (t, ... if f.required else f.default)
    return create_model(f"{cls.__name__}Spec", __base__=_Load, __module__=__name__, **fields)


_LOAD_SPECS: dict = {}


def load_types() -> dict[str, type[_Load]]:
    """The ``[[loads]]`` table models by ``type``, one per registered load type, in the
    order of registration.

    Examples
    --------
    >>> from assur.io._schema_types import load_types
    >>> list(load_types())
    ['weight', 'force', 'moment', 'resisting_moment', 'spring', 'mass']
    >>> load_types()["weight"].model_validate({"type": "weight", "point": "S6", "P": "P6"}).P
    'P6'
    """
    from ..core.loads import registry
    types = registry()
    key = tuple(types.items())
    if _LOAD_SPECS.get("key") != key:
        _LOAD_SPECS.update(key=key, specs={n: load_spec(c) for n, c in types.items()})
    return _LOAD_SPECS["specs"]
