"""Model files: a mechanism, its range and its design conditions in TOML.

A model file describes one machine — frame points, structural groups with their
branches, named links, loads, cylinders, machine data, the range of the
generalized coordinate(s) and the ``[[solve]]`` conditions that fix unknown
parameters — in the format of ``docs/model-format.md``. :func:`load` parses and
validates it once into an immutable :class:`Model` whose ``mechanism`` is an
ordinary :class:`~assur.Mechanism` (SI units, parameters solved); everything else
(examples, tests, CLI, reports) uses that (DESIGN.md §5).

Values may carry units (``"17.5 MPa"``, ``"22 deg"``, ``"80 mm"``); they are
converted here and nowhere else (DESIGN.md §7). Every problem with a file is a
:class:`ModelFileError` naming the file, the key path and the line, what was
expected and what was found. Files are data: nothing in them is executed.

Examples
--------
>>> from assur import io
>>> model = io.load(io.bundled("hitch_003"))
>>> [round(model.mechanism.params[k], 4) for k in ("L4", "Sp", "L7")]
[0.6613, 0.4694, 0.7522]
>>> model.range.shape
(10,)
>>> io.loads('[model]\\nname = "x"\\ncoordinates = ["S"]\\n', name="x.toml")
Traceback (most recent call last):
...
assur.io.ModelFileError: x.toml:1: range: missing required key "range"
"""

from __future__ import annotations

import difflib
import re
import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from types import MappingProxyType
from typing import Mapping

import numpy as np

from ..mechanism import Mechanism
from ._build import Builder
from ._errors import ModelFileError, key_path
from ._extends import resolve as resolve_extends
from ._lines import line_index

ModelFileError.__module__ = __name__  # shown as assur.io.ModelFileError

__all__ = ["Model", "ModelFileError", "load", "loads", "bundled", "key_path"]


@dataclass(frozen=True)
class Model:
    """A loaded model file.

    Attributes
    ----------
    mechanism : Mechanism
        The mechanism with every ``[[solve]]`` unknown replaced by its root [SI].
    range : numpy.ndarray, shape (n,) for one coordinate, (n1·n2·…, k) for k
        The positions of the ``[range]`` section [m or rad], read-only. For k > 1
        coordinates it is the full grid, the first coordinate varying slowest —
        the shape :meth:`Mechanism.solve` takes for one design.
    ranges : mapping of str to numpy.ndarray, shape (n_i,)
        The positions of each coordinate on its own [m or rad].
    solved : tuple of SolvedCondition
        The ``[[solve]]`` conditions in the order solved, with roots and residuals.
    source : Path or None
        The file loaded (None for :func:`loads`).
    """

    mechanism: Mechanism
    range: np.ndarray
    ranges: Mapping[str, np.ndarray]
    solved: tuple = ()
    source: Path | None = None

    @property
    def name(self) -> str:
        return self.mechanism.name

    def __repr__(self):
        src = f", source={str(self.source)!r}" if self.source else ""
        return (f"Model({self.mechanism.name!r}, {len(self.range)} positions, "
                f"{len(self.solved)} solved{src})")


_TOML_POS = re.compile(r"\s*\(at line (\d+), column (\d+)\)\s*$")
_TOML_END = re.compile(r"\s*\(at end of document\)\s*$")


def _parse_toml(text: str, name: str) -> dict:
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        msg = str(e)
        m = _TOML_POS.search(msg)
        if m:
            line, col = int(m.group(1)), int(m.group(2))
            problem = f"TOML syntax error: {msg[:m.start()]} (column {col})"
            if "Illegal character '\\n'" in msg:
                problem += "; is a string missing its closing quote?"
        else:
            lines = text.rstrip("\n").count("\n") + 1
            line = lines
            problem = f"TOML syntax error: {_TOML_END.sub('', msg)} (at the end of the file)"
        raise ModelFileError(name, line, "", problem) from None


def loads(text: str, name: str = "<string>", *, source: Path | None = None) -> Model:
    """Load a model from the TOML ``text``.

    Parameters
    ----------
    text : str
        The model file's content.
    name : str
        How errors name the file (default ``"<string>"``).
    source : Path, optional
        The file the text was read from: an ``extends`` path is relative to its
        directory (without it, to the current directory).

    Returns
    -------
    Model

    Raises
    ------
    ModelFileError
        For any problem in the text: TOML syntax, structure, units, references,
        a mechanism that its groups cannot define, a ``[[solve]]`` condition
        without a root (or with several) in its bracket; with ``extends``, a
        missing base file or a cycle, and any problem of a key a base file gives
        (located in that file).
    """
    if not isinstance(text, str):
        raise TypeError(f"loads() takes the file's text as str, got {type(text).__name__}")
    text = text.removeprefix("\ufeff")
    data = _parse_toml(text, name)
    index = line_index(text)
    if "extends" in data:
        data, index = resolve_extends(data, index, name, source, _parse_toml)
    builder = Builder(name, data, index)
    mech, grid, axes, solved = builder.build()
    return Model(mech, grid, MappingProxyType(axes), tuple(solved), source)


def load(path) -> Model:
    """Load a model file.

    Parameters
    ----------
    path : str or os.PathLike
        A ``.toml`` model file (see ``docs/model-format.md``).

    Returns
    -------
    Model

    Raises
    ------
    ModelFileError
        For any problem in the file (see :func:`loads`); errors name the file as
        ``path`` was given.
    FileNotFoundError
        If there is no such file.
    """
    p = Path(path)
    data = p.read_bytes()
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        line = data[:e.start].count(b"\n") + 1
        raise ModelFileError(str(path), line, "", f"expected UTF-8 text, found the byte "
                                                  f"0x{data[e.start]:02x}") from None
    return loads(text, name=str(path), source=p)


def _bundled_names():
    root = resources.files("assur.models")
    return sorted(f.name[:-5] for f in root.iterdir() if f.name.endswith(".toml"))


def bundled(name: str) -> Path:
    """Path of a model file shipped with assur, e.g. ``bundled("hitch_003")``.

    Parameters
    ----------
    name : str
        File name with or without ``.toml``: ``hitch_003``, ``header_000``,
        ``header_000_fixed``.

    Raises
    ------
    ValueError
        For an unknown name (the message lists the bundled ones).
    """
    stem = name[:-5] if name.endswith(".toml") else name
    names = _bundled_names()
    if stem not in names:
        close = difflib.get_close_matches(stem, names, n=1)
        hint = f'; did you mean "{close[0]}"?' if close else ""
        raise ValueError(f"no bundled model {name!r}{hint} (bundled: {', '.join(names)})")
    return Path(str(resources.files("assur.models") / f"{stem}.toml"))
