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
* along a held path (``[range]`` with ``hold``, :mod:`assur.core.held`), its held
  coordinate cannot reach its target within its limits at some position ("assembly":
  the hold, why, the position — the held coordinates of every design solved at every
  position first, vectorized over designs × positions by
  :func:`assur.core.held.hold_paths`; the outputs then evaluated at each design's own
  positions);
* a capacity it reads has a transmission number ≤ 0 somewhere ("lift");
* a constraint does not hold ("constraint": the first one violated, by how much).

No design stops the batch.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import AssemblyError, ModelError
from ._batch import (ASSEMBLY, CONSTRAINT, ENGINE, FAILURE_TEXT, FEASIBLE, LIFT, Batch,
                     _evaluate_chunk)
from .criteria import Reductions, lift_outputs

__all__ = ["Variable", "Problem", "Batch", "FEASIBLE", "ASSEMBLY", "ENGINE", "LIFT",
           "CONSTRAINT", "FAILURE_TEXT"]

#: designs per kernel call (bounds memory: q and status take 16 B per position)
CHUNK = 1 << 16

#: designs per block of :meth:`Problem.draw` (one random stream per block)
BLOCK = 4096


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
        Where every design is checked [m or rad]; with ``path``, ``path.q`` (the
        original design's positions).
    variables : sequence of Variable
    constraints : sequence of Criterion
        Each with a :class:`~assur.synthesis.search.criteria.Limit`.
    objectives : sequence of Criterion
        Each with a sense (maximize or minimize); none for a plain sweep.
    name : str, optional
    source : tuple, optional
        How to rebuild the problem in another process (``(function, args)``, set by
        :func:`assur.io.load_problem`: the model's content, not its path): a problem
        made from a file pickles as that recipe, so Dask workers rebuild it instead of
        receiving compiled kernels.
    identity : str, optional
        What identifies the recipe (the hash of the model's content, the variables, the
        positions), recorded in a sweep's manifest so that ``--resume`` continues only
        the same problem; default: a hash of the names, bounds and positions.
    chunk : int
        Designs per kernel call.
    polish : bool
        Whether :func:`~assur.synthesis.search.search.optimize` polishes differential
        evolution's optimum by SLSQP with exact gradients unless told otherwise
        (``[design] polish`` of a model file); False along a held path (no exact
        gradients there yet, :meth:`jet`).
    path : assur.core.held.HeldPath, optional
        The original design's held path (``Model.path``): every design is checked at
        its own positions, its held coordinates solved at each value of the path's
        parameter ``path.s`` with its parameters (and its targets and limits, where
        a hold's ``refs`` name variables).

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
                 name=None, source=None, chunk=CHUNK, polish=True, identity=None, path=None):
        self.variables = tuple(variables)
        self._identity = identity
        self.path = path
        self.polish = bool(polish) and path is None
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
        if path is not None and not np.array_equal(self.positions, path.q):
            raise ModelError(f"design problem {self.name!r}: along a held path the "
                             f"positions are the path's (path.q, shape {path.q.shape}), "
                             f"got shape {self.positions.shape}")
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

    def draw(self, seed, start, stop) -> np.ndarray:
        """Designs ``start`` … ``stop − 1`` of the sequence of seed ``seed``, drawn
        uniformly within the bounds, shape (stop − start, number of variables) [SI].

        Design ``i`` is the same whatever range it is drawn in: the sequence is made of
        blocks of :data:`BLOCK` designs, block ``k`` drawn by its own generator
        ``default_rng([seed, k])`` — so a Dask worker draws its chunk from (seed, range)
        and a sweep's results do not depend on how it was cut into tasks.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> X = pb.draw(1, 0, 10_000)
        >>> X.shape, bool((pb.draw(1, 4000, 4100) == X[4000:4100]).all())
        ((10000, 8), True)
        >>> bool(((X >= pb.bounds[:, 0]) & (X <= pb.bounds[:, 1])).all())
        True
        """
        start, stop = int(start), int(stop)
        if not 0 <= start <= stop:
            raise ModelError(f"designs {start} … {stop}: expected 0 ≤ start ≤ stop")
        lo, hi = self.bounds.T
        nv = len(self.variables)
        out = np.empty((stop - start, nv))
        for k in range(start // BLOCK, -(-stop // BLOCK)):
            a, b = max(start, k * BLOCK), min(stop, (k + 1) * BLOCK)
            u = np.random.default_rng([int(seed), k]).random((b - k * BLOCK, nv))
            out[a - start:b - start] = lo + (hi - lo) * u[a - k * BLOCK:]
        return out

    @property
    def identity(self) -> str:
        """What identifies this problem in a sweep's manifest (hex): the recipe's
        (the model's content hash, the variables, the positions) when made from a
        file, else a hash of the variables' names and bounds and of the positions.

        Examples
        --------
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> a = load_problem(io.bundled("hitch_003_design"), positions=6)
        >>> b = load_problem(io.bundled("hitch_003_design"), positions=7)
        >>> len(a.identity), a.identity != b.identity
        (64, True)
        """
        if self._identity is None:
            import hashlib
            h = hashlib.sha256(repr((self.name, self.names)).encode("utf-8"))
            h.update(np.ascontiguousarray(self.bounds).tobytes())
            h.update(np.ascontiguousarray(self.positions).tobytes())
            self._identity = h.hexdigest()
        return self._identity

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
            self.with_design(x).solve(self.positions_of(x))
        except AssemblyError as e:
            return str(e)
        except ModelError as e:
            if self.path is None:
                raise
            return str(e)
        return ""

    def positions_of(self, x) -> np.ndarray:
        """The positions design ``x`` [SI] is checked at [m or rad]: :attr:`positions`,
        or along a held path its own (:func:`assur.core.held.hold_path` with its
        parameters), shape (n, k).

        Raises
        ------
        ModelError, AssemblyError
            Along a held path: the design's held coordinate cannot reach its target
            within its limits at some position (the message names it).

        Examples
        --------
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> pb.positions_of(pb.x0) is pb.positions             # no held path: the same
        True
        """
        if self.path is None:
            return self.positions
        from ...core.held import hold_path
        x = np.asarray(x, float).reshape(1, -1)
        p = self.path
        return hold_path(self.mechanism, p.along, p.s, p.holds, self._params(x),
                         along_unit=p.along_unit).q

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
        if self.path is not None:
            raise ModelError(f"design problem {self.name!r}: no exact gradients along a "
                             f"held path yet ({self.path.describe()}): the positions move "
                             f"with the design (search without polish)")
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
            red, nfail, err, held = self._reduce(self.x0[None])
            if held is not None and not held.ok[0]:
                err = [str(held.error(0))]
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
        self._check_call(min(len(X), self.chunk))  # before the kernel allocates
        ref = self.reference() if needs_ref else {}
        parts = [_evaluate_chunk(self, X[i:i + self.chunk], ref)
                 for i in range(0, len(X), self.chunk)]
        return Batch.concat(self, parts) if len(parts) != 1 else parts[0]

    def _params(self, X):
        return {v.name: X[:, j] for j, v in enumerate(self.variables)}

    def _reduce(self, X):
        """Reductions of the outputs over the positions for the designs ``X``, the
        number of failed positions per design, the engine's refusal per design (None
        where it evaluated) and, along a held path, the designs' paths
        (:class:`assur.core.held.HeldPaths`; else None): a design whose held
        coordinate cannot reach is not evaluated (its reductions 0, its failed
        positions the scan's)."""
        if self.path is None:
            return self._reduce_at(X, None) + (None,)
        from ...core.held import hold_paths
        p = self.path
        held = hold_paths(self.mechanism, p.along, p.s, p.holds, self._params(X),
                          along_unit=p.along_unit)
        m = len(X)
        red0 = [{o: np.zeros(m) for o in self.outputs} for _ in range(2)]
        red0 += [{o: np.full(m, -1, np.int64) for o in self.outputs} for _ in range(2)]
        nfail = np.where(held.ok, 0, held.failed_positions)
        errors = [None] * m
        w = np.flatnonzero(held.ok)
        if len(w):
            red, nf, err = self._reduce_at(X[w], held.q[w])
            for d, r in zip(red0, (red.mins, red.maxs, red.argmins, red.argmaxs)):
                for o in self.outputs:
                    d[o][w] = r[o]
            nfail[w] = nf
            for j, e in zip(w.tolist(), err):
                errors[j] = e
        return Reductions(*red0, self._param_fn(X)), nfail, errors, held

    def _reduce_at(self, X, Q):
        """:meth:`_reduce` at the positions Q of each design, shape (m, n, k) (None:
        :attr:`positions` for all). Splits the batch where the engine raises."""
        m = len(X)
        try:
            f = self.mechanism.evaluate(self.positions if Q is None else Q, self._params(X),
                                        outputs=self.outputs, reduce=True,
                                        on_failure="report")
        except (ModelError, AssemblyError) as e:
            if m == 1:
                zero = {o: np.zeros(1) for o in self.outputs}
                neg = {o: np.full(1, -1) for o in self.outputs}
                return (Reductions(zero, dict(zero), neg, dict(neg), self._param_fn(X)),
                        np.full(1, self.n_positions), [str(e)])
            h = m // 2
            a = self._reduce_at(X[:h], None if Q is None else Q[:h])
            b = self._reduce_at(X[h:], None if Q is None else Q[h:])
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

    # ---- memory ------------------------------------------------------------------------
    @property
    def bytes_per_design(self) -> int:
        """Estimated memory one design takes in a :class:`Batch` [bytes]: its variables,
        its status and reason fields, its criteria's values, margins and scales, the
        reductions of every output (twice: the chunks' parts and their concatenation).

        Examples
        --------
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> pb.bytes_per_design  # [bytes]
        1088
        """
        nv, nc, no = len(self.variables), len(self.constraints), len(self.objectives)
        return 16 * (2 * nv + 3 * nc + no + 8 * len(self.outputs) + 10)

    @property
    def bytes_per_position(self) -> int:
        """Memory one position of one design takes in a kernel call [bytes]: the
        coordinates and the status (:meth:`assur.Mechanism.evaluate` with ``reduce=True``).

        Examples
        --------
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> pb.bytes_per_position  # one coordinate [bytes]
        24
        """
        return 8 * (len(self.mechanism.coordinates) + 2)

    def check_memory(self, designs, what, reduce, *, chunk=None, per_design=0):
        """Refuse ``designs`` designs before anything is allocated when they, or one
        kernel call over them (at most ``chunk`` designs, and :attr:`chunk`, × the
        positions), would exceed :func:`assur.core.inputs.max_memory`.

        Parameters
        ----------
        designs : float
            Designs held at once (a sweep's samples, a population).
        what : str
            The request, for the message (e.g. ``"sweep: samples = 1e+09"``).
        reduce : str
            What to make smaller (e.g. ``"the samples (--samples)"``).
        chunk : int, optional
            Designs per task of the executor (default: :attr:`chunk`).
        per_design : int
            Bytes a design takes besides its :class:`Batch` row (e.g. the search's
            own copies of a population).

        Raises
        ------
        ModelError
            With the estimate and the limit.

        Examples
        --------
        >>> import os
        >>> from unittest import mock
        >>> from assur import io
        >>> from assur.io import load_problem
        >>> pb = load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm
        >>> with mock.patch.dict(os.environ, {"ASSUR_MAX_MEMORY": "1 MiB"}):
        ...     pb.check_memory(1e6, "sweep: samples = 1e+06", "the samples (--samples)")
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: sweep: samples = 1e+06: 1e+06 designs would need about 1.01 GiB of memory (limit 1 MiB; set ASSUR_MAX_MEMORY to change it, or reduce the samples (--samples))
        """
        from ...core.inputs import check_memory
        designs = float(designs)
        check_memory(designs, self.bytes_per_design + per_design, what, unit="designs",
                     reduce=reduce)
        self._check_call(min(designs, self.chunk, chunk or self.chunk))

    def _check_call(self, designs):
        """Refuse one kernel call of ``designs`` designs × the positions that would
        exceed the memory limit (a sweep holds one call at a time: the per-call size
        counts, not the total)."""
        from ...core.inputs import check_memory
        n = self.n_positions
        check_memory(designs * n, self.bytes_per_position,
                     f"design problem {self.name!r}: {designs:.4g} designs × {n} positions "
                     f"in one kernel call", unit="positions",
                     reduce="the positions ([design] positions or --positions) or the "
                            "designs per task (--chunk)")

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
