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
import os
import re
import stat
import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Mapping

import numpy as np

from ..core.mechanism import Mechanism
from ._errors import ModelFileError, key_path
from ._extends import resolve as resolve_extends
from ._lines import LazyIndex, line_index, line_of
from ._parsed import ParsedText
from ._schema import load_types_table, schema_table
from .problems import load_problem

ModelFileError.__module__ = __name__  # shown as assur.io.ModelFileError
ParsedText.__module__ = __name__

__all__ = ["Model", "ModelFileError", "load", "loads", "parse_text", "ParsedText", "bundled",
           "key_path", "schema_table", "load_types_table", "read_targets", "load_problem"]


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
    dynamics : DynamicsSpec or None
        The ``[dynamics]`` section (flywheel target, counter-masses;
        :mod:`assur.io._dynamics`, docs/crank-dynamics.md), None without one.
    lift_test : LiftTest or None
        The ``[lift_test]`` section (the standard lift test of a hitch, ISO 789-2;
        :mod:`assur.machines.hitch_lift`), None without one.
    drive : Circuit or None
        The ``[[drive]]`` components as an :class:`assur.dynamics.drive.Circuit`
        (:mod:`assur.io._drive`, docs/simulation.md), None without them.
    simulation : SimulationSpec or None
        The ``[simulation]`` section, None without one.
    design : DesignSpec or None
        The ``[design]`` section: design variables, constraints and objectives
        (:mod:`assur.io._design`, docs/design.md), None without one.
    tolerances : tuple of Tolerance
        The ``[tolerances]`` section (:mod:`assur.io._tolerances`,
        :mod:`assur.synthesis.tolerance`), empty without one.
    warnings : tuple of str
        What the file allows but probably does not mean — a parameter that nothing
        uses (``file:line: params.<name>: …``). ``assur check`` and ``assur analyze``
        print them; :func:`load` with ``warn=True`` issues them as
        :class:`assur.errors.ModelWarning`.
    paired : bool
        True when ``[range] paired = true``: the coordinates move together, position
        i of each with position i of the others (``range`` has shape (n, k)), not
        over their full grid; also for a held path.
    path : HeldPath or None
        A ``[range]`` with held coordinates (``S1 = { hold = "phi9", equals = …,
        within = […] }``): the held coordinates solved at every position of the one
        given, and the path's derivatives dq/ds, d²q/ds² (:mod:`assur.core.held`);
        None otherwise.
    ratings : tuple of Rating
        The ``[[rating]]`` tables (:mod:`assur.machines.ratings`, docs/ratings.md), in
        the file's order; empty without them. :meth:`analyze` evaluates them.

    Examples
    --------
    >>> from assur import io
    >>> model = io.load(io.bundled("hitch_003"))
    >>> model.mechanism.name, model.source.name
    ('hitch_003', 'hitch_003.toml')
    >>> [(s.condition.unknown, round(s.value, 4)) for s in model.solved]  # Find roots [m]
    [('L4', 0.6613), ('Sp', 0.4694), ('L7', 0.7522)]
    >>> round(float(model.range[0]), 3), round(float(model.range[-1]), 3)  # [range] of S [m]
    (0.42, 0.67)
    """

    mechanism: Mechanism
    range: np.ndarray
    ranges: Mapping[str, np.ndarray]
    solved: tuple = ()
    source: Path | None = None
    dynamics: object = None
    warnings: tuple = ()
    lift_test: object = None
    paired: bool = False
    drive: object = None
    simulation: object = None
    design: object = None
    tolerances: tuple = ()
    path: object = None
    ratings: tuple = ()

    @property
    def shape(self) -> tuple:
        """The positions' arrangement: ``(n,)`` for one coordinate or paired paths,
        ``(n1, n2, …)`` for the grid of k coordinates (first coordinate first).

        Examples
        --------
        >>> from assur import io
        >>> io.load(io.bundled("hitch_003")).shape     # 10 positions of S
        (10,)
        >>> model = io.load(io.bundled("loader_lab1"))
        >>> model.shape, model.range.shape             # the grid of (S, S1) and its rows
        ((13, 8), (104, 2))
        """
        if self.paired or len(self.ranges) == 1:
            return (len(self.range),)
        return tuple(len(a) for a in self.ranges.values())

    @property
    def name(self) -> str:
        """The mechanism's name (``[model] name`` of the file).

        Examples
        --------
        >>> from assur import io
        >>> io.load(io.bundled("hitch_003")).name
        'hitch_003'
        """
        return self.mechanism.name

    def analyze(self, balancing: bool = True):
        """Everything the file asks for, as ``assur analyze`` computes it: the
        :class:`~assur.analysis.Analysis` over :attr:`range` with the solved conditions
        and the file's warnings, the crank dynamics of ``[motion]``/``[dynamics]``
        (:func:`assur.analysis.add_dynamics`) and the lift test of ``[lift_test]``
        (:func:`assur.analysis.add_lift_test`).

        Along a held path (:attr:`path`) the kinematics carry it
        (``analysis.kinematics.path``: transmission numbers along the path), and a
        ``[motion]`` speed of the path's parameter moves the held coordinates with it
        (:meth:`assur.core.held.HeldPath.motion_rates`: the inertia loads along the path).

        ``balancing=False`` leaves out the counter-masses' search of ``[dynamics]`` (an
        optimization of a second or more, whose results no table holds: the page and
        the tables' exports do without it).

        Raises
        ------
        AssemblyError, ModelError, SingularPositionError

        Examples
        --------
        >>> from assur import io
        >>> a = io.load(io.bundled("hitch_003")).analyze()   # the 10 positions of [range]
        >>> [round(float(f)) for f in a.cylinder("ГЦ").force[[0, -1]]]   # Fgc, table 4.1 [N]
        [129614, 135652]
        >>> [s.condition.unknown for s in a.solved]
        ['L4', 'Sp', 'L7']
        >>> round(float(a.lift_test.hitch_force[0]))      # [lift_test] at the lowest height [N]
        29825
        >>> crank = io.load(io.bundled("cleaning_lab3"))     # [dynamics] counter-masses
        >>> crank.analyze(balancing=False).balancing is None
        True
        """
        import dataclasses

        from ..analysis import add_dynamics, add_lift_test
        rates = self.path.motion_rates(self.mechanism) if self.path is not None else None
        if rates is None:
            analysis = self.mechanism.analyze(self.range)
        else:  # a rod moving along a held path: the held coordinates follow (q̇ = q'·ṡ)
            analysis = self.mechanism.analyze(self.range, qdot=rates[0], qddot=rates[1])
            analysis.notes.append(rates[2])
        if self.path is not None:
            analysis.kinematics.path = self.path
        spec = self.dynamics
        if not balancing and spec is not None and spec.counter_masses:
            spec = dataclasses.replace(spec, counter_masses=())
        add_dynamics(analysis, spec)
        add_lift_test(analysis, self.lift_test)
        # [[rating]]: each rating over the analysis' positions (assur.machines.ratings)
        analysis.ratings = tuple(r.evaluate(self.mechanism, analysis.kinematics)
                                 for r in self.ratings)
        analysis.solved = tuple(self.solved)
        analysis.model_warnings = tuple(self.warnings)  # shown among the report's warnings
        analysis.source = self.source.name if self.source else None  # the file, not its folders
        return analysis

    def _repr_html_(self):
        """Solved conditions, drawing and tables in a notebook (:mod:`assur.views.notebook`)."""
        from ..views.notebook import model_html
        return model_html(self)

    def __repr__(self):
        src = f", source={str(self.source)!r}" if self.source else ""
        return (f"Model({self.mechanism.name!r}, {len(self.range)} positions, "
                f"{len(self.solved)} solved{src})")


_TOML_POS = re.compile(r"\s*\(at line (\d+), column (\d+)\)\s*$")
_TOML_END = re.compile(r"\s*\(at end of document\)\s*$")


#: deepest nesting of arrays, inline tables and dotted keys a model file may use (the
#: format itself needs 5: ``machine.weights[0].P[0]``)
MAX_DEPTH = 32
#: largest model file read [bytes] (64 MiB; a file of a million range values is ~10 MiB)
MAX_FILE_BYTES = 64 * 1024**2

_TOKENS = re.compile(r'"""[\s\S]*?"""|\'\'\'[\s\S]*?\'\'\'|"(?:[^"\\\n]|\\.)*"|'
                     r"'[^'\n]*'|#[^\n]*|[\[\]{}\n]")
_KEY_BEFORE = re.compile(r"""\s*("(?:[^"\\]|\\.)*"|'[^']*'|[^=\[\]{}#"']+?)\s*=\s*$""")
_LONG_INT = re.compile(r"\d[\d_]{4000,}")


def _bracket_depth_error(text: str, name: str):
    """A :class:`ModelFileError` at the first line where arrays or inline tables nest
    deeper than :data:`MAX_DEPTH`, or None (one linear pass, no recursion)."""
    depth, line, key = 0, 1, ""
    for m in _TOKENS.finditer(text):
        tok = m.group()
        if tok == "\n":
            line += 1
        elif tok in "[{":
            if depth == 0:  # the key this value belongs to, as written
                start = text.rfind("\n", 0, m.start()) + 1
                k = _KEY_BEFORE.match(text, start, m.start())
                key = k.group(1).strip() if k else ""
            depth += 1
            if depth > MAX_DEPTH:
                return ModelFileError(name, line, key, f"arrays or inline tables nested more "
                                                       f"than {MAX_DEPTH} deep")
        elif tok in "]}":
            depth = max(depth - 1, 0)
        else:
            line += tok.count("\n")
    return None


def _data_depth_error(data, name, text):
    """A :class:`ModelFileError` at the first key path deeper than :data:`MAX_DEPTH`
    (dotted keys, table headers), or None; iterative."""
    stack = [((), data)]
    while stack:
        path, v = stack.pop()
        if len(path) > MAX_DEPTH:
            where = path[:MAX_DEPTH + 1]
            return ModelFileError(name, line_of(line_index(text), where), key_path(where[:4])
                                  + ".…", f"keys nested more than {MAX_DEPTH} deep")
        if isinstance(v, dict):
            stack.extend((path + (k,), x) for k, x in v.items())
        elif isinstance(v, list):
            stack.extend((path + (i,), x) for i, x in enumerate(v))
    return None


def _parse_toml(text: str, name: str) -> dict:
    deep = _bracket_depth_error(text, name)
    if deep is not None:
        raise deep
    try:
        data = tomllib.loads(text)
    except ValueError as e:
        if isinstance(e, tomllib.TOMLDecodeError):
            raise _syntax_error(e, text, name) from None
        if "digits" not in str(e):
            raise
        # tomllib lets int() refuse integers of more than 4300 digits: one user error
        m = _LONG_INT.search(text)
        line = text.count("\n", 0, m.start()) + 1 if m else 1
        start = text.rfind("\n", 0, m.start()) + 1 if m else 0
        k = _KEY_BEFORE.match(text, start, m.start()) if m else None
        raise ModelFileError(name, line, k.group(1).strip() if k else "", "an integer with more than 4000 digits; "
                                             "expected a number of at most 1e300") from None
    except RecursionError:  # nesting that _bracket_depth_error does not see (guard)
        raise ModelFileError(name, 1, "", f"nesting deeper than {MAX_DEPTH} levels") from None
    deep = _data_depth_error(data, name, text)
    if deep is not None:
        raise deep
    return data


def _syntax_error(e, text, name):
    """The :class:`ModelFileError` of a :class:`tomllib.TOMLDecodeError`."""
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
    return ModelFileError(name, line, "", problem)




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

    Examples
    --------
    >>> from assur import io
    >>> text = io.bundled("hitch_003").read_text(encoding="utf-8")
    >>> model = io.loads(text, name="hitch_003.toml")
    >>> model.mechanism.frame_points
    ('01', '03', '05', '07')
    >>> try:
    ...     io.loads(text.replace('L5 = "0.480 m"', 'L5 = "22 deg"'), name="hitch_003.toml")
    ... except io.ModelFileError as e:
    ...     print(e.line, e.key_path)
    32 params.L5
    """
    if not isinstance(text, str):
        raise TypeError(f"loads() takes the file's text as str, got {type(text).__name__}")
    return parse_text(text, name, source=source).build()


def parse_text(text: str, name: str = "<string>", *, source: Path | None = None) -> ParsedText:
    """The first half of :func:`loads`: the TOML ``text`` parsed and its ``extends``
    resolved (:class:`ParsedText`); its :meth:`~ParsedText.build` is the model.

    Raises
    ------
    ModelFileError
        TOML syntax, nesting too deep, a base file (``extends``) missing or wrong.

    Examples
    --------
    >>> from assur import io
    >>> p = io.parse_text('[model]\\nname = "x"\\n', "x.toml")
    >>> p.data, p.name
    ({'model': {'name': 'x'}}, 'x.toml')
    """
    text = text.removeprefix("\ufeff")
    data = _parse_toml(text, name)
    index = LazyIndex(text)  # scanned only for a message's line
    if "extends" in data:
        data, index = resolve_extends(data, index, name, source, _parse_toml)
    return ParsedText(data, index, name, source)


def _warn(model: Model) -> Model:
    import warnings

    from ..errors import ModelWarning
    for w in model.warnings:
        warnings.warn(w, ModelWarning, stacklevel=3)
    return model


def load(path, *, warn: bool = False) -> Model:
    """Load a model file.

    Parameters
    ----------
    path : str or os.PathLike
        A ``.toml`` model file (see ``docs/model-format.md``).
    warn : bool
        Issue :attr:`Model.warnings` (parameters nothing uses) as
        :class:`assur.errors.ModelWarning` (default: only keep them in the model).

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
    ModelError
        If ``path`` is not a regular file (a directory, a FIFO, a device), cannot
        be read, or is larger than :data:`MAX_FILE_BYTES`.

    Examples
    --------
    >>> from assur import io
    >>> model = io.load(io.bundled("hitch_003"))   # solves its three [[solve]] conditions
    >>> [s.condition.unknown for s in model.solved]
    ['L4', 'Sp', 'L7']
    >>> round(model.mechanism.params["L4"], 6)     # [m]
    0.661283
    >>> model.range.shape                          # the [range] positions of S [m]
    (10,)
    """
    p = Path(path)
    data = read_model_bytes(p, str(path))
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        line = data[:e.start].count(b"\n") + 1
        raise ModelFileError(str(path), line, "", f"expected UTF-8 text, found the byte "
                                                  f"0x{data[e.start]:02x}") from None
    model = loads(text, name=str(path), source=p)
    return _warn(model) if warn else model


def read_model_bytes(p: Path, shown: str, what: str = "model file (.toml)",
                     limit: int | None = None) -> bytes:
    """The bytes of the model file ``p``, refusing what is not a regular file of at
    most :data:`MAX_FILE_BYTES` *before* opening it (a FIFO would block, a device
    such as ``/dev/zero`` would never end). ``what`` names the file expected in the
    messages and ``limit`` its size at most [bytes] (default :data:`MAX_FILE_BYTES`),
    for the other files a command reads (``assur fit``'s printed table).

    Raises
    ------
    FileNotFoundError
        No such file.
    ModelError
        ``"<path>: is a directory …"``, ``"<path>: not a regular file …"``,
        ``"<path>: file name too long"``, ``"<path>: … larger than 64 MiB"``.
    """
    from ..errors import ModelError
    limit = MAX_FILE_BYTES if limit is None else int(limit)
    noun = what.split(" (")[0]
    try:
        st = os.stat(p)
    except FileNotFoundError:
        raise
    except (OSError, ValueError) as e:  # name too long, NUL byte, permission: one message
        why = e.strerror if isinstance(e, OSError) and e.strerror else str(e)
        raise ModelError(f"{shown}: cannot read the {noun}: {why}") from None
    if stat.S_ISDIR(st.st_mode):
        raise ModelError(f"{shown}: is a directory; expected a {what}")
    if not stat.S_ISREG(st.st_mode):
        raise ModelError(f"{shown}: not a regular file (a FIFO, socket or device); expected "
                         f"a {what}")
    if st.st_size > limit:
        raise ModelError(f"{shown}: the file has {st.st_size / 1024**2:.1f} MiB; a {noun} "
                         f"may have at most {limit // 1024**2} MiB")
    try:
        with open(p, "rb") as f:
            data = f.read(limit + 1)
    except OSError as e:  # permission denied, I/O error: one message
        raise ModelError(f"{shown}: cannot read the {noun}: {e.strerror or e}") from None
    if len(data) > limit:  # grew while reading
        raise ModelError(f"{shown}: a {noun} may have at most {limit // 1024**2} MiB")
    return data


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

    Examples
    --------
    >>> from assur import io
    >>> io.bundled("hitch_003").name
    'hitch_003.toml'
    >>> io.bundled("hitch_03")        # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: no bundled model 'hitch_03'; did you mean "hitch_003"? (bundled: ...)
    """
    stem = name[:-5] if name.endswith(".toml") else name
    names = _bundled_names()
    if stem not in names:
        close = difflib.get_close_matches(stem, names, n=1)
        hint = f'; did you mean "{close[0]}"?' if close else ""
        raise ValueError(f"no bundled model {name!r}{hint} (bundled: {', '.join(names)})")
    return Path(str(resources.files("assur.models") / f"{stem}.toml"))


def read_targets(path, mechanism):
    """A printed table (CSV, ``quantity [unit]`` headers) as targets of
    :func:`assur.synthesis.fitting.fit_parameters`; see :mod:`assur.io._fit_table`.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> from assur import examples, io
    >>> table = "S [m],phi(6) [deg],phi(5) [deg]\\n0.420,88.5,-15.7\\n0.670,110.3,33.0\\n"
    >>> with tempfile.TemporaryDirectory() as tmp:     # two rows of seed 003 table 2.1
    ...     path = Path(tmp) / "table_2_1.csv"
    ...     _ = path.write_text(table, encoding="utf-8")
    ...     targets = io.read_targets(path, examples.hitch_003())
    >>> [(t.name, t.period) for t in targets]          # angles compared modulo 360 [deg]
    [('phi(6)', 360.0), ('phi(5)', 360.0)]
    >>> [float(v) for v in targets[0].values], [float(v) for v in targets[0].tolerance]  # [deg]
    ([88.5, 110.3], [0.05, 0.05])
    """
    from ._fit_table import read_targets as read
    return read(path, mechanism)
