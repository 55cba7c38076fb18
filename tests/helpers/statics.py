"""Random loads on the random mechanisms of :mod:`tests.helpers.analogs`, an
independent global solve of their statics, and the checks of the kinetostatics (the
property tests of :mod:`tests.core.test_statics`, whose docstring describes the
checks, references and tolerances; the families serve the fused-kernel, dynamics and
group tests too)."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from hypothesis import Phase, assume, settings, target
from hypothesis import strategies as st

from assur.core import statics
from assur.groups import Crank, CylinderLever, DoubleSliderDyad, Dyad, SleeveDyad, SliderDyad, \
    SliderInput
from tests.helpers.analogs import MARGIN, SETTINGS, Builder, _dir, _floats, _line_dir, _point, \
    _prp_dirs, analogs, cylinder_dyad_family, fd_steps, margins, prp_family, rpr_family, \
    rrp_family


#: gravity for the masses [m/s²] (assur's default, the seeds' value)
G = 9.81



#: characteristic length converting moments to forces [m]
ELL0 = 1.0



#: relative tolerances (see the module docstring)
RTOL_VW = 1e-9



RTOL_EQ = 1e-9



RTOL_REF = 1e-8



RTOL_LIN = 1e-9



RTOL_POWER = 1e-7



KINDS = ("weight", "force", "moment", "spring", "mass")



#: shortest spring [m] (shorter: the example is rejected, its direction is ill-defined)
MIN_SPRING = 0.05



#: worst |error| / tolerance of each check seen in this session (for reports)
WORST = {}



# the bug tests fail at once; shrinking them would only re-run many structures
BUG_SETTINGS = settings(SETTINGS, phases=[Phase.explicit, Phase.reuse, Phase.generate])



def _cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]



def _dot(a, b):
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1]



def _perp(u):
    return np.stack([-u[..., 1], u[..., 0]], -1)



def _mag(v):
    return np.hypot(v[..., 0], v[..., 1])



# ---------------------------------------------------------------------------------
# the mechanism families: exactly the builder calls of tests.helpers.analogs (same
# kernels, so a cache warmed by either test serves both)
# ---------------------------------------------------------------------------------
def cylinder_lever_family(data):
    """Cylinder–lever input (cylinder 2, lever 3) with rigid points P, T+, T− on the
    lever and an RRR dyad III hanging from T−; or with a pose point S6 on the lever
    and an RRR dyad IV hanging from it."""
    kind = data.draw(st.sampled_from(["rigid points", "pose point"]), label="structure")
    if kind == "rigid points":
        b = Builder(data, "cylinder-lever + rigid points", ("S",))
        o, t = b.input("cylinder-lever", "S")
        b.rigid_angle("P", o, t, "P")
        b.rigid_triangle("T+", t, o, "T+", 1)
        b.rigid_triangle("T-", o, t, "T-", -1)
        b.frame_near("F", "T-", 0.4, 1.2)
        b.dyad("III", "T-", "F", "D", -1)
        b.link("body", o, t)
        b.link("P", o, "P")
        b.link("T+", t, "T+")
        b.link("T-", o, "T-")
        b.link("4", "T-", "D")
        b.link("5", "F", "D")
    else:
        b = Builder(data, "cylinder-lever + pose point", ("S",))
        t, o = b.input("cylinder-lever", "S")
        b.pose_point("S6", o, t, "S6", "S")
        b.frame_near("F", "S6", 0.4, 1.2)
        b.dyad("IV", "S6", "F", "D", -1)
        b.link("6", o, "S6")
        b.link("4", "S6", "D")
        b.link("5", "F", "D")
    return b



def crank_family(data):
    """Four-bar (crank 1, coupler IIa, rocker IIb; both branches), alone, with rigid
    points on the coupler and a dyad III from P, or with a pose point S6 on the
    coupler and a dyad IV from it."""
    kind = data.draw(st.sampled_from(["four-bar", "rigid points", "pose point"]),
                     label="structure")
    if kind == "four-bar":
        b = Builder(data, "four-bar", ("th",))
        b.fourbar("th", sigma=b.branch())
        b.link("1", "A0", "A")
        b.link("2", "A", "C")
        b.link("3", "B0", "C")
        b.distance("AB0", "A", "B0")
    elif kind == "rigid points":
        b = Builder(data, "four-bar + rigid points", ("th",))
        b.fourbar("th")
        b.rigid_angle("P", "A", "C", "P")
        b.rigid_triangle("T+", "C", "A", "T+", 1)
        b.rigid_triangle("T-", "A", "C", "T-", -1)
        b.frame_near("F", "P", 0.4, 1.2)
        b.dyad("III", "P", "F", "D", 1)
        b.link("body", "A", "C")
        b.link("P", "A", "P")
        b.link("T+", "C", "T+")
        b.link("T-", "A", "T-")
        b.link("4", "P", "D")
        b.link("5", "F", "D")
    else:
        b = Builder(data, "four-bar + pose point", ("th",))
        b.fourbar("th")
        b.pose_point("S6", "C", "A", "S6", "th")
        b.frame_near("F", "S6", 0.4, 1.2)
        b.dyad("IV", "S6", "F", "D", 1)
        b.link("6", "C", "S6")
        b.link("4", "S6", "D")
        b.link("5", "F", "D")
    return b



class CommonSliderDirection(Builder):
    """All designs of a batch share the slider's direction (a per-design direction
    is :func:`test_slider_input_batch_with_a_direction_per_design`, failing)."""

    def draw(self, lo, hi, label):
        v = super().draw(lo, hi, label)
        return np.full_like(v, v[0]) if label == "slider direction" else v

    def par(self, name, value):
        name = super().par(name, value)
        if name == "dir":  # a number, not an array over the designs
            self.params[name] = float(np.asarray(value)[0])
        return name



class Batch(Builder):
    """Always a batch of 2–3 designs."""

    def __init__(self, data, name, coordinates):
        super().__init__(data, name, coordinates)
        self.batch, self.M = True, max(self.M, 2)



def slider_family(data, builder=CommonSliderDirection):
    """Slider input 1 (block B on a fixed line) and an RRR dyad (F, B) → C."""
    b = builder(data, "slider-crank", ("s",))
    b.frame_random("O")
    b.slider_input("O", "B", "s")
    b.frame_near("F", "B", 0.4, 1.2)
    b.dyad("II", "F", "B", "C", b.branch())
    b.link("2", "B", "C")
    b.link("3", "F", "C")
    b.distance("OB", "O", "B")
    return b



def cylinder_radius_family(data, kind=None):
    """k = 2: a crank (th) or cylinder–lever (S) input and an RRR dyad II whose radius
    is the second coordinate S2 (crank: its first link IIa is the cylinder;
    cylinder–lever: its second link IIb); or a crank and an RRP dyad II whose
    radius (rod IIr) is the coordinate L."""
    kind = kind or data.draw(st.sampled_from(["crank", "cylinder-lever", "slider radius"]),
                             label="structure")
    if kind == "slider radius":
        b = Builder(data, f"crank + {kind}", ("th", "L"))
        b.input("crank", "th")
        beta = b.draw(-math.pi, math.pi, "line direction")
        b.frame_near("L0", "A", 0.2, 0.8)
        b.slider_dyad("II", "A", "X", "L0", -1, beta, radius_coord="L")
        b.link("rod", "A", "X")
        b.link("1", "A0", "A")
        return b
    return cylinder_dyad_family(data, kind)



def prepare(b):
    """Build the case; positions that fail or come near a dead point (margin <
    MARGIN, as in tests.helpers.analogs) are replaced by the reference pose."""
    case = b.build()
    r = case.solve()
    good = r.ok.reshape(case.Q.shape[:2])
    assert good[:, 0].all(), f"the reference pose does not assemble\n{case.reproducer()}"
    good &= margins(case, r) >= MARGIN
    assume(good[:, 0].all())
    if not good.all():
        case.Q = np.where(good[..., None], case.Q, case.q0[:, None, :])
    return case



# ---------------------------------------------------------------------------------
# random loads
# ---------------------------------------------------------------------------------
def rod_ends(mech):
    """(point, link) of the moving end of every cylinder (a link whose length is a
    coordinate): the end at the joint its group adds."""
    bodies = mech.bodies
    return {(g.out, l) for g in mech.groups for l in (getattr(g, "links", ()) or ())
            if hasattr(g, "out") and l in bodies and bodies[l]["variable"]}



def draw_loads(data, mech, label, rod_end_loads=False):
    """A random list of 1–4 loads (plain tuples, numbers only; see with_loads)."""
    bodies = mech.bodies
    moving = [b for b in bodies if b != "0"]
    skip = set() if rod_end_loads else rod_ends(mech)
    carriers = [(p, b) for b in moving for p in bodies[b]["points"] if (p, b) not in skip]
    anchors = carriers + [(p, "0") for p in bodies["0"]["points"]]
    n = data.draw(st.integers(1, 4), label=f"{label}: number of loads")
    loads = []
    for i in range(n):
        kind = data.draw(st.sampled_from(KINDS), label=f"{label} {i}: kind")
        if kind == "weight":
            at = data.draw(st.sampled_from(carriers), label="weight: point, link")
            loads.append(("weight", at, data.draw(_floats(0.0, 2000.0), label="P")))
        elif kind == "force":
            at = data.draw(st.sampled_from(carriers), label="force: point, link")
            loads.append(("force", at, data.draw(_floats(-1000.0, 1000.0), label="fx"),
                          data.draw(_floats(-1000.0, 1000.0), label="fy")))
        elif kind == "moment":
            link = data.draw(st.sampled_from(moving), label="moment: link")
            loads.append(("moment", link, data.draw(_floats(-500.0, 500.0), label="M")))
        elif kind == "spring":
            a = data.draw(st.sampled_from(carriers), label="spring: end a")
            others = [x for x in anchors if x[0] != a[0] and x[1] != a[1]]
            bb = data.draw(st.sampled_from(others), label="spring: end b")
            loads.append(("spring", a, bb, data.draw(_floats(0.0, 2e4), label="rate"),
                          data.draw(_floats(0.0, 1.0), label="free length"),
                          data.draw(_floats(-500.0, 500.0), label="preload")))
        else:
            at = data.draw(st.sampled_from(carriers), label="mass: point, link")
            loads.append(("mass", at, data.draw(_floats(0.1, 200.0), label="m"),
                          data.draw(_floats(0.0, 20.0), label="J")))
    return loads



def fixed_loads(data, mech, label):
    """One load of every kind at places fixed by the mechanism's structure — a weight
    at the first point a moving link carries, a point force at the last, a moment on
    the last moving link, a spring from the first carried point to the first point of
    another link or the frame, a mass at the middle carried point — with random values
    (the ranges of :func:`draw_loads`), made pairwise distinct and ≠ 1 (the spring's
    count) by a relative 1e-9 where they coincide: the fused kernel reads one row per
    distinct number, so that every example of one structure shares its kernel and
    only the values differ."""
    bodies = mech.bodies
    moving = [b for b in bodies if b != "0"]
    skip = rod_ends(mech)
    carriers = [(p, b) for b in moving for p in bodies[b]["points"] if (p, b) not in skip]
    anchors = carriers + [(p, "0") for p in bodies["0"]["points"]]
    a = carriers[0]
    spring_to = next(x for x in anchors if x[0] != a[0] and x[1] != a[1])
    taken = {1.0}

    def value(lo, hi, what):
        v = data.draw(_floats(lo, hi), label=f"{label}: {what}")
        while v in taken:
            v = v * (1 + 1e-9) + 1e-9
        taken.add(v)
        return v

    return [("weight", carriers[0], value(0.0, 2000.0, "P")),
            ("force", carriers[-1], value(-1000.0, 1000.0, "fx"), value(-1000.0, 1000.0, "fy")),
            ("moment", moving[-1], value(-500.0, 500.0, "M")),
            ("spring", a, spring_to, value(0.0, 2e4, "rate"), value(0.0, 1.0, "free length"),
             value(-500.0, 500.0, "preload")),
            ("mass", carriers[len(carriers) // 2], value(0.1, 200.0, "m"),
             value(0.0, 20.0, "J"))]


def assume_springs_long(case, loads):
    """Reject an example with a spring shorter than MIN_SPRING anywhere (its
    direction is ill-defined; at zero length assur divides 0 by 0)."""
    r = case.solve()
    for ld in loads:
        if ld[0] == "spring":
            d = _point(case, r, ld[2][0]) - _point(case, r, ld[1][0])
            assume(_mag(d).min() > MIN_SPRING)



def with_loads(mech, loads, lam=1.0):
    """The mechanism with the loads added through the builder, scaled by ``lam``
    (a load names its link only when it is not the point's owner)."""
    def link(p, b):
        return None if mech.owner(p) == b else b

    for i, ld in enumerate(loads):
        kind = ld[0]
        if kind == "weight":
            (p, b), P = ld[1], ld[2]
            mech = mech.weight(p, lam * P, link=link(p, b))
        elif kind == "force":
            (p, b), fx, fy = ld[1], ld[2], ld[3]
            mech = mech.force(p, lam * fx, lam * fy, link=link(p, b))
        elif kind == "moment":
            mech = mech.moment(ld[1], lam * ld[2])
        elif kind == "spring":
            (pa, ba), (pb, bb), rate, free, pre = ld[1:]
            links = None if mech.owner(pa) == ba and mech.owner(pb) == bb else (ba, bb)
            mech = mech.spring(f"k{i}", pa, pb, lam * rate, free, lam * pre, links=links)
        else:
            (p, b), m, J = ld[1], ld[2], ld[3]
            mech = mech.mass(b, lam * m, p, J=lam * J)
    return mech



def loads_code(loads, mech):
    """Builder calls of the loads, for reproducers."""
    lines = []

    def link(p, b):
        return "" if mech.owner(p) == b else f", link={b!r}"

    for i, ld in enumerate(loads):
        kind = ld[0]
        if kind == "weight":
            lines.append(f"m = m.weight({ld[1][0]!r}, {ld[2]!r}{link(*ld[1])})")
        elif kind == "force":
            lines.append(f"m = m.force({ld[1][0]!r}, {ld[2]!r}, {ld[3]!r}{link(*ld[1])})")
        elif kind == "moment":
            lines.append(f"m = m.moment({ld[1]!r}, {ld[2]!r})")
        elif kind == "spring":
            (pa, ba), (pb, bb), rate, free, pre = ld[1:]
            links = "" if mech.owner(pa) == ba and mech.owner(pb) == bb else \
                f", links=({ba!r}, {bb!r})"
            lines.append(f"m = m.spring('k{i}', {pa!r}, {pb!r}, {rate!r}, {free!r}, {pre!r}"
                         f"{links})")
        else:
            lines.append(f"m = m.mass({ld[1][1]!r}, {ld[2]!r}, {ld[1][0]!r}, J={ld[3]!r})")
    return lines



# ---------------------------------------------------------------------------------
# motion of points and links (for the inertia loads and the power balance)
# ---------------------------------------------------------------------------------
def angle_pair(mech, body):
    """Two points of ``body`` whose direction turns with it, or None (the frame, a
    slider on a fixed direction). A slider block turns with its guide."""
    if body == "0":
        return None
    pts = mech.bodies[body]["points"]
    if len(pts) >= 2:
        return pts[0], pts[1]
    for g in mech.groups:
        if isinstance(g, SliderDyad) and g.links[1] == body:
            return angle_pair(mech, guide_of(mech, g))
        if isinstance(g, SliderInput) and g.links[0] == body:
            return None
        if isinstance(g, SleeveDyad) and g.links[1] == body:
            return angle_pair(mech, g.links[0])  # the sleeve turns with the rod
        if isinstance(g, DoubleSliderDyad) and body in g.links:
            return angle_pair(mech, prp_guides(mech, g)[g.links.index(body)])
    raise AssertionError(f"link {body!r} with one point is no slider block")



def guide_of(mech, g):
    """The link carrying the line of an RRP dyad."""
    if g.line_link:
        p, q = g.line_link
        (b,) = [b for b, v in mech.bodies.items() if p in v["points"] and q in v["points"]]
        return b
    return mech.owner(g.line_point)



def prp_guides(mech, g):
    """The links carrying line a and line b of a PRP dyad."""
    def carrier(p, line_link):
        if line_link:
            P, Q = line_link
            (b,) = [b for b, v in mech.bodies.items() if P in v["points"] and Q in v["points"]]
            return b
        return mech.owner(p)

    return carrier(g.a, g.line_link_a), carrier(g.b, g.line_link_b)



class Motion:
    """Positions, velocities, accelerations (M, n, 2) of points and ω, ε (M, n) of
    links for coordinate rates Qd, Qdd (M, n, k) (None: at rest)."""

    def __init__(self, case, r, Qd=None, Qdd=None):
        self.case, self.r, self.mech = case, r, case.mech
        self.Qd, self.Qdd = Qd, Qdd

    def x(self, p):
        return _point(self.case, self.r, p)

    def v(self, p):
        return self.case.shaped(self.r.velocity(p, self.case.api_q(self.Qd)), 1)

    def a(self, p):
        return self.case.shaped(self.r.acceleration(p, self.case.api_q(self.Qd),
                                                    self.case.api_q(self.Qdd)), 1)

    def omega(self, body):
        pair = angle_pair(self.mech, body)
        if pair is None:
            return np.zeros(self.case.Q.shape[:2])
        d = self.x(pair[1]) - self.x(pair[0])
        return _cross(d, self.v(pair[1]) - self.v(pair[0])) / _dot(d, d)

    def epsilon(self, body):
        """dω/dt of the direction of two points (exact for a variable length too:
        ε = d×d̈/|d|² − 2(d·ḋ)(d×ḋ)/|d|⁴)."""
        pair = angle_pair(self.mech, body)
        if pair is None:
            return np.zeros(self.case.Q.shape[:2])
        d = self.x(pair[1]) - self.x(pair[0])
        dd = self.v(pair[1]) - self.v(pair[0])
        ddd = self.a(pair[1]) - self.a(pair[0])
        r2 = _dot(d, d)
        return _cross(d, ddd) / r2 - 2 * _dot(d, dd) * _cross(d, dd) / r2 ** 2

    def transmissions(self):
        """τ_j (M, n, k): largest |∂r/∂q_j| of a point, 1 m × |∂φ/∂q_j| of a link."""
        case, r, mech = self.case, self.r, self.mech
        out = np.zeros(case.Q.shape)
        J = {}
        for j, c in enumerate(mech.coordinates):
            for p in mech.points:
                J[p, j] = np.stack([case.shaped(r.dx(p, wrt=c)), case.shaped(r.dy(p, wrt=c))],
                                   -1)
                out[..., j] = np.maximum(out[..., j], _mag(J[p, j]))
            for b in mech.bodies:
                pair = angle_pair(mech, b)
                if pair is None:
                    continue
                d = self.x(pair[1]) - self.x(pair[0])
                w = _cross(d, J[pair[1], j] - J[pair[0], j]) / _dot(d, d)
                out[..., j] = np.maximum(out[..., j], ELL0 * np.abs(w))
        return out



def resolve_loads(mot, loads, dynamic):
    """The loads as point forces [(link, point, f (M, n, 2))] and moments
    [(link, M (M, n))], by the conventions documented in assur.core.loads."""
    shape = mot.case.Q.shape[:2]
    forces, couples = [], []

    def const(fx, fy):
        return np.broadcast_to(np.array([fx, fy], dtype=float), shape + (2,))

    for ld in loads:
        kind = ld[0]
        if kind == "weight":
            (p, b), P = ld[1], ld[2]
            forces.append((b, p, const(0.0, -P)))
        elif kind == "force":
            (p, b), fx, fy = ld[1], ld[2], ld[3]
            forces.append((b, p, const(fx, fy)))
        elif kind == "moment":
            couples.append((ld[1], np.full(shape, float(ld[2]))))
        elif kind == "spring":
            (pa, ba), (pb, bb), rate, free, pre = ld[1:]
            d = mot.x(pb) - mot.x(pa)
            L = _mag(d)
            T = pre + rate * (L - free)
            u = d / L[..., None]
            forces.append((ba, pa, T[..., None] * u))   # pulls a toward b
            forces.append((bb, pb, -T[..., None] * u))
        else:
            (p, b), m, J = ld[1], ld[2], ld[3]
            forces.append((b, p, const(0.0, -m * G)))
            if dynamic:
                forces.append((b, p, -m * mot.a(p)))
                couples.append((b, -J * mot.epsilon(b)))
    return forces, couples



# ---------------------------------------------------------------------------------
# the independent reference: all links at once
# ---------------------------------------------------------------------------------
def reference_statics(mot, forces, couples):
    """Reactions and actuator forces from the global equilibrium of all moving links.

    Joints, from the groups' definitions: an RRR dyad or cylinder–lever group has
    pins at its outer joints (to the links owning them) and at its middle joint; a
    crank a pin at its pivot and the drive moment T; a slider input a prismatic pair
    with the frame (normal force N, moment M, drive force F along the line); an RRP
    dyad pins at its outer joint and at the block, and a prismatic pair block–guide
    (N, M); an RPR dyad pins rod–owner(a) at a and sleeve–owner(b) at b and a
    prismatic pair rod–sleeve at b (N along the rod's normal, M); a PRP dyad
    prismatic pairs guide a–slider a and guide b–slider b at the pin (N along each
    line's normal, M) and a pin slider a–slider b. A cylinder (a link whose length is a coordinate) is two bodies, one at
    each end, joined by a prismatic pair whose axial force (positive pushing the
    ends apart) is the actuator force; a load at an end acts on that end's body.
    Each moving body: ΣF = 0 and ΣM = 0 about its own first point.

    Returns ``(joints, actuators)``: ``{(i, j): (point, force of i on j (M, n, 2),
    moment of i on j (M, n))}`` and ``{coordinate: F (M, n)}``.
    """
    case, mech = mot.case, mot.mech
    bodies = mech.bodies
    shape = case.Q.shape[:2]
    coords = mech.coordinates
    X = {p: mot.x(p) for p in mech.points}
    nodes = {}  # body key -> (row, centre point)

    def node(b, p=None):
        if b == "0":
            return None
        if bodies[b]["variable"]:
            p = p if p is not None else bodies[b]["points"][0]
            assert p in bodies[b]["points"][:2], (b, p)
            key = (b, p)
        else:
            key = (b,)
            p = bodies[b]["points"][0]
        if key not in nodes:
            nodes[key] = (3 * len(nodes), p)
        return key

    cols = []  # each: list of ("f", node, point, direction (M, n, 2)) / ("m", node, sign)
    joints = {}  # (i, j) -> (point, [(col, direction)], moment col or None)
    act = {}

    def is_coord(ref):
        return isinstance(ref, str) and ref in coords

    def column(*contribs):
        cols.append([c for c in contribs if c[1] is not None])
        return len(cols) - 1

    ex = np.broadcast_to(np.array([1.0, 0.0]), shape + (2,))
    ey = np.broadcast_to(np.array([0.0, 1.0]), shape + (2,))

    def pin(i, j, p):
        ni, nj = node(i, p), node(j, p)
        cx = column(("f", nj, p, ex), ("f", ni, p, -ex))
        cy = column(("f", nj, p, ey), ("f", ni, p, -ey))
        joints[(i, j)] = (p, [(cx, ex), (cy, ey)], None)

    def prism(guide, block, p, u, drive=None):
        ng, nb = node(guide, p), node(block, p)
        n = _perp(u)
        cn = column(("f", nb, p, n), ("f", ng, p, -n))
        cm = column(("m", nb, 1.0), ("m", ng, -1.0))
        parts = [(cn, n)]
        if drive is not None:
            cf = column(("f", nb, p, u), ("f", ng, p, -u))
            parts.append((cf, u))
            act[drive] = cf
        joints[(guide, block)] = (p, parts, cm)

    def cylinder(b, coord):
        P, Q = bodies[b]["points"][:2]
        d = X[Q] - X[P]
        e = d / _mag(d)[..., None]
        n = _perp(e)
        nP, nQ = node(b, P), node(b, Q)
        act[coord] = column(("f", nQ, Q, e), ("f", nP, Q, -e))
        column(("f", nQ, Q, n), ("f", nP, Q, -n))
        column(("m", nQ, 1.0), ("m", nP, -1.0))

    for g in mech.groups:
        if isinstance(g, (Dyad, CylinderLever)):
            la, lb = g.links
            pin(mech.owner(g.a), la, g.a)
            pin(la, lb, g.out)
            pin(mech.owner(g.b), lb, g.b)
            for link, ref in ((la, g.ra), (lb, g.rb)):
                if is_coord(ref):
                    cylinder(link, ref)
        elif isinstance(g, Crank):
            (l,) = g.links
            pin(mech.owner(g.pivot), l, g.pivot)
            act[g.q] = column(("m", node(l), 1.0), ("m", node(mech.owner(g.pivot)), -1.0))
            p, parts, _ = joints[(mech.owner(g.pivot), l)]
            joints[(mech.owner(g.pivot), l)] = (p, parts, act[g.q])
        elif isinstance(g, SliderInput):
            (l,) = g.links
            beta = np.broadcast_to(case.val(g.direction), shape)
            prism(mech.owner(g.origin), l, g.out, _dir(beta), drive=g.s)
        elif isinstance(g, SliderDyad):
            la, lb = g.links
            pin(mech.owner(g.a), la, g.a)
            pin(la, lb, g.out)
            prism(guide_of(mech, g), lb, g.out, _line_dir(case, mot.r, g))
            if is_coord(g.radius):
                cylinder(la, g.radius)
        elif isinstance(g, SleeveDyad):
            rod, sleeve = g.links
            pin(mech.owner(g.a), rod, g.a)
            pin(mech.owner(g.b), sleeve, g.b)
            # the sleeve (at its pivot b) slides along the rod's line a → out
            d = X[g.out] - X[g.a]
            prism(rod, sleeve, g.b, d / _mag(d)[..., None])
        elif isinstance(g, DoubleSliderDyad):
            la, lb = g.links
            ga, gb = prp_guides(mech, g)
            ua, ub = _prp_dirs(case, mot.r, g)
            prism(ga, la, g.out, ua)
            prism(gb, lb, g.out, ub)
            pin(la, lb, g.out)
    # loads: assign nodes first so that every body has its rows
    rhs_items = [(node(b, p), p, f) for b, p, f in forces] + \
        [(node(b), None, M) for b, M in couples]
    neq, nunk = 3 * len(nodes), len(cols)
    assert neq == nunk, f"reference system {neq} equations, {nunk} unknowns"
    A = np.zeros(shape + (neq, nunk))
    rhs = np.zeros(shape + (neq,))

    def wrench(key, p, f):
        row, c = nodes[key]
        return row, (f[..., 0], f[..., 1], _cross(X[p] - X[c], f))

    for ci, contribs in enumerate(cols):
        for c in contribs:
            if c[0] == "f":
                row, w = wrench(c[1], c[2], c[3])
                for k in range(3):
                    A[..., row + k, ci] += w[k]
            else:
                A[..., nodes[c[1]][0] + 2, ci] += c[2]
    for key, p, f in rhs_items:
        if key is None:
            continue
        if p is None:
            rhs[..., nodes[key][0] + 2] -= f
        else:
            row, w = wrench(key, p, f)
            for k in range(3):
                rhs[..., row + k] -= w[k]
    sol = np.linalg.solve(A, rhs[..., None])[..., 0]
    out = {}
    for (i, j), (p, parts, cm) in joints.items():
        F = sum(sol[..., c][..., None] * d for c, d in parts)
        out[(i, j)] = (p, F, sol[..., cm] if cm is not None else np.zeros(shape))
    return out, {c: sol[..., col] for c, col in act.items()}



# ---------------------------------------------------------------------------------
# the checks
# ---------------------------------------------------------------------------------
def load_scale(forces, couples, shape):
    S = np.zeros(shape)
    for _, _, f in forces:
        S = S + _mag(f)
    for _, M in couples:
        S = S + np.abs(M) / ELL0
    return S



class Solved:
    """assur's statics for one load set, with the scales of the module docstring."""

    def __init__(self, case, loads, Qd, Qdd, analyze=False):
        self.case, self.loads = case, loads
        self.mech = with_loads(case.mech, loads)
        kw = {}
        if Qd is not None:
            kw = dict(qdot=case.api_q(Qd), qddot=case.api_q(Qdd))
        q = case.api_q(case.Q)
        if analyze:
            an = self.mech.analyze(q, on_failure="report", check_continuity=False, **kw)
            self.r, self.st = an.kinematics, an.statics
        else:
            self.r = self.mech.solve(q, on_failure="report", check_continuity=False)
            self.st = statics.solve(self.r, **kw)
        assert self.r.ok.all()
        self.mot = Motion(case, self.r, Qd, Qdd)
        self.forces, self.couples = resolve_loads(self.mot, loads, Qd is not None)
        shape = case.Q.shape[:2]
        self.S = load_scale(self.forces, self.couples, shape)
        self.tau = self.mot.transmissions()
        self.A = self.S[..., None] * self.tau  # (M, n, k)
        self.R = self.S.copy()
        for p, i, j in self.st.joints:
            self.R = np.maximum(self.R, _mag(self.reaction(i, j)))
            self.R = np.maximum(self.R, np.abs(self.moment(i, j)) / ELL0)
        ell = np.full(shape, ELL0)
        for p in self.mech.points:
            ell = np.maximum(ell, _mag(self.mot.x(p)))
        self.ell = ell

    def reaction(self, i, j):
        return self.case.shaped(self.st.reaction(i, j), 1)

    def moment(self, i, j):
        return self.case.shaped(self.st.reaction_moment(i, j))

    def vw(self, c):
        return self.case.shaped(self.st.actuator_force(c))

    def rx(self, c):
        return self.case.shaped(self.st.actuator_force_from_reactions(c))



def _assert_close(what, a, b, tol, where):
    """|a − b| <= tol elementwise; returns the worst |a − b|/tol."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    tol = np.maximum(tol, 1e-250)  # all loads zero: only (denormal) rounding is left
    if a.ndim > tol.ndim:
        err = np.abs(a - b).max(axis=tuple(range(tol.ndim, a.ndim)))
    else:
        err = np.abs(a - b)
    ratio = err / np.maximum(tol, 1e-300)
    if not (err <= tol).all():
        idx = np.unravel_index(np.argmax(ratio), ratio.shape)
        raise AssertionError(
            f"{what} at design {idx[0]}, position {idx[1]}: {a[idx]!r} vs {b[idx]!r}, "
            f"|diff| = {err[idx]:.3g} > tol {tol[idx]:.3g}\n{where()}")
    return float(ratio.max())



def reproducer(case, loads, Qd, Qdd):
    lines = ["from assur import statics", case.reproducer()] + loads_code(loads, case.mech)
    lines.append("r = m.solve(q, on_failure='report', check_continuity=False)")
    if Qd is None:
        lines.append("st = statics.solve(r)")
    else:
        lines.append(f"st = statics.solve(r, qdot=np.array({case.api_q(Qd).tolist()!r}), "
                     f"qddot=np.array({case.api_q(Qdd).tolist()!r}))")
    return "\n".join(lines)



def draw_rates(data, case):
    """Random q̇, q̈ (M, n, k): |q̇_j| ∈ [0.2, 2]·scale_j /s, |q̈_j| ≤ 10·scale_j /s²."""
    shape = case.Q.shape
    size = int(np.prod(shape))

    def arr(lo, hi, label):
        return np.array(data.draw(st.lists(_floats(lo, hi), min_size=size, max_size=size),
                                  label=label)).reshape(shape)

    sign = np.where(arr(-1.0, 1.0, "sign of q̇") < 0, -1.0, 1.0)
    sc = case.scale[:, None, :]
    return sign * arr(0.2, 2.0, "|q̇| / scale") * sc, arr(-10.0, 10.0, "q̈ / scale") * sc



def check_statics(case, data, extra_loads=(), rod_end_loads=False):
    """Checks 1–5 of the module docstring on one random mechanism with random loads.
    ``extra_loads`` are added to the first load set (the bug test's rod-end load)."""
    mech = case.mech
    loads_a = draw_loads(data, mech, "set A", rod_end_loads) + list(extra_loads)
    loads_b = draw_loads(data, mech, "set B", rod_end_loads)
    dynamic = data.draw(st.booleans(), label="with inertia (q̇, q̈)")
    Qd, Qdd = draw_rates(data, case) if dynamic else (None, None)
    lam = data.draw(st.sampled_from((-1.0, 1.0)), label="sign of λ") * \
        data.draw(_floats(0.2, 3.0), label="|λ|")
    both = loads_a + loads_b
    assume_springs_long(case, both)
    full = Solved(case, both, Qd, Qdd, analyze=True)

    def where():
        return reproducer(case, both, Qd, Qdd)

    # 4. reference: joints, reactions, prismatic and drive moments
    ref, ref_act = reference_statics(full.mot, full.forces, full.couples)
    got = {frozenset((i, j)): p for p, i, j in full.st.joints}
    want = {frozenset(ij): p for ij, (p, _, _) in ref.items()}
    assert got == want, f"joints {full.st.joints} != reference {sorted(ref)}\n{where()}"
    for p, F, Mz in ref.values():  # the scale: the larger of assur's and the reference's
        full.R = np.maximum(full.R, np.maximum(_mag(F), np.abs(Mz) / ELL0))
    tolR = RTOL_REF * full.R
    w_ref = 0.0
    for (i, j), (p, F, Mz) in ref.items():
        w_ref = max(w_ref, _assert_close(f"reaction of {i} on {j} at {p} vs reference",
                                         full.reaction(i, j), F, tolR, where))
        w_ref = max(w_ref, _assert_close(f"moment of {i} on {j} at {p} vs reference",
                                         full.moment(i, j) / ELL0, Mz / ELL0, tolR, where))
        assert np.array_equal(full.reaction(j, i), -full.reaction(i, j))
    # 1. virtual work = reactions; and = the reference's actuator forces
    w_vw = 0.0
    for jc, c in enumerate(mech.coordinates):
        tolA = full.A[..., jc]
        w_ref = max(w_ref, _assert_close(f"actuator force {c}: virtual work vs reference",
                                         full.vw(c), ref_act[c], RTOL_REF * tolA, where))
        w_vw = max(w_vw, _assert_close(f"actuator force {c}: virtual work vs reactions",
                                       full.vw(c), full.rx(c), RTOL_VW * tolA, where))
    # 2. equilibrium of every moving link
    fres, mres = (full.case.shaped(a) for a in full.st.equilibrium_residual())
    w_eq = max(_assert_close("|ΣF| of a link", fres, 0.0, RTOL_EQ * full.R, where),
               _assert_close("|ΣM| of a link", mres, 0.0, RTOL_EQ * full.R * full.ell, where))
    # 5. superposition A + B and scaling by λ
    sa = Solved(case, loads_a, Qd, Qdd)
    sb = Solved(case, loads_b, Qd, Qdd)
    sl = scaled(case, both, lam, Qd, Qdd)
    w_lin = 0.0
    tolR = RTOL_LIN * (sa.R + sb.R + full.R)
    for p, i, j in full.st.joints:
        w_lin = max(w_lin, _assert_close(
            f"superposition: reaction of {i} on {j}", full.reaction(i, j),
            sa.reaction(i, j) + sb.reaction(i, j), tolR, where))
        w_lin = max(w_lin, _assert_close(
            f"superposition: moment of {i} on {j}", full.moment(i, j) / ELL0,
            (sa.moment(i, j) + sb.moment(i, j)) / ELL0, tolR, where))
        w_lin = max(w_lin, _assert_close(
            f"scaling by λ = {lam}: reaction of {i} on {j}", sl.reaction(i, j),
            lam * full.reaction(i, j), (1 + abs(lam)) * RTOL_LIN * full.R, where))
    for jc, c in enumerate(mech.coordinates):
        tolA = RTOL_LIN * (sa.A + sb.A + full.A)[..., jc]
        for name, get in (("virtual work", Solved.vw), ("reactions", Solved.rx)):
            w_lin = max(w_lin, _assert_close(f"superposition: actuator force {c} ({name})",
                                             get(full, c), get(sa, c) + get(sb, c), tolA,
                                             where))
            w_lin = max(w_lin, _assert_close(
                f"scaling by λ = {lam}: actuator force {c} ({name})", get(sl, c),
                lam * get(full, c), (1 + abs(lam)) * RTOL_LIN * full.A[..., jc], where))
    # 3. power balance
    w_pow = power_balance(full, Qd, Qdd, where) if dynamic else 0.0
    worst = {"virtual work vs reactions": w_vw, "assur vs reference": w_ref,
             "equilibrium residual": w_eq, "linearity": w_lin, "power balance": w_pow}
    for key, w in worst.items():
        WORST[key] = max(WORST.get(key, 0.0), w)
    # one target (several make hypothesis keep a costly Pareto front)
    target(max(worst.values()), label="worst |error| / tolerance of all checks")
    return full



def scaled(case, loads, lam, Qd, Qdd):
    """assur's statics with every load scaled by ``lam`` (no scales computed)."""
    s = Solved.__new__(Solved)
    s.case, s.loads = case, loads
    s.mech = with_loads(case.mech, loads, lam)
    s.r = s.mech.solve(case.api_q(case.Q), on_failure="report", check_continuity=False)
    kw = {} if Qd is None else dict(qdot=case.api_q(Qd), qddot=case.api_q(Qdd))
    s.st = statics.solve(s.r, **kw)
    return s



def energy(case, loads, mot, X0):
    """T + V − (T + V at t = 0) for the motion ``mot`` (positions relative to X0, the
    positions at t = 0; velocities v0 at t = 0), shape (M, n) — every term formed
    as a difference so that it stays small."""
    E = np.zeros(mot.case.Q.shape[:2])
    for ld in loads:
        kind = ld[0]
        if kind == "weight":
            (p, _), P = ld[1], ld[2]
            E = E + P * (mot.x(p)[..., 1] - X0[p][0][..., 1])
        elif kind == "spring":
            (pa, _), (pb, _), rate, free, pre = ld[1:]
            L = _mag(mot.x(pb) - mot.x(pa))
            L0 = _mag(X0[pb][0] - X0[pa][0])
            dL = L - L0
            E = E + pre * dL + 0.5 * rate * dL * (L + L0 - 2 * free)
        elif kind == "mass":
            (p, b), m, J = ld[1], ld[2], ld[3]
            v, v0 = mot.v(p), X0[p][1]
            w, w0 = mot.omega(b), X0[b]
            E = E + m * G * (mot.x(p)[..., 1] - X0[p][0][..., 1]) \
                + 0.5 * m * _dot(v - v0, v + v0) + 0.5 * J * (w - w0) * (w + w0)
    return E



def power_balance(full, Qd, Qdd, where):
    """Σ F_j q̇_j = d(T + V)/dt − Σ F·v − Σ M·ω at t = 0 (module docstring, item 3)."""
    case, loads, mot = full.case, full.loads, full.mot
    M, n, k = case.Q.shape
    # time step: no coordinate moves by more than tests.helpers.analogs' FD step, 1e-4
    # of the length over which the analogs change (near an assembly limit ≪ scale)
    hq = fd_steps(case, analogs(case, mot.r))  # (M, n, k)
    with np.errstate(over="ignore"):  # a tiny q̈ drawn: no limit (inf)
        t1 = np.divide(hq, np.abs(Qd), out=np.full(hq.shape, np.inf), where=Qd != 0)
        t2 = np.sqrt(np.divide(2 * hq, np.abs(Qdd), out=np.full(hq.shape, np.inf),
                               where=Qdd != 0))
    h = np.minimum(t1, t2).min(-1)  # (M, n) time step [s]
    for ld in loads:  # and no spring turns by more than 1e-4 rad
        if ld[0] == "spring":
            (pa, _), (pb, _) = ld[1], ld[2]
            vr = _mag(mot.v(pb) - mot.v(pa))
            L = _mag(mot.x(pb) - mot.x(pa))
            with np.errstate(over="ignore"):
                h = np.minimum(h, np.divide(1e-4 * L, vr, out=np.full(h.shape, np.inf),
                                            where=vr > 0))
    steps = (1.0, -1.0, 2.0, -2.0)
    t = np.stack([s * h for s in steps], 1)[..., None]  # (M, 4, n, 1)
    Qn = case.Q[:, None] + Qd[:, None] * t + 0.5 * Qdd[:, None] * t * t
    Qdn = Qd[:, None] + Qdd[:, None] * t
    nb = replace(case, Q=Qn.reshape(M, 4 * n, k))
    rn = nb.solve()
    assert rn.ok.all(), f"a neighbouring instant does not assemble\n{where()}"
    mn = Motion(nb, rn, Qdn.reshape(M, 4 * n, k), None)
    bodies = [b for b in case.mech.bodies if b != "0"]
    def four(a):  # t = 0 values in the order of the neighbours (instant-major)
        return np.concatenate([a] * 4, axis=1)

    X0 = {p: (four(mot.x(p)), four(mot.v(p))) for p in case.mech.points}
    X0.update({b: four(mot.omega(b)) for b in bodies})
    E = energy(case, loads, mn, X0).reshape(M, 4, n)
    dEdt = (8 * (E[:, 0] - E[:, 1]) - (E[:, 2] - E[:, 3])) / (12 * h)
    # non-conservative applied power, actuator power, and the scale of all terms
    P_nc = np.zeros((M, n))
    scale = np.zeros((M, n))
    for ld in loads:
        kind = ld[0]
        if kind == "force":
            (p, _), fx, fy = ld[1], ld[2], ld[3]
            v = mot.v(p)
            P_nc = P_nc + fx * v[..., 0] + fy * v[..., 1]
            scale = scale + math.hypot(fx, fy) * _mag(v)
        elif kind == "moment":
            w = mot.omega(ld[1])
            P_nc = P_nc + ld[2] * w
            scale = scale + abs(ld[2]) * np.abs(w)
        elif kind == "weight":
            scale = scale + ld[2] * _mag(mot.v(ld[1][0]))
        elif kind == "spring":
            (pa, _), (pb, _), rate_, free, pre = ld[1:]
            d = mot.x(pb) - mot.x(pa)
            L = _mag(d)
            scale = scale + np.abs(pre + rate_ * (L - free)) * _mag(mot.v(pb) - mot.v(pa))
        else:
            (p, b), m, J = ld[1], ld[2], ld[3]
            v = mot.v(p)
            scale = scale + m * (G + _mag(mot.a(p))) * _mag(v) \
                + J * np.abs(mot.epsilon(b) * mot.omega(b))
    # floor: every load at the largest speed (the rounding of T + V is far below)
    speed = np.zeros((M, n))
    for p in case.mech.points:
        speed = np.maximum(speed, _mag(mot.v(p)))
    for b in bodies:
        speed = np.maximum(speed, ELL0 * np.abs(mot.omega(b)))
    scale = scale + full.S * speed
    P_act = np.zeros((M, n))
    for jc, c in enumerate(case.mech.coordinates):
        P_act = P_act + full.vw(c) * Qd[..., jc]
        scale = scale + np.abs(full.vw(c) * Qd[..., jc])
    return _assert_close("power balance: Σ F·q̇ vs d(T + V)/dt − Σ F·v − Σ M·ω", P_act,
                         dEdt - P_nc, RTOL_POWER * scale, where)



FAMILIES = {"cylinder-lever": cylinder_lever_family, "crank": crank_family,
            "slider": slider_family, "cylinder radius (k = 2)": cylinder_radius_family,
            "RRP": rrp_family, "RPR": rpr_family, "PRP": prp_family}

