"""The checks of a :class:`~assur.core.mechanism.Mechanism`'s description: what it
refuses on construction (and what a copy re-checks, ``Mechanism._with``), each a
:class:`~assur.errors.ModelError` naming the mechanism and the part at fault.

* :func:`validate` — the groups in solving order (points known before use, defined
  once, references to parameters or coordinates, each group's own check), links and
  distances, then the topology and the parts that refer to it (:func:`check_parts`);
* :func:`check_parts` — the loads (the names their declared point, link and value
  fields hold, and each load's own ``check``), the machine, the cylinders and their
  supply lines, the wheels;
* :func:`check_params`, :func:`check_gravity`, :func:`check_motions`.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import ModelError
from ..groups import Link
from ..groups.base import is_number, signed_name
from .cylinders import Cylinder
from .loads import Weight, names_in
from .motion import Motion
from .topology import build_topology
from .wheels import Wheel


def validate(mech, check_params=True):
    """Check the structure of ``mech``, set its topology and check its parts and, with
    ``check_params``, its parameter values.

    Examples
    --------
    >>> from assur import Mechanism
    >>> Mechanism("m", coordinates=("j1",)).frame("O", 0.0, 0.0).crank(
    ...     "c", pivot="A", out="B", radius=0.1, q="j1")             # radius [m]
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'm': crank 'c' needs point 'A', which no earlier group defines (known: ['O'])
    """
    known: set[str] = set()
    names: set[str] = set()
    where = f"mechanism {mech.name!r}"
    for g in mech.groups:
        if g.type_name != "frame" and g.name in names:
            raise ModelError(f"{where}: duplicate group name {g.name!r}")
        names.add(g.name)
        for p in g.inputs():
            if p not in known:
                raise ModelError(
                    f"{where}: {g.kind} {g.name!r} needs point {p!r}, which "
                    f"no earlier group defines (known: {sorted(known)})")
        for p in g.outputs():
            if p in known:
                raise ModelError(f"{where}: point {p!r} is defined twice "
                                 f"(again by {g.kind} {g.name!r})")
            known.add(p)
        for role, ref in g.refs().items():
            check_ref(mech, g, role, ref)
        problem = g.validate(mech.coordinates)
        if problem:
            raise ModelError(f"{where}: {g.kind} {g.name!r}: {problem}")
    for obj in mech.links + mech.distances:
        ends = (obj.tail, obj.head) if isinstance(obj, Link) else (obj.a, obj.b)
        for p in ends:
            if p not in known:
                raise ModelError(f"{where}: link/distance {obj.name!r} refers "
                                 f"to unknown point {p!r} (known: {sorted(known)})")
    mech._topology = build_topology(mech.name, mech.coordinates, mech.groups)
    check_parts(mech, known)
    lnames = [l.name for l in mech.links] + [d.name for d in mech.distances]
    dup = {n for n in lnames if lnames.count(n) > 1}
    if dup:
        raise ModelError(f"{where}: duplicate link/distance names {sorted(dup)}")
    if check_params:
        check_params_of(mech, mech.params)


def check_params_of(mech, params):
    """Every value of ``params`` finite, a number or a 1-D array over designs.

    Examples
    --------
    >>> from assur import examples
    >>> examples.hitch_003().with_params(L4=float("inf"))
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': parameter 'L4' must be a finite number or a 1-D array over designs, got inf
    """
    for n, v in params.items():
        a = np.asarray(v, dtype=float)
        if a.ndim > 1 or not np.all(np.isfinite(a)):
            raise ModelError(f"mechanism {mech.name!r}: parameter {n!r} must be a finite "
                             f"number or a 1-D array over designs, got {v!r}")


def check_gravity(mech):
    """Gravity ≥ 0 [m/s²], a finite direction [rad], and no ``weight`` load without
    gravity.

    Examples
    --------
    >>> from assur import examples
    >>> examples.hitch_003().with_gravity(-9.81)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': gravity must be a number ≥ 0 [m/s²] (0: none), got -9.81
    """
    g = mech.gravity
    if g is not None and not (math.isfinite(float(g)) and float(g) >= 0):
        raise ModelError(f"mechanism {mech.name!r}: gravity must be a number ≥ 0 [m/s²] "
                         f"(0: none), got {g!r}")
    d = mech.gravity_direction
    if d is not None and not math.isfinite(float(d)):
        raise ModelError(f"mechanism {mech.name!r}: the direction of gravity must be a "
                         f"finite angle, got {d!r}")
    if g is not None and float(g) == 0:
        w = [ld for ld in mech.loads if isinstance(ld, Weight)]
        if w:
            raise ModelError(f"mechanism {mech.name!r} has no gravity (a mechanism in a "
                             f"horizontal plane) but a weight load at point "
                             f"{w[0].point!r}: give the load as a force, or give gravity")


def check_motions(mech):
    """Each motion a :class:`~assur.core.motion.Motion` of a coordinate of its kind,
    at most one per coordinate.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.motion import Motion
    >>> m = examples.hitch_003()
    >>> m._with(motions=[Motion("S", "ccw", 1.0, kind="angle")])      # |ω| [rad/s]
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': the motion of 'S' is for a angle coordinate; 'S' is a length coordinate
    """
    seen = set()
    for mo in mech.motions:
        if not isinstance(mo, Motion):
            raise ModelError(f"mechanism {mech.name!r}: motions must be "
                             f"assur.core.motion.Motion, got {mo!r}")
        if mo.coordinate not in mech.coordinates:
            raise ModelError(f"mechanism {mech.name!r}: a motion is given for "
                             f"{mo.coordinate!r}, which is not a generalized coordinate "
                             f"{list(mech.coordinates)}")
        if (mech.coordinate_kind(mo.coordinate) == "angle") != (mo.kind == "angle"):
            raise ModelError(f"mechanism {mech.name!r}: the motion of {mo.coordinate!r} "
                             f"is for a {mo.kind} coordinate; {mo.coordinate!r} is a "
                             f"{mech.coordinate_kind(mo.coordinate)} coordinate")
        if mo.coordinate in seen:
            raise ModelError(f"mechanism {mech.name!r}: two motions of {mo.coordinate!r}")
        seen.add(mo.coordinate)


class _Refs:
    """The checks of the names a part refers to, worded for ``mech``: a value
    (finite, or a parameter), a point (known), a link (a body)."""

    def __init__(self, mech, known):
        self.mech, self.known = mech, known
        self.where = f"mechanism {mech.name!r}"

    def value(self, what, ref):
        if is_number(ref):
            if not math.isfinite(float(ref)):
                raise ModelError(f"{self.where}: {what} = {ref!r} is not finite")
        elif not (isinstance(ref, str) and (signed_name(ref) or ref) in self.mech.params):
            raise ModelError(f"{self.where}: {what} refers to {ref!r}, which is not a "
                             f"parameter {sorted(self.mech.params)}")

    def point(self, what, p):
        if p not in self.known:
            raise ModelError(f"{self.where}: {what} is at unknown point {p!r} (known: "
                             f"{sorted(self.known)})")

    def link(self, what, link):
        bodies = self.mech.topology.bodies
        if link is not None and link not in bodies:
            raise ModelError(f"{self.where}: {what} acts on unknown link {link!r} (links: "
                             f"{sorted(bodies)})")


def check_parts(mech, known):
    """The loads, the machine, the cylinders and the wheels of ``mech`` against its
    points ``known``, its links and its parameters.

    Examples
    --------
    >>> from assur import examples
    >>> examples.hitch_003().weight("S7", 100.0)                  # [N]
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': weight is at unknown point 'S7' (known: ['01', '03', '05', '07', '23', '34', '45', '56', '67', 'F610', 'S6'])
    """
    refs = _Refs(mech, known)
    for ld in mech.loads:
        check_load(mech, ld, refs)
    if mech.machine is not None:
        refs.point("the machine's implement", mech.machine.point)
        for t in mech.machine.ref_names():
            refs.value("the machine's data", t)
        refs.value("the machine's implement weight", mech.machine.weight)
    check_cylinders(mech, refs)
    check_wheels(mech, refs)


def check_wheels(mech, refs):
    """Each wheel (:class:`assur.core.wheels.Wheel`) at a known point, heading along a
    link with a direction (a named link, or a moving link of the groups), its values
    finite or parameters, a given diameter and width positive.

    Examples
    --------
    >>> from assur import examples
    >>> examples.hitch_003().wheel("w", at="01", link="9", diameter=1.1, width=0.3)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': wheel 'w' heads along unknown link '9' (links with a direction: ['2', '3', '34', '4', '5', '6', '7'])
    """
    where = refs.where
    named = [ln.name for ln in mech.links]
    topo = mech.topology
    turning = named + [b for b in topo.bodies if b != "0" and b not in named
                       and topo.angle_points(b) is not None]
    for w in mech.wheels:
        if not isinstance(w, Wheel):
            raise ModelError(f"{where}: wheels must be assur.core.wheels.Wheel, got {w!r}")
        what = f"wheel {w.name!r}"
        refs.point(what, w.at)
        if w.link is not None and w.link not in turning:
            raise ModelError(f"{where}: {what} heads along unknown link {w.link!r} (links "
                             f"with a direction: {sorted(turning)})")
        for f in w.quantities:
            ref = getattr(w, f)
            refs.value(f"{what}: {f}", ref)
            if f in w.flags and is_number(ref) and not float(ref) > 0:
                raise ModelError(f"{where}: {what}: {f} must be positive, got {ref!r}")


def check_load(mech, ld, refs):
    """One load: the names its declared fields hold (:class:`assur.core.loads.Load`),
    then its own ``check(mech)``.

    Examples
    --------
    >>> from assur import examples
    >>> examples.hitch_003().moment("9", 100.0)                   # [N·m]
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': moment acts on unknown link '9' (links: ['0', '2', '3', '4', '5', '6', '7'])
    """
    if not (hasattr(ld, "apply") and hasattr(ld, "quantities")
            and hasattr(ld, "point_fields") and hasattr(ld, "link_fields")):
        raise ModelError(f"{refs.where}: unknown load {ld!r} (a load declares quantities, "
                         f"point_fields, link_fields and apply; assur.core.loads)")
    what = f"{ld.type_name} {getattr(ld, 'name', None) or ''}".rstrip()
    for f in ld.point_fields:
        for p in names_in(getattr(ld, f)):
            refs.point(what, p)
    for f in ld.link_fields:
        for link in names_in(getattr(ld, f)):
            refs.link(what, link)
    for f in ld.quantities:
        refs.value(f"{what}: {f}", getattr(ld, f))
    check = getattr(ld, "check", None)  # a load's own check against the mechanism
    if check is not None:
        problem = check(mech)
        if problem:
            raise ModelError(f"{refs.where}: {what}: {problem}")


def check_cylinders(mech, refs):
    """Each cylinder drives a coordinate (once) or, passive, is a named distance on a
    supply line; its side and values; then the supply lines.

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.hitch_003()
    >>> m.cylinder("ГЦ2", "S", bore=0.08)                        # bore [m]
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': two cylinder entries drive 'S'
    """
    where = refs.where
    seen = set()
    distances = {d.name for d in mech.distances}
    for c in mech.cylinders:
        if not isinstance(c, Cylinder):
            raise ModelError(f"{where}: cylinders must be assur.core.cylinders.Cylinder, got "
                             f"{c!r}")
        if (c.coordinate is None) == (c.distance is None):
            raise ModelError(f"{where}: cylinder {c.name!r}: give either the coordinate it "
                             f"drives or, for a passive cylinder, the distance that is its "
                             f"length (not both)")
        if c.distance is not None:
            if c.distance not in distances:
                raise ModelError(f"{where}: passive cylinder {c.name!r}: {c.distance!r} is "
                                 f"not a named distance {sorted(distances)}")
            if c.supply is None:
                raise ModelError(f"{where}: passive cylinder {c.name!r} (length "
                                 f"{c.distance!r}) needs the supply line it shares with a "
                                 f"cylinder that drives a coordinate (supply = …)")
        elif c.coordinate not in mech.coordinates:
            raise ModelError(f"{where}: cylinder {c.name!r} drives {c.coordinate!r}, which is "
                             f"not a generalized coordinate {list(mech.coordinates)}")
        elif c.coordinate in seen:
            raise ModelError(f"{where}: two cylinder entries drive {c.coordinate!r}")
        if c.coordinate is not None:
            seen.add(c.coordinate)
        if c.side not in ("piston", "rod", "auto", *c.DIRECTIONS):
            raise ModelError(f"{where}: cylinder {c.name!r}: side must be one of: "
                             f"{['piston', 'rod', 'auto', *c.DIRECTIONS]}, got {c.side!r}")
        for f in c.quantities:
            refs.value(f"cylinder {c.name!r}: {f}", getattr(c, f))
    check_supply_lines(mech, where)


def check_supply_lines(mech, where):
    """Exactly one driving cylinder per supply line, and each cylinder's side given
    when several share the line.

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.hitch_003()
    >>> m.with_cylinders([m.cylinders[0].__class__("C", distance="d", supply="P",
    ...                                            bore=0.08)])        # bore [m]
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': passive cylinder 'C': 'd' is not a named distance []
    """
    lines = {}
    for c in mech.cylinders:
        if c.supply is not None:
            lines.setdefault(c.supply, []).append(c)
    for line, cyls in lines.items():
        active = [c for c in cyls if c.coordinate is not None]
        if len(active) != 1:
            raise ModelError(f"{where}: supply line {line!r}: expected exactly one cylinder "
                             f"that drives a coordinate, found {len(active)} "
                             f"({', '.join(c.name for c in active) or 'none'}); the others "
                             f"are passive (distance = …)")
        if len(cyls) > 1 and any(c.side == "auto" for c in cyls):
            raise ModelError(f"{where}: supply line {line!r}: with several cylinders on "
                             f"one line, give each cylinder's pressurised side "
                             f"(\"piston\" or \"rod\"), not \"auto\"")


def check_ref(mech, g, role, ref):
    """A group's length/angle reference: a finite number, a parameter (optionally
    signed) or a coordinate.

    Examples
    --------
    >>> from assur import Mechanism
    >>> Mechanism("m", coordinates=("j1",)).frame("O", 0.0, 0.0).crank(
    ...     "c", pivot="O", out="A", radius="r", q="j1")
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'm': crank 'c': radius refers to 'r', which is neither a parameter [] nor a coordinate ['j1']
    """
    if ref is None:
        return
    if is_number(ref):
        if not math.isfinite(float(ref)):
            raise ModelError(f"mechanism {mech.name!r}: {g.kind} {g.name!r}: {role} = {ref!r} "
                             f"is not finite")
        return
    if isinstance(ref, str):
        if (signed_name(ref) or ref) in mech.params or ref in mech.coordinates:
            return
        raise ModelError(f"mechanism {mech.name!r}: {g.kind} {g.name!r}: {role} refers to "
                         f"{ref!r}, which is neither a parameter {sorted(mech.params)} nor a "
                         f"coordinate {list(mech.coordinates)}")
    raise ModelError(f"mechanism {mech.name!r}: {g.kind} {g.name!r}: {role} must be a "
                     f"number or a name, got {ref!r}")
