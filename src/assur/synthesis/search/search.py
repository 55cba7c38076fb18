"""Searches over a :class:`~assur.synthesis.search.problem.Problem`: whole populations per call.

* :func:`optimize` — one objective: :func:`scipy.optimize.differential_evolution`
  with ``vectorized=True``, so every generation is **one** call of
  :meth:`Problem.evaluate` (one fused-kernel batch). The constraints go to scipy as
  one vectorized :class:`~scipy.optimize.NonlinearConstraint` (the total relative
  violation, ≤ 0): scipy ranks a feasible design above an infeasible one and two
  infeasible ones by their violation (Lampinen's rule), so the search walks from
  designs that do not assemble towards ones that do. The objective and the
  constraint of a population are computed together and cached.
* :func:`pareto` — several objectives: NSGA-II (pymoo) on the same batches; the
  Pareto front of the feasible designs.

The objective is what the problem says (maximised ones are negated for the
minimisers). After differential evolution, :func:`optimize` polishes its best design
by SLSQP with the criteria's exact gradients (:mod:`assur.synthesis.search.polish`; scipy's own
finite-difference polish stays off) and keeps the polished design only if the same
batch evaluation finds it feasible and not worse.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import ModelError

__all__ = ["optimize", "pareto", "OptimizeResult", "ParetoResult"]


@dataclass
class OptimizeResult:
    """The outcome of :func:`optimize`.

    Attributes
    ----------
    x : ndarray, shape (number of variables,)
        The best design [SI].
    batch : Batch
        Its evaluation (one design).
    original : Batch
        The evaluation of the original design.
    evaluations : int
        Designs evaluated.
    calls : int
        Batches evaluated (kernel calls per chunk).
    generations : int
    message : str
        scipy's.
    verified : str
        :meth:`Problem.verify` of the best design: "" when it assembles continuously
        between the positions too, else why not.
    polished : assur.synthesis.search.polish.Polished or None
        The exact-gradient polish (None: not asked for): differential evolution's
        best (``polished.start``, ``polished.start_value``), the polished value, SLSQP's
        iterations and gradient evaluations, and why the polished design was not kept
        or the polish skipped. ``x`` and ``batch`` are the design kept.

    Examples
    --------
    The seed-003 hitch's smallest capacity reserve at S6 maximised over its top-link
    pivot 07 (X07, Y07 within ±30 mm), by a short differential evolution (5
    generations) and the exact-gradient polish:

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.synthesis.search import Problem
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.search import optimize
    >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
    >>> top = Problem(pb.original, pb.positions[::5], pb.variables[6:], pb.constraints,
    ...               pb.objectives)  # only the top-link pivot 07 moves; 10 positions
    >>> r = optimize(top, popsize=5, maxiter=5, seed=0)
    >>> r.generations <= 5, r.evaluations <= 5 * 2 * (5 + 1)  # 10 designs each, and the first
    (True, True)
    >>> round(float(r.original.objectives[0, 0]), 2), round(r.value, 2)  # seed's, best [%]
    (9.44, 17.18)
    >>> p = r.polished                       # differential evolution's best, then SLSQP's
    >>> p.accepted, round(p.start_value, 2), round(p.value, 2), p.value > p.start_value  # [%]
    (True, 16.54, 17.18, True)
    >>> print(p.summary(lambda v: f"{v:.2f} %"))  # doctest: +ELLIPSIS
    polish (SLSQP, exact gradients): 16.54 % → 17.18 % (... iterations, ... gradient evaluations)
    >>> np.round(r.x * 1e3, 1).tolist(), r.verified  # X07, Y07 [mm]; assembles throughout
    ([385.0, 925.0], '')
    """

    x: np.ndarray
    batch: object
    original: object
    evaluations: int
    calls: int
    generations: int
    message: str
    verified: str = ""
    polished: object = None

    @property
    def feasible(self) -> bool:
        """Whether the best design meets every constraint (and assembles).

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.synthesis.search import Problem
        >>> from assur.io import load_problem
        >>> from assur.synthesis.search.search import optimize
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> top = Problem(pb.original, pb.positions[::5], pb.variables[6:], pb.constraints,
        ...               pb.objectives)  # only the top-link pivot 07 moves; 10 positions
        >>> r = optimize(top, popsize=5, maxiter=5, seed=0)
        >>> r.feasible, r.batch.reason(0)
        (True, '')
        """
        return bool(self.batch.feasible[0])

    @property
    def value(self) -> float:
        """The best design's (first) objective [SI].

        Examples
        --------
        The seed-003 hitch's smallest capacity reserve at S6, from 9.44 % with the
        seed's top-link pivot 07 to:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.synthesis.search import Problem
        >>> from assur.io import load_problem
        >>> from assur.synthesis.search.search import optimize
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> top = Problem(pb.original, pb.positions[::5], pb.variables[6:], pb.constraints,
        ...               pb.objectives)  # only the top-link pivot 07 moves; 10 positions
        >>> r = optimize(top, popsize=5, maxiter=5, seed=0)
        >>> round(r.value, 2)  # [%]
        17.18
        """
        return float(self.batch.objectives[0, 0])


class _Cached:
    """Objective and constraint of designs from one evaluation each: scipy asks for
    the constraint of a whole trial population and then for the objective of its
    feasible part; rows already evaluated are served from a memo."""

    MEMO = 1 << 18  # rows kept at most (cleared when full)

    def __init__(self, problem, evaluate):
        self.problem = problem
        self.evaluate = evaluate
        self.memo = {}
        self.evaluations = 0
        self.calls = 0
        self.sign = -1.0 if problem.objectives[0].sense == "maximize" else 1.0

    def get(self, X):
        """``(objective to minimise, violation)`` per row of ``X``, shape (m,) each."""
        X = np.ascontiguousarray(X)
        keys = [r.tobytes() for r in X]
        todo = [i for i, k in enumerate(keys) if k not in self.memo]
        if todo:
            if len(self.memo) + len(todo) > self.MEMO:
                self.memo.clear()
            b = self.evaluate(X[todo])
            self.evaluations += len(todo)
            self.calls += 1
            f = self.sign * b.objectives[:, 0]
            for j, i in enumerate(todo):
                self.memo[keys[i]] = (f[j], b.violation[j])
        out = np.array([self.memo[k] for k in keys]).reshape(len(keys), 2)
        return out[:, 0], out[:, 1]

    def objective(self, x):
        X = np.atleast_2d(np.asarray(x, float).T)  # scipy: (N, S) vectorized, (N,) polish
        f = self.get(X)[0]
        return f if np.ndim(x) > 1 else float(f[0])

    def violation(self, x):
        X = np.atleast_2d(np.asarray(x, float).T)
        v = self.get(X)[1]
        return v[None, :] if np.ndim(x) > 1 else v


def optimize(problem, *, popsize=15, maxiter=100, seed=None, tol=1e-6, init="latinhypercube",
             callback=None, x0=True, evaluate=None, polish=None):
    """Maximise or minimise the problem's (first) objective subject to its constraints.

    Parameters
    ----------
    problem : Problem
        With at least one objective.
    popsize : int
        Population size per variable (scipy's meaning).
    maxiter : int
        Generations at most.
    seed : int, optional
        For reproducible runs.
    tol : float
        scipy's relative convergence tolerance.
    init : str
        scipy's initialisation.
    callback : callable, optional
        ``callback(generation, best_value)`` after every generation (progress).
    x0 : bool
        Seed the population with the original design (with the design of the box
        nearest to it where the variables' bounds exclude the file's values).
    evaluate : callable, optional
        ``evaluate(X) → Batch`` for a population (default: :meth:`Problem.evaluate`;
        ``lambda X: executor.evaluate(problem, X)`` sends it to a Dask cluster,
        :mod:`assur.synthesis.search.scale`).
    polish : bool, optional
        Polish differential evolution's best feasible design by SLSQP with the exact
        gradients of the criteria (:func:`assur.synthesis.search.polish.polish`; skipped with a
        note when a criterion has none). The polished design is judged by ``evaluate``.
        Default: :attr:`Problem.polish` (``[design] polish`` of a model file, else True).

    Returns
    -------
    OptimizeResult

    Raises
    ------
    ModelError
        The problem has no objective.

    Examples
    --------
    Maximise the seed-003 hitch's smallest capacity reserve at S6 (9.44 % for the
    seed's design over 10 positions) by moving the top-link pivot 07 within ±30 mm,
    keeping the lift range and the pressure limit: both coordinates end at a bound.

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.synthesis.search import Problem
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.search import optimize
    >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
    >>> top = Problem(pb.original, pb.positions[::5], pb.variables[6:], pb.constraints,
    ...               pb.objectives)  # only the top-link pivot 07 moves; 10 positions
    >>> r = optimize(top, popsize=5, maxiter=5, seed=0)
    >>> r.feasible, round(r.value, 2)  # [%]
    (True, 17.18)
    >>> np.round((r.x - top.x0) * 1e3, 1).tolist()  # X07, Y07 moved [mm]
    [-30.0, 30.0]
    >>> r0 = optimize(top, popsize=5, maxiter=5, seed=0, polish=False)
    >>> round(r0.value, 2), r0.polished is None  # differential evolution alone [%]
    (16.54, True)
    """
    from scipy.optimize import NonlinearConstraint, differential_evolution

    from .polish import polish as run_polish

    if not problem.objectives:
        raise ModelError(f"design problem {problem.name!r}: no objective to optimise")
    # the population (popsize × variables designs: scipy's copies, the memo, a batch)
    nv = len(problem.variables)
    problem.check_memory(float(popsize) * nv, f"optimize: popsize = {popsize} "
                         f"(a population of {float(popsize) * nv:.4g} designs)",
                         "the population (--popsize)", per_design=48 * nv + 300)
    cache = _Cached(problem, evaluate or problem.evaluate)
    gen = [0]

    def cb(intermediate_result):
        gen[0] += 1
        if callback is not None:
            callback(gen[0], cache.sign * float(intermediate_result.fun))

    # the violation also counts designs that do not assemble: always a constraint
    cons = NonlinearConstraint(cache.violation, -np.inf, 0.0)
    res = differential_evolution(cache.objective, problem.bounds, popsize=popsize,
                                 maxiter=maxiter, seed=seed, tol=tol, init=init,
                                 vectorized=True, updating="deferred", polish=False,
                                 constraints=cons, callback=cb,
                                 x0=_seed(problem) if x0 else None)
    x = np.asarray(res.x)
    best = problem.evaluate(x[None])
    polished = None
    if problem.polish if polish is None else polish:
        polished = run_polish(problem, x, start_batch=best, evaluate=evaluate)
        if polished.accepted:
            x = polished.x
            best = problem.evaluate(x[None])
    return OptimizeResult(x, best, problem.evaluate(problem.x0[None]),
                          cache.evaluations, cache.calls, int(res.nit), str(res.message),
                          problem.verify(x) if best.feasible[0] else "", polished)


def _seed(problem):
    """The original design, clipped into the variables' bounds (a box that excludes the
    file's value: scipy refuses a seed outside it)."""
    lo, hi = (np.array(b, dtype=float) for b in zip(*problem.bounds))
    return np.clip(problem.x0, lo, hi)


@dataclass
class ParetoResult:
    """The outcome of :func:`pareto`.

    Attributes
    ----------
    X : ndarray, shape (k, number of variables)
        The non-dominated feasible designs [SI].
    batch : Batch
        Their evaluation (objective values in :attr:`Batch.objectives`).
    original : Batch
    evaluations : int
    generations : int

    Examples
    --------
    The seed-003 hitch's capacity reserve at S6 against the lift range of 56 when
    the cylinder's frame pivot 01 moves (±30 mm): 12 non-dominated designs.

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.synthesis.search import Problem, criterion
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.search import pareto
    >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
    >>> lift = criterion("bound", {"quantity": "Y(56)", "of": "span"}, pb.original,
    ...                  sense="maximize")  # the lift range of 56 [m]
    >>> two = Problem(pb.original, pb.positions[::5], pb.variables[:2], [pb.constraints[2]],
    ...               [pb.objectives[0], lift])  # cylinder pivot 01 moves; p ≤ relief
    >>> front = pareto(two, pop_size=12, generations=8, seed=0)
    >>> front.X.shape[1], front.generations  # 2 variables; 8 generations
    (2, 8)
    >>> front.evaluations <= 12 * 8          # at most 12 designs a generation
    True
    >>> round(float(front.original.objectives[0, 1]), 3)  # the seed's lift range [m]
    0.788
    """

    X: np.ndarray
    batch: object
    original: object
    evaluations: int
    generations: int


def pareto(problem, *, pop_size=40, generations=40, seed=None, callback=None,
           evaluate=None):
    """The Pareto front of several objectives by NSGA-II (pymoo), one batch per
    generation.

    Parameters
    ----------
    problem : Problem
        With two or more objectives.
    pop_size : int
    generations : int
    seed : int, optional
    callback : callable, optional
        ``callback(generation, number of front designs)``.
    evaluate : callable, optional
        ``evaluate(X) → Batch`` (as for :func:`optimize`).

    Returns
    -------
    ParetoResult

    Raises
    ------
    ModelError
        The problem has fewer than two objectives.

    Examples
    --------
    More lift range of the seed-003 hitch's point 56 costs capacity reserve at S6,
    as the cylinder's frame pivot 01 moves within ±30 mm (a short NSGA-II run):

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.synthesis.search import Problem, criterion
    >>> from assur.io import load_problem
    >>> from assur.synthesis.search.search import pareto
    >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
    >>> lift = criterion("bound", {"quantity": "Y(56)", "of": "span"}, pb.original,
    ...                  sense="maximize")  # the lift range of 56 [m]
    >>> two = Problem(pb.original, pb.positions[::5], pb.variables[:2], [pb.constraints[2]],
    ...               [pb.objectives[0], lift])  # cylinder pivot 01 moves; p ≤ relief
    >>> front = pareto(two, pop_size=12, generations=8, seed=0)
    >>> reserve, span = front.batch.objectives.T  # [%], [m]
    >>> bool(front.batch.feasible.all()), len(front.X)
    (True, 12)
    >>> order = np.argsort(reserve)
    >>> bool(np.all(np.diff(span[order]) <= 0))  # the more reserve, the less range
    True
    >>> round(float(reserve.max()), 2), round(float(span.max()), 3)  # [%], [m]
    (11.75, 0.838)
    >>> pareto(pb)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: design problem 'hitch_003': a Pareto front needs two or more objectives, it has 1
    """
    from ..._extras import require
    require("pareto", "the Pareto front (NSGA-II)")
    from pymoo.algorithms.moo.nsga2 import NSGA2
    from pymoo.core.callback import Callback
    from pymoo.core.problem import Problem as PymooProblem
    from pymoo.optimize import minimize

    if len(problem.objectives) < 2:
        raise ModelError(f"design problem {problem.name!r}: a Pareto front needs two or more "
                         f"objectives, it has {len(problem.objectives)}")
    # pymoo keeps every individual as an object (about 2 kB) besides the batch
    problem.check_memory(pop_size, f"pareto: pop_size = {pop_size}",
                         "the population (--popsize)", per_design=2048 + 48 * len(problem.variables))
    count = [0]
    run = evaluate or problem.evaluate
    lo, hi = problem.bounds.T

    class _P(PymooProblem):
        def __init__(self):
            super().__init__(n_var=len(lo), n_obj=len(problem.objectives), n_ieq_constr=1,
                             xl=lo, xu=hi)

        def _evaluate(self, X, out, *args, **kwargs):
            b = run(X)
            count[0] += len(X)
            # an infeasible design (one that does not assemble too) is ranked by its
            # violation (pymoo's constraint domination)
            out["F"] = b.scores()
            out["G"] = b.violation[:, None]

    class _CB(Callback):
        def notify(self, algorithm):
            if callback is not None:
                callback(algorithm.n_gen, len(algorithm.opt))

    res = minimize(_P(), NSGA2(pop_size=pop_size), ("n_gen", int(generations)),
                   seed=seed, verbose=False, callback=_CB())
    X = np.atleast_2d(res.X) if res.X is not None else np.zeros((0, len(lo)))
    b = problem.evaluate(X) if len(X) else None
    if b is not None:
        keep = b.feasible
        X = X[keep]
        b = problem.evaluate(X) if len(X) else None
    return ParetoResult(X, b, problem.evaluate(problem.x0[None]), count[0], int(generations))
