"""Line numbers of the keys of a TOML text.

:mod:`tomllib` returns plain dicts and lists without positions, so the loader
finds them itself: :func:`line_index` walks the raw text once with a small
scanner that knows just enough TOML to skip values (the four kinds of strings,
arrays, inline tables, scalars) and records, for every key and every array item,
the line where it starts. Keys are recorded as *paths*: tuples of table keys
(``str``) and array indices (``int``), e.g. ``("groups", 2, "ra")`` for the key
``ra`` of the third ``[[groups]]`` table, ``("frame", "01", 0)`` for the first
item of ``"01" = [...]`` in ``[frame]``.

The text has already been accepted by :mod:`tomllib` when this runs, so the
scanner does not validate; if it meets something it does not understand it stops
and returns what it has recorded so far (an error then falls back to the line of
the nearest enclosing key, see :func:`line_of`).
"""

from __future__ import annotations

import bisect
import re
from collections.abc import Mapping

_BARE = re.compile(r"[A-Za-z0-9_-]+")
_ESCAPES = {"b": "\b", "t": "\t", "n": "\n", "f": "\f", "r": "\r", '"': '"', "\\": "\\"}


class _Scanner:
    def __init__(self, text: str):
        self.t = text
        self.n = len(text)
        self.i = 0
        self.nl = [m.start() for m in re.finditer("\n", text)]
        self.index: dict[tuple, int] = {}
        self.aot: dict[tuple, int] = {}  # array-of-tables path -> index of its last table

    # ---- positions -------------------------------------------------------------------
    def line(self, pos=None) -> int:
        return bisect.bisect_right(self.nl, (self.i if pos is None else pos) - 1) + 1

    def record(self, path, pos=None, overwrite=True):
        if overwrite or path not in self.index:
            self.index[path] = self.line(pos)

    # ---- lexical helpers -----------------------------------------------------------
    def peek(self, k=1):
        return self.t[self.i:self.i + k]

    def skip_ws(self):
        while self.i < self.n and self.t[self.i] in " \t":
            self.i += 1

    def skip_comment(self):
        if self.peek() == "#":
            while self.i < self.n and self.t[self.i] != "\n":
                self.i += 1

    def skip_blank(self):
        """Whitespace, newlines and comments (between array items)."""
        while self.i < self.n:
            c = self.t[self.i]
            if c in " \t\r\n":
                self.i += 1
            elif c == "#":
                self.skip_comment()
            else:
                return

    def key_part(self) -> str:
        self.skip_ws()
        c = self.peek()
        if c == '"':
            return self.basic_string()
        if c == "'":
            j = self.t.index("'", self.i + 1)
            s = self.t[self.i + 1:j]
            self.i = j + 1
            return s
        m = _BARE.match(self.t, self.i)
        if not m:
            raise ValueError(f"key expected at {self.i}")
        self.i = m.end()
        return m.group()

    def key(self) -> tuple:
        parts = [self.key_part()]
        while True:
            self.skip_ws()
            if self.peek() != ".":
                return tuple(parts)
            self.i += 1
            parts.append(self.key_part())

    def basic_string(self) -> str:
        out = []
        self.i += 1
        while True:
            c = self.t[self.i]
            if c == '"':
                self.i += 1
                return "".join(out)
            if c == "\\":
                e = self.t[self.i + 1]
                if e in _ESCAPES:
                    out.append(_ESCAPES[e])
                    self.i += 2
                elif e in "uU":
                    k = 4 if e == "u" else 8
                    out.append(chr(int(self.t[self.i + 2:self.i + 2 + k], 16)))
                    self.i += 2 + k
                else:  # pragma: no cover - tomllib rejected it already
                    raise ValueError("bad escape")
                continue
            out.append(c)
            self.i += 1

    # ---- values --------------------------------------------------------------------
    def value(self, path):
        self.skip_ws()
        t, i = self.t, self.i
        if t.startswith('"""', i) or t.startswith("'''", i):
            q = t[i]
            j = i + 3
            while True:
                if q == '"' and t[j] == "\\":
                    j += 2
                    continue
                if t.startswith(q * 3, j):
                    j += 3
                    extra = 0
                    while extra < 2 and j < self.n and t[j] == q:
                        j += 1
                        extra += 1
                    break
                j += 1
            self.i = j
        elif t[i] == '"':
            self.basic_string()
        elif t[i] == "'":
            self.i = t.index("'", i + 1) + 1
        elif t[i] == "[":
            self.i += 1
            k = 0
            while True:
                self.skip_blank()
                if self.peek() == "]":
                    self.i += 1
                    return
                self.record(path + (k,))
                self.value(path + (k,))
                k += 1
                self.skip_blank()
                if self.peek() == ",":
                    self.i += 1
                elif self.peek() == "]":
                    self.i += 1
                    return
                else:
                    raise ValueError("array")
        elif t[i] == "{":
            self.i += 1
            while True:
                self.skip_blank()
                if self.peek() == "}":
                    self.i += 1
                    return
                start = self.i
                k = self.key()
                for d in range(1, len(k)):
                    self.record(path + k[:d], start, overwrite=False)
                self.record(path + k, start)
                self.skip_ws()
                if self.peek() != "=":
                    raise ValueError("inline table")
                self.i += 1
                self.value(path + k)
                self.skip_blank()
                if self.peek() == ",":
                    self.i += 1
        else:  # number, boolean, date-time
            while self.i < self.n and self.t[self.i] not in ",]}#\n":
                self.i += 1

    # ---- document ------------------------------------------------------------------
    def resolve(self, keys) -> tuple:
        """Path of a header's keys, with the current index of every array of tables."""
        path: tuple = ()
        for k in keys:
            path += (k,)
            if path in self.aot:
                path += (self.aot[path],)
        return path

    def document(self):
        current: tuple = ()
        while True:
            self.skip_blank()
            if self.i >= self.n:
                return
            start = self.i
            if self.t.startswith("[[", self.i):
                self.i += 2
                keys = self.key()
                base = self.resolve(keys[:-1]) + (keys[-1],)
                self.aot[base] = self.aot.get(base, -1) + 1
                current = base + (self.aot[base],)
                self.record(base, start, overwrite=False)
                self.record(current, start)
                self.i = self.t.index("]]", self.i) + 2
            elif self.peek() == "[":
                self.i += 1
                keys = self.key()
                current = self.resolve(keys)
                self.record(current, start)
                self.i = self.t.index("]", self.i) + 1
            else:
                k = self.key()
                for d in range(1, len(k)):
                    self.record(current + k[:d], start, overwrite=False)
                self.record(current + k, start)
                self.skip_ws()
                if self.peek() != "=":
                    raise ValueError("key/value")
                self.i += 1
                self.value(current + k)
            self.skip_ws()
            self.skip_comment()


def line_index(text: str) -> dict[tuple, int]:
    """Map every key path of a TOML ``text`` to the line (1-based) where it starts.

    Parameters
    ----------
    text : str
        A TOML document already accepted by :func:`tomllib.loads`.

    Returns
    -------
    dict of tuple to int
        ``("groups", 2)`` → line of the third ``[[groups]]`` header,
        ``("groups", 2, "ra")`` → line of its key ``ra``, ``("links", "3", 1)`` →
        line of the second item of the array ``links."3"``.

    Examples
    --------
    >>> idx = line_index('[model]\\nname = "x"\\n\\n[[groups]]\\nra = "L4"\\n')
    >>> idx[("model", "name")], idx[("groups", 0)], idx[("groups", 0, "ra")]
    (2, 4, 5)
    """
    s = _Scanner(text)
    try:
        s.document()
    except (ValueError, IndexError):  # not expected after tomllib: keep what we have
        pass
    return s.index


class LazyIndex(Mapping):
    """The :func:`line_index` of a text, scanned when a line is first asked for: a file
    that loads without an error (the page's every answer) never pays for the scan.

    Examples
    --------
    >>> idx = LazyIndex('[model]\\nname = "x"\\n')
    >>> idx.scanned, idx[("model", "name")], idx.scanned
    (False, 2, True)
    """

    def __init__(self, text: str):
        self._text = text
        self._index = None

    @property
    def scanned(self) -> bool:
        """True once the text has been scanned."""
        return self._index is not None

    def _scan(self) -> dict:
        if self._index is None:
            self._index = line_index(self._text)
        return self._index

    def __getitem__(self, path):
        return self._scan()[path]

    def __contains__(self, path):
        return path in self._scan()

    def __iter__(self):
        return iter(self._scan())

    def __len__(self):
        return len(self._scan())


def line_of(index: dict[tuple, int], path) -> int:
    """Line of ``path``, or of its nearest recorded parent (a missing key is reported
    at the line of the table that lacks it); 1 when nothing matches."""
    path = tuple(path)
    while path:
        if path in index:
            return index[path]
        path = path[:-1]
    return 1
