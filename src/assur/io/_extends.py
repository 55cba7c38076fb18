"""``extends = "base.toml"``: a model file as a few overrides of another.

A file with a top-level ``extends`` key is its base file (a path relative to the
extending file; the base may extend another) with the extending file's tables
merged over it:

* a table (``[params]``, ``[model]``, an inline table) is merged key by key; a key
  of the extending file replaces the base's;
* an array of tables (``[[groups]]``, ``[[loads]]``, ``[[cylinders]]``,
  ``[[solve]]``, ``[[tables.formulas]]``, the ``weights`` of ``[machine]`` …) is
  merged entry by entry: an entry whose ``name`` (``unknown`` for ``[[solve]]``)
  is that of a base entry is merged into it key by key — or replaces it whole
  when it gives a ``type`` (a complete ``[[groups]]`` or ``[[loads]]`` entry) —
  and any other entry is appended after the base's;
* any other value, arrays of values included (``notes``, ``coordinates``, a frame
  point's ``[x, y]``), replaces the base's; so does a coordinate's ``[range]`` entry
  and a ``[motion]`` speed table (one value in one of several forms).

Every key keeps its location: the merged line index maps each key path to the
line of the file the key came from, as a :class:`Line` (an ``int`` that knows its
file), so an error in a key of the base file names the base file and its line.
A missing base file, one that is not UTF-8 or not TOML, and a cycle of
``extends`` are errors at the ``extends`` key of the file that names it.
"""

from __future__ import annotations

import os
from pathlib import Path

from ..errors import ModelError
from ._errors import ModelFileError
from ._lines import line_index, line_of

#: the key an entry of an array of tables is matched by, per array (default "name")
MATCH_KEYS = {("solve",): "unknown"}


class Line(int):
    """A line number (1-based) that also names its file."""

    file: str

    def __new__(cls, line: int, file: str):
        obj = super().__new__(cls, int(line))
        obj.file = file
        return obj

    def __reduce__(self):
        return (Line, (int(self), self.file))


def _located(index: dict, file: str) -> dict:
    return {p: (v if isinstance(v, Line) else Line(v, file)) for p, v in index.items()}


class _Source:
    """One parsed file: its data, located line index and file name."""

    def __init__(self, data, index, file):
        self.data = data
        self.index = index
        self.file = file

    def loc(self, path):
        line = line_of(self.index, path)
        return line if isinstance(line, Line) else Line(line, self.file)


def _record(value, src: _Source, spath, mpath, out):
    """Record the location of ``value`` (from ``src`` at ``spath``) and of everything
    inside it under the merged path ``mpath``."""
    out[mpath] = src.loc(spath)
    if isinstance(value, dict):
        for k, v in value.items():
            _record(v, src, spath + (k,), mpath + (k,), out)
    elif isinstance(value, list):
        for i, v in enumerate(value):
            _record(v, src, spath + (i,), mpath + (i,), out)


def _is_table_array(v) -> bool:
    return isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v)


def _whole(mpath) -> bool:
    """Inline tables that are one value in one of several forms, replaced whole: a
    coordinate's ``[range]`` (values, or from/to/count, or from/to/step) and the
    ω(t) table of a ``[motion]`` speed."""
    return ((len(mpath) == 2 and mpath[0] == "range")
            or (len(mpath) == 3 and mpath[0] == "motion" and mpath[2] == "speed")
            # a list of texts replaces the base's, also when its texts are tables of
            # languages ({ en = "…", ru = "…" }, which look like an array of tables)
            or (bool(mpath) and mpath[-1] in ("notes", "flags")))


def _merge(base, bsrc, bpath, child, csrc, cpath, mpath, out):
    """Merge ``child`` over ``base``; record locations under ``mpath``."""
    if isinstance(base, dict) and isinstance(child, dict) and not _whole(mpath):
        merged = {}
        for k, bv in base.items():
            if k in child:
                merged[k] = _merge(bv, bsrc, bpath + (k,), child[k], csrc, cpath + (k,),
                                   mpath + (k,), out)
            else:
                merged[k] = bv
                _record(bv, bsrc, bpath + (k,), mpath + (k,), out)
        for k, cv in child.items():
            if k not in base:
                merged[k] = cv
                _record(cv, csrc, cpath + (k,), mpath + (k,), out)
        out[mpath] = csrc.loc(cpath)
        return merged
    if _is_table_array(base) and _is_table_array(child) and not _whole(mpath):
        key = MATCH_KEYS.get(mpath, "name")
        merged = []
        where = {}  # match value -> merged index
        for i, bv in enumerate(base):
            name = bv.get(key)
            if isinstance(name, str) and name not in where:
                where[name] = len(merged)
            merged.append(bv)
            _record(bv, bsrc, bpath + (i,), mpath + (len(merged) - 1,), out)
        for j, cv in enumerate(child):
            name = cv.get(key)
            k = where.get(name) if isinstance(name, str) else None
            if k is None:
                merged.append(cv)
                _record(cv, csrc, cpath + (j,), mpath + (len(merged) - 1,), out)
                continue
            bi = next(i for i, bv in enumerate(base) if bv.get(key) == name)
            if "type" in cv:
                # an entry with its type is complete: it replaces the base's whole
                for p in [p for p in out if p[:len(mpath) + 1] == mpath + (k,)]:
                    del out[p]
                merged[k] = cv
                _record(cv, csrc, cpath + (j,), mpath + (k,), out)
            else:
                merged[k] = _merge(merged[k], bsrc, bpath + (bi,), cv, csrc, cpath + (j,),
                                   mpath + (k,), out)
        out[mpath] = csrc.loc(cpath)
        return merged
    # a value, or an array of values: the child's replaces the base's
    for p in [p for p in out if p[:len(mpath)] == mpath]:
        del out[p]
    _record(child, csrc, cpath, mpath, out)
    return child


def _read(path: Path, shown: str, parse, fail):
    """The parsed base file and its text: a regular file of at most the model files'
    size (:func:`assur.io.read_model_bytes`; a FIFO, a directory or a larger file is
    ``fail``'s message at the ``extends`` key)."""
    from . import read_model_bytes
    try:
        data = read_model_bytes(path, shown, what="base model file (.toml)")
    except ModelError as e:
        raise fail(f"the base file {e}") from None
    try:
        text = data.decode("utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError as e:
        line = data[:e.start].count(b"\n") + 1
        raise ModelFileError(shown, line, "", f"expected UTF-8 text, found the byte "
                                              f"0x{data[e.start]:02x}") from None
    return parse(text, shown), text


def resolve(data: dict, index: dict, name: str, source: Path | None, parse,
            chain: tuple = ()) -> tuple[dict, dict]:
    """The file ``data`` (with line ``index``) merged over its ``extends`` chain.

    Parameters
    ----------
    data, index : dict
        The parsed file and its line index (:func:`assur.io._lines.line_index`).
    name : str
        How errors name the file.
    source : Path or None
        The file's path; ``extends`` is relative to its directory (to the current
        directory when None).
    parse : callable
        ``parse(text, name) -> dict``, the TOML reader that raises located errors.
    chain : tuple of Path
        The files that extend this one (resolved paths), to refuse cycles.

    Returns
    -------
    (dict, dict)
        The merged data without ``extends``, and the merged line index whose values
        are :class:`Line` objects naming the file of each key.

    Raises
    ------
    ModelFileError
        At the ``extends`` key: not a string, a missing or unreadable base file, a
        cycle; or any error of a base file, located in that file.
    """
    index = _located(index, name)
    if "extends" not in data:
        return data, index
    ext = data["extends"]
    where = Line(index.get(("extends",), 1), name)

    def fail(problem):
        return ModelFileError(name, where, "extends", problem)

    if not isinstance(ext, str) or not ext.strip():
        raise fail(f'expected the path of a base model file (e.g. "header_000.toml"), found '
                   f"{ext!r}")
    here = source.resolve() if source is not None else None
    base_dir = here.parent if here is not None else Path.cwd()
    said = ext if len(ext) <= 120 else ext[:60] + "…" + ext[-40:]   # a long path, shortened
    said = said.replace("\x00", "\\u0000")
    try:  # a symlink loop, a NUL byte, a name too long: one message at the key
        path = (base_dir / ext).resolve()
        exists = path.exists()
    except (OSError, RuntimeError, ValueError) as e:
        why = e.strerror if isinstance(e, OSError) and e.strerror else str(e)
        if isinstance(e, RuntimeError):
            why = "a loop of symbolic links"
        raise fail(f'cannot read the base file "{said}": {why}') from None
    shown = (os.path.join(os.path.dirname(name), ext) if source is not None else ext)
    chain = chain + ((here,) if here is not None else ())
    if path in chain:
        loop = " → ".join(p.name for p in chain[chain.index(path):]) + f" → {path.name}"
        raise fail(f'"{said}" extends this file again: a cycle of extends ({loop})')
    if not exists:
        raise fail(f'cannot read the base file "{said}": no such file ({path})')
    bdata, btext = _read(path, shown, parse, fail)
    bdata, bindex = resolve(bdata, line_index(btext), shown, path, parse, chain)
    child = {k: v for k, v in data.items() if k != "extends"}
    out = {}
    merged = _merge(bdata, _Source(bdata, bindex, shown), (), child, _Source(child, index, name),
                    (), (), out)
    out.pop((), None)
    return merged, out
