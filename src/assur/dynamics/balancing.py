"""The common centre of mass of the moving links over a crank turn and its
balancing by counter-masses.

Seed 001 lab 3: "static balancing is achieved only when the centre of mass stays
still or moves uniformly in a straight line … the centre of mass of the cleaning
mechanism describes a curved path over a cycle (one turn of the driving link), so
one seeks a partial balancing: a smaller area of the figure the centre of mass
describes (fig. 3.3)"; "the largest amplitudes of the oscillation of the common
centre of mass over a crank turn were A_x = 3.97 mm, A_y = 3.85 mm".

Definitions (positions φ over one turn; M = Σ m_i of the moving links)::

    r_c(φ) = Σ m_i·r_Si(φ) / M                                   [m]
    A_x    = (max x_c − min x_c)/2,   A_y = (max y_c − min y_c)/2  [m]
    area   = ½·Σ (x_k·y_{k+1} − x_{k+1}·y_k)   (closed path, signed) [m²]

A_x, A_y are the half-swings (the amplitudes of the oscillation about the middle
of its range; the lab prints them without a formula). The area is positive when
the path runs counter-clockwise as the positions are listed.

Counter-masses. A counter-mass μ on link L at ``(a, b)`` in the link's frame (``a``
along its first→second point P→Q, ``b`` to the left) is at ``P + a·u + b·n``; the
numerator of r_c gains ``μ·P + (μa)·u + (μb)·n`` — linear in ``w = (μ, μa, μb)``
— and M gains μ. The objective of a whole population of candidate balancings is
then one matrix product (:func:`balance` uses scipy's differential evolution with
``vectorized=True``, polished by L-BFGS-B).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..core.loads import centre_of_mass, masses_of
from ..errors import ModelError
from .masses import LinkMass, design_value

__all__ = ["CentreOfMassPath", "common_centre", "CounterMass", "Balancing",
           "balance", "OBJECTIVES"]


@dataclass(frozen=True)
class CentreOfMassPath:
    """The common centre of mass over the positions.

    Attributes
    ----------
    x, y : ndarray, shape (..., n)
        r_c [m].
    mass : ndarray
        Total moving mass M [kg] (per design).
    amplitude_x, amplitude_y : ndarray
        A_x, A_y: half the swing of x_c and y_c [m].
    area : ndarray
        Signed area enclosed by the closed path [m²] (counter-clockwise positive).

    Examples
    --------
    A unit square run counter-clockwise by 2 kg:

    >>> from assur.dynamics.balancing import CentreOfMassPath
    >>> c = CentreOfMassPath(np.array([0.0, 1.0, 1.0, 0.0]), np.array([0.0, 0.0, 1.0, 1.0]), 2.0)
    >>> float(c.amplitude_x), float(c.amplitude_y), float(c.area)  # [m], [m], [m²]
    (0.5, 0.5, 1.0)
    """

    x: np.ndarray = field(repr=False)
    y: np.ndarray = field(repr=False)
    mass: np.ndarray
    amplitude_x: np.ndarray = field(init=False)
    amplitude_y: np.ndarray = field(init=False)
    area: np.ndarray = field(init=False)

    def __post_init__(self):
        object.__setattr__(self, "amplitude_x", amplitudes(self.x))
        object.__setattr__(self, "amplitude_y", amplitudes(self.y))
        object.__setattr__(self, "area", shoelace(self.x, self.y))


def amplitudes(x):
    """Half the swing (max − min)/2 over the last axis."""
    return 0.5 * (np.max(x, axis=-1) - np.min(x, axis=-1))


def shoelace(x, y):
    """Signed area of the closed polygon through (x, y) over the last axis [m²]."""
    return 0.5 * np.sum(x * np.roll(y, -1, axis=-1) - np.roll(x, -1, axis=-1) * y, axis=-1)


def _centre(kin):
    """The common centre of mass (x, y) (m, n) [m] and the total mass (m, 1) [kg] of
    the moving masses (:func:`assur.core.loads.centre_of_mass`, the formula of the
    outputs ``Xc``, ``Yc`` too)."""
    masses = masses_of(kin.mechanism)
    if not masses:
        raise ModelError(f"mechanism {kin.mechanism.name!r} has no masses on moving links")
    return centre_of_mass(masses, lambda ref: design_value(kin, ref), kin.value)


def common_centre(kin):
    """The common centre of mass of the moving links' masses (:class:`CentreOfMassPath`)
    over the positions of ``kin`` (one turn of the crank for A_x, A_y, the area).

    Examples
    --------
    The bundled grain-cleaning mechanism (``cleaning_lab3.toml``; the lab prints
    A_x = 3.97 mm, A_y = 3.85 mm for its own machine):

    >>> from assur import io
    >>> model = io.load(io.bundled("cleaning_lab3"))  # lab 3 structure, illustrative sizes
    >>> kin = model.mechanism.solve(model.range)  # one crank turn, 1° steps
    >>> from assur.dynamics.balancing import common_centre
    >>> c = common_centre(kin)
    >>> float(c.mass)  # M [kg]
    270.5
    >>> round(float(c.amplitude_x) * 1e3, 2), round(float(c.amplitude_y) * 1e3, 2)  # A_x, A_y [mm]
    (3.95, 3.74)
    >>> round(float(c.area) * 1e6, 2)  # enclosed area [mm²]
    3.71
    """
    x, y, tot = _centre(kin)
    o = kin.reshape
    return CentreOfMassPath(o(np.broadcast_to(x, (kin.m, kin.n))),
                            o(np.broadcast_to(y, (kin.m, kin.n))),
                            tot[:, 0] if kin.m > 1 or len(kin.shape) == 2 else tot[0, 0])


@dataclass(frozen=True)
class CounterMass:
    """A counter-mass to place on ``link``: its mass and its position in the link's
    frame (``along`` the first→second point, ``offset`` to the left), each within
    (low, high) bounds [kg], [m], [m]. Equal bounds fix a value.

    Examples
    --------
    5 kg fixed 100 mm behind the crank's pivot of the bundled grain-cleaning
    mechanism: nothing left to optimise, :func:`balance` only evaluates it.

    >>> from assur import io
    >>> model = io.load(io.bundled("cleaning_lab3"))  # lab 3 structure, illustrative sizes
    >>> kin = model.mechanism.solve(model.range)  # one crank turn, 1° steps
    >>> from assur.dynamics.balancing import CounterMass, balance
    >>> cm = CounterMass("1", mass=(5.0, 5.0), along=(-0.1, -0.1))
    >>> b = balance(kin, [cm])
    >>> b.message
    'every variable is fixed by its bounds'
    >>> b.after.mass, round(float(b.after.amplitude_x) * 1e3, 2)  # M [kg], A_x [mm]
    (275.5, 2.2)
    """

    link: str
    mass: tuple[float, float]
    along: tuple[float, float] = (0.0, 0.0)
    offset: tuple[float, float] = (0.0, 0.0)


#: objectives of :func:`balance`: the sum of the amplitudes A_x + A_y, the larger of
#: the two, or the absolute enclosed area
OBJECTIVES = ("amplitudes", "max_amplitude", "area")


@dataclass(frozen=True)
class Balancing:
    """Result of :func:`balance`.

    Attributes
    ----------
    before, after : CentreOfMassPath
        The common centre of mass without and with the counter-masses.
    masses : tuple of LinkMass
        The counter-masses found (point masses, J = 0; those of zero mass left
        out); add them to the mechanism with :func:`assur.dynamics.crank.with_masses`
        (their points are named ``"C<link>"``).
    objective : str
    value : float
        The objective at the optimum [m or m²].
    success : bool
    message : str
        The optimizer's message.

    Examples
    --------
    The counter-mass found on the rocker 3 of the bundled grain-cleaning mechanism,
    put on the mechanism: its centre of mass follows the path predicted.

    >>> from assur import io
    >>> model = io.load(io.bundled("cleaning_lab3"))  # lab 3 structure, illustrative sizes
    >>> kin = model.mechanism.solve(model.range)  # one crank turn, 1° steps
    >>> from assur.dynamics.balancing import CounterMass, balance, common_centre
    >>> from assur.dynamics.crank import with_masses
    >>> b = balance(kin, [CounterMass("3", (0.0, 30.0), (-0.3, 0.3))])
    >>> [(m.name, round(m.m, 1), round(m.along, 3)) for m in b.masses]  # [kg], [m]
    [('C3', 30.0, -0.169)]
    >>> c = common_centre(with_masses(model.mechanism, b.masses).solve(model.range))
    >>> round(float(c.amplitude_x) * 1e3, 2), round(float(b.after.amplitude_x) * 1e3, 2)  # [mm]
    (0.2, 0.2)
    """

    before: CentreOfMassPath
    after: CentreOfMassPath
    masses: tuple
    objective: str
    value: float
    success: bool
    message: str


def _frame_basis(kin, link):
    """P, u, n of a link over the positions: arrays (2, n) of one design."""
    topo = kin.mechanism.topology
    if link not in topo.bodies or link == "0":
        raise ModelError(f"counter-mass on unknown or fixed link {link!r} (moving links: "
                         f"{sorted(b for b in topo.bodies if b != '0')})")
    pts = topo.bodies[link]
    if len(pts) < 2:
        raise ModelError(f"counter-mass on link {link!r}, which has the single point "
                         f"{pts[0]!r}: choose a link with two joints")
    P, Q = kin.value(pts[0])[:, 0], kin.value(pts[1])[:, 0]
    d = Q - P
    u = d / np.hypot(d[0], d[1])
    n = np.stack([-u[1], u[0]])
    return P, u, n


def balance(kin, counter_masses, objective="amplitudes", seed=0, maxiter=1000, popsize=15,
            tol=1e-10):
    """Counter-masses that minimise the amplitudes (or the area) of the common
    centre of mass over the positions of ``kin`` (one turn), within bounds.

    Parameters
    ----------
    kin : Kinematics
        One design solved over a crank turn, with its masses (``mass`` loads).
    counter_masses : sequence of CounterMass
        Where counter-masses may go and their bounds.
    objective : {"amplitudes", "max_amplitude", "area"}
        A_x + A_y [m], max(A_x, A_y) [m], or |area| [m²].
    seed : int
        Seed of the differential evolution (the result is reproducible).
    maxiter, popsize, tol
        Of :func:`scipy.optimize.differential_evolution`.

    Returns
    -------
    Balancing

    Notes
    -----
    Variables (μ, a, b) per counter-mass; the centre of mass of the balanced
    mechanism is ``(N0 + Σ μ·P + μa·u + μb·n)/(M + Σ μ)``, evaluated for a whole
    population at once. The objectives are piecewise smooth (max/min over the
    positions), hence a global, derivative-free search.

    Examples
    --------
    Up to 30 kg within ±0.3 m along the rocker 3 of the bundled grain-cleaning
    mechanism: A_x drops from 3.95 to 0.20 mm, A_y from 3.74 to 3.27 mm.

    >>> from assur import io
    >>> model = io.load(io.bundled("cleaning_lab3"))  # lab 3 structure, illustrative sizes
    >>> kin = model.mechanism.solve(model.range)  # one crank turn, 1° steps
    >>> from assur.dynamics.balancing import CounterMass, balance
    >>> b = balance(kin, [CounterMass("3", mass=(0.0, 30.0), along=(-0.3, 0.3))])
    >>> b.success, round(b.value * 1e3, 2)  # A_x + A_y [mm]
    (True, 3.48)
    >>> [round(float(c.amplitude_y) * 1e3, 2) for c in (b.before, b.after)]  # A_y [mm]
    [3.74, 3.27]
    >>> balance(kin, [CounterMass("3", (0.0, 30.0))], objective="volume")
    Traceback (most recent call last):
    ...
    ValueError: objective must be one of: ['amplitudes', 'max_amplitude', 'area']
    """
    from scipy.optimize import differential_evolution

    if objective not in OBJECTIVES:
        raise ValueError(f"objective must be one of: {list(OBJECTIVES)}")
    if kin.k != 1 or kin.m != 1:
        raise ValueError("balance: one design of a one-coordinate mechanism")
    cms = list(counter_masses)
    if not cms:
        raise ValueError("balance: give at least one CounterMass")
    x0, y0, tot = _centre(kin)
    M0 = float(tot[0, 0])  # kg
    N0 = np.stack([np.broadcast_to(x0, (1, kin.n))[0], np.broadcast_to(y0, (1, kin.n))[0]]) * M0
    bases = [_frame_basis(kin, c.link) for c in cms]
    bounds = []
    for c in cms:
        for what, b in (("mass", c.mass), ("along", c.along), ("offset", c.offset)):
            lo, hi = (float(v) for v in b)
            if not (np.isfinite(lo) and np.isfinite(hi) and lo <= hi):
                raise ValueError(f"counter-mass on link {c.link!r}: {what} bounds {b!r} must be "
                                 f"finite with low ≤ high")
            if what == "mass" and lo < 0:
                raise ValueError(f"counter-mass on link {c.link!r}: mass bounds {b!r} must be ≥ 0")
            bounds.append((lo, hi))
    # (3C, 2, n): the centre's numerator per unit of μ, μa, μb
    B = np.concatenate([np.stack([P, u, n]) for P, u, n in bases])

    def path(z):
        """z (3C, S) → x, y (S, n) and the total mass (S,)."""
        z = z.reshape(len(cms), 3, -1)
        mu, a, b = z[:, 0], z[:, 1], z[:, 2]  # (C, S)
        w = np.stack([mu, mu * a, mu * b], 1).reshape(3 * len(cms), -1)  # (3C, S)
        numer = (w.T @ B.reshape(len(B), -1)).reshape(-1, 2, kin.n)  # (S, 2, n), one BLAS product
        Mt = M0 + mu.sum(0)
        return ((N0[0] + numer[:, 0]) / Mt[:, None], (N0[1] + numer[:, 1]) / Mt[:, None],
                Mt)

    def cost(z):
        x, y, _ = path(z)
        if objective == "area":
            return np.abs(shoelace(x, y))
        ax, ay = amplitudes(x), amplitudes(y)
        return ax + ay if objective == "amplitudes" else np.maximum(ax, ay)

    lo = np.array([b[0] for b in bounds])
    hi = np.array([b[1] for b in bounds])
    free = lo < hi
    if not free.any():
        z = lo
        res_success, res_msg = True, "every variable is fixed by its bounds"
    else:
        def cost_free(zf):
            zf = np.asarray(zf, float)
            z = np.repeat(lo[:, None], zf.shape[1] if zf.ndim == 2 else 1, axis=1)
            z[free] = zf if zf.ndim == 2 else zf[:, None]
            c = cost(z)
            return c if zf.ndim == 2 else float(c[0])

        res = differential_evolution(cost_free, list(zip(lo[free], hi[free])), seed=seed,
                                     vectorized=True, updating="deferred", maxiter=maxiter,
                                     popsize=popsize, tol=tol, polish=True)
        z = lo.copy()
        z[free] = res.x
        res_success, res_msg = bool(res.success), str(res.message)
    x, y, Mt = path(z[:, None])
    after = CentreOfMassPath(x[0], y[0], float(Mt[0]))
    before = CentreOfMassPath(N0[0] / M0, N0[1] / M0, M0)
    zz = z.reshape(len(cms), 3)
    found = tuple(LinkMass(c.link, float(mu), along=float(a), offset=float(b),
                           name=f"C{c.link}" if sum(d.link == c.link for d in cms) == 1
                           else f"C{c.link}_{i}")
                  for i, (c, (mu, a, b)) in enumerate(zip(cms, zz)) if mu > 0)
    return Balancing(before, after, found, objective, float(cost(z[:, None])[0]), res_success,
                     res_msg)
