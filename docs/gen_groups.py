"""Regenerate the group-types table of docs/model-format.md from the group registry.

    python docs/gen_groups.py          # rewrite the table in place
    python docs/gen_groups.py --check  # exit 1 if the docs are out of date

The table is :func:`assur.io.schema_table` between the markers
``assur.io._schema.TABLE_BEGIN`` and ``TABLE_END``; tests/test_io_groups.py checks
that the docs hold exactly that table.
"""

from __future__ import annotations

import pathlib
import sys

from assur.io import _schema

DOC = pathlib.Path(__file__).with_name("model-format.md")


def render(text: str) -> str:
    """``text`` with the block between the markers replaced by the generated table."""
    head, sep, rest = text.partition(_schema.TABLE_BEGIN + "\n")
    if not sep or _schema.TABLE_END not in rest:
        raise SystemExit(f"{DOC}: the markers of the group-types table are missing")
    tail = rest[rest.index(_schema.TABLE_END):]
    return head + sep + _schema.schema_table() + tail


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
