"""A :class:`~assur.design.problem.Problem` from a model file with a ``[design]``
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
    positions evenly over its span (one coordinate) [m or rad]."""
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
    """
    return _load(str(Path(path).resolve()), tuple(variables), positions, chunk)


@functools.lru_cache(maxsize=8)
def _load(path, variables, positions, chunk):
    from .. import io
    from ..io._design import parse_var
    from .problem import CHUNK, Problem
    model = io.load(path)
    spec = model.design
    cli = [parse_var(v, model.mechanism) for v in variables]
    names = {v.name for v in cli}
    vars_ = [v for v in (spec.variables if spec else ()) if v.name not in names] + cli
    if not vars_:
        raise ModelError(f"{path}: no design variables: give a [design.variables] table or "
                         f"--var NAME=LOW:HIGH")
    count = positions if positions is not None else (spec.positions if spec else None)
    polish = spec.polish if spec is not None and spec.polish is not None else True
    return Problem(model.mechanism, positions_of(model, count), vars_,
                   spec.constraints if spec else (), spec.objectives if spec else (),
                   name=model.name, source=(_load, (path, variables, positions, chunk)),
                   chunk=chunk or CHUNK, polish=polish)
