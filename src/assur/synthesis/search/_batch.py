"""Results of a batch of designs (:class:`Batch`: values, feasibility and every
infeasible design's reason) and how one chunk of designs becomes one
(:mod:`assur.synthesis.search.problem`)."""

from __future__ import annotations

import numpy as np

from ...core import diagnostics
from ...core.program import execute
from ...errors import AssemblyError, ModelError
from ...kernel.emit import CODES_PER_OP

__all__ = ["Batch", "FEASIBLE", "ASSEMBLY", "ENGINE", "LIFT", "CONSTRAINT", "FAILURE_TEXT"]

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


def _held_base(mech):
    """The first :attr:`Batch.detail` of a held path's failure (hold 0): after the
    groups, links and distances a failure to assemble names."""
    return len(mech.groups) + len(mech.links) + len(mech.distances)


def _assembly_failures(problem, X, Q=None):
    """(group index, failure code, position) of the first failed position of each
    design of ``X`` (all of which fail somewhere) at :attr:`Problem.positions` or at
    each design's own positions ``Q`` (m, n, k): one kinematic pass."""
    mech = problem.mechanism.with_params(**problem._params(X))
    prog = mech.program(())
    ptab, trig, _ = mech.prepared(prog)
    qarr, _, m, n = mech.coordinate_array(problem.positions if Q is None else Q,
                                          ptab.shape[1])
    if ptab.shape[1] == 1 and m > 1:
        ptab, trig = np.repeat(ptab, m, axis=1), np.repeat(trig, m, axis=1)
    status = execute(prog, ptab, qarr, n, False, trig=trig)["status"].reshape(m, n)
    failed = status >= 0
    pos = np.argmax(failed, axis=1)
    st = status[np.arange(m), pos]
    op, code = np.divmod(st, CODES_PER_OP)
    op = np.where(failed.any(axis=1), op, -1)
    return op, code, pos


def _evaluate_chunk(problem, X, ref):
    """The :class:`Batch` of the designs ``X`` of ``problem`` (one kernel call, split
    only where the engine refuses a design); ``ref``: the constraints' values for the
    original design, by name, where a limit is ``"original"``."""
    m = len(X)
    red, nfail, errors, held = problem._reduce(X)
    status = np.zeros(m, np.int8)
    detail = np.full(m, -1, np.int64)  # group index / criterion index
    code = np.zeros(m, np.int64)
    where = np.full(m, -1, np.int64)  # position index
    amount = np.zeros(m)
    engine = np.array([e is not None for e in errors])
    status[engine] = ENGINE
    hf = np.zeros(m, bool) if held is None else ~held.ok
    if hf.any():  # a held coordinate that cannot reach its target: no positions
        status[hf] = ASSEMBLY
        detail[hf] = _held_base(problem.mechanism) + held.hold[hf]
        code[hf], where[hf] = held.code[hf], held.position[hf]
    asm = (nfail > 0) & ~engine & ~hf
    if asm.any():
        op, cd, pos = _assembly_failures(problem, X[asm],
                                         None if held is None else held.q[asm])
        status[asm] = ASSEMBLY
        detail[asm], code[asm], where[asm] = op, cd, pos
    ok = status == FEASIBLE
    # a capacity needs the point to rise over the whole range
    for j, (o, _p) in enumerate(problem.lifts.items()):
        bad = ok & (red.mins[o] <= 0)
        status[bad], detail[bad], where[bad] = LIFT, j, red.argmins[o][bad]
        amount[bad] = red.mins[o][bad]
        ok &= ~bad
    nc, no = len(problem.constraints), len(problem.objectives)
    # the criteria on the designs that evaluated; the others keep 0 and a margin of
    # minus their scale (what the values mean there: nothing)
    values, margins = np.zeros((m, nc)), np.zeros((m, nc))
    scales, objectives = np.ones((m, nc)), np.zeros((m, no))
    if ok.any():
        r = red.subset(ok)
        for i, c in enumerate(problem.constraints):
            rf = None if c.name not in ref else ref[c.name]
            values[ok, i] = c.value(r)
            margins[ok, i] = c.margin(r, rf)
            scales[ok, i] = c.scale(r, rf)
        for i, c in enumerate(problem.objectives):
            objectives[ok, i] = c.value(r)
    bad_rows = ~ok
    margins[bad_rows] = -1.0
    violated = margins < 0
    first = np.argmax(violated, axis=1) if nc else np.zeros(m, np.int64)
    viol = ok & violated.any(axis=1)
    status[viol], detail[viol] = CONSTRAINT, first[viol]
    amount[viol] = margins[viol, first[viol]]
    for i, c in enumerate(problem.constraints):
        w = viol & (first == i)
        if w.any():
            where[w] = c.where(red.subset(w))
    # normalised total violation (DE's constraint, pymoo's G): assembly failures
    # count by the share of positions that fail
    violation = np.where(margins < 0, -margins / scales, 0.0).sum(axis=1)
    n = problem.n_positions
    violation = np.where(bad_rows, 1.0 + nc + nfail / n, violation)
    return Batch(problem, X, status, detail, code, where, amount, values, margins,
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
        if w >= 0 and pb.path is not None:  # the held coordinates differ per design
            at = (f" at position {w} "
                  f"({diagnostics.coordinate_text(mech, pb.path.along, pb.path.s[w])})")
        elif w >= 0:
            coords = ", ".join(diagnostics.coordinate_text(mech, c, v) for c, v in
                               zip(mech.coordinates, np.atleast_1d(pb.positions[w])))
            at = f" at position {w} ({coords})"
        if st == ASSEMBLY and pb.path is not None and det >= _held_base(mech):
            from ...core.held import HELD_TEXT
            hd = pb.path.holds[det - _held_base(mech)]
            why = HELD_TEXT.get(cd, f"failure code {cd}").format(c=hd.coordinate,
                                                                 y=hd.quantity)
            return f"does not assemble along the held path: {why}{at}"
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
        try:  # along a held path: the design's own positions (or why it has none)
            pb.mechanism.solve(pb.positions_of(self.X[i]), pb._params(self.X[i:i + 1]),
                               check_continuity=False)
        except (AssemblyError, ModelError) as e:
            if isinstance(e, ModelError) and pb.path is None:
                raise
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
