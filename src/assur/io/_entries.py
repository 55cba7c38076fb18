"""What the file loader's passes share: the flags a value may carry and their words,
the physical span of a kind, the message of an unreadable value, and what the
entries of ``[[groups]]``, ``[[loads]]`` and ``[[cylinders]]`` hold — read from the
registered types' declared fields (:mod:`assur.groups`, :mod:`assur.core.loads`)
and the cylinder's own declaration, never from a list of types.
"""

from __future__ import annotations

from ..core.cylinders import Cylinder
from ..core.inputs import span_problem
from ..core.loads import load_type
from ..groups import group_type
from . import _schema as S
from ._units import ANGLE, KINDS, LENGTH

# constraints on values beyond their kind: (test, words)
FLAGS = {
    "positive": (lambda v: v > 0, lambda k: f"a positive {k.name}"),
    "nonneg": (lambda v: v >= 0, lambda k: f"a non-negative {k.name}"),
    "fraction": (lambda v: 0 < v <= 1, lambda k: "a number in (0, 1]"),
    "share": (lambda v: 0 <= v < 1, lambda k: "a number in [0, 1)"),
    "count": (lambda v: v > 0, lambda k: "a positive whole number"),
}

#: the unit kind of a group field's ``quantity`` (:class:`assur.groups.Field`)
QUANTITY = {"length": LENGTH, "angle": ANGLE}


def kind(quantity):
    """The unit kind (:data:`assur.io._units.KINDS`) of a declared quantity
    (:data:`assur.core.quantities.DEFAULT_UNITS`: ``"angular_velocity"`` is the kind
    ``"angular velocity"``)."""
    return KINDS.get(quantity) or KINDS[quantity.replace("_", " ")]


# ---- [[groups]] --------------------------------------------------------------------------
def fields(g, *roles):
    """The fields of group entry ``g``'s type with one of ``roles``, in their order."""
    return [f for f in group_type(g.type).fields if f.role in roles]


def group_values(g):
    """``{field: (kind, flag, may be a coordinate)}`` of the value fields of ``g``."""
    return {f.name: (QUANTITY[f.quantity], f.flag, f.coordinate_ok)
            for f in fields(g, "value")}


def group_outputs(g):
    """The names of the point fields of ``g`` that name the points it adds."""
    return tuple(group_type(g.type).out_fields)


def group_links(g):
    """The roles of the links group entry ``g``'s type adds (None: a point on a link)."""
    return group_type(g.type).link_roles


def group_inputs(g, gp):
    """``[(key path, point)]`` of the points ``g`` needs: its point fields that are not
    outputs, then the pairs of its line fields that are given."""
    outs = group_outputs(g)
    inputs = [(gp + (f.name,), getattr(g, f.name)) for f in fields(g, "point")
              if f.name not in outs]
    for f in fields(g, "line"):
        pair = getattr(g, f.name)
        if pair is not None:
            inputs += [(gp + (f.name, k), p) for k, p in enumerate(pair)]
    return inputs


# ---- [[loads]], [[cylinders]] ------------------------------------------------------------
def load_values(ld):
    """``{field: (kind, flag)}`` of the value fields of load entry ``ld``'s type."""
    return {f.name: (kind(f.quantity), f.flag) for f in load_type(ld.type).fields
            if f.role == "value"}


def load_points(ld):
    """The fields of load entry ``ld``'s type that name points."""
    return load_type(ld.type).point_fields


def load_links(ld):
    """The fields of load entry ``ld``'s type that name links (one, or a pair)."""
    return load_type(ld.type).link_fields


#: the cylinder's value fields: ``{field: (kind, flag)}``
CYLINDER_VALUES = {f: (kind(q), Cylinder.flags.get(f)) for f, q in Cylinder.quantities.items()}


# ---- values -------------------------------------------------------------------------------
#: the kind of span (:data:`assur.core.inputs.SPANS`) a flag asks for
_SPAN_OF_FLAG = {"fraction": "efficiency", "count": "count"}


def span(kind_, flag, si):
    """What is wrong with ``si`` against the physical span of ``kind_`` (and ``flag``:
    an efficiency, a cylinder count, a positive value), or None."""
    name = _SPAN_OF_FLAG.get(flag) or (kind_.name if kind_ is not None else None)
    if name is None or isinstance(si, str):
        return None
    return span_problem(name, float(si), flag in ("positive", "count"))


def unreadable(err, expected, found):
    """Message for a value that :func:`assur.io._units.parse` cannot read: what was wrong
    with it (an unknown unit), what was expected and what was found."""
    reason = str(err)
    if reason.startswith("expected"):
        return f"{reason}, found {S.show(found)}"
    return (f"{reason}: " if reason else "") + f"expected {expected}, found {S.show(found)}"
