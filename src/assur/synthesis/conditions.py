"""Design solving — Mathcad's Given/Find: unknown parameters fixed by conditions.

A :class:`Condition` says: choose the parameter ``unknown`` inside ``bracket`` so
that ``quantity`` (a point coordinate ``X<point>``/``Y<point>``, a link angle
``phi<link>`` or a named distance) equals ``target`` at the position ``at`` of the
generalized coordinate(s). Seed 003 §2.2–2.3:

* L4 such that Y56(Smin) = 0.2 m;
* Sp such that Y56(Sp) = 0.4 m (the working stroke: the unknown is the position);
* L7 such that φ6(Sp) = 90°.

Conditions are solved in dependency order: each step solves the one condition
whose other unknowns are all known. The root in the bracket is located by
evaluating the condition on a grid of the bracket — one vectorized batch, the
candidate values being designs — and refined with Brent's method
(:func:`scipy.optimize.brentq`). No root, or several, is an error that names them.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..core.held import output_kind
from ..errors import AssemblyError, ModelError

__all__ = ["DesignError", "Condition", "SolvedCondition", "solve_conditions", "condition_residual",
           "SCAN_POINTS"]

#: grid of the bracket used to find sign changes (and to detect several roots)
SCAN_POINTS = 257


class DesignError(ModelError):
    """A design condition has no root, or several, in its bracket.

    Examples
    --------
    Seed 003's condition Y56(Smin) = 0.2 m has its root L4 = 0.6613 m outside
    [0.7, 0.8] m:

    >>> from assur import examples
    >>> from assur.synthesis.conditions import Condition, DesignError, solve_conditions
    >>> cond = Condition("L4", (0.7, 0.8), {"S": 0.42}, "Y56", 0.2)
    >>> try:
    ...     solve_conditions(examples.hitch_003(), [cond])
    ... except DesignError as e:
    ...     print(e)
    condition Y56(S = 0.42) = 0.2 for L4: no root for L4 in the bracket [0.7, 0.8]: Y56 − target stays between -0.3006 and -0.08489
    """


@dataclass(frozen=True)
class Condition:
    """``quantity(at) = target`` fixes the parameter ``unknown`` in ``bracket``.

    Parameters
    ----------
    unknown : str
        Parameter to solve for [SI].
    bracket : (float, float)
        Search interval of the unknown [SI].
    at : mapping of coordinate name to float or parameter name
        The position where the condition holds (e.g. ``{"S": "Smin"}``).
    quantity : str
        ``X<point>``, ``Y<point>`` [m], ``phi<link>`` [rad] or a distance name [m].
    target : float
        Required value [m or rad].
    source : str, optional
        Where the condition comes from (a file and line), for messages.
    unit : assur.core.quantities.Unit, optional
        The unit to show the target (and the residual) in: the one the file wrote
        ``equals`` in (``"90 deg"``); None: the quantity's default (m, or degrees).
    unknown_unit : assur.core.quantities.Unit, optional
        The unit to show the unknown (its bracket, roots) in: the one the file gives
        the parameter; None: SI. Messages of a condition that fails say so in these
        units (a bracket in inches, a target in degrees).

    Examples
    --------
    Seed 003 §2.3: L7 such that the implement 6 stands upright, φ6(Sp) = 90°, at the
    working stroke Sp (a parameter named as the position):

    >>> import math
    >>> from assur.synthesis.conditions import Condition
    >>> cond = Condition("L7", (0.56, 1.05), {"S": "Sp"}, "phi6", math.pi / 2)
    >>> cond.describe()
    'phi6(S = Sp) = 1.5708 for L7'
    """

    unknown: str
    bracket: tuple
    at: dict
    quantity: str
    target: float
    source: str | None = None
    unit: object = None
    unknown_unit: object = None

    def shown(self, value, of="quantity", digits=6) -> str:
        """``value`` [SI] of the quantity (or ``of="unknown"``) as the messages show it:
        in :attr:`unit` (:attr:`unknown_unit`) with its symbol, else as it is [SI].

        Examples
        --------
        >>> import math
        >>> from assur.core.quantities import Unit
        >>> from assur.synthesis.conditions import Condition
        >>> c = Condition("L7", (0.56, 1.05), {"S": "Sp"}, "phi6", math.pi / 2,
        ...               unit=Unit("deg", math.pi / 180), unknown_unit=Unit("in", 0.0254))
        >>> c.shown(math.pi / 2), c.shown(0.6604, "unknown")
        ('90 deg', '26 in')
        """
        u = self.unit if of == "quantity" else self.unknown_unit
        if u is None:
            return f"{value:.{digits}g}"
        return f"{float(u.of(value)):.{digits}g} {u.text}"

    def describe(self):
        """The condition in one line, ``quantity(position) = target for unknown (source)``
        (the target in SI).

        Examples
        --------
        Seed 003 §2.2, with where it comes from:

        >>> from assur.synthesis.conditions import Condition
        >>> Condition("L4", (0.48, 0.9), {"S": "Smin"}, "Y56", 0.2, source="seed 003 §2.2").describe()
        'Y56(S = Smin) = 0.2 for L4 (seed 003 §2.2)'
        """
        at = ", ".join(f"{k} = {v}" for k, v in self.at.items())
        src = f" ({self.source})" if self.source else ""
        return f"{self.quantity}({at}) = {self.shown(self.target)} for {self.unknown}{src}"


@dataclass
class SolvedCondition:
    """The outcome of one condition: the root [SI] and its residual.

    Examples
    --------
    Seed 003's L4 from Y56(Smin) = 0.2 m (printed L4 = 0.6613 m): the residual is at
    rounding level, and the bracket's scan counts among the evaluations.

    >>> from assur import examples
    >>> from assur.synthesis.conditions import Condition, solve_conditions
    >>> cond = Condition("L4", (0.48, 0.9), {"S": 0.42}, "Y56", 0.2)
    >>> _, (sc,) = solve_conditions(examples.hitch_003(), [cond])
    >>> round(sc.value, 4), abs(sc.residual) < 1e-12, sc.evaluations > 257  # L4 [m]
    (0.6613, True, True)
    """

    condition: Condition
    value: float
    residual: float
    evaluations: int = 0
    notes: list = field(default_factory=list)


def _quantity(mech, name):
    """('x'|'y'|'phi'|'dist', object name) of a condition's quantity: a declared link's
    angle, a moving point's coordinate or a distance (:func:`assur.core.held.output_kind`),
    or ModelError."""
    return output_kind(mech, name, what="quantity", declared=True)


def _depends(mech, cond, unknowns):
    """The unknowns a condition's value depends on (through the groups that define
    its quantity, and its position)."""
    kind, obj = _quantity(mech, cond.quantity)
    if kind == "phi":
        lk = next(l for l in mech.links if l.name == obj)
        pts = (lk.tail, lk.head)
    elif kind == "dist":
        dd = next(d for d in mech.distances if d.name == obj)
        pts = (dd.a, dd.b)
    else:
        pts = (obj,)
    last = max(mech.defining_index(p) for p in pts)
    used = set()
    for g in mech.groups[:last + 1]:
        for ref in g.refs().values():
            if isinstance(ref, str):
                used.add(ref)
    for v in cond.at.values():
        if isinstance(v, str):
            used.add(v)
    return {u for u in unknowns if u in used}


def condition_residual(mech, cond, values):
    """Residual quantity − target [m or rad] of a condition for the unknown at each
    of ``values`` (a batch of designs), and whether each assembles there.

    Parameters
    ----------
    mech : Mechanism
    cond : Condition
    values : array_like, shape (m,)
        Values of ``cond.unknown`` [SI].

    Returns
    -------
    residual : ndarray, shape (m,)
        ``quantity(at) − target``; angles compared modulo 2π [m or rad].
    ok : ndarray of bool, shape (m,)
        False where the mechanism does not assemble (its residual is meaningless).

    Examples
    --------
    Y56(S = 0.42 m) − 0.2 m of the seed-003 hitch for three values of L4: it changes
    sign near the seed's root L4 = 0.6613 m.

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.synthesis.conditions import Condition, condition_residual
    >>> cond = Condition("L4", (0.48, 0.9), {"S": 0.42}, "Y56", 0.2)
    >>> r, ok = condition_residual(examples.hitch_003(), cond, [0.6, 0.6613, 0.7])
    >>> np.round(r * 1e3, 3).tolist(), ok.tolist()  # [mm]
    ([134.518, -0.037, -84.89], [True, True, True])
    """
    params = {cond.unknown: np.asarray(values, float)}
    # the unknown's values go to the solve as a batch of parameters; a mechanism with
    # them set is built only when a position of `at` is written with the unknown
    by_unknown = any(isinstance(v, str) and cond.unknown in v for v in cond.at.values())
    m = mech.with_params(**params) if by_unknown else mech
    q = []
    for c in mech.coordinates:
        if c not in cond.at:
            raise ModelError(f"condition {cond.describe()}: give the position of every "
                             f"coordinate {list(mech.coordinates)} in `at`")
        v = cond.at[c]
        q.append(np.broadcast_to(np.asarray(m.value_of(v), float), (len(values),)))
    q = np.stack(q, axis=-1)  # (m, k)
    qq = q[:, None, 0] if len(mech.coordinates) == 1 else q[:, None, :]
    res = m.solve(qq, params=None if by_unknown else params, on_failure="report",
                  check_continuity=False)
    kind, obj = _quantity(mech, cond.quantity)
    if kind == "phi":
        val = res.phi(obj)
    elif kind == "dist":
        val = res.length(obj)
    else:
        val = res.x(obj) if kind == "x" else res.y(obj)
    val = val.reshape(len(values))
    ok = res.ok.reshape(len(values))
    r = val - cond.target
    if kind == "phi":  # compare angles modulo 2π
        r = np.angle(np.exp(1j * r))
    return r, ok


def solve_conditions(mech, conditions, xtol=1e-13):
    """Solve design conditions in dependency order.

    Parameters
    ----------
    mech : Mechanism
        Every unknown must be one of its parameters (its value is a start value
        only).
    conditions : sequence of Condition

    Returns
    -------
    mechanism : Mechanism
        With the unknowns replaced by their roots.
    solved : list of SolvedCondition
        In the order solved.

    Raises
    ------
    DesignError
        When a condition has no root or several roots in its bracket, or the
        conditions cannot be ordered (two unknowns fixed by one condition).

    Examples
    --------
    Seed 003's three Find blocks from the seed's start values, given in any order:
    solved L4 first, then Sp, then L7, to the printed L4 = 0.6613, Sp = 0.4694,
    L7 = 0.7522 m.

    >>> import math
    >>> from assur import examples
    >>> from assur.synthesis.conditions import Condition, solve_conditions
    >>> conditions = [
    ...     Condition("L7", (0.56, 1.05), {"S": "Sp"}, "phi6", math.pi / 2),  # φ6(Sp) = 90°
    ...     Condition("Sp", (0.42, 0.67), {"S": "Sp"}, "Y56", 0.4),  # Y56(Sp) = 0.4 m
    ...     Condition("L4", (0.48, 0.9), {"S": 0.42}, "Y56", 0.2),  # Y56(Smin) = 0.2 m
    ... ]
    >>> start = examples.hitch_003(L4=0.6, L7=0.7, Sp=0.545)
    >>> mech, solved = solve_conditions(start, conditions)
    >>> [s.condition.unknown for s in solved]
    ['L4', 'Sp', 'L7']
    >>> [round(mech.params[k], 4) for k in ("L4", "Sp", "L7")]  # [m]
    [0.6613, 0.4694, 0.7522]
    """
    conds = list(conditions)
    unknowns = [c.unknown for c in conds]
    for c in conds:
        if c.unknown not in mech.params:
            raise DesignError(f"condition {c.describe()}: {c.unknown!r} is not a parameter of "
                              f"the model ({sorted(mech.params)})")
        lo, hi = c.bracket
        if not (np.isfinite(lo) and np.isfinite(hi) and lo < hi):
            raise DesignError(f"condition {c.describe()}: bracket must be [low, high] with "
                              f"low < high, got {c.bracket}")
    dup = {u for u in unknowns if unknowns.count(u) > 1}
    if dup:
        raise DesignError(f"parameters {sorted(dup)} are fixed by more than one condition")
    deps = {id(c): _depends(mech, c, unknowns) for c in conds}
    for c in conds:
        if c.unknown not in deps[id(c)]:
            raise DesignError(f"condition {c.describe()} does not depend on {c.unknown!r}: the "
                              f"quantity is defined before any group that uses it")
    done, solved = set(), []
    pending = conds[:]
    while pending:
        ready = [c for c in pending if deps[id(c)] - {c.unknown} <= done]
        if not ready:
            raise DesignError("the conditions cannot be solved one at a time: "
                              + "; ".join(f"{c.describe()} needs "
                                          f"{sorted(deps[id(c)] - done - {c.unknown})}"
                                          for c in pending))
        c = ready[0]
        sc = _solve_one(mech, c, xtol)
        mech = mech.with_params(**{c.unknown: sc.value})
        solved.append(sc)
        done.add(c.unknown)
        pending.remove(c)
    return mech, solved


def _solve_one(mech, c, xtol):
    lo, hi = float(c.bracket[0]), float(c.bracket[1])
    grid = np.linspace(lo, hi, SCAN_POINTS)
    r, ok = condition_residual(mech, c, grid)
    notes = []
    bracket = f"[{c.shown(lo, 'unknown')}, {c.shown(hi, 'unknown')}]"
    if not ok.any():
        raise DesignError(f"condition {c.describe()}: the mechanism does not assemble anywhere "
                          f"in the bracket {bracket}")
    if not ok.all():
        notes.append(f"the mechanism does not assemble for {c.unknown} in "
                     f"{_spans(grid, ~ok, c)}")
    roots = []
    exact = np.flatnonzero(ok & (r == 0))
    for i in exact:
        roots.append((grid[i], grid[i]))
    for i in range(len(grid) - 1):
        if ok[i] and ok[i + 1] and r[i] * r[i + 1] < 0:
            # a jump of an angle residual through ±π is not a root
            if abs(r[i] - r[i + 1]) > np.pi and _quantity(mech, c.quantity)[0] == "phi":
                continue
            roots.append((grid[i], grid[i + 1]))
    if not roots:
        rr = r[ok]
        raise DesignError(f"condition {c.describe()}: no root for {c.unknown} in the bracket "
                          f"{bracket}: {c.quantity} − target stays between "
                          f"{c.shown(rr.min(), digits=4)} and {c.shown(rr.max(), digits=4)}"
                          + (f"; {notes[0]}" if notes else ""))
    if len(roots) > 1:
        where = ", ".join(f"≈{c.shown(0.5 * (a + b), 'unknown')}" for a, b in roots[:6])
        raise DesignError(f"condition {c.describe()}: {len(roots)} roots for {c.unknown} in "
                          f"the bracket {bracket} ({where}); narrow the bracket")
    a, b = roots[0]
    count = [0]

    def f(x):
        count[0] += 1
        rv, okv = condition_residual(mech, c, np.array([x]))
        if not okv[0]:
            raise AssemblyError(f"condition {c.describe()}: the mechanism does not assemble at "
                                f"{c.unknown} = {c.shown(x, 'unknown', 9)}")
        return float(rv[0])

    from scipy.optimize import brentq  # imported here: a cached solve does not need it

    x = a if a == b else brentq(f, a, b, xtol=xtol, rtol=4 * np.finfo(float).eps)
    res = f(x)
    return SolvedCondition(c, float(x), res, count[0] + SCAN_POINTS, notes)


def _spans(grid, mask, c):
    idx = np.flatnonzero(mask)
    runs = np.split(idx, np.flatnonzero(np.diff(idx) != 1) + 1)
    return ", ".join(f"[{c.shown(grid[r[0]], 'unknown', 4)}, {c.shown(grid[r[-1]], 'unknown', 4)}]"
                     for r in runs if len(r))
