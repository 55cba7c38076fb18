"""Cached roots of a model file's ``[[solve]]`` conditions, verified before use.

Solving the conditions (:func:`assur.synthesis.conditions.solve_conditions`: a scan of each
bracket, then Brent's method) is most of a warm ``assur check`` and needs
:mod:`scipy.optimize`. The roots depend only on the model file, so they are kept
in ``<assur cache>/solve/<key>.json`` (beside the kernels,
:func:`assur.kernel.cache_dir`, so ``$ASSUR_CACHE_DIR`` is honoured), ``key`` the
SHA-256 of the file's data after ``extends`` (every base file's keys included),
the conditions and the assur version.

A cached entry is never trusted as such: each condition's residual is evaluated
once at the cached roots (:func:`assur.synthesis.conditions.condition_residual`, no scipy)
and must assemble and be within :data:`RESIDUAL_TOL`; otherwise — and for an entry
that is missing, unreadable, corrupt or for other conditions — the conditions are
solved and the entry written again (atomically: a temporary file replaced). A
cache that cannot be written is skipped silently.
"""

from __future__ import annotations

import hashlib
import json
import os

import numpy as np

__all__ = ["solve", "directory", "entry_path", "RESIDUAL_TOL"]

#: |quantity − target| [m or rad] a cached root must reproduce; Brent's roots
#: (xtol 1e-13) leave residuals of ~1e-13, and an assembly closes to 1e-9
RESIDUAL_TOL = 1e-10

#: bump when the entry's layout changes
FORMAT = 1


def _key(data, conditions) -> str:
    from .. import __version__

    conds = [(c.unknown, [float(b) for b in c.bracket], sorted(c.at.items()), c.quantity,
              float(c.target)) for c in conditions]
    text = json.dumps([FORMAT, __version__, data, conds], sort_keys=True, default=repr,
                      ensure_ascii=False)
    return hashlib.sha256(text.encode()).hexdigest()[:32]


def directory():
    """``<assur cache>/solve``: beside the kernels (:func:`assur.kernel.cache_dir`)."""
    from ..kernel.cache import cache_dir

    return cache_dir().parent / "solve"


def entry_path(data, conditions):
    """The cache file of a model's data (after ``extends``) and its conditions."""
    return directory() / f"{_key(data, conditions)}.json"


def _read(path, conditions):
    """The entry's ``[(unknown, value, evaluations, notes)]`` in solving order, or None
    when it is missing, unreadable or does not fit the conditions."""
    try:
        entry = json.loads(path.read_text(encoding="utf-8"))
        roots = [(str(r["unknown"]), float(r["value"]), int(r["evaluations"]),
                  [str(n) for n in r["notes"]]) for r in entry["roots"]]
    except (OSError, ValueError, KeyError, TypeError):
        return None
    if sorted(r[0] for r in roots) != sorted(c.unknown for c in conditions) \
            or not all(np.isfinite(r[1]) for r in roots):
        return None
    return roots


def _verified(mech, conditions, roots):
    """``(mechanism, solved)`` at the cached roots if every condition holds there
    (assembles, |residual| ≤ RESIDUAL_TOL), else None."""
    from ..errors import AssemblyError, ModelError
    from ..synthesis.conditions import SolvedCondition, condition_residual

    by_unknown = {c.unknown: c for c in conditions}
    try:
        solved_mech = mech.with_params(**{u: v for u, v, _, _ in roots})
        solved = []
        for u, v, evaluations, notes in roots:
            c = by_unknown[u]
            r, ok = condition_residual(solved_mech, c, np.array([v]))
            if not (ok[0] and abs(r[0]) <= RESIDUAL_TOL):
                return None
            solved.append(SolvedCondition(c, v, float(r[0]), evaluations, notes))
    except (AssemblyError, ModelError):
        return None
    return solved_mech, solved


def _write(path, solved):
    entry = {"format": FORMAT,
             "roots": [{"unknown": s.condition.unknown, "value": s.value,
                        "residual": s.residual, "evaluations": s.evaluations,
                        "notes": list(s.notes)} for s in solved]}
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_text(json.dumps(entry, indent=1), encoding="utf-8")
        os.replace(tmp, path)
    except OSError:  # a read-only cache: solve every time
        pass


def solve(data, mech, conditions, solver):
    """``solver(mech, conditions)`` → ``(mechanism, solved)``, or the verified cached
    result of an earlier call with the same ``data`` (the model file's, after
    ``extends``) and conditions."""
    try:
        path = entry_path(data, conditions)
    except OSError:  # no cache directory: solve
        return solver(mech, conditions)
    roots = _read(path, conditions)
    if roots is not None:
        hit = _verified(mech, conditions, roots)
        if hit is not None:
            return hit
    result = solver(mech, conditions)
    _write(path, result[1])
    return result
