"""Random assemblable mechanisms and the checks of their analogs (the property tests
of :mod:`tests.core.test_kinematics`, whose docstring describes the checks and their
tolerances; the builders serve the kinetostatics, dynamics and group tests too)."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from hypothesis import HealthCheck, Phase, assume, settings, target
from hypothesis import strategies as st

from assur import Mechanism
from assur.groups import Crank, CylinderLever, DoubleSliderDyad, Dyad, Frame, PosePoint, \
    RigidPoint, SleeveDyad, SliderDyad, SliderInput
from tests.helpers import TARGETING, examples


#: complex step [m or rad]
H_CS = 1e-30



#: relative tolerance of first- and second-order analogs (see the module docstring)
RTOL = 1e-7



#: closure / position tolerance [m]
CLOSURE_TOL = 1e-9



#: smallest |sin μ| of an RRR dyad (|cos γ| of an RRP dyad, |s|/|a–b| of an RPR dyad, |sin|
#: of the angle between the lines of a PRP dyad) at a checked position
MARGIN = 0.05



#: finite-difference step of the second-order check relative to the length over
#: which the analogs change (at most the coordinate's scale), see fd_steps
H_REL = 1e-4



# no "explain" phase: it re-runs hundreds of variants, and each new mechanism
# structure is a new kernel to compile; the hill-climb towards the worst error ratio
# (Phase.target, ~120 more examples per test) in the "deep" profile only (TARGETING)
SETTINGS = settings(max_examples=examples(200), deadline=None,
                    phases=[Phase.explicit, Phase.reuse, Phase.generate]
                    + ([Phase.target] if TARGETING else []) + [Phase.shrink],
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])



def _floats(lo, hi):
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False)



def _rot(v, beta):
    """Rotate vectors v (..., 2) by beta (broadcastable to v[..., 0])."""
    c, s = np.cos(beta), np.sin(beta)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)



def _norm(v):
    return np.hypot(v[..., 0], v[..., 1])



def _ang(v):
    return np.arctan2(v[..., 1], v[..., 0])



def _dir(beta):
    return np.stack([np.cos(beta), np.sin(beta)], -1)



# ---------------------------------------------------------------------------------
# random mechanisms built from a reference pose
# ---------------------------------------------------------------------------------
class Builder:
    """Draws a random mechanism and the reference pose it assembles at.

    Every drawn quantity is an array over the ``M`` designs (``M = 1`` for a single
    design); ``pos`` holds the reference position (M, 2) of every point, ``q0`` the
    reference value of every coordinate. Discrete choices (branches, structure) are
    the caller's, so all designs of a batch share one structure.
    """

    def __init__(self, data, name, coordinates):
        self.data = data
        self.name = name
        self.coordinates = tuple(coordinates)
        self.batch = data.draw(st.booleans(), label="batch")
        self.M = data.draw(st.integers(1, 3), label="designs") if self.batch else 1
        self.n = data.draw(st.integers(1, 4), label="positions around the reference")
        self.params = {}
        self.calls = []
        self.pos = {}
        self.q0, self.spread, self.scale = {}, {}, {}

    # drawing ------------------------------------------------------------------------
    def draw(self, lo, hi, label):
        """One value per design in [lo, hi], shape (M,)."""
        return np.array(self.data.draw(st.lists(_floats(lo, hi), min_size=self.M,
                                                max_size=self.M), label=label))

    def branch(self, label="branch"):
        return self.data.draw(st.sampled_from((1, -1)), label=label)

    # parameters, groups ------------------------------------------------------------------
    def par(self, name, value):
        value = np.asarray(value, dtype=float)
        self.params[name] = value.copy() if self.batch else float(value[0])
        return name

    def add(self, method, *args, **kw):
        self.calls.append((method, args, kw))

    def coordinate(self, name, q0, spread, scale):
        """Reference value, sampling half-width and scale (for the FD step), each (M,)."""
        one = np.ones(self.M)
        self.q0[name], self.spread[name], self.scale[name] = q0 * one, spread * one, scale * one

    def link(self, name, tail, head):
        self.add("link", name, tail, head)

    def distance(self, name, a, b):
        self.add("distance", name, a, b)

    def frame(self, name, xy):
        self.pos[name] = xy
        self.add("frame", name, x=self.par("X" + name, xy[:, 0]), y=self.par("Y" + name, xy[:, 1]))

    def frame_random(self, name):
        self.frame(name, np.stack([self.draw(-1.0, 1.0, f"x{name}"),
                                   self.draw(-1.0, 1.0, f"y{name}")], -1))

    def frame_near(self, name, ref, rmin, rmax):
        """A frame point at distance [rmin, rmax] from the reference position of ``ref``."""
        th = self.draw(-math.pi, math.pi, f"direction to {name}")
        rho = self.draw(rmin, rmax, f"distance to {name}")
        self.frame(name, self.pos[ref] + rho[:, None] * _dir(th))

    def place(self, a, b, sigma, label):
        """Reference position of a dyad joint on side ``sigma`` of the line a → b.

        Returns (C, |C−a|, |C−b|). With α ∈ [−0.3, 1.3] along and β ∈ [0.25, 1.2]
        across (in units of |ab|), |sin μ| > 0.45 at the reference pose.
        """
        A, B = self.pos[a], self.pos[b]
        d = B - A
        alpha = self.draw(-0.3, 1.3, f"{label} along")
        beta = self.draw(0.25, 1.2, f"{label} across")
        perp = np.stack([-d[:, 1], d[:, 0]], -1)
        C = A + alpha[:, None] * d + sigma * beta[:, None] * perp
        return C, _norm(C - A), _norm(C - B)

    # groups drawn at the reference pose ----------------------------------------------------
    def crank(self, pivot, out, coord, radius_coord=None):
        """Crank (angle ``coord``, ±1 rad around the reference); its radius may be the
        coordinate ``radius_coord`` (±20 %)."""
        r = self.draw(0.1, 0.5, "crank radius")
        th0 = self.draw(-math.pi, math.pi, "crank angle at the reference pose")
        phase = self.draw(-math.pi, math.pi, "crank phase")
        self.pos[out] = self.pos[pivot] + r[:, None] * _dir(th0)
        if radius_coord:
            self.coordinate(radius_coord, r, 0.2 * r, r)
        self.add("crank", "crank", pivot=pivot, out=out,
                 radius=radius_coord or self.par("R" + out, r), q=coord,
                 phase=self.par("phase", phase), links=("1",))
        self.coordinate(coord, th0 - phase, 1.0, 1.0)

    def cylinder_lever(self, base, pivot, out, coord, sigma):
        """Cylinder–lever group, cylinder length ``coord`` (±25 % around the reference)."""
        C, s0, lever = self.place(base, pivot, sigma, "lever end")
        self.pos[out] = C
        self.add("cylinder_lever", "cylinder-lever", base=base, pivot=pivot, out=out,
                 lever=self.par("L" + out, lever), s=coord, branch=sigma, links=("2", "3"))
        self.coordinate(coord, s0, 0.25 * s0, s0)

    def dyad(self, name, a, b, out, sigma, ra=None, rb=None):
        """RRR dyad placed at the reference pose; ``ra``/``rb`` given as a coordinate
        name make that radius the coordinate (±20 %)."""
        C, la, lb = self.place(a, b, sigma, f"joint {out}")
        self.pos[out] = C
        for ref, val in ((ra, la), (rb, lb)):
            if ref is not None:
                self.coordinate(ref, val, 0.2 * val, val)
        self.add("dyad", name, a=a, b=b, out=out, ra=ra or self.par(f"ra{out}", la),
                 rb=rb or self.par(f"rb{out}", lb), branch=sigma, links=(name + "a", name + "b"))

    def slider_input(self, origin, out, coord):
        """Slider along a fixed line through ``origin``; travel s + offset ∈ [0.5, 1] m
        at the reference pose, s ± 0.3 m around it."""
        t0 = self.draw(0.5, 1.0, "slider travel at the reference pose")
        off = self.draw(-0.3, 0.3, "slider offset")
        beta = self.draw(-math.pi, math.pi, "slider direction")
        self.pos[out] = self.pos[origin] + t0[:, None] * _dir(beta)
        self.add("slider_input", "slider", origin=origin, out=out, s=coord,
                 offset=self.par("off", off), direction=self.par("dir", beta), links=("1",))
        self.coordinate(coord, t0 - off, 0.3, t0)

    def _unit(self, p, q, beta):
        d = self.pos[q] - self.pos[p]
        return _rot(d, beta) / _norm(d)[:, None]

    def rigid_angle(self, name, origin, toward, out, length_coord=None):
        """Rigid point by length and angle; its length may be a coordinate (±20 %)."""
        ell = self.draw(0.1, 1.0, f"|{origin}–{out}|")
        beta = self.draw(-math.pi, math.pi, f"angle of {out}")
        self.pos[out] = self.pos[origin] + ell[:, None] * self._unit(origin, toward, beta)
        if length_coord:
            self.coordinate(length_coord, ell, 0.2 * ell, ell)
        self.add("rigid_point", name, origin=origin, toward=toward, out=out,
                 length=length_coord or self.par("l" + out, ell), angle=self.par("b" + out, beta),
                 )

    def rigid_triangle(self, name, origin, toward, out, tau):
        """Rigid point by the three sides of its triangle, turn side ``tau``; the angle
        at ``origin`` is kept in [0.3, π − 0.3] (a proper triangle)."""
        base = _norm(self.pos[toward] - self.pos[origin])
        ell = self.draw(0.15, 1.0, f"|{origin}–{out}|")
        gam = self.draw(0.3, math.pi - 0.3, f"angle at {origin}")
        opp = np.sqrt(base * base + ell * ell - 2 * base * ell * np.cos(gam))
        self.pos[out] = self.pos[origin] + ell[:, None] * self._unit(origin, toward, tau * gam)
        self.add("rigid_point", name, origin=origin, toward=toward, out=out,
                 length=self.par("l" + out, ell), base=self.par("base" + out, base),
                 opposite=self.par("opp" + out, opp), branch=tau)

    def slider_dyad(self, name, a, out, line_point, sigma, beta, line_link=None,
                    radius_coord=None):
        """RRP dyad at the reference pose: its joint ``out`` on the line through
        ``line_point`` with u·(out − a) = σκ, κ ∈ [0.2, 0.8] (so ``branch = σ``)."""
        u = self._unit(*line_link, beta) if line_link else _dir(beta)
        L0, A = self.pos[line_point], self.pos[a]
        kappa = self.draw(0.2, 0.8, f"{out} along the line from the foot of {a}")
        t = (u * (A - L0)).sum(-1) + sigma * kappa
        self.pos[out] = L0 + t[:, None] * u
        r = _norm(self.pos[out] - A)
        if radius_coord:
            self.coordinate(radius_coord, r, 0.2 * r, r)
        self.add("slider_dyad", name, a=a, out=out, radius=radius_coord or self.par("r" + out, r),
                 line_point=line_point, direction=self.par("beta" + out, beta),
                 line_link=line_link, branch=sigma, links=(name + "r", name + "s"))

    def rpr_dyad(self, name, a, b, out, sigma):
        """RPR dyad (rod pinned at ``a`` through a sleeve pivoted at ``b``) at the
        reference pose: B − A is the rod's direction û turned by ψ ∈ [−1.1, 1.1] rad,
        so the slide s = (B − A)·û = σ|AB|cos ψ (|s|/|AB| > 0.45, sign σ = ``branch``)
        and the offset e = û × (B − A) = |AB| sin ψ (B on the left of û for e > 0);
        ``out`` at ℓ ∈ [0.3, 1.5]·|AB| along û."""
        A, B = self.pos[a], self.pos[b]
        w = B - A
        D = _norm(w)
        psi = self.draw(-1.1, 1.1, f"{name}: angle of the sleeve off the rod")
        ell = self.draw(0.3, 1.5, f"{name}: |{a}–{out}| / |{a}–{b}|") * D
        e = D * np.sin(psi)
        s = sigma * D * np.cos(psi)
        # B − A = s·û + e·R90(û) is û turned by atan2(e, s)
        u = _rot(w, -np.arctan2(e, s)) / D[:, None]
        self.pos[out] = A + ell[:, None] * u
        self.add("rpr_dyad", name, a=a, b=b, out=out, length=self.par("l" + out, ell),
                 offset=self.par("e" + out, e), branch=sigma, links=(name + "r", name + "s"))

    def prp_dyad(self, name, a, out, b_frame, line_link_a=None, side="a"):
        """PRP dyad at the reference pose: line a through the known point ``a`` at the
        absolute angle θa (drawn; with ``line_link_a = (P, Q)`` its ``direction_a`` is
        θa − angle(P→Q)), the pin ``out`` at τ ∈ ±[0.2, 1] m along it, line b through
        ``out`` at θb = θa ± [0.5, π − 0.5] (|sin| of the angle between the lines >
        0.47) and a new frame point ``b_frame`` on line b at ±[0.2, 1] m from
        ``out``. ``side="b"`` swaps the roles in the group: the known point's line is
        its line b (``line_link_b``), the frame point's its line a."""
        A = self.pos[a]
        tha = self.draw(-math.pi, math.pi, f"{name}: angle of line a")
        delta = self.draw(0.5, math.pi - 0.5, f"{name}: angle between the lines")
        sgn = np.where(self.draw(-1.0, 1.0, f"{name}: side of line b") < 0, -1.0, 1.0)
        thb = tha + sgn * delta
        tau = self.draw(0.2, 1.0, f"{name}: |{a}–{out}|") * np.where(
            self.draw(-1.0, 1.0, f"{name}: sign along line a") < 0, -1.0, 1.0)
        C = A + tau[:, None] * _dir(tha)
        self.pos[out] = C
        rho = self.draw(0.2, 1.0, f"{name}: |{b_frame}–{out}|") * np.where(
            self.draw(-1.0, 1.0, f"{name}: sign along line b") < 0, -1.0, 1.0)
        self.frame(b_frame, C + rho[:, None] * _dir(thb))
        beta_a = tha
        if line_link_a:
            P, Q = (self.pos[x] for x in line_link_a)
            beta_a = tha - _ang(Q - P)
        if side == "a":
            self.add("prp_dyad", name, a=a, b=b_frame, out=out,
                     direction_a=self.par("dira" + out, beta_a),
                     direction_b=self.par("dirb" + out, thb),
                     line_link_a=line_link_a, links=(name + "a", name + "b"))
        else:
            self.add("prp_dyad", name, a=b_frame, b=a, out=out,
                     direction_a=self.par("dira" + out, thb),
                     direction_b=self.par("dirb" + out, beta_a),
                     line_link_b=line_link_a, links=(name + "a", name + "b"))

    def pose_point(self, name, origin, toward, out, coord):
        """Point fixed to the link origin→toward by its offset at the reference pose."""
        rho = self.draw(0.1, 0.9, f"|{origin}–{out}|")
        th = self.draw(-math.pi, math.pi, f"direction {origin}→{out} at the pose")
        off = rho[:, None] * _dir(th)
        self.pos[out] = self.pos[origin] + off
        self.add("pose_point", name, origin=origin, toward=toward, out=out,
                 dx=self.par("dx" + out, off[:, 0]), dy=self.par("dy" + out, off[:, 1]),
                 at=self.par("pose", self.q0[coord]))

    def input(self, kind, coord, sigma=-1):
        """A crank (frame A0, end A) or a cylinder–lever (frames 01, 03, lever end 23)
        input; returns the (pivot, end) of its moving link."""
        if kind == "crank":
            self.frame_random("A0")
            self.crank("A0", "A", coord)
            return "A0", "A"
        self.frame_random("01")
        self.frame_near("03", "01", 0.2, 1.0)
        self.cylinder_lever("01", "03", "23", coord, sigma)
        return "03", "23"

    def fourbar(self, coord, sigma=1):
        """Crank A0–A and RRR dyad (A, B0) → C: the coupler is A–C, the rocker B0–C."""
        self.input("crank", coord)
        self.frame_near("B0", "A", 0.4, 1.2)
        self.dyad("II", "A", "B0", "C", sigma)

    def build(self):
        m = Mechanism(self.name, coordinates=self.coordinates, params=self.params)
        for method, args, kw in self.calls:
            m = getattr(m, method)(*args, **kw)
        k = len(self.coordinates)
        q0 = np.stack([self.q0[c] for c in self.coordinates], -1)  # (M, k)
        size = self.M * self.n * k
        u = np.array(self.data.draw(st.lists(_floats(-1.0, 1.0), min_size=size, max_size=size),
                                    label="position offsets")).reshape(self.M, self.n, k)
        spread = np.stack([self.spread[c] for c in self.coordinates], -1)[:, None, :]
        # position 0 of every design is the reference pose itself
        Q = np.concatenate([q0[:, None, :], q0[:, None, :] + u * spread], axis=1)
        scale = np.stack([self.scale[c] for c in self.coordinates], -1)
        return Case(m, self, Q, q0, scale)



# ---------------------------------------------------------------------------------
# the checks
# ---------------------------------------------------------------------------------
@dataclass
class Case:
    mech: Mechanism
    b: Builder
    Q: np.ndarray  # (M, n, k) positions; Q[:, 0] is the reference pose
    q0: np.ndarray  # (M, k) reference pose
    scale: np.ndarray  # (M, k) scale of each coordinate (1 rad, or the reference length)

    @property
    def k(self):
        return self.Q.shape[-1]

    def api_q(self, Q):
        """Coordinates as solve() takes them: (n,)/(n, k) single, (m, n)/(m, n, k) batch."""
        Q = Q if self.k > 1 else Q[..., 0]
        return Q if self.b.batch else Q[0]

    def solve(self):
        return self.mech.solve(self.api_q(self.Q), on_failure="report", check_continuity=False)

    def shaped(self, a, tail=0):
        """Result array, shape (+ tail) → (M, n, *tail)."""
        a = np.asarray(a)
        return a.reshape(self.Q.shape[:2] + a.shape[a.ndim - tail:])

    def val(self, ref):
        """Value of a reference, broadcastable to (M, n)."""
        if isinstance(ref, str) and ref in self.mech.coordinates:
            return self.Q[..., self.mech.coordinates.index(ref)]
        if isinstance(ref, str):
            return np.asarray(self.mech.params[ref], dtype=float).reshape(-1, 1)
        return float(ref)

    def reproducer(self):
        def arr(v):
            return repr(np.asarray(v).tolist())

        lines = ["import numpy as np", "from assur import Mechanism",
                 "params = {" + ", ".join(f"{k!r}: {arr(v)}" for k, v in self.mech.params.items())
                 + "}",
                 f"m = Mechanism({self.mech.name!r}, coordinates={self.mech.coordinates!r}, "
                 "params=params)"]
        for method, args, kw in self.b.calls:
            a = [repr(x) for x in args] + [f"{k}={v!r}" for k, v in kw.items()]
            lines.append(f"m = m.{method}({', '.join(a)})")
        lines.append(f"q = np.array({arr(self.api_q(self.Q))})")
        lines.append("r = m.solve(q, on_failure='report', check_continuity=False)")
        return "\n".join(lines)



def _point(case, r, p):
    return np.stack([case.shaped(r.x(p)), case.shaped(r.y(p))], -1)  # (M, n, 2)



def _jac(case, a):
    """First-order analog (shape [+ (k,)]) → (M, n, k)."""
    return case.shaped(a[..., None] if case.k == 1 else a, 1)



def _hess(case, a):
    """Second-order analog (shape [+ (k, k)]) → (M, n, k, k)."""
    return case.shaped(a[..., None, None] if case.k == 1 else a, 2)



#: families of analogs compared on a common scale: lengths (point coordinates and
#: named distances) and angles
FAMILIES = ("length", "angle")



def analogs(case, r, accessors=False):
    """Kernel analogs as {family: (labels, J (M, n, N, k), H (M, n, N, k, k))}."""
    rows = {f: ([], [], []) for f in FAMILIES}

    def put(fam, label, J, H):
        rows[fam][0].append(label)
        rows[fam][1].append(J)
        rows[fam][2].append(H)

    for p in case.mech.points:
        put("length", f"X{p}", _jac(case, r.dx(p)), _hess(case, r.ddx(p)))
        put("length", f"Y{p}", _jac(case, r.dy(p)), _hess(case, r.ddy(p)))
        if accessors:  # the single-coordinate accessors agree with the full arrays
            for j, c in enumerate(case.mech.coordinates):
                assert np.array_equal(case.shaped(r.dx(p, wrt=c)), rows["length"][1][-2][..., j])
                assert np.array_equal(case.shaped(r.ddy(p, wrt=c)),
                                      rows["length"][2][-1][..., j, j])
    for d in case.mech.distances:
        put("length", d.name, _jac(case, r.dlength(d.name)), _hess(case, r.ddlength(d.name)))
    for l in case.mech.links:
        put("angle", "phi" + l.name, _jac(case, r.dphi(l.name)), _hess(case, r.ddphi(l.name)))
    return {f: (lab, np.stack(J, 2), np.stack(H, 2)) for f, (lab, J, H) in rows.items() if lab}



def complex_step(case):
    """Reference first-order analogs {family: (labels, J (M, n, N, k))} by complex step
    of evaluate_positions, in the same order as :func:`analogs`."""
    mech = case.mech
    over = {k: np.asarray(v)[:, None] for k, v in mech.params.items()} if case.b.batch else {}
    shape = case.Q.shape[:2]
    cols = {f: ([], []) for f in FAMILIES}
    for j, c in enumerate(mech.coordinates):
        q = {cc: case.Q[..., jj].astype(complex) for jj, cc in enumerate(mech.coordinates)}
        q[c] = q[c] + 1j * H_CS
        pts = mech.evaluate_positions(q, over)

        def P(p):
            return [np.broadcast_to(np.asarray(v, dtype=complex), shape) for v in pts[p]]

        out = {f: [] for f in FAMILIES}
        labels = {f: [] for f in FAMILIES}
        for p in mech.points:
            x, y = P(p)
            out["length"] += [x.imag / H_CS, y.imag / H_CS]
            labels["length"] += [f"X{p}", f"Y{p}"]
        for d in mech.distances:
            (ax, ay), (bx, by) = P(d.a), P(d.b)
            out["length"].append(np.sqrt((bx - ax) ** 2 + (by - ay) ** 2).imag / H_CS)
            labels["length"].append(d.name)
        for l in mech.links:
            (tx, ty), (hx, hy) = P(l.tail), P(l.head)
            dx, dy = hx - tx, hy - ty
            # φ = arctan(Δy/Δx) + const where |Δx| >= |Δy|, else −arctan(Δx/Δy) + const
            use_x = np.abs(dx.real) >= np.abs(dy.real)
            ratio = np.where(use_x, dy, dx) / np.where(use_x, dx, dy)
            out["angle"].append(np.where(use_x, 1.0, -1.0) * np.arctan(ratio).imag / H_CS)
            labels["angle"].append("phi" + l.name)
        for f in FAMILIES:
            if out[f]:
                cols[f][0][:] = labels[f]
                cols[f][1].append(np.stack(out[f], 2))  # (M, n, N)
    return {f: (lab, np.stack(J, -1)) for f, (lab, J) in cols.items() if lab}



def fd_steps(case, kern):
    """Finite-difference step per element and coordinate, (M, n, k).

    ``h_j = H_REL · min(c_j, ρ_j)``: ``c_j`` the coordinate's scale (1 rad for a crank
    angle, its reference value for a length) and ``ρ_j`` the length in q_j over which
    the first-order analogs change by their own size, ``ρ_j = |J|/|∂J/∂q_j|``, the
    largest |J| and |∂J/∂q_j| of any family (lengths or angles) in the coordinates'
    units. Near an
    assembly limit the analogs behave like √(q − q*) and ρ ≈ 2|q − q*| shrinks
    even at a fair transmission angle (short links), so a fixed step would not do.
    The kernel's Hessian only *sizes* the step here: a wrong one makes the step
    smaller (more rounding) or the default, never the reference equal to it.
    """
    c = case.scale[:, None, :]  # (M, 1, k)
    s1 = np.zeros(case.Q.shape[:2])  # (M, n): the largest |J| of any family
    s2 = np.zeros(case.Q.shape)      # (M, n, k): the largest |∂J/∂q_j| of any family
    for _, J, H in kern.values():
        s1 = np.maximum(s1, (np.abs(J).max(axis=2) * c).max(axis=-1))  # in family units
        s2 = np.maximum(s2, (np.abs(H).max(axis=2) * c[..., None]).max(axis=-2))
    # ρ from the largest analogs of any family, not family by family: a link at a
    # stationary angle (φ' ≈ 0, φ'' ≠ 0) has |J|/|H| ≈ 0 with nothing singular about
    # it, and a step that small (5e-10 rad) lets rounding (ε·|J|/h ≈ 1e-7) exceed the
    # tolerance; near an assembly limit the singular family has the largest |H|, and a
    # ρ even 10× too large keeps the fourth-order truncation (h/ρ)⁴ below 1e-12.
    # A Hessian of rounding size (a denormal drawn angle) sets no step.
    with_h = s2 > 1e-200 * np.maximum(s1[..., None], 1.0)
    rho = np.where(with_h, s1[..., None] / np.where(with_h, s2, 1.0), np.inf)
    return H_REL * np.minimum(c, rho)



def fd_hessian(case, h):
    """Hessians {family: (M, n, N, k, k)} by central differences of the kernel's
    first-order analogs (last axis: the coordinate differentiated by), steps ``h``
    (M, n, k) from :func:`fd_steps`.

    Fourth-order central difference (Richardson extrapolation of the central
    differences with steps h and 2h):
    ``(8·[J(q+h) − J(q−h)] − [J(q+2h) − J(q−2h)]) / (12 h)``.
    With h = 1e-4·ρ (ρ the analogs' own length of change, see fd_steps) its
    truncation error is ~(h/ρ)⁴ ~ 1e-16 and its rounding error ~ε·ρ/h ~ 1e-12 of
    the Hessian's size, far below the 1e-7 tolerance. (The plain central
    difference, error (h/ρ)²/6, would need h ~ 1e-5·ρ and then lose ~1e-11 to
    rounding — also fine, but with less margin; near a dead point ρ ≪ 1.)
    All 4k neighbours of all positions are solved in one batch.
    """
    M, n, k = case.Q.shape
    steps = (1, -1, 2, -2)
    Qn = np.repeat(case.Q[:, None], 4 * k, axis=1)  # (M, 4k, n, k)
    for j in range(k):
        for si, s in enumerate(steps):
            Qn[:, 4 * j + si, :, j] += s * h[:, :, j]
    nb = replace(case, Q=Qn.reshape(M, 4 * k * n, k))
    r = nb.solve()
    assert r.ok.all(), (f"a neighbour at ±h, ±2h of a checked position does not assemble: "
                        f"{r.failures[:1]}\n{case.reproducer()}")
    out = {}
    for f, (_, J, _) in analogs(nb, r).items():
        J = J.reshape((M, k, 4, n) + J.shape[2:])  # (M, j, step, n, N, i)
        cols = [(8 * (J[:, j, 0] - J[:, j, 1]) - (J[:, j, 2] - J[:, j, 3]))
                / (12 * h[:, :, j, None, None]) for j in range(k)]
        out[f] = np.stack(cols, -1)
    return out



def compare(case, what, labels, a, b, weight, floor=0.0):
    """Assert |a − b| <= RTOL·scale, a and b of shape (M, n, N, *comp).

    ``scale`` per design and component: the largest of |b| of the component, of
    |b·weight| over all components / weight of the component, and ``floor``
    (M, *comp); ``weight`` (M, *comp) brings each component to the family's units
    (products of the coordinates' scales). Returns the worst err/tol.
    """
    ncomp = a.ndim - 3
    w = weight[(slice(None), None, None) + (slice(None),) * ncomp]
    absb = np.abs(b)
    own = absb.max(axis=(1, 2), keepdims=True)
    common = (absb * w).max(axis=tuple(range(1, a.ndim)), keepdims=True)
    floor = np.asarray(floor, dtype=float)
    if floor.ndim:
        floor = floor[(slice(None), None, None) + (slice(None),) * ncomp]
    scale = np.maximum(np.maximum(own, common / w), floor)
    tol = np.broadcast_to(RTOL * np.maximum(scale, 1e-300), a.shape)
    err = np.abs(a - b)
    ratio = err / tol
    if not (err <= tol).all():
        idx = np.unravel_index(np.argmax(ratio), ratio.shape)
        comp = [case.mech.coordinates[c] for c in idx[3:]]
        raise AssertionError(
            f"{what} d/d{'d'.join(comp)} of {labels[idx[2]]} disagrees at design {idx[0]}, "
            f"position {idx[1]} (q = {case.Q[idx[0], idx[1]].tolist()}): kernel {a[idx]!r}, "
            f"reference {b[idx]!r}, |diff| = {err[idx]:.3g} > tol {tol[idx]:.3g}\n"
            f"reproducer:\n{case.reproducer()}")
    return float(ratio.max())



def margins(case, r):
    """Smallest conditioning measure over the dyads at every element, (M, n)."""
    out = np.full(case.Q.shape[:2], np.inf)
    for g in case.mech.groups:
        if isinstance(g, (Dyad, CylinderLever)):
            out = np.minimum(out, np.abs(np.sin(case.shaped(r.transmission_angle(g.name)))))
        elif isinstance(g, SliderDyad):
            u = _line_dir(case, r, g)
            w = _point(case, r, g.out) - _point(case, r, g.a)
            # (a non-assembled element has w = 0: margin 0)
            out = np.minimum(out, np.abs((u * w).sum(-1)) / np.maximum(_norm(w), 1e-300))
        elif isinstance(g, SleeveDyad):
            # slide |s| = |(B − A)·û| over |A–B|, û along the rod A → out
            w = _point(case, r, g.b) - _point(case, r, g.a)
            u = _point(case, r, g.out) - _point(case, r, g.a)
            out = np.minimum(out, np.abs((u * w).sum(-1)) / np.maximum(_norm(u) * _norm(w),
                                                                       1e-300))
        elif isinstance(g, DoubleSliderDyad):
            # |sin| of the angle between the two lines
            ua, ub = _prp_dirs(case, r, g)
            out = np.minimum(out, np.abs(ua[..., 0] * ub[..., 1] - ua[..., 1] * ub[..., 0]))
    return out



def _line_of(case, r, direction, line_link):
    """Unit direction (M, n, 2) of a line: ``direction`` from +x, or turned from the
    direction P → Q of ``line_link = (P, Q)`` (solved points)."""
    beta = np.broadcast_to(case.val(direction), case.Q.shape[:2])
    if line_link:
        d = _point(case, r, line_link[1]) - _point(case, r, line_link[0])
        return _rot(d, beta) / _norm(d)[..., None]
    return _dir(beta)



def _prp_dirs(case, r, g):
    """Unit directions of the two lines of a PRP dyad."""
    return (_line_of(case, r, g.direction_a, g.line_link_a),
            _line_of(case, r, g.direction_b, g.line_link_b))



def _line_dir(case, r, g):
    beta = np.broadcast_to(case.val(g.direction), case.Q.shape[:2])
    if g.line_link:
        d = _point(case, r, g.line_link[1]) - _point(case, r, g.line_link[0])
        return _rot(d, beta) / _norm(d)[..., None]
    return _dir(beta)



def check_closure(case, r):
    """Closure residuals, every group's constraints, links, distances, reference pose."""
    mech = case.mech
    shape = case.Q.shape[:2]
    res = case.shaped(r.closure_residual())
    assert (res <= CLOSURE_TOL).all(), f"closure residual {res.max():.3g} m\n{case.reproducer()}"
    P = {p: _point(case, r, p) for p in mech.points}
    errs = {}

    def dist(a, b):
        return _norm(P[b] - P[a])

    def v(ref):
        return np.broadcast_to(case.val(ref), shape)

    def offset(origin, toward, length, beta):
        d = P[toward] - P[origin]
        return P[origin] + v(length)[..., None] * _rot(d, beta) / _norm(d)[..., None]

    for g in mech.groups:
        if isinstance(g, Frame):
            errs[g.name] = _norm(P[g.name] - np.stack([v(g.x), v(g.y)], -1))
        elif isinstance(g, (Dyad, CylinderLever)):
            errs[g.name] = np.maximum(np.abs(dist(g.a, g.out) - v(g.ra)),
                                      np.abs(dist(g.b, g.out) - v(g.rb)))
        elif isinstance(g, Crank):
            want = P[g.pivot] + v(g.radius)[..., None] * _dir(v(g.q) + v(g.phase))
            errs[g.name] = _norm(P[g.out] - want)
        elif isinstance(g, SliderInput):
            want = P[g.origin] + (v(g.s) + v(g.offset))[..., None] * _dir(v(g.direction))
            errs[g.name] = _norm(P[g.out] - want)
        elif isinstance(g, RigidPoint):
            if g.angle is not None:
                beta = v(g.angle)
            else:
                bb, ll, oo = v(g.base), v(g.length), v(g.opposite)
                beta = g.branch * np.arccos((bb * bb + ll * ll - oo * oo) / (2 * bb * ll))
                # third side (origin and toward are joints of one link of length ``base``)
                errs[g.name + " (opposite side)"] = np.abs(dist(g.toward, g.out) - oo)
            errs[g.name] = _norm(P[g.out] - offset(g.origin, g.toward, g.length, beta))
        elif isinstance(g, SliderDyad):
            u = _line_dir(case, r, g)
            w = P[g.out] - P[g.line_point]
            errs[g.name + " (on its line)"] = np.abs(u[..., 0] * w[..., 1] - u[..., 1] * w[..., 0])
            errs[g.name] = np.abs(dist(g.a, g.out) - v(g.radius))
        elif isinstance(g, SleeveDyad):
            # the rod A → out has length ℓ; B is at the signed distance e from its line
            # (û × (B − A) = e, B on the left for e > 0) and ahead of A along û for
            # branch +1 (behind for −1): σ·(B − A)·û > 0
            u = (P[g.out] - P[g.a]) / dist(g.a, g.out)[..., None]
            w = P[g.b] - P[g.a]
            errs[g.name] = np.abs(dist(g.a, g.out) - v(g.length))
            errs[g.name + " (sleeve offset)"] = np.abs(u[..., 0] * w[..., 1]
                                                       - u[..., 1] * w[..., 0] - v(g.offset))
            assert (g.branch * (u * w).sum(-1) > 0).all(), \
                f"{g.name}: the sleeve is on the wrong side of the rod's pin\n{case.reproducer()}"
        elif isinstance(g, DoubleSliderDyad):
            # out on line a through a and on line b through b
            for p, u in zip((g.a, g.b), _prp_dirs(case, r, g)):
                w = P[g.out] - P[p]
                errs[f"{g.name} (on the line through {p})"] = np.abs(u[..., 0] * w[..., 1]
                                                                     - u[..., 1] * w[..., 0])
        elif isinstance(g, PosePoint):
            # fixed to the link origin→toward at its offset of the reference pose
            o, t, c = (case.b.pos[x][:, None] for x in (g.origin, g.toward, g.out))
            d = P[g.toward] - P[g.origin]
            want = P[g.origin] + _norm(c - o)[..., None] * _rot(
                d, _ang(c - o) - _ang(t - o)) / _norm(d)[..., None]
            errs[g.name] = _norm(P[g.out] - want)
    for l in mech.links:
        d = P[l.head] - P[l.tail]
        e = np.angle(np.exp(1j * (case.shaped(r.phi(l.name)) - _ang(d))))
        errs["link " + l.name] = np.abs(e) * _norm(d)  # as a displacement of its head [m]
    for dd in mech.distances:
        errs["distance " + dd.name] = np.abs(case.shaped(r.length(dd.name)) - dist(dd.a, dd.b))
    # at the reference pose (position 0) every point is where it was constructed
    for p in mech.points:
        errs["reference position of " + p] = _norm(P[p][:, 0] - case.b.pos[p])
    for what, e in errs.items():
        assert (e <= CLOSURE_TOL).all(), (f"{what}: residual {e.max():.3g} m > {CLOSURE_TOL} m"
                                          f"\n{case.reproducer()}")



def check(case):
    """All checks on one random mechanism (see the module docstring)."""
    r = case.solve()
    good = r.ok.reshape(case.Q.shape[:2])
    assert good[:, 0].all(), f"the reference pose does not assemble\n{case.reproducer()}"
    good &= margins(case, r) >= MARGIN
    assume(good[:, 0].all())  # rare: a reference pose closer than MARGIN to a dead point
    if not good.all():
        # positions that fail or are near a dead point: replaced by the reference pose
        case.Q = np.where(good[..., None], case.Q, case.q0[:, None, :])
        r = case.solve()
        assert r.ok.all()
    check_closure(case, r)
    kern = analogs(case, r, accessors=True)
    # 1. first order against the complex step
    w1 = 0.0
    for f, (labels, J) in complex_step(case).items():
        assert labels == kern[f][0]
        w1 = max(w1, compare(case, "first-order analog", labels, kern[f][1], J, case.scale))
    # 2. second order against central differences of the kernel's first order
    w2 = 0.0
    weight2 = case.scale[:, :, None] * case.scale[:, None, :]
    for f, H in fd_hessian(case, fd_steps(case, kern)).items():
        # a second-order analog's magnitude is at least that of the first-order analogs
        # per unit (scale) of coordinate: φ'' ~ φ'/(1 rad) — this also covers a family
        # whose Hessian vanishes (e.g. φ = −θ exactly), where only FD noise is left
        J = np.abs(kern[f][1]) * case.scale[:, None, None, :]
        floor = J.max(axis=(1, 2, 3))[:, None, None] / weight2
        w2 = max(w2, compare(case, "second-order analog", kern[f][0], kern[f][2], H, weight2,
                             floor))
    target(w1, label="first order: max |error| / tolerance")
    target(w2, label="second order: max |error| / tolerance")



def cylinder_dyad_family(data, kind):
    """k = 2: a crank (th) or cylinder–lever (S) input and an RRR dyad II whose radius
    is the second coordinate S2 (crank: its first radius, branch +1; cylinder–lever:
    its second, branch −1). Shared with the kinetostatics tests (same kernels)."""
    first = "th" if kind == "crank" else "S"
    b = Builder(data, f"{kind} + cylinder dyad", (first, "S2"))
    _, p = b.input(kind, first)
    b.frame_near("05", p, 0.4, 1.2)
    if kind == "crank":
        b.dyad("II", p, "05", "45", 1, ra="S2")
        b.distance("S2=", p, "45")
    else:
        b.dyad("II", p, "05", "45", -1, rb="S2")
        b.distance("S2=", "05", "45")
    b.link("4", p, "45")
    b.link("5", "05", "45")
    return b



def rrp_family(data):
    """Four-bar with RRP dyads: III on a fixed line through L0 (joint X), IV on a line
    carried by the rocker B0–C (joint Y); branches σ and −σ (shared with the
    kinetostatics tests, which then reuse the compiled kernel)."""
    sigma = data.draw(st.sampled_from((1, -1)), label="branch of the fixed-line dyad")
    b = Builder(data, "four-bar + RRP dyads", ("th",))
    b.fourbar("th")
    beta = b.draw(-math.pi, math.pi, "fixed line direction")
    # the fixed line's frame point: offset e across and τ along from the crank end
    e, tau = b.draw(-0.6, 0.6, "line offset"), b.draw(-0.8, 0.8, "line point along")
    u = _dir(beta)
    b.frame("L0", b.pos["A"] + e[:, None] * np.stack([-u[:, 1], u[:, 0]], -1) + tau[:, None] * u)
    b.slider_dyad("III", "A", "X", "L0", sigma, beta)
    gamma = b.draw(-math.pi, math.pi, "moving line direction from B0→C")
    b.slider_dyad("IV", "A", "Y", "C" if sigma == -1 else "B0", -sigma, gamma,
                  line_link=("B0", "C"))
    b.link("1", "A0", "A")
    b.link("3", "B0", "C")
    b.link("rodX", "A", "X")
    b.link("rodY", "A", "Y")
    b.distance("CY", "C", "Y")
    return b



def rpr_family(data):
    """Crank A0–A and an RPR dyad III (rod ``IIIr``, sleeve ``IIIs``), the slotted
    lever (кулиса): ``sleeve on the crank`` — the rod pinned at the frame point B0
    slides through a sleeve pivoted at the crank end A (branch +1); ``rod on the
    crank`` — the rod pinned at A slides through a sleeve pivoted at B0 (branch −1).
    Length ℓ and offset e are parameters. Shared with the kinetostatics tests."""
    kind = data.draw(st.sampled_from(["sleeve on the crank", "rod on the crank"]),
                     label="structure")
    b = Builder(data, f"crank + RPR dyad, {kind}", ("th",))
    b.input("crank", "th")
    b.frame_near("B0", "A", 0.3, 1.0)
    a, s, sigma = ("B0", "A", 1) if kind == "sleeve on the crank" else ("A", "B0", -1)
    b.rpr_dyad("III", a, s, "D", sigma)
    b.link("1", "A0", "A")
    b.link("rod", a, "D")
    b.distance("AB0", a, s)
    return b



def prp_family(data):
    """PRP dyad III (sliders ``IIIa`` on line a, ``IIIb`` on line b, pin D).
    ``slider``: a slider input drives block B along a fixed line; line a passes
    through B (a translating body) at a fixed direction, line b through a frame
    point F. ``link a``: four-bar; line a passes through the rocker's joint C and
    turns with the rocker B0→C (``line_link_a``); line b through a frame point F.
    ``link b``: the same with the roles of the lines swapped (``line_link_b``; the
    pin is then owned by the slider on the moving line).
    Shared with the kinetostatics tests."""
    kind = data.draw(st.sampled_from(["slider", "link a", "link b"]), label="structure")
    if kind == "slider":
        b = Builder(data, "slider + PRP dyad", ("s",))
        b.frame_random("O")
        b.slider_input("O", "B", "s")
        b.prp_dyad("III", "B", "D", "F")
        b.distance("OB", "O", "B")
    else:
        b = Builder(data, "four-bar + PRP dyad", ("th",))
        b.fourbar("th")
        b.prp_dyad("III", "C", "D", "F", line_link_a=("B0", "C"), side=kind[-1])
        b.link("1", "A0", "A")
        b.link("3", "B0", "C")
        b.distance("CD", "C", "D")
    # not |F–D|: D slides along line b through F, so that distance passes through 0
    # (a kink no analog has) — a frame point off the line instead
    b.distance("0D", "O" if kind == "slider" else "A0", "D")
    return b

