"""Polishing a design with exact gradients: SLSQP from the optimum of a global search.

Differential evolution (:func:`assur.synthesis.search.search.optimize`) finds the basin; its
best design is rarely the basin's bottom. :func:`polish` runs the one local refiner,
:func:`assur.synthesis.refine.refine` (scipy's SLSQP), from it on the problem as its
criteria define it —

* the objective: the problem's (first) objective, maximised or minimised as it says
  (the refiner divides it by its magnitude at the start);
* one inequality per constraint: its margin (:meth:`Criterion.margin`, ≥ 0 where it
  holds) divided by its scale (:meth:`Criterion.scale`, the limit's magnitude), at
  least a small slack (1e-9) so that an active constraint is not lost to rounding;
* the variables scaled to [0, 1] over their bounds, which are SLSQP's bounds (the
  refiner's :class:`~assur.synthesis.refine.Scaled`) —

with the exact gradients of the criteria (:attr:`Criterion.gradient`: the
sensitivity of the output at the active position, :mod:`assur.synthesis.sensitivity`). One
evaluation of the sensitivities (every criterion output, every position, every
variable, by forward-mode dual numbers) serves the objective, the constraints and
all their gradients at a design.

The polished design is accepted only if the batch evaluation the search used (the
fused kernel over every position: assembly, lift, every constraint) finds it
feasible and its objective not worse than the start's; otherwise the start is kept
and :attr:`Polished.note` says why. If a criterion has no exact gradient the polish
is skipped with a note naming it (no finite differences).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import AssemblyError, ModelError
from ..refine import refine

__all__ = ["polish", "Polished", "missing_gradients"]


@dataclass(frozen=True)
class Polished:
    """Result of :func:`polish`.

    Attributes
    ----------
    x : ndarray, shape (number of variables,)
        The design kept: the polished one if accepted, else the start [SI].
    start : ndarray, shape (number of variables,)
        The start (the global search's optimum) [SI].
    start_value, value : float
        The objective of the start and of the polished design, both from the batch
        evaluation (nan for ``value`` when the polish did not run) [SI].
    accepted : bool
        The polished design replaces the start.
    ran : bool
        SLSQP ran (False: skipped, see ``note``).
    nit : int
        SLSQP iterations.
    nfev : int
        Evaluations of the criteria (each one call of the sensitivities).
    njev : int
        Gradient evaluations (objective's gradient requests by SLSQP).
    message : str
        SLSQP's message ("" when it did not run).
    note : str
        Why the start was kept or the polish skipped ("" when accepted).

    Examples
    --------
    The seed-003 hitch's smallest capacity reserve at S6 polished over its top-link
    pivot 07 alone (X07, Y07 within ±30 mm): both go to a bound.

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.synthesis.search import Problem
    >>> from assur.io import load_problem
    >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
    >>> top = Problem(pb.original, pb.positions[::5], pb.variables[6:], pb.constraints,
    ...               pb.objectives)  # only the top-link pivot 07 moves; 10 positions
    >>> from assur.synthesis.search.polish import polish
    >>> p = polish(top, top.x0)
    >>> p.accepted, p.ran, p.note
    (True, True, '')
    >>> round(p.start_value, 2), round(p.value, 2)  # min reserve [%]
    (9.44, 17.18)
    >>> np.round((p.x - p.start) * 1e3, 1).tolist()  # X07, Y07 moved [mm]
    [-30.0, 30.0]
    """

    x: np.ndarray
    start: np.ndarray
    start_value: float
    value: float
    accepted: bool
    ran: bool
    nit: int = 0
    nfev: int = 0
    njev: int = 0
    message: str = ""
    note: str = ""

    def summary(self, show=None) -> str:
        """One line: ``"polish (SLSQP, exact gradients): 22.1 → 23.4 (12 iterations,
        13 gradient evaluations)"``, or why it was skipped or not kept. ``show`` formats
        a value (default ``"{:.6g}"``).

        Examples
        --------
        The top-link pivot 07 of the seed-003 hitch polished, and a start that is not
        feasible (the cylinder pivot Y01 30 mm higher lifts the lowest position of 56):

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.synthesis.search import Problem
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> top = Problem(pb.original, pb.positions[::5], pb.variables[6:], pb.constraints,
        ...               pb.objectives)  # only the top-link pivot 07 moves; 10 positions
        >>> from assur.synthesis.search.polish import polish
        >>> p = polish(top, top.x0)
        >>> print(p.summary(lambda v: f"{v:.2f} %"))  # doctest: +ELLIPSIS
        polish (SLSQP, exact gradients): 9.44 % → 17.18 % (... iterations, ... gradient evaluations)
        >>> x = pb.x0.copy()
        >>> x[1] += 0.03  # [m]
        >>> print(polish(pb, x).summary())
        polish skipped: the start is not feasible: constraint min Y(56) ≤ 0.2 m does not hold at position 0 (S = 0.42): 0.325266 m
        """
        show = show or (lambda v: f"{float(v):.6g}")
        if not self.ran:
            return f"polish skipped: {self.note}"
        head = (f"polish (SLSQP, exact gradients): {show(self.start_value)} → "
                f"{show(self.value)} ({self.nit} iterations, {self.njev} gradient "
                f"evaluations)")
        return head if self.accepted else f"{head}; kept the start: {self.note}"


def missing_gradients(problem) -> list:
    """The names of the problem's criteria (its first objective and every constraint)
    without an exact gradient.

    Examples
    --------
    Every criterion of the bundled seed-003 design problem has one:

    >>> from assur import io
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.polish import missing_gradients
    >>> missing_gradients(load_problem(io.bundled("hitch_003_design")))
    []
    """
    crit = list(problem.objectives[:1]) + list(problem.constraints)
    return [f"{c.kind} {c.name}" for c in crit if c.gradient is None]


def polish(problem, x, *, start_batch=None, evaluate=None, maxiter=100, ftol=1e-9,
           slack=1e-9):
    """Polish a design by SLSQP with the criteria's exact gradients.

    Parameters
    ----------
    problem : Problem
        With an objective; its first objective is polished.
    x : array_like, shape (number of variables,)
        The start, a feasible design (e.g. differential evolution's best) [SI].
    start_batch : Batch, optional
        The start's evaluation (default: evaluated here).
    evaluate : callable, optional
        ``evaluate(X) → Batch``: the batch evaluation that judges the polished design
        (default :meth:`Problem.evaluate`; the search's own, e.g. on Dask).
    maxiter : int
        SLSQP iterations at most.
    ftol : float
        SLSQP's tolerance on the scaled objective.
    slack : float
        SLSQP holds every constraint with this margin relative to its scale (a
        constraint active at the optimum is met by rounding either way; the batch
        evaluation counts a margin of −1e-16 as violated).

    Returns
    -------
    Polished

    Raises
    ------
    ModelError
        The problem has no objective, or ``x`` has the wrong shape.

    Examples
    --------
    The seed-003 hitch's smallest capacity reserve at S6, polished over the top-link
    pivot 07 from the seed's design: from 9.44 % to 17.18 % with X07 and Y07 at their
    bounds (385 mm, 925 mm), the batch evaluation confirming it feasible.

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.synthesis.search import Problem
    >>> from assur.io import load_problem
    >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
    >>> top = Problem(pb.original, pb.positions[::5], pb.variables[6:], pb.constraints,
    ...               pb.objectives)  # only the top-link pivot 07 moves; 10 positions
    >>> from assur.synthesis.search.polish import polish
    >>> p = polish(top, top.x0)
    >>> p.accepted, round(p.value, 2)  # [%]
    (True, 17.18)
    >>> np.round(p.x * 1e3, 1).tolist()  # X07, Y07 [mm]
    [385.0, 925.0]
    >>> bool(top.evaluate(p.x[None]).feasible[0])
    True
    >>> polish(top, [0.4])
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: polish: a design has 2 values (['X07', 'Y07']), got shape (1,)
    """
    if not problem.objectives:
        raise ModelError(f"design problem {problem.name!r}: no objective to polish")
    run = evaluate or problem.evaluate
    names = problem.names
    x0 = np.asarray(x, float).reshape(-1)
    if x0.shape != (len(names),):
        raise ModelError(f"polish: a design has {len(names)} values ({list(names)}), "
                         f"got shape {np.shape(x)}")
    b0 = start_batch if start_batch is not None else run(x0[None])
    obj = problem.objectives[0]
    sign = -1.0 if obj.sense == "maximize" else 1.0
    v0 = float(b0.objectives[0, 0])
    missing = missing_gradients(problem)
    if missing:
        return Polished(x0, x0, v0, float("nan"), False, False,
                        note=f"no exact gradient for {', '.join(missing)}")
    if not b0.feasible[0]:
        return Polished(x0, x0, v0, float("nan"), False, False,
                        note=f"the start is not feasible: {b0.reason(0)}")
    ref = problem.reference() if any(
        isinstance(c.limit.value, str) and c.limit.value == "original"
        for c in problem.constraints) else {}

    def criteria(xx):
        """(objective, its gradient, margins/scales, their gradients) at the design
        ``xx`` [SI]: one call of the sensitivities."""
        s, red = problem.jet(xx)
        g, dg = [], []
        for c in problem.constraints:
            rf = ref.get(c.name)
            sc = float(c.scale(red, rf)[0])
            g.append(float(c.margin(red, rf)[0]) / sc)
            dg.append(c.margin_gradient(s, red, names) / sc)
        return (float(obj.value(red)[0]), obj.gradient(s, red), np.array(g),
                np.array(dg).reshape(len(g), len(names)))

    # a trial design that cannot be evaluated (one that does not assemble, links in
    # line) ends SLSQP: its last iterate is the result
    r = refine(criteria, x0, problem.bounds, maximize=obj.sense == "maximize", slack=slack,
               names=names, constraint_names=[c.name for c in problem.constraints],
               stop_on=(AssemblyError, ModelError), maxiter=maxiter, ftol=ftol)
    stop = r.message if r.stopped else ""
    xp = r.x
    bp = run(xp[None])
    vp = float(bp.objectives[0, 0])
    note = ""
    if not bp.feasible[0]:
        note = f"the polished design is not feasible: {bp.reason(0)}"
    elif sign * vp > sign * v0:
        note = (f"the polished design is worse ({obj.show(vp)} against "
                f"{obj.show(v0)})")
    else:
        verified = problem.verify(xp)
        if verified:
            note = f"the polished design does not assemble continuously: {verified}"
    if stop and note:
        note = f"{note} ({stop})"
    ok = not note
    return Polished(xp if ok else x0, x0, v0, vp, ok, True, r.nit, r.nfev, r.njev, r.message,
                    note)
