"""Machine stability: axle reactions, load shares and the 20 % steerability rule.

A tractor or loader carrying an implement is a rigid body on two axles. All
weights act vertically downward, the ground reactions of the axles vertically
upward; the implement's centre of mass moves with the mechanism, so its
horizontal coordinate is an array over positions (e.g. ``XS6(S)`` from the
kinematics). The machine is *steerable* when the steered axle carries at least
``min_share`` (20 % in the seeds) of the total weight (seed 003 §6; seed 001,
lab 1, eqs. 15–18).

Sign convention
---------------
``x`` is the horizontal coordinate of the mechanism's frame [m] (the seeds' X
axis); axles, machine weights and counterweights sit at fixed ``x``. A weight
``P`` [N] at ``x`` is the force ``(0, −P)``; an axle reaction ``R`` [N] at its
``x`` is the force ``(0, +R)``. Seed 003, with the rear axle B at the origin of
the hitch frame and the implement behind it::

       P_гр          P_мсха                       P6
        |              |                          |
        v              v                          v
   -----+------o-------+----------------o---------+-------> x
     −(a+L)    ^ A    −b                ^ B       XS6(S)
               | R_A  (x = −L)          | R_B  (x = 0)

Moments about the other axle give the reaction of each axle,

.. math::

    R_s = \\frac{\\sum_i P_i\\,(x_i - x_o)}{x_s - x_o}, \\qquad
    R_o = \\frac{\\sum_i P_i\\,(x_s - x_i)}{x_s - x_o},

so ``R_s + R_o = ΣP`` (balance of vertical forces) and ``R_s·x_s + R_o·x_o =
ΣP_i·x_i`` (balance of moments) hold to rounding.

Maximum implement weight
------------------------
With the implement weight ``P`` as the unknown, the steered reaction is linear
in it, ``R_s(P) = R_0 + c·P`` with ``c = ∂R_s/∂P = (x_imp − x_o)/(x_s − x_o)``
[-] and ``R_0`` the steered reaction of the machine alone; the rule
``R_s(P) ≥ m·(W_0 + P)`` (``m`` = ``min_share``, ``W_0`` the machine's weight)
gives, for ``c < m``,

.. math::

    P \\le P_{max} = \\frac{R_0 - m\\,W_0}{m - c}.

``max_implement_weight`` is the largest weight of the admissible set
``{P ≥ 0 : R_s(P) ≥ m·(W_0 + P)}``:

* ``c < m`` and ``R_0 ≥ m·W_0``: the finite ``P_max`` above;
* ``c ≥ m`` (the implement sits over or beyond the steered axle's side enough to
  load it by at least the share ``m`` of its own weight): no upper limit, the
  value is ``np.inf`` — a real "no limit", not a failure. When also ``R_0 <
  m·W_0`` the admissible set is ``[P_min, ∞)``: light implements fail while heavy
  ones pass, see ``steerable`` for the actual weight;
* ``c ≤ m`` and ``R_0 < m·W_0`` (the machine alone already violates the rule and
  the implement cannot help): the admissible set is empty and the value is 0;
  ``steerable`` is False there for every weight.

The other axle is not checked: a reaction ``R_o < 0`` (the machine tips over
the steered axle) is returned as computed.

Seed 001, lab 1, eqs. (16) and (18) are this limit for one geometry (see
``tests/machines/test_stability.py``). Seed 003 §6 prints a dimensionally inconsistent
limit (GS6max); its model file reproduces it as a flagged extra column of table
6.1 (``[[tables.formulas]]``, :mod:`assur.core.columns`), never the main result.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Mapping, Sequence

import numpy as np
from numpy.typing import ArrayLike

from ._stability_result import StabilityResult, _stack_results

__all__ = ["Machine", "StabilityResult", "axle_reactions", "Carrying"]


def _finite(value, what: str) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{what} must be a finite number, got {value!r}") from None
    if not math.isfinite(v):
        raise ValueError(f"{what} must be a finite number, got {value!r}")
    return v


def _weights(items, kind: str) -> tuple[tuple[str, float, float], ...]:
    out = []
    for k, item in enumerate(items):
        if isinstance(item, (str, bytes)) or len(item) != 3:
            raise ValueError(f"each of {kind} must be a tuple (name, weight [N], x [m]); "
                             f"item {k} is {item!r}")
        name, p, x = item
        if not isinstance(name, str):
            raise ValueError(f"the name of {kind} item {k} must be a string, got {name!r}")
        p = _finite(p, f"weight of {kind} {name!r} [N]")
        if p < 0:
            raise ValueError(f"weights act downward and must be ≥ 0: {kind} {name!r} has "
                             f"weight {p} N")
        out.append((name, p, _finite(x, f"x of {kind} {name!r} [m]")))
    return tuple(out)


@dataclass(frozen=True)
class Machine:
    """A machine on two axles with fixed weights (machine parts and counterweights).

    Parameters
    ----------
    axles : mapping of str to float
        Exactly two axles, name → horizontal coordinate ``x`` of the wheel contact
        (the axle's reaction line) [m]. Their order is kept for tables.
    steered : str
        Name of the steered axle; must be one of ``axles``.
    weights : sequence of (str, float, float)
        The machine itself: ``(name, weight P, x)``, weight [N] ≥ 0, x [m]. May be
        several parts (frame, engine, tanks…).
    counterweights : sequence of (str, float, float), optional
        Ballast, same form as ``weights``. Kept apart so that the limit can be given
        with and without it (seed 001 eq. 16 vs 18). Default: none.
    min_share : float, optional
        The steered axle must carry at least this share of the total weight [-];
        ``0 ≤ min_share < 1``. Default 0.2 (the 20 % rule of seeds 001 and 003).

    Raises
    ------
    ValueError
        If there are not exactly two axles, they share one ``x``, ``steered`` is
        not an axle name, a number is not finite, a weight is negative, a name is
        repeated, ``min_share`` is outside [0, 1) or the machine weighs nothing.

    Examples
    --------
    Seed 003 §6 (rear axle B at the hitch origin, front axle A steered):

    >>> m = Machine({"A": -2.96, "B": 0.0}, steered="A",
    ...             weights=[("tractor", 56000.0, -1.62)],
    ...             counterweights=[("front ballast", 8000.0, -3.56)])
    >>> m.other, m.weight
    ('B', 64000.0)
    """

    axles: Mapping[str, float]
    steered: str
    weights: Sequence[tuple[str, float, float]] = ()
    counterweights: Sequence[tuple[str, float, float]] = ()
    min_share: float = 0.2

    def __post_init__(self):
        try:
            items = list(dict(self.axles).items())
        except (TypeError, ValueError):
            raise ValueError(f"axles must be a mapping name → x [m], "
                             f"got {self.axles!r}") from None
        if len(items) != 2:
            raise ValueError(f"a machine needs exactly two axles (name → x [m]); got "
                             f"{len(items)}: {[n for n, _ in items]}")
        axles = {}
        for name, x in items:
            if not isinstance(name, str):
                raise ValueError(f"axle names must be strings, got {name!r}")
            axles[name] = _finite(x, f"x of axle {name!r} [m]")
        (na, xa), (nb, xb) = axles.items()
        if xa == xb:
            raise ValueError(f"the two axles must be at different x; {na!r} and {nb!r} are "
                             f"both at x = {xa} m")
        if self.steered not in axles:
            raise ValueError(f"steered must be one of: {list(axles)}; got {self.steered!r}")
        weights = _weights(self.weights, "weights")
        counterweights = _weights(self.counterweights, "counterweights")
        names = [w[0] for w in weights + counterweights]
        repeated = sorted({n for n in names if names.count(n) > 1})
        if repeated:
            raise ValueError(f"weight names must be unique; repeated: {repeated}")
        min_share = _finite(self.min_share, "min_share [-]")
        if not 0.0 <= min_share < 1.0:
            raise ValueError(f"min_share is a share of the total weight and must satisfy "
                             f"0 ≤ min_share < 1; got {min_share}")
        if not sum(w[1] for w in weights + counterweights) > 0:
            raise ValueError("the machine must have a positive total weight "
                             "(weights + counterweights > 0 N)")
        object.__setattr__(self, "axles", axles)
        object.__setattr__(self, "weights", weights)
        object.__setattr__(self, "counterweights", counterweights)
        object.__setattr__(self, "min_share", min_share)

    @property
    def other(self) -> str:
        """Name of the axle that does not steer.

        Examples
        --------
        >>> from assur.machines.stability import Machine
        >>> m = Machine({"A": -2.96, "B": 0.0}, steered="A",            # seed 003 §6 [m]
        ...             weights=[("tractor", 56000.0, -1.62)],            # [N], [m]
        ...             counterweights=[("front ballast", 8000.0, -3.56)])
        >>> m.other
        'B'
        """
        return next(n for n in self.axles if n != self.steered)

    @property
    def weight(self) -> float:
        """Total weight of the machine with its counterweights [N].

        Examples
        --------
        >>> from assur.machines.stability import Machine
        >>> m = Machine({"A": -2.96, "B": 0.0}, steered="A",            # seed 003 §6 [m]
        ...             weights=[("tractor", 56000.0, -1.62)],            # [N], [m]
        ...             counterweights=[("front ballast", 8000.0, -3.56)])
        >>> m.weight                  # P_мсха + P_гр [N]
        64000.0
        """
        return sum(w[1] for w in self.weights + self.counterweights)

    def carry(self, point, weight, refs=None) -> "Carrying":
        """The machine carrying an implement of ``weight`` [N] at ``point`` of a mechanism
        (what :meth:`assur.Mechanism.with_machine` stores).

        Examples
        --------
        >>> from assur.machines.stability import Machine
        >>> m = Machine({"A": -2.96, "B": 0.0}, steered="A",            # seed 003 §6 [m]
        ...             weights=[("tractor", 56000.0, -1.62)],            # [N], [m]
        ...             counterweights=[("front ballast", 8000.0, -3.56)])
        >>> c = m.carry("S6", 27500.0)                                    # P6 at S6 [N]
        >>> c.point, c.weight
        ('S6', 27500.0)
        """
        return Carrying(self, point, weight, refs)

    def _steered_reaction(self, items) -> float:
        """Reaction of the steered axle under ``items`` alone [N] (moments about the
        other axle)."""
        xs, xo = self.axles[self.steered], self.axles[self.other]
        return sum(p * (x - xo) for _, p, x in items) / (xs - xo)

    @cached_property
    def _constants(self):
        """What :func:`axle_reactions` needs of the machine alone, made once: x of the
        steered and the other axle [m], the moment of the weights and counterweights
        about the other axle [N·m], the steered axle's reaction and the weight with
        and without the counterweights [N]."""
        xs, xo = self.axles[self.steered], self.axles[self.other]
        fixed = self.weights + self.counterweights
        return (xs, xo, sum(pi * (xi - xo) for _, pi, xi in fixed),
                self._steered_reaction(fixed), self.weight,
                self._steered_reaction(self.weights), sum(w[1] for w in self.weights))


def _limit(r0: float, w0: float, c: np.ndarray, m: float, masks=None) -> np.ndarray:
    """Sup of {P ≥ 0 : r0 + c·P ≥ m·(w0 + P)} [N]; inf if unbounded, 0 if empty.
    ``masks``: ``(m − c, m − c > 0)`` when the caller has them (both limits of
    :func:`axle_reactions` share them)."""
    den, pos = masks if masks is not None else (m - c, None)
    excess = r0 - m * w0          # R_0 − m·W_0 [N]
    if type(den) is float:        # one position: the same cases on a number (a numpy
        # scalar, e.g. from a 0-d array, keeps the array path and returns an array)
        if excess >= 0:
            return excess / den if den > 0 else math.inf
        return math.inf if den < 0 else 0.0
    if pos is None:
        pos = den > 0
    if excess >= 0:  # bounded where den > 0 (excess/den), unbounded where den ≤ 0
        out = np.empty(np.shape(den))
        out.fill(np.inf)
        return np.divide(excess, den, out=out, where=pos)
    # no weight where den ≥ 0 (0 at den > 0: max(excess, 0)/den), unbounded where den < 0
    return np.where(den < 0, np.inf, 0.0)


def axle_reactions(machine: Machine, implement_weight: ArrayLike,
                   implement_x: ArrayLike) -> StabilityResult:
    """Axle reactions, load shares and the maximum implement weight (20 % rule).

    Parameters
    ----------
    machine : Machine
        Axles, steered axle, machine weights and counterweights.
    implement_weight : array_like
        Weight of the implement [N] ≥ 0: a scalar, or an array over designs that
        broadcasts against ``implement_x`` (e.g. shape (n_designs, 1)).
    implement_x : array_like
        Horizontal coordinate of the implement's centre of mass [m], any shape,
        e.g. ``XS6(S)`` of shape (n_positions,) or (n_designs, n_positions).

    Returns
    -------
    StabilityResult
        All arrays with the broadcast shape of the two inputs.

    Raises
    ------
    ValueError
        If an input is not finite or the implement weight is negative.

    Notes
    -----
    Moments about the other axle give the steered axle's reaction and the vertical
    balance the other's — the same as its moments about the steered axle (module
    notes; seed 003 §6, ``R_A·L = P_гр·(a + L) + P_мсха·b − P6·XS6``; seed 001 lab 1
    eq. 15, 17). The
    maximum implement weight solves ``R_s(P) = m·(W_0 + P)`` with the implement at
    ``implement_x``; it does not depend on ``implement_weight`` and is ``np.inf``
    when the implement loads the steered axle by at least ``m`` of its own weight
    (``c ≥ m``), 0 when no weight keeps the rule.

    Examples
    --------
    >>> m = Machine({"A": -2.96, "B": 0.0}, steered="A",
    ...             weights=[("tractor", 56000.0, -1.62)],
    ...             counterweights=[("front ballast", 8000.0, -3.56)])
    >>> r = axle_reactions(m, 27500.0, [1.992, 1.753])
    >>> r.reaction("A").round(0), r.share("A").round(1)
    (array([21764., 23984.]), array([23.8, 26.2]))
    >>> r.max_implement_weight.round(0)
    array([31467., 34675.])
    """
    p = np.asarray(implement_weight, dtype=float)
    x = np.asarray(implement_x, dtype=float)
    if p.ndim == 0:   # one weight (the common case): Python-float checks, no broadcasting
        p = float(p)
        if not math.isfinite(p):
            raise ValueError("implement_weight [N] must be finite")
        if p < 0:
            raise ValueError(f"implement_weight acts downward and must be ≥ 0 N; it is {p} N")
        shape = x.shape
    else:
        if not np.isfinite(p).all():
            raise ValueError("implement_weight [N] must be finite")
        if (p < 0).any():
            raise ValueError(f"implement_weight acts downward and must be ≥ 0 N; smallest is "
                             f"{p.min()} N")
        shape = np.broadcast_shapes(p.shape, x.shape)
        if p.shape != shape:
            p = np.broadcast_to(p, shape)
    one = isinstance(p, float) and x.size == 1
    if one:   # one position (dynamics, the page): the formulas below on numbers
        x = float(x.reshape(-1)[0])
    if not (math.isfinite(x) if one else np.isfinite(x).all()):
        raise ValueError("implement_x [m] must be finite")
    if not one and x.shape != shape:
        x = np.broadcast_to(x, shape)

    s = machine.steered
    # the machine's own numbers, made once per machine (Machine._constants)
    xs, xo, mom_o, r_cw, weight, r_bare, w_bare = machine._constants
    span = xs - xo
    c = (x - xo) / span                       # ∂R_s/∂P [-]
    # moments about the other axle give R_s, the vertical balance R_o (module notes)
    r_s = mom_o / span + p * c
    total = weight + p                        # [N]: a number for one implement weight
    r_o = total - r_s
    reactions = {n: (r_s if n == s else r_o) for n in machine.axles}
    per_cent = 100.0 / total
    shares = {n: reactions[n] * per_cent for n in machine.axles}
    m = machine.min_share
    steerable = r_s >= m * total
    den = m - c                               # m − ∂R_s/∂P [-]
    masks = (den, None if one else den > 0)
    g_cw = _limit(r_cw, weight, c, m, masks)
    g_bare = _limit(r_bare, w_bare, c, m, masks)
    if one:   # the numbers as arrays of the input's shape, made in one call
        names = list(machine.axles)
        rows = np.array([*(reactions[n] for n in names), *(shares[n] for n in names),
                         total, g_cw, g_bare]).reshape((-1, *shape))
        k = len(names)
        reactions = dict(zip(names, rows[:k]))
        shares = dict(zip(names, rows[k:2 * k]))
        total, g_cw, g_bare = rows[2 * k:]
        steerable = np.array(steerable).reshape(shape)
    elif not isinstance(total, np.ndarray):
        total, w = np.empty(shape), total
        total.fill(w)
    return StabilityResult(
        reactions=reactions, shares=shares, steered=s, min_share=m,
        total_weight=total, steered_share=shares[s], steerable=steerable,
        max_implement_weight=g_cw,
        max_implement_weight_without_counterweights=g_bare)


@dataclass(frozen=True)
class Carrying:
    """A :class:`Machine` carrying the mechanism's implement.

    Parameters
    ----------
    machine : Machine
    point : str
        The mechanism point where the implement's weight acts (its centre of mass,
        seed 003 S6) — its x over the positions comes from the kinematics.
    weight : float or str
        The implement's weight [N], a number or a model parameter (seed 003 P6).
    refs : mapping, optional
        How the machine's numbers follow the model parameters (below).

    Notes
    -----
    A value a seed computes beside the limit (seed 003's printed GS6max) is not
    the machine's business: the model declares it as an extra formula column
    (:class:`assur.core.columns.Formula`).

    Examples
    --------
    The seed-003 hitch's tractor carries the implement's weight P6 at S6:

    >>> from assur import examples
    >>> carrying = examples.hitch_003().machine
    >>> carrying.point, carrying.weight, carrying.machine.steered
    ('S6', 'P6', 'A')
    >>> kin = examples.hitch_003().solve([0.42, 0.67])
    >>> [round(float(v)) for v in carrying.evaluate(kin).max_implement_weight]  # [N]
    [31464, 34679]
    """

    machine: Machine
    point: str
    weight: object
    #: how the machine's numbers follow the model parameters: ``{"axles": {name: terms},
    #: "weights": ((name, P terms, x terms), …), "counterweights": (…)}``, each value a
    #: sum of ``(sign, number or parameter name)`` terms; None: the numbers as given
    refs: Mapping[str, object] | None = None

    def ref_names(self):
        """Parameter names the machine's data refer to.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().machine.ref_names()   # seed 003 §1.6
        ['L', 'P_gr', 'P_mcxa', 'a', 'b']
        """
        if not self.refs:
            return []
        terms = [t for ts in self.refs["axles"].values() for t in ts]
        for part in ("weights", "counterweights"):
            for _, p, x in self.refs.get(part, ()):
                terms += list(p) + list(x)
        return sorted({r for _, r in terms if isinstance(r, str)})

    def quantities(self):
        """``{parameter: quantity}`` of the parameters the machine's data refer to
        (:mod:`assur.core.quantities`): axle and weight positions are lengths, weights
        forces; the implement's weight too.

        Examples
        --------
        >>> from assur import examples
        >>> q = examples.hitch_003().machine.quantities()
        >>> q["L"], q["b"], q["P_mcxa"], q["P6"]     # wheelbase, positions, weights
        ('length', 'length', 'force', 'force')
        >>> len(q)
        6
        """
        out = {}
        if isinstance(self.weight, str):
            out[self.weight] = "force"
        if self.refs:
            for terms in self.refs["axles"].values():
                out.update({r: "length" for _, r in terms if isinstance(r, str)})
            for part in ("weights", "counterweights"):
                for _, p, x in self.refs.get(part, ()):
                    out.update({r: "force" for _, r in p if isinstance(r, str)})
                    out.update({r: "length" for _, r in x if isinstance(r, str)})
        return out

    def machine_for(self, params):
        """The :class:`Machine` with its numbers from the parameter values ``params``
        (one design: scalars).

        Examples
        --------
        The seed-003 tractor with a longer wheelbase L = 3.2 m:

        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> params = {name: float(m.params[name]) for name in m.machine.ref_names()}
        >>> machine = m.machine.machine_for({**params, "L": 3.2})
        >>> machine.axles, machine.weight          # [m], [N]
        ({'A': -3.2, 'B': 0.0}, 64000.0)
        >>> [(n, P, round(x, 3)) for n, P, x in machine.counterweights]   # at −(a + L) [N], [m]
        [('противовесы', 8000.0, -3.8)]
        """
        if not self.refs:
            return self.machine

        def num(terms):
            return float(sum(s * (float(params[r]) if isinstance(r, str) else float(r))
                             for s, r in terms))

        return Machine({a: num(t) for a, t in self.refs["axles"].items()},
                       steered=self.machine.steered,
                       weights=[(n, num(p), num(x)) for n, p, x in self.refs["weights"]],
                       counterweights=[(n, num(p), num(x))
                                       for n, p, x in self.refs.get("counterweights", ())],
                       min_share=self.machine.min_share)

    def evaluate(self, kin):
        """Axle reactions and limits over the kinematics' positions, a
        :class:`StabilityResult`. With parameters that vary over a batch of designs,
        each design gets its machine.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> r = m.machine.evaluate(m.solve([0.42, 0.67]))
        >>> [round(float(v)) for v in r.reaction("A")]    # Ra, seed 003 table 6.1 [N]
        [21761, 23987]

        Two designs, with and without the front ballast P_гр:

        >>> b = m.solve([0.42, 0.67], params={"P_gr": [8000.0, 0.0]})   # [N]
        >>> m.machine.evaluate(b).steerable.tolist()
        [[True, True], [False, False]]
        """
        mech = kin.mechanism

        def val(ref):
            v = np.asarray(mech.value_of(ref), float)
            if v.ndim == 1 and v.shape[0] > 1:
                return v.reshape((-1,) + (1,) * (len(kin.shape) - 1))
            return v.reshape(()) if v.ndim == 1 else v

        # what does not depend on the positions, once per mechanism (and shape of its
        # batch): the parameters the machine refers to, whether they vary over designs,
        # the machine of one design, the implement's weight
        hit = mech.memo(("stability", "machine", id(self), len(kin.shape)),
                        lambda: (self, *self._refs(mech), val(self.weight)))
        names, varying, machine, weight = (hit[1:] if hit[0] is self else
                                           (*self._refs(mech), val(self.weight)))
        if varying and len(kin.shape) == 2:
            rows = []
            for d in range(kin.shape[0]):
                pd_ = {r: np.atleast_1d(np.asarray(mech.params[r], float))
                       [d if np.size(mech.params[r]) > 1 else 0] for r in names}
                w = np.broadcast_to(weight, kin.shape)[d]
                rows.append(axle_reactions(self.machine_for(pd_), w, kin.x(self.point)[d]))
            return _stack_results(rows)
        return axle_reactions(machine, weight, kin.x(self.point))

    def _refs(self, mech):
        names = self.ref_names()
        varying = [r for r in names if np.size(mech.params[r]) > 1]
        pd_ = {r: float(np.atleast_1d(np.asarray(mech.params[r], float))[0]) for r in names}
        return names, varying, self.machine_for(pd_)
