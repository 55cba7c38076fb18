"""Kinetostatics: actuator forces by virtual work and joint reactions by Assur
groups in reverse order.

Two routes to the same forces (DESIGN.md §4):

* **Virtual work** (fast, used in sweeps and synthesis): the generalized force of
  the applied loads ``Q_j = Σ F·∂r/∂q_j + Σ M·∂φ/∂q_j − Σ T·∂L/∂q_j`` from the exact
  analogs; the actuator must supply ``F_j = −Q_j`` (seed 003: Fgc = P6·IS6;
  seed 000: FS = P·Is before efficiency).
* **Reactions** (seed 003 §5): each structural group, last to first, is in
  equilibrium under its loads and the reactions of the groups already solved; its
  joint forces follow from two 2x2 solves (the same matrix as its position
  analysis, singular at a dead point). The actuator force is then the axial
  component of the cylinder's pin force.

Convention: ``reaction(i, j)`` is the force of link ``i`` on link ``j`` at their
joint [N] (so ``reaction(j, i) = −reaction(i, j)``); the frame is link ``"0"``.
A model may name reactions as its source does and declare columns that source
prints with the opposite sign (seed 003 R05, R34, R45; BRIEF.md): that is data of
the model (``tables["reactions"]``, ``tables["signs"]``, :mod:`assur.core.columns`),
explained in its own file.

Inertia (d'Alembert) is included when coordinate rates q̇, q̈ are given: the
acceleration of a centre of mass is ``a = J·q̈ + q̇ᵀ·H·q̇`` from the analogs.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from ..errors import ModelError
from .gravity import GRAVITY, gravity_unit
from .reactions import ReactionContextBase

__all__ = ["Statics", "GRAVITY", "gravity_unit", "applied_loads", "virtual_work_forces",
           "spring_states", "solve",
           "ReactionContextBase", "ReactionContext"]

class Statics:
    """Actuator forces, joint reactions and checks over the positions.

    Produced by :func:`solve`; arrays have the kinematics' shape.

    Attributes
    ----------
    kinematics : Kinematics
    joints : list of (point, i, j)
        Every joint with a reaction: the force of link i on link j at ``point``.
    flags : list of str
        Notes for reports (a source's printed signs are the model's sign maps,
        ``tables["signs"]``).

    Examples
    --------
    >>> from assur import examples
    >>> st = examples.hitch_003().analyze([0.42, 0.67]).statics
    >>> [round(float(f)) for f in st.actuator_force("S")]   # Fgc, seed 003 table 4.1 [N]
    [129614, 135652]
    >>> [round(float(v)) for v in st.reaction("0", "7")[0]]  # R07, table 5.1 [N]
    [-45683, 11272]
    """

    def __init__(self, kin, forces_vw, joints, actuator_rx, residual, flags, finite=False):
        self.kinematics = kin
        self._vw = forces_vw
        self._joints = joints  # {(i, j): (point, fx, fy, mz)}
        self._act_rx = actuator_rx
        self._residual = residual
        self.flags = list(flags)
        # True when every array was checked finite where it was computed (the fused
        # kernel's outputs): first_nonfinite need not look again
        self._finite = finite

    @property
    def joints(self):
        """Every joint with a reaction: ``[(point, i, j), ...]``, the force of link i
        on link j at ``point``, groups last to first (the reverse-order pass).

        Examples
        --------
        >>> from assur import examples
        >>> st = examples.hitch_003().analyze([0.42]).statics
        >>> len(st.joints), st.joints[0]   # 9 pins; group III (6,7) is solved first
        (9, ('56', '5', '6'))
        >>> sorted(p for p, i, j in st.joints if i == "0")   # the frame's pivots
        ['01', '03', '05', '07']
        """
        return [(v[0], i, j) for (i, j), v in self._joints.items()]

    def _o(self, a):
        mn = (self.kinematics.m, self.kinematics.n)
        return self.kinematics.reshape(a if getattr(a, "shape", None) == mn
                                       else np.broadcast_to(a, mn))

    def actuator_force(self, coordinate=None):
        """Force the actuator of a coordinate must supply, by virtual work [N]
        (or driving moment [N·m] for a crank angle): F = −Q, positive pushing.

        Examples
        --------
        >>> from assur import examples
        >>> st = examples.hitch_003().analyze([0.42, 0.67]).statics
        >>> [round(float(f)) for f in st.actuator_force()]   # Fgc, seed 003 table 4.1 [N]
        [129614, 135652]
        >>> st.actuator_force("L3")
        Traceback (most recent call last):
        ...
        KeyError: "unknown coordinate 'L3'; coordinates: ['S']"
        """
        c = self._coord(coordinate)
        return self._o(self._vw[c])

    def actuator_force_from_reactions(self, coordinate=None):
        """The same force from the joint reactions (axial component of the cylinder's
        pin force, the crank's driving moment, the slider's drive) [N or N·m].

        Examples
        --------
        >>> from assur import examples
        >>> st = examples.hitch_003().analyze([0.42, 0.67]).statics
        >>> F = st.actuator_force_from_reactions("S")   # R23 along 01→23
        >>> [round(float(f)) for f in F]                # Fgc, table 4.1 [N]
        [129614, 135652]
        >>> float(abs(st.actuator_force_from_reactions() - st.actuator_force()).max()) < 1e-6
        True
        """
        c = self._coord(coordinate)
        if c not in self._act_rx:
            raise KeyError(f"no reaction-derived actuator force for {c!r}")
        return self._o(self._act_rx[c])

    def _coord(self, c):
        coords = self.kinematics.coordinates
        if c is None:
            if len(coords) != 1:
                raise ValueError(f"name the coordinate: one of {list(coords)}")
            return coords[0]
        if c not in coords:
            raise KeyError(f"unknown coordinate {c!r}; coordinates: {list(coords)}")
        return c

    def reaction(self, i, j):
        """Force of link ``i`` on link ``j`` at their joint, shape (..., 2) [N].

        Examples
        --------
        >>> from assur import examples
        >>> st = examples.hitch_003().analyze([0.42]).statics
        >>> [round(float(v)) for v in st.reaction("5", "6")[0]]   # R56, seed 003 table 5.1
        [45683, 16228]
        """
        i, j = str(i), str(j)
        if (i, j) in self._joints:
            _, fx, fy, _ = self._joints[(i, j)]
            sgn = 1.0
        elif (j, i) in self._joints:
            _, fx, fy, _ = self._joints[(j, i)]
            sgn = -1.0
        else:
            pairs = sorted(self._joints)
            raise KeyError(f"links {i!r} and {j!r} share no joint; joints: {pairs}")
        return sgn * np.stack([self._o(fx), self._o(fy)], axis=-1)

    def reaction_moment(self, i, j):
        """Moment of link ``i`` on link ``j`` at a prismatic pair or a driven crank
        [N·m] (zero at a plain pin).

        Examples
        --------
        The crank bearing O1 of the grain-cleaning mechanism (seed 001 lab 3,
        illustrative dimensions) carries the driving moment; a plain pin carries none:

        >>> import numpy as np
        >>> from assur import io
        >>> model = io.load(io.bundled("cleaning_lab3"))
        >>> st = model.mechanism.analyze(np.radians([0.0, 90.0])).statics   # φ1 [rad]
        >>> [round(float(v), 2) for v in st.reaction_moment("0", "1")]      # [N·m]
        [-20.83, -20.02]
        >>> [round(float(v), 2) for v in st.actuator_force("j1")]           # the same [N·m]
        [-20.83, -20.02]
        >>> [float(v) for v in st.reaction_moment("1", "2")]                # pin A [N·m]
        [0.0, 0.0]
        """
        i, j = str(i), str(j)
        if (i, j) in self._joints:
            return self._o(self._joints[(i, j)][3])
        if (j, i) in self._joints:
            return -self._o(self._joints[(j, i)][3])
        raise KeyError(f"links {i!r} and {j!r} share no joint; joints: {sorted(self._joints)}")

    def reaction_magnitude(self, i, j):
        """|R_ij| [N].

        Examples
        --------
        >>> from assur import examples
        >>> st = examples.hitch_003().analyze([0.42, 0.67]).statics
        >>> [round(float(v)) for v in st.reaction_magnitude("5", "6")]  # |R56| of table 5.1 [N]
        [48480, 74485]
        """
        r = self.reaction(i, j)
        return np.hypot(r[..., 0], r[..., 1])

    def equilibrium_residual(self):
        """Largest |ΣF| [N] and |ΣM| [N·m] over all moving links, recomputed from the
        loads and the reactions: ``(force, moment)`` arrays of the result shape.

        Examples
        --------
        >>> from assur import examples
        >>> st = examples.hitch_003().analyze([0.42, 0.67]).statics
        >>> f, mo = st.equilibrium_residual()
        >>> f.shape, bool(f.max() < 1e-6), bool(mo.max() < 1e-6)   # [N], [N·m]
        ((2,), True, True)
        """
        if callable(self._residual):
            self._residual = self._residual()
        f, mo = self._residual
        return self._o(f), self._o(mo)

    def first_nonfinite(self):
        """``(what, element)`` of the first reaction or actuator force that is NaN or
        infinite, or None.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import solve
        >>> st = solve(examples.hitch_003().solve([0.42, 0.67]), method="array")
        >>> print(st.first_nonfinite())   # every reaction and force is finite
        None
        """
        if self._finite:
            return None
        items = [(f"reaction R{i},{j}", (fx, fy, mz))
                 for (i, j), (_, fx, fy, mz) in self._joints.items()]
        items += [(f"actuator force along {c!r}", (v,)) for c, v in self._vw.items()]
        for what, arrs in items:
            for a in arrs:
                a = np.asarray(a, dtype=float)
                if not np.isfinite(a).all():
                    return what, int(np.flatnonzero(~np.isfinite(a.ravel()))[0])
        return None

    def named_reactions(self):
        """The reactions the mechanism names (``tables["reactions"]``):
        ``{name: (i, j)}``, the force of link i on link j, e.g. seed 003
        ``R05 = ("0", "5")``.

        Examples
        --------
        >>> from assur import examples
        >>> st = examples.hitch_003().analyze([0.42]).statics
        >>> names = st.named_reactions()
        >>> names["R05"], names["R01"]   # seed 003's names: force of link i on link j
        (('0', '5'), ('0', '2'))
        >>> [round(float(v)) for v in st.reaction(*names["R05"])[0]]   # [N]
        [49391, -47486]
        """
        return {name: (str(v[0]), str(v[1]))
                for name, v in self.kinematics.mechanism.tables.get("reactions", {}).items()}

    def to_frame(self, printed_signs=False):
        """pandas DataFrame of the reactions and actuator forces.

        Columns ``R{i}{j}x``, ``R{i}{j}y``, ``R{i}{j}`` [N] for every joint (force of i on
        j); where the mechanism names a reaction (``tables["reactions"]``) that name is
        used. With ``printed_signs=True`` every column a sign map of the mechanism names
        (``tables["signs"]``, :func:`assur.core.columns.column_signs`) is multiplied by its
        sign, as its source prints it. ``F_{coordinate}`` is the actuator force [N] by
        virtual work.

        Examples
        --------
        >>> from assur import examples
        >>> st = examples.hitch_003().analyze([0.42, 0.67]).statics
        >>> df = st.to_frame(printed_signs=True)
        >>> list(df.columns[:4]), len(df.columns)
        (['S', 'R56x', 'R56y', 'R56'], 29)
        >>> [round(float(v)) for v in df["R05x"]]   # as seed 003 table 5.1 prints it [N]
        [-49391, -45742]
        >>> [round(float(v)) for v in st.to_frame()["R05x"]]   # force of 0 on 5 [N]
        [49391, 45742]
        """
        import pandas as pd

        from .columns import column_signs

        kin = self.kinematics
        signs = column_signs(kin.mechanism) if printed_signs else {}
        cols = {c: kin.q(c).ravel() for c in kin.coordinates}
        named = {ij: name for name, ij in self.named_reactions().items()}
        for (i, j), (pt, fx, fy, mz) in self._joints.items():
            name = named.get((str(i), str(j)), f"R{i}{j}")
            cols[f"{name}x"] = signs.get(f"{name}x", 1) * self._o(fx).ravel()
            cols[f"{name}y"] = signs.get(f"{name}y", 1) * self._o(fy).ravel()
            cols[name] = signs.get(name, 1) * np.hypot(self._o(fx), self._o(fy)).ravel()
        for c in kin.coordinates:
            cols[f"F_{c}"] = signs.get(f"F_{c}", 1) * self.actuator_force(c).ravel()
        return pd.DataFrame(cols)


def _values(kin):
    """A function turning a reference into an array broadcastable to (m, n)."""
    mech = kin.mechanism

    def val(ref):
        if ref is None:
            return 0.0
        v = np.asarray(mech.value_of(ref), dtype=float)
        if v.ndim == 1:
            if v.shape[0] == 1:
                return v[0]
            return v[:, None]
        return v
    return val


class _LoadCollector:
    """Load context over arrays (see :mod:`assur.core.loads`): collects the point forces,
    couples and springs of the loads, broadcastable to (m, n)."""

    def __init__(self, kin, g, qd=None, qdd=None):
        self.kin = kin
        self.mech = kin.mechanism
        self.value = _values(kin)
        self.g = g
        self.gravity_unit = gravity_unit(kin.mechanism)
        self.moving = qd is not None
        self.qd, self.qdd = qd, qdd
        self.forces, self.couples, self.springs = [], [], []

    def point(self, p):
        return self.kin.value(p)

    def owner(self, p):
        return self.mech.owner(p)

    def force(self, link, point, fx, fy):
        self.forces.append((link, point, fx, fy))

    def couple(self, link, M):
        self.couples.append((link, M))

    def spring(self, load, T, L):
        self.springs.append((load, T, L))

    def nonzero(self, L, what):
        if np.any(L == 0):
            raise ModelError(f"{what} at {int((L == 0).sum())} position(s); its direction is "
                             f"undefined there")

    def rate(self, link, coordinate=None):
        """∂φ_link/∂q of a coordinate (the only one by default), (m, n) [rad/m or rad/rad]."""
        a = 0 if coordinate is None else self.kin.coordinates.index(coordinate)
        return self.kin.body_rates(link)[0][a]

    def acceleration(self, point):
        J1 = self.kin.jacobian(point)  # (2, k, m, n)
        J2 = self.kin.hessian(point)
        acc = (np.einsum("ckmn,mnk->cmn", J1, self.qdd)
               + np.einsum("mnk,cklmn,mnl->cmn", self.qd, J2, self.qd))
        return acc[0], acc[1]

    def angular_acceleration(self, link):
        w1, w2 = self.kin.body_rates(link)
        return (np.einsum("kmn,mnk->mn", w1, self.qdd)
                + np.einsum("mnk,klmn,mnl->mn", self.qd, w2, self.qd))


def applied_loads(kin, qdot=None, qddot=None, g=None):
    """The applied loads as point forces and link moments, each with its link.

    Returns
    -------
    forces : list of (link, point, fx, fy)
        Arrays broadcastable to (m, n) [N].
    couples : list of (link, M) [N·m]
    springs : list of (Spring, T, L) with the tension T [N] and length L [m]

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.statics import applied_loads
    >>> forces, couples, springs = applied_loads(examples.hitch_003().solve([0.42]))
    >>> [(link, pt, float(fx), float(fy)) for link, pt, fx, fy in forces]  # P6 [N]
    [('6', 'S6', 0.0, -27500.0)]
    >>> couples, springs
    ([], [])
    """
    qd = qdd = None
    if qdot is not None:
        qd = np.broadcast_to(np.asarray(qdot, float).reshape(kin.shape + (-1,))
                             if kin.k > 1 else np.asarray(qdot, float)[..., None],
                             kin.shape + (kin.k,)).reshape(kin.m, kin.n, kin.k)
        if qddot is None:  # steady motion: no coordinate accelerations
            qddot = np.zeros(kin.shape + ((kin.k,) if kin.k > 1 else ()))
        qdd = np.broadcast_to(np.asarray(qddot, float)[..., None]
                              if kin.k == 1 else np.asarray(qddot, float),
                              kin.shape + (kin.k,)).reshape(kin.m, kin.n, kin.k)
    c = _LoadCollector(kin, kin.mechanism.g if g is None else g, qd, qdd)
    for ld in kin.mechanism.loads:
        ld.apply(c)
    return c.forces, c.couples, c.springs


def spring_states(kin):
    """Length, tension and force of every spring of the mechanism over the positions.

    Returns
    -------
    dict of str to (L, T, F)
        By spring name: its length |ab| [m], the tension of one spring
        ``T = preload + rate·(L − free_length)`` [N], and the force of all ``count``
        springs, ``F = count·T`` [N]; arrays of the kinematics' shape (a parameter
        over designs broadcasts).

    Examples
    --------
    Two springs along the hitch's cylinder 01–23 (length S), 1000 N/m, free length
    0.5 m, preload 50 N:

    >>> from assur import examples
    >>> from assur.core.statics import spring_states
    >>> m = examples.hitch_003().spring("s", "01", "23", rate=1000.0, free_length=0.5,
    ...                                 preload=50.0, count=2)
    >>> L, T, F = spring_states(m.solve([0.42, 0.67]))["s"]
    >>> [round(float(v), 3) for v in L]   # = S [m]
    [0.42, 0.67]
    >>> [round(float(v), 1) for v in T]   # 50 + 1000·(L − 0.5) [N]
    [-30.0, 220.0]
    >>> [round(float(v), 1) for v in F]   # 2·T [N]
    [-60.0, 440.0]
    """
    from .loads import Spring

    c = _LoadCollector(kin, 0.0)
    out = {}
    for ld in kin.mechanism.loads:
        if not isinstance(ld, Spring):
            continue
        (ax, ay), (bx, by) = c.point(ld.a), c.point(ld.b)
        L = np.hypot(bx - ax, by - ay)
        T = ld.tension(c, L)
        shape = (kin.m, kin.n)
        L, T = np.broadcast_to(L, shape), np.broadcast_to(T, shape)
        out[ld.name] = (kin.reshape(L), kin.reshape(T),
                        kin.reshape(np.broadcast_to(c.value(ld.count) * T, shape)))
    return out


def virtual_work_forces(kin, qdot=None, qddot=None, g=None):
    """Actuator forces by virtual work, ``{coordinate: F}`` with F of shape (m, n).

    ``F_j = −Q_j``, ``Q_j = Σ F·∂r/∂q_j + Σ M·∂φ/∂q_j`` (spring forces enter as the
    point forces of their tension).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.statics import virtual_work_forces
    >>> F = virtual_work_forces(examples.hitch_003().solve([0.42, 0.67]))
    >>> list(F), [round(float(v)) for v in F["S"].ravel()]   # Fgc, table 4.1 [N]
    (['S'], [129614, 135652])
    """
    forces, couples, _ = applied_loads(kin, qdot, qddot, g)
    Q = np.zeros((kin.k, kin.m, kin.n))
    for link, pt, fx, fy in forces:
        J = kin.jacobian(pt)  # (2, k, m, n)
        Q += fx * J[0] + fy * J[1]
    for link, M in couples:
        w1, _ = kin.body_rates(link)
        Q += M * w1
    return {c: -Q[j] for j, c in enumerate(kin.coordinates)}


#: positions per block of the reverse-order pass: bounds the memory of its temporaries
#: on very large ranges (the dyads are solved by a compiled loop, so smaller blocks do
#: not pay: the concatenation costs more than cache-sized temporaries save)
BLOCK = 1 << 22


def _rate_block(rate, kin, i0, i1):
    """The positions i0:i1 of a coordinate rate (scalar, or an array over positions)."""
    if rate is None:
        return None
    r = np.asarray(rate, float)
    if kin.k == 1:
        return r[..., i0:i1] if r.ndim and r.shape[-1] == kin.n else r
    return r[..., i0:i1, :] if r.ndim >= 2 and r.shape[-2] == kin.n else r


#: designs × positions from which statics.solve uses the fused kernel by default
FUSED_MIN = 4096

#: calls of the array pass on smaller static problems of one mechanism (the same
#: object: structure, loads and values), after which the fused kernel takes over for
#: it (a loop over single positions pays its compilation once; a mechanism analysed a
#: few times, as the tests' random ones, never does)
FUSED_AFTER = 3


def _use_fused(kin) -> bool:
    """The default method for static loads: fused on large problems and on mechanisms
    analysed repeatedly (:data:`FUSED_MIN`, :data:`FUSED_AFTER`)."""
    mech = kin.mechanism
    # whether the result holds every point depends only on which it holds: once per
    # mechanism and set of output points
    if not mech.memo(("statics", "all points", kin.points), kin.has_all_points):
        return False
    if kin.m * kin.n >= FUSED_MIN:
        return True
    calls = mech.memo(("statics", "small calls"), lambda: [0])
    calls[0] += 1
    return calls[0] > FUSED_AFTER


def solve(kin, qdot=None, qddot=None, g=None, method=None):
    """Actuator forces (both routes), joint reactions and equilibrium residuals.

    Very large ranges are processed in blocks of :data:`BLOCK` positions (the same
    formulas).


    Parameters
    ----------
    kin : Kinematics
        Result of :meth:`assur.Mechanism.solve` with all points (the default).
    qdot, qddot : array_like, optional
        Coordinate rates [m/s, m/s²] (shape ``(..., k)`` for k > 1) for inertia loads;
        without them the analysis is static.
    g : float, optional
        Gravity [m/s²] for the masses' weights (weights given in N are used as given);
        default: the mechanism's (:attr:`assur.Mechanism.g`).
    method : {None, "fused", "array"}
        ``"array"``: the reverse-order pass over arrays of positions (group by group,
        numpy); ``"fused"``: the same group code traced into one compiled loop
        (:mod:`assur.core.outputs`, static loads only). Default: fused for static loads on at
        least :data:`FUSED_MIN` elements, or once the mechanism has been analysed more
        than :data:`FUSED_AFTER` times (one position at a time, as dynamics does),
        when the kinematics hold every point (the kernel is compiled once per structure
        and loads, then cached on disk); the array pass otherwise.
        The tests hold the two equal to 1e-9.

    Returns
    -------
    Statics

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.statics import solve
    >>> kin = examples.hitch_003().solve([0.42, 0.67])
    >>> [round(float(v)) for v in solve(kin, method="array").actuator_force()]  # Fgc [N]
    [129614, 135652]
    >>> [round(float(v)) for v in solve(kin, g=9.81).reaction("5", "6")[:, 1]]  # R56y [N]
    [16228, 69359]
    >>> solve(kin, method="numba")
    Traceback (most recent call last):
    ...
    ValueError: method must be one of: [None, 'fused', 'array']
    """
    if method not in (None, "fused", "array"):
        raise ValueError("method must be one of: [None, 'fused', 'array']")
    g = kin.mechanism.g if g is None else g
    if method == "fused" or (method is None and qdot is None and qddot is None
                             and _use_fused(kin)):
        return _solve_fused(kin, g)
    if kin.n <= BLOCK:
        return _solve(kin, qdot, qddot, g)
    parts = [(_solve(kin.positions(i0, min(kin.n, i0 + BLOCK)),
                     _rate_block(qdot, kin, i0, i0 + BLOCK),
                     _rate_block(qddot, kin, i0, i0 + BLOCK), g))
             for i0 in range(0, kin.n, BLOCK)]

    first = parts[0]
    joints = {}
    for key, (pt, *_rest) in first._joints.items():
        cols = [np.concatenate([np.broadcast_to(p._joints[key][c], (kin.m, p.kinematics.n))
                                for p in parts], axis=-1) for c in (1, 2, 3)]
        joints[key] = (pt, *cols)
    vw = {c: np.concatenate([np.broadcast_to(p._vw[c], (kin.m, p.kinematics.n))
                             for p in parts], axis=-1) for c in first._vw}
    act = {c: np.concatenate([np.broadcast_to(p._act_rx[c], (kin.m, p.kinematics.n))
                              for p in parts], axis=-1) for c in first._act_rx}

    def residual():
        res = [p.equilibrium_residual() for p in parts]
        return tuple(np.concatenate([np.asarray(r[i]).reshape(kin.m, -1) for r in res],
                                    axis=-1) for i in (0, 1))

    return Statics(kin, vw, joints, act, residual, [])


def _residual(kin, applied, joints):
    """Equilibrium of every moving link: applied loads + all joint forces on it, as
    (|ΣF|, |ΣM|) maxima over the links, arrays (m, n) (computed when asked for: a
    check, not part of the result)."""
    m, n = kin.m, kin.n
    fres = np.zeros((m, n))
    mres = np.zeros((m, n))
    for b in kin.mechanism.topology.bodies:
        if b == "0":
            continue
        fx, fy, mo = [np.broadcast_to(a, (m, n)) for a in applied[b]]
        for (i, j), (pt, rx, ry, mz) in joints.items():
            if b not in (i, j):
                continue
            sg = 1.0 if j == b else -1.0
            px, py = kin.value(pt)
            fx = fx + sg * rx
            fy = fy + sg * ry
            mo = mo + sg * (px * ry - py * rx + mz)
        fres = np.maximum(fres, np.hypot(fx, fy))
        mres = np.maximum(mres, np.abs(mo))
    return fres, mres


def _applied(kin, qdot, qddot, g):
    """The applied loads on every body as wrenches about the origin (Fx, Fy, M)."""
    r = ReactionContext(kin, set())
    forces, couples, _ = applied_loads(kin, qdot, qddot, g)
    for link, pt, fx, fy in forces:
        r.apply(link, pt, fx, fy)
    for link, M in couples:
        r.apply_moment(link, M)
    return r.W


class _JointRows(Mapping):
    """``{(i, j): (point, Rx, Ry, Rm)}`` over the fused kernel's output rows: a joint's
    rows are viewed when it is asked for (one position at a time, as dynamics calls,
    makes no views that nobody reads). ``index``: ``{(i, j): (point, first row)}``."""

    __slots__ = ("_index", "_out")

    def __init__(self, index, out):
        self._index, self._out = index, out

    def __getitem__(self, key):
        pt, r = self._index[key]
        return pt, self._out[r], self._out[r + 1], self._out[r + 2]

    def __contains__(self, key):
        return key in self._index

    def __iter__(self):
        return iter(self._index)

    def __len__(self):
        return len(self._index)


def _solve_fused(kin, g):
    """Static reactions and actuator forces of all positions from the fused kernel
    (:mod:`assur.core.outputs`): the same group code as :func:`_solve`, traced into one
    compiled loop — an order of magnitude faster on large ranges and on one position."""
    from . import outputs as fused   # imported when used: it brings numba

    mech = kin.mechanism
    joints_, _, out = fused.statics_outputs(kin, g)
    # the outputs' rows, in order: Rx, Ry, Rm of each joint, then F, Fr of each coordinate
    index, actuated = mech.memo(("statics", "fused rows"), lambda: (
        {(i, j): (pt, 3 * r) for r, (i, j, pt) in enumerate(joints_)},
        tuple((c, 3 * len(joints_) + 2 * a, fused.has_actuator(mech, c))
              for a, c in enumerate(mech.coordinates))))
    joints = _JointRows(index, out)
    vw, act = {}, {}
    for c, r, has in actuated:
        vw[c] = out[r]
        if has:
            act[c] = out[r + 1]

    def residual():
        return _residual(kin, _applied(kin, None, None, g), joints)

    # fused.evaluate has checked every output finite (failed elements are 0)
    return Statics(kin, vw, joints, act, residual, [], finite=True)


class ReactionContext(ReactionContextBase):
    """The reverse-order pass over arrays of shape (m, n) (designs, positions).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.statics import ReactionContext
    >>> r = ReactionContext(examples.hitch_003().solve([0.42, 0.67]), set())
    >>> r.shape                              # one design, two positions
    (1, 2)
    >>> float(r.value("P6"))                  # [N]
    27500.0
    """

    def __init__(self, kin, rod_ends):
        super().__init__(kin.mechanism, rod_ends)
        self.kin = kin
        self.shape = (kin.m, kin.n)
        self._val = _values(kin)

    def point(self, p):
        """(x, y) of a point, arrays (m, n) [m].

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42, 0.67]), set())
        >>> x, y = r.point("01")                     # a frame pivot [m]
        >>> x.tolist(), y.tolist()
        ([[0.415, 0.415]], [[0.563, 0.563]])
        """
        return self.kin.value(p)

    def value(self, ref):
        """Value of a number or parameter, broadcastable to (m, n).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42]), set())
        >>> float(r.value("L3")), float(r.value(2.5)), r.value(None)   # [m], [-], none
        (0.2, 2.5, 0.0)
        """
        return self._val(ref)

    def inv(self, x):
        """1/x, and 0 where x = 0 (a degenerate, failed position).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42, 0.67]), set())
        >>> r.inv([4.0, 0.0]).tolist()
        [[0.25, 0.0]]
        """
        x = np.broadcast_to(np.asarray(x, float), self.shape)
        return np.divide(1.0, x, out=np.zeros(self.shape), where=x != 0.0)

    def record(self, i, j, pt, fx, fy, mz=0.0):
        """Record the force (and moment) of body i on body j at point ``pt``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(examples.hitch_003().solve([0.42, 0.67]), set())
        >>> r.record("5", "6", "56", 100.0, -50.0)        # [N]
        >>> pt, fx, fy, mz = r.joints[("5", "6")]
        >>> pt, fx.tolist(), fy.tolist(), mz.tolist()     # broadcast to (m, n)
        ('56', [[100.0, 100.0]], [[-50.0, -50.0]], [[0.0, 0.0]])
        """
        self.joints[(i, j)] = (pt, np.broadcast_to(fx, self.shape),
                               np.broadcast_to(fy, self.shape), np.broadcast_to(mz, self.shape))


def _solve(kin, qdot, qddot, g):
    """The reverse-order pass over one block of positions: each group solves its own
    reactions (:meth:`assur.groups.base.Group.reactions`)."""
    mech = kin.mechanism
    topo = mech.topology
    missing = [p for pts in topo.bodies.values() for p in pts if not kin.has_point(p)]
    if missing:
        raise ValueError(f"the kinematics lack points {missing}: solve without `outputs=`")
    forces, couples, _ = applied_loads(kin, qdot, qddot, g)

    def is_coord(ref):
        return isinstance(ref, str) and ref in mech.coordinates

    rod_ends = {e for g_ in mech.groups
                for e in g_.rod_ends(topo.group_links[g_.name], is_coord)}
    r = ReactionContext(kin, rod_ends)
    for link, pt, fx, fy in forces:
        r.apply(link, pt, fx, fy)
    for link, M in couples:
        r.apply_moment(link, M)
    # (apply rebinds, never mutates, so this keeps the applied loads alone)
    applied = {b: list(w) for b, w in r.W.items()}
    for g_ in reversed(mech.groups):
        r.links = topo.group_links[g_.name]
        g_.reactions(r)
    joints, act = r.joints, r.act
    vw = virtual_work_forces(kin, qdot, qddot, g)

    def residual():
        return _residual(kin, applied, joints)

    return Statics(kin, vw, joints, act, residual, [])
