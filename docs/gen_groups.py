"""Regenerate the generated tables of docs/model-format.md from the registries: the
group types (``[[groups]]``) and the load types (``[[loads]]``).

    python docs/gen_groups.py          # rewrite the tables in place
    python docs/gen_groups.py --check  # exit 1 if the docs are out of date

The tables are :func:`assur.io.schema_table` between the markers
``assur.io._schema.TABLE_BEGIN`` and ``TABLE_END``, and
:func:`assur.io.load_types_table` between ``LOAD_TABLE_BEGIN`` and ``LOAD_TABLE_END``;
tests/io/test_schema.py and tests/core/test_loads_registry.py check that the docs hold
exactly those tables.
"""

from __future__ import annotations

import pathlib
import sys

from assur.io import _schema

DOC = pathlib.Path(__file__).with_name("model-format.md")

#: (what, begin marker, end marker, the table) of each generated block
TABLES = [
    ("group-types", _schema.TABLE_BEGIN, _schema.TABLE_END, _schema.schema_table),
    ("load-types", _schema.LOAD_TABLE_BEGIN, _schema.LOAD_TABLE_END, _schema.load_types_table),
]


def replace(text: str, what: str, begin: str, end: str, table: str) -> str:
    """``text`` with the block between the markers ``begin`` and ``end`` replaced by
    ``table``."""
    head, sep, rest = text.partition(begin + "\n")
    if not sep or end not in rest:
        raise SystemExit(f"{DOC}: the markers of the {what} table are missing")
    tail = rest[rest.index(end):]
    return head + sep + table + tail


def render(text: str) -> str:
    """``text`` with every generated block replaced by its table."""
    for what, begin, end, make in TABLES:
        text = replace(text, what, begin, end, make())
    return text


def main(argv) -> int:
    text = DOC.read_text(encoding="utf-8")
    new = render(text)
    if "--check" in argv:
        if new != text:
            print(f"{DOC} is out of date: run python docs/gen_groups.py", file=sys.stderr)
            return 1
        return 0
    if new != text:
        DOC.write_text(new, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
