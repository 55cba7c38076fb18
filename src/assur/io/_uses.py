"""Pass 1 of the file loader (:class:`assur.io._build.Builder`): every value is looked
at where it is used, which fixes its kind (a dyad's ``ra`` is a length, a weight's
``P`` a force …). A literal converts to SI at once; a name must be a parameter (or,
where a length may be one, a generalized coordinate) and the parameter takes the kind
of its use (:meth:`~assur.io._build.Builder.value`).
"""

from __future__ import annotations

from . import _schema as S
from ._entries import CYLINDER_VALUES, QUANTITY, fields, group_outputs, group_values, \
    load_values, unreadable
from ._units import ACCELERATION, ANGLE, ANGULAR_VELOCITY, FORCE, LENGTH, NUMBER, TIME, \
    VELOCITY, UnitError, is_name, parse


class Uses:
    """The uses pass, a part of :class:`~assur.io._build.Builder`."""

    def uses(self):
        """Record every value's use, section by section (the groups first: they fix the
        kind of each coordinate)."""
        self.use_coordinates()
        self.use_params()
        self.use_gravity()
        self.use_groups()
        self.motion_uses()
        self.use_loads_and_cylinders()
        self.use_machine()
        self.use_ranges()
        self.use_solve()

    def use_coordinates(self):
        """``[model] coordinates``: names, each once."""
        sp = self.spec
        self.coords = tuple(sp.model.coordinates)
        seen = {}
        for j, c in enumerate(self.coords):
            if not is_name(c):
                raise self.error(("model", "coordinates", j), f"expected a name (a letter or _ "
                                 f"then letters, digits, _), found {S.show(c)}")
            if c in seen:
                raise self.error(("model", "coordinates", j), f'the coordinate "{c}" is listed '
                                                              f"twice")
            seen[c] = j

    def use_params(self):
        """``[params]``: each a name (not a coordinate's) and a value with its unit."""
        sp = self.spec
        self.params_raw = {}
        self._uses_gravity = "gravity" in sp.model.model_fields_set
        for name, v in sp.params.items():
            path = ("params", name)
            if not is_name(name):
                raise self.error(path, f"expected a parameter name (a letter or _ then letters, "
                                       f'digits, _), found "{name}"')
            if name in self.coords:
                raise self.error(path, f'"{name}" is a generalized coordinate and cannot also be '
                                       f"a parameter")
            try:
                p = parse(v)
            except UnitError as e:
                raise self.error(path, unreadable(e, 'a value (a number, or a number with its '
                                                     'unit such as "0.48 m")', v)) from None
            if isinstance(p, str):
                raise self.error(path, f'expected a value (a number, or a number with its unit '
                                       f'such as "0.48 m"), found {S.show(v)}: a parameter '
                                       f"cannot refer to another")
            self.params_raw[name] = p

    def use_gravity(self):
        """``[model] gravity``: an acceleration, optionally with a direction."""
        sp = self.spec
        if self._uses_gravity:
            gv = sp.model.gravity
            if isinstance(gv, dict):
                if "value" in gv:
                    self.value(("model", "gravity", "value"), gv["value"], ACCELERATION,
                               "positive")
                if "direction" in gv:
                    self.value(("model", "gravity", "direction"), gv["direction"], ANGLE)
            elif gv != "none":
                self.value(("model", "gravity"), gv, ACCELERATION, "positive")

    def use_groups(self):
        """The coordinates the input groups drive (their kind), the frame points, the
        groups' values and positions; then every coordinate must be used by a group."""
        sp = self.spec
        # the kind of each coordinate, from the input groups that it drives
        for i, g in enumerate(self.groups):
            for f in fields(g, "coordinate"):
                self.coordinate_field(("groups", i, f.name), getattr(g, f.name),
                                      QUANTITY[f.quantity])
        for name, fp in sp.frame.items():
            if isinstance(fp, dict):  # polar: origin + length∠angle
                self.value(("frame", name, "length"), fp["length"], LENGTH, "positive")
                self.value(("frame", name, "angle"), fp["angle"], ANGLE)
            else:
                self.value(("frame", name, 0), fp[0], LENGTH)
                self.value(("frame", name, 1), fp[1], LENGTH)
        for i, g in enumerate(self.groups):
            for field, (kind, flag, coord_ok) in group_values(g).items():
                if field in g.model_fields_set:
                    self.value(("groups", i, field), getattr(g, field), kind, flag, coord_ok)
            for f in fields(g, "position"):
                if f.name in g.model_fields_set:
                    self.position(("groups", i, f.name), getattr(g, f.name))
        for j, c in enumerate(self.coords):  # only groups have used coordinates so far
            if c not in self.coord_kind:
                raise self.error(("model", "coordinates", j),
                                 f'the coordinate "{c}" is not used by any group: nothing moves '
                                 f"with it (drive an input group with it, or remove it)")

    def use_loads_and_cylinders(self):
        """``[[loads]]`` (the value fields their types declare) and ``[[cylinders]]``."""
        sp = self.spec
        for i, ld in enumerate(self.loads):
            for field, (kind, flag) in load_values(ld).items():
                if field in ld.model_fields_set:
                    self.value(("loads", i, field), getattr(ld, field), kind, flag)
        for i, c in enumerate(sp.cylinders):
            if (c.coordinate is None) == (c.distance is None):
                raise self.error(("cylinders", i), "expected either coordinate (the cylinder "
                                                   "drives it) or distance (a passive "
                                                   "cylinder's length), not both or neither")
            if c.coordinate is not None:
                self.coordinate_field(("cylinders", i, "coordinate"), c.coordinate,
                                      self.kind_of_coordinate(c.coordinate))
            for field, (kind, flag) in CYLINDER_VALUES.items():
                if field in c.model_fields_set:
                    self.value(("cylinders", i, field), getattr(c, field), kind, flag)

    def use_machine(self):
        """``[machine]``: axles, weights, the steered share, the implement's weight."""
        sp = self.spec
        if sp.machine is not None:
            m = sp.machine
            for a, x in m.axles.items():
                self.terms(("machine", "axles", a), x, LENGTH)
            for part in ("weights", "counterweights"):
                for k, w in enumerate(getattr(m, part)):
                    self.terms(("machine", part, k, "P"), w.P, FORCE)
                    self.terms(("machine", part, k, "x"), w.x, LENGTH)
            self.value(("machine", "min_share"), m.min_share, NUMBER, "share")
            self.value(("machine", "implement", "weight"), m.implement.weight, FORCE, "nonneg")

    def use_ranges(self):
        """``[range]``: one per coordinate, of its kind."""
        sp = self.spec
        for c, r in sp.range.items():
            if c not in self.coords:
                raise self.error(("range", c), f'unknown coordinate "{c}": expected one of the '
                                               f'coordinates ({", ".join(self.coords)})'
                                               f"{S.did_you_mean(c, self.coords)}")
            kind = self.kind_of_coordinate(c)
            if r.hold is not None:  # a held coordinate (io/_positions.py, core/held.py)
                quantities = self.solve_quantities()
                if r.hold not in quantities:
                    raise self.error(("range", c, "hold"),
                                     f"expected X<point>, Y<point>, phi<link> or a distance "
                                     f"name, found {S.show(r.hold)}"
                                     f"{S.did_you_mean(r.hold, quantities)}")
                self.value(("range", c, "equals"), r.equals, quantities[r.hold])
                for k, v in enumerate(r.within):
                    self.value(("range", c, "within", k), v, kind)
            elif "values" in r.model_fields_set:
                for k, v in enumerate(r.values):
                    self.value(("range", c, "values", k), v, kind)
            else:
                self.value(("range", c, "from"), r.from_, kind)
                self.value(("range", c, "to"), r.to, kind)
                if "step" in r.model_fields_set:
                    self.value(("range", c, "step"), r.step, kind)
        missing = [c for c in self.coords if c not in sp.range]
        if missing:
            raise self.error(("range",), f"expected a range for every coordinate "
                                         f"({', '.join(self.coords)}), missing "
                                         f"{', '.join(missing)}")

    def solve_quantities(self):
        """The outputs a ``[[solve]]`` condition or a held ``[range]`` names, by kind:
        ``X<point>``, ``Y<point>``, ``phi<link>``, distances."""
        sp = self.spec
        points = list(sp.frame) + [getattr(g, f) for g in self.groups
                                   for f in group_outputs(g)]
        quantities = {f"{a}{p}": LENGTH for p in points for a in "XY"}
        quantities.update({f"phi{l}": ANGLE for l in sp.links})
        quantities.update({f"phi{d[2]}": ANGLE for d in sp.distances.values() if d[2]})
        quantities.update({d: LENGTH for d in sp.distances})
        return quantities

    def use_solve(self):
        """``[[solve]]``: the quantity, the position ``at`` and the target ``equals``."""
        sp = self.spec
        quantities = self.solve_quantities()
        for i, s in enumerate(sp.solve):
            if s.quantity not in quantities:
                raise self.error(("solve", i, "quantity"),
                                 f"expected X<point>, Y<point>, phi<link> or a distance name, "
                                 f"found {S.show(s.quantity)}"
                                 f"{S.did_you_mean(s.quantity, quantities)}")
            self.position(("solve", i, "at"), s.at)
            self.value(("solve", i, "equals"), s.equals, quantities[s.quantity])

    def motion_uses(self):
        """``[motion]``: one entry per coordinate — direction, speed (a value or a
        table in time), start. A crank angle: ``"ccw"``/``"cw"``, an angular velocity;
        a length (a cylinder's rod): ``"extend"``/``"retract"``, a velocity."""
        for c, ms in self.spec.motion.items():
            mp = ("motion", c)
            if c not in self.coords:
                raise self.error(mp, f'unknown coordinate "{c}": expected one of the '
                                     f'coordinates ({", ".join(self.coords)})'
                                     f"{S.did_you_mean(c, self.coords)}")
            kind = self.kind_of_coordinate(c)
            crank = kind is ANGLE
            words = ("ccw", "cw") if crank else ("extend", "retract")
            if ms.direction is not None and ms.direction not in words:
                raise self.error(mp + ("direction",),
                                 f'expected "{words[0]}" or "{words[1]}" for '
                                 f'{"a crank angle" if crank else "a length"} coordinate, '
                                 f'found "{ms.direction}"')
            speed_kind = ANGULAR_VELOCITY if crank else VELOCITY
            if isinstance(ms.speed, dict):
                w = "omega" if "omega" in ms.speed else "v"
                if w != ("omega" if crank else "v"):
                    raise self.error(mp + ("speed", w),
                                     f'a speed table of {"a crank" if crank else "a rod"} '
                                     f'gives {"omega" if crank else "v"} = [...], found {w}')
                for k, v in enumerate(ms.speed["t"]):
                    self.value(mp + ("speed", "t", k), v, TIME)
                for k, v in enumerate(ms.speed[w]):
                    self.value(mp + ("speed", w, k), v, speed_kind, "positive")
            elif ms.speed is not None:
                self.value(mp + ("speed",), ms.speed, speed_kind, "positive")
            if ms.start is not None:
                self.value(mp + ("start",), ms.start, kind)
            if ms.law is not None:
                if ms.speed is not None or ms.start is not None:
                    raise self.error(mp + ("law",), "a law of motion gives the motion whole: "
                                                    "give no speed or start with it")
                for k, v in enumerate(ms.law["t"]):
                    self.value(mp + ("law", "t", k), v, TIME)
                for k, v in enumerate(ms.law["q"]):
                    self.value(mp + ("law", "q", k), v, kind)
