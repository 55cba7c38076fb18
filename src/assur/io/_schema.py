"""The structure of a model file, as pydantic models.

This layer checks the *shape* of the file: which tables and keys exist, which
are required, the TOML type of every value (string, integer, array, table),
and refuses unknown keys. What the values *mean* — units and their dimensions,
references to parameters, points and links — is checked when the mechanism is
built (:mod:`assur.io._build`), where the context is known.

Groups and loads are tables with a ``type`` key; each type has its own model,
picked from :func:`group_types` / :data:`LOAD_TYPES` (an unknown type is an error
listing the valid ones). The group models are not written here: they derive from
the fields of the registered group types (:mod:`assur.groups`).
"""

from __future__ import annotations

import difflib
import typing
from typing import Annotated, Any, Optional

from pydantic import AfterValidator, BaseModel, ConfigDict, Field, StrictBool, StrictInt, \
    StrictStr, ValidationError, create_model, model_validator
from pydantic_core import PydanticCustomError


def _value(v):
    if isinstance(v, bool) or not isinstance(v, (int, float, str)):
        raise PydanticCustomError(
            "value", 'expected a number or a string (a value with its unit such as "0.48 m", '
                     'or a parameter name)')
    return v


def _name(v):
    if not v.strip():
        raise PydanticCustomError("name", "expected a non-empty name")
    return v


def _branch(v):
    if isinstance(v, bool) or not isinstance(v, int) or v not in (1, -1):
        raise PydanticCustomError(
            "branch", "expected 1 or -1 (the assembly mode: the side of the directed line "
                      "between the outer joints, see docs/model-format.md)")
    return v


def _sign(v):
    if isinstance(v, bool) or not isinstance(v, int) or v not in (1, -1):
        raise PydanticCustomError("sign", "expected 1 or -1 (the printed columns are sign × "
                                          "assur's values)")
    return v


#: a number, or a string: a value with its unit or a parameter name
Value = Annotated[Any, AfterValidator(_value)]

#: the languages a text may be given in (:mod:`assur.texts`)
_LANGS = ("en", "ru")


def _text(v):
    if isinstance(v, str):
        return v
    if isinstance(v, dict):
        bad = [k for k in v if k not in _LANGS]
        if bad or not v or not all(isinstance(x, str) for x in v.values()):
            raise PydanticCustomError(
                "text", "expected a text: a string, or a table of languages such as "
                        '{ en = "…", ru = "…" } (languages: en, ru)')
        return dict(v)
    raise PydanticCustomError("text", 'expected a text: a string, or a table of languages '
                                      'such as { en = "…", ru = "…" }')


#: user text: a string or ``{ en = "…", ru = "…" }`` (:func:`assur.texts.text`)
Text = Annotated[Any, AfterValidator(_text)]


def _terms(v):
    if isinstance(v, list):
        if not v:
            raise PydanticCustomError("terms", "expected at least one term")
        return [_value(x) for x in v]
    return _value(v)


_FRAME_KEYS = ("origin", "length", "angle")


def _frame_point(v):
    """A frame point: ``[x, y]``, or ``{ origin = "O1", length = …, angle = … }``."""
    if isinstance(v, dict):
        unknown = [k for k in v if k not in _FRAME_KEYS]
        if unknown:
            raise PydanticCustomError(
                "frame", 'unknown key "{k}"{hint} in a polar frame point (allowed: origin, '
                         'length, angle)', {"k": unknown[0], "hint": did_you_mean(
                             unknown[0], _FRAME_KEYS)})
        missing = [k for k in _FRAME_KEYS if k not in v]
        if missing:
            raise PydanticCustomError("frame", "a polar frame point needs origin, length and "
                                               "angle; missing {m}", {"m": ", ".join(missing)})
        if not isinstance(v["origin"], str) or not v["origin"].strip():
            raise PydanticCustomError("frame", "origin: expected the name of a frame point")
        return {"origin": v["origin"], "length": _value(v["length"]),
                "angle": _value(v["angle"])}
    if isinstance(v, list) and len(v) == 2:
        return (_value(v[0]), _value(v[1]))
    raise PydanticCustomError(
        "frame", 'expected [x, y] (two lengths) or { origin = "<frame point>", length = …, '
                 'angle = … }')


def _distance(v):
    """A named distance: ``[a, b]``, or ``{ a = …, b = …, angle = "<name>" }`` naming
    its direction a → b too."""
    if isinstance(v, dict):
        unknown = [k for k in v if k not in ("a", "b", "angle")]
        if unknown:
            raise PydanticCustomError("distance", 'unknown key "{k}" in a distance (allowed: '
                                                  "a, b, angle)", {"k": unknown[0]})
        if not all(isinstance(v.get(k), str) and v[k].strip() for k in ("a", "b")):
            raise PydanticCustomError("distance", "a distance needs a and b, the names of two "
                                                  "points")
        ang = v.get("angle")
        if ang is not None and not (isinstance(ang, str) and ang.strip()):
            raise PydanticCustomError("distance", "angle: expected a name for the direction "
                                                  "a → b")
        return (v["a"], v["b"], ang)
    if (isinstance(v, list) and len(v) == 2 and all(isinstance(x, str) and x.strip()
                                                   for x in v)):
        return (v[0], v[1], None)
    raise PydanticCustomError("distance", 'expected ["a", "b"] (two points) or '
                                          '{ a = "…", b = "…", angle = "<name>" }')


#: a frame point: [x, y] or a polar table (origin, length, angle)
FramePoint = Annotated[Any, AfterValidator(_frame_point)]


#: a machine position or weight: a value, a parameter name with an optional leading
#: "-", or a list of such terms that are added (e.g. ["-a", "-L"] for −(a + L))
Terms = Annotated[Any, AfterValidator(_terms)]
Name = Annotated[StrictStr, AfterValidator(_name)]
Branch = Annotated[Any, AfterValidator(_branch)]
Sign = Annotated[Any, AfterValidator(_sign)]


class _Table(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, populate_by_name=False)


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

    @model_validator(mode="after")
    def _one_form(self):
        given = self.model_fields_set
        forms = "values = [...], or from, to and count, or from, to and step"
        if "values" in given:
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


# ---- [[groups]] ---------------------------------------------------------------------
class _Group(_Table):
    type: StrictStr
    name: Name
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


def group_types() -> dict[str, type[_Group]]:
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
        _SPECS.update(key=key, specs={n: group_spec(c) for n, c in types.items()})
    return _SPECS["specs"]


#: markers of the generated group-types table in ``docs/model-format.md``
TABLE_BEGIN = ("<!-- BEGIN group types: generated from the registry by assur.io.schema_table() "
               "(python docs/gen_groups.py); do not edit -->")
TABLE_END = "<!-- END group types -->"


def _cell(text: str) -> str:
    return str(text).replace("|", "\\|")


def _default(v) -> str:
    if isinstance(v, float) and v.is_integer():
        return str(int(v))
    return str(v)


def _key(cls, f) -> str:
    """One key of the docs table: name (what it holds, unit, default): doc."""
    if f.role == "point":
        what = "point it adds" if f.name in cls.out_fields else "point"
    elif f.role == "line":
        what = "two points"
    elif f.role == "value":
        what = f.quantity + (" > 0" if f.flag == "positive" else "")
        what += " or a coordinate" if f.coordinate_ok else ""
    elif f.role == "coordinate":
        what = f"{f.quantity} coordinate"
    elif f.role == "position":
        what = "position"
    else:
        what = "1 or -1"
    if not f.required:
        what += ", *optional*" + ("" if f.default is None else f", {_default(f.default)}")
    return f"`{f.name}` ({what})" + (f": {f.doc}" if f.doc else "")


def schema_table() -> str:
    """The Markdown table of the ``[[groups]]`` types of ``docs/model-format.md``,
    generated from the registry: type, kind, keys (what each holds, its quantity and
    unit, its default, its description) and the links the group adds.

    Examples
    --------
    >>> from assur.io import schema_table
    >>> rows = schema_table().splitlines()
    >>> rows[0]
    '| type | kind | keys | links |'
    >>> [row.split(" | ")[0] for row in rows[2:4]]        # the first registered group types
    ['| `cylinder_lever`', '| `dyad`']
    >>> rows[3].split(" | ")[-1]                          # the links a dyad adds
    '[link at a, link at b] |'
    """
    from ..groups import group_type
    rows = ["| type | kind | keys | links |", "|---|---|---|---|"]
    for name in group_types():
        cls = group_type(name)
        keys = "; ".join(_key(cls, f) for f in cls.fields)
        links = ("[carrier], *optional*" if cls.link_roles is None else
                 "[" + ", ".join(cls.link_roles) + "]")
        rows.append(f"| `{name}` | {_cell(cls.kind)} | {_cell(keys)} | {_cell(links)} |")
    return "\n".join(rows) + "\n"


def __getattr__(name):
    if name == "GROUP_TYPES":
        return group_types()
    raise AttributeError(name)


# ---- [[loads]], [[cylinders]] ---------------------------------------------------------
class _Load(_Table):
    type: StrictStr


class WeightSpec(_Load):
    point: Name
    P: Value
    link: Optional[Name] = None
    name: Optional[Name] = None


class ForceSpec(_Load):
    point: Name
    fx: Value = 0.0
    fy: Value = 0.0
    link: Optional[Name] = None
    name: Optional[Name] = None


class MomentSpec(_Load):
    link: Name
    M: Value
    name: Optional[Name] = None


class SpringSpec(_Load):
    name: Name
    a: Name
    b: Name
    rate: Value
    free_length: Value
    preload: Value = 0.0
    links: Optional[tuple[Name, Name]] = None
    count: Value = 1


class MassSpec(_Load):
    link: Name
    m: Value
    point: Name
    J: Value = 0.0


class ResistingMomentSpec(_Load):
    link: Name
    M: Value
    travel: typing.Literal[1, -1] = 1
    coordinate: Optional[Name] = None
    name: Optional[Name] = None


LOAD_TYPES = {"weight": WeightSpec, "force": ForceSpec, "moment": MomentSpec,
              "spring": SpringSpec, "mass": MassSpec,
              "resisting_moment": ResistingMomentSpec}


class CylinderSpec(_Table):
    name: Name
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
    side: typing.Literal["piston", "rod", "auto"] = "piston"


# ---- [machine] ----------------------------------------------------------------------
class WeightItem(_Table):
    name: Name
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
    machine: Optional[MachineSpec] = None
    tables: Optional[TablesSpec] = None
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


# ---- errors ---------------------------------------------------------------------------
def _unwrap(t):
    while True:
        origin = typing.get_origin(t)
        if origin is Annotated:
            t = typing.get_args(t)[0]
        elif origin is typing.Union:
            args = [a for a in typing.get_args(t) if a is not type(None)]
            t = args[0] if len(args) == 1 else t
            if len(args) != 1:
                return t
        else:
            return t


def _field(cls, key):
    for name, f in cls.model_fields.items():
        if (f.alias or name) == key:
            return f
    return None


def allowed_keys(cls, loc) -> list[str]:
    """The keys allowed in the table at ``loc`` (a path below ``cls``)."""
    t = cls
    for part in loc:
        t = _unwrap(t)
        if isinstance(t, type) and issubclass(t, BaseModel):
            f = _field(t, part)
            if f is None:
                return []
            t = f.annotation
        elif typing.get_origin(t) in (list, tuple):
            args = typing.get_args(t)
            t = args[part] if typing.get_origin(t) is tuple and isinstance(part, int) and \
                len(args) > part and args[-1] is not Ellipsis else args[0]
        elif typing.get_origin(t) is dict:
            t = typing.get_args(t)[1]
        else:
            return []
    t = _unwrap(t)
    if isinstance(t, type) and issubclass(t, BaseModel):
        return [f.alias or n for n, f in t.model_fields.items()]
    return []


def show(v, _depth=0) -> str:
    """A value as it would be written in TOML (for "found …" in messages); long
    strings, huge integers and deep nesting are abbreviated."""
    if _depth > 3 and isinstance(v, (list, tuple, dict)):
        return "[…]" if isinstance(v, (list, tuple)) else "{ … }"
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        if len(v) > 80:
            v = v[:60] + "…" + v[-10:]
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, int) and abs(v) > 10**30:  # repr of a huge int is unreadable (or fails)
        return f"an integer of about {int(abs(v).bit_length() * 0.30103) + 1} digits"
    if isinstance(v, (int, float)):
        return repr(v)
    if isinstance(v, (list, tuple)):
        inner = ", ".join(show(x, _depth + 1) for x in v[:4]) + (", …" if len(v) > 4 else "")
        return f"[{inner}]"
    if isinstance(v, dict):
        inner = ", ".join(f"{k} = {show(x, _depth + 1)}" for k, x in list(v.items())[:3])
        return "{ " + inner + (", …" if len(v) > 3 else "") + " }"
    return type(v).__name__


def did_you_mean(word, choices) -> str:
    """``'; did you mean "x"?'`` for the closest choices, or ``""``."""
    close = difflib.get_close_matches(str(word), [str(c) for c in choices], n=2, cutoff=0.6)
    if not close:
        return ""
    return "; did you mean " + " or ".join(f'"{c}"' for c in close) + "?"


_EXPECT = {
    "string_type": "expected a string",
    "int_type": "expected an integer",
    "float_type": "expected a number",
    "list_type": "expected an array",
    "tuple_type": "expected an array",
    "dict_type": "expected a table",
    "model_type": "expected a table",
    "model_attributes_type": "expected a table",
}


def describe(err, cls) -> tuple[tuple, str]:
    """(path, message) of one pydantic error, in the words of a model file."""
    loc = tuple(err["loc"])
    typ = err["type"]
    inp = err.get("input")
    ctx = err.get("ctx") or {}
    if typ == "missing":
        if isinstance(loc[-1], int):  # a fixed-length array that is too short
            return loc[:-1], f"expected at least {loc[-1] + 1} items, found {show(inp)}"
        return loc, f'missing required key "{loc[-1]}"'
    if typ == "extra_forbidden":
        allowed = allowed_keys(cls, loc[:-1])
        hint = did_you_mean(loc[-1], allowed)
        return loc, (f'unknown key "{loc[-1]}"{hint} (allowed: {", ".join(allowed)})'
                     if allowed else f'unknown key "{loc[-1]}"{hint}')
    if typ in _EXPECT:
        text = _EXPECT[typ]
    elif typ == "literal_error":
        text = f"expected one of {ctx.get('expected')}"
    elif typ == "greater_than_equal":
        text = f"expected an integer ≥ {ctx.get('ge')}"
    elif typ in ("too_short", "too_long"):
        what = "item" if ctx.get("min_length", ctx.get("max_length")) == 1 else "items"
        if typ == "too_short":
            text = f"expected at least {ctx.get('min_length')} {what}"
        else:
            text = f"expected at most {ctx.get('max_length')} {what}"
        if isinstance(inp, dict) and not inp:
            return loc, text + ", found an empty table"
    else:
        text = err["msg"]
        if text.startswith("Input should be "):
            text = "expected " + text[len("Input should be "):]
        elif text.startswith("Value error, "):
            text = text[len("Value error, "):]
    return loc, f"{text}, found {show(inp)}"


def validate(cls, data, prefix=()):
    """Validate ``data`` with ``cls``: ``(instance or None, [(path, message), …])``."""
    try:
        return cls.model_validate(data), []
    except ValidationError as e:
        return None, [(prefix + p, m) for p, m in (describe(x, cls) for x in e.errors())]
