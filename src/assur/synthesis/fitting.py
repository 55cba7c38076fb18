"""Fitting parameters to a table: robust least squares over parameters with bounds.

A source often prints a table of a mechanism's outputs but not all of its
dimensions (seed 001 lab 5 prints φ5, φ3', φ5', U53 over S = 0.35…0.51 m and no
link lengths). :func:`fit_parameters` finds the parameters that reproduce such a
table: each :class:`Target` is a quantity — any expression of the model's extra
formulas (:class:`assur.core.columns.Formula`: ``phi(5)``, ``dphi(3)``,
``dphi(5)/dphi(3)``, ``X(45)``, …) — tabulated at positions of the generalized
coordinate with the precision it is printed at.

Method
------
1. **Screening** (vectorized): ``screen`` candidate designs drawn uniformly (a
   seeded Sobol sequence) inside the bounds are solved as one batch of designs
   (DESIGN.md §1); designs that do not assemble at every tabulated position are
   dropped; the ``starts`` best by robust cost are kept.
2. **Refinement**: :func:`scipy.optimize.least_squares` (trust-region reflective,
   bounds) from each start. The residual of a tabulated value is scaled by its
   printed precision, ``r = (model − printed)/tolerance`` (``tolerance`` = half a
   unit of the last printed digit), so that ``|r| ≤ 1`` means "reproduced at the
   printed precision".
3. **Robustness to a misprint**: the loss is ``"soft_l1"`` with ``f_scale = 1``
   (one tolerance): residuals within the printed precision count quadratically, a
   misprinted value only linearly, so one wrong digit cannot drag the fit; after the
   fit every value with ``|r| > outlier`` (default 20 tolerances) is returned as an
   outlier, to be flagged, never silently dropped; the fit is then refined once
   without the outliers, which removes what pull the robust loss left them.

A design that fails to assemble at a tabulated position gets the residual
:data:`FAIL_RESIDUAL` everywhere (the trust region then shrinks back), and a
refinement that ends at such a design is discarded.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import least_squares

from ..core.columns import Formula, FormulaError
from ..core.inputs import bytes_per_position, check_memory
from ..errors import AssemblyError, ModelError

__all__ = ["Target", "FitResult", "fit_parameters", "FAIL_RESIDUAL"]

#: residual [tolerances] of every value of a design that cannot assemble: far above
#: what any assembling design can miss by (an angle off by 360° at 0.0005° is 7e5)
FAIL_RESIDUAL = 1e12


@dataclass(frozen=True)
class Target:
    """A tabulated quantity to reproduce.

    Parameters
    ----------
    name : str
        The column's name in the source (``"phi5"``).
    expr : str
        The quantity as a formula expression (:class:`assur.core.columns.Formula`),
        evaluated in SI: ``"phi(5)"`` [rad], ``"dphi(3)"`` [rad/m].
    positions : array_like, shape (n,)
        Values of the (single) generalized coordinate [SI].
    values : array_like, shape (n,)
        The printed values, in ``unit``.
    scale : float
        SI value of one ``unit`` (π/180 for degrees). Default 1.
    tolerance : float or array_like, shape (n,)
        Half a unit of the last printed digit, in ``unit`` (0.0005 for 3 decimals);
        one per value when the values are printed to different precisions.
    period : float, optional
        A period of the quantity in ``unit`` (360 for an angle in degrees): the
        residual is then taken modulo the period.

    Examples
    --------
    φ6 of the seed-003 hitch printed in degrees to 3 decimals at six cylinder
    lengths; the hitch itself reproduces it within the printed precision:

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.synthesis.fitting import Target
    >>> S = [0.42, 0.47, 0.52, 0.57, 0.62, 0.67]  # [m]
    >>> phi6 = [88.458, 90.028, 92.817, 96.905, 102.615, 110.344]  # [deg]
    >>> t = Target("phi6", "phi(6)", S, phi6, scale=np.pi / 180, tolerance=0.0005, period=360)
    >>> r = t.residual(examples.hitch_003().solve(S))  # [tolerances]
    >>> bool(np.all(np.abs(r) <= 1))
    True
    >>> Target("phi6", "phi(6)", S, phi6[:5])
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: target 'phi6': 6 positions and 5 values; give one value per position
    """

    name: str
    expr: str
    positions: tuple
    values: tuple
    scale: float = 1.0
    tolerance: float | tuple = 0.0005
    period: float | None = None
    _formula: Formula = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self):
        q = np.asarray(self.positions, dtype=float).reshape(-1)
        v = np.asarray(self.values, dtype=float).reshape(-1)
        if q.size != v.size or q.size == 0:
            raise ModelError(f"target {self.name!r}: {q.size} positions and {v.size} values; "
                             f"give one value per position")
        if not (np.isfinite(q).all() and np.isfinite(v).all()):
            raise ModelError(f"target {self.name!r}: positions and values must be finite")
        tol = np.broadcast_to(np.asarray(self.tolerance, dtype=float), v.shape)
        if not (np.all(tol > 0) and np.all(np.isfinite(tol)) and self.scale > 0):
            raise ModelError(f"target {self.name!r}: tolerance and scale must be positive")
        object.__setattr__(self, "tolerance", tuple(tol.tolist()) if np.ndim(self.tolerance)
                           else float(self.tolerance))
        object.__setattr__(self, "positions", tuple(q.tolist()))  # plain floats (their repr)
        object.__setattr__(self, "values", tuple(v.tolist()))
        object.__setattr__(self, "_formula", Formula(self.name, self.expr))

    def residual(self, kin):
        """``(model − printed)/tolerance`` at the positions, shape ``kin.shape``.

        Examples
        --------
        φ6 of the seed-003 hitch (L7 = 0.7522 m) printed to 0.001°, against a top
        link L7 = 0.75 m: off by about half a degree, ~1000 tolerances of 0.0005°.

        >>> import numpy as np
        >>> from assur import examples
        >>> from assur.synthesis.fitting import Target
        >>> S = [0.42, 0.47, 0.52]  # [m]
        >>> t = Target("phi6", "phi(6)", S, [88.458, 90.028, 92.817], scale=np.pi / 180)
        >>> np.round(t.residual(examples.hitch_003(L7=0.75).solve(S))).tolist()  # [tolerances]
        [494.0, 483.0, 496.0]
        """
        d = self._formula.evaluate(kin) / self.scale - np.asarray(self.values)
        if self.period is not None:
            d = (d + 0.5 * self.period) % self.period - 0.5 * self.period
        return d / np.asarray(self.tolerance)


@dataclass
class FitResult:
    """Result of :func:`fit_parameters`.

    Attributes
    ----------
    params : dict of str to float
        The fitted parameters [SI].
    residuals : dict of str to numpy.ndarray
        Per target, ``(model − printed)/tolerance`` at its positions [tolerances].
    outliers : list of (str, float, float, float)
        ``(target, position [SI], printed, fitted)`` of every value off by more than
        ``outlier`` tolerances: a misprint of the source to flag.
    cost : float
        The robust cost at the optimum.
    starts : int
        Refinements run.

    Examples
    --------
    The top link L7 of the seed-003 hitch fitted to its φ6 table with one misprint
    (96.905° printed as 106.905°): L7 comes back as the seed's 0.7522 m and the
    misprint as an outlier.

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.synthesis.fitting import Target, fit_parameters
    >>> S = [0.42, 0.47, 0.52, 0.57, 0.62, 0.67]  # [m]
    >>> phi6 = [88.458, 90.028, 92.817, 106.905, 102.615, 110.344]  # [deg], 4th misprinted
    >>> table = Target("phi6", "phi(6)", S, phi6, scale=np.pi / 180, tolerance=0.0005, period=360)
    >>> fit = fit_parameters(examples.hitch_003(L7=0.7), {"L7": (0.6, 0.9)}, [table],
    ...                      screen=16, starts=1)
    >>> round(fit.params["L7"], 4), fit.starts  # [m], refinements
    (0.7522, 1)
    >>> [(t, float(q), float(v), round(float(f), 3)) for t, q, v, f in fit.outliers]  # [m], [deg]
    [('phi6', 0.57, 106.905, 96.905)]
    """

    params: dict
    residuals: dict
    outliers: list
    cost: float
    starts: int

    def max_residual(self, exclude_outliers=True):
        """Largest |residual| [tolerances], the outliers left out by default.

        Examples
        --------
        The fit of the seed-003 hitch's L7 to its φ6 table with one misprint: the
        other values are reproduced within the printed precision.

        >>> import numpy as np
        >>> from assur import examples
        >>> from assur.synthesis.fitting import Target, fit_parameters
        >>> S = [0.42, 0.47, 0.52, 0.57, 0.62, 0.67]  # [m]
        >>> phi6 = [88.458, 90.028, 92.817, 106.905, 102.615, 110.344]  # [deg], 4th misprinted
        >>> table = Target("phi6", "phi(6)", S, phi6, scale=np.pi / 180, tolerance=0.0005, period=360)
        >>> fit = fit_parameters(examples.hitch_003(L7=0.7), {"L7": (0.6, 0.9)}, [table],
        ...                      screen=16, starts=1)
        >>> fit.max_residual() <= 1  # [tolerances]
        True
        >>> round(fit.max_residual(exclude_outliers=False), -1)  # the misprint [tolerances]
        20000.0
        """
        worst = 0.0
        out = {(t, p) for t, p, *_ in self.outliers} if exclude_outliers else set()
        for name, r in self.residuals.items():
            for p, v in zip(self._positions[name], r):
                if (name, p) not in out:
                    worst = max(worst, abs(float(v)))
        return worst

    _positions: dict = field(default_factory=dict, repr=False)


def _residuals(mech, names, x, targets, q):
    """Residuals of the designs ``x`` (shape (m, p)), shape (m, Σn), and the mask of
    designs that assemble at every position (the others get FAIL_RESIDUAL)."""
    m = x.shape[0]
    params = {n: x[:, i] for i, n in enumerate(names)}
    out = np.full((m, sum(len(t.values) for t in targets)), FAIL_RESIDUAL)
    none = np.zeros(m, dtype=bool)
    try:
        kin = mech.with_params(**params).solve(q, on_failure="report")
    except (AssemblyError, ModelError):
        return out, none
    ok = np.asarray(kin.ok).reshape(m, -1).all(axis=1)
    if not ok.any():
        return out, none
    good = np.flatnonzero(ok)
    if not ok.all():
        params = {n: x[good, i] for i, n in enumerate(names)}
        try:
            kin = mech.with_params(**params).solve(q, on_failure="raise")
        except (AssemblyError, ModelError):
            return out, none
    cols = []
    try:
        for t in targets:
            idx = np.searchsorted(q, np.asarray(t.positions))
            cols.append(t.residual(kin).reshape(len(good), -1)[:, idx])
    except FormulaError:
        return out, none
    out[good] = np.concatenate(cols, axis=1)
    return out, ok


def _jacobian(mech, names, x, targets, q):
    """∂(residuals)/∂x at one design ``x`` (shape (p,)), shape (Σn, p) [1/SI]: exact,
    the targets' formulas over the forward-mode dual numbers of :mod:`assur.synthesis.sensitivity`
    (:meth:`assur.core.columns.Formula.compute`); zeros where the design does not assemble
    (the residuals are the constant FAIL_RESIDUAL there). None when a formula needs
    what the dual numbers do not carry (``ddphi``): the caller differences instead."""
    from .sensitivity import jet_context
    jac = np.zeros((sum(len(t.values) for t in targets), len(names)))
    if not _residuals(mech, names, x[None, :], targets, q)[1][0]:
        return jac
    ctx = jet_context(mech.with_params(**dict(zip(names, x))), q, names, reactions=False)
    j = 0
    try:
        for t in targets:
            idx = np.searchsorted(q, np.asarray(t.positions))
            _, der = ctx.plain(t._formula.compute(ctx.formula_terms()))
            tol = np.broadcast_to(np.asarray(t.tolerance, dtype=float), (len(idx),))
            jac[j:j + len(idx)] = der.reshape(-1, len(names))[idx] / (t.scale * tol[:, None])
            j += len(idx)
    except ModelError:
        return None
    return jac


def _cost(r):
    """The soft-l1 cost per design (f_scale = 1): Σ 2(√(1 + r²) − 1)."""
    return np.sum(2.0 * (np.sqrt(1.0 + r * r) - 1.0), axis=-1)


def fit_parameters(mech, bounds, targets, *, screen=4096, starts=8, seed=0, outlier=20.0,
                   loss="soft_l1", start=None):
    """Parameters within ``bounds`` that reproduce the tabulated ``targets``.

    Parameters
    ----------
    mech : Mechanism
        One coordinate; its other parameters stay as they are.
    bounds : mapping of str to (float, float)
        The parameters to fit and their bounds [SI].
    targets : sequence of Target
    screen : int
        Candidate designs of the vectorized screening (a power of 2 is best).
    starts : int
        Least-squares refinements, from the best screened designs.
    seed : int
        Seed of the Sobol sequence (the fit is reproducible).
    outlier : float
        |residual| [tolerances] above which a value is reported as an outlier.
    loss : str
        The loss of :func:`scipy.optimize.least_squares` (``"soft_l1"``: robust).
    start : mapping of str to float, optional
        A start of its own [SI] (e.g. an earlier fit), refined besides the screened
        ones; the parameters it leaves out start at the mechanism's values.

    Returns
    -------
    FitResult

    Raises
    ------
    ModelError
        If no screened design assembles at every tabulated position.

    Examples
    --------
    φ6 of the seed-003 hitch printed to 0.001° with one misprinted value, fitted by
    L7 from a wrong start (0.7 m): the seed's L7 = 0.7522 m comes back.

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.synthesis.fitting import Target, fit_parameters
    >>> S = [0.42, 0.47, 0.52, 0.57, 0.62, 0.67]  # [m]
    >>> phi6 = [88.458, 90.028, 92.817, 106.905, 102.615, 110.344]  # [deg], 4th misprinted
    >>> table = Target("phi6", "phi(6)", S, phi6, scale=np.pi / 180, tolerance=0.0005, period=360)
    >>> fit = fit_parameters(examples.hitch_003(L7=0.7), {"L7": (0.6, 0.9)}, [table],
    ...                      screen=16, starts=1)
    >>> round(fit.params["L7"], 4)  # [m]
    0.7522
    >>> len(fit.outliers), np.round(fit.residuals["phi6"][[0, 3]]).tolist()  # [tolerances]
    (1, [-1.0, -20000.0])
    >>> fit_parameters(examples.hitch_003(), {"Lx": (0.6, 0.9)}, [table])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: fit_parameters: unknown parameter(s) ['Lx']; known: [...]
    """
    if len(mech.coordinates) != 1:
        raise ModelError(f"fit_parameters: {mech.name!r} has {len(mech.coordinates)} "
                         f"coordinates; fitting supports one")
    names = list(bounds)
    unknown = [n for n in names if n not in mech.params]
    if unknown:
        raise ModelError(f"fit_parameters: unknown parameter(s) {unknown}; known: "
                         f"{sorted(mech.params)}")
    lo = np.array([float(bounds[n][0]) for n in names])
    hi = np.array([float(bounds[n][1]) for n in names])
    if not np.all(hi > lo):
        raise ModelError(f"fit_parameters: every bound needs low < high: {dict(bounds)}")
    q = np.unique(np.concatenate([np.asarray(t.positions) for t in targets]))
    from scipy.stats import qmc

    # the screening solves every candidate at every tabulated position at once
    cols = sum(len(t.values) for t in targets)
    check_memory(screen, q.size * bytes_per_position(mech) + 24 * (len(names) + cols) + 64,
                 f"fit_parameters: screen = {screen} designs × {q.size} positions",
                 unit="designs", reduce="the screened designs (--screen)")
    sob = qmc.Sobol(len(names), scramble=True, seed=seed).random(screen)
    cand = lo + sob * (hi - lo)
    r0, ok = _residuals(mech, names, cand, targets, q)
    cost = np.where(ok, _cost(r0), np.inf)
    order = np.argsort(cost)[:int(ok.sum())]
    if not ok.any() and start is None:
        raise ModelError(f"fit_parameters: none of {screen} designs within the bounds "
                         f"assembles at every tabulated position; widen the bounds")
    x0s = list(cand[order[:starts]])
    if start is not None:
        x0s.insert(0, np.clip([float(start.get(n, mech.params[n])) for n in names], lo, hi))
    best = None

    def assembles(x):
        return bool(_residuals(mech, names, x[None, :], targets, q)[1][0])

    exact = _jacobian(mech, names, x0s[0], targets, q) is not None

    def jac(x, keep=slice(None)):
        return _jacobian(mech, names, x, targets, q)[keep]

    for x0 in x0s:
        sol = least_squares(lambda x: _residuals(mech, names, x[None, :], targets, q)[0][0],
                            x0, jac=jac if exact else "2-point", bounds=(lo, hi), loss=loss,
                            f_scale=1.0, x_scale="jac", xtol=1e-14, ftol=1e-14, gtol=1e-14,
                            max_nfev=2000)
        if not assembles(sol.x):   # never return a design that cannot assemble
            continue
        if best is None or sol.cost < best.cost:
            best = sol
    if best is None:
        raise ModelError(f"fit_parameters: no refinement of {len(x0s)} start(s) ended at a "
                         f"design that assembles at every tabulated position")
    r = _residuals(mech, names, best.x[None, :], targets, q)[0][0]
    keep = np.abs(r) <= outlier
    if not keep.all() and keep.any():
        # refine without the outliers: the robust loss limits their pull, this removes it
        def kept(x):
            return _residuals(mech, names, x[None, :], targets, q)[0][0][keep]

        sol = least_squares(kept, best.x, jac=(lambda x: jac(x, keep)) if exact else "2-point",
                            bounds=(lo, hi), loss=loss, f_scale=1.0, x_scale="jac",
                            xtol=1e-14, ftol=1e-14, gtol=1e-14, max_nfev=2000)
        if assembles(sol.x):
            best = sol
        r = _residuals(mech, names, best.x[None, :], targets, q)[0][0]
    residuals, outliers, positions, j = {}, [], {}, 0
    for t in targets:
        rt = r[j:j + len(t.values)]
        j += len(t.values)
        residuals[t.name] = rt
        positions[t.name] = t.positions
        tol = np.broadcast_to(np.asarray(t.tolerance), rt.shape)
        for p, v, e, tl in zip(t.positions, t.values, rt, tol):
            if abs(e) > outlier:
                outliers.append((t.name, p, v, v + e * float(tl)))
    return FitResult({n: float(v) for n, v in zip(names, best.x)}, residuals, outliers,
                     float(best.cost), len(x0s), positions)
