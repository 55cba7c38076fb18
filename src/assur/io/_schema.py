"""The structure of a model file, as pydantic models.

This layer checks the *shape* of the file: which tables and keys exist, which
are required, the TOML type of every value (string, integer, array, table),
and refuses unknown keys. What the values *mean* — units and their dimensions,
references to parameters, points and links — is checked when the mechanism is
built (:mod:`assur.io._build`), where the context is known.

Groups and loads are tables with a ``type`` key; each type has its own model,
picked from :func:`group_types` / :func:`load_types` (an unknown type is an error
listing the valid ones). Those models are not written here: they derive from the
fields of the registered group types (:mod:`assur.groups`) and load types
(:mod:`assur.core.loads`) — :mod:`assur.io._schema_types`; the docs tables too
(:mod:`assur.io._schema_tables`). The value types are in
:mod:`assur.io._schema_values`, the words of the errors in
:mod:`assur.io._schema_words`; all are re-exported here.
"""

from __future__ import annotations

import typing
from typing import Annotated, Any, Optional

from pydantic import AfterValidator, Field, StrictBool, StrictInt, StrictStr, model_validator
from pydantic_core import PydanticCustomError

from ._schema_tables import (LOAD_TABLE_BEGIN, LOAD_TABLE_END, TABLE_BEGIN, TABLE_END,
                             load_types_table, schema_table)
from ._schema_types import group_spec, group_types, load_spec, load_types
from ._schema_values import (Branch, FramePoint, Name, ShownName, Sign, Terms, Text, Value,
                             _Table,
                             _distance, _value)
from ._schema_words import allowed_keys, describe, did_you_mean, show, validate

__all__ = ["FileSpec", "group_types", "load_types", "group_spec", "load_spec", "schema_table",
           "load_types_table", "TABLE_BEGIN", "TABLE_END", "LOAD_TABLE_BEGIN",
           "LOAD_TABLE_END", "Value", "Name", "Text", "Terms", "FramePoint", "Branch", "Sign",
           "allowed_keys", "describe", "did_you_mean", "show", "validate"]


# ---- [model], [range] ---------------------------------------------------------------
def _gravity(v):
    """``[model] gravity``: a value, ``"none"``, or ``{ value, direction }``."""
    if v == "none":
        return v
    if isinstance(v, dict):
        extra = sorted(set(v) - {"value", "direction"})
        if extra or not v:
            raise PydanticCustomError(
                "gravity", 'expected { value = "9.81 m/s^2", direction = -90 } (keys value, '
                           'direction), found the key(s) {keys}', {"keys": ", ".join(extra)})
        return {k: _value(x) for k, x in v.items()}
    return _value(v)


class ModelSection(_Table):
    name: Name
    title: Optional[Text] = None
    coordinates: Annotated[list[Name], Field(min_length=1)]
    notes: list[Text] = []
    gravity: Annotated[Any, AfterValidator(_gravity)] = None


class RangeSpec(_Table):
    from_: Value = Field(None, alias="from")
    to: Value = None
    count: Annotated[StrictInt, Field(ge=2)] = None
    step: Value = None
    values: Annotated[list[Value], Field(min_length=1)] = None
    #: a held coordinate: solved at every position so that the output ``hold``
    #: equals ``equals``, within its limits (:mod:`assur.core.held`)
    hold: Name = None
    equals: Value = None
    within: tuple[Value, Value] = None

    @model_validator(mode="after")
    def _one_form(self):
        given = self.model_fields_set
        forms = ("values = [...], or from, to and count, or from, to and step, or hold, "
                 "equals and within")
        held = {"hold", "equals", "within"}
        if given & held:
            if given - held:
                raise PydanticCustomError("range", f"expected one of: {forms}; not both "
                                                   f"hold and " + ", ".join(
                                                       sorted(k.rstrip("_")
                                                              for k in given - held)))
            missing = [k for k in ("hold", "equals", "within") if k not in given]
            if missing:
                raise PydanticCustomError("range", "a held coordinate needs hold (the "
                                                   "output held), equals (its value) and "
                                                   "within = [low, high] (the coordinate's "
                                                   "limits); missing " + ", ".join(missing))
        elif "values" in given:
            if given & {"from_", "to", "count", "step"}:
                raise PydanticCustomError("range", f"expected one of: {forms}; not both "
                                                   f"values and from/to")
        elif {"count", "step"} <= given:
            raise PydanticCustomError("range", f"expected one of: {forms}; not both count "
                                               f"and step")
        elif not ({"from_", "to"} <= given and given & {"count", "step"}):
            missing = [k.rstrip("_") for k in ("from_", "to") if k not in given]
            if not given & {"count", "step"}:
                missing.append("count (or step)")
            raise PydanticCustomError("range", f"expected one of: {forms}; missing "
                                               + ", ".join(missing))
        return self


def _speed(v):
    """A speed: a value (``"300 rpm"``, ``"0.05 m/s"``), or a table in time
    ``{ t = [...], omega = [...] }`` (a crank) or ``{ t = [...], v = [...] }`` (a rod)."""
    if isinstance(v, dict):
        unknown = [k for k in v if k not in ("t", "omega", "v")]
        if unknown:
            raise PydanticCustomError("speed", 'unknown key "{k}" in a speed table '
                                               "(allowed: t, and omega for a crank or v for a "
                                               "rod)", {"k": unknown[0]})
        keys = [k for k in ("omega", "v") if k in v]
        if len(keys) != 1:
            raise PydanticCustomError("speed", "a speed table needs t = [...] and one of "
                                               "omega = [...] (a crank) or v = [...] (a rod)")
        w = keys[0]
        for k in ("t", w):
            if not isinstance(v.get(k), list) or len(v[k]) < 2:
                raise PydanticCustomError("speed", "a speed table needs t = [...] and "
                                                   "{w} = [...], at least two values each",
                                          {"w": w})
        if len(v["t"]) != len(v[w]):
            raise PydanticCustomError("speed", "t and {w} need as many values ({a} and {b})",
                                      {"w": w, "a": len(v["t"]), "b": len(v[w])})
        return {"t": [_value(x) for x in v["t"]], w: [_value(x) for x in v[w]]}
    return _value(v)


def _law(v):
    """A law of motion ``{ t = [...], q = [...] }`` (:mod:`assur.core.motion`)."""
    if not isinstance(v, dict) or set(v) != {"t", "q"}:
        raise PydanticCustomError("law", "expected a law of motion { t = [...], q = [...] }: "
                                         "times and the coordinate's values")
    for k in ("t", "q"):
        if not isinstance(v[k], list) or len(v[k]) < 2:
            raise PydanticCustomError("law", "a law of motion needs t = [...] and q = [...], "
                                             "at least two values each")
    if len(v["t"]) != len(v["q"]):
        raise PydanticCustomError("law", "t and q need as many values ({a} and {b})",
                                  {"a": len(v["t"]), "b": len(v["q"])})
    return {k: [_value(x) for x in v[k]] for k in ("t", "q")}


class MotionSpec(_Table):
    """``[motion]`` of one coordinate: direction and speed, or a law of motion q(t)
    (:mod:`assur.core.motion`)."""
    direction: typing.Literal["ccw", "cw", "extend", "retract"] = None
    speed: Annotated[Any, AfterValidator(_speed)] = None
    start: Value = None
    law: Annotated[Any, AfterValidator(_law)] = None


class CylinderSpec(_Table):
    #: a string, or { en = "…", ru = "…" } (the report shows the language's)
    name: ShownName
    coordinate: Optional[Name] = None
    distance: Optional[Name] = None
    supply: Optional[Name] = None
    bore: Value
    rod: Value = 0.0
    rod2: Value = 0.0
    count: Value = 1
    eta_mech: Value = 1.0
    eta_hyd: Value = 1.0
    p_relief: Value = 0.0
    dp_throttle: Value = 0.0
    dp_line: Value = 0.0
    #: the working chamber, or the working direction naming it ("extend" = "piston",
    #: "retract" = "rod"; assur.core.cylinders.Cylinder)
    side: typing.Literal["piston", "rod", "auto", "extend", "retract"] = "piston"


class WheelSpec(_Table):
    """``[[wheels]]``: a wheel drawn on a link (:class:`assur.core.wheels.Wheel`)."""
    #: a string, or { en = "…", ru = "…" }
    name: ShownName
    #: a link of [links] whose direction φ the heading follows (none: a fixed heading)
    link: Optional[Name] = None
    #: the point it is centred on
    at: Name
    #: rolling direction relative to the link's direction (from +x without a link)
    heading: Value = 0.0
    diameter: Value
    width: Value


# ---- [machine] ----------------------------------------------------------------------
class WeightItem(_Table):
    name: ShownName
    P: Terms
    x: Terms


class ImplementSpec(_Table):
    point: Name
    weight: Value


class MachineSpec(_Table):
    axles: dict[str, Terms]
    steered: Name
    weights: Annotated[list[WeightItem], Field(min_length=1)]
    counterweights: list[WeightItem] = []
    min_share: Value = 0.2
    implement: ImplementSpec


# ---- [tables], [[solve]], the file ---------------------------------------------------
class FormulaSpec(_Table):
    """An extra column computed by an expression (:class:`assur.core.columns.Formula`)."""
    name: Name
    expr: StrictStr
    unit: StrictStr = "-"
    table: Optional[StrictStr] = None
    label: Optional[Text] = None
    flags: list[Text] = []


class SignSpec(_Table):
    """Columns printed with a sign, and why (:class:`assur.core.columns.SignMap`)."""
    columns: Annotated[list[Name], Field(min_length=1)]
    sign: Sign
    note: Text = ""


class TablesSpec(_Table):
    ratios: list[tuple[Name, Name]] = None
    transmissions: list[Name] = None
    #: a name of the reaction = [i, j]: the force of link i on link j
    reactions: dict[str, tuple[Name, Name]] = None
    #: report column symbol → the model's symbol (e.g. F_S = "Fgc")
    symbols: dict[str, Name] = None
    formulas: list[FormulaSpec] = None
    signs: list[SignSpec] = None
    #: angle columns: "continuous" along the positions, or "wrapped" to [0°, 360°)
    angles: typing.Literal["continuous", "wrapped"] = None
    #: analogs of a crank angle: with respect to the "coordinate", or along the direction
    #: of "rotation" of its [motion] (dφ/dφ1 · sign φ1')
    analogs: typing.Literal["coordinate", "rotation"] = None
    #: links whose loads every lift capacity carries (seed 001 lab 1 eq. 14: the boom)
    dead_loads: list[Name] = None
    #: second-order analogs (ddphi, dd<distance>, dU) in table 3.1
    second_order: StrictBool = None
    #: how the report numbers its tables: "report" (1, 2, … in the report's order, the
    #: default) or "seed" (the seed worksheet's numbers 2.1 … 6.1: the seed-003 hitch)
    numbering: typing.Literal["report", "seed"] = None


class PlotSpec(_Table):
    """One plot the page shows first: ``y`` (one or more columns of one table, the first
    solid, the others dashed) over ``x`` (a column of the same table; default: the
    coordinate)."""
    y: Annotated[list[Name], Field(min_length=1, max_length=8)]
    x: Name = None


class DisplaySpec(_Table):
    """``[display]``: how the model's results are shown (:mod:`assur.core.display`)."""
    #: the unit system: "file" (each kind in the unit the file writes it in),
    #: "engineering", "si" or "imperial"
    units: typing.Literal["file", "engineering", "si", "imperial"] = None
    #: the language of reports and pages: "en" or "ru"
    lang: typing.Literal["en", "ru"] = None
    #: the plots the page shows first (before those it chooses from the tables' content)
    plots: Annotated[list[PlotSpec], Field(max_length=16)] = None


class SolveSpec(_Table):
    unknown: Name
    bracket: tuple[Value, Value]
    at: dict[str, Value]
    quantity: Name
    equals: Value


class FileSpec(_Table):
    model: ModelSection
    params: dict[str, Value] = {}
    range: dict[str, RangeSpec]
    frame: Annotated[dict[str, FramePoint], Field(min_length=1)]
    groups: list[dict[str, Any]] = []
    links: dict[str, tuple[Name, Name]] = {}
    distances: dict[str, Annotated[Any, AfterValidator(_distance)]] = {}
    loads: list[dict[str, Any]] = []
    cylinders: list[CylinderSpec] = []
    #: [[wheels]]: checked by :mod:`assur.io._wheels` (wheels drawn on links)
    wheels: list[WheelSpec] = []
    machine: Optional[MachineSpec] = None
    tables: Optional[TablesSpec] = None
    display: Optional[DisplaySpec] = None
    solve: list[SolveSpec] = []
    #: [dynamics]: checked by :mod:`assur.io._dynamics` (flywheel, counter-masses)
    dynamics: Optional[dict[str, Any]] = None
    #: [lift_test]: checked by :mod:`assur.io._lift_test` (ISO 789-2 lift test)
    lift_test: Optional[dict[str, Any]] = None
    #: [tolerances]: checked by :mod:`assur.io._tolerances` (manufacturing tolerances)
    tolerances: Optional[Any] = None
    #: [[drive]] and [simulation]: checked by :mod:`assur.io._drive` (hydraulic drive)
    drive: Optional[Any] = None
    simulation: Optional[dict[str, Any]] = None
    #: [design]: checked by :mod:`assur.io._design` (design variables and criteria)
    design: Optional[dict[str, Any]] = None
    motion: dict[str, MotionSpec] = {}
    #: [[rating]]: checked by :mod:`assur.io._ratings` (ratings of the standards)
    rating: Optional[Any] = None


def __getattr__(name):
    if name == "GROUP_TYPES":
        return group_types()
    if name == "LOAD_TYPES":
        return load_types()
    raise AttributeError(name)
