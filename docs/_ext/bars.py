"""Absolute values in docstrings: ``|A–B|`` means a distance, not a reST
substitution, and ``(*shape, n)`` unpacks a shape, not emphasis. Escape those bars
and stars of prose lines before docutils reads them; leave tables, literal blocks,
doctests and inline literals alone."""

from __future__ import annotations

import re

_LITERAL = re.compile(r"(``.*?``|`[^`]*`)")
#: a star that unpacks, "(*shape, n)": not the start of emphasis
_STAR = re.compile(r"([(\[,] ?)\*(?=\w)")


def _indent(line: str) -> int:
    return len(line) - len(line.lstrip())


def _escape_prose(line: str) -> str:
    parts = _LITERAL.split(line)
    return "".join(p if i % 2 else _STAR.sub(r"\1\\*", re.sub(r"(?<!\\)\|", r"\\|", p))
                   for i, p in enumerate(parts))


def escape(lines: list[str]) -> list[str]:
    """The docstring's lines with the bars of prose escaped (in place and returned)."""
    out = []
    literal_at = None  # indentation of the paragraph that opened a literal block
    doctest = False
    for line in lines:
        s = line.strip()
        if literal_at is not None:
            if s and _indent(line) <= literal_at:
                literal_at = None
            else:
                out.append(line)
                continue
        if doctest:
            if not s:
                doctest = False
            out.append(line)
            continue
        if s.startswith(">>>"):
            doctest = True
            out.append(line)
            continue
        # "| " opens a grid-table row or a line block; "+" a table border
        if (s.startswith(("| ", "+", "..")) or s == "|"
                or re.match(r"^[=\-+ ]+$", s or "x")):
            out.append(line)
        else:
            out.append(_escape_prose(line))
        if s.endswith("::"):
            literal_at = _indent(line)
    lines[:] = out
    return lines


def process(app, what, name, obj, options, lines):
    escape(lines)


def setup(app):
    app.connect("autodoc-process-docstring", process, priority=900)
    return {"parallel_read_safe": True}
