"""Property-based checks of the exact kinematic analogs on random mechanisms.

For random *assemblable* mechanisms of every structural-group type (drawn by
hypothesis, single designs and batches of designs), at scattered positions kept
away from dead points, every test checks:

1. **First-order analogs** returned by :meth:`Mechanism.solve` — dX, dY of every
   point, dφ of every link, d(length) of every named distance, for k = 2 the full
   Jacobian — against **complex-step** derivatives of
   :meth:`Mechanism.evaluate_positions` (coordinate passed as ``q + 1j*h``,
   ``h = 1e-30``, derivative ``Im(f)/h``; angles are differentiated as angles,
   ``Im(arctan(Δy/Δx))/h`` or ``−Im(arctan(Δx/Δy))/h``, whichever ratio is bounded —
   the branch offset of the arctangent is a real constant and drops out).
2. **Second-order analogs** — ddX, ddY, ddφ, dd(length), for k = 2 the full k×k
   Hessian, mixed terms included — against **central differences of the kernel's
   first-order analogs** (solves at q ± h and q ± 2h, see ``fd_column``).
3. **Closure**: ``Kinematics.closure_residual() <= 1e-9 m``; every group's
   constraints recomputed from the returned points (|out−a| = ra and |out−b| = rb
   of each RRR dyad / cylinder–lever, rigid offsets, slider lines, crank radius…)
   to 1e-9 m; and at the reference pose the solved points equal the geometry the
   mechanism was constructed from.

Why the references are independent of the kernel's analytic derivative code:
the kernel propagates a second-order jet through each group by solving the
closure equations differentiated once and twice. Reference 1 never
differentiates anything by hand: it runs the *position* formulas of
:mod:`assur.groups` (a separate plain-numpy implementation, law of cosines,
quadratic of the slider line…) on complex numbers, and the complex step gives
their derivative exact to rounding (no subtraction, so ``h`` can be 1e-30).
Reference 2 uses only the kernel's *first*-order output at neighbouring positions —
code that check 1 has just validated independently — so an error in the
second-order right-hand sides (the ``r1``, ``r2``, ``u''``, ``t''`` terms) cannot
hide behind it. (Central differences of *positions* would lose half the digits;
differencing the exact first derivatives does not.)

Tolerances (the same form everywhere): an analog ``a`` from the kernel and its
reference ``b`` must satisfy ``|a − b| <= 1e-7 · scale``, where ``scale`` is the
largest |b| of that *kind* of analog (point analogs [m/q], angle analogs [rad/q],
distance analogs [m/q]) over all points/links of the mechanism and all checked
positions of that design, for the same derivative component (coordinate j, or
pair j, l). A single analog that happens to pass through zero is thus judged
against the mechanism's own magnitude, not against its own vanishing value.

Dead points are avoided: a position is used only where every RRR dyad has
``|sin μ| >= 0.05`` (μ its transmission angle) and every RRP dyad has
``|cos γ| >= 0.05`` (γ between its radius and its line); other sampled positions
are replaced by the reference pose, which assembles by construction.

Every mechanism is built from a reference pose: joint positions are drawn first
and the lengths (and branches) derived from them, so the mechanism assembles there;
positions are then drawn in a neighbourhood of that pose and solved with
``on_failure="report"`` and ``check_continuity=False``. All parameters are named,
so a batch (params of shape (m,), q of shape (m, n)) has the same structure.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from hypothesis import HealthCheck, assume, given, settings, target
from hypothesis import strategies as st

from assur import Mechanism
from assur.groups import Crank, CylinderLever, Dyad, Frame, RigidPoint, SliderDyad, SliderInput
from assur.mechanism import PosePoint

#: complex step [m or rad]
H_CS = 1e-30
#: relative tolerance of first- and second-order analogs (see module docstring)
RTOL = 1e-7
#: closure / position tolerance [m]
CLOSURE_TOL = 1e-9
#: smallest |sin μ| of an RRR dyad (|cos γ| of an RRP dyad) at a checked position
MARGIN = 0.05
#: finite-difference step of the second-order check, relative to the coordinate's
#: scale (a crank angle: 1 rad; a length: the coordinate's value at the reference pose)
H_REL = 1e-4

SETTINGS = settings(max_examples=200, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


def _floats(lo, hi):
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False)


def _rot(v, beta):
    """Rotate vectors v (..., 2) by beta (...,)."""
    c, s = np.cos(beta), np.sin(beta)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)


def _norm(v):
    return np.hypot(v[..., 0], v[..., 1])


def _ang(v):
    return np.arctan2(v[..., 1], v[..., 0])


# ---------------------------------------------------------------------------------
# building random mechanisms from a reference pose
# ---------------------------------------------------------------------------------
class Builder:
    """Draws a random mechanism and the reference pose it assembles at.

    Every drawn quantity is an array over the ``M`` designs (``M = 1`` for a
    single design); ``pos`` holds the reference position of every point, ``q0``
    the reference value of every coordinate.
    """

    def __init__(self, data, name, coordinates):
        self.data = data
        self.name = name
        self.coordinates = tuple(coordinates)
        self.batch = data.draw(st.booleans(), label="batch")
        self.M = data.draw(st.integers(1, 3), label="designs") if self.batch else 1
        self.n = data.draw(st.integers(1, 4), label="extra positions")
        self.params = {}
        self.calls = []
        self.pos = {}
        self.q0 = {}
        self.spread = {}
        self.hstep = {}

    # drawing
    def draw(self, lo, hi, label):
        """One value per design in [lo, hi], shape (M,)."""
        return np.array(self.data.draw(st.lists(_floats(lo, hi), min_size=self.M,
                                                max_size=self.M), label=label))

    def pick(self, options, label):
        return self.data.draw(st.sampled_from(options), label=label)

    def branch(self, label):
        return self.pick((1, -1), label)

    # parameters and groups
    def par(self, name, value):
        value = np.asarray(value, dtype=float)
        self.params[name] = value.copy() if self.batch else float(value[0])
        return name

    def add(self, method, name, **kw):
        self.calls.append((method, (name,), kw))

    def frame(self, name, xy):
        self.pos[name] = xy
        self.add("frame", name, x=self.par("X" + name, xy[:, 0]), y=self.par("Y" + name, xy[:, 1]))

    def frame_random(self, name):
        xy = np.stack([self.draw(-1.0, 1.0, f"x{name}"), self.draw(-1.0, 1.0, f"y{name}")], -1)
        self.frame(name, xy)

    def frame_near(self, name, ref, rmin, rmax):
        """A frame point at distance [rmin, rmax] from point ``ref``."""
        th = self.draw(-math.pi, math.pi, f"angle to {name}")
        rho = self.draw(rmin, rmax, f"distance to {name}")
        self.frame(name, self.pos[ref] + rho[:, None] * np.stack([np.cos(th), np.sin(th)], -1))

    def place(self, a, b, sigma, label):
        """Reference position of a dyad joint on side ``sigma`` of the line a → b.

        Returns (C, |C−a|, |C−b|). With α ∈ [−0.3, 1.3], β ∈ [0.25, 1.2] (in units
        of |ab|) the transmission angle at the reference pose has |sin μ| > 0.45.
        """
        A, B = self.pos[a], self.pos[b]
        d = B - A
        alpha = self.draw(-0.3, 1.3, f"{label} along")
        beta = self.draw(0.25, 1.2, f"{label} across")
        perp = np.stack([-d[:, 1], d[:, 0]], -1)
        C = A + alpha[:, None] * d + sigma * beta[:, None] * perp
        return C, _norm(C - A), _norm(C - B)

    def coordinate(self, name, q0, spread, h):
        """Reference value q0 (M,), sampling half-width ``spread`` (M,) and FD step."""
        self.q0[name] = np.asarray(q0, dtype=float) * np.ones(self.M)
        self.spread[name] = np.asarray(spread, dtype=float) * np.ones(self.M)
        self.hstep[name] = np.asarray(h, dtype=float) * np.ones(self.M)

    def link(self, name, tail, head):
        self.calls.append(("link", (name, tail, head), {}))

    def distance(self, name, a, b):
        self.calls.append(("distance", (name, a, b), {}))

    # common inputs --------------------------------------------------------------
    def crank_input(self, pivot, out, coord, radius=(0.1, 0.6)):
        """Crank at frame point ``pivot``; returns nothing, sets pos[out] and q0."""
        r = self.draw(*radius, "crank radius")
        th0 = self.draw(-math.pi, math.pi, "crank angle at the reference pose")
        phase = self.draw(-math.pi, math.pi, "crank phase")
        self.pos[out] = self.pos[pivot] + r[:, None] * np.stack([np.cos(th0), np.sin(th0)], -1)
        self.add("crank", "crank", pivot=pivot, out=out, radius=self.par("R" + out, r),
                 angle=coord, phase=self.par("phase", phase), links=("1",))
        self.coordinate(coord, th0 - phase, 1.0, H_REL)

    def cylinder_lever_input(self, base, pivot, out, coord, sigma):
        C, s0, lever = self.place(base, pivot, sigma, "lever end")
        self.pos[out] = C
        self.add("cylinder_lever", "cylinder-lever", base=base, pivot=pivot, out=out,
                 lever=self.par("L" + out, lever), s=coord, branch=sigma, links=("2", "3"))
        self.coordinate(coord, s0, 0.25 * s0, H_REL * s0)

    def dyad(self, name, a, b, out, sigma, ra=None, rb=None):
        """RRR dyad whose joint ``out`` is placed at the reference pose; ``ra``/``rb``
        given as a coordinate name make that radius the coordinate."""
        C, la, lb = self.place(a, b, sigma, f"joint {out}")
        self.pos[out] = C
        ra_ref = ra or self.par(f"ra_{out}", la)
        rb_ref = rb or self.par(f"rb_{out}", lb)
        for ref, val in ((ra, la), (rb, lb)):
            if ref is not None:
                self.coordinate(ref, val, 0.2 * val, H_REL * val)
        self.add("dyad", name, a=a, b=b, out=out, ra=ra_ref, rb=rb_ref, branch=sigma,
                 links=(f"{name}a", f"{name}b"))

    def build(self):
        m = Mechanism(self.name, coordinates=self.coordinates, params=self.params)
        for method, args, kw in self.calls:
            m = getattr(m, method)(*args, **kw)
        k = len(self.coordinates)
        q0 = np.stack([self.q0[c] for c in self.coordinates], -1)  # (M, k)
        u = np.array(self.data.draw(st.lists(_floats(-1.0, 1.0), min_size=self.M * self.n * k,
                                             max_size=self.M * self.n * k),
                                    label="position offsets")).reshape(self.M, self.n, k)
        spread = np.stack([self.spread[c] for c in self.coordinates], -1)
        # position 0 of every design is the reference pose itself
        Q = np.concatenate([q0[:, None, :], q0[:, None, :] + u * spread[:, None, :]], axis=1)
        h = np.stack([self.hstep[c] for c in self.coordinates], -1)
        return Case(m, self, Q, q0, h)


# ---------------------------------------------------------------------------------
# the checks
# ---------------------------------------------------------------------------------
@dataclass
class Case:
    mech: Mechanism
    b: Builder
    Q: np.ndarray  # (M, n, k) positions, Q[:, 0] the reference pose
    q0: np.ndarray  # (M, k)
    h: np.ndarray  # (M, k) finite-difference steps

    @property
    def k(self):
        return self.Q.shape[-1]

    def api_q(self, Q):
        """Coordinates in the shape solve() takes: (n,)/(n,k) single, (m,n)/(m,n,k) batch."""
        Q = Q if self.k > 1 else Q[..., 0]
        return Q if self.b.batch else Q[0]

    def solve(self, Q):
        return self.mech.solve(self.api_q(Q), on_failure="report", check_continuity=False)

    def shaped(self, a, tail=0):
        """Result array (shape + tail) -> (M, n, *tail)."""
        a = np.asarray(a)
        return a.reshape((self.Q.shape[0], self.Q.shape[1]) + a.shape[a.ndim - tail:])

    def val(self, ref, Q=None):
        """Value of a reference, broadcastable to (M, n)."""
        Q = self.Q if Q is None else Q
        if isinstance(ref, str) and ref in self.mech.coordinates:
            return Q[..., self.mech.coordinates.index(ref)]
        if isinstance(ref, str):
            return np.asarray(self.mech.params[ref], dtype=float).reshape(-1, 1)
        return float(ref)

    def reproducer(self):
        lines = ["import numpy as np", "from assur import Mechanism",
                 "params = {" + ", ".join(
                     f"{k!r}: {np.asarray(v).tolist()!r}" for k, v in self.mech.params.items())
                 + "}",
                 f"m = Mechanism({self.mech.name!r}, coordinates={self.mech.coordinates!r}, "
                 "params=params)"]
        for method, args, kw in self.b.calls:
            a = [repr(x) for x in args] + [f"{k}={v!r}" for k, v in kw.items()]
            lines.append(f"m = m.{method}({', '.join(a)})")
        lines.append(f"q = np.array({self.api_q(self.Q).tolist()!r})")
        lines.append("r = m.solve(q, on_failure='report', check_continuity=False)")
        return "\n".join(lines)


def _point(r, case, p):
    return np.stack([case.shaped(r.x(p)), case.shaped(r.y(p))], -1)  # (M, n, 2)


def _jac(case, a):
    """First-order analog array (shape [+ (k,)]) -> (M, n, k)."""
    return case.shaped(a[..., None] if case.k == 1 else a, 1)


def _hess(case, a):
    return case.shaped(a[..., None, None] if case.k == 1 else a, 2)


def margins(case, r):
    """Smallest conditioning measure over the dyads at every element, (M, n)."""
    mech = case.mech
    out = np.full(case.Q.shape[:2], np.inf)
    for g in mech.groups:
        if isinstance(g, (Dyad, CylinderLever)):
            out = np.minimum(out, np.abs(np.sin(case.shaped(r.transmission_angle(g.name)))))
        elif isinstance(g, SliderDyad):
            beta = case.val(g.direction)
            if g.line_link:
                P, Q = _point(r, case, g.line_link[0]), _point(r, case, g.line_link[1])
                u = _rot(Q - P, beta) / _norm(Q - P)[..., None]
            else:
                u = np.stack(np.broadcast_arrays(np.cos(beta), np.sin(beta)), -1)
            w = _point(r, case, g.out) - _point(r, case, g.a)
            out = np.minimum(out, np.abs((u * w).sum(-1)) / _norm(w))
    return out


def analogs(case, r):
    """Kernel analogs by kind: {kind: {name: (J (M,n,c,k), H (M,n,c,k,k))}}."""
    res = {"point": {}, "angle": {}, "distance": {}}
    for p in case.mech.points:
        J = np.stack([_jac(case, r.dx(p)), _jac(case, r.dy(p))], 2)
        H = np.stack([_hess(case, r.ddx(p)), _hess(case, r.ddy(p))], 2)
        # the single-coordinate accessors agree with the full arrays
        for j, c in enumerate(case.mech.coordinates):
            assert np.array_equal(case.shaped(r.dx(p, wrt=c)), J[:, :, 0, j])
            assert np.array_equal(case.shaped(r.ddy(p, wrt=c)), H[:, :, 1, j, j])
        res["point"][p] = (J, H)
    for l in case.mech.links:
        res["angle"][l.name] = (_jac(case, r.dphi(l.name))[:, :, None],
                                _hess(case, r.ddphi(l.name))[:, :, None])
    for d in case.mech.distances:
        res["distance"][d.name] = (_jac(case, r.dlength(d.name))[:, :, None],
                                   _hess(case, r.ddlength(d.name))[:, :, None])
    return res


def complex_step(case):
    """Reference first-order analogs {kind: {name: (M, n, c, k)}} by complex step."""
    mech = case.mech
    over = {k: np.asarray(v)[:, None] for k, v in mech.params.items()} if case.b.batch else {}
    cols = {"point": {}, "angle": {}, "distance": {}}
    for j, c in enumerate(mech.coordinates):
        q = {cc: case.Q[..., jj].astype(complex) for jj, cc in enumerate(mech.coordinates)}
        q[c] = q[c] + 1j * H_CS
        pts = mech.evaluate_positions(q, over)
        shape = case.Q.shape[:2]

        def P(p):
            x, y = pts[p]
            return (np.broadcast_to(np.asarray(x, dtype=complex), shape),
                    np.broadcast_to(np.asarray(y, dtype=complex), shape))

        for p in mech.points:
            x, y = P(p)
            cols["point"].setdefault(p, []).append(np.stack([x.imag, y.imag], -1) / H_CS)
        for l in mech.links:
            (tx, ty), (hx, hy) = P(l.tail), P(l.head)
            dx, dy = hx - tx, hy - ty
            # φ = arctan(Δy/Δx) + const where |Δx| >= |Δy|, else −arctan(Δx/Δy) + const
            use_x = np.abs(dx.real) >= np.abs(dy.real)
            ratio = np.where(use_x, dy, dx) / np.where(use_x, dx, dy)
            dphi = np.where(use_x, 1.0, -1.0) * np.arctan(ratio).imag / H_CS
            cols["angle"].setdefault(l.name, []).append(dphi[..., None])
        for d in mech.distances:
            (ax, ay), (bx, by) = P(d.a), P(d.b)
            dl = np.sqrt((bx - ax) ** 2 + (by - ay) ** 2).imag / H_CS
            cols["distance"].setdefault(d.name, []).append(dl[..., None])
    return {kind: {n: np.stack(v, -1) for n, v in d.items()} for kind, d in cols.items()}


def fd_column(case, j):
    """d/dq_j of the kernel's first-order analogs: {kind: {name: (M, n, c, k)}}.

    Fourth-order central difference (Richardson extrapolation of two central
    differences, steps h and 2h):
    ``(8·[J(q+h) − J(q−h)] − [J(q+2h) − J(q−2h)]) / (12 h)``.
    Its truncation error is h⁴/30·J⁽⁵⁾ and its rounding error ~ 1.5·ε·|J|/h.
    ``h = H_REL × the coordinate's scale`` (1e-4 rad for a crank angle, 1e-4·S0
    for a length) keeps both far below 1e-7 of the analogs' scale even at the
    ``MARGIN`` dead-point distance, where each further derivative grows like
    1/sin²μ (a plain central difference there would need h ~ 1e-6 and then lose
    to rounding).
    """
    out = {}
    h = case.h[:, j][:, None]  # (M, 1)
    J = {}
    for s in (1, -1, 2, -2):
        Q = case.Q.copy()
        Q[..., j] += s * h
        r = case.solve(Q)
        assert r.ok.all(), (f"a neighbour at {s:+d}·h of a checked position does not "
                            f"assemble: {r.failures[:1]}\n{case.reproducer()}")
        J[s] = analogs(case, r)
    hh = h[:, :, None, None]  # (M, 1, 1, 1)
    for kind in J[1]:
        out[kind] = {n: (8 * (J[1][kind][n][0] - J[-1][kind][n][0])
                         - (J[2][kind][n][0] - J[-2][kind][n][0])) / (12 * hh)
                     for n in J[1][kind]}
    return out


#: analogs compared on a common scale: lengths (point coordinates and named
#: distances, [m/q]) and angles ([rad/q])
FAMILY = {"point": "length", "distance": "length", "angle": "angle"}


def compare(case, what, kernel, ref):
    """Assert |kernel − ref| <= RTOL·scale for one derivative component.

    ``kernel`` and ``ref``: {kind: {name: (M, n, c)}} (c = 2 for points, 1 otherwise).
    ``scale`` is the largest |ref| of that family (``FAMILY``) over all names and
    positions of each design (see the module docstring). Returns the worst err/tol.
    """
    worst = 0.0
    scales = {}
    for kind in ref:
        fam = FAMILY[kind]
        for v in ref[kind].values():
            s = np.abs(v).max(axis=(1, 2), keepdims=True)[..., None]  # (M, 1, 1, 1)
            scales[fam] = np.maximum(scales.get(fam, 0.0), s)
    for kind in ref:
        if not ref[kind]:
            continue
        names = list(ref[kind])
        a = np.stack([kernel[kind][n] for n in names], 2)  # (M, n, N, c)
        b = np.stack([ref[kind][n] for n in names], 2)
        scale = scales[FAMILY[kind]]  # per design
        tol = RTOL * np.maximum(scale, 1e-12)
        err = np.abs(a - b)
        ratio = err / tol
        worst = max(worst, float(ratio.max()))
        if not (err <= tol).all():
            d, i, nidx, c = np.unravel_index(np.argmax(ratio), ratio.shape)
            comp = f" {'xy'[c]}" if kind == "point" else ""
            raise AssertionError(
                f"{what} of {kind} {names[nidx]!r}{comp} disagrees at design {d}, position "
                f"{i} (q = {case.Q[d, i].tolist()}): kernel {a[d, i, nidx, c]!r}, reference "
                f"{b[d, i, nidx, c]!r}, |diff| = {err[d, i, nidx, c]:.3g} > tol "
                f"{tol[d, 0, 0, 0]:.3g} (scale {scale[d, 0, 0, 0]:.3g})\n"
                f"reproducer:\n{case.reproducer()}")
    return worst


def _component(d, idx):
    return {kind: {n: v[(...,) + idx] for n, v in x.items()} for kind, x in d.items()}


def check_closure(case, r):
    """Closure residuals, every group's constraints, and the reference pose."""
    mech = case.mech
    res = case.shaped(r.closure_residual())
    assert (res <= CLOSURE_TOL).all(), f"closure residual {res.max():.3g} m\n{case.reproducer()}"
    P = {p: _point(r, case, p) for p in mech.points}
    errs = {}

    def dist(a, b):
        return _norm(P[b] - P[a])

    for g in mech.groups:
        if isinstance(g, Frame):
            errs[g.name] = _norm(P[g.name] - np.stack(np.broadcast_arrays(
                case.val(g.x), case.val(g.y)), -1))
        elif isinstance(g, (Dyad, CylinderLever)):
            errs[g.name] = np.maximum(np.abs(dist(g.a, g.out) - case.val(g.ra)),
                                      np.abs(dist(g.b, g.out) - case.val(g.rb)))
        elif isinstance(g, Crank):
            th = case.val(g.angle) + case.val(g.phase)
            want = P[g.pivot] + case.val(g.radius)[..., None] * np.stack(
                np.broadcast_arrays(np.cos(th), np.sin(th)), -1) if np.ndim(
                case.val(g.radius)) else P[g.pivot] + g.radius * np.stack([np.cos(th), np.sin(th)], -1)
            errs[g.name] = _norm(P[g.out] - want)
        elif isinstance(g, SliderInput):
            t = np.broadcast_to(case.val(g.s) + case.val(g.offset), case.Q.shape[:2])
            beta = np.broadcast_to(case.val(g.direction), case.Q.shape[:2])
            want = P[g.origin] + t[..., None] * np.stack([np.cos(beta), np.sin(beta)], -1)
            errs[g.name] = _norm(P[g.out] - want)
        elif isinstance(g, RigidPoint):
            if g.angle is not None:
                beta = case.val(g.angle)
            else:
                bb, ll, oo = case.val(g.base), case.val(g.length), case.val(g.opposite)
                beta = g.branch * np.arccos((bb * bb + ll * ll - oo * oo) / (2 * bb * ll))
                # the triangle's third side: |out − toward| = opposite (origin and toward
                # are joints of one rigid link whose length is ``base``)
                errs[g.name + " opposite"] = np.abs(dist(g.toward, g.out) - oo)
            beta = np.broadcast_to(beta, case.Q.shape[:2])
            d = P[g.toward] - P[g.origin]
            want = P[g.origin] + np.asarray(case.val(g.length))[..., None] * _rot(
                d, beta) / _norm(d)[..., None]
            errs[g.name] = _norm(P[g.out] - want)
        elif isinstance(g, SliderDyad):
            beta = np.broadcast_to(case.val(g.direction), case.Q.shape[:2])
            if g.line_link:
                d = P[g.line_link[1]] - P[g.line_link[0]]
                u = _rot(d, beta) / _norm(d)[..., None]
            else:
                u = np.stack([np.cos(beta), np.sin(beta)], -1)
            w = P[g.out] - P[g.line_point]
            errs[g.name + " line"] = np.abs(u[..., 0] * w[..., 1] - u[..., 1] * w[..., 0])
            errs[g.name] = np.abs(dist(g.a, g.out) - case.val(g.radius))
        elif isinstance(g, PosePoint):
            # fixed on the link origin→toward at its reference-pose offset (dx, dy)
            o, t, c = (case.b.pos[x][:, None] for x in (g.origin, g.toward, g.out))
            beta = _ang(c - o) - _ang(t - o)
            d = P[g.toward] - P[g.origin]
            want = P[g.origin] + _norm(c - o)[..., None] * _rot(d, beta) / _norm(d)[..., None]
            errs[g.name] = _norm(P[g.out] - want)
    for l in mech.links:
        d = P[l.head] - P[l.tail]
        e = np.angle(np.exp(1j * (case.shaped(r.phi(l.name)) - _ang(d))))
        errs["link " + l.name] = np.abs(e) * _norm(d)  # [m] at the head
    for dd in mech.distances:
        errs["distance " + dd.name] = np.abs(case.shaped(r.length(dd.name)) - dist(dd.a, dd.b))
    # at the reference pose (position 0) the points are where they were constructed
    for p in mech.points:
        errs["reference pose " + p] = np.pad(_norm(P[p][:, 0] - case.b.pos[p])[:, None],
                                             ((0, 0), (0, case.Q.shape[1] - 1)))
    for what, e in errs.items():
        assert (e <= CLOSURE_TOL).all(), (f"{what}: residual {e.max():.3g} m > "
                                          f"{CLOSURE_TOL} m\n{case.reproducer()}")


def check(case):
    """All checks on one random mechanism (see the module docstring)."""
    r = case.solve(case.Q)
    good = r.ok.reshape(case.Q.shape[:2])
    # the reference pose assembles by construction, with a healthy margin
    assert good[:, 0].all(), f"reference pose does not assemble\n{case.reproducer()}"
    good &= margins(case, r) >= MARGIN
    assume(good[:, 0].all())
    # positions that fail or are near a dead point are replaced by the reference pose
    case.Q = np.where(good[..., None], case.Q, case.q0[:, None, :])
    r = case.solve(case.Q)
    assert r.ok.all()
    check_closure(case, r)
    kern = analogs(case, r)
    J = {kind: {n: v[0] for n, v in x.items()} for kind, x in kern.items()}
    H = {kind: {n: v[1] for n, v in x.items()} for kind, x in kern.items()}
    coords = case.mech.coordinates
    # 1. first order against complex step, each coordinate j
    cs = complex_step(case)
    w1 = max(compare(case, f"first-order analog d/d{c}", _component(J, (j,)),
                     _component(cs, (j,))) for j, c in enumerate(coords))
    # 2. second order against central differences of the kernel's first order:
    #    the column d/dq_j of the Hessian, every entry (i, j) (mixed ones included)
    w2 = 0.0
    for j, c in enumerate(coords):
        fd = fd_column(case, j)
        for i, ci in enumerate(coords):
            w2 = max(w2, compare(case, f"second-order analog d2/d{ci}d{c}",
                                 _component(H, (i, j)), _component(fd, (i,))))
    target(w1, label="first order: max error / tolerance")
    target(w2, label="second order: max error / tolerance")


# ---------------------------------------------------------------------------------
# the tests, one per group type
#
# Each distinct *structure* (group types, connections, branch signs, parameter
# order) is a separately generated and numba-compiled kernel (~3 s, cached on disk
# afterwards), so the discrete choices below are deliberately few (2–6 structures
# per test; both branches of every group type are still covered). Everything
# continuous — frame points, lengths, angles, positions, batch size — is random.
# ---------------------------------------------------------------------------------
@SETTINGS
@given(st.data())
def test_cylinder_lever_input(data):
    """(a) Cylinder–lever input group: two frame pivots, cylinder length S."""
    b = Builder(data, "cylinder-lever", ("S",))
    b.frame_random("01")
    b.frame_near("03", "01", 0.2, 1.0)
    b.cylinder_lever_input("01", "03", "23", "S", b.branch("branch"))
    b.link("2", "01", "23")
    b.link("3", "03", "23")
    b.distance("S=", "01", "23")
    check(b.build())


@SETTINGS
@given(st.data())
def test_crank_and_rrr_dyad(data):
    """(b) Four-bar: crank input (angle coordinate) followed by an RRR dyad."""
    b = Builder(data, "four-bar", ("th",))
    b.frame_random("A0")
    b.crank_input("A0", "A", "th")
    b.frame_near("B0", "A", 0.4, 1.2)
    b.dyad("II", "A", "B0", "C", b.branch("branch"))
    b.link("1", "A0", "A")
    b.link("2", "A", "C")
    b.link("3", "B0", "C")
    b.distance("AB0", "A", "B0")
    check(b.build())


@SETTINGS
@given(st.data())
def test_dyad_with_cylinder_radius_two_coordinates(data):
    """(c) RRR dyad whose radius is the second generalized coordinate S2 (a cylinder
    inside the chain), k = 2: full Jacobian and 2x2 Hessian (mixed terms)."""
    kind = data.draw(st.sampled_from(["crank", "cylinder-lever"]), label="input")
    first = "th" if kind == "crank" else "S"
    b = Builder(data, f"{kind} + cylinder dyad", (first, "S2"))
    if kind == "crank":
        b.frame_random("A0")
        b.crank_input("A0", "A", "th")
        p = "A"
    else:
        b.frame_random("01")
        b.frame_near("03", "01", 0.2, 1.0)
        b.cylinder_lever_input("01", "03", "23", "S", -1)
        p = "23"
    b.frame_near("05", p, 0.4, 1.2)
    # the crank drives the dyad's first radius, the lever its second (structure budget)
    ra, rb = ("S2", None) if kind == "crank" else (None, "S2")
    b.dyad("II", p, "05", "45", b.branch("branch"), ra=ra, rb=rb)
    b.link("4", p, "45")
    b.link("5", "05", "45")
    b.distance("S2=", p if ra else "05", "45")
    check(b.build())
