"""The one error a model file can raise: :class:`ModelFileError`."""

from __future__ import annotations

import re

from ..errors import ModelError

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def key_path(path) -> str:
    """``("groups", 2, "ra")`` → ``"groups[2].ra"``; keys that are not bare TOML keys
    are quoted: ``("reactions", "R 5")`` → ``'reactions."R 5"'``.

    Examples
    --------
    >>> from assur.io import key_path
    >>> key_path(("groups", 2, "ra"))
    'groups[2].ra'
    >>> key_path(("reactions", "R 5"))
    'reactions."R 5"'
    """
    out = ""
    for part in path:
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            key = part if _BARE.match(part) else '"' + part.replace('"', '\\"') + '"'
            out += ("." if out else "") + key
    return out


class ModelFileError(ModelError):
    """A model file is malformed: the file, the key path and the line, what was
    expected and what was found.

    The message reads ``<file>:<line>: <key path>: <problem>``, e.g.
    ``hitch_003.toml:57: groups[2].ra: expected a length (e.g. "0.48 m"), found "22 deg"``.

    Attributes
    ----------
    file : str
        The file as it was given to :func:`assur.io.load` (or the ``name`` given to
        :func:`assur.io.loads`).
    key_path : str
        Where in the file: ``groups[2].ra``, ``params.L4``, ``solve[0]`` (array
        indices from 0); ``""`` for a TOML syntax error.
    line : int
        Line of that key in the file (1-based); for a missing key, the line of the
        table that lacks it.
    problem : str
        The message without the location.

    Examples
    --------
    >>> from assur import io
    >>> e = io.ModelFileError("hitch_003.toml", 57, "groups[2].ra",
    ...                       'expected a length (e.g. "0.48 m"), found "22 deg"')
    >>> print(e)
    hitch_003.toml:57: groups[2].ra: expected a length (e.g. "0.48 m"), found "22 deg"
    >>> try:
    ...     io.loads('[model]\\nname = "x"\\ncoordinates = ["S"]\\n', name="x.toml")
    ... except io.ModelFileError as err:
    ...     print(err.file, err.line, err.key_path, "|", err.problem)
    x.toml 1 range | missing required key "range"
    """

    def __init__(self, file: str, line: int, key_path: str, problem: str):
        self.file = file
        self.line = line
        self.key_path = key_path
        self.problem = problem
        where = f"{file}:{line}: " + (f"{key_path}: " if key_path else "")
        super().__init__(where + problem)

    def __reduce__(self):  # picklable (process pools, pytest-xdist)
        return (type(self), (self.file, self.line, self.key_path, self.problem))
