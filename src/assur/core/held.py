"""Held outputs along a path: coordinates defined by a condition at every position.

A mechanism of k coordinates moves along a *path* when one coordinate ``s`` (the
path's parameter, e.g. the boom cylinder S of seed 001 lab 1) is given and the
other k − 1 are *held*: each is solved at every position so that an output keeps a
target value, ``h_i(q) = y_i(q) − target_i = 0`` (a self-levelling lift: the traverse
cylinder S1 such that the traverse's angle stays fixed while S lifts the boom).

Solving
-------
One held coordinate ``u`` with its limits ``within = [low, high]`` (the cylinder's
stroke) is found at every position at once: the residual is sampled on ``scan``
values of ``u`` in the limits (one batched solve of n·scan positions), the one
sign change is bracketed (an angle's jump through ±π is not a root; none, or more
than one, is an error naming the position), and a safeguarded Newton step on the
exact analog ``∂h/∂u`` (bisection where the step leaves the bracket) runs on all
positions together until ``|h| ≤ tol`` (1e-12 m or rad). Several held coordinates
are solved by Newton's method on the exact Jacobian ``∂h/∂u`` from the middle of
their limits.

Analogs along the path (the implicit-function rule)
---------------------------------------------------
With ``q(s) = (s, u(s))`` and ``h(q(s)) = 0`` at every s:

.. math::  h_u\\,u' = -h_s, \\qquad h_u\\,u'' = -\\,q'^T h_{qq}\\,q'

(for one held coordinate ``u' = −h_s/h_u`` and
``u'' = −(h_ss + 2 h_su u' + h_uu u'²)/h_u``), and every output y of the
mechanism has the path derivatives

.. math::  \\frac{dy}{ds} = y_q\\,q', \\qquad
           \\frac{d^2y}{ds^2} = q'^T y_{qq}\\,q' + y_q\\,q''

— :meth:`HeldPath.along`, the one place where the path is composed with the
mechanism's analogs (k-coordinate partials ∂/∂q, DESIGN.md §2). Transmission
numbers along the path (``dY/dS`` with S1 following), the coordinate rates of a
rod moving along it (``q̇ = q'·ṡ``, ``q̈ = q'·s̈ + q''·ṡ²``: the inertia loads of
the statics) come from it. The statics' cylinder forces and capacities are those
of the k-coordinate mechanism at each position of the path (a force balance does
not depend on the path by which the position was reached).

The file's form is ``[range] S1 = { hold = "phi9", equals = "-30 deg", within =
["S1min", "S1max"] }`` (docs/model-format.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import AssemblyError, ModelError
from .quantities import Unit

__all__ = ["Hold", "HeldPath", "hold_path", "quantity_jets", "output_kind"]

_DEG = Unit("deg", math.pi / 180.0)
_M = Unit("m", 1.0)


def output_kind(mech, name, *, what="output", declared=False):
    """``("x"|"y"|"phi"|"dist", object)`` of an output named as ``[[solve]]``
    conditions, ``[design]`` constraints and held coordinates name them:
    ``X<point>``, ``Y<point>`` [m], ``phi<link>`` [rad] or a distance's name [m]; with
    ``declared``, the angles of the declared links only (a design condition's
    quantity), else of the bodies too.

    Raises
    ------
    ModelError
        ``"unknown <what> '<name>': use …"`` with the names the model has.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.held import output_kind
    >>> m = examples.hitch_003()
    >>> output_kind(m, "Y56"), output_kind(m, "phi3")
    (('y', '56'), ('phi', '3'))
    >>> output_kind(m, "Y99", what="quantity", declared=True)   # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: unknown quantity 'Y99': use X<point>/Y<point> (points [...
    """
    links = {l.name for l in mech.links} | (set() if declared else set(mech.bodies))
    dists = {d.name for d in mech.distances}
    points = set(mech.points) | set(mech.frame_points)
    if name.startswith("phi") and name[3:] in links:
        return "phi", name[3:]
    if name[:1] in "XY" and name[1:] in points:
        return name[0].lower(), name[1:]
    if name in dists:
        return "dist", name
    raise ModelError(f"unknown {what} {name!r}: use X<point>/Y<point> (points "
                     f"{sorted(points)}), phi<link> (links {sorted(links)}) or a distance "
                     f"{sorted(dists)}")


def _kind(mech, name):
    return output_kind(mech, name)


def quantity_jets(kin, name):
    """An output of a solved mechanism by name, with its exact analogs over all k
    coordinates.

    Parameters
    ----------
    kin : Kinematics
        A solve of one design over positions of shape (n, k) (k ≥ 2).
    name : str
        ``X<point>``, ``Y<point>`` [m], ``phi<link>`` [rad] or a distance name [m] —
        the names of ``[[solve]]`` conditions and ``[design]`` constraints.

    Returns
    -------
    value : ndarray, shape (n,)
    d1 : ndarray, shape (n, k)
        ∂y/∂q [m/m, rad/m, …].
    d2 : ndarray, shape (n, k, k)
        ∂²y/∂q∂q.

    Examples
    --------
    >>> from assur import io
    >>> from assur.core.held import quantity_jets
    >>> kin = io.load(io.bundled("loader_lab1")).mechanism.solve([[1.2, 0.85]])  # S, S1 [m]
    >>> v, d1, d2 = quantity_jets(kin, "phi9")
    >>> v.shape, d1.shape, d2.shape
    ((1,), (1, 2), (1, 2, 2))
    """
    kind, obj = _kind(kin.mechanism, name)
    if kind == "phi":
        return kin.phi(obj), kin.dphi(obj), kin.ddphi(obj)
    if kind == "dist":
        return kin.length(obj), kin.dlength(obj), kin.ddlength(obj)
    if kind == "x":
        return kin.x(obj), kin.dx(obj), kin.ddx(obj)
    return kin.y(obj), kin.dy(obj), kin.ddy(obj)


@dataclass(frozen=True)
class Hold:
    """A held coordinate: ``coordinate`` solved at every position of a path so that
    the output ``quantity`` equals ``target``.

    Attributes
    ----------
    coordinate : str
        The held generalized coordinate (e.g. the traverse cylinder ``"S1"``).
    quantity : str
        The output held: ``X<point>``, ``Y<point>``, ``phi<link>`` or a distance.
    target : float
        Its value [m or rad]; angles are compared modulo 2π.
    within : (float, float)
        The coordinate's limits [m or rad] (a cylinder's stroke): the one value in
        them that reaches the target is taken.
    unit, coordinate_unit : Unit, optional
        Units the messages show the quantity and the coordinate in (default: degrees
        for an angle, metres for a length; the coordinate as SI).
    source : str, optional
        Where it was written (``"file.toml:42"``), for messages.

    Examples
    --------
    >>> import math
    >>> from assur.core.held import Hold
    >>> h = Hold("S1", "phi9", math.radians(-30), (0.75, 0.98))   # [rad], [m]
    >>> h.describe()
    'S1 holds phi9 = -30 deg'
    """

    coordinate: str
    quantity: str
    target: float
    within: tuple
    unit: object = None
    coordinate_unit: object = None
    source: str | None = None

    def shown(self, value, of="quantity", digits=6) -> str:
        """``value`` [SI] in the unit messages use (``of="coordinate"``: the held
        coordinate's).

        Examples
        --------
        >>> import math
        >>> from assur.core.held import Hold
        >>> Hold("S1", "phi9", 0.0, (0.75, 0.98)).shown(math.pi / 2)   # [rad] → deg
        '90 deg'
        """
        if of == "quantity":
            u = self.unit or (_DEG if self.quantity.startswith("phi") else _M)
        else:
            u = self.coordinate_unit
        if u is None:
            return f"{value:.{digits}g}"
        return f"{float(u.of(value)):.{digits}g} {u.text}"

    def describe(self) -> str:
        """``"S1 holds phi9 = -30 deg (file.toml:42)"``.

        Examples
        --------
        >>> from assur.core.held import Hold
        >>> Hold("S1", "Y09", 1.5, (0.75, 0.98), source="x.toml:3").describe()   # [m]
        'S1 holds Y09 = 1.5 m (x.toml:3)'
        """
        src = f" ({self.source})" if self.source else ""
        return f"{self.coordinate} holds {self.quantity} = {self.shown(self.target)}{src}"


@dataclass(frozen=True)
class HeldPath:
    """A path through the coordinates: ``along`` given, the others held.

    Attributes
    ----------
    coordinates : tuple of str
        The mechanism's coordinates (the order of the trailing axes).
    along : str
        The path's parameter s (a coordinate given by ``[range]``).
    holds : tuple of Hold
    q : ndarray, shape (n, k)
        The positions [m or rad], read-only.
    dq, ddq : ndarray, shape (n, k)
        dq/ds and d²q/ds² (1 and 0 in the column of ``along``), read-only.
    residual : float
        The largest ``|h|`` left at the solution [m or rad].

    Examples
    --------
    >>> from assur import io
    >>> path = io.load(io.bundled("loader_lab1_level")).path
    >>> path.along, [h.quantity for h in path.holds], path.q.shape
    ('S', ['phi9'], (11, 2))
    >>> path.residual < 1e-12
    True
    """

    coordinates: tuple
    along: str
    holds: tuple
    q: np.ndarray = field(repr=False)
    dq: np.ndarray = field(repr=False)
    ddq: np.ndarray = field(repr=False)
    residual: float = 0.0

    @property
    def s(self) -> np.ndarray:
        """The path's parameter at each position [m or rad], shape (n,).

        Examples
        --------
        >>> from assur import io
        >>> path = io.load(io.bundled("loader_lab1_level")).path
        >>> round(float(path.s[0]), 4), round(float(path.s[-1]), 4)    # S [m]
        (1.0011, 1.25)
        """
        return self.q[:, self.coordinates.index(self.along)]

    def part(self, i0, i1):
        """The same path restricted to positions i0:i1 (views).

        Examples
        --------
        >>> from assur import io
        >>> path = io.load(io.bundled("loader_lab1_level")).path
        >>> path.part(2, 5).q.shape, bool((path.part(2, 5).dq == path.dq[2:5]).all())
        ((3, 2), True)
        """
        import dataclasses
        sl = slice(i0, i1)
        return dataclasses.replace(self, q=self.q[sl], dq=self.dq[sl], ddq=self.ddq[sl])

    def along_path(self, d1, d2):
        """The derivatives along the path of an output whose partial analogs are
        ``d1`` = ∂y/∂q, shape (n, k), and ``d2`` = ∂²y/∂q∂q, shape (n, k, k):
        ``dy/ds = y_q·q'`` and ``d²y/ds² = q'ᵀ·y_qq·q' + y_q·q''``.

        Returns
        -------
        (ndarray, ndarray), each shape (n,)

        Examples
        --------
        The held output itself stands still along the path:

        >>> from assur import io
        >>> from assur.core.held import quantity_jets
        >>> model = io.load(io.bundled("loader_lab1_level"))
        >>> kin = model.mechanism.solve(model.range)
        >>> _, d1, d2 = quantity_jets(kin, "phi9")
        >>> a, b = model.path.along_path(d1, d2)
        >>> bool(abs(a).max() < 1e-12), bool(abs(b).max() < 1e-10)
        (True, True)
        """
        d1, d2 = np.asarray(d1), np.asarray(d2)
        first = np.einsum("...j,...j->...", d1, self.dq)
        second = (np.einsum("...i,...ij,...j->...", self.dq, d2, self.dq)
                  + np.einsum("...j,...j->...", d1, self.ddq))
        return first, second

    def derivative(self, kin, quantity):
        """An output by name (``X09``, ``Y09``, ``phi3``, a distance) and its first
        and second derivatives along the path, each shape (n,).

        Examples
        --------
        >>> from assur import io
        >>> model = io.load(io.bundled("loader_lab1_level"))
        >>> kin = model.mechanism.solve(model.range)
        >>> y, dy, ddy = model.path.derivative(kin, "YS9")   # [m], [m/m], [1/m]
        >>> dy.shape
        (11,)
        """
        v, d1, d2 = quantity_jets(kin, quantity)
        return (v,) + self.along_path(d1, d2)

    def transmission(self, kin, point, axis="y"):
        """The transmission number along the path, ``I = dY/ds`` of a point (``axis
        ="x"``: dX/ds) [m/m], shape (n,): the one that gives the work of a load on
        the point per unit of the path's parameter, with the held coordinates
        following.

        Examples
        --------
        >>> from assur import io
        >>> model = io.load(io.bundled("loader_lab1_level"))
        >>> kin = model.mechanism.solve(model.range)
        >>> I = model.path.transmission(kin, "S9")             # dY_S9/dS, S1 held [m/m]
        >>> bool((I > 0).all())                                # the tool rises with S
        True
        """
        return self.derivative(kin, f"{axis.upper()}{point}")[1]

    def rates(self, sdot, sddot):
        """The coordinate rates ``q̇ = q'·ṡ`` and ``q̈ = q'·s̈ + q''·ṡ²`` [m/s, m/s²
        or rad/s, rad/s²], each shape (n, k), of a motion along the path at ``ṡ``,
        ``s̈`` (scalars or shape (n,)).

        Examples
        --------
        >>> from assur import io
        >>> path = io.load(io.bundled("loader_lab1_level")).path
        >>> qdot, qddot = path.rates(0.05, 0.0)              # Ṡ [m/s], S̈ [m/s²]
        >>> qdot.shape, bool((qdot[:, 0] == 0.05).all())
        ((11, 2), True)
        """
        sd = np.asarray(sdot, float)[..., None]
        sdd = np.asarray(sddot, float)[..., None]
        return self.dq * sd, self.dq * sdd + self.ddq * sd ** 2

    def motion_rates(self, mech):
        """The coordinate rates of the rod's (or crank's) motion of the path's
        parameter (``[motion]``, :meth:`assur.Mechanism.with_motion`) along the path:
        ``(q̇, q̈, note)`` with q̇, q̈ of shape (n, k) (:meth:`rates`) and a
        :class:`assur.texts.Text` saying so; None without such a motion.

        Raises
        ------
        ModelError
            A held coordinate with a motion of its own (it follows the path).

        Examples
        --------
        >>> from assur import io
        >>> model = io.load(io.bundled("loader_lab1_level"))
        >>> mech = model.mechanism.with_motion("S", "extend", speed=0.05)   # [m/s]
        >>> qdot, qddot, note = model.path.motion_rates(mech)
        >>> [round(float(v), 4) for v in qdot[0]]                  # Ṡ, Ṡ1 [m/s]
        [0.05, -0.0162]
        >>> print(model.path.motion_rates(model.mechanism))        # no motion given
        None
        """
        from ..texts import Text
        for h in self.holds:
            mo = mech.motion(h.coordinate)
            if mo is not None and mo.has_speed:
                raise ModelError(f"{h.describe()}: {h.coordinate} follows the path along "
                                 f"{self.along}; give the motion of {self.along}, not of "
                                 f"{h.coordinate}")
        mo = mech.motion(self.along)
        if mo is None or not mo.has_speed:
            return None
        sdot, sddot = mo.rates(self.s)
        qdot, qddot = self.rates(sdot, sddot)
        held = ", ".join(h.coordinate for h in self.holds)
        note = Text(f"{mech.name}: inertia loads at the motion of {self.along} of [motion], "
                    f"{held} following the held path",
                    ru=f"{mech.name}: силы инерции при движении {self.along} по [motion], "
                       f"{held} следует удерживаемой траектории")
        return qdot, qddot, note

    def describe(self) -> str:
        """One line: the parameter and what is held.

        Examples
        --------
        >>> from assur import io
        >>> io.load(io.bundled("loader_lab1_level")).path.describe()
        'path along S, 11 positions: S1 holds phi9 = 75 deg'
        """
        holds = "; ".join(h.describe().split(" (")[0] for h in self.holds)
        return f"path along {self.along}, {len(self.q)} positions: {holds}"


def _wrap(r):
    return np.angle(np.exp(1j * r))


def _residuals(kin, holds, with_jets=False):
    """h (n, h) and, with jets, ∂h/∂q (n, h, k) and ∂²h/∂q∂q (n, h, k, k)."""
    vals, d1s, d2s = [], [], []
    for hd in holds:
        v, d1, d2 = quantity_jets(kin, hd.quantity)
        r = v - hd.target
        vals.append(_wrap(r) if _kind(kin.mechanism, hd.quantity)[0] == "phi" else r)
        d1s.append(d1)
        d2s.append(d2)
    h = np.stack(vals, axis=-1)
    if not with_jets:
        return h
    return h, np.stack(d1s, axis=1), np.stack(d2s, axis=1)


def hold_path(mech, along, values, holds, params=None, *, tol=1e-12, scan=41,
              along_unit=None, max_iter=60):
    """Solve the held coordinates at every value of the path's parameter and the
    path's derivatives (the implicit-function rule).

    Parameters
    ----------
    mech : Mechanism
        A mechanism of k ≥ 2 coordinates.
    along : str
        The coordinate given (the path's parameter s).
    values : array_like, shape (n,)
        Its values [m or rad].
    holds : sequence of Hold
        One per other coordinate (k − 1 of them).
    params : mapping, optional
        Parameter overrides (one design).
    tol : float
        The largest residual |h| accepted [m or rad].
    scan : int
        Samples of the limits of a single held coordinate.
    along_unit : Unit, optional
        The unit messages show s in.

    Returns
    -------
    HeldPath

    Raises
    ------
    ModelError
        No value (or several) of a held coordinate within its limits reaches the
        target at some position; the message names the position, the held output
        and its target.
    AssemblyError
        The mechanism assembles nowhere in the limits at some position (the group
        is named).

    Examples
    --------
    The mini-loader of seed 001 lab 1: the traverse cylinder S1 keeps the traverse 9
    at 75° while the boom cylinder S extends from 1.0 to 1.25 m:

    >>> import math
    >>> import numpy as np
    >>> from assur import io
    >>> from assur.core.held import Hold, hold_path
    >>> mech = io.load(io.bundled("loader_lab1")).mechanism
    >>> h = Hold("S1", "phi9", math.radians(75), (0.77, 0.98))      # [rad], [m]
    >>> path = hold_path(mech, "S", np.linspace(1.0, 1.25, 4), [h])  # S [m]
    >>> phi9 = mech.solve(path.q).phi("9")
    >>> bool(np.abs(phi9 - math.radians(75)).max() < 1e-12)
    True
    >>> [round(float(v), 4) for v in path.q[:, 1]]                  # S1 [m]
    [0.9436, 0.9128, 0.8718, 0.8104]
    """
    coords = tuple(mech.coordinates)
    holds = tuple(holds)
    if along not in coords:
        raise ModelError(f"{mech.name}: the path's parameter {along!r} is not a coordinate "
                         f"({', '.join(coords)})")
    held = [h.coordinate for h in holds]
    if sorted(held + [along]) != sorted(coords) or len(set(held)) != len(held):
        raise ModelError(f"{mech.name}: a path is one coordinate given and every other one "
                         f"held; coordinates {', '.join(coords)}, given {along}, held "
                         f"{', '.join(held) or 'none'}")
    for h in holds:
        _kind(mech, h.quantity)
        lo, hi = (float(v) for v in h.within)
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
            raise ModelError(f"{h.describe()}: within = [{h.shown(lo, 'coordinate')}, "
                             f"{h.shown(hi, 'coordinate')}] must be [low, high] with "
                             f"low < high")
    s = np.asarray(values, dtype=float).reshape(-1)
    n, k = s.size, len(coords)
    ia = coords.index(along)
    iu = [coords.index(c) for c in held]
    ushow = along_unit

    def where(i):
        v = s[i]
        return f"{along} = " + (f"{float(ushow.of(v)):.6g} {ushow.text}" if ushow
                                else f"{v:.6g}")

    def positions(u):
        q = np.empty(u.shape[:-1] + (k,))
        q[..., ia] = s if u.ndim == 2 else s[:, None]
        q[..., iu] = u
        return q

    def solve(q):
        return mech.solve(q.reshape(-1, k), params=params, on_failure="report",
                          check_continuity=False)

    def no_assembly(i, hd, u0):
        q = np.empty((1, k))
        q[0, ia] = s[i]
        q[0, iu] = u0
        try:
            mech.solve(q, params=params, check_continuity=False)
        except AssemblyError as e:
            raise AssemblyError(f"{hd.describe()}: at {where(i)} (position {i + 1} of the "
                                f"path) the mechanism does not assemble for {hd.coordinate} "
                                f"in [{hd.shown(hd.within[0], 'coordinate')}, "
                                f"{hd.shown(hd.within[1], 'coordinate')}]: {e}",
                                group=e.group,
                                links=e.links, coordinate=e.coordinate, position=i,
                                amount=e.amount) from None
        raise AssemblyError(f"{hd.describe()}: at {where(i)} (position {i + 1} of the path) "
                            f"the mechanism does not assemble for {hd.coordinate} in its "
                            f"limits", position=i)

    if len(holds) == 1:
        hd = holds[0]
        lo, hi = (float(v) for v in hd.within)
        grid = np.linspace(lo, hi, scan)
        kin = solve(positions(np.broadcast_to(grid[None, :, None], (n, scan, 1))))
        r = _residuals(kin, holds)[:, 0].reshape(n, scan)
        ok = kin.ok.reshape(n, scan)
        r = np.where(ok, r, 0.0)
        both = ok[:, :-1] & ok[:, 1:]
        change = both & (r[:, :-1] * r[:, 1:] < 0)
        if _kind(mech, hd.quantity)[0] == "phi":   # a jump through ±π is no root
            change &= np.abs(r[:, :-1] - r[:, 1:]) < np.pi
        exact = ok & (r == 0)
        roots = change.sum(axis=1) + exact.sum(axis=1)
        for i in range(n):  # the messages only: the first position without one root
            if roots[i] == 1:
                continue
            if not ok[i].any():
                no_assembly(i, hd, 0.5 * (lo + hi))
            span = (f"[{hd.shown(hd.within[0], 'coordinate')}, "
                    f"{hd.shown(hd.within[1], 'coordinate')}]")
            if roots[i] == 0:
                rr = r[i][ok[i]]
                raise ModelError(f"{hd.describe()}: at {where(i)} (position {i + 1} of the "
                                 f"path) no {hd.coordinate} in {span} reaches "
                                 f"{hd.quantity} = {hd.shown(hd.target)}: {hd.quantity} − "
                                 f"target stays between {hd.shown(rr.min(), digits=4)} and "
                                 f"{hd.shown(rr.max(), digits=4)} there")
            raise ModelError(f"{hd.describe()}: at {where(i)} (position {i + 1} of the path) "
                             f"{int(roots[i])} values of {hd.coordinate} in {span} reach "
                             f"{hd.quantity} = {hd.shown(hd.target)}; narrow within")
        # the bracket [a, b] of each position's root (an exact sample: a = b)
        j = np.where(exact.any(axis=1), np.argmax(exact, axis=1), np.argmax(change, axis=1))
        rows = np.arange(n)
        a = grid[j]
        b = np.where(exact[rows, j], grid[j], grid[np.minimum(j + 1, scan - 1)])
        ra = r[rows, j]
        u = 0.5 * (a + b)
        for _ in range(max_iter):
            kin = solve(positions(u[:, None]))
            if not kin.ok.all():
                i = int(np.flatnonzero(~kin.ok.reshape(-1))[0])
                no_assembly(i, hd, u[i])
            h, d1, _ = _residuals(kin, holds, with_jets=True)
            h, du = h[:, 0], d1[:, 0, iu[0]]
            if np.abs(h).max() <= tol:
                break
            same = np.sign(h) == np.sign(ra)
            a, b = np.where(same, u, a), np.where(same, b, u)
            ra = np.where(same, h, ra)
            step = u - h / np.where(du == 0, 1.0, du)
            inside = (du != 0) & (step > np.minimum(a, b)) & (step < np.maximum(a, b))
            u = np.where(np.abs(h) <= tol, u, np.where(inside, step, 0.5 * (a + b)))
        u = u[:, None]
    else:  # several held coordinates: Newton on the exact Jacobian ∂h/∂u
        lows = np.array([float(h.within[0]) for h in holds])
        highs = np.array([float(h.within[1]) for h in holds])
        u = np.broadcast_to(0.5 * (lows + highs), (n, len(holds))).copy()
        for _ in range(max_iter):
            kin = solve(positions(u))
            if not kin.ok.all():
                i = int(np.flatnonzero(~kin.ok.reshape(-1))[0])
                no_assembly(i, holds[0], u[i])
            h, d1, _ = _residuals(kin, holds, with_jets=True)
            if np.abs(h).max() <= tol:
                break
            u = u - np.linalg.solve(d1[:, :, iu], h[..., None])[..., 0]
        out = (u < lows) | (u > highs)
        if out.any():
            i, c = (int(x) for x in np.argwhere(out)[0])
            hd = holds[c]
            raise ModelError(f"{hd.describe()}: at {where(i)} (position {i + 1} of the path) "
                             f"Newton's method leaves {hd.coordinate}'s limits "
                             f"[{hd.shown(lows[c], 'coordinate')}, "
                             f"{hd.shown(highs[c], 'coordinate')}] "
                             f"(at {hd.shown(u[i, c], 'coordinate')})")
    h, d1, d2 = _residuals(kin, holds, with_jets=True)
    bad = np.abs(h) > tol
    if bad.any():
        i, c = (int(x) for x in np.argwhere(bad)[0])
        hd = holds[c]
        raise ModelError(f"{hd.describe()}: at {where(i)} (position {i + 1} of the path) "
                         f"Newton's method does not converge ({hd.quantity} − target = "
                         f"{hd.shown(h[i, c], digits=3)} after {max_iter} steps)")
    q = positions(u)
    # the implicit-function rule: h_u u' = −h_s, h_u u'' = −q'ᵀ h_qq q'
    hu = d1[:, :, iu]                                   # (n, h, h)
    if np.any(np.abs(np.linalg.det(hu)) == 0):
        i = int(np.flatnonzero(np.abs(np.linalg.det(hu)) == 0)[0])
        raise ModelError(f"{holds[0].describe()}: at {where(i)} the held output does not "
                         f"change with the held coordinate (∂h/∂u = 0): the path has no "
                         f"derivative there")
    dq = np.zeros((n, k))
    dq[:, ia] = 1.0
    dq[:, iu] = -np.linalg.solve(hu, d1[:, :, ia][..., None])[..., 0]
    curv = np.einsum("ni,nhij,nj->nh", dq, d2, dq)
    ddq = np.zeros((n, k))
    ddq[:, iu] = -np.linalg.solve(hu, curv[..., None])[..., 0]
    for a_ in (q, dq, ddq):
        a_.setflags(write=False)
    return HeldPath(coords, along, holds, q, dq, ddq, float(np.abs(h).max()))
