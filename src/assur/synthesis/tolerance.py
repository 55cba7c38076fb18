"""Tolerance analysis: Monte Carlo over manufacturing tolerances, and the first-order
stack-up from the exact sensitivities beside it.

A :class:`Tolerance` says how a parameter (a pivot coordinate, a link length, a bore…)
scatters about its nominal value when the machine is built:

* ``normal`` (default): ``±t`` is the ±3σ band (σ = t/3), the usual convention of
  statistical tolerancing; or σ given directly;
* ``uniform``: anywhere within ``±t`` (σ = t/√3).

:func:`monte_carlo` draws ``samples`` machines with a seeded
:class:`numpy.random.Generator`, evaluates them as **one batch of designs** through
the fused kernel (:meth:`assur.Mechanism.evaluate`) over the positions, and returns
the distributions of the outputs (capacity, pressure…) — percentiles P1, P5, P50,
P95, P99 per position and of each machine's worst value over the range — with the
share of machines that fail to assemble and why (the group and its message).

:func:`first_order` is the linear stack-up

.. math::  \\sigma_{out}^2 = \\sum_i \\left(\\frac{\\partial out}{\\partial p_i}\\,
           \\sigma_i\\right)^2

with the derivatives exact (:mod:`assur.synthesis.sensitivity`). For small tolerances the two
agree; for an output linear in the toleranced parameters they agree exactly when the
stack-up uses the σ of the drawn sample (``sigma="sample"``).

Examples
--------
>>> from assur import examples
>>> from assur.synthesis.tolerance import Tolerance, monte_carlo
>>> m = examples.hitch_003()
>>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]
>>> r = monte_carlo(m, [0.45, 0.6], tol, outputs=["p(ГЦ)"], samples=200, seed=1)
>>> r.failure_share
0.0
>>> r.percentiles("p(ГЦ)").shape
(2, 5)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import AssemblyError, ModelError
from ..core.inputs import check_memory

__all__ = ["Tolerance", "ToleranceResult", "monte_carlo", "first_order", "default_outputs",
           "worst_kind",
           "PERCENTILES", "DISTRIBUTIONS"]

#: the percentiles reported [%]
PERCENTILES = (1.0, 5.0, 50.0, 95.0, 99.0)
#: the distributions a tolerance may have
DISTRIBUTIONS = ("normal", "uniform")
#: failing machines whose reason is looked up (each is one solve)
REASONS_MAX = 50


@dataclass(frozen=True)
class Tolerance:
    """The scatter of one parameter about its nominal value.

    Parameters
    ----------
    param : str
        The model parameter.
    pm : float
        Half-width ±t [SI unit of the parameter]: ±3σ of a normal distribution, or
        the bounds of a uniform one.
    dist : {"normal", "uniform"}
    std : float, optional
        Standard deviation σ [SI] of a normal distribution, instead of ``pm``.

    Examples
    --------
    ±0.5 mm on the frame pivot 01 of the seed-003 hitch (±3σ), ±1 mm uniform on
    its brace L4:

    >>> from assur.synthesis.tolerance import Tolerance
    >>> x01, l4 = Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")
    >>> round(x01.sigma * 1e3, 4), round(l4.sigma * 1e3, 4)  # σ [mm]
    (0.1667, 0.5774)
    >>> Tolerance("L4", 1e-3, "triangular")
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: tolerance of 'L4': dist must be one of: ['normal', 'uniform'], got 'triangular'
    """

    param: str
    pm: float = 0.0
    dist: str = "normal"
    std: float | None = None

    def __post_init__(self):
        if self.dist not in DISTRIBUTIONS:
            raise ModelError(f"tolerance of {self.param!r}: dist must be one of: "
                             f"{list(DISTRIBUTIONS)}, got {self.dist!r}")
        if self.dist == "uniform" and self.std is not None:
            raise ModelError(f"tolerance of {self.param!r}: a uniform tolerance is given "
                             f"by its half-width ±t, not by σ")
        s = self.sigma
        if not (math.isfinite(s) and s >= 0.0):
            raise ModelError(f"tolerance of {self.param!r}: the scatter must be finite and "
                             f"not negative, got ±{self.pm!r}, σ = {self.std!r}")

    @property
    def sigma(self) -> float:
        """Standard deviation σ [SI]: t/3 (normal), t/√3 (uniform) or as given.

        Examples
        --------
        >>> from assur.synthesis.tolerance import Tolerance
        >>> round(Tolerance("X01", 0.6e-3).sigma * 1e3, 4)  # ±0.6 mm as ±3σ: σ [mm]
        0.2
        >>> round(Tolerance("L4", 0.6e-3, "uniform").sigma * 1e3, 4)  # t/√3 [mm]
        0.3464
        >>> Tolerance("X01", std=0.25e-3).sigma * 1e3  # given [mm]
        0.25
        """
        if self.std is not None:
            return float(self.std)
        return float(self.pm) / (3.0 if self.dist == "normal" else math.sqrt(3.0))

    def draw(self, rng, n) -> np.ndarray:
        """``n`` deviations from the nominal value [SI].

        Examples
        --------
        Three draws of a uniform ±1 mm: reproducible with a seeded generator, and
        within the band.

        >>> import numpy as np
        >>> from assur.synthesis.tolerance import Tolerance
        >>> d = Tolerance("L4", 1e-3, "uniform").draw(np.random.default_rng(0), 3)
        >>> np.round(d * 1e3, 4).tolist()  # [mm]
        [0.2739, -0.4604, -0.9181]
        """
        if self.dist == "uniform":
            return rng.uniform(-self.pm, self.pm, n)
        return rng.normal(0.0, self.sigma, n)


def default_outputs(mech) -> tuple:
    """Pressure of every cylinder with a coordinate and its capacity at the model's
    transmission points (``[tables] transmissions``) or at the implement's point.

    Examples
    --------
    The seed-003 hitch: the lift cylinder's pressure and its capacity at the
    suspension axis 56 and the implement's centre of mass S6:

    >>> from assur import examples
    >>> from assur.synthesis.tolerance import default_outputs
    >>> default_outputs(examples.hitch_003())
    ('p(ГЦ)', 'G(ГЦ, 56)', 'G(ГЦ, S6)')
    """
    points = list(mech.tables.get("transmissions", ()) or ())
    machine = getattr(mech, "machine", None)
    imp = getattr(machine, "point", None) if machine is not None else None
    if not points and imp:
        points = [imp]
    out = []
    for c in mech.cylinders:
        if c.coordinate is None or c.supply is not None or c.side == "auto":
            continue
        out.append(f"p({c.name})")
        from ..machines.capacity import lifts
        out += [f"G({c.name}, {p})" for p in points if lifts(mech, c.coordinate, p)]
    if not out:
        raise ModelError(f"{mech.name}: no cylinder with a pressure to analyse; name the "
                         f"outputs")
    return tuple(out)


def worst_kind(output) -> str:
    """How a machine's output over the range is summarised, ``"min"`` or ``"max"``:
    its minimum for a capacity or a reserve (the weakest position), its maximum
    otherwise (the peak pressure).

    Examples
    --------
    >>> from assur.synthesis.tolerance import worst_kind
    >>> worst_kind("G(ГЦ, 56)"), worst_kind("p(ГЦ)")
    ('min', 'max')
    """
    return "min" if output.strip().startswith(("G(", "reserve(")) else "max"


@dataclass(frozen=True)
class ToleranceResult:
    """Monte Carlo over the tolerances (and the first-order stack-up beside it).

    Attributes
    ----------
    outputs : tuple of str
    tolerances : tuple of Tolerance
    q : ndarray, shape (n,)
        Positions [m or rad].
    nominal : ndarray, shape (n, outputs)
        Outputs of the nominal machine [SI].
    samples : ndarray, shape (N, n, outputs)
        Outputs of every drawn machine (0 where a machine did not assemble) [SI].
    deviations : ndarray, shape (N, tolerances)
        The drawn deviations of the parameters [SI].
    assembled : ndarray of bool, shape (N,)
        Machines that assemble at every position.
    reasons : tuple of (int, str, str)
        ``(machine, group, message)`` of failing machines (the first :data:`REASONS_MAX`).
    units : mapping of str to str
    seed : int or None
    linear_sigma : ndarray, shape (n, outputs)
        σ of the first-order stack-up with the tolerances' σ [SI].
    gradient : ndarray, shape (n, outputs, tolerances)
        ∂output/∂parameter at the nominal machine [SI].

    Examples
    --------
    200 seed-003 hitches with ±0.5 mm on X01 and ±1 mm uniform on L4, at two
    cylinder lengths:

    >>> from assur import examples
    >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
    >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # ±t [m]
    >>> r = monte_carlo(examples.hitch_003(), [0.45, 0.6], tol, outputs=["p(ГЦ)"],
    ...                 samples=200, seed=1)
    >>> r.samples.shape, r.units["p(ГЦ)"]  # (machines, positions, outputs)
    ((200, 2, 1), 'Pa')
    >>> [round(float(p) / 1e6, 3) for p in r.nominal[:, 0]]  # nominal pressure [MPa]
    [14.569, 15.429]
    >>> r.gradient.shape  # ∂p/∂X01, ∂p/∂L4 at each position
    (2, 1, 2)
    """

    outputs: tuple
    tolerances: tuple
    q: np.ndarray
    nominal: np.ndarray
    samples: np.ndarray
    deviations: np.ndarray
    assembled: np.ndarray
    reasons: tuple
    units: dict
    seed: int | None
    linear_sigma: np.ndarray
    gradient: np.ndarray
    extra: dict = field(default_factory=dict)

    def _o(self, output):
        if output not in self.outputs:
            raise KeyError(f"{output!r} is not an output; outputs: {list(self.outputs)}")
        return self.outputs.index(output)

    @property
    def failure_share(self) -> float:
        """Share of the drawn machines that do not assemble over the whole range [-].

        Examples
        --------
        ±0.3 m uniform on the brace L4 of the seed-003 hitch is far beyond what it
        can take: 14 of 50 machines do not assemble at S = 0.42 or 0.67 m.

        >>> from assur import examples
        >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
        >>> r = monte_carlo(examples.hitch_003(), [0.42, 0.67], [Tolerance("L4", 0.3, "uniform")],
        ...                 outputs=["p(ГЦ)"], samples=50, seed=1)
        >>> r.failure_share  # [-]
        0.28
        >>> r.reasons[0][:2]  # (machine, group that fails)
        (1, 'III (6,7)')
        """
        return float(1.0 - self.assembled.mean())

    def values(self, output) -> np.ndarray:
        """The output of the machines that assembled, shape (N_ok, n) [SI].

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
        >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # ±t [m]
        >>> r = monte_carlo(examples.hitch_003(), [0.45, 0.6], tol, outputs=["p(ГЦ)"],
        ...                 samples=200, seed=1)
        >>> r.values("p(ГЦ)").shape  # (machines, positions)
        (200, 2)
        >>> r.values("p(ГЦ, 56)")
        Traceback (most recent call last):
        ...
        KeyError: "'p(ГЦ, 56)' is not an output; outputs: ['p(ГЦ)']"
        """
        return self.samples[self.assembled, :, self._o(output)]

    def percentiles(self, output, q=PERCENTILES) -> np.ndarray:
        """Percentiles per position, shape (n, len(q)) [SI].

        Examples
        --------
        P1, P5, P50, P95, P99 of the seed-003 hitch's cylinder pressure at
        S = 0.45 and 0.6 m (±0.5 mm on X01, ±1 mm uniform on L4):

        >>> from assur import examples
        >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
        >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # ±t [m]
        >>> r = monte_carlo(examples.hitch_003(), [0.45, 0.6], tol, outputs=["p(ГЦ)"],
        ...                 samples=200, seed=1)
        >>> (np.round(r.percentiles("p(ГЦ)") / 1e6, 3)).tolist()  # [MPa]
        [[14.553, 14.556, 14.569, 14.582, 14.585], [15.407, 15.409, 15.431, 15.449, 15.451]]
        """
        v = self.values(output)
        if v.shape[0] == 0:
            raise ModelError("no drawn machine assembles: no distribution to report")
        return np.percentile(v, q, axis=0).T

    def worst(self, output) -> np.ndarray:
        """Each assembled machine's worst value over the range (minimum of a capacity,
        maximum otherwise), shape (N_ok,) [SI].

        Examples
        --------
        The peak cylinder pressure of each seed-003 hitch drawn, over S = 0.45 and
        0.6 m:

        >>> from assur import examples
        >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
        >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # ±t [m]
        >>> r = monte_carlo(examples.hitch_003(), [0.45, 0.6], tol, outputs=["p(ГЦ)"],
        ...                 samples=200, seed=1)
        >>> w = r.worst("p(ГЦ)")
        >>> w.shape, bool((w == r.values("p(ГЦ)").max(axis=1)).all())
        ((200,), True)
        >>> [round(float(p) / 1e6, 3) for p in w[:3]]  # [MPa]
        [15.413, 15.418, 15.424]
        """
        v = self.values(output)
        return v.min(axis=1) if worst_kind(output) == "min" else v.max(axis=1)

    def worst_percentiles(self, output, q=PERCENTILES) -> np.ndarray:
        """Percentiles of :meth:`worst`, shape (len(q),) [SI].

        Examples
        --------
        The peak pressure of the seed-003 hitches drawn is at S = 0.6 m for every
        one, so its percentiles are those of that position:

        >>> from assur import examples
        >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
        >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # ±t [m]
        >>> r = monte_carlo(examples.hitch_003(), [0.45, 0.6], tol, outputs=["p(ГЦ)"],
        ...                 samples=200, seed=1)
        >>> (np.round(r.worst_percentiles("p(ГЦ)") / 1e6, 3)).tolist()  # P1 … P99 [MPa]
        [15.407, 15.409, 15.431, 15.449, 15.451]
        """
        w = self.worst(output)
        if w.shape[0] == 0:
            raise ModelError("no drawn machine assembles: no distribution to report")
        return np.percentile(w, q)

    def std(self, output) -> np.ndarray:
        """Standard deviation over the assembled machines per position, (n,) [SI].

        Examples
        --------
        >>> from assur import examples
        >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
        >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # ±t [m]
        >>> r = monte_carlo(examples.hitch_003(), [0.45, 0.6], tol, outputs=["p(ГЦ)"],
        ...                 samples=200, seed=1)
        >>> (np.round(r.std("p(ГЦ)") / 1e3, 3)).tolist()  # σ of p at S = 0.45, 0.6 m [kPa]
        [8.633, 13.161]
        """
        v = self.values(output)
        if v.shape[0] < 2:
            raise ModelError(f"the spread σ over the machines needs two or more that "
                             f"assemble; {v.shape[0]} of {self.samples.shape[0]} did")
        return v.std(axis=0, ddof=1)

    def mean(self, output) -> np.ndarray:
        """Mean over the assembled machines per position, (n,) [SI].

        Examples
        --------
        Close to the nominal pressure (14.569, 15.429 MPa) of the seed-003 hitch:

        >>> from assur import examples
        >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
        >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # ±t [m]
        >>> r = monte_carlo(examples.hitch_003(), [0.45, 0.6], tol, outputs=["p(ГЦ)"],
        ...                 samples=200, seed=1)
        >>> (np.round(r.mean("p(ГЦ)") / 1e6, 4)).tolist()  # [MPa]
        [14.5695, 15.4306]
        """
        return self.values(output).mean(axis=0)

    def linear_std(self, output, sigma="tolerance") -> np.ndarray:
        """First-order σ per position [SI]: with the tolerances' σ, or with
        ``sigma="sample"`` the σ of the drawn deviations (then exact for a linear
        output).

        Examples
        --------
        Beside the Monte Carlo σ of the seed-003 hitch's pressure (8.633 and
        13.161 kPa): with the drawn deviations' σ the linear stack-up matches it,
        the pressure being nearly linear in such small deviations.

        >>> from assur import examples
        >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
        >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # ±t [m]
        >>> r = monte_carlo(examples.hitch_003(), [0.45, 0.6], tol, outputs=["p(ГЦ)"],
        ...                 samples=200, seed=1)
        >>> (np.round(r.linear_std("p(ГЦ)") / 1e3, 3)).tolist()  # [kPa]
        [8.799, 12.772]
        >>> (np.round(r.linear_std("p(ГЦ)", sigma="sample") / 1e3, 3)).tolist()  # [kPa]
        [8.633, 13.16]
        """
        g = self.gradient[:, self._o(output), :]
        if sigma == "sample":
            cov = np.cov(self.deviations[self.assembled].T, ddof=1).reshape(
                len(self.tolerances), len(self.tolerances))
            return np.sqrt(np.einsum("ni,ij,nj->n", g, cov, g))
        s = np.array([t.sigma for t in self.tolerances])
        return np.sqrt(((g * s) ** 2).sum(axis=-1))


def first_order(mech, q, tolerances, outputs):
    """The first-order stack-up: (σ per position and output, shape (n, outputs), and
    the gradient, shape (n, outputs, tolerances)) [SI], σ² = Σ (∂out/∂p_i·σ_i)².

    Examples
    --------
    The seed-003 hitch's cylinder pressure at S = 0.45 and 0.6 m, ±0.5 mm on X01
    (σ = 0.167 mm) and ±1 mm uniform on L4 (σ = 0.577 mm):

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.synthesis.tolerance import Tolerance, first_order
    >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]
    >>> sigma, grad = first_order(examples.hitch_003(), [0.45, 0.6], tol, ["p(ГЦ)"])
    >>> (np.round(sigma[:, 0] / 1e3, 3)).tolist()  # σ of p [kPa]
    [8.799, 12.772]
    >>> (np.round(grad[0, 0] / 1e6, 2)).tolist()  # ∂p/∂X01, ∂p/∂L4 at S = 0.45 m [kPa/mm]
    [17.39, -14.39]
    """
    from .sensitivity import sensitivities
    params = [t.param for t in tolerances]
    s = sensitivities(mech, q, params=params, outputs=outputs)
    sig = np.array([t.sigma for t in tolerances])
    return np.sqrt(((s.jacobian * sig) ** 2).sum(axis=-1)), s.jacobian


def _reasons(mech, q, values, failed):
    out = []
    for d in failed[:REASONS_MAX]:
        one = {k: float(v[d]) for k, v in values.items()}
        try:
            mech.solve(q, one)
        except AssemblyError as e:
            out.append((int(d), str(getattr(e, "group", "") or ""), str(e)))
        else:  # assembles at the positions but a pose of the model does not
            out.append((int(d), "", "fails only in the fused evaluation"))
    return tuple(out)


def monte_carlo(mech, q, tolerances, outputs=None, samples=1000, seed=None, g=None):
    """Monte Carlo over manufacturing tolerances, as one batch of designs.

    Parameters
    ----------
    mech : Mechanism or assur.io.Model
        The nominal machine (a model gives its mechanism and, without ``q``, range).
    q : array_like, shape (n,), or None
        Positions [m or rad] (one coordinate).
    tolerances : sequence of Tolerance
    outputs : sequence of str, optional
        :mod:`assur.core.outputs` outputs (default: :func:`default_outputs`).
    samples : int
        Number of machines drawn N.
    seed : int, optional
        Seed of the :class:`numpy.random.Generator` (same seed, same machines).
    g : float, optional
        Gravity [m/s²].

    Returns
    -------
    ToleranceResult

    Raises
    ------
    ModelError
        Unknown parameters or outputs, a parameter toleranced twice, samples < 2.
    AssemblyError
        The nominal machine does not assemble.

    Examples
    --------
    1000 seed-003 hitches built with ±0.5 mm on the frame pivot X01 and ±1 mm
    uniform on the brace L4: the cylinder pressure's spread at S = 0.45 and 0.6 m.

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.synthesis.tolerance import Tolerance, monte_carlo
    >>> tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]  # [m]
    >>> r = monte_carlo(examples.hitch_003(), [0.45, 0.6], tol, outputs=["p(ГЦ)"],
    ...                 samples=1000, seed=1)
    >>> r.failure_share, r.values("p(ГЦ)").shape  # [-], (machines, positions)
    (0.0, (1000, 2))
    >>> p5, p50, p95 = r.percentiles("p(ГЦ)", q=(5, 50, 95))[1] / 1e6  # at S = 0.6 m
    >>> round(float(p95 - p5), 3)  # [MPa]
    0.04
    >>> monte_carlo(examples.hitch_003(), [0.45], [Tolerance("Lx", 1e-3)])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: monte_carlo: ['Lx'] are not parameters of hitch_003; parameters: [...]
    """
    model = mech
    mech = getattr(model, "mechanism", model)
    if q is None:
        q = getattr(model, "range", None)
        if q is None:
            raise ModelError("monte_carlo: give the positions q")
    q = np.asarray(q, dtype=float)
    if len(mech.coordinates) != 1 or q.ndim != 1:
        raise ModelError("monte_carlo: one generalized coordinate, positions of shape (n,)")
    tolerances = tuple(tolerances)
    if not tolerances:
        raise ModelError("monte_carlo: no tolerances")
    names = [t.param for t in tolerances]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise ModelError(f"monte_carlo: {dup} toleranced twice")
    bad = [n for n in names if n not in mech.params]
    if bad:
        raise ModelError(f"monte_carlo: {bad} are not parameters of {mech.name}; parameters: "
                         f"{list(mech.params)}")
    samples = int(samples)
    if samples < 2:
        raise ModelError(f"monte_carlo: samples must be at least 2, got {samples}")
    outputs = tuple(default_outputs(mech) if outputs is None else outputs)
    # every machine's values at every position are held (the kernel's coordinates and
    # outputs, then their stack and the masked copy) besides its deviations
    n, no = q.size, len(outputs)
    check_memory(samples, 8 * n * (len(mech.coordinates) + 2 + 4 * no) + 24 * len(tolerances)
                 + 64, f"monte_carlo: samples = {samples} over {n} positions",
                 unit="machines", reduce="the samples (--samples)")
    nominal = mech.evaluate(q, outputs=outputs, g=g)  # raises if the nominal fails
    rng = np.random.default_rng(seed)
    dev = np.stack([t.draw(rng, samples) for t in tolerances], axis=-1)
    values = {t.param: float(mech.params[t.param]) + dev[:, i]
              for i, t in enumerate(tolerances)}
    res = mech.evaluate(q, values, outputs=outputs, on_failure="report", g=g)
    ok = np.asarray(res.failures).reshape(samples) == 0
    vals = np.stack([np.asarray(res[o]).reshape(samples, len(q)) for o in outputs], axis=-1)
    vals = np.where(ok[:, None, None], vals, 0.0)
    reasons = _reasons(mech, q, values, np.flatnonzero(~ok))
    lin, grad = first_order(mech, q, tolerances, outputs)
    return ToleranceResult(outputs, tolerances, q,
                           np.stack([np.asarray(nominal[o]) for o in outputs], -1), vals,
                           dev, ok, reasons, dict(nominal.units), seed, lin, grad)
