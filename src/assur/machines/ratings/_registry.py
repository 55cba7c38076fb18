"""The registry of rating kinds, keyed by the model file's ``type`` (the pattern of
:mod:`assur.core.loads` and :mod:`assur.groups`, DESIGN.md §9)."""

from __future__ import annotations

from .base import Rating, declared

__all__ = ["register", "registry", "rating_type"]

_REGISTRY: dict[str, type] = {}


def register(cls):
    """Class decorator: register a rating kind under ``cls.type_name`` and record its
    :attr:`~assur.machines.ratings.Rating.fields` from its
    :func:`~assur.machines.ratings.param` declarations.

    Examples
    --------
    >>> from dataclasses import dataclass
    >>> from typing import ClassVar
    >>> from assur.machines.ratings import Rating, param, register, rating_type
    >>> register(rating_type("crane_chart")) is rating_type("crane_chart")   # again: no change
    True
    >>> @dataclass(frozen=True)
    ... class Twice(Rating):
    ...     point: str = param("point")
    ...     type_name: ClassVar[str] = "crane_chart"
    ...     def evaluate(self, mech, kin): ...
    >>> register(Twice)
    Traceback (most recent call last):
    ...
    ValueError: rating type 'crane_chart' is registered twice
    """
    name = getattr(cls, "type_name", "")
    if not (isinstance(name, str) and name.isidentifier()):
        raise ValueError(f"a rating type needs a type_name (an identifier), got {name!r}")
    if name in _REGISTRY:
        if _REGISTRY[name] is not cls:
            raise ValueError(f"rating type {name!r} is registered twice")
        return cls
    if not issubclass(cls, Rating) or cls.evaluate is Rating.evaluate:
        raise TypeError(f"rating type {name!r} must subclass Rating and implement evaluate")
    cls.fields = declared(cls)
    _REGISTRY[name] = cls
    return cls


def registry() -> dict[str, type]:
    """The registered rating kinds by model-file ``type`` (a copy), in their order.

    Examples
    --------
    >>> from assur.machines.ratings import registry
    >>> list(registry())
    ['crane_chart', 'excavator_digging', 'loader_tipping', 'loader_breakout', 'loader_lift']
    """
    return dict(_REGISTRY)


def rating_type(name: str) -> type:
    """The rating kind registered under the model-file ``type`` ``name``.

    Raises
    ------
    KeyError
        Naming the registered types.

    Examples
    --------
    >>> from assur.machines.ratings import rating_type
    >>> rating_type("crane_chart").type_name
    'crane_chart'
    >>> rating_type("crane")   # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    KeyError: "no rating type 'crane'; types: crane_chart, excavator_digging, loader_tipping, ..."
    """
    try:
        return _REGISTRY[name]
    except KeyError:
        raise KeyError(f"no rating type {name!r}; types: {', '.join(_REGISTRY)}") from None
