"""The tables of ``docs/model-format.md`` generated from the registries: the
``[[groups]]`` types (:func:`schema_table`) and the ``[[loads]]`` types
(:func:`load_types_table`), each between its markers (``python docs/gen_groups.py``
rewrites them; a test fails if the docs drift).
"""

from __future__ import annotations

from ._schema_types import group_types

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


#: markers of the generated load-types table in ``docs/model-format.md``
LOAD_TABLE_BEGIN = ("<!-- BEGIN load types: generated from the registry by "
                    "assur.io.load_types_table() (python docs/gen_groups.py); do not edit -->")
LOAD_TABLE_END = "<!-- END load types -->"

#: how a load field's role reads in the docs table
_LOAD_ROLE_WORDS = {"point": "point", "link": "link", "links": "two links", "name": "name",
                    "sign": "1 or -1", "coordinate": "coordinate"}
_FLAG_WORDS = {"nonneg": " ≥ 0", "positive": " > 0", "count": ", a whole number > 0"}


def _load_key(f) -> str:
    """One key of the load-types table: name (what it holds, default): doc."""
    if f.role == "value":
        what = f.quantity.replace("_", " ") + _FLAG_WORDS.get(f.flag, "")
    else:
        what = _LOAD_ROLE_WORDS.get(f.role, f.role)
    if not f.required:
        what += ", *optional*" + ("" if f.default is None else f", {_default(f.default)}")
    return f"`{f.name}` ({what})" + (f": {f.doc}" if f.doc else "")


def load_types_table() -> str:
    """The Markdown table of the ``[[loads]]`` types of ``docs/model-format.md``,
    generated from the registry (:func:`assur.core.loads.registry`): type, keys (what
    each holds, its quantity, its default, its description) and what the load is.

    Examples
    --------
    >>> from assur.io import load_types_table
    >>> rows = load_types_table().splitlines()
    >>> rows[0]
    '| type | keys | what it is |'
    >>> [row.split(" | ")[0] for row in rows[2:4]]        # the first registered load types
    ['| `weight`', '| `force`']
    >>> rows[2].split(" | ")[1].split("; ")[1]            # the weight's P
    '`P` (force ≥ 0): its magnitude, along gravity [N]'
    """
    from ..core.loads import registry
    rows = ["| type | keys | what it is |", "|---|---|---|"]
    for name, cls in registry().items():
        keys = "; ".join(_load_key(f) for f in cls.fields)
        rows.append(f"| `{name}` | {_cell(keys)} | {_cell(cls.summary)} |")
    return "\n".join(rows) + "\n"
