"""The words of a model file's structural errors: a pydantic error turned into the
key path and message a user reads (what was expected, what was found, the keys
allowed, a did-you-mean), and TOML-like display of values.
"""

from __future__ import annotations

import difflib
import typing
from typing import Annotated

from pydantic import BaseModel, ValidationError


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
        if typing.get_origin(t) is typing.Union:  # a member named by pydantic's tag
            t = next((a for a in typing.get_args(t) if getattr(a, "__name__", None) == part),
                     None)
            if t is None:
                return []
            continue
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


def _union_tags(data, loc, typ="") -> list:
    """``(index, input)`` of each segment of ``loc`` that is not a key of ``data`` but the
    tag of a union's member (pydantic names each alternative it tried: ``_Within``,
    ``list[…]``), with the input the alternatives were tried on."""
    node, tags = data, []
    # the last segment is a key (missing, or not allowed) or a member's tag
    last = len(loc) - (1 if typ in ("missing", "extra_forbidden") else 0)
    for i, seg in enumerate(loc[:last]):
        if isinstance(node, dict) and seg in node:
            node = node[seg]
        elif isinstance(node, (list, tuple)) and isinstance(seg, int) and 0 <= seg < len(node):
            node = node[seg]
        elif isinstance(seg, str):
            tags.append((i, node))
        else:
            break
    return tags


def _fits(tag: str, value) -> bool:
    """True if the union member tagged ``tag`` takes a value of ``value``'s shape (a
    table for a model, an array for a list or tuple, else a plain value)."""
    if tag.startswith(("list[", "tuple[", "set[")):
        return isinstance(value, (list, tuple))
    if "[" not in tag and tag[:1].isupper() or tag.startswith("_"):
        return isinstance(value, dict)
    return not isinstance(value, (dict, list, tuple))


def validate(cls, data, prefix=()):
    """Validate ``data`` with ``cls``: ``(instance or None, [(path, message), …])``.

    Of the alternatives of a union, only the errors of those that take the value's shape
    are told (a table given where a table or an array is allowed: what is wrong with the
    table), and the path holds the file's keys only, never pydantic's names of the
    alternatives.

    Examples
    --------
    A ``[design]`` variable is ``[low, high]``, ``{ low, high }`` or ``{ within }``;
    given a table, the keys of the table it comes nearest to are told (not "expected
    an array", nor the other table's keys):

    >>> from assur.io._design import DesignSection
    >>> from assur.io._schema_words import validate
    >>> for path, message in validate(DesignSection, {"variables": {"X01": {"low": "0.5 m"}}},
    ...                               ("design",))[1]:
    ...     print(".".join(path) + ":", message)
    design.variables.X01.high: missing required key "high"
    >>> for path, message in validate(DesignSection, {"variables": {"X01": {"width": 1}}},
    ...                               ("design",))[1]:
    ...     print(".".join(path) + ":", message)
    design.variables.X01.within: missing required key "within"
    design.variables.X01.width: unknown key "width"; did you mean "within"? (allowed: within)
    """
    try:
        return cls.model_validate(data), []
    except ValidationError as e:
        errors = list(e.errors())
    out = []
    # where several alternatives of a union take the value's shape (two kinds of table),
    # the one the value comes nearest to: the fewest errors ({ low = … } is told its
    # missing "high", not the other table's missing "within")
    tried: dict = {}
    for x in errors:
        loc = tuple(x["loc"])
        tags = _union_tags(data, loc, x["type"])
        if tags and all(_fits(str(loc[i]), v) for i, v in tags):
            site = loc[:tags[0][0]]
            member = tuple(loc[i] for i, _ in tags)
            tried.setdefault(site, {}).setdefault(member, 0)
            tried[site][member] += 1
    nearest = {site: min(members, key=members.get) for site, members in tried.items()}
    for fitting in (True, False):  # no alternative of the value's shape: say them all
        for x in errors:
            loc = tuple(x["loc"])
            tags = _union_tags(data, loc, x["type"])
            if fitting and not all(_fits(str(loc[i]), v) for i, v in tags):
                continue
            if fitting and tags and nearest.get(loc[:tags[0][0]],
                                                None) != tuple(loc[i] for i, _ in tags):
                continue
            p, m = describe(x, cls)
            drop = {i for i, _ in tags}
            path = prefix + tuple(seg for i, seg in enumerate(p) if i not in drop)
            if (path, m) not in out:
                out.append((path, m))
        if out:
            break
    return None, out
