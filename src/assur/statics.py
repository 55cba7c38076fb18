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
the model (``tables["reactions"]``, ``tables["signs"]``, :mod:`assur.columns`),
explained in its own file.

Inertia (d'Alembert) is included when coordinate rates q̇, q̈ are given: the
acceleration of a centre of mass is ``a = J·q̈ + q̇ᵀ·H·q̇`` from the analogs.
"""

from __future__ import annotations

import numpy as np

from .errors import AssemblyError, ModelError
from .groups import Crank, CylinderLever, Dyad, RigidPoint, SliderDyad, SliderInput
from .loads import Couple, Mass, PointForce, Spring, Weight
from .mechanism import PosePoint

#: default acceleration of gravity g [m/s²] turning masses into weights: 9.81, the
#: value engineering worksheets use (all the seeds do). A model may set its own
#: (``[model] gravity = "9.80665 m/s^2"``), a call its own (``analyze(..., g=…)``).
GRAVITY = 9.81


def _cross(ax, ay, bx, by):
    return ax * by - ay * bx


def _dyad_impl():
    from numba import njit

    @njit(cache=True, nogil=True, error_model="numpy")
    def dyad_reactions(ax, ay, bx, by, cx, cy, fax, fay, ma, fbx, fby, mb, out):
        """Reactions of an RRR dyad (links a: A–C, b: B–C) under the wrenches (F, M about
        the origin) of its two links, in one fused pass over the positions.

        Link a: R_A − R_C + F_a = 0 and (A−C)×R_A + M_a,C = 0; link b: R_B + R_C + F_b = 0
        and (B−C)×R_B + M_b,C = 0, so ``[[-u_y, u_x], [-w_y, w_x]]·R_A = [r1, r2]`` with
        u = A−C, w = B−C (seed 003 §5.1–5.3, group by group). Writes out[0:6] = R_A,
        R_C (force of a on b), R_B; zero where the dyad is degenerate (a failed
        position: det = 0)."""
        m, n = ax.shape
        for i in range(m):
            for j in range(n):
                c_x = cx[i, j]
                c_y = cy[i, j]
                f_ax = fax[i, j]
                f_ay = fay[i, j]
                f_bx = fbx[i, j]
                f_by = fby[i, j]
                mac = ma[i, j] - (c_x * f_ay - c_y * f_ax)
                mbc = mb[i, j] - (c_x * f_by - c_y * f_bx)
                ux = ax[i, j] - c_x
                uy = ay[i, j] - c_y
                wx = bx[i, j] - c_x
                wy = by[i, j] - c_y
                det = ux * wy - uy * wx
                idet = 1.0 / det if det != 0.0 else 0.0
                r1 = -mac
                r2 = mbc - (wx * (f_ay + f_by) - wy * (f_ax + f_bx))
                rax = (r1 * wx - ux * r2) * idet
                ray = (-uy * r2 + wy * r1) * idet
                rcx = rax + f_ax
                rcy = ray + f_ay
                out[0, i, j] = rax
                out[1, i, j] = ray
                out[2, i, j] = rcx
                out[3, i, j] = rcy
                out[4, i, j] = -rcx - f_bx
                out[5, i, j] = -rcy - f_by

    return dyad_reactions


_dyad_reactions = _dyad_impl()


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
    """

    def __init__(self, kin, forces_vw, joints, actuator_rx, residual, flags):
        self.kinematics = kin
        self._vw = forces_vw
        self._joints = joints  # {(i, j): (point, fx, fy, mz)}
        self._act_rx = actuator_rx
        self._residual = residual
        self.flags = list(flags)

    @property
    def joints(self):
        return [(v[0], i, j) for (i, j), v in self._joints.items()]

    def _o(self, a):
        return self.kinematics._out(np.broadcast_to(a, (self.kinematics.m, self.kinematics.n)))

    def actuator_force(self, coordinate=None):
        """Force the actuator of a coordinate must supply, by virtual work [N]
        (or driving moment [N·m] for a crank angle): F = −Q, positive pushing."""
        c = self._coord(coordinate)
        return self._o(self._vw[c])

    def actuator_force_from_reactions(self, coordinate=None):
        """The same force from the joint reactions (axial component of the cylinder's
        pin force, the crank's driving moment, the slider's drive) [N or N·m]."""
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
        """Force of link ``i`` on link ``j`` at their joint, shape (..., 2) [N]."""
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
        [N·m] (zero at a plain pin)."""
        i, j = str(i), str(j)
        if (i, j) in self._joints:
            return self._o(self._joints[(i, j)][3])
        return -self._o(self._joints[(j, i)][3])

    def reaction_magnitude(self, i, j):
        """|R_ij| [N]."""
        r = self.reaction(i, j)
        return np.hypot(r[..., 0], r[..., 1])

    def equilibrium_residual(self):
        """Largest |ΣF| [N] and |ΣM| [N·m] over all moving links, recomputed from the
        loads and the reactions: ``(force, moment)`` arrays of the result shape."""
        if callable(self._residual):
            self._residual = self._residual()
        f, mo = self._residual
        return self._o(f), self._o(mo)

    def named_reactions(self):
        """The reactions the mechanism names (``tables["reactions"]``):
        ``{name: (i, j)}``, the force of link i on link j, e.g. seed 003
        ``R05 = ("0", "5")``."""
        return {name: (str(v[0]), str(v[1]))
                for name, v in self.kinematics.mechanism.tables.get("reactions", {}).items()}

    def to_frame(self, printed_signs=False):
        """pandas DataFrame of the reactions and actuator forces.

        Columns ``R{i}{j}x``, ``R{i}{j}y``, ``R{i}{j}`` [N] for every joint (force of i on
        j); where the mechanism names a reaction (``tables["reactions"]``) that name is
        used. With ``printed_signs=True`` every column a sign map of the mechanism names
        (``tables["signs"]``, :func:`assur.columns.column_signs`) is multiplied by its
        sign, as its source prints it. ``F_{coordinate}`` is the actuator force [N] by
        virtual work.
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


def _body_angle_jets(kin, body, mech):
    """(φ', φ'') of a link, shapes (k, m, n), (k, k, m, n), from two of its points."""
    pts = mech._bodies[body]["points"]
    k, m, n = kin.k, kin.m, kin.n
    if body == "0":
        return np.zeros((k, m, n)), np.zeros((k, k, m, n))
    if len(pts) < 2:
        # a slider block turns with its guide
        for g in mech.groups:
            links = mech._group_links.get(g.name, ())
            if isinstance(g, SliderDyad) and len(links) == 3 and links[1] == body:
                return _body_angle_jets(kin, links[2], mech)
            if isinstance(g, SliderInput) and links and links[0] == body:
                return _body_angle_jets(kin, mech.owner(g.origin), mech)
        return np.zeros((k, m, n)), np.zeros((k, k, m, n))
    P, Q = pts[0], pts[1]
    d = kin._val(Q) - kin._val(P)  # (2, m, n)
    d1 = kin._jet1(Q) - kin._jet1(P)  # (2, k, m, n)
    d2 = kin._jet2(Q) - kin._jet2(P)  # (2, k, k, m, n)
    r2 = d[0] ** 2 + d[1] ** 2
    c1 = d[0] * d1[1] - d[1] * d1[0]  # (k, m, n)
    w1 = c1 / r2
    dot1 = d[0] * d1[0] + d[1] * d1[1]
    w2 = np.empty((k, k, m, n))
    for a in range(k):
        for b in range(k):
            num = (d1[0, b] * d1[1, a] - d1[1, b] * d1[0, a]) + (d[0] * d2[1, a, b]
                                                               - d[1] * d2[0, a, b])
            w2[a, b] = num / r2 - 2 * c1[a] * dot1[b] / r2**2
    return w1, w2


def applied_loads(kin, qdot=None, qddot=None, g=GRAVITY):
    """The applied loads as point forces and link moments, each with its link.

    Returns
    -------
    forces : list of (link, point, fx, fy)
        Arrays broadcastable to (m, n) [N].
    couples : list of (link, M) [N·m]
    springs : list of (Spring, T, L) with the tension T [N] and length L [m]
    """
    mech = kin.mechanism
    val = _values(kin)
    forces, couples, springs = [], [], []
    moving = qdot is not None
    if moving:
        qd = np.broadcast_to(np.asarray(qdot, float).reshape(kin.shape + (-1,))
                             if kin.k > 1 else np.asarray(qdot, float)[..., None],
                             kin.shape + (kin.k,)).reshape(kin.m, kin.n, kin.k)
        if qddot is None:  # steady motion: no coordinate accelerations
            qddot = np.zeros(kin.shape + ((kin.k,) if kin.k > 1 else ()))
        qdd = np.broadcast_to(np.asarray(qddot, float)[..., None]
                              if kin.k == 1 else np.asarray(qddot, float),
                              kin.shape + (kin.k,)).reshape(kin.m, kin.n, kin.k)
    for ld in mech.loads:
        if isinstance(ld, Weight):
            forces.append((ld.link or mech.owner(ld.point), ld.point, 0.0, -val(ld.P)))
        elif isinstance(ld, PointForce):
            forces.append((ld.link or mech.owner(ld.point), ld.point, val(ld.fx), val(ld.fy)))
        elif isinstance(ld, Couple):
            couples.append((ld.link, val(ld.M)))
        elif isinstance(ld, Spring):
            ax, ay = kin._val(ld.a)
            bx, by = kin._val(ld.b)
            L = np.hypot(bx - ax, by - ay)
            if np.any(L == 0):
                raise ModelError(f"spring {ld.name!r}: its ends {ld.a!r} and {ld.b!r} coincide "
                                 f"at {int((L == 0).sum())} position(s); its direction is "
                                 f"undefined there")
            T = val(ld.preload) + val(ld.rate) * (L - val(ld.free_length))
            ux, uy = (bx - ax) / L, (by - ay) / L
            la, lb = ld.links or (mech.owner(ld.a), mech.owner(ld.b))
            forces.append((la, ld.a, T * ux, T * uy))
            forces.append((lb, ld.b, -T * ux, -T * uy))
            springs.append((ld, T, L))
        elif isinstance(ld, Mass):
            mval = val(ld.m)
            forces.append((ld.link, ld.point, 0.0, -mval * g))
            if moving:
                J1 = kin._jet1(ld.point)  # (2, k, m, n)
                J2 = kin._jet2(ld.point)
                acc = (np.einsum("ckmn,mnk->cmn", J1, qdd)
                       + np.einsum("mnk,cklmn,mnl->cmn", qd, J2, qd))
                forces.append((ld.link, ld.point, -mval * acc[0], -mval * acc[1]))
                w1, w2 = _body_angle_jets(kin, ld.link, mech)
                eps = np.einsum("kmn,mnk->mn", w1, qdd) + np.einsum("mnk,klmn,mnl->mn", qd, w2,
                                                                    qd)
                couples.append((ld.link, -val(ld.J) * eps))
    return forces, couples, springs


def virtual_work_forces(kin, qdot=None, qddot=None, g=GRAVITY):
    """Actuator forces by virtual work, ``{coordinate: F}`` with F of shape (m, n).

    ``F_j = −Q_j``, ``Q_j = Σ F·∂r/∂q_j + Σ M·∂φ/∂q_j`` (spring forces enter as the
    point forces of their tension).
    """
    mech = kin.mechanism
    forces, couples, _ = applied_loads(kin, qdot, qddot, g)
    Q = np.zeros((kin.k, kin.m, kin.n))
    for link, pt, fx, fy in forces:
        J = kin._jet1(pt)  # (2, k, m, n)
        Q += fx * J[0] + fy * J[1]
    for link, M in couples:
        w1, _ = _body_angle_jets(kin, link, mech)
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


def solve(kin, qdot=None, qddot=None, g=GRAVITY):
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
    g : float
        Gravity [m/s²] for the masses' weights (weights given in N are used as given).

    Returns
    -------
    Statics
    """
    if kin.n <= BLOCK:
        return _solve(kin, qdot, qddot, g)
    parts = [(_solve(kin._positions(i0, min(kin.n, i0 + BLOCK)),
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


def _solve(kin, qdot, qddot, g):
    """The reverse-order pass over one block of positions."""
    mech = kin.mechanism
    m, n = kin.m, kin.n
    missing = [p for b in mech._bodies.values() for p in b["points"]
               if p not in kin._pidx and p not in kin._frame]
    if missing:
        raise ValueError(f"the kinematics lack points {missing}: solve without `outputs=`")
    forces, couples, _ = applied_loads(kin, qdot, qddot, g)
    zero = np.zeros((m, n))
    W = {b: [0.0, 0.0, 0.0] for b in mech._bodies}  # Fx, Fy, M(origin); arrays once loaded

    at = {}  # (link, point) -> forces applied there, for a cylinder's axial force
    coords_ = set(mech.coordinates)
    rod_ends = set()
    for g_ in mech.groups:
        links_ = mech._group_links.get(g_.name, ())
        if isinstance(g_, (Dyad, CylinderLever)):
            for ref, l_ in ((g_.ra, links_[0]), (g_.rb, links_[1])):
                if isinstance(ref, str) and ref in coords_:
                    rod_ends.add((l_, g_.out))
        elif isinstance(g_, SliderDyad) and isinstance(g_.radius, str) \
                and g_.radius in coords_:
            rod_ends.add((links_[0], g_.out))

    def add_force(body, pt, fx, fy):
        px, py = kin._val(pt)
        w = W[body]
        w[0] = w[0] + fx
        w[1] = w[1] + fy
        w[2] = w[2] + px * fy - py * fx
        if (body, pt) in rod_ends:
            f = at.setdefault((body, pt), [0.0, 0.0])
            f[0] = f[0] + fx
            f[1] = f[1] + fy

    def axial(cyl, end, fx, fy, ux, uy):
        """A cylinder's push from the force (fx, fy) its rod end ``end`` exerts on the
        next link, less what the loads applied at that end to the cylinder take."""
        lx, ly = at.get((cyl, end), (0.0, 0.0))
        return (fx - lx) * ux + (fy - ly) * uy

    for link, pt, fx, fy in forces:
        add_force(link, pt, fx, fy)
    for link, M in couples:
        W[link][2] = W[link][2] + M
    # (add_force rebinds, never mutates, so this keeps the applied loads alone)
    applied = {b: list(w) for b, w in W.items()}

    joints = {}
    act = {}

    def record(i, j, pt, fx, fy, mz=0.0):
        joints[(i, j)] = (pt, np.broadcast_to(fx, (m, n)), np.broadcast_to(fy, (m, n)),
                          np.broadcast_to(mz, (m, n)))

    def about(body, cx, cy):
        """Wrench of a body's loads: (Fx, Fy, moment about point c)."""
        fx, fy, mo = W[body]
        return fx, fy, mo - (cx * fy - cy * fx)

    coords = mech.coordinates
    for g_ in reversed(mech.groups):
        links = mech._group_links.get(g_.name, ())
        if isinstance(g_, (Dyad, CylinderLever)):
            la, lb = links
            A, B, C = g_.a, g_.b, g_.out
            bA, bB = mech.owner(A), mech.owner(B)
            ax, ay = kin._val(A)
            bx, by = kin._val(B)
            cx, cy = kin._val(C)
            full = (m, n)
            args = [np.broadcast_to(np.asarray(v, float), full)
                     for v in (ax, ay, bx, by, cx, cy, *W[la], *W[lb])]
            res = np.empty((6, m, n))
            _dyad_reactions(*args, res)
            rax, ray, rcx, rcy, rbx, rby = res
            record(bA, la, A, rax, ray)
            record(la, lb, C, rcx, rcy)
            record(bB, lb, B, rbx, rby)
            add_force(bA, A, -rax, -ray)
            add_force(bB, B, -rbx, -rby)
            for ref, (px, py), cyl, (fx_, fy_) in ((g_.ra, (ax, ay), la, (rcx, rcy)),
                                                   (g_.rb, (bx, by), lb, (-rcx, -rcy))):
                if isinstance(ref, str) and ref in coords:
                    # the cylinder's rod end C pushes the other link with (fx_, fy_)
                    L = np.hypot(cx - px, cy - py)
                    act[ref] = axial(cyl, C, fx_, fy_, (cx - px) / L, (cy - py) / L)
        elif isinstance(g_, Crank):
            (l,) = links
            if isinstance(g_.radius, str) and g_.radius in coords:
                raise ModelError(f"reactions of crank {g_.name!r} with a variable radius are not "
                                 f"modelled (use the virtual-work forces)")
            P = g_.pivot
            bP = mech.owner(P)
            px, py = kin._val(P)
            fx, fy, mp = about(l, px, py)
            record(bP, l, P, -fx, -fy, -mp)
            add_force(bP, P, fx, fy)
            W[bP][2] = W[bP][2] + mp
            act[g_.angle] = -mp
        elif isinstance(g_, SliderInput):
            (l,) = links
            C = g_.out
            bG = mech.owner(g_.origin)
            cx, cy = kin._val(C)
            beta = _values(kin)(g_.direction)  # per design: shape (m, 1) or scalar
            ux, uy = np.cos(beta), np.sin(beta)
            fx, fy, mc = about(l, cx, cy)
            # guide + drive on the slider: −(fx, fy) at C and −mc
            record(bG, l, C, -fx, -fy, -mc)
            add_force(bG, C, fx, fy)
            W[bG][2] = W[bG][2] + mc
            act[g_.s] = -(fx * ux + fy * uy)
        elif isinstance(g_, SliderDyad):
            la, lb, guide = links
            A, C = g_.a, g_.out
            bA = mech.owner(A)
            ax, ay = kin._val(A)
            cx, cy = kin._val(C)
            # line direction u and normal n
            beta = np.asarray(mech.value_of(g_.direction), float)
            beta = beta[:, None] if beta.ndim == 1 and m > 1 else beta
            if g_.line_link:
                p0, p1 = g_.line_link
                vx = kin._val(p1)[0] - kin._val(p0)[0]
                vy = kin._val(p1)[1] - kin._val(p0)[1]
                th = np.arctan2(vy, vx) + beta
            else:
                th = beta + np.zeros((m, n))
            nx, ny = -np.sin(th), np.cos(th)
            fax, fay, mac = about(la, cx, cy)
            fbx, fby, mbc = about(lb, cx, cy)
            ux, uy = ax - cx, ay - cy
            den = _cross(ux, uy, nx, ny)
            N = (mac - _cross(ux, uy, fax + fbx, fay + fby)) / den
            rax = -fax - fbx - N * nx
            ray = -fay - fby - N * ny
            rcx, rcy = rax + fax, ray + fay
            mg = -mbc
            record(bA, la, A, rax, ray)
            record(la, lb, C, rcx, rcy)
            record(guide, lb, C, N * nx, N * ny, mg)
            add_force(bA, A, -rax, -ray)
            add_force(guide, C, -N * nx, -N * ny)
            W[guide][2] = W[guide][2] - mg
            if isinstance(g_.radius, str) and g_.radius in coords:
                L = np.hypot(cx - ax, cy - ay)
                act[g_.radius] = axial(la, C, rcx, rcy, (cx - ax) / L, (cy - ay) / L)
        elif isinstance(g_, RigidPoint):
            if isinstance(g_.length, str) and g_.length in coords:
                raise ModelError(f"reactions of the telescopic arm {g_.name!r} are not modelled "
                                 f"(use the virtual-work forces)")
        elif isinstance(g_, PosePoint):
            pass
    vw = virtual_work_forces(kin, qdot, qddot, g)

    def residual():
        """Equilibrium of every moving link: applied loads + all joint forces on it
        (computed when asked for: a check, not part of the result)."""
        fres = np.zeros((m, n))
        mres = np.zeros((m, n))
        for b in mech._bodies:
            if b == "0":
                continue
            fx, fy, mo = [np.broadcast_to(a, (m, n)) for a in applied[b]]
            for (i, j), (pt, rx, ry, mz) in joints.items():
                if b not in (i, j):
                    continue
                sg = 1.0 if j == b else -1.0
                px, py = kin._val(pt)
                fx = fx + sg * rx
                fy = fy + sg * ry
                mo = mo + sg * (px * ry - py * rx + mz)
            fres = np.maximum(fres, np.hypot(fx, fy))
            mres = np.maximum(mres, np.abs(mo))
        return fres, mres

    return Statics(kin, vw, joints, act, residual, [])
