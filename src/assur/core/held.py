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

__all__ = ["Hold", "HeldPath", "HeldPaths", "hold_path", "hold_paths", "quantity_jets",
           "output_kind", "HELD_TEXT"]

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
    refs : (str or None, str or None, str or None), optional
        The parameters the target, the low and the high limit are (a design that
        changes one of them holds its own; None: the value given).

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
    refs: tuple | None = None

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
    along_unit : Unit, optional
        The unit messages show s in.

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
    along_unit: object = None

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


#: why a design's held path failed (:attr:`HeldPaths.code`; 0: it did not)
HELD, NO_ROOT, SEVERAL, NO_ASSEMBLY, NO_CONVERGENCE, FLAT, LEAVES_LIMITS, BAD_LIMITS = range(8)

#: the words of each failure, ``{c}`` the held coordinate and ``{y}`` the held output
HELD_TEXT = {NO_ROOT: "no {c} within its limits reaches the target of {y}",
             SEVERAL: "several values of {c} within its limits reach the target of {y}",
             NO_ASSEMBLY: "the mechanism does not assemble for {c} within its limits",
             NO_CONVERGENCE: "Newton's method does not converge on {c}",
             FLAT: "{y} does not change with {c} (∂h/∂u = 0)",
             LEAVES_LIMITS: "Newton's method leaves {c}'s limits",
             BAD_LIMITS: "{c}'s limits are not [low, high] with low < high"}

#: positions (designs × positions × samples) per kernel call of the scan of the limits
SCAN_POSITIONS = 1 << 18


def _wrap(r):
    return np.angle(np.exp(1j * r))


def _residuals(kin, holds, targets, with_jets=False):
    """h (m, N, h) of a solve over (m, N, k) positions with the targets (m, h) and, with
    jets, ∂h/∂q (m, N, h, k) and ∂²h/∂q∂q (m, N, h, k, k)."""
    vals, d1s, d2s = [], [], []
    for c, hd in enumerate(holds):
        v, d1, d2 = quantity_jets(kin, hd.quantity)
        r = v - targets[:, c, None]
        vals.append(_wrap(r) if _kind(kin.mechanism, hd.quantity)[0] == "phi" else r)
        d1s.append(d1)
        d2s.append(d2)
    h = np.stack(vals, axis=-1)
    if not with_jets:
        return h
    return h, np.stack(d1s, axis=-2), np.stack(d2s, axis=-3)


def _outputs(mech, holds):
    """The kernel's outputs the held quantities need (None: all of them)."""
    links = {l.name for l in mech.links}
    dists = {d.name for d in mech.distances}
    out = []
    for h in holds:
        kind, obj = _kind(mech, h.quantity)
        if (kind == "phi" and obj not in links) or (kind in "xy" and obj not in mech.points) \
                or (kind == "dist" and obj not in dists):
            return None
        out.append(obj)
    return tuple(dict.fromkeys(out))


def _designs(params):
    """The number of designs of parameter overrides (arrays of shape (m,))."""
    return max([int(np.size(v)) for v in (params or {}).values()] + [1])


def _subset(params, m, idx):
    """The overrides of the designs ``idx`` (scalars as they are); None for none."""
    if not params:
        return None
    return {k: (np.asarray(v, float).reshape(-1)[idx] if np.size(v) == m and np.ndim(v)
                else v) for k, v in params.items()}


def _hold_values(mech, holds, params, m):
    """The targets and limits of every design, each shape (m, number of holds): a
    hold's ``refs`` (parameter names) read from the design's parameters."""
    allp = {**mech.params, **(params or {})}
    out = np.empty((3, m, len(holds)))
    for c, h in enumerate(holds):
        refs = h.refs or (None, None, None)
        for j, (ref, v) in enumerate(zip(refs, (h.target,) + tuple(h.within))):
            out[j, :, c] = np.broadcast_to(np.asarray(
                float(v) if ref is None else mech.value_of(ref, allp), float), (m,))
    return out[0], out[1], out[2]


@dataclass(frozen=True)
class HeldPaths:
    """The held paths of m designs over the same values of the path's parameter
    (:func:`hold_paths`): positions and analogs of the designs whose held coordinates
    reach their targets, and for every other design why not (a failure, never an
    exception and never NaN).

    Attributes
    ----------
    coordinates, along, holds
        As :class:`HeldPath` (the holds as given: their ``refs`` name the parameters
        each design reads its target and limits from).
    s : ndarray, shape (n,)
        The path's parameter [m or rad].
    q, dq, ddq : ndarray, shape (m, n, k)
        Positions and dq/ds, d²q/ds² (0 for a failed design).
    residual : ndarray, shape (m,)
        The largest |h| left [m or rad].
    code : ndarray of int8, shape (m,)
        0 (:data:`HELD`) or why not: :data:`NO_ROOT`, :data:`SEVERAL`,
        :data:`NO_ASSEMBLY`, :data:`NO_CONVERGENCE`, :data:`FLAT`,
        :data:`LEAVES_LIMITS`, :data:`BAD_LIMITS` (words: :data:`HELD_TEXT`).
    hold, position : ndarray of int, shape (m,)
        The hold and the first position that failed (−1: none).
    failed_positions : ndarray of int, shape (m,)
        How many positions the scan of the limits finds without one root (at least 1
        for a failed design).

    Examples
    --------
    The mini-loader's traverse held at 75° for three lever pivots L35 [m]: a
    lever pivot 10 cm farther out leaves the tool beyond S1's stroke:

    >>> import math
    >>> import numpy as np
    >>> from assur import io
    >>> from assur.core.held import Hold, hold_paths
    >>> mech = io.load(io.bundled("loader_lab1")).mechanism
    >>> h = Hold("S1", "phi9", math.radians(75), (0.77, 0.98))       # [rad], [m]
    >>> p = hold_paths(mech, "S", np.linspace(1.0, 1.25, 4), [h],
    ...                params={"L35": np.array([2.05, 2.06, 2.15])})  # L35 [m]
    >>> p.ok.tolist(), p.position.tolist()
    ([True, True, False], [-1, -1, 0])
    >>> [round(float(v), 4) for v in p.q[0, :, 1]]                   # S1 [m]
    [0.9436, 0.9128, 0.8718, 0.8104]
    >>> print(p.error(2))  # doctest: +ELLIPSIS
    S1 holds phi9 = 75 deg: at S = 1 (position 1 of the path) no S1 in [0.77, 0.98] reaches phi9 = 75 deg: ...
    """

    coordinates: tuple
    along: str
    holds: tuple
    s: np.ndarray = field(repr=False)
    q: np.ndarray = field(repr=False)
    dq: np.ndarray = field(repr=False)
    ddq: np.ndarray = field(repr=False)
    residual: np.ndarray = field(repr=False)
    code: np.ndarray = field(repr=False)
    hold: np.ndarray = field(repr=False)
    position: np.ndarray = field(repr=False)
    failed_positions: np.ndarray = field(repr=False)
    info: dict = field(repr=False, default_factory=dict)

    def __len__(self):
        return len(self.q)

    @property
    def ok(self) -> np.ndarray:
        """True for the designs whose held coordinates reach their targets at every
        position, shape (m,).

        Examples
        --------
        >>> import math
        >>> from assur import io
        >>> from assur.core.held import Hold, hold_paths
        >>> mech = io.load(io.bundled("loader_lab1")).mechanism
        >>> h = Hold("S1", "phi9", math.radians(75), (0.77, 0.98))       # [rad], [m]
        >>> hold_paths(mech, "S", [1.0, 1.2], [h], params={"L9": [0.3, 0.5]}).ok.tolist()
        [True, False]
        """
        return self.code == HELD

    def design_hold(self, i, c=0) -> Hold:
        """Hold ``c`` with design ``i``'s own target and limits.

        Examples
        --------
        >>> import math
        >>> from assur import io
        >>> from assur.core.held import Hold, hold_paths
        >>> mech = io.load(io.bundled("loader_lab1")).mechanism
        >>> h = Hold("S1", "phi9", 1.3, (0.77, 0.98), refs=(None, None, "S1max"))  # [rad], [m]
        >>> p = hold_paths(mech, "S", [1.0], [h], params={"S1max": [0.95, 0.97]})
        >>> p.design_hold(1).within                                 # S1's limits [m]
        (0.77, 0.97)
        """
        import dataclasses
        t, lo, hi = (self.info[k][i, c] for k in ("targets", "lows", "highs"))
        return dataclasses.replace(self.holds[c], target=float(t),
                                   within=(float(lo), float(hi)))

    def path(self, i) -> HeldPath:
        """Design ``i``'s :class:`HeldPath` (its failure raised, as :func:`hold_path`).

        Examples
        --------
        >>> import math
        >>> from assur import io
        >>> from assur.core.held import Hold, hold_paths
        >>> mech = io.load(io.bundled("loader_lab1")).mechanism
        >>> h = Hold("S1", "phi9", math.radians(75), (0.77, 0.98))       # [rad], [m]
        >>> p = hold_paths(mech, "S", [1.0, 1.2], [h], params={"L35": [2.05, 2.06]})
        >>> p.path(1).q.shape, p.path(1).residual < 1e-12
        ((2, 2), True)
        """
        e = self.error(i)
        if e is not None:
            raise e
        arrs = [np.array(a[i]) for a in (self.q, self.dq, self.ddq)]
        for a in arrs:
            a.setflags(write=False)
        holds = tuple(self.design_hold(i, c) for c in range(len(self.holds)))
        return HeldPath(self.coordinates, self.along, holds, *arrs,
                        float(self.residual[i]), self.info.get("along_unit"))

    def where(self, i) -> str:
        """The path's parameter at position ``i`` (``"S = 1.2 m"``), for messages.

        Examples
        --------
        >>> import math
        >>> from assur import io
        >>> from assur.core.held import Hold, hold_paths
        >>> mech = io.load(io.bundled("loader_lab1")).mechanism
        >>> h = Hold("S1", "phi9", math.radians(75), (0.77, 0.98))       # [rad], [m]
        >>> hold_paths(mech, "S", [1.0, 1.2], [h]).where(1)
        'S = 1.2'
        """
        v, u = float(self.s[i]), self.info.get("along_unit")
        return f"{self.along} = " + (f"{float(u.of(v)):.6g} {u.text}" if u else f"{v:.6g}")

    def error(self, i):
        """Why design ``i`` has no held path, as the exception :func:`hold_path` raises
        for it (:class:`ModelError`, or :class:`AssemblyError` naming the group);
        None when it has one.

        Examples
        --------
        >>> import math
        >>> from assur import io
        >>> from assur.core.held import Hold, hold_paths
        >>> mech = io.load(io.bundled("loader_lab1")).mechanism
        >>> h = Hold("S1", "phi9", math.radians(75), (0.77, 0.98))       # [rad], [m]
        >>> p = hold_paths(mech, "S", [1.0, 1.2], [h], params={"L9": [0.3, 0.5]})
        >>> p.error(0) is None, type(p.error(1)).__name__
        (True, 'ModelError')
        """
        code, c, p = int(self.code[i]), int(self.hold[i]), int(self.position[i])
        if code == HELD:
            return None
        hd = self.design_hold(i, c)
        lo, hi = hd.within
        span = f"[{hd.shown(lo, 'coordinate')}, {hd.shown(hi, 'coordinate')}]"
        value = float(self.info["value"][i])
        if code == BAD_LIMITS:
            return ModelError(f"{hd.describe()}: within = {span} must be [low, high] with "
                              f"low < high")
        at = f"{hd.describe()}: at {self.where(p)} (position {p + 1} of the path)"
        if code == NO_ASSEMBLY:
            return self._no_assembly(i, hd, at, span)
        if code == NO_ROOT:
            rmin, rmax = self.info["span"][i]
            return ModelError(f"{at} no {hd.coordinate} in {span} reaches {hd.quantity} = "
                              f"{hd.shown(hd.target)}: {hd.quantity} − target stays between "
                              f"{hd.shown(rmin, digits=4)} and {hd.shown(rmax, digits=4)} "
                              f"there")
        if code == SEVERAL:
            return ModelError(f"{at} {int(value)} values of {hd.coordinate} in {span} reach "
                              f"{hd.quantity} = {hd.shown(hd.target)}; narrow within")
        if code == LEAVES_LIMITS:
            return ModelError(f"{at} Newton's method leaves {hd.coordinate}'s limits {span} "
                              f"(at {hd.shown(value, 'coordinate')})")
        if code == NO_CONVERGENCE:
            return ModelError(f"{at} Newton's method does not converge ({hd.quantity} − "
                              f"target = {hd.shown(value, digits=3)} after "
                              f"{self.info['max_iter']} steps)")
        return ModelError(f"{self.design_hold(i, 0).describe()}: at {self.where(p)} the held "
                          f"output does not change with the held coordinate (∂h/∂u = 0): "
                          f"the path has no derivative there")

    def _no_assembly(self, i, hd, at, span):
        """The AssemblyError of design ``i`` at its failed position, in its group's words."""
        mech, params = self.info["mech"], self.info["params"]
        p = int(self.position[i])
        k = len(self.coordinates)
        q = np.empty((1, k))
        q[0, self.coordinates.index(self.along)] = self.s[p]
        q[0, [self.coordinates.index(h.coordinate) for h in self.holds]] = self.info["at"][i]
        try:
            mech.solve(q, params=_subset(params, len(self), [i]), check_continuity=False)
        except AssemblyError as e:
            return AssemblyError(f"{at} the mechanism does not assemble for {hd.coordinate} "
                                 f"in {span}: {e}", group=e.group, links=e.links,
                                 coordinate=e.coordinate, position=p, amount=e.amount)
        return AssemblyError(f"{at} the mechanism does not assemble for {hd.coordinate} in "
                             f"its limits", position=p)


def hold_paths(mech, along, values, holds, params=None, *, tol=1e-12, scan=41,
               along_unit=None, max_iter=60):
    """Solve the held coordinates of m designs at every value of the path's
    parameter, vectorized over designs × positions (the batched :func:`hold_path`).

    Each design reads its parameters from ``params`` (arrays of shape (m,)) and its
    holds' targets and limits from the parameters their ``refs`` name. The scan of
    the limits runs over designs × positions × samples (a kernel call for at most
    :data:`SCAN_POSITIONS` of them), Newton's method over designs × positions.

    Parameters
    ----------
    mech : Mechanism
        A mechanism of k ≥ 2 coordinates.
    along : str
        The coordinate given (the path's parameter s).
    values : array_like, shape (n,)
        Its values [m or rad], the same for every design.
    holds : sequence of Hold
        One per other coordinate (k − 1 of them).
    params : mapping, optional
        Parameter overrides, arrays of shape (m,) for m designs.
    tol, scan, along_unit, max_iter
        As for :func:`hold_path`.

    Returns
    -------
    HeldPaths
        A design whose held coordinate cannot reach its target within its limits at
        some position (or does not assemble there) is a failure of its own
        (:attr:`HeldPaths.code`, :meth:`HeldPaths.error`); the others are unaffected.

    Raises
    ------
    ModelError
        What no design could change: ``along`` is not a coordinate, the holds do not
        hold every other coordinate once, a held output is unknown.

    Examples
    --------
    The mini-loader's traverse held at 75° for two tie lengths L8 [m]:

    >>> import math
    >>> import numpy as np
    >>> from assur import io
    >>> from assur.core.held import Hold, hold_paths
    >>> mech = io.load(io.bundled("loader_lab1")).mechanism
    >>> h = Hold("S1", "phi9", math.radians(75), (0.77, 0.98))      # [rad], [m]
    >>> p = hold_paths(mech, "S", np.linspace(1.0, 1.25, 4), [h], params={"L8": [0.5, 0.51]})
    >>> p.q.shape, p.ok.tolist()
    ((2, 4, 2), [True, True])
    >>> phi9 = mech.solve(p.q, params={"L8": [0.5, 0.51]}).phi("9")
    >>> bool(np.abs(phi9 - math.radians(75)).max() < 1e-12)
    True
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
    s = np.asarray(values, dtype=float).reshape(-1)
    n, k, nh = s.size, len(coords), len(holds)
    m = _designs(params)
    ia, iu = coords.index(along), [coords.index(c) for c in held]
    targets, lows, highs = _hold_values(mech, holds, params, m)
    outs = _outputs(mech, holds)
    r = _Run(m, n, k, nh)
    bad = ~(np.isfinite(lows) & np.isfinite(highs) & (lows < highs))
    for i, c in zip(*np.nonzero(bad)):
        r.fail(np.array([i]), BAD_LIMITS, c, 0, 1)

    def solve(idx, q):
        """(mc, N, k) positions of the designs idx, solved (failures reported)."""
        return mech.solve(q, params=_subset(params, m, idx), outputs=outs,
                          on_failure="report", check_continuity=False)

    def positions(u):
        """(mc, n, …, k) positions of held values u of shape (mc, n, …, nh)."""
        q = np.empty(u.shape[:-1] + (k,))
        q[..., ia] = s.reshape((n,) + (1,) * (u.ndim - 3))
        q[..., iu] = u
        return q

    live = np.flatnonzero(~bad.any(axis=1))
    per = max(1, SCAN_POSITIONS // max(1, n * (scan if nh == 1 else 1)))
    for a in range(0, len(live), per):
        idx = live[a:a + per]
        sub = _Chunk(idx, targets[idx], lows[idx], highs[idx], r, tol, max_iter)
        if nh == 1:
            u = sub.scan(solve, positions, holds[0], mech, scan, n)
            u = sub.narrow(u)      # the designs with one root at every position
            if u is None:
                continue
            u = sub.newton_one(solve, positions, holds, iu[0], u)
        else:
            u = sub.newton(solve, positions, holds, iu, n)
        if sub.live.any():
            sub.analogs(holds, ia, iu, u, positions)
    info = dict(targets=targets, lows=lows, highs=highs, value=r.value, span=r.span, at=r.at,
                mech=mech, params=params, along_unit=along_unit, max_iter=max_iter)
    return HeldPaths(coords, along, holds, s, r.q, r.dq, r.ddq, r.residual, r.code, r.hold,
                     r.position, r.count, info)


class _Run:
    """The result arrays of :func:`hold_paths`, written chunk by chunk."""

    def __init__(self, m, n, k, nh):
        self.q, self.dq, self.ddq = (np.zeros((m, n, k)) for _ in range(3))
        self.residual, self.value = np.zeros(m), np.zeros(m)
        self.span, self.at = np.zeros((m, 2)), np.zeros((m, nh))
        self.code = np.zeros(m, np.int8)
        self.hold, self.position = np.full(m, -1, np.int64), np.full(m, -1, np.int64)
        self.count = np.zeros(m, np.int64)

    def fail(self, idx, code, c, pos, count, value=None):
        """Designs ``idx`` (not failed before) fail with ``code`` at hold ``c``, position
        ``pos`` (arrays or scalars), ``count`` failed positions."""
        new = idx[self.code[idx] == HELD]
        sel = self.code[idx] == HELD
        self.code[new] = code
        for arr, v in ((self.hold, c), (self.position, pos), (self.count, count),
                       (self.value, value)):
            if v is not None:
                arr[new] = np.broadcast_to(np.asarray(v), idx.shape)[sel]


class _Chunk:
    """One chunk of designs of :func:`hold_paths` (indices ``idx`` into the run)."""

    def __init__(self, idx, targets, lows, highs, run, tol, max_iter):
        self.idx, self.t, self.lo, self.hi = idx, targets, lows, highs
        self.run, self.tol, self.max_iter = run, tol, max_iter
        self.live = np.ones(len(idx), bool)   # not failed

    def fail(self, mask, code, c, pos, count=1, value=None):
        """The designs of the chunk where ``mask`` fail (the first reason kept)."""
        mask = mask & self.live
        if mask.any():
            w = np.flatnonzero(mask)
            pick = (lambda v: None if v is None else np.broadcast_to(np.asarray(v),
                                                                     mask.shape)[w])
            self.run.fail(self.idx[w], code, pick(c), pick(pos), pick(count), pick(value))
            self.live &= ~mask

    def scan(self, solve, positions, hd, mech, scan, n):
        """The bracket of each position's root from ``scan`` samples of the limits:
        the start (mc, n) of Newton's method, and its bracket kept on the chunk."""
        mc = len(self.idx)
        grid = np.linspace(self.lo[:, 0], self.hi[:, 0], scan, axis=1)       # (mc, scan)
        g4 = np.broadcast_to(grid[:, None, :, None], (mc, n, scan, 1))
        kin = solve(self.idx, positions(g4).reshape(mc, n * scan, -1))
        r = _residuals(kin, (hd,), self.t)[..., 0].reshape(mc, n, scan)
        ok = kin.ok.reshape(mc, n, scan)
        r = np.where(ok, r, 0.0)
        change = ok[..., :-1] & ok[..., 1:] & (r[..., :-1] * r[..., 1:] < 0)
        if _kind(mech, hd.quantity)[0] == "phi":   # a jump through ±π is no root
            change &= np.abs(r[..., :-1] - r[..., 1:]) < np.pi
        exact = ok & (r == 0)
        roots = change.sum(axis=-1) + exact.sum(axis=-1)                       # (mc, n)
        wrong = roots != 1
        p = np.argmax(wrong, axis=1)
        rows = np.arange(mc)
        none_ok = ~ok[rows, p].any(axis=1)
        with_ok = ~none_ok & wrong.any(axis=1)
        if with_ok.any():  # the range of h − target at the position, for the message
            w = np.flatnonzero(with_ok)
            okw, rw = ok[w, p[w]], r[w, p[w]]
            self.run.span[self.idx[w]] = np.stack(
                [np.where(okw, rw, np.inf).min(axis=1),
                 np.where(okw, rw, -np.inf).max(axis=1)], axis=1)
        count = wrong.sum(axis=1)
        failed = wrong.any(axis=1)
        self.run.at[self.idx[failed & none_ok]] = 0.5 * (self.lo + self.hi)[failed & none_ok]
        self.fail(failed & none_ok, NO_ASSEMBLY, 0, p, count)
        self.fail(failed & (roots[rows, p] == 0), NO_ROOT, 0, p, count)
        self.fail(failed, SEVERAL, 0, p, count, roots[rows, p])
        # the bracket [a, b] of each position's root (an exact sample: a = b)
        j = np.where(exact.any(axis=-1), np.argmax(exact, axis=-1), np.argmax(change, axis=-1))
        a = np.take_along_axis(grid, j, axis=1)
        b = np.where(np.take_along_axis(exact, j[..., None], axis=-1)[..., 0], a,
                     np.take_along_axis(grid, np.minimum(j + 1, scan - 1), axis=1))
        self.a, self.b = a, b
        self.ra = np.take_along_axis(r, j[..., None], axis=-1)[..., 0]
        return 0.5 * (a + b)

    def narrow(self, u):
        """Keep the live designs only (their starts u returned; None: none left)."""
        w = np.flatnonzero(self.live)
        if not len(w):
            return None
        self.idx, self.t, self.lo, self.hi = (a[w] for a in (self.idx, self.t, self.lo,
                                                             self.hi))
        self.a, self.b, self.ra = self.a[w], self.b[w], self.ra[w]
        self.live = self.live[w]
        return u[w]

    def _solve_live(self, solve, positions, u):
        """Solve at held values u (mc, n, nh); a design not assembling at some position
        fails there. Returns the kinematics and the mask of elements that count."""
        kin = solve(self.idx, positions(u))
        okp = kin.ok
        bad = self.live & ~okp.all(axis=1)
        if bad.any():
            p = np.argmax(~okp, axis=1)
            w = np.flatnonzero(bad)
            self.run.at[self.idx[w]] = u[w, p[w]]
            self.fail(bad, NO_ASSEMBLY, 0, p)
        return kin, self.live[:, None] & okp

    def newton_one(self, solve, positions, holds, iu, u):
        """Safeguarded Newton on one held coordinate within its bracket, (mc, n, 1)."""
        tol = self.tol
        a, b, ra = self.a, self.b, self.ra
        for _ in range(self.max_iter):
            kin, use = self._solve_live(solve, positions, u[..., None])
            h, d1, _ = _residuals(kin, holds, self.t, with_jets=True)
            h, du = np.where(use, h[..., 0], 0.0), d1[..., 0, iu]
            if np.abs(h).max() <= tol:
                break
            same = np.sign(h) == np.sign(ra)
            a, b = np.where(same, u, a), np.where(same, b, u)
            ra = np.where(same, h, ra)
            step = u - h / np.where(du == 0, 1.0, du)
            inside = (du != 0) & (step > np.minimum(a, b)) & (step < np.maximum(a, b))
            u = np.where(np.abs(h) <= tol, u, np.where(inside, step, 0.5 * (a + b)))
        self.kin = kin
        return u[..., None]

    def newton(self, solve, positions, holds, iu, n):
        """Newton's method on the exact Jacobian ∂h/∂u from the middle of the limits,
        (mc, n, nh)."""
        mid = 0.5 * (self.lo + self.hi)
        u = np.broadcast_to(mid[:, None, :], (len(self.idx), n, mid.shape[1])).copy()
        for _ in range(self.max_iter):
            kin, use = self._solve_live(solve, positions, u)
            h, d1, _ = _residuals(kin, holds, self.t, with_jets=True)
            h = np.where(use[..., None], h, 0.0)
            if np.abs(h).max() <= self.tol:
                break
            J = d1[..., iu]
            flat = np.linalg.det(J) == 0
            self._flat(flat & use)
            J = np.where(flat[..., None, None], np.eye(len(iu)), J)
            u = u - np.linalg.solve(J, h[..., None])[..., 0]
        self.kin = kin
        out = self.live[:, None, None] & ((u < self.lo[:, None]) | (u > self.hi[:, None]))
        if out.any():
            flat_out = out.reshape(len(self.idx), -1)
            first = np.argmax(flat_out, axis=1)
            p, c = np.divmod(first, len(iu))
            rows = np.arange(len(self.idx))
            self.fail(flat_out.any(axis=1), LEAVES_LIMITS, c, p, value=u[rows, p, c])
        return u

    def _flat(self, flat):
        """Designs with ∂h/∂u singular at some position (mc, n) fail there."""
        if flat.any():
            self.fail(flat.any(axis=1), FLAT, 0, np.argmax(flat, axis=1))

    def analogs(self, holds, ia, iu, u, positions):
        """The residual check and dq/ds, d²q/ds² (the implicit-function rule) of the
        chunk's live designs, written to the run."""
        h, d1, d2 = _residuals(self.kin, holds, self.t, with_jets=True)
        h = np.where(self.kin.ok[..., None], h, 0.0)
        bad = np.abs(h) > self.tol                                         # (mc, n, nh)
        if bad.any():
            flat_b = bad.reshape(len(self.idx), -1)
            p, c = np.divmod(np.argmax(flat_b, axis=1), len(iu))
            rows = np.arange(len(self.idx))
            self.fail(flat_b.any(axis=1), NO_CONVERGENCE, c, p, value=h[rows, p, c])
        # the implicit-function rule: h_u u' = −h_s, h_u u'' = −q'ᵀ h_qq q'
        hu = d1[..., iu]                                                   # (mc, n, h, h)
        flat = np.linalg.det(hu) == 0
        self._flat(flat)
        hu = np.where(flat[..., None, None], np.eye(len(iu)), hu)
        mc, n = u.shape[:2]
        dq = np.zeros((mc, n, d1.shape[-1]))
        dq[..., ia] = 1.0
        dq[..., iu] = -np.linalg.solve(hu, d1[..., ia][..., None])[..., 0]
        curv = np.einsum("mni,mnhij,mnj->mnh", dq, d2, dq)
        ddq = np.zeros_like(dq)
        ddq[..., iu] = -np.linalg.solve(hu, curv[..., None])[..., 0]
        w = np.flatnonzero(self.live)
        dest = self.idx[w]
        self.run.q[dest] = positions(u)[w]
        self.run.dq[dest], self.run.ddq[dest] = dq[w], ddq[w]
        self.run.residual[dest] = np.abs(h[w]).reshape(len(w), -1).max(axis=1, initial=0.0)


def hold_path(mech, along, values, holds, params=None, *, tol=1e-12, scan=41,
              along_unit=None, max_iter=60):
    """Solve the held coordinates at every value of the path's parameter and the
    path's derivatives (the implicit-function rule): :func:`hold_paths` of one design,
    its failure raised.

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
    if _designs(params) != 1:
        raise ModelError(f"{mech.name}: hold_path solves one design; parameters of "
                         f"{_designs(params)} designs go to hold_paths")
    return hold_paths(mech, along, values, holds, params, tol=tol, scan=scan,
                      along_unit=along_unit, max_iter=max_iter).path(0)
