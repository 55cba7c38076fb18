"""A design problem and the evaluation of batches of designs.

A :class:`Problem` is a mechanism, the positions to check it at, the design
variables (parameters with bounds) and the criteria (:mod:`assur.synthesis.search.criteria`).
:meth:`Problem.evaluate` runs a whole batch of designs — an array of shape
(m, number of variables) — through **one** fused-kernel call per chunk of designs
(:meth:`assur.Mechanism.evaluate` with ``reduce=True``: the minimum and maximum of
every output over the positions, no position stored), and returns a
:class:`Batch`: the criteria's values, which designs are feasible, and for every
infeasible one the reason.

A design is infeasible, with its reason (:attr:`Batch.reasons`), when

* it does not assemble at some position ("assembly": the first group that fails,
  its failure, the position — found by one extra kinematic pass over the failed
  designs of the chunk, vectorized);
* the engine refuses it as a whole ("engine": e.g. a pose that cannot assemble,
  a non-finite output — the batch is split in halves until that design is alone,
  so the rest of the batch is still evaluated);
* a capacity it reads has a transmission number ≤ 0 somewhere ("lift");
* a constraint does not hold ("constraint": the first one violated, by how much).

No design stops the batch.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import diagnostics
from ...errors import AssemblyError, ModelError
from ...kernel.emit import CODES_PER_OP
from ...core.program import execute
from .criteria import Reductions, lift_outputs

__all__ = ["Variable", "Problem", "Batch", "FEASIBLE", "ASSEMBLY", "ENGINE", "LIFT",
           "CONSTRAINT", "FAILURE_TEXT"]

#: kinds of :attr:`Batch.status`
FEASIBLE, ASSEMBLY, ENGINE, LIFT, CONSTRAINT = 0, 1, 2, 3, 4

#: short words of the kernel's failure codes (assur.kernel.emit.FAIL_*)
FAILURE_TEXT = {1: "its outer joints are farther apart than its two sides reach",
                2: "its outer joints are closer than the difference of its sides",
                3: "its three sides cannot form a triangle",
                4: "the circle does not reach the slider line",
                5: "two points that define a direction coincide",
                6: "it passes a dead point",
                7: "it cannot move continuously between positions",
                8: "two slider lines are parallel"}

#: designs per kernel call (bounds memory: q and status take 16 B per position)
CHUNK = 1 << 16


@dataclass(frozen=True)
class Variable:
    """A design variable: a numeric parameter of the model and its bounds.

    Attributes
    ----------
    name : str
        A parameter of the mechanism.
    low, high : float
        Bounds [SI].
    unit : assur.core.quantities.Unit or None
        The unit to show its values in (the file's).

    Examples
    --------
    The frame pivot X01 of the seed-003 hitch (415 mm) within ±30 mm:

    >>> from assur.synthesis.search import Variable
    >>> from assur.core.quantities import Unit
    >>> v = Variable("X01", 0.385, 0.445, Unit("mm", 1e-3))  # [m]
    >>> v.show(0.415)
    '415 mm'
    >>> Variable("X01", 0.445, 0.385)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: design variable X01: bounds must be finite with low < high, got [0.445, 0.385]
    """

    name: str
    low: float
    high: float
    unit: object = None

    def __post_init__(self):
        if not (np.isfinite(self.low) and np.isfinite(self.high) and self.low < self.high):
            raise ModelError(f"design variable {self.name}: bounds must be finite with "
                             f"low < high, got [{self.low!r}, {self.high!r}]")

    def show(self, si) -> str:
        """``si`` in the variable's unit, e.g. ``"415 mm"``.

        Examples
        --------
        >>> from assur.synthesis.search import Variable
        >>> from assur.core.quantities import Unit
        >>> Variable("X01", 0.385, 0.445, Unit("mm", 1e-3)).show(0.4151)  # [m] in mm
        '415.1 mm'
        >>> Variable("X01", 0.385, 0.445).show(0.4151)  # no unit: the SI number
        '0.4151'
        """
        if self.unit is None:
            return f"{float(si):.6g}"
        return f"{float(self.unit.of(si)):.6g} {self.unit.text}"


class Problem:
    """A design search: variables, constraints and objectives over positions.

    Parameters
    ----------
    mechanism : Mechanism
        The original design (its parameter values are the start and the reference).
    positions : array_like, shape (n,) (one coordinate) or (n, k)
        Where every design is checked [m or rad].
    variables : sequence of Variable
    constraints : sequence of Criterion
        Each with a :class:`~assur.synthesis.search.criteria.Limit`.
    objectives : sequence of Criterion
        Each with a sense (maximize or minimize); none for a plain sweep.
    name : str, optional
    source : tuple, optional
        How to rebuild the problem in another process (``(function, args)``, set by
        :func:`assur.io.load_problem`): a problem made from a file pickles as
        that recipe, so Dask workers rebuild it instead of receiving compiled kernels.
    chunk : int
        Designs per kernel call.
    polish : bool
        Whether :func:`~assur.synthesis.search.search.optimize` polishes differential
        evolution's optimum by SLSQP with exact gradients unless told otherwise
        (``[design] polish`` of a model file).

    Examples
    --------
    >>> from assur import io
    >>> from assur.io import load_problem
    >>> pb = load_problem(io.bundled("hitch_003_design"))
    >>> [v.name for v in pb.variables][:4]
    ['X01', 'Y01', 'X03', 'Y03']
    >>> b = pb.evaluate(pb.x0[None])
    >>> bool(b.feasible[0]), round(float(b.objectives[0, 0]), 2)
    (True, 8.94)
    """

    def __init__(self, mechanism, positions, variables, constraints=(), objectives=(), *,
                 name=None, source=None, chunk=CHUNK, polish=True):
        self.variables = tuple(variables)
        self.polish = bool(polish)
        self.constraints = tuple(constraints)
        self.objectives = tuple(objectives)
        self.name = name or mechanism.name
        self.source = source
        self.chunk = int(chunk)
        if not self.variables:
            raise ModelError(f"design problem {self.name!r}: no design variables")
        names = [v.name for v in self.variables]
        for v in self.variables:
            if v.name not in mechanism.params:
                raise ModelError(f"design variable {v.name!r} is not a parameter of "
                                 f"{mechanism.name!r} ({sorted(mechanism.params)})")
            if names.count(v.name) > 1:
                raise ModelError(f"design variable {v.name!r} is given twice")
        for c in self.constraints:
            if c.limit is None:
                raise ModelError(f"constraint {c.name}: no limit")
        for c in self.objectives:
            if c.sense is None:
                raise ModelError(f"objective {c.name}: maximize or minimize?")
        # bounds outside a parameter's physical span (a length ≤ 0, a count < 1) are
        # refused here, once, rather than design by design
        from ...core.inputs import check_params
        check_params(mechanism, {v.name: np.array([v.low, v.high]) for v in self.variables})
        mech = mechanism
        have = {d.name for d in mech.distances}
        for c in self.constraints + self.objectives:
            for dn, a, b in c.distances:
                if dn not in have:
                    mech = mech.distance(dn, a, b)
                    have.add(dn)
        self.original = mechanism
        self.mechanism = mech
        self.positions = np.asarray(positions, float)
        outs = []
        for c in self.constraints + self.objectives:
            outs += [o for o in c.outputs if o not in outs]
        self.lifts = lift_outputs(outs, mech)
        outs += [o for o in self.lifts if o not in outs]
        if not outs:  # a problem with no criteria still checks assembly
            outs = [f"X({mech.points[-1]})"]
        self.outputs = tuple(outs)
        self._reference = None

    # ---- pickling: a file-made problem travels as its recipe ----------------------------
    def __reduce__(self):
        if self.source is None:
            raise TypeError(f"design problem {self.name!r} was not made from a model file: "
                            f"make it with assur.io.load_problem to run it on Dask")
        fn, args = self.source
        return fn, args

    # ---- variables -------------------------------------------------------------------
    @property
    def names(self) -> tuple:
        """The variables' names.

        Examples
        --------
        The bundled seed-003 design problem moves the hitch's four frame pivots:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> pb.names
        ('X01', 'Y01', 'X03', 'Y03', 'X05', 'Y05', 'X07', 'Y07')
        """
        return tuple(v.name for v in self.variables)

    @property
    def bounds(self) -> np.ndarray:
        """Bounds of the variables, shape (number of variables, 2) [SI].

        Examples
        --------
        The seed-003 hitch's pivots within 30 mm of the seed's (X01 = 415 mm):

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> pb.bounds.shape, np.round(pb.bounds[0] * 1e3, 1).tolist()  # X01 [mm]
        ((8, 2), [385.0, 445.0])
        """
        return np.array([(v.low, v.high) for v in self.variables])

    @property
    def x0(self) -> np.ndarray:
        """The original design's values of the variables, shape (number of variables,) [SI].

        Examples
        --------
        The seed-003 hitch's pivots 01, 03, 05, 07:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> np.round(pb.x0 * 1e3, 1).tolist()  # [mm]
        [415.0, 563.0, 250.0, 1112.0, 135.0, 480.0, 415.0, 895.0]
        """
        return np.array([float(self.original.params[v.name]) for v in self.variables])

    def sample(self, m, seed=None) -> np.ndarray:
        """``m`` designs drawn uniformly within the bounds, shape (m, number of variables).

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> X = pb.sample(3, seed=0)
        >>> X.shape, np.round(X[0, :2] * 1e3, 1).tolist()  # X01, Y01 of the first [mm]
        ((3, 8), [423.2, 549.2])
        >>> bool(((X >= pb.bounds[:, 0]) & (X <= pb.bounds[:, 1])).all())
        True
        """
        rng = np.random.default_rng(seed)
        lo, hi = self.bounds.T
        return lo + (hi - lo) * rng.random((int(m), len(self.variables)))

    def with_design(self, x):
        """The mechanism with the variables set to ``x`` [SI] (the original one's
        structure, without the distances the criteria add).

        Examples
        --------
        The seed-003 hitch with its top-link pivot Y07 30 mm higher:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> x = pb.x0.copy()
        >>> x[7] += 0.03  # [m]
        >>> round(pb.with_design(x).params["Y07"], 4)  # [m]
        0.925
        """
        x = np.asarray(x, float).reshape(-1)
        return self.original.with_params(**{v.name: float(xi)
                                            for v, xi in zip(self.variables, x)})

    def verify(self, x) -> str:
        """Check one design [SI] the way a single analysis does — every position, the
        branches kept continuous *between* positions too (the batches check the
        positions only): "" when it holds, else the :class:`AssemblyError` message.

        Examples
        --------
        The seed's design holds; a drawn one does not reach at the lowest position:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> pb.verify(pb.x0)
        ''
        >>> print(pb.verify(pb.sample(27, seed=1)[26]))  # doctest: +ELLIPSIS
        cylinder–lever group 'I (2,3)' (links 2, 3) cannot assemble at position 0 (S = 0.42): the distance |01–03| = 0.627009 m exceeds S + L3 = 0.42 + 0.2 = 0.62 m by 7.01 mm; ...
        """
        try:
            self.with_design(x).solve(self.positions)
        except AssemblyError as e:
            return str(e)
        return ""

    # ---- exact gradients ---------------------------------------------------------------
    def jet(self, x):
        """Exact sensitivities of the criteria's outputs at one design.

        Parameters
        ----------
        x : array_like, shape (number of variables,)
            The design [SI].

        Returns
        -------
        sens : assur.synthesis.sensitivity.Sensitivities
            The outputs the criteria read (:attr:`outputs` without the lift checks)
            over :attr:`positions` and their derivatives with respect to the variables
            (forward-mode dual numbers, :func:`assur.synthesis.sensitivity.sensitivities`).
        red : Reductions
            Their minimum, maximum and positions (:func:`~.criteria.jet_reductions`):
            ``c.value(red)`` and ``c.gradient(sens, red)`` give a criterion's value
            [SI] and its gradient [SI per variable unit].

        Raises
        ------
        AssemblyError
            The design does not assemble at some position.
        ModelError
            A value or derivative is not finite there (a singular position).

        Examples
        --------
        The seed-003 hitch's outputs over the 50 positions and their derivatives with
        respect to the 8 pivot coordinates; the objective's value (the smallest
        capacity reserve at S6, 8.94 %) and its gradient:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> sens, red = pb.jet(pb.x0)
        >>> sens.outputs, np.shape(sens.jacobian)  # (positions, outputs, variables)
        (('Y(56)', 'p(ГЦ)', 'reserve(ГЦ, S6, P6)'), (50, 3, 8))
        >>> obj = pb.objectives[0]
        >>> round(float(obj.value(red)[0]), 3)  # [%]
        8.941
        >>> round(float(obj.gradient(sens, red)[0]) / 1e3, 3)  # d/dX01 [%/mm]
        0.12
        """
        from ..sensitivity import sensitivities
        from .criteria import jet_reductions
        x = np.asarray(x, float).reshape(-1)
        if x.shape != (len(self.variables),):
            raise ModelError(f"design problem {self.name!r}: a design has "
                             f"{len(self.variables)} values ({list(self.names)}), got "
                             f"shape {x.shape}")
        outputs = [o for o in self.outputs if o not in self.lifts]
        sens = sensitivities(self.mechanism, self.positions, params=self.names,
                             outputs=outputs, values=dict(zip(self.names, x)))
        return sens, jet_reductions(sens, self._param_fn(x[None]))

    # ---- evaluation ------------------------------------------------------------------
    def reference(self):
        """The criteria's values for the original design (used by ``"original"``
        limits), evaluated once.

        Examples
        --------
        The seed-003 hitch's own lift range and peak pressure, the limits its
        ``"original"`` constraints compare with:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> ref = pb.reference()
        >>> round(float(ref["min Y(56)"][0]), 4), round(float(ref["max Y(56)"][0]), 4)  # [m]
        (0.2, 1.0432)
        >>> round(float(ref["max p(ГЦ)"][0]) / 1e6, 3)  # [MPa]
        16.064
        """
        if self._reference is None:
            red, nfail, err = self._reduce(self.x0[None])
            if nfail[0] or err[0] is not None:
                raise ModelError(f"design problem {self.name!r}: the original design does not "
                                 f"assemble over the positions, so a limit cannot be "
                                 f"'original': {err[0] or 'some positions fail'}")
            self._reference = {c.name: c.value(red) for c in self.constraints}
        return self._reference

    def evaluate(self, X) -> "Batch":
        """Evaluate a batch of designs.

        Parameters
        ----------
        X : array_like, shape (m, number of variables)
            Values of the variables [SI], one design per row.

        Returns
        -------
        Batch

        Examples
        --------
        Four designs of the bundled seed-003 design problem: the seed's own, its top
        link pivot Y07 30 mm higher, its cylinder pivot Y01 30 mm higher, and a drawn
        one that does not assemble.

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> X = np.array([pb.x0] * 3 + [pb.sample(27, seed=1)[26]])  # four designs [m]
        >>> X[1, 7] += 0.03; X[2, 1] += 0.03  # Y07, Y01 30 mm higher
        >>> b = pb.evaluate(X)
        >>> b.feasible.tolist()
        [True, True, False, False]
        >>> np.round(b.objective(), 3).tolist()  # min capacity reserve at S6 [%]
        [8.941, 12.527, 8.196, 0.0]
        >>> pb.evaluate(np.zeros((2, 3)))
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: design problem 'hitch_003': designs must have shape (m, 8) for the variables ['X01', 'Y01', 'X03', 'Y03', 'X05', 'Y05', 'X07', 'Y07'], got (2, 3)
        """
        X = np.atleast_2d(np.asarray(X, float))
        if X.ndim != 2 or X.shape[1] != len(self.variables) or not len(X):
            raise ModelError(f"design problem {self.name!r}: designs must have shape "
                             f"(m, {len(self.variables)}) for the variables {list(self.names)}, "
                             f"got {X.shape}")
        if not np.isfinite(X).all():
            i = int(np.argwhere(~np.isfinite(X))[0, 0])
            raise ModelError(f"design {i} has a value that is not finite: {X[i]!r}")
        needs_ref = any(isinstance(c.limit.value, str) and c.limit.value == "original"
                        for c in self.constraints)
        ref = self.reference() if needs_ref else {}
        parts = [self._evaluate_chunk(X[i:i + self.chunk], ref)
                 for i in range(0, len(X), self.chunk)]
        return Batch.concat(self, parts) if len(parts) != 1 else parts[0]

    def _params(self, X):
        return {v.name: X[:, j] for j, v in enumerate(self.variables)}

    def _reduce(self, X):
        """Reductions of the outputs over the positions for the designs ``X``, the
        number of failed positions per design and the engine's refusal per design
        (None where it evaluated). Splits the batch where the engine raises."""
        m = len(X)
        try:
            f = self.mechanism.evaluate(self.positions, self._params(X), outputs=self.outputs,
                                        reduce=True, on_failure="report")
        except (ModelError, AssemblyError) as e:
            if m == 1:
                zero = {o: np.zeros(1) for o in self.outputs}
                neg = {o: np.full(1, -1) for o in self.outputs}
                return (Reductions(zero, dict(zero), neg, dict(neg), self._param_fn(X)),
                        np.full(1, self.n_positions), [str(e)])
            h = m // 2
            a, b = self._reduce(X[:h]), self._reduce(X[h:])
            red = Reductions(*({o: np.concatenate([ra[o], rb[o]]) for o in self.outputs}
                               for ra, rb in ((a[0].mins, b[0].mins), (a[0].maxs, b[0].maxs),
                                              (a[0].argmins, b[0].argmins),
                                              (a[0].argmaxs, b[0].argmaxs))),
                             self._param_fn(X))
            return red, np.concatenate([a[1], b[1]]), a[2] + b[2]
        red = Reductions({o: f.min(o) for o in self.outputs}, {o: f.max(o) for o in self.outputs},
                         {o: f.argmin(o) for o in self.outputs},
                         {o: f.argmax(o) for o in self.outputs}, self._param_fn(X))
        return red, np.asarray(f.failures), [None] * m

    def _param_fn(self, X):
        params = self._params(X)
        m = len(X)

        def value(ref):
            return np.broadcast_to(self.mechanism.value_of(ref, {**self.mechanism.params,
                                                                 **params}), (m,))
        return value

    @property
    def n_positions(self) -> int:
        """Number of positions every design is checked at.

        Examples
        --------
        The bundled seed-003 design problem's ``[design] positions = 50`` over the
        hitch's range S = 0.420 … 0.670 m:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> pb.n_positions, round(float(pb.positions[0]), 3), round(float(pb.positions[-1]), 3)  # [m]
        (50, 0.42, 0.67)
        """
        return int(self.positions.shape[0])

    def _assembly_failures(self, X):
        """(group index, failure code, position) of the first failed position of each
        design of ``X`` (all of which fail somewhere): one kinematic pass."""
        mech = self.mechanism.with_params(**self._params(X))
        prog = mech.program(())
        ptab, trig, _ = mech.prepared(prog)
        qarr, _, m, n = mech.coordinate_array(self.positions, ptab.shape[1])
        if ptab.shape[1] == 1 and m > 1:
            ptab, trig = np.repeat(ptab, m, axis=1), np.repeat(trig, m, axis=1)
        status = execute(prog, ptab, qarr, n, False, trig=trig)["status"].reshape(m, n)
        failed = status >= 0
        pos = np.argmax(failed, axis=1)
        st = status[np.arange(m), pos]
        op, code = np.divmod(st, CODES_PER_OP)
        op = np.where(failed.any(axis=1), op, -1)
        return op, code, pos

    def _evaluate_chunk(self, X, ref):
        m = len(X)
        red, nfail, errors = self._reduce(X)
        status = np.zeros(m, np.int8)
        detail = np.full(m, -1, np.int64)  # group index / criterion index
        code = np.zeros(m, np.int64)
        where = np.full(m, -1, np.int64)  # position index
        amount = np.zeros(m)
        engine = np.array([e is not None for e in errors])
        status[engine] = ENGINE
        asm = (nfail > 0) & ~engine
        if asm.any():
            op, cd, pos = self._assembly_failures(X[asm])
            status[asm] = ASSEMBLY
            detail[asm], code[asm], where[asm] = op, cd, pos
        ok = status == FEASIBLE
        # a capacity needs the point to rise over the whole range
        for j, (o, _p) in enumerate(self.lifts.items()):
            bad = ok & (red.mins[o] <= 0)
            status[bad], detail[bad], where[bad] = LIFT, j, red.argmins[o][bad]
            amount[bad] = red.mins[o][bad]
            ok &= ~bad
        nc, no = len(self.constraints), len(self.objectives)
        # the criteria on the designs that evaluated; the others keep 0 and a margin of
        # minus their scale (what the values mean there: nothing)
        values, margins = np.zeros((m, nc)), np.zeros((m, nc))
        scales, objectives = np.ones((m, nc)), np.zeros((m, no))
        if ok.any():
            r = red.subset(ok)
            for i, c in enumerate(self.constraints):
                rf = None if c.name not in ref else ref[c.name]
                values[ok, i] = c.value(r)
                margins[ok, i] = c.margin(r, rf)
                scales[ok, i] = c.scale(r, rf)
            for i, c in enumerate(self.objectives):
                objectives[ok, i] = c.value(r)
        bad_rows = ~ok
        margins[bad_rows] = -1.0
        violated = margins < 0
        first = np.argmax(violated, axis=1) if nc else np.zeros(m, np.int64)
        viol = ok & violated.any(axis=1)
        status[viol], detail[viol] = CONSTRAINT, first[viol]
        amount[viol] = margins[viol, first[viol]]
        for i, c in enumerate(self.constraints):
            w = viol & (first == i)
            if w.any():
                where[w] = c.where(red.subset(w))
        # normalised total violation (DE's constraint, pymoo's G): assembly failures
        # count by the share of positions that fail
        violation = np.where(margins < 0, -margins / scales, 0.0).sum(axis=1)
        n = self.n_positions
        violation = np.where(bad_rows, 1.0 + nc + nfail / n, violation)
        return Batch(self, X, status, detail, code, where, amount, values, margins,
                     objectives, violation, nfail, list(errors))


class Batch:
    """Results of :meth:`Problem.evaluate` for m designs.

    Attributes
    ----------
    problem : Problem
    X : ndarray, shape (m, number of variables)
        The designs [SI].
    status : ndarray of int8, shape (m,)
        :data:`FEASIBLE`, :data:`ASSEMBLY`, :data:`ENGINE`, :data:`LIFT` or
        :data:`CONSTRAINT`.
    values : ndarray, shape (m, number of constraints)
        Each constraint's value [SI] (0 where the design did not evaluate).
    margins : ndarray, shape (m, number of constraints)
        ≥ 0 where a constraint holds [SI].
    objectives : ndarray, shape (m, number of objectives)
        Each objective's value [SI] (0 where the design did not evaluate).
    violation : ndarray, shape (m,)
        Sum of the constraints' violations relative to their limits; a design that did
        not evaluate counts 1 + number of constraints + its share of failed positions.
    failed_positions : ndarray of int, shape (m,)
        Positions at which each design does not assemble.

    Examples
    --------
    Four designs of the bundled seed-003 design problem: the seed's own, its top
    link pivot Y07 30 mm higher, its cylinder pivot Y01 30 mm higher, and a drawn
    one that does not assemble.

    >>> import numpy as np
    >>> from assur import io
    >>> from assur.io import load_problem
    >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
    >>> X = np.array([pb.x0] * 3 + [pb.sample(27, seed=1)[26]])  # four designs [m]
    >>> X[1, 7] += 0.03; X[2, 1] += 0.03  # Y07, Y01 30 mm higher
    >>> b = pb.evaluate(X)
    >>> len(b), b.status.tolist()  # FEASIBLE 0, ASSEMBLY 1, CONSTRAINT 4
    (4, [0, 0, 4, 1])
    >>> np.round(b.values[2], 4).tolist()  # min Y56, max Y56 [m], max p [Pa]
    [0.3253, 1.1181, 16174326.2144]
    >>> np.round(b.violation, 4).tolist(), b.failed_positions.tolist()
    ([0.0, 0.0, 0.6263, 4.04], [0, 0, 0, 2])
    """

    def __init__(self, problem, X, status, detail, code, where, amount, values, margins,
                 objectives, violation, failed_positions, errors):
        self.problem = problem
        self.X = X
        self.status = status
        self.detail, self.code, self.where, self.amount = detail, code, where, amount
        self.values, self.margins = values, margins
        self.objectives = objectives
        self.violation = violation
        self.failed_positions = failed_positions
        self.errors = errors

    @classmethod
    def concat(cls, problem, parts):
        """One batch of the designs of ``parts`` (batches of ``problem``), in order.

        Examples
        --------
        Four designs of the bundled seed-003 design problem: the seed's own, its top
        link pivot Y07 30 mm higher, its cylinder pivot Y01 30 mm higher, and a drawn
        one that does not assemble.

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> X = np.array([pb.x0] * 3 + [pb.sample(27, seed=1)[26]])  # four designs [m]
        >>> X[1, 7] += 0.03; X[2, 1] += 0.03  # Y07, Y01 30 mm higher
        >>> b = pb.evaluate(X)
        >>> from assur.synthesis.search import Batch
        >>> both = Batch.concat(pb, [b, pb.evaluate(pb.x0[None])])
        >>> len(both), both.feasible.tolist()
        (5, [True, True, False, False, True])
        """
        cat = np.concatenate
        return cls(problem, *(cat([getattr(p, a) for p in parts]) for a in
                              ("X", "status", "detail", "code", "where", "amount", "values",
                               "margins", "objectives", "violation", "failed_positions")),
                   [e for p in parts for e in p.errors])

    def __len__(self):
        return len(self.X)

    @property
    def feasible(self) -> np.ndarray:
        """True for the designs that assemble everywhere and meet every constraint.

        Examples
        --------
        Four designs of the bundled seed-003 design problem: the seed's own, its top
        link pivot Y07 30 mm higher, its cylinder pivot Y01 30 mm higher, and a drawn
        one that does not assemble.

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> X = np.array([pb.x0] * 3 + [pb.sample(27, seed=1)[26]])  # four designs [m]
        >>> X[1, 7] += 0.03; X[2, 1] += 0.03  # Y07, Y01 30 mm higher
        >>> b = pb.evaluate(X)
        >>> b.feasible.tolist()
        [True, True, False, False]
        """
        return self.status == FEASIBLE

    def objective(self, i=0) -> np.ndarray:
        """Values of objective ``i`` [SI], shape (m,).

        Examples
        --------
        Four designs of the bundled seed-003 design problem: the seed's own, its top
        link pivot Y07 30 mm higher, its cylinder pivot Y01 30 mm higher, and a drawn
        one that does not assemble.

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> X = np.array([pb.x0] * 3 + [pb.sample(27, seed=1)[26]])  # four designs [m]
        >>> X[1, 7] += 0.03; X[2, 1] += 0.03  # Y07, Y01 30 mm higher
        >>> b = pb.evaluate(X)
        >>> pb.objectives[0].name
        'min reserve(ГЦ, S6, P6)'
        >>> np.round(b.objective(0), 3).tolist()  # [%], 0 where not evaluated
        [8.941, 12.527, 8.196, 0.0]
        """
        return self.objectives[:, i]

    def scores(self) -> np.ndarray:
        """The objectives as quantities to minimise (maximised ones negated), shape
        (m, number of objectives).

        Examples
        --------
        The capacity reserve is maximised, so its scores are negated:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> X = np.array([pb.x0] * 3 + [pb.sample(27, seed=1)[26]])  # four designs [m]
        >>> X[1, 7] += 0.03; X[2, 1] += 0.03  # Y07, Y01 30 mm higher
        >>> b = pb.evaluate(X)
        >>> np.round(b.scores()[:, 0], 3).tolist()  # [%]
        [-8.941, -12.527, -8.196, -0.0]
        """
        sign = np.array([-1.0 if c.sense == "maximize" else 1.0
                         for c in self.problem.objectives])
        return self.objectives * sign

    def best(self) -> int:
        """Index of the best feasible design for the first objective (−1: none).

        Examples
        --------
        Raising the top link pivot Y07 by 30 mm gives the seed-003 hitch more reserve
        (12.5 % against 8.9 %) and keeps it feasible; the third design has 8.2 % but
        breaks a constraint:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> X = np.array([pb.x0] * 3 + [pb.sample(27, seed=1)[26]])  # four designs [m]
        >>> X[1, 7] += 0.03; X[2, 1] += 0.03  # Y07, Y01 30 mm higher
        >>> b = pb.evaluate(X)
        >>> b.best()
        1
        >>> pb.evaluate(X[2:]).best()  # no feasible design
        -1
        """
        if not self.feasible.any() or not self.problem.objectives:
            return -1
        s = np.where(self.feasible, self.scores()[:, 0], np.inf)
        return int(np.argmin(s))

    # ---- reasons -----------------------------------------------------------------------
    def _text(self, st, det, cd, w, lim=None):
        """The reason of one kind of failure (status, group or criterion, code) at
        position ``w``: made once per distinct combination of a batch."""
        pb = self.problem
        mech = pb.mechanism
        at = ""
        if w >= 0:
            coords = ", ".join(diagnostics.coordinate_text(mech, c, v) for c, v in
                               zip(mech.coordinates, np.atleast_1d(pb.positions[w])))
            at = f" at position {w} ({coords})"
        if st == ASSEMBLY:
            if det < len(mech.groups):
                g = mech.groups[det]
                links = diagnostics.group_links(mech, g)
                ltxt = f" (links {', '.join(links)})" if links else ""
                return (f"does not assemble: {g.kind} {g.name!r}{ltxt}: "
                        f"{FAILURE_TEXT.get(cd, f'failure code {cd}')}{at}")
            obj = (mech.links + mech.distances)[det - len(mech.groups)]
            return f"does not assemble: link {obj.name!r}: its two points coincide{at}"
        if st == LIFT:
            return (f"point {list(pb.lifts.values())[det]} does not rise with the coordinate: "
                    f"its transmission number {list(pb.lifts)[det]} ≤ 0{at}")
        c = pb.constraints[det]
        rel = "≥" if c.limit.sense == "at_least" else "≤"
        bound = f" {rel} {lim}" if isinstance(lim, str) else \
            f" {rel} {c.show(lim)}" if lim is not None else f" ({c.limit.sense})"
        return f"constraint {c.name}{bound} does not hold{at}"

    def _limits(self):
        """Each constraint's limit when it is the same for every design (a number,
        ``"original"``, a parameter that is not a variable) [SI]; the name of the
        variable it is; None when no design of the batch violates it."""
        out = []
        for j, c in enumerate(self.problem.constraints):
            v = c.limit.value if c.limit.value is not None else c.args.get("relief")
            if isinstance(v, str) and v in self.problem.names:
                out.append(v)  # a design variable: named, its value differs per design
                continue
            ev = np.flatnonzero(self.status == CONSTRAINT)
            ev = ev[self.detail[ev] == j]
            if not len(ev):
                out.append(None)
                continue
            i = ev[0]
            val, mg = self.values[i, j], self.margins[i, j]
            out.append(float(val - mg if c.limit.sense == "at_least" else val + mg))
        return out

    @property
    def reasons(self) -> list:
        """Why each design is infeasible ("" for a feasible one), e.g.
        ``"does not assemble: cylinder–lever group 'I (2,3)' (links 2, 3): … at
        position 0 (S = 0.42)"`` or ``"constraint max Y(56) ≥ 1.04316 m does not hold at
        position 49 (S = 0.67)"``. Vectorized: the words are made once per distinct
        (kind, group or constraint, failure, position) of the batch and spread to the
        designs by index; :meth:`reason` adds the design's own values.

        Examples
        --------
        Four designs of the bundled seed-003 design problem: the seed's own, its top
        link pivot Y07 30 mm higher, its cylinder pivot Y01 30 mm higher, and a drawn
        one that does not assemble.

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> X = np.array([pb.x0] * 3 + [pb.sample(27, seed=1)[26]])  # four designs [m]
        >>> X[1, 7] += 0.03; X[2, 1] += 0.03  # Y07, Y01 30 mm higher
        >>> b = pb.evaluate(X)
        >>> for r in b.reasons:
        ...     print(repr(r))
        ''
        ''
        'constraint min Y(56) ≤ 0.2 m does not hold at position 0 (S = 0.42)'
        "does not assemble: cylinder–lever group 'I (2,3)' (links 2, 3): its outer joints are farther apart than its two sides reach at position 0 (S = 0.42)"
        """
        out = np.full(len(self), "", dtype=object)
        bad = np.flatnonzero(~self.feasible & (self.status != ENGINE))
        if len(bad):
            # one int64 key per design: status, group or constraint, code, position
            d, c, w = (self.detail[bad].astype(np.int64) + 1, self.code[bad].astype(np.int64),
                       self.where[bad].astype(np.int64) + 1)
            nd, nc, nw = int(d.max()) + 1, int(c.max()) + 1, int(w.max()) + 1
            key = ((self.status[bad].astype(np.int64) * nd + d) * nc + c) * nw + w
            uniq, inv = np.unique(key, return_inverse=True)
            lims = self._limits()
            texts = []
            for k in uniq.tolist():
                k, wi = divmod(k, nw)
                k, ci = divmod(k, nc)
                st, di = divmod(k, nd)
                texts.append(self._text(st, di - 1, ci, wi - 1,
                                        lims[di - 1] if st == CONSTRAINT else None))
            out[bad] = np.array(texts, dtype=object)[inv.reshape(-1)]
        for i in np.flatnonzero(self.status == ENGINE):
            out[i] = f"refused by the engine: {self.errors[i]}"
        return out.tolist()

    def reason(self, i) -> str:
        """The reason of design ``i`` with its own values (a constraint's value and
        limit, a transmission number), "" for a feasible design.

        Examples
        --------
        Y01 30 mm higher lifts the seed-003 hitch's lowest position of 56 to 0.325 m:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> X = np.array([pb.x0] * 3 + [pb.sample(27, seed=1)[26]])  # four designs [m]
        >>> X[1, 7] += 0.03; X[2, 1] += 0.03  # Y07, Y01 30 mm higher
        >>> b = pb.evaluate(X)
        >>> b.reason(2)
        'constraint min Y(56) ≤ 0.2 m does not hold at position 0 (S = 0.42): 0.325266 m'
        >>> b.reason(0)
        ''
        """
        st = int(self.status[i])
        if st == FEASIBLE:
            return ""
        if st == ENGINE:
            return f"refused by the engine: {self.errors[i]}"
        det, w = int(self.detail[i]), int(self.where[i])
        if st == CONSTRAINT:
            c = self.problem.constraints[det]
            val, mg = self.values[i, det], self.margins[i, det]
            lim = val - mg if c.limit.sense == "at_least" else val + mg
            return (self._text(st, det, int(self.code[i]), w, lim)
                    + f": {c.show(val)}")
        text = self._text(st, det, int(self.code[i]), w)
        if st == LIFT:
            text += f": {self.amount[i]:.4g}"
        return text

    def explain(self, i) -> str:
        """The engine's full message for an infeasible design ``i`` (for an assembly
        failure: the group's own words with its values, as
        :class:`~assur.errors.AssemblyError` gives them).

        Examples
        --------
        The drawn design that does not assemble, in the group's own words:

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> X = np.array([pb.x0] * 3 + [pb.sample(27, seed=1)[26]])  # four designs [m]
        >>> X[1, 7] += 0.03; X[2, 1] += 0.03  # Y07, Y01 30 mm higher
        >>> b = pb.evaluate(X)
        >>> print(b.explain(3))
        cylinder–lever group 'I (2,3)' (links 2, 3) cannot assemble at position 0 (S = 0.42): the distance |01–03| = 0.627009 m exceeds S + L3 = 0.42 + 0.2 = 0.62 m by 7.01 mm; 2 of 50 positions fail (S = 0.42…0.425102)
        >>> b.explain(2) == b.reason(2)  # not an assembly failure
        True
        """
        if int(self.status[i]) != ASSEMBLY:
            return self.reason(i)
        pb = self.problem
        try:
            pb.mechanism.solve(pb.positions, pb._params(self.X[i:i + 1]),
                               check_continuity=False)
        except AssemblyError as e:
            return str(e)
        return self.reason(i)

    def to_frame(self):
        """A :class:`pandas.DataFrame`: one row per design, the variables [SI], the
        objectives and constraint values [SI], ``feasible``, ``status``,
        ``failed_positions`` and ``reason``.

        Examples
        --------
        Four designs of the bundled seed-003 design problem: the seed's own, its top
        link pivot Y07 30 mm higher, its cylinder pivot Y01 30 mm higher, and a drawn
        one that does not assemble.

        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> X = np.array([pb.x0] * 3 + [pb.sample(27, seed=1)[26]])  # four designs [m]
        >>> X[1, 7] += 0.03; X[2, 1] += 0.03  # Y07, Y01 30 mm higher
        >>> b = pb.evaluate(X)
        >>> df = b.to_frame()
        >>> df.shape  # 8 variables, 1 objective, 3 constraints, 5 more columns
        (4, 17)
        >>> df[["feasible", "status", "failed_positions"]].values.tolist()
        [[True, 0, 0], [True, 0, 0], [False, 4, 0], [False, 1, 2]]
        """
        import pandas as pd
        pb = self.problem
        cols = {v.name: self.X[:, j] for j, v in enumerate(pb.variables)}
        for j, c in enumerate(pb.objectives):
            cols[f"objective: {c.sense} {c.name}"] = self.objectives[:, j]
        for j, c in enumerate(pb.constraints):
            cols[f"constraint: {c.name}"] = self.values[:, j]
        cols["feasible"] = self.feasible
        cols["status"] = self.status
        cols["failed_positions"] = self.failed_positions
        cols["violation"] = self.violation
        cols["reason"] = self.reasons
        return pd.DataFrame(cols)
