"""The value types of a model file's schema: numbers with units or parameter names,
names, texts, frame points, distances, machine terms, ±1 — each a pydantic annotation
whose check says in a file's words what was expected — and the base of every table.
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import AfterValidator, BaseModel, ConfigDict, StrictStr
from pydantic_core import PydanticCustomError

from ._schema_words import did_you_mean


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


def _shown_name(v):
    """A name shown to the reader: a non-empty string, or ``{ en = "…", ru = "…" }``
    (the English name, or the first given, identifies it; reports show the
    language's)."""
    from ..texts import text

    if isinstance(v, dict):
        t = text(_text(v))
        if not all(x.strip() for x in v.values()):
            raise PydanticCustomError("name", "expected a non-empty name in every language")
        return t
    if not isinstance(v, str):
        raise PydanticCustomError("name", 'expected a name: a string, or a table of languages '
                                          'such as { en = "arm 34", ru = "плечо 34" }')
    return _name(v)


#: a group's name: a string, or a table of languages (a :class:`assur.texts.Text`)
ShownName = Annotated[Any, AfterValidator(_shown_name)]


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
