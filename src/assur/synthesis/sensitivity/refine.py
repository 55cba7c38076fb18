"""Local refinement of a design with exact gradients: scipy's SLSQP on the epigraph
form of a max–min problem.

Maximising the smallest value of an output over the positions (the capacity at the
weakest position) is not smooth — the weakest position changes. Written in epigraph
form it is: maximise t subject to ``output(x, q_i) ≥ t`` at every position q_i, a
smooth problem whose constraint gradients are the exact sensitivities of
:func:`assur.synthesis.sensitivity.sensitivities` (one call gives all positions and all
parameters). Limits ``output(x, q_i) ≤ c`` or ``≥ c`` (a pressure at most the relief
setting, a height kept) are constraints of the same kind.

This is the local step after a global search (differential evolution) has found
the basin; it does not search the design space itself.

Examples
--------
>>> from assur import examples
>>> from assur.synthesis.sensitivity.refine import local_refine
>>> m = examples.hitch_003()
>>> r = local_refine(m, m.solve([0.42]).q().ravel().tolist() + [0.67], "G(ГЦ, 56)",
...                  {"X01": (0.40, 0.43)})
>>> r.success and r.value >= r.start_value
True
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import ModelError
from . import sensitivities

__all__ = ["local_refine", "Refined", "Scaled"]


class Scaled:
    """Design variables scaled to [0, 1] over their bounds, and one evaluation per
    point shared by SLSQP's objective, constraints and their gradients (SLSQP asks
    for each at the same point): the machinery of :func:`local_refine` and of
    :func:`assur.synthesis.search.polish.polish`.

    Parameters
    ----------
    lo, hi : array_like, shape (variables,)
        Bounds [SI]; a variable with ``hi == lo`` is scaled by 1.
    fn : callable
        ``fn(x)`` at the unscaled design ``x`` [SI] → anything (the values and
        gradients of one sensitivity call); evaluated once per distinct point.
    clip : bool
        Clip ``z`` to [0, 1] before unscaling (SLSQP may step a rounding outside its
        bounds).

    Attributes
    ----------
    span : ndarray
        ``hi − lo`` (1 where 0): d x / d z, the factor of every gradient in z.
    count : int
        Evaluations of ``fn``.

    Examples
    --------
    >>> from assur.synthesis.sensitivity.refine import Scaled
    >>> ev = Scaled([0.40, 1.0], [0.43, 1.0], lambda x: float(x.sum()))  # bounds [m]
    >>> [round(float(v), 6) for v in ev.span]  # the second variable is fixed: scaled by 1 [m]
    [0.03, 1.0]
    >>> round(ev([0.5, 0.0]), 3), round(ev([0.5, 0.0]), 3), ev.count   # one evaluation per point [m]
    (1.415, 1.415, 1)
    """

    def __init__(self, lo, hi, fn, clip=False):
        self.lo, hi = np.asarray(lo, float), np.asarray(hi, float)
        self.span = np.where(hi > self.lo, hi - self.lo, 1.0)
        self.fn, self.clip = fn, clip
        self.count = 0
        self._key = self._value = None

    def x(self, z):
        """The design [SI] at the scaled point ``z``.

        Examples
        --------
        >>> from assur.synthesis.sensitivity.refine import Scaled
        >>> ev = Scaled([0.40], [0.43], fn=None, clip=True)       # X01 in 0.40…0.43 m
        >>> [round(float(v), 3) for v in ev.x([0.5])], [round(float(v), 3) for v in ev.x([1.2])]  # [m]
        ([0.415], [0.43])
        """
        z = np.asarray(z, float)
        return self.lo + (np.clip(z, 0.0, 1.0) if self.clip else z) * self.span

    def z(self, x):
        """The scaled point of the design ``x`` [SI].

        Examples
        --------
        >>> from assur.synthesis.sensitivity.refine import Scaled
        >>> ev = Scaled([0.40], [0.43], fn=None)                  # X01 in 0.40…0.43 m
        >>> [round(float(v), 6) for v in ev.z([0.415])]           # [-]
        [0.5]
        """
        return (np.asarray(x, float) - self.lo) / self.span

    def __call__(self, z):
        key = np.asarray(z, float).tobytes()
        if key != self._key:
            self._value = self.fn(self.x(z))
            self._key = key
            self.count += 1
        return self._value


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
        Calls of :func:`sensitivities` (each: all positions, value and gradient).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.synthesis.sensitivity.refine import local_refine
    >>> r = local_refine(examples.hitch_003(), [0.42, 0.67], "G(ГЦ, 56)", {"X01": (0.40, 0.43)})
    >>> r.success, r.params, round(r.value)   # X01 [m], smallest G56 [N]
    (True, {'X01': 0.4}, 34209)
    >>> r.evaluations >= r.nit > 0            # sensitivity calls, SLSQP iterations
    True
    """

    params: dict
    value: float
    start_value: float
    success: bool
    message: str
    nit: int
    evaluations: int


def local_refine(mech, q, maximize, bounds, limits=(), *, maxiter=100, ftol=1e-10):
    """Maximise the smallest ``maximize`` over the positions ``q`` by SLSQP with exact
    gradients.

    Parameters
    ----------
    mech : Mechanism
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
    >>> from assur.synthesis.sensitivity.refine import local_refine
    >>> m = examples.hitch_003()
    >>> r = local_refine(m, [0.42, 0.545, 0.67], "G(ГЦ, 56)", {"X01": (0.40, 0.43)})  # S [m]
    >>> r.success, r.params                   # the cylinder's pivot moves to its bound [m]
    (True, {'X01': 0.4})
    >>> round(r.start_value), round(r.value)  # smallest capacity at 56, from table 4.1's [N]
    (33139, 34209)
    >>> r = local_refine(m, [0.42, 0.545, 0.67], "G(ГЦ, 56)", {"X01": (0.40, 0.43)},
    ...                  limits=[("p(ГЦ)", "<=", 16e6)])          # a pressure limit [Pa]
    >>> round(r.params["X01"], 4), round(r.value)                 # [m], [N]
    (0.4186, 32859)
    """
    from scipy.optimize import minimize

    names = tuple(bounds)
    if not names:
        raise ModelError("local_refine: give at least one parameter with its bounds")
    for o, rel, _ in limits:
        if rel not in ("<=", ">="):
            raise ModelError(f"local_refine: a limit's relation must be one of: ['<=', '>='], "
                             f"got {rel!r}")
    outputs = [maximize] + [o for o, _, _ in limits]
    lo = np.array([bounds[p][0] for p in names], float)
    hi = np.array([bounds[p][1] for p in names], float)
    x0 = np.array([float(mech.params[p]) for p in names])

    def jets(x):
        s = sensitivities(mech, q, params=names, outputs=outputs, values=dict(zip(names, x)))
        return s.value, s.jacobian * ev.span  # d/dz

    ev = Scaled(lo, hi, jets)
    v0, _ = ev(ev.z(x0))
    scale = float(np.abs(v0[:, 0]).max()) or 1.0
    nv = len(names)

    # variables (z, t): z the scaled parameters in [0, 1], t the bound on the output
    def obj(w):
        return -w[-1] / scale

    def obj_jac(w):
        g = np.zeros_like(w)
        g[-1] = -1.0 / scale
        return g

    def cons(w):
        val, _ = ev(w[:nv])
        parts = [(val[:, 0] - w[-1]) / scale]
        for k, (_, rel, c) in enumerate(limits, start=1):
            d = val[:, k] - c
            parts.append((-d if rel == "<=" else d) / (abs(c) or 1.0))
        return np.concatenate(parts)

    def cons_jac(w):
        _, jac = ev(w[:nv])
        n = jac.shape[0]
        rows = [np.hstack([jac[:, 0, :] / scale, -np.ones((n, 1)) / scale])]
        for k, (_, rel, c) in enumerate(limits, start=1):
            j = jac[:, k, :] * (-1.0 if rel == "<=" else 1.0) / (abs(c) or 1.0)
            rows.append(np.hstack([j, np.zeros((n, 1))]))
        return np.vstack(rows)

    w0 = np.append(ev.z(x0), v0[:, 0].min())
    res = minimize(obj, w0, jac=obj_jac, method="SLSQP",
                   bounds=[(0.0, 1.0)] * nv + [(None, None)],
                   constraints=[{"type": "ineq", "fun": cons, "jac": cons_jac}],
                   options={"maxiter": maxiter, "ftol": ftol})
    z = np.clip(res.x[:nv], 0.0, 1.0)
    val, _ = ev(z)
    x = ev.x(z)
    return Refined(dict(zip(names, (float(v) for v in x))), float(val[:, 0].min()),
                   float(v0[:, 0].min()), bool(res.success), str(res.message), int(res.nit),
                   ev.count)
