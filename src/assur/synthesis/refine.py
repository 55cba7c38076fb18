"""One local refiner: scipy's SLSQP with exact gradients (issue 22).

A design — the optimum of a global search, or any design — is refined inside its
basin by :func:`scipy.optimize.minimize` (``method="SLSQP"``) with **exact**
gradients (the sensitivities of :mod:`assur.synthesis.sensitivity`, forward-mode dual
numbers through the engine's own group code), never finite differences. It does
not search the design space: differential evolution finds the basin
(:func:`assur.synthesis.search.search.optimize`), this finds its bottom.

:func:`refine` is the one implementation. Its users build its criteria:

* :func:`local_refine` — the smallest value of one output over the positions
  maximised (a capacity at the weakest position), with limits on outputs at every
  position (a pressure at most the relief setting);
* :func:`assur.synthesis.search.polish.polish` — a design problem's first objective
  and its constraints, from its criteria's exact gradients; the refined design is
  then judged by the batch evaluation of the search.

The contract of :func:`refine`
------------------------------
``criteria(x)`` gives, at a design ``x`` [the variables' SI units]:

* ``f`` — the objective [its unit]: a number, or an array of numbers whose largest
  is minimised (whose smallest is maximised, ``maximize=True``);
* ``df`` — its gradient ∂f/∂x, shape (n,) or (len(f), n) [unit of f / unit of x];
* ``g`` — the constraints, shape (m,), held where ``g ≥ 0`` and scaled by the
  caller to order one (a margin divided by its limit's magnitude) [-];
* ``dg`` — their Jacobian ∂g/∂x, shape (m, n) [1 / unit of x].

SLSQP then works on the problem::

    minimise f(x) / s   (or max_i f_i(x) / s)
    subject to  g_j(x) ≥ slack,   low ≤ x ≤ high

with the variables scaled to [0, 1] over their bounds (:class:`Scaled`; a variable
whose bounds are equal stays there) and the objective divided by
``s = max |f(x0)|`` (1 if that is 0). An array objective is written in epigraph
form — one more variable t: minimise t subject to ``f_i(x) ≤ t`` — the smooth
problem whose optimum is the max–min one (the weakest position changes as the
design moves; the largest of the f_i has no gradient where two tie, the epigraph
form does not need one). ``criteria`` is called once per distinct design: its four
parts serve the objective, the constraints and both gradients.

The start may violate constraints (SLSQP starts from infeasible points too): the
result says so in words (:attr:`Refinement.start_note`), and whether the result
holds every constraint (:attr:`Refinement.note`). A trial design where
``criteria`` raises one of ``stop_on`` (a design that does not assemble) ends the
refinement at the last iterate, the message saying so.

Examples
--------
The nearest point of the disc x² + y² ≤ 1 to (2, 1), x and y within [0, 3] —
(2, 1)/√5, where the constraint is active:

>>> import numpy as np
>>> from assur.synthesis.refine import refine
>>> def criteria(x):                       # distance² to (2, 1), and 1 − x² − y² ≥ 0
...     d = x - [2.0, 1.0]
...     return d @ d, 2 * d, [1.0 - x @ x], [-2 * x]
>>> r = refine(criteria, [0.0, 0.0], [(0.0, 3.0), (0.0, 3.0)], names=("x", "y"),
...            constraint_names=("x² + y² ≤ 1",))
>>> r.success, r.feasible, np.round(r.x * np.sqrt(5), 6).tolist()
(True, True, [2.0, 1.0])
>>> round(r.start_value, 6), round(r.value, 6), r.improved   # (√5 − 1)² = 1.527864
(5.0, 1.527864, True)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.outputs import output_unit
from ..errors import ModelError
from ._refinement import TOL, Refinement, Scaled, _Stop
from .sensitivity import sensitivities

__all__ = ["refine", "Refinement", "local_refine", "Refined", "Scaled"]


def refine(criteria, x0, bounds, *, maximize=False, slack=0.0, names=None,
           constraint_names=None, stop_on=(), maxiter=100, ftol=1e-9, tol=TOL):
    """Refine a design locally by SLSQP with exact gradients (the one local refiner).

    Parameters
    ----------
    criteria : callable
        ``criteria(x) → (f, df, g, dg)`` at a design ``x``, ndarray of shape (n,)
        [SI]: the objective ``f`` (a number, or an array whose largest element is
        minimised — smallest maximised) [its unit], its gradient ``df``, shape (n,)
        or (len(f), n) [unit of f / SI unit of x], the constraints ``g``, shape (m,),
        held where ≥ 0 and scaled to order one [-] (m may be 0), and their Jacobian
        ``dg``, shape (m, n). Called once per distinct design (the module's
        docstring states the problem SLSQP solves).
    x0 : array_like, shape (n,)
        The start [SI]; clipped to the bounds. It may violate constraints.
    bounds : array_like, shape (n, 2)
        ``(low, high)`` of each variable, finite, ``low ≤ high`` [SI].
    maximize : bool
        Maximise ``f`` (its smallest element) instead of minimising.
    slack : float
        Every constraint is held as ``g ≥ slack`` [-] (a constraint active at the
        optimum is then met despite rounding).
    names : sequence of str, optional
        The variables' names (default ``x0``, ``x1``…), for :attr:`Refinement.params`.
    constraint_names : sequence of str, optional
        The constraints' names (default ``constraint 0``…), for the notes.
    stop_on : tuple of exception types
        Raised by ``criteria`` at a trial design, they end the refinement at the last
        iterate (:attr:`Refinement.stopped`); at the start they propagate. Any other
        exception propagates.
    maxiter : int
        SLSQP iterations at most.
    ftol : float
        SLSQP's tolerance on the scaled objective [-].
    tol : float
        A constraint counts as held where ``g ≥ −tol`` (the notes) [-].

    Returns
    -------
    Refinement

    Raises
    ------
    ModelError
        Bounds that are not finite pairs with low ≤ high for every variable, or
        ``criteria`` parts of the wrong shape.

    Examples
    --------
    Minimise (x − 2)² + (y − 1)² subject to x + y ≤ 2 with x, y in [0, 1.5]: the
    optimum (1.5, 0.5) — on the line x + y = 2 and at the bound of x:

    >>> import numpy as np
    >>> from assur.synthesis.refine import refine
    >>> def criteria(x):
    ...     d = x - [2.0, 1.0]
    ...     return d @ d, 2 * d, [(2.0 - x.sum()) / 2.0], [[-0.5, -0.5]]
    >>> r = refine(criteria, [0.0, 0.0], [(0.0, 1.5), (0.0, 1.5)], names=("x", "y"))
    >>> r.success, r.feasible, {k: round(v, 6) for k, v in r.params.items()}
    (True, True, {'x': 1.5, 'y': 0.5})
    >>> round(r.value, 6), r.improved
    (0.5, True)

    The largest of several objectives, by the epigraph form: max(|x − 1|², |x + 1|²)
    is smallest at x = 0.

    >>> r = refine(lambda x: ((x - [1.0, -1.0]) ** 2, 2 * (x - [1.0, -1.0])[:, None], [],
    ...                       np.zeros((0, 1))), [0.7], [(-2.0, 2.0)])
    >>> round(r.params["x0"], 6) + 0.0, round(r.value, 6)
    (0.0, 1.0)
    >>> refine(lambda x: (0.0, [0.0], [], [[]]), [0.0], [(1.0, 0.0)], names=("L4",))
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: refine: the bounds of L4 must be finite with low ≤ high, got [1.0, 0.0]
    """
    x0, names, lo, hi = _checked(x0, bounds, names)
    nv = len(x0)
    seen = {}
    ev = Scaled(lo, hi, _evaluation(criteria, stop_on, nv, seen), clip=True)
    zhi = np.where(hi > lo, 1.0, 0.0)  # a variable with equal bounds stays at them
    z0 = np.clip(ev.z(x0), 0.0, zhi)
    try:
        f0, _, g0, _ = ev(z0)
    except _Stop as e:
        raise e.__cause__ from None
    epi = f0.ndim > 0  # an array objective: the epigraph variable t after z
    if epi and f0.size == 0:
        raise ModelError("refine: criteria gave an empty objective")
    constraint_names = _constraint_names(constraint_names, len(g0))
    fs = float(np.abs(f0).max()) or 1.0

    def best(f):
        """The objective as a number: an array's smallest (maximised) or largest."""
        return float((f.min() if maximize else f.max()) if epi else f)

    count = {"g": 0}
    if epi:
        fun, jac, cons, cons_jac = _epigraph(ev, nv, fs, maximize, slack, count)
        w0 = np.append(z0, best(f0))
        wb = [(0.0, float(u)) for u in zhi] + [(None, None)]
    else:
        fun, jac, cons, cons_jac = _direct(ev, fs, maximize, slack, count)
        w0, wb = z0, [(0.0, float(u)) for u in zhi]
    constraints = [{"type": "ineq", "fun": cons, "jac": cons_jac}] if epi or len(g0) else []
    z, nit, stopped, success, message = _slsqp(fun, w0, jac, wb, constraints, z0, zhi,
                                               maxiter, ftol)
    x = ev.x(z)
    end = seen.get(x.tobytes())
    if end is None:
        try:
            end = ev(z)
        except _Stop as e:  # the design SLSQP ended at cannot be evaluated: keep the start
            z, x, end, stopped, success = z0, ev.x(z0), ev(z0), True, False
            message = f"stopped: the result could not be evaluated ({e})"
    return Refinement(x, ev.x(z0), best(end[0]), best(f0), end[2], g0, success, message, nit,
                      ev.count, count["g"], stopped, names, constraint_names, bool(maximize),
                      float(tol))


def _checked(x0, bounds, names):
    """The start [SI], the variables' names and their bounds, checked (:func:`refine`)."""
    x0 = np.asarray(x0, float).reshape(-1)
    nv = len(x0)
    names = tuple(names) if names is not None else tuple(f"x{i}" for i in range(nv))
    b = np.asarray(bounds, float)
    if b.shape != (nv, 2) or len(names) != nv:
        raise ModelError(f"refine: {nv} variables need {nv} names and {nv} bounds (low, "
                         f"high); got {len(names)} names and bounds of shape {b.shape}")
    lo, hi = b[:, 0], b[:, 1]
    for i in np.flatnonzero(~(np.isfinite(lo) & np.isfinite(hi) & (lo <= hi))):
        raise ModelError(f"refine: the bounds of {names[i]} must be finite with low ≤ high, "
                         f"got [{float(lo[i])!r}, {float(hi[i])!r}]")
    return x0, names, lo, hi


def _evaluation(criteria, stop_on, nv, seen):
    """``criteria`` at a design as arrays of checked shapes, each kept in ``seen`` by
    the design's bytes; one of ``stop_on`` raised as :class:`_Stop`."""

    def fn(x):
        try:
            f, df, g, dg = criteria(x)
        except stop_on as e:
            raise _Stop(str(e)) from e
        g = np.asarray(g, float).reshape(-1)
        f, df = np.asarray(f, float), np.asarray(df, float)
        f = f.reshape(-1) if f.ndim > 1 else f
        try:
            df = df.reshape(f.shape + (nv,))
            dg = np.asarray(dg, float).reshape(len(g), nv)
        except ValueError:
            raise ModelError(f"refine: criteria gave an objective of shape {f.shape}, its "
                             f"gradient of shape {df.shape}, {len(g)} constraints and their "
                             f"Jacobian of shape {np.shape(dg)}, for {nv} variables") from None
        seen[x.tobytes()] = value = (f, df, g, dg)
        return value
    return fn


def _constraint_names(constraint_names, m):
    """The names of the ``m`` constraints (default ``constraint 0``…), checked."""
    if constraint_names is None:
        constraint_names = tuple(f"constraint {j}" for j in range(m))
    constraint_names = tuple(constraint_names)
    if len(constraint_names) != m:
        raise ModelError(f"refine: {len(constraint_names)} constraint names for {m} "
                         f"constraints")
    return constraint_names


def _epigraph(ev, nv, fs, maximize, slack, count):
    """SLSQP's objective, its gradient, the constraints and their Jacobian at
    ``w = (z, t)`` for an array objective, with the epigraph variable t: maximise t
    with f_i ≥ t (minimise t with f_i ≤ t); ``count["g"]`` counts the gradients."""
    sign = -1.0 if maximize else 1.0

    def fun(w):
        return sign * w[-1] / fs

    def jac(w):
        count["g"] += 1
        d = np.zeros_like(w)
        d[-1] = sign / fs
        return d

    def cons(w):
        f, _, g, _ = ev(w[:nv])
        return np.concatenate([(f - w[-1]) / fs if maximize else (w[-1] - f) / fs,
                               g - slack])

    def cons_jac(w):
        _, df, _, dg = ev(w[:nv])
        k = len(df)
        head = (np.hstack([(df * ev.span) / fs, -np.ones((k, 1)) / fs]) if maximize else
                np.hstack([-(df * ev.span) / fs, np.ones((k, 1)) / fs]))
        return np.vstack([head, np.hstack([dg * ev.span, np.zeros((len(dg), 1))])])
    return fun, jac, cons, cons_jac


def _direct(ev, fs, maximize, slack, count):
    """SLSQP's objective, its gradient, the constraints and their Jacobian at the
    scaled design ``z`` for a number objective; ``count["g"]`` counts the gradients."""

    def fun(z):
        f = ev(z)[0]
        return float((-f if maximize else f) / fs)

    def jac(z):
        count["g"] += 1
        d = ev(z)[1] * ev.span
        return (-d if maximize else d) / fs

    def cons(z):
        return ev(z)[2] - slack

    def cons_jac(z):
        return ev(z)[3] * ev.span
    return fun, jac, cons, cons_jac


def _slsqp(fun, w0, jac, wb, constraints, z0, zhi, maxiter, ftol):
    """Run SLSQP from ``w0``: the scaled design it ends at (the last iterate when a
    trial design raised :class:`_Stop`), its iterations, whether it stopped so,
    whether it converged, and its message."""
    from scipy.optimize import minimize

    nv = len(z0)
    iterates = [z0]
    stopped = False
    try:
        res = minimize(fun, w0, jac=jac, method="SLSQP", bounds=wb, constraints=constraints,
                       callback=lambda wk: iterates.append(np.array(wk[:nv])),
                       options={"maxiter": int(maxiter), "ftol": ftol})
        z, nit = np.clip(res.x[:nv], 0.0, zhi), int(res.nit)
        success, message = bool(res.success), str(res.message)
    except _Stop as e:
        # a trial step left the designs that can be evaluated: the last iterate is the result
        z, nit, stopped, success = iterates[-1], len(iterates) - 1, True, False
        message = f"stopped: a trial design could not be evaluated ({e})"
    return z, nit, stopped, success, message


@dataclass(frozen=True)
class Refined:
    """Result of :func:`local_refine`.

    Attributes
    ----------
    params : dict of str to float
        The refined values [SI].
    value, start_value : float
        The smallest output over the positions after and before [its unit].
    success : bool
    message : str
    nit : int
        SLSQP iterations.
    evaluations : int
        Calls of :func:`~assur.synthesis.sensitivity.sensitivities` (each: all
        positions, value and gradient).
    note : str
        ``""``, or in words: the start or the result does not hold a limit.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.synthesis.refine import local_refine
    >>> r = local_refine(examples.hitch_003(), [0.42, 0.67], "G(ГЦ, 56)", {"X01": (0.40, 0.43)})
    >>> r.success, r.params, round(r.value)   # X01 [m], smallest G56 [N]
    (True, {'X01': 0.4}, 34209)
    >>> r.value > r.start_value, r.note       # improved; no limits to break
    (True, '')
    """

    params: dict
    value: float
    start_value: float
    success: bool
    message: str
    nit: int
    evaluations: int
    note: str = ""


def local_refine(mech, q, maximize, bounds, limits=(), *, maxiter=100, ftol=1e-10):
    """Maximise the smallest ``maximize`` over the positions ``q`` by SLSQP with exact
    gradients (:func:`refine` with an array objective: the epigraph form).

    Maximising the smallest value of an output over the positions (the capacity at
    the weakest position) is not smooth — the weakest position changes. Written in
    epigraph form it is: maximise t subject to ``output(x, q_i) ≥ t`` at every
    position q_i, a smooth problem whose constraint gradients are the exact
    sensitivities of :func:`assur.synthesis.sensitivity.sensitivities` (one call
    gives all positions and all parameters). Limits ``output(x, q_i) ≤ c`` or ``≥ c``
    (a pressure at most the relief setting, a height kept) are constraints of the
    same kind, each divided by ``|c|`` (1 if 0).

    Parameters
    ----------
    mech : Mechanism
        Its values of the parameters in ``bounds`` are the start (clipped to the bounds).
    q : array_like, shape (n,)
        Positions [m or rad].
    maximize : str
        An output (:mod:`assur.core.outputs` notation), e.g. ``"G(ГЦ, S6)"``.
    bounds : mapping of str to (float, float)
        The design parameters and their bounds [SI].
    limits : sequence of (str, str, float)
        ``(output, "<=" or ">=", value)`` at every position [SI].
    maxiter : int
    ftol : float
        SLSQP's tolerance on the objective (scaled by the start value).

    Returns
    -------
    Refined

    Raises
    ------
    ModelError
        An unknown parameter, output or relation.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.synthesis.refine import local_refine
    >>> m = examples.hitch_003()
    >>> r = local_refine(m, [0.42, 0.545, 0.67], "G(ГЦ, 56)", {"X01": (0.40, 0.43)})  # S [m]
    >>> r.success, r.params                   # the cylinder's pivot moves to its bound [m]
    (True, {'X01': 0.4})
    >>> round(r.start_value), round(r.value)  # smallest capacity at 56, from table 4.1's [N]
    (33139, 34209)

    A pressure limit the seed's design breaks at the end of the stroke (16.06 MPa):
    the refined design holds it, for a little capacity.

    >>> r = local_refine(m, [0.42, 0.545, 0.67], "G(ГЦ, 56)", {"X01": (0.40, 0.43)},
    ...                  limits=[("p(ГЦ)", "<=", 16e6)])          # [Pa]
    >>> r.success, round(r.params["X01"], 4), round(r.value)      # [m], [N]
    (True, 0.4186, 32859)
    >>> print(r.note)
    the start is not feasible: p(ГЦ) ≤ 16000000 Pa at position 2 does not hold: its scaled margin is -0.00398
    """
    names = tuple(bounds)
    if not names:
        raise ModelError("local_refine: give at least one parameter with its bounds")
    for o, rel, _ in limits:
        if rel not in ("<=", ">="):
            raise ModelError(f"local_refine: a limit's relation must be one of: ['<=', '>='], "
                             f"got {rel!r}")
    outputs = [maximize] + [o for o, _, _ in limits]
    x0 = np.array([float(mech.params[p]) for p in names])
    npos = len(np.atleast_1d(np.asarray(q, float)))

    def criteria(x):
        s = sensitivities(mech, q, params=names, outputs=outputs, values=dict(zip(names, x)))
        val, jac = s.value, s.jacobian       # (positions, outputs), (…, parameters)
        g, dg = [], []
        for k, (_, rel, c) in enumerate(limits, start=1):
            d = val[:, k] - c
            g.append((-d if rel == "<=" else d) / (abs(c) or 1.0))
            dg.append(jac[:, k, :] * (-1.0 if rel == "<=" else 1.0) / (abs(c) or 1.0))
        return (val[:, 0], jac[:, 0, :], np.concatenate(g) if g else np.zeros(0),
                np.concatenate(dg) if dg else np.zeros((0, len(names))))

    shown = {"<=": "≤", ">=": "≥"}
    units = {o: output_unit(mech, o) for o, _, _ in limits}
    r = refine(criteria, x0, [bounds[p] for p in names], maximize=True, names=names,
               constraint_names=[f"{o} {shown[rel]} {c:.10g} {units[o]} at position {i}"
                                 for o, rel, c in limits for i in range(npos)],
               maxiter=maxiter, ftol=ftol)
    note = "; ".join(n for n in (r.start_note, r.note) if n)
    return Refined(r.params, r.value, r.start_value, r.success, r.message, r.nit, r.nfev, note)
