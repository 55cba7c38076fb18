"""What :func:`assur.synthesis.refine.refine` works with and gives: the design
variables scaled to [0, 1] with one evaluation per point (:class:`Scaled`) and the
result (:class:`Refinement`) (:mod:`assur.synthesis.refine`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Scaled", "Refinement", "TOL"]

#: constraints held to within this [-] (they are scaled to order one) count as held
TOL = 1e-9


class Scaled:
    """Design variables scaled to [0, 1] over their bounds, and one evaluation per
    point shared by SLSQP's objective, constraints and their gradients (SLSQP asks
    for each at the same point): the machinery of :func:`refine`.

    Parameters
    ----------
    lo, hi : array_like, shape (variables,)
        Bounds [SI]; a variable with ``hi == lo`` is scaled by 1.
    fn : callable
        ``fn(x)`` at the unscaled design ``x`` [SI] → anything (the values and
        gradients of one sensitivity call); evaluated once per distinct point (the
        last point is remembered).
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
    >>> from assur.synthesis.refine import Scaled
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
        >>> from assur.synthesis.refine import Scaled
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
        >>> from assur.synthesis.refine import Scaled
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


def _worst(g, names, tol) -> str:
    """The most violated constraint of ``g`` (and how many more) in words, "" if none."""
    bad = np.flatnonzero(~(g >= -tol))
    if not len(bad):
        return ""
    j = bad[np.argmin(np.where(np.isnan(g[bad]), -np.inf, g[bad]))]
    more = f" (and {len(bad) - 1} more)" if len(bad) > 1 else ""
    return f"{names[j]} does not hold: its scaled margin is {g[j]:.3g}{more}"


@dataclass(frozen=True)
class Refinement:
    """Result of :func:`refine`.

    Attributes
    ----------
    x : ndarray, shape (n,)
        The refined design, within the bounds [SI]: SLSQP's result, or the last
        iterate when a trial design could not be evaluated (``stopped``).
    start : ndarray, shape (n,)
        The start, within the bounds (where SLSQP started) [SI].
    value, start_value : float
        The objective at ``x`` and at ``start`` — for an array objective its largest
        element (its smallest with ``maximize``) [its unit].
    g, start_g : ndarray, shape (m,)
        The constraints at ``x`` and at ``start``, as ``criteria`` gives them
        (held where ≥ 0) [-].
    success : bool
        SLSQP reports convergence (False when stopped).
    message : str
        SLSQP's message, or ``"stopped: a trial design could not be evaluated (…)"``.
    nit : int
        SLSQP iterations.
    nfev : int
        Calls of ``criteria`` (one per distinct design).
    njev : int
        Requests of the objective's gradient by SLSQP.
    stopped : bool
        A trial design raised one of ``stop_on``.
    names, constraint_names : tuple of str
        Of the variables and of the constraints (for the notes).
    maximize : bool
        The objective was maximised.
    tol : float
        A constraint counts as held where ``g ≥ −tol`` [-].

    Examples
    --------
    >>> import numpy as np
    >>> from assur.synthesis.refine import refine
    >>> r = refine(lambda x: ((x[0] - 2) ** 2, [2 * (x[0] - 2)], [], np.zeros((0, 1))),
    ...            [0.0], [(-1.0, 1.0)], names=("a",))   # (a − 2)², a within [−1, 1]
    >>> round(r.params["a"], 6), round(r.value, 6), r.start_value, r.g.shape  # at the bound
    (1.0, 1.0, 4.0, (0,))
    >>> r.success, r.feasible, r.improved, r.note
    (True, True, True, '')
    """

    x: np.ndarray
    start: np.ndarray
    value: float
    start_value: float
    g: np.ndarray
    start_g: np.ndarray
    success: bool
    message: str
    nit: int
    nfev: int
    njev: int
    stopped: bool = False
    names: tuple = ()
    constraint_names: tuple = ()
    maximize: bool = False
    tol: float = TOL

    @property
    def params(self) -> dict:
        """The refined design by variable name [SI].

        Examples
        --------
        >>> from assur.synthesis.refine import refine
        >>> r = refine(lambda x: (-x[0], [-1.0], [], [[]]), [0.0], [(0.0, 0.5)], names=("L",))
        >>> {k: round(v, 6) for k, v in r.params.items()}  # − L is smallest at L's upper bound [m]
        {'L': 0.5}
        """
        return {n: float(v) for n, v in zip(self.names, self.x)}

    @property
    def feasible(self) -> bool:
        """Whether the refined design holds every constraint (to ``tol``).

        Examples
        --------
        >>> from assur.synthesis.refine import refine
        >>> r = refine(lambda x: (x[0], [1.0], [x[0] - 2.0], [[1.0]]), [0.0], [(0.0, 1.0)],
        ...            constraint_names=("x ≥ 2",))  # x ≥ 2 cannot hold within [0, 1]
        >>> r.feasible, r.start_feasible
        (False, False)
        """
        return bool(np.all(self.g >= -self.tol))

    @property
    def start_feasible(self) -> bool:
        """Whether the start holds every constraint (to ``tol``).

        Examples
        --------
        >>> from assur.synthesis.refine import refine
        >>> r = refine(lambda x: (x[0], [1.0], [1.0 - x[0]], [[-1.0]]), [0.5], [(0.0, 2.0)])
        >>> r.start_feasible, r.feasible, round(r.params["x0"], 6) + 0.0  # x ≤ 1 holds; x → 0
        (True, True, 0.0)
        """
        return bool(np.all(self.start_g >= -self.tol))

    @property
    def improved(self) -> bool:
        """The objective is strictly better at ``x`` than at the start.

        Examples
        --------
        >>> from assur.synthesis.refine import refine
        >>> r = refine(lambda x: (x[0] ** 2, [2 * x[0]], [], [[]]), [0.0], [(-1.0, 1.0)])
        >>> r.improved, r.value      # the start is the optimum already
        (False, 0.0)
        """
        if self.maximize:
            return bool(self.value > self.start_value)
        return bool(self.value < self.start_value)

    @property
    def start_note(self) -> str:
        """``""`` if the start holds every constraint, else which one does not, in words.

        Examples
        --------
        >>> from assur.synthesis.refine import refine
        >>> r = refine(lambda x: (x[0], [1.0], [1.0 - x[0]], [[-1.0]]), [1.5], [(0.0, 2.0)],
        ...            constraint_names=("x ≤ 1",))
        >>> print(r.start_note)
        the start is not feasible: x ≤ 1 does not hold: its scaled margin is -0.5
        >>> r.feasible, round(r.params["x0"], 6) + 0.0  # the result holds it
        (True, 0.0)
        """
        why = _worst(self.start_g, self.constraint_names, self.tol)
        return f"the start is not feasible: {why}" if why else ""

    @property
    def note(self) -> str:
        """``""`` if the refined design holds every constraint, else which one does not,
        in words.

        Examples
        --------
        >>> from assur.synthesis.refine import refine
        >>> r = refine(lambda x: (x[0], [1.0], [x[0] - 2.0], [[1.0]]), [0.0], [(0.0, 1.0)],
        ...            constraint_names=("x ≥ 2",))  # cannot hold within [0, 1]
        >>> print(r.note)
        the result is not feasible: x ≥ 2 does not hold: its scaled margin is -1
        """
        why = _worst(self.g, self.constraint_names, self.tol)
        return f"the result is not feasible: {why}" if why else ""

    def summary(self, show=None) -> str:
        """One line: the objective from the start to the result, SLSQP's iterations and
        message, and what does not hold. ``show`` formats a value (default ``"{:.6g}"``).

        Examples
        --------
        >>> from assur.synthesis.refine import refine
        >>> r = refine(lambda x: (x[0], [1.0], [1.0 - x[0]], [[-1.0]]), [1.5], [(0.0, 2.0)],
        ...            constraint_names=("x ≤ 1",))
        >>> print(r.summary(lambda v: f"{v:.3f}"))                # doctest: +ELLIPSIS
        refine (SLSQP, exact gradients): 1.500 → 0.000 (... iterations, ... evaluations: ...); the start is not feasible: x ≤ 1 does not hold: its scaled margin is -0.5
        """
        show = show or (lambda v: f"{float(v):.6g}")
        parts = [f"refine (SLSQP, exact gradients): {show(self.start_value)} → "
                 f"{show(self.value)} ({self.nit} iterations, {self.nfev} evaluations: "
                 f"{self.message})"]
        parts += [n for n in (self.start_note, self.note) if n]
        return "; ".join(parts)


class _Stop(Exception):
    """``criteria`` raised one of ``stop_on`` at a trial design."""
