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

Here: the result :class:`Statics` and :func:`solve`, which chooses the route (the
array pass by blocks of positions, or the fused kernel of :mod:`assur.core.outputs`).
The loads and the virtual work are in :mod:`assur.core.virtual_work`, the array
reverse pass in :mod:`assur.core.reverse_pass`; their names are re-exported here.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from .gravity import GRAVITY, gravity_unit
from .reactions import ReactionContextBase
from .reverse_pass import ReactionContext, _applied, _residual, reverse_pass
from .virtual_work import applied_loads, spring_states, virtual_work_forces

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


def _solve(kin, qdot, qddot, g):
    """The reverse-order pass over one block of positions (:func:`reverse_pass`)."""
    return Statics(kin, *reverse_pass(kin, qdot, qddot, g), [])


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
