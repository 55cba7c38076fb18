"""A :class:`~assur.synthesis.search.problem.Problem` from a model file with a ``[design]``
section (:mod:`assur.io._design`), plus variables given on the command line.

A problem made here carries its model's **content**, not its path: the bytes of the
file and of every file of its ``extends`` chain (:class:`ModelContent`), with the
extra variables and the positions. It pickles as that recipe, so a Dask worker on
another host — another working directory, no access to the model's folder — rebuilds
it, once per process, instead of receiving compiled kernels. Problems are cached by
the hash of that content (:attr:`ModelContent.digest`), never by path: a file edited
between two calls gives a new problem, in this process and on every worker.
"""

from __future__ import annotations

import hashlib
import os
import tempfile
import threading
import tomllib
from collections import OrderedDict
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import ModelError

__all__ = ["load_problem", "positions_of", "ModelContent", "model_content", "rebuild"]

#: problems kept per process (by content hash, variables, positions, chunk)
CACHE_SIZE = 8

_cache: OrderedDict = OrderedDict()
_lock = threading.Lock()


def positions_of(model, count=None):
    """The positions a design is checked at: the file's ``[range]``, or ``count``
    positions evenly over its span (one coordinate) [m or rad].

    Examples
    --------
    The seed-003 hitch's ten positions S = 0.420 … 0.670 m (seed §1.3), or six over
    the same span:

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.io.problems import positions_of
    >>> model = io.load(io.bundled("hitch_003"))
    >>> np.round(positions_of(model), 4).tolist()  # [m]
    [0.42, 0.4478, 0.4756, 0.5033, 0.5311, 0.5589, 0.5867, 0.6144, 0.6422, 0.67]
    >>> np.round(positions_of(model, 6), 4).tolist()  # [m]
    [0.42, 0.47, 0.52, 0.57, 0.62, 0.67]
    """
    q = np.asarray(model.range, float)
    if count is None:
        return q
    if q.ndim != 1:
        raise ModelError("[design] positions = N needs one coordinate; give the positions "
                         "with [range] for several")
    return np.linspace(q[0], q[-1], int(count))


@dataclass(frozen=True)
class ModelContent:
    """A model file's content with its ``extends`` chain: what a task carries instead
    of a path.

    Attributes
    ----------
    main : str
        The model file's path relative to the files' common folder.
    files : tuple of (str, bytes)
        Every file of the chain (the model file first): its path relative to the
        common folder and its bytes.
    shown : str
        The path as the user gave it (for messages; not part of :attr:`digest`).

    Examples
    --------
    >>> from assur import io
    >>> from assur.io.problems import model_content
    >>> c = model_content(io.bundled("hitch_003_design"))  # extends hitch_003.toml
    >>> [name for name, _ in c.files]
    ['hitch_003_design.toml', 'hitch_003.toml']
    >>> len(c.digest)  # SHA-256, hex
    64
    """

    main: str
    files: tuple
    shown: str = field(default="", compare=False)

    @property
    def digest(self) -> str:
        """SHA-256 of the files' relative paths and bytes (hex).

        Examples
        --------
        The same bytes at another path have the same digest:

        >>> import tempfile
        >>> from pathlib import Path
        >>> from assur import io
        >>> from assur.io.problems import model_content
        >>> src = io.bundled("hitch_003")
        >>> with tempfile.TemporaryDirectory() as d:
        ...     copy = Path(d) / "hitch_003.toml"
        ...     _ = copy.write_bytes(src.read_bytes())
        ...     model_content(copy).digest == model_content(src).digest
        True
        """
        h = hashlib.sha256()
        for name, data in self.files:
            h.update(name.encode("utf-8") + b"\0" + len(data).to_bytes(8, "little") + data)
        h.update(b"main\0" + self.main.encode("utf-8"))
        return h.hexdigest()

    def materialize(self, root=None) -> Path:
        """Write the files under ``root``/<digest> (default: the temporary folder's
        ``assur-models``), once, and return the model file's path there.

        Examples
        --------
        >>> import tempfile
        >>> from assur import io
        >>> from assur.io.problems import model_content
        >>> c = model_content(io.bundled("hitch_003_design"))
        >>> with tempfile.TemporaryDirectory() as d:
        ...     io.load(c.materialize(d)).name
        'hitch_003'
        """
        base = Path(root if root is not None else
                    Path(tempfile.gettempdir()) / "assur-models") / self.digest[:32]
        for name, data in self.files:
            p = base / name
            if p.is_file() and p.read_bytes() == data:
                continue
            p.parent.mkdir(parents=True, exist_ok=True)
            tmp = p.with_name(f".{p.name}.{os.getpid()}.{threading.get_ident()}.tmp")
            tmp.write_bytes(data)
            os.replace(tmp, p)
        return base / self.main


def model_content(path) -> ModelContent:
    """The content of the model file ``path`` and of its ``extends`` chain, read now.

    A file that is not TOML, or whose base cannot be read, ends the chain there (its
    loading reports the error at its key).

    Examples
    --------
    >>> from assur import io
    >>> from assur.io.problems import model_content
    >>> c = model_content(io.bundled("hitch_003"))
    >>> c.main, len(c.files)
    ('hitch_003.toml', 1)
    """
    from . import load, read_model_bytes
    try:
        first = Path(path).resolve()
    except (OSError, RuntimeError, ValueError):  # a symlink loop, a NUL byte …
        load(path)  # its own message
        raise
    paths, datas = [], []
    p = first
    while p is not None and p not in paths:
        data = read_model_bytes(p, str(path) if p == first else str(p))
        paths.append(p)
        datas.append(data)
        try:
            ext = tomllib.loads(data.decode("utf-8").removeprefix("\ufeff")).get("extends")
            nxt = (p.parent / ext).resolve() if isinstance(ext, str) and ext.strip() else None
            p = nxt if nxt is not None and nxt.is_file() else None
        except (UnicodeDecodeError, tomllib.TOMLDecodeError, OSError, RuntimeError,
                ValueError):  # the chain ends here: loading the file reports it at its key
            p = None
    root = Path(os.path.commonpath([str(q.parent) for q in paths]))
    rel = [q.relative_to(root).as_posix() for q in paths]
    return ModelContent(rel[0], tuple(zip(rel, datas)), shown=str(path))


def load_problem(path, variables=(), positions=None, chunk=None):
    """The design problem of a model file.

    Parameters
    ----------
    path : str or os.PathLike
        A model file; its ``[design]`` section gives variables and criteria.
    variables : sequence of str
        More variables as ``"NAME=LOW:HIGH"`` or ``"NAME=±DELTA"`` (units as in files);
        one given in the file too replaces the file's.
    positions : int, optional
        Positions over the range (default: ``[design] positions``, else the range).
    chunk : int, optional
        Designs per kernel call.

    Returns
    -------
    Problem
        Made once per content (the file's and its bases' bytes), variables, positions
        and chunk: an edited file gives a new problem.

    Examples
    --------
    The bundled design problem of the seed-003 hitch (its four frame pivots within
    ±30 mm, 50 positions), with the brace L4 (0.6613 m) added within ±20 mm and
    checked at 6 positions instead:

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.io import load_problem
    >>> pb = load_problem(io.bundled("hitch_003_design"), variables=["L4=±20 mm"], positions=6)
    >>> pb.names[-3:], pb.n_positions
    (('X07', 'Y07', 'L4'), 6)
    >>> np.round(pb.bounds[-1], 4).tolist()  # L4 [m]
    [0.6413, 0.6813]
    >>> [c.name for c in pb.objectives]
    ['min reserve(ГЦ, S6, P6)']

    A model file without a ``[design]`` section needs variables:

    >>> load_problem(io.bundled("hitch_003"))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: ...hitch_003.toml: no design variables: give a [design.variables] table or --var NAME=LOW:HIGH
    """
    from .. import io
    args = (tuple(variables), positions, chunk)
    for _ in range(3):  # a file edited while it loads: read again
        content = model_content(path)
        key = (content.digest,) + args
        with _lock:
            if key in _cache:
                _cache.move_to_end(key)
                return _cache[key]
        pb = _build(io.load(Path(path)), str(Path(path).resolve()), content, *args)
        if model_content(path).digest == content.digest:
            return _remember(key, pb)
    raise ModelError(f"{path}: the file changed three times while it was loading")


def rebuild(content, variables, positions, chunk):
    """The problem of a recipe (a worker's side of :func:`load_problem`): from the
    cache by content hash, else from ``content`` written to a temporary folder.

    Examples
    --------
    >>> from assur import io
    >>> from assur.io import load_problem
    >>> from assur.io.problems import model_content, rebuild
    >>> pb = load_problem(io.bundled("hitch_003_design"), positions=6)
    >>> rebuild(model_content(io.bundled("hitch_003_design")), (), 6, None) is pb
    True
    """
    from .. import io
    key = (content.digest, tuple(variables), positions, chunk)
    with _lock:
        if key in _cache:
            _cache.move_to_end(key)
            return _cache[key]
    path = content.materialize()
    return _remember(key, _build(io.load(path), content.shown or str(path), content, *key[1:]))


def _remember(key, pb):
    with _lock:
        pb = _cache.setdefault(key, pb)
        _cache.move_to_end(key)
        while len(_cache) > CACHE_SIZE:
            _cache.popitem(last=False)
    return pb


def _build(model, path, content, variables, positions, chunk):
    from ._design import check_positions, parse_var
    from ..synthesis.search.problem import CHUNK, Problem
    spec = model.design
    cli = [parse_var(v, model.mechanism) for v in variables]
    names = {v.name for v in cli}
    vars_ = [v for v in (spec.variables if spec else ()) if v.name not in names] + cli
    if not vars_:
        raise ModelError(f"{path}: no design variables: give a [design.variables] table or "
                         f"--var NAME=LOW:HIGH")
    count = positions if positions is not None else (spec.positions if spec else None)
    if positions is not None:  # [design] positions were checked when the file loaded
        check_positions(model.mechanism, positions, "--positions")
    polish = spec.polish if spec is not None and spec.polish is not None else True
    identity = hashlib.sha256(repr((content.digest, tuple(variables), positions)).encode(
        "utf-8")).hexdigest()
    path = _held_path(model, count, path_of=str(path))
    return Problem(model.mechanism, positions_of(model, count) if path is None else path.q,
                   vars_, spec.constraints if spec else (), spec.objectives if spec else (),
                   name=model.name, source=(rebuild, (content, variables, positions, chunk)),
                   chunk=chunk or CHUNK, polish=polish, identity=identity, path=path)


def _held_path(model, count, path_of):
    """The model's held path (``[range]`` with ``hold``), over ``count`` values of its
    parameter evenly over its span when given; None without one."""
    from ..core.held import hold_path
    from ..errors import AssemblyError
    path = model.path
    if path is None or count is None:
        return path
    s = np.linspace(path.s[0], path.s[-1], int(count))
    try:
        return hold_path(model.mechanism, path.along, s, path.holds,
                         along_unit=path.along_unit)
    except (AssemblyError, ModelError) as e:
        raise ModelError(f"{path_of}: [design] positions = {int(count)} over the held "
                         f"path: {e}") from None
