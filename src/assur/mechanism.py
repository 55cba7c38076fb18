"""The :class:`Mechanism`: frame points, an ordered list of structural groups,
named links, and the parameters they refer to.

A mechanism is a plain description; :meth:`Mechanism.solve` compiles it into the
program run by :mod:`assur._kernel` and returns a :class:`assur.kinematics.Kinematics`
result. Every parameter may be a scalar or an array over designs, shape ``(m,)``;
generalized coordinates are arrays of shape ``(n,)`` (one design) or ``(m, n)``
(a batch of designs), see DESIGN.md §1–2.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from types import MappingProxyType
from typing import Iterable, Mapping

import numpy as np

from . import _kernel as K
from .errors import AssemblyError, ModelError
from .groups import Crank, CylinderLever, Distance, Dyad, Frame, Group, Link, RigidPoint, \
    SliderDyad, SliderInput



def _fmt(v):
    return f"{float(v):.6g}"


def _is_number(x):
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, bool)


@dataclass(frozen=True)
class PosePoint:
    """Rigid point whose offset ``(dx, dy)`` from ``origin`` is known at one pose.

    Seed 003 fixes the implement's centre of mass S6 by its offset (X6, Y6) from the
    suspension axis 56 at the working stroke S = Sp:
    ``φS6 = 2π + atan(Y6/X6) − φ6(Sp)``, ``LS6 = √(X6² + Y6²)``. The angle and
    length are derived per design by a pre-pass at the pose.
    """

    name: str
    origin: str
    toward: str
    out: str
    dx: object
    dy: object
    at: tuple
    links: tuple[str, ...] = ()
    kind = "rigid point fixed at a pose"

    def inputs(self):
        return (self.origin, self.toward)

    def outputs(self):
        return (self.out,)

    def refs(self):
        return {"dx": self.dx, "dy": self.dy}

    def group_links(self):
        return tuple(self.links)


class Mechanism:
    """A planar linkage: frame points, structural groups in solving order, links.

    Parameters
    ----------
    name : str
        Name of the machine (e.g. ``"hitch_003"``).
    coordinates : sequence of str
        Names of the k generalized coordinates (cylinder lengths [m] or crank
        angles [rad]), e.g. ``("S",)``.
    params : mapping of str to float or array_like, shape (m,)
        Named parameters [SI units: m, rad]. Arrays make a batch of ``m`` designs.
    title : str, optional
        Human title for reports.

    Examples
    --------
    >>> from assur import Mechanism
    >>> m = Mechanism("fourbar", coordinates=("S",), params={"L3": 0.2})
    >>> m = m.frame("01", 0.415, 0.563).frame("03", 0.25, 1.112)
    >>> m = m.cylinder_lever("lever", base="01", pivot="03", out="23", lever="L3",
    ...                      s="S", branch=-1, links=("2", "3"))
    >>> m = m.link("3", "03", "23")
    >>> r = m.solve([0.42, 0.67])
    >>> [round(float(v), 1) for v in r.phi("3", degrees=True)]
    [-40.2, 37.2]
    """

    def __init__(self, name: str, coordinates: Iterable[str] = ("S",),
                 params: Mapping[str, object] | None = None, title: str | None = None,
                 groups: Iterable = (), links: Iterable[Link] = (),
                 distances: Iterable[Distance] = (), tables: Mapping | None = None,
                 notes: Iterable[str] = (), loads: Iterable = (), cylinders: Iterable = (),
                 machine=None):
        self.name = name
        self.title = title or name
        self.coordinates = tuple(coordinates)
        if not self.coordinates:
            raise ModelError(f"mechanism {name!r}: at least one generalized coordinate is needed")
        if len(set(self.coordinates)) != len(self.coordinates):
            raise ModelError(f"mechanism {name!r}: duplicate coordinate names {self.coordinates}")
        self.params = MappingProxyType(dict(params or {}))
        self.groups = tuple(groups)
        self.links = tuple(links)
        self.distances = tuple(distances)
        #: what :meth:`Kinematics.to_frame` tabulates: ``ratios`` (pairs), ``transmissions``
        self.tables = MappingProxyType(dict(tables or {}))
        #: notes on seed slips resolved in this model (shown in reports)
        self.notes = tuple(notes)
        #: applied loads (:mod:`assur.loads`): weights, forces, moments, springs, masses
        self.loads = tuple(loads)
        #: hydraulic cylinders acting as generalized coordinates (:class:`assur.loads.Cylinder`)
        self.cylinders = tuple(cylinders)
        #: machine data for stability (:class:`assur.stability.Machine`) or None
        self.machine = machine
        self._validate()

    # ---- building (each returns a new mechanism) -------------------------------
    def _with(self, **kw):
        d = dict(name=self.name, coordinates=self.coordinates, params=self.params,
                 title=self.title, groups=self.groups, links=self.links,
                 distances=self.distances, tables=self.tables, notes=self.notes,
                 loads=self.loads, cylinders=self.cylinders, machine=self.machine)
        d.update(kw)
        return Mechanism(**d)

    def add(self, *groups) -> "Mechanism":
        """Return a mechanism with ``groups`` appended (solved after the existing ones)."""
        return self._with(groups=self.groups + tuple(groups))

    def frame(self, name, x, y) -> "Mechanism":
        """Add a frame pivot at ``(x, y)`` [m] (numbers or parameter names)."""
        return self.add(Frame(name=name, x=x, y=y))

    def cylinder_lever(self, name, **kw) -> "Mechanism":
        """Add a :class:`~assur.groups.CylinderLever` input group."""
        kw["links"] = tuple(kw.get("links", ()))
        return self.add(CylinderLever(name=name, **kw))

    def dyad(self, name, **kw) -> "Mechanism":
        """Add an RRR :class:`~assur.groups.Dyad`."""
        kw["links"] = tuple(kw.get("links", ()))
        return self.add(Dyad(name=name, **kw))

    def crank(self, name, **kw) -> "Mechanism":
        """Add a :class:`~assur.groups.Crank` input."""
        kw["links"] = tuple(kw.get("links", ()))
        return self.add(Crank(name=name, **kw))

    def slider_input(self, name, **kw) -> "Mechanism":
        """Add a :class:`~assur.groups.SliderInput` (prismatic input)."""
        kw["links"] = tuple(kw.get("links", ()))
        return self.add(SliderInput(name=name, **kw))

    def slider_dyad(self, name, **kw) -> "Mechanism":
        """Add an RRP :class:`~assur.groups.SliderDyad`."""
        kw["links"] = tuple(kw.get("links", ()))
        if kw.get("line_link") is not None:
            kw["line_link"] = tuple(kw["line_link"])
        return self.add(SliderDyad(name=name, **kw))

    def rigid_point(self, name, **kw) -> "Mechanism":
        """Add a :class:`~assur.groups.RigidPoint` on a link."""
        kw["links"] = tuple(kw.get("links", ()))
        return self.add(RigidPoint(name=name, **kw))

    def pose_point(self, name, *, origin, toward, out, dx, dy, at, links=()) -> "Mechanism":
        """Add a rigid point known by its offset ``(dx, dy)`` [m] from ``origin`` at the
        pose where the generalized coordinates equal ``at`` (see :class:`PosePoint`)."""
        at = tuple(at) if isinstance(at, (tuple, list)) else (at,)
        return self.add(PosePoint(name=name, origin=origin, toward=toward, out=out, dx=dx,
                                  dy=dy, at=at, links=tuple(links)))

    def link(self, name, tail, head) -> "Mechanism":
        """Name the link whose angle φ_name is the direction ``tail → head``."""
        return self._with(links=self.links + (Link(name, tail, head),))

    def distance(self, name, a, b) -> "Mechanism":
        """Name the distance |a–b| [m] (e.g. a dependent cylinder length)."""
        return self._with(distances=self.distances + (Distance(name, a, b),))

    # ---- loads and actuators ---------------------------------------------------
    def weight(self, point, P, link=None, name=None) -> "Mechanism":
        """Add a weight ``P`` [N] acting downward at ``point`` (see :mod:`assur.loads`)."""
        from .loads import Weight
        return self._with(loads=self.loads + (Weight(point, P, link, name),))

    def force(self, point, fx=0.0, fy=0.0, link=None, name=None) -> "Mechanism":
        """Add a force ``(fx, fy)`` [N] at ``point``."""
        from .loads import PointForce
        return self._with(loads=self.loads + (PointForce(point, fx, fy, link, name),))

    def moment(self, link, M, name=None) -> "Mechanism":
        """Add a moment ``M`` [N·m] (counter-clockwise positive) on ``link``."""
        from .loads import Couple
        return self._with(loads=self.loads + (Couple(link, M, name),))

    def spring(self, name, a, b, rate, free_length, preload=0.0, links=None) -> "Mechanism":
        """Add a spring between points ``a`` and ``b`` (rate [N/m], free length [m],
        preload [N]); tension pulls the points together."""
        from .loads import Spring
        links = tuple(links) if links else None
        return self._with(loads=self.loads + (Spring(name, a, b, rate, free_length, preload,
                                                     links),))

    def mass(self, link, m, point, J=0.0) -> "Mechanism":
        """Give ``link`` a mass ``m`` [kg] at ``point`` and inertia ``J`` [kg·m²]."""
        from .loads import Mass
        return self._with(loads=self.loads + (Mass(link, m, point, J),))

    def cylinder(self, name, coordinate, **kw) -> "Mechanism":
        """Add hydraulic cylinder data for a coordinate (see :class:`assur.loads.Cylinder`)."""
        from .loads import Cylinder
        return self._with(cylinders=self.cylinders + (Cylinder(name, coordinate, **kw),))

    def with_machine(self, machine, point, weight, seed_gs6max=None, refs=None) -> "Mechanism":
        """Carry the implement (weight [N] at ``point``) on a machine for the stability
        analysis (:class:`assur.stability.Machine`, :class:`assur.stability.Carrying`);
        ``refs`` ties the machine's positions and weights to parameters."""
        from .stability import Carrying
        return self._with(machine=Carrying(machine, point, weight, seed_gs6max, refs))

    def with_params(self, **values) -> "Mechanism":
        """Return a copy with some parameters replaced (scalars or arrays over designs)."""
        unknown = sorted(set(values) - set(self.params))
        if unknown:
            raise ModelError(f"mechanism {self.name!r}: unknown parameter(s) {unknown}; "
                             f"known: {sorted(self.params)}")
        p = dict(self.params)
        p.update(values)
        return self._with(params=p)

    def with_tables(self, **tables) -> "Mechanism":
        t = dict(self.tables)
        t.update(tables)
        return self._with(tables=t)

    # ---- introspection ---------------------------------------------------------
    @property
    def points(self) -> tuple[str, ...]:
        """Names of all points in solving order (frame points first as declared)."""
        return tuple(p for g in self.groups for p in g.outputs())

    @property
    def frame_points(self) -> tuple[str, ...]:
        return tuple(g.name for g in self.groups if isinstance(g, Frame))

    def group(self, name) -> Group:
        for g in self.groups:
            if g.name == name:
                return g
        raise KeyError(f"no group {name!r} in mechanism {self.name!r}")

    def _validate(self):
        known: set[str] = set()
        names: set[str] = set()
        for g in self.groups:
            if g.name in names and not isinstance(g, Frame):
                raise ModelError(f"mechanism {self.name!r}: duplicate group name {g.name!r}")
            names.add(g.name)
            for p in g.inputs():
                if p not in known:
                    raise ModelError(
                        f"mechanism {self.name!r}: {g.kind} {g.name!r} needs point {p!r}, which "
                        f"no earlier group defines (known: {sorted(known)})")
            for p in g.outputs():
                if p in known:
                    raise ModelError(f"mechanism {self.name!r}: point {p!r} is defined twice "
                                     f"(again by {g.kind} {g.name!r})")
                known.add(p)
            for role, ref in g.refs().items():
                self._check_ref(g, role, ref)
            br = getattr(g, "branch", 1)
            if br not in (1, -1):
                raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r}: branch must be "
                                 f"+1 or -1, got {br!r}")
            for attr in ("angle", "s"):
                if isinstance(g, (Crank, SliderInput)) and hasattr(g, attr):
                    v = getattr(g, attr)
                    if v not in self.coordinates:
                        raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r}: {attr}="
                                         f"{v!r} is not a generalized coordinate "
                                         f"{self.coordinates}")
        for obj in self.links + self.distances:
            ends = (obj.tail, obj.head) if isinstance(obj, Link) else (obj.a, obj.b)
            for p in ends:
                if p not in known:
                    raise ModelError(f"mechanism {self.name!r}: link/distance {obj.name!r} refers "
                                     f"to unknown point {p!r} (known: {sorted(known)})")
        self._bodies = self._topology()
        self._validate_loads(known)
        lnames = [l.name for l in self.links] + [d.name for d in self.distances]
        dup = {n for n in lnames if lnames.count(n) > 1}
        if dup:
            raise ModelError(f"mechanism {self.name!r}: duplicate link/distance names {sorted(dup)}")
        for n, v in self.params.items():
            a = np.asarray(v, dtype=float)
            if a.ndim > 1 or not np.all(np.isfinite(a)):
                raise ModelError(f"mechanism {self.name!r}: parameter {n!r} must be a finite "
                                 f"number or a 1-D array over designs, got {v!r}")

    def _validate_loads(self, known):
        from .loads import Couple, Cylinder, Mass, PointForce, Spring, Weight
        where = f"mechanism {self.name!r}"

        def ref_ok(what, ref):
            if _is_number(ref):
                if not math.isfinite(float(ref)):
                    raise ModelError(f"{where}: {what} = {ref!r} is not finite")
            elif not (isinstance(ref, str) and ref in self.params):
                raise ModelError(f"{where}: {what} refers to {ref!r}, which is not a parameter "
                                 f"{sorted(self.params)}")

        def point_ok(what, p):
            if p not in known:
                raise ModelError(f"{where}: {what} is at unknown point {p!r} (known: "
                                 f"{sorted(known)})")

        def link_ok(what, l):
            if l is not None and l not in self._bodies:
                raise ModelError(f"{where}: {what} acts on unknown link {l!r} (links: "
                                 f"{sorted(self._bodies)})")

        for ld in self.loads:
            if isinstance(ld, Weight):
                point_ok("weight", ld.point)
                ref_ok(f"weight at {ld.point}", ld.P)
                link_ok("weight", ld.link)
            elif isinstance(ld, PointForce):
                point_ok("force", ld.point)
                ref_ok(f"force at {ld.point}: fx", ld.fx)
                ref_ok(f"force at {ld.point}: fy", ld.fy)
                link_ok("force", ld.link)
            elif isinstance(ld, Couple):
                link_ok("moment", ld.link)
                ref_ok(f"moment on {ld.link}", ld.M)
            elif isinstance(ld, Spring):
                point_ok(f"spring {ld.name!r}", ld.a)
                point_ok(f"spring {ld.name!r}", ld.b)
                for r in (ld.rate, ld.free_length, ld.preload):
                    ref_ok(f"spring {ld.name!r}", r)
                for l in ld.links or ():
                    link_ok(f"spring {ld.name!r}", l)
            elif isinstance(ld, Mass):
                link_ok("mass", ld.link)
                point_ok(f"mass of link {ld.link}", ld.point)
                ref_ok(f"mass of link {ld.link}", ld.m)
                ref_ok(f"inertia of link {ld.link}", ld.J)
            else:
                raise ModelError(f"{where}: unknown load {ld!r}")
        if self.machine is not None:
            point_ok("the machine's implement", self.machine.point)
            for t in self.machine.ref_names():
                ref_ok("the machine's data", t)
            ref_ok("the machine's implement weight", self.machine.weight)
            for k, v in (self.machine.seed_gs6max or {}).items():
                ref_ok(f"seed GS6max {k}", v)
        seen = set()
        for c in self.cylinders:
            if not isinstance(c, Cylinder):
                raise ModelError(f"{where}: cylinders must be assur.loads.Cylinder, got {c!r}")
            if c.coordinate not in self.coordinates:
                raise ModelError(f"{where}: cylinder {c.name!r} drives {c.coordinate!r}, which is "
                                 f"not a generalized coordinate {list(self.coordinates)}")
            if c.coordinate in seen:
                raise ModelError(f"{where}: two cylinder entries drive {c.coordinate!r}")
            seen.add(c.coordinate)
            if c.side not in ("piston", "rod"):
                raise ModelError(f"{where}: cylinder {c.name!r}: side must be one of: "
                                 f"['piston', 'rod'], got {c.side!r}")
            for f in ("bore", "rod", "count", "eta_mech", "eta_hyd", "p_relief", "dp_throttle",
                      "dp_line"):
                ref_ok(f"cylinder {c.name!r}: {f}", getattr(c, f))

    def owner(self, point):
        """The link that owns ``point``: loads at the point and later groups attached
        there act on it. Frame points belong to "0"; a dyad's middle joint to its
        second link; a rigid point to its link; a crank or slider end to the crank
        or slider."""
        return self._owner[point]

    @property
    def bodies(self):
        """Rigid bodies: ``{name: {"points": [...], "variable": bool}}``; the frame is "0".

        Derived from the groups: a dyad's two links (a link whose length is a
        generalized coordinate — a cylinder — is ``variable``), the lever and the
        cylinder of the cylinder–lever group, a crank, a slider, and the points
        that rigid points add to existing links. Links not named in a group get
        the name ``"<group>:a"``/``":b"``.
        """
        return {k: {"points": list(v["points"]), "variable": v["variable"]}
                for k, v in self._bodies.items()}

    def _topology(self):
        bodies: dict = {"0": {"points": [], "variable": False}}
        owner: dict = {}
        self._owner = owner
        self._group_links = {}

        def new(name, g, points, variable=False):
            if name in bodies:
                raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r} names its link "
                                 f"{name!r}, but an earlier group already has a link of that "
                                 f"name (a group adds new links; name them uniquely)")
            bodies[name] = {"points": list(points), "variable": variable}

        def names(g, n):
            given = tuple(getattr(g, "links", ()) or ())
            if given and len(given) != n:
                raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r} has {n} link(s), "
                                 f"got links={given!r}")
            return given or tuple(f"{g.name}:{c}" for c in "ab"[:n])

        def is_coord(ref):
            return isinstance(ref, str) and ref in self.coordinates

        def carrier(g, p, q, given):
            """The one rigid body that holds both p and q."""
            cands = [b for b, v in bodies.items() if p in v["points"] and q in v["points"]]
            if given:
                if given[0] not in bodies:
                    raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r}: link "
                                     f"{given[0]!r} is not defined by an earlier group")
                if given[0] not in cands:
                    raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r}: points {p!r} "
                                     f"and {q!r} are not both on link {given[0]!r}")
                cands = [given[0]]
            if len(cands) != 1:
                raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r}: points {p!r} "
                                 f"and {q!r} must lie on one rigid link, found "
                                 f"{cands or 'none'}")
            if bodies[cands[0]]["variable"]:
                raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r}: link "
                                 f"{cands[0]!r} has a variable length (a cylinder) and cannot "
                                 f"carry a rigid point or a slider line")
            return cands[0]

        for g in self.groups:
            if isinstance(g, Frame):
                bodies["0"]["points"].append(g.name)
                owner[g.name] = "0"
            elif isinstance(g, CylinderLever):
                cyl, lev = names(g, 2)
                new(cyl, g, (g.base, g.out), variable=True)
                new(lev, g, (g.pivot, g.out), variable=is_coord(g.lever))
                owner[g.out] = lev
                self._group_links[g.name] = (cyl, lev)
            elif isinstance(g, Dyad):
                la, lb = names(g, 2)
                new(la, g, (g.a, g.out), variable=is_coord(g.ra))
                new(lb, g, (g.b, g.out), variable=is_coord(g.rb))
                owner[g.out] = lb
                self._group_links[g.name] = (la, lb)
            elif isinstance(g, Crank):
                (l,) = names(g, 1)
                new(l, g, (g.pivot, g.out), variable=is_coord(g.radius))
                owner[g.out] = l
                self._group_links[g.name] = (l,)
            elif isinstance(g, SliderInput):
                (l,) = names(g, 1)
                new(l, g, (g.out,))
                owner[g.out] = l
                self._group_links[g.name] = (l,)
            elif isinstance(g, (RigidPoint, PosePoint)):
                given = tuple(getattr(g, "links", ()) or ())
                b = carrier(g, g.origin, g.toward, given)
                if isinstance(g, RigidPoint) and is_coord(g.length):
                    # a telescopic arm: the new point is on a link of its own
                    new(f"{g.name}:arm", g, (g.origin, g.out), variable=True)
                    owner[g.out] = f"{g.name}:arm"
                    self._group_links[g.name] = (f"{g.name}:arm",)
                else:
                    bodies[b]["points"].append(g.out)
                    owner[g.out] = b
                    self._group_links[g.name] = (b,)
            elif isinstance(g, SliderDyad):
                la, lb = names(g, 2)
                guide = (carrier(g, g.line_link[0], g.line_link[1], ()) if g.line_link
                         else owner[g.line_point])
                new(la, g, (g.a, g.out), variable=is_coord(g.radius))
                new(lb, g, (g.out,))
                owner[g.out] = la
                self._group_links[g.name] = (la, lb, guide)
        return bodies

    def _check_ref(self, g, role, ref):
        if ref is None:
            return
        if _is_number(ref):
            if not math.isfinite(float(ref)):
                raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r}: {role} = {ref!r} "
                                 f"is not finite")
            return
        if isinstance(ref, str):
            if ref in self.params or ref in self.coordinates:
                return
            raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r}: {role} refers to "
                             f"{ref!r}, which is neither a parameter {sorted(self.params)} nor a "
                             f"coordinate {list(self.coordinates)}")
        raise ModelError(f"mechanism {self.name!r}: {g.kind} {g.name!r}: {role} must be a "
                         f"number or a name, got {ref!r}")

    # ---- evaluation --------------------------------------------------------------
    def value_of(self, ref, params=None):
        """Value of a reference (number or parameter name) as a float array over designs."""
        p = self.params if params is None else params
        if _is_number(ref):
            return np.asarray(float(ref))
        return np.asarray(p[ref], dtype=float)

    def evaluate_positions(self, q, params=None):
        """Point positions by the plain-numpy formulas of the groups (any dtype).

        This is the reference implementation used to check the compiled kernel
        (complex-step differentiation in the tests). It does not check assembly.

        Parameters
        ----------
        q : mapping of coordinate name to array_like
            Generalized coordinate values (may be complex).
        params : mapping, optional
            Parameter values overriding the mechanism's (may be complex).

        Returns
        -------
        dict of str to (x, y) tuples of arrays [m]
        """
        p = dict(self.params)
        p.update(params or {})
        pose = self._pose_values(p)

        def val(ref):
            if ref is None:
                return None
            if _is_number(ref):
                return float(ref)
            if ref in q:
                return q[ref]
            return p[ref]

        pts: dict = {}
        for g in self.groups:
            if isinstance(g, PosePoint):
                _NumericRigid(g, *pose[g.name]).evaluate(pts, val)
            else:
                g.evaluate(pts, val)
        return pts

    def _pose_values(self, p):
        """Derived (angle [rad], length [m]) of every PosePoint, by reference evaluation."""
        out = {}
        prefix = []
        for g in self.groups:
            if isinstance(g, PosePoint):
                sub = self._with(groups=tuple(prefix), links=(), distances=())
                qd = {c: np.asarray(sub.value_of(a, p)) for c, a in zip(self.coordinates, g.at)}
                pts = sub.evaluate_positions(qd, {k: v for k, v in p.items()})
                ox, oy = pts[g.origin]
                tx, ty = pts[g.toward]
                dx = np.asarray(sub.value_of(g.dx, p))
                dy = np.asarray(sub.value_of(g.dy, p))
                beta = np.arctan2(dy, dx) - np.arctan2(ty - oy, tx - ox)
                out[g.name] = (beta, np.hypot(dx, dy))
                prefix.append(_NumericRigid(g, beta, np.hypot(dx, dy)))
            else:
                prefix.append(g)
        return out

    def solve(self, q, params: Mapping | None = None, *, outputs=None, on_failure="raise",
              check_continuity=True):
        """Positions and exact kinematic analogs over the generalized coordinate(s).

        Parameters
        ----------
        q : array_like, shape (n,) or (m, n) for k = 1; shape (..., k) for k > 1
            Values of the generalized coordinate(s) [m or rad]. A 2-D array (k = 1)
            holds one row of positions per design.
        params : mapping, optional
            Parameter overrides; array values of shape (m,) make a batch.
        outputs : iterable of str, optional
            Point, link and distance names to return (default: all). Asking for
            fewer makes large sweeps faster (only those are written to memory).
        on_failure : {"raise", "report"}
            ``"raise"`` (default) raises :class:`AssemblyError` at the first
            position that cannot assemble; ``"report"`` returns the result with
            its ``ok`` mask and ``failures`` (values at failed elements are 0,
            never NaN).
        check_continuity : bool
            For k = 1, check that no dyad opens or passes a dead point *between*
            consecutive positions (cubic Hermite of the squared triangle height).

        Returns
        -------
        Kinematics
        """
        from .kinematics import Kinematics  # local: kinematics imports nothing back

        if on_failure not in ("raise", "report"):
            raise ValueError("on_failure must be one of: ['raise', 'report']")
        from . import inputs  # hardening hook: params= validated like a model file
        inputs.check_params(self, params)
        mech = self.with_params(**params) if params else self
        prog = mech._compile(outputs)
        qarr, shape, m, n = mech._coordinates_array(q, prog["m"])
        ptab = prog["params"]
        if ptab.shape[1] == 1 and m > 1:
            ptab = np.repeat(ptab, m, axis=1)
        elif ptab.shape[1] != m:
            raise ModelError(f"mechanism {self.name!r}: parameters describe {ptab.shape[1]} "
                             f"designs but the coordinates {m}")
        ptab = np.ascontiguousarray(ptab)
        pose_failures = mech._fill_pose_rows(prog, ptab)
        check = bool(check_continuity and len(self.coordinates) == 1 and n > 1)
        res = _execute(prog, ptab, qarr, n, check)
        status = res["status"]
        failed = status >= 0
        if pose_failures and not failed.any():
            raise pose_failures[0]
        kin = Kinematics(mech, prog, qarr.reshape((len(self.coordinates), m, n)), res, shape,
                         ok=~failed.reshape(m, n), params=ptab)
        if failed.any():
            if on_failure == "raise":
                raise mech._assembly_error(prog, ptab, qarr, status, res["amount"], n, kin)
            kin.failures = mech._describe_failures(prog, ptab, qarr, status, res["amount"], n)
        return kin

    def analyze(self, q, params=None, *, qdot=None, qddot=None, **kw):
        """Kinematics, actuator forces, joint reactions, cylinders and stability in one
        call; returns :class:`assur.analysis.Analysis` (see :func:`assur.analysis.analyze`)."""
        from .analysis import analyze
        return analyze(self, q, params=params, qdot=qdot, qddot=qddot, **kw)

    # ---- compilation ---------------------------------------------------------------
    def _coordinates_array(self, q, m_params):
        from . import inputs  # hardening hook: None, empty, ragged, text, memory estimate
        q = inputs.coordinates_array(q, self, m_params)
        k = len(self.coordinates)
        if np.iscomplexobj(q):
            raise ModelError("generalized coordinates must be real numbers [m or rad]")
        try:
            a = np.asarray(q, dtype=float)
        except (TypeError, ValueError):
            raise ModelError(f"generalized coordinates must be numbers, got {q!r}") from None
        if not np.all(np.isfinite(a)):
            bad = np.argwhere(~np.isfinite(a))[0]
            raise ModelError(f"generalized coordinate value at index {tuple(bad)} is not finite")
        if k == 1:
            if a.ndim == 0:
                a = a[None]
            shape = a.shape
            if a.ndim == 1:
                a2 = np.broadcast_to(a, (m_params, a.shape[0])) if m_params > 1 else a[None]
                if m_params > 1:
                    shape = a2.shape
            elif a.ndim == 2:
                a2 = a
            else:
                raise ModelError(f"coordinates must have shape (n,) or (m, n), got {a.shape}")
            m, n = a2.shape
            return np.ascontiguousarray(a2.reshape(1, m * n)), shape, m, n
        if a.shape[-1] != k:
            raise ModelError(f"mechanism {self.name!r} has {k} coordinates {self.coordinates}: "
                             f"q must have a trailing axis of length {k}, got shape {a.shape}")
        if a.ndim == 1:
            a = a[None]
        shape = a.shape[:-1]
        if a.ndim == 2:
            a = np.broadcast_to(a, (m_params,) + a.shape) if m_params > 1 else a[None]
            if m_params > 1:
                shape = a.shape[:-1]
        m, n = a.shape[0], a.shape[1]
        qa = np.moveaxis(a, -1, 0).reshape(k, m * n)
        return np.ascontiguousarray(qa), shape, m, n

    def _compile(self, outputs=None):
        pnames = list(self.params)
        rows = [np.atleast_1d(np.asarray(self.params[n], dtype=float)) for n in pnames]
        index = {n: i for i, n in enumerate(pnames)}
        literal_rows = {}

        def pref(ref):
            """Parameter row of a number or parameter name."""
            if _is_number(ref):
                key = float(ref)
                if key not in literal_rows:
                    literal_rows[key] = len(rows)
                    rows.append(np.array([key]))
                return literal_rows[key]
            if ref in index:
                return index[ref]
            raise ModelError(f"{ref!r} is not a parameter of {self.name!r}")

        def lref(ref):
            """Length reference: parameter row >= 0 or coordinate -(j+1)."""
            if isinstance(ref, str) and ref in self.coordinates:
                return -(self.coordinates.index(ref) + 1)
            return pref(ref)

        slot = {}
        ops = []
        pose_rows = []
        frame_rows = {}
        trig = []  # (kind, data): each takes two rows (cos, sin) of the trig table

        def trow(kind, *data):
            trig.append((kind,) + data)
            return 2 * (len(trig) - 1)

        for g in self.groups:
            row = [0] * K.NCOL
            for o in g.outputs():
                slot[o] = len(slot)
            if isinstance(g, Frame):
                row[:4] = [K.OP_FRAME, slot[g.name], pref(g.x), pref(g.y)]
                frame_rows[g.name] = (row[2], row[3])
            elif isinstance(g, (Dyad, CylinderLever)):
                row[:7] = [K.OP_RRR, slot[g.out], slot[g.a], slot[g.b], lref(g.ra), lref(g.rb),
                           g.branch]
            elif isinstance(g, Crank):
                row[:6] = [K.OP_CRANK, slot[g.out], slot[g.pivot], lref(g.radius),
                           self.coordinates.index(g.angle), pref(g.phase)]
            elif isinstance(g, SliderInput):
                row[:6] = [K.OP_SLIDE, slot[g.out], slot[g.origin],
                           self.coordinates.index(g.s), pref(g.offset),
                           trow("angle", pref(g.direction))]
            elif isinstance(g, RigidPoint):
                if g.angle is not None:
                    row[:7] = [K.OP_RIGID, slot[g.out], slot[g.origin], slot[g.toward],
                               lref(g.length), trow("angle", pref(g.angle)), 0]
                else:
                    pl, pb, po = pref(g.length), pref(g.base), pref(g.opposite)
                    row[:10] = [K.OP_RIGID, slot[g.out], slot[g.origin], slot[g.toward],
                                pl, trow("triangle", pb, pl, po, g.branch), 1, pb, po,
                                g.branch]
            elif isinstance(g, PosePoint):
                rb = len(rows)
                rows.append(np.array([0.0]))
                rl = len(rows)
                rows.append(np.array([0.0]))
                row[:7] = [K.OP_RIGID, slot[g.out], slot[g.origin], slot[g.toward], rl,
                           trow("angle", rb), 0]
                pose_rows.append((len(ops), g, rb, rl))
                pref(g.dx), pref(g.dy)  # literal offsets get their rows before ptab is sized
            elif isinstance(g, SliderDyad):
                dp, dq = (slot[g.line_link[0]], slot[g.line_link[1]]) if g.line_link else (-1, -1)
                row[:9] = [K.OP_RRP, slot[g.out], slot[g.a], lref(g.radius), slot[g.line_point],
                           dp, dq, trow("angle", pref(g.direction)), g.branch]
            else:  # pragma: no cover - guarded by the type checks above
                raise ModelError(f"unknown group type {type(g).__name__}")
            ops.append(row)
        n_points = len(slot)
        scal = {}
        kinds = {}
        for l in self.links:
            scal[l.name] = len(scal)
            kinds[l.name] = "angle"
            ops.append([K.OP_ANGLE, scal[l.name], slot[l.tail], slot[l.head]] + [0] * (K.NCOL - 4))
        for dd in self.distances:
            scal[dd.name] = len(scal)
            kinds[dd.name] = "distance"
            ops.append([K.OP_DIST, scal[dd.name], slot[dd.a], slot[dd.b]] + [0] * (K.NCOL - 4))
        m = max([r.shape[0] for r in rows] + [1])
        for i, r in enumerate(rows):
            if r.shape[0] not in (1, m):
                name = pnames[i] if i < len(pnames) else "?"
                raise ModelError(f"mechanism {self.name!r}: parameter {name!r} has {r.shape[0]} "
                                 f"designs, others {m}")
        ptab = np.empty((len(rows), m))
        for i, r in enumerate(rows):
            ptab[i] = r
        frame = {g.name for g in self.groups if isinstance(g, Frame)}
        if outputs is None:
            out_pts = [p for p in slot if p not in frame]
            out_sca = list(scal)
        else:
            outputs = list(outputs)
            bad = [o for o in outputs if o not in slot and o not in scal]
            if bad:
                raise ModelError(f"unknown outputs {bad}; points: {list(slot)}, links and "
                                 f"distances: {list(scal)}")
            out_pts = [o for o in outputs if o in slot and o not in frame]
            out_sca = [o for o in outputs if o in scal]
        return dict(ops=np.array(ops, dtype=np.int64).reshape(-1, K.NCOL), params=ptab, m=m,
                    slot=slot, scal=scal, kinds=kinds, out_pts=out_pts, out_sca=out_sca,
                    n_points=n_points, pose_rows=pose_rows, pnames=pnames, trig=trig,
                    frame_rows=frame_rows,
                    literal_rows=literal_rows, lref=lref, pref=pref)

    def _fill_pose_rows(self, prog, ptab):
        """Pre-pass: derive angle and length of PosePoints at their pose, per design.

        Returns the list of :class:`AssemblyError` for poses that cannot assemble
        (their rows stay 0); the caller raises them unless the main range fails
        earlier, which gives the more useful message.
        """
        pose_failures = []
        for opi, g, rb, rl in prog["pose_rows"]:
            m = ptab.shape[1]
            qpose = np.empty((len(self.coordinates), m))
            for j, a in enumerate(g.at):
                r = prog["lref"](a)
                if r < 0:
                    raise ModelError(f"pose of {g.name!r} must be given by numbers or parameters")
                qpose[j] = ptab[r]
            sub = dict(prog, ops=prog["ops"][:opi], out_pts=[g.origin, g.toward], out_sca=[])
            res = _execute(sub, ptab, qpose, 1, False)
            if (res["status"] >= 0).any():
                e = int(np.flatnonzero(res["status"] >= 0)[0])
                msg, _ = self._failure_message(prog, ptab, qpose, res["status"], res["amount"],
                                               1, e)
                pose_failures.append(AssemblyError(
                    f"{g.kind} {g.name!r} is defined at the pose "
                    f"{', '.join(f'{c} = {v:.6g}' for c, v in zip(self.coordinates, qpose[:, e]))}"
                    f", where the mechanism cannot assemble: {msg}", group=g.name,
                    links=g.group_links(), coordinate=dict(zip(self.coordinates, qpose[:, e])),
                    design=e))
                continue
            (ox, oy), (tx, ty) = res["pv"][0], res["pv"][1]
            dx = ptab[prog["pref"](g.dx)]
            dy = ptab[prog["pref"](g.dy)]
            ptab[rb] = np.arctan2(dy, dx) - np.arctan2(ty - oy, tx - ox)
            ptab[rl] = np.hypot(dx, dy)
        return pose_failures

    # ---- failures --------------------------------------------------------------------
    def _describe_failures(self, prog, ptab, qarr, status, amount, n):
        idx = np.flatnonzero(status >= 0)
        return [self._failure_message(prog, ptab, qarr, status, amount, n, e)[0]
                for e in idx[:20]]

    def _assembly_error(self, prog, ptab, qarr, status, amount, n, kin):
        idx = np.flatnonzero(status >= 0)
        e = int(idx[0])
        msg, g = self._failure_message(prog, ptab, qarr, status, amount, n, e)
        d, pos = divmod(e, n)
        fails_here = idx[(idx >= d * n) & (idx < (d + 1) * n)]
        if len(self.coordinates) == 1 and n > 1:
            pos_idx = fails_here - d * n
            runs = np.split(pos_idx, np.flatnonzero(np.diff(pos_idx) != 1) + 1)
            qd = qarr[0, d * n:(d + 1) * n]
            spans = ", ".join(f"{qd[r[0]]:.6g}…{qd[r[-1]]:.6g}" if len(r) > 1 else
                              f"{qd[r[0]]:.6g}" for r in runs[:5])
            msg += (f"; {len(fails_here)} of {n} positions fail"
                    f" ({self.coordinates[0]} = {spans}{', …' if len(runs) > 5 else ''})")
        if ptab.shape[1] > 1:
            nd = len(np.unique(idx // n))
            msg += f"; {nd} of {ptab.shape[1]} designs fail, first design {d}"
        return AssemblyError(msg, group=g.name, links=g.group_links(),
                             coordinate=dict(zip(self.coordinates, qarr[:, e])), design=d,
                             position=pos,
                             amount=(float(amount[e]) if int(status[e]) % 16 == K.FAIL_CONTINUITY
                                     else self._failure_amount(prog, ptab, qarr, e, n,
                                                               int(status[e]) // 16,
                                                               int(status[e]) % 16)),
                             failures=kin.ok)

    def _failure_amount(self, prog, ptab, qarr, e, n, opi, code):
        """By how much group ``opi`` violates its inequality at element ``e`` [m] (or
        sin μ at a dead point), from the plain-numpy reference positions of the groups
        before it — the kernel reports only which group failed."""
        if opi >= len(self.groups) or code == K.FAIL_COINCIDENT:
            return 0.0
        g = self.groups[opi]
        d = e // n
        params = {name: ptab[i, d] for i, name in enumerate(prog["pnames"])}
        qd = {c: qarr[j, e] for j, c in enumerate(self.coordinates)}
        prefix = self._with(groups=self.groups[:opi], links=(), distances=(), loads=(),
                            cylinders=(), machine=None)
        pts = prefix.evaluate_positions(qd, params) if opi else {}

        def v(ref):
            if isinstance(ref, str) and ref in qd:
                return float(qd[ref])
            return float(ptab[prog["pref"](ref), d])

        if isinstance(g, RigidPoint) and code == K.FAIL_TRIANGLE:
            b, ell, o = v(g.base), v(g.length), v(g.opposite)
            return max(ell - (b + o), b - (ell + o), o - (ell + b))
        if isinstance(g, (Dyad, CylinderLever)):
            (ax, ay), (bx, by) = pts[g.a], pts[g.b]
            L = math.hypot(bx - ax, by - ay)
            ra, rb = v(g.ra), v(g.rb)
            if code == K.FAIL_TOO_FAR:
                return L - (ra + rb)
            if code == K.FAIL_TOO_CLOSE:
                return abs(ra - rb) - L
            aa = (ra * ra - rb * rb + L * L) / (2 * L)
            return math.sqrt(max(ra * ra - aa * aa, 0.0)) * L / (ra * rb)  # sin μ
        if isinstance(g, SliderDyad):
            ax, ay = pts[g.a]
            lx, ly = pts[g.line_point]
            beta = v(g.direction)
            if g.line_link:
                (px, py), (qx, qy) = pts[g.line_link[0]], pts[g.line_link[1]]
                beta += math.atan2(qy - py, qx - px)
            ux, uy = math.cos(beta), math.sin(beta)
            wx, wy = lx - ax, ly - ay
            r = v(g.radius)
            if code == K.FAIL_LINE:
                return abs(ux * wy - uy * wx) - r
            bb = ux * wx + uy * wy
            return 2.0 * math.sqrt(max(bb * bb - (wx * wx + wy * wy - r * r), 0.0))
        return 0.0

    def _failure_message(self, prog, ptab, qarr, status, amount, n, e):
        opi, code = divmod(int(status[e]), 16)
        d, pos = divmod(e, n)
        ngroups = len(self.groups)
        at = ", ".join(f"{c} = {qarr[j, e]:.6g}" for j, c in enumerate(self.coordinates))
        where = f"at position {pos} ({at})" + (f" of design {d}" if ptab.shape[1] > 1 else "")
        if opi >= ngroups:
            obj = (self.links + self.distances)[opi - ngroups]
            return (f"link {obj.name!r}: its two points coincide {where}", obj)
        g = self.groups[opi]
        links = g.group_links()
        ltxt = f" (links {', '.join(links)})" if links else ""
        amt = (float(amount[e]) if code == K.FAIL_CONTINUITY
               else self._failure_amount(prog, ptab, qarr, e, n, opi, code))

        def v(ref):
            if isinstance(ref, str) and ref in self.coordinates:
                return qarr[self.coordinates.index(ref), e]
            return ptab[prog["pref"](ref), d]

        def nm(ref):
            return ref if isinstance(ref, str) else _fmt(ref)

        head = f"{g.kind} {g.name!r}{ltxt} cannot assemble {where}: "
        if code in (K.FAIL_TOO_FAR, K.FAIL_TOO_CLOSE):
            ra, rb = v(g.ra), v(g.rb)
            a, b = g.inputs()[:2]
            dist = ra + rb + amt if code == K.FAIL_TOO_FAR else abs(ra - rb) - amt
            if code == K.FAIL_TOO_FAR:
                msg = (f"the distance |{a}–{b}| = {dist:.6g} m exceeds {nm(g.ra)} + {nm(g.rb)} = "
                       f"{_fmt(ra)} + {_fmt(rb)} = {_fmt(ra + rb)} m by {amt * 1e3:.3g} mm")
            else:
                msg = (f"the distance |{a}–{b}| = {dist:.6g} m is less than |{nm(g.ra)} − "
                       f"{nm(g.rb)}| = |{_fmt(ra)} − {_fmt(rb)}| = {_fmt(abs(ra - rb))} m by "
                       f"{amt * 1e3:.3g} mm")
        elif code == K.FAIL_TRIANGLE:
            names = {"base": g.base, "length": g.length, "opposite": g.opposite}
            vals = {k: v(r) for k, r in names.items()}
            sides = ", ".join(f"{nm(names[k])} = {_fmt(vals[k])}" for k in
                              ("base", "opposite", "length"))
            for k in ("length", "base", "opposite"):
                o1, o2 = [x for x in ("base", "length", "opposite") if x != k]
                if vals[k] > vals[o1] + vals[o2]:
                    msg = (f"the triangle {sides} m cannot close: {nm(names[k])} exceeds "
                           f"{nm(names[o1])} + {nm(names[o2])} = {_fmt(vals[o1] + vals[o2])} m by "
                           f"{(vals[k] - vals[o1] - vals[o2]) * 1e3:.3g} mm")
                    break
            else:  # pragma: no cover - the kernel only reports violated triangles
                msg = f"the triangle {sides} m cannot close"
            head = f"{g.kind} {g.name!r}{ltxt} fails {where}: "
        elif code == K.FAIL_LINE:
            msg = (f"the circle of radius {nm(g.radius)} = {_fmt(v(g.radius))} m about {g.a!r} "
                   f"does not reach the slider line through {g.line_point!r}: it falls short by "
                   f"{amt * 1e3:.3g} mm")
        elif code == K.FAIL_COINCIDENT:
            msg = f"two points that must define a direction coincide ({', '.join(g.inputs())})"
        elif code == K.FAIL_CONTINUITY:
            c = self.coordinates[0]
            head = (f"{g.kind} {g.name!r}{ltxt} cannot move continuously from {c} = "
                    f"{qarr[0, e - 1]:.6g} to {c} = {qarr[0, e]:.6g}"
                    f"{f' (design {d})' if ptab.shape[1] > 1 else ''}: ")
            msg = ("its triangle flattens or opens between these positions (the squared "
                   f"height, interpolated with its exact slope, dips to {amt:.3g} m²): a dead "
                   "point or a loss of assembly between samples; refine the positions, or "
                   "check the range and the branch")
        elif code == K.FAIL_DEAD_POINT:
            msg = (f"dead point: the links are collinear (sine of the transmission angle "
                   f"{amt:.3g}), the analogs are singular")
        else:  # pragma: no cover
            msg = f"failure code {code}"
        return head + msg, g

    def _defining_index(self, point):
        for i, g in enumerate(self.groups):
            if point in g.outputs():
                return i
        raise KeyError(point)

    def __repr__(self):
        return (f"Mechanism({self.name!r}, coordinates={self.coordinates}, "
                f"{len(self.groups)} groups, {len(self.links)} links)")


class _NumericRigid(RigidPoint):
    """A PosePoint resolved to numbers for the reference evaluation."""

    def __init__(self, g, beta, ell):
        object.__setattr__(self, "name", g.name)
        object.__setattr__(self, "origin", g.origin)
        object.__setattr__(self, "toward", g.toward)
        object.__setattr__(self, "out", g.out)
        object.__setattr__(self, "links", tuple(g.links))
        object.__setattr__(self, "branch", 1)
        object.__setattr__(self, "base", None)
        object.__setattr__(self, "opposite", None)
        object.__setattr__(self, "_beta", beta)
        object.__setattr__(self, "_ell", ell)
        object.__setattr__(self, "length", "__ell")
        object.__setattr__(self, "angle", "__beta")

    def refs(self):
        return {}

    def evaluate(self, pts, val):
        from .groups import _unit_eval
        ux, uy = _unit_eval(pts, self.origin, self.toward, self._beta)
        px, py = pts[self.origin]
        pts[self.out] = (px + self._ell * ux, py + self._ell * uy)


def _trig_table(prog, ptab):
    """cos and sin of every fixed angle of the program, per design, shape (2·n, m).

    A triangle-defined angle is ``branch·acos((b² + l² − o²)/(2·b·l))`` (seed 000
    DELFI); its argument is clipped here only so that the table is finite — a
    triangle that cannot close is detected and reported by the kernel.
    """
    m = ptab.shape[1]
    out = np.empty((max(2 * len(prog["trig"]), 1), m))
    for i, item in enumerate(prog["trig"]):
        if item[0] == "angle":
            beta = ptab[item[1]]
        else:
            _, pb, pl, po, br = item
            b, ell, o = ptab[pb], ptab[pl], ptab[po]
            den = 2.0 * b * ell
            ok = den > 0
            c = np.divide(b * b + ell * ell - o * o, den, out=np.ones(m), where=ok)
            beta = br * np.arccos(np.clip(c, -1.0, 1.0))
        out[2 * i] = np.cos(beta)
        out[2 * i + 1] = np.sin(beta)
    return out


def _execute(prog, ptab, qarr, n, check=False):
    """Run the compiled kernel; returns the raw output arrays."""
    k = qarr.shape[0]
    E = qarr.shape[1]
    slot, scal = prog["slot"], prog["scal"]
    out_pts = [slot[p] for p in prog["out_pts"]]
    out_sca = [scal[s] for s in prog["out_sca"]]
    kern = K.get_kernel(prog["ops"], k, out_pts, out_sca)
    npo, nso = len(out_pts), len(out_sca)
    # one block, rows: point values, first, second analogs, then scalars likewise
    ang = [i for i, s in enumerate(prog["out_sca"]) if prog["kinds"][s] == "angle"]
    sizes = [npo * 2, npo * 2 * k, npo * 2 * k * k, nso, nso * k, nso * k * k, len(ang)]
    out = np.empty((sum(sizes), E))
    parts = np.split(out, np.cumsum(sizes)[:-1])
    pv = parts[0].reshape(npo, 2, E)
    pd = parts[1].reshape(npo, 2, k, E)
    pdd = parts[2].reshape(npo, 2, k, k, E)
    sv = parts[3].reshape(nso, E)
    sd = parts[4].reshape(nso, k, E)
    sdd = parts[5].reshape(nso, k, k, E)
    status = np.empty(E, dtype=np.int64)
    # written by the continuity pass at its failures only (read only there); the
    # other amounts are recomputed on demand
    amount = np.empty(E)
    dyads = [i for i, r in enumerate(prog["ops"]) if r[0] == K.OP_RRR] if k == 1 else []
    gout = np.empty((2 * len(dyads), E if check else 1))
    K.run(kern, ptab, _trig_table(prog, ptab), qarr, n, check, out, gout, status, amount)
    if check and dyads:
        codes = np.array([i * 16 + K.FAIL_CONTINUITY for i in dyads], dtype=np.int64)
        if K.check_continuity(gout, qarr, n, status, amount, codes):
            out[:, (status % 16 == K.FAIL_CONTINUITY) & (status >= 0)] = 0.0
    def angle(row, i):
        """angle = atan2(dy, dx) (the kernel left dy in sv[i]), then continuous along
        the positions of each design when they are a range (both release the GIL)."""
        np.arctan2(sv[i], parts[6][row], out=sv[i])
        if check and n > 1:
            K.unwrap_rows(sv, np.array([i], dtype=np.int64), n)

    if E >= 65536 and len(ang) > 1:
        for f in [K._get_pool().submit(angle, row, i) for row, i in enumerate(ang)]:
            f.result()
    else:
        for row, i in enumerate(ang):
            angle(row, i)
    return dict(pv=pv, pd=pd, pdd=pdd, sv=sv, sd=sd, sdd=sdd, status=status, amount=amount)
