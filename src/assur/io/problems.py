"""A :class:`~assur.synthesis.search.problem.Problem` from a model file with a ``[design]``
section (:mod:`assur.io._design`), plus variables given on the command line.

A problem made here pickles as its recipe (the file's path and the extra
variables), so that Dask workers rebuild it — once per process — instead of
receiving compiled kernels.
"""

from __future__ import annotations

import functools
from pathlib import Path

import numpy as np

from ..errors import ModelError

__all__ = ["load_problem", "positions_of"]


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
    return _load(str(Path(path).resolve()), tuple(variables), positions, chunk)


@functools.lru_cache(maxsize=8)
def _load(path, variables, positions, chunk):
    from .. import io
    from ._design import check_positions, parse_var
    from ..synthesis.search.problem import CHUNK, Problem
    model = io.load(path)
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
    return Problem(model.mechanism, positions_of(model, count), vars_,
                   spec.constraints if spec else (), spec.objectives if spec else (),
                   name=model.name, source=(_load, (path, variables, positions, chunk)),
                   chunk=chunk or CHUNK, polish=polish)
