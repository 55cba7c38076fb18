"""From a validated model file to a :class:`~assur.Mechanism`.

Four passes over the file's tables (:class:`Builder`):

1. *Uses.* Every value is looked at where it is used, which fixes its kind (a
   dyad's ``ra`` is a length, a rigid point's ``angle`` an angle, a weight's ``P``
   a force …). A literal value converts to SI at once; a name must be a parameter
   (or, where a length may be one, a generalized coordinate) and the parameter
   takes the kind of its use. A parameter used as two kinds is an error.
2. *Parameters.* Each converts to SI with the kind of its uses: the unit must
   have that dimension; a plain number is SI, or degrees for an angle. A parameter
   that is never used keeps the kind of its unit.
3. *Mechanism.* Frame, groups in order, links, distances, loads, cylinders,
   machine and tables are added one at a time to a :class:`~assur.Mechanism`, each
   point and link name checked against those defined before it; anything the
   mechanism itself refuses is reported at the entry being added.
4. *Solve and range.* The ``[[solve]]`` conditions become
   :class:`~assur.synthesis.conditions.Condition` objects solved by
   :func:`~assur.synthesis.conditions.solve_conditions`; a failure is reported at its
   ``[[solve]]`` entry. The range is evaluated with the solved parameters.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import AssemblyError, ModelError
from ..groups import group_type
from ..groups.base import ref_value, signed_name
from ..core.inputs import bytes_per_position, check_memory, span_problem
from ..core.loads import LOAD_TYPES
from ..core.cylinders import Cylinder
from ..core.mechanism import Mechanism
from ..machines.stability import Machine
from ..core.statics import GRAVITY
from ..texts import text
from . import _schema as S
from ._errors import ModelFileError, key_path
from ._lines import line_of
from ._units import ACCELERATION, ANGLE, ANGULAR_VELOCITY, FORCE, KINDS, LENGTH, NUMBER, TIME, \
    VELOCITY, UnitError, display_unit, is_name, parse, to_si, unit_kind

# constraints on values beyond their kind: (test, words)
_FLAGS = {
    "positive": (lambda v: v > 0, lambda k: f"a positive {k.name}"),
    "nonneg": (lambda v: v >= 0, lambda k: f"a non-negative {k.name}"),
    "fraction": (lambda v: 0 < v <= 1, lambda k: "a number in (0, 1]"),
    "share": (lambda v: 0 <= v < 1, lambda k: "a number in [0, 1)"),
    "count": (lambda v: v > 0, lambda k: "a positive whole number"),
}

#: the unit kind of a group field's ``quantity`` (:class:`assur.groups.Field`)
_QUANTITY = {"length": LENGTH, "angle": ANGLE}


def _group_type(g):
    """The registered group type of a validated ``[[groups]]`` entry."""
    return group_type(g.type)


def _fields(g, *roles):
    """The fields of group entry ``g``'s type with one of ``roles``, in their order."""
    return [f for f in _group_type(g).fields if f.role in roles]


def _group_values(g):
    """``{field: (kind, flag, may be a coordinate)}`` of the value fields of ``g``."""
    return {f.name: (_QUANTITY[f.quantity], f.flag, f.coordinate_ok)
            for f in _fields(g, "value")}


def _group_outputs(g):
    """The names of the point fields of ``g`` that name the points it adds."""
    return tuple(_group_type(g).out_fields)


def _group_inputs(g, gp):
    """``[(key path, point)]`` of the points ``g`` needs: its point fields that are not
    outputs, then the pairs of its line fields that are given."""
    outs = _group_outputs(g)
    inputs = [(gp + (f.name,), getattr(g, f.name)) for f in _fields(g, "point")
              if f.name not in outs]
    for f in _fields(g, "line"):
        pair = getattr(g, f.name)
        if pair is not None:
            inputs += [(gp + (f.name, k), p) for k, p in enumerate(pair)]
    return inputs


#: ``{type: {field: (kind, flag)}}`` and ``{type: point fields}`` of the load types, and
#: the cylinder's value fields — from each type's own declarations (:mod:`assur.core.loads`)
_LOAD_VALUES = {t: {f: (KINDS[q], cls.flags.get(f)) for f, q in cls.quantities.items()}
                for t, cls in LOAD_TYPES.items()}
_LOAD_POINTS = {t: tuple(cls.point_fields) for t, cls in LOAD_TYPES.items()}
_CYLINDER_VALUES = {f: (KINDS[q], Cylinder.flags.get(f)) for f, q in Cylinder.quantities.items()}


#: the kind of span (:data:`assur.core.inputs.SPANS`) a flag asks for
_SPAN_OF_FLAG = {"fraction": "efficiency", "count": "count"}


def _span(kind, flag, si):
    """What is wrong with ``si`` against the physical span of ``kind`` (and ``flag``:
    an efficiency, a cylinder count, a positive value), or None."""
    span = _SPAN_OF_FLAG.get(flag) or (kind.name if kind is not None else None)
    if span is None or isinstance(si, str):
        return None
    return span_problem(span, float(si), flag in ("positive", "count"))


def _unreadable(err, expected, found):
    """Message for a value that :func:`parse` cannot read: what was wrong with it (an
    unknown unit), what was expected and what was found."""
    reason = str(err)
    if reason.startswith("expected"):
        return f"{reason}, found {S.show(found)}"
    return (f"{reason}: " if reason else "") + f"expected {expected}, found {S.show(found)}"


class Builder:
    """Builds one model file; every error is a :class:`ModelFileError` located by
    its key path and the file's line index."""

    def __init__(self, file: str, data: dict, index: dict):
        self.file = file
        self.data = data
        self.index = index
        self.resolved: dict = {}      # key path -> SI value or a name
        self.param_use: dict = {}     # parameter -> (kind, path of the first use)
        self.param_flag: dict = {}    # parameter -> [(flag, path)]
        self.coord_kind: dict = {}    # coordinate -> (kind, path)

    # ---- errors ----------------------------------------------------------------------
    def line(self, path) -> int:
        return line_of(self.index, path)

    def error(self, path, problem) -> ModelFileError:
        path = tuple(path)
        line = self.line(path)
        # a key that a base file gave (``extends``) is located in that file
        file = getattr(line, "file", None) or self.file
        return ModelFileError(file, int(line), key_path(path), problem)

    # ---- pass 0: structure ------------------------------------------------------------
    def validate(self):
        data, errors = self.data, []
        #: [range] paired = true: the coordinates move together, position by position
        self.paired = False
        rng = data.get("range")
        if isinstance(rng, dict) and "paired" in rng and not isinstance(rng["paired"], dict):
            p = rng["paired"]
            data = dict(data, range={k: v for k, v in rng.items() if k != "paired"})
            if not isinstance(p, bool):
                errors.append((("range", "paired"), f"expected true or false, found {S.show(p)}"))
            self.paired = p is True
        spec, errs = S.validate(S.FileSpec, data)
        errors += errs
        self.groups, self.loads = [], []
        for section, types, out in (("groups", S.group_types(), self.groups),
                                    ("loads", S.LOAD_TYPES, self.loads)):
            raw = self.data.get(section, [])
            if not isinstance(raw, list):
                continue
            for i, entry in enumerate(raw):
                if not isinstance(entry, dict):
                    continue
                t = entry.get("type")
                where = (section, i, "type")
                options = ", ".join(types)
                if "type" not in entry:
                    errors.append(((section, i), f'missing required key "type" (one of: '
                                                 f'{options})'))
                elif not isinstance(t, str):
                    errors.append((where, f"expected a string (one of: {options}), found "
                                          f"{S.show(t)}"))
                elif t not in types:
                    what = "group" if section == "groups" else "load"
                    errors.append((where, f'unknown {what} type "{t}"'
                                          f'{S.did_you_mean(t, types)} (one of: {options})'))
                else:
                    obj, errs = S.validate(types[t], entry, (section, i))
                    errors += errs
                    out.append(obj)
        if errors:
            # a misspelt key is both unknown and missing: report what was written first
            errors.sort(key=lambda e: (e[1].startswith("missing"), self.line(e[0])))
            path, problem = errors[0]
            raise self.error(path, problem)
        self.spec = spec

    # ---- pass 1: uses -----------------------------------------------------------------
    def value(self, path, v, kind, flag=None, coordinate_ok=False):
        """Resolve the value ``v`` at ``path`` used as ``kind``: an SI number or a
        parameter/coordinate name (whose use is recorded)."""
        path = tuple(path)
        base = signed_name(v)
        if base is not None and base != str(v).strip():  # "-Mc": −(the parameter Mc)
            if flag or base not in self.params_raw:
                why = (f"expected {_FLAGS[flag][1](kind)}" if flag else
                       f"expected {kind.article} (e.g. {kind.example}) or a parameter name "
                       f"with an optional leading minus")
                raise self.error(path, f'{why}, found "{v}"' + (
                    "" if flag else f', and "{base}" is not a parameter'
                    f"{S.did_you_mean(base, list(self.params_raw))}"))
            self.value(path, base, kind)
            self.resolved[path] = "-" + base
            return "-" + base
        try:
            p = parse(v)
        except UnitError as e:
            raise self.error(path, _unreadable(e, f"{kind.article} (e.g. {kind.example}) or "
                                                  f"a parameter name", v)) from None
        if isinstance(p, str):
            if p in self.coords:
                if not coordinate_ok:
                    raise self.error(path, f"expected {kind.article} (e.g. {kind.example}) or a "
                                           f'parameter, found "{p}", which is a generalized '
                                           f"coordinate")
                self.use_coordinate(path, p, kind)
            elif p in self.params_raw:
                prev = self.param_use.get(p)
                if prev and prev[0] is not kind:
                    raise self.error(path, f'expected {kind.article}, found "{p}", a parameter '
                                           f"used as {prev[0].article} at "
                                           f"{key_path(prev[1])}")
                self.param_use.setdefault(p, (kind, path))
                if flag:
                    self.param_flag.setdefault(p, []).append((flag, path))
            else:
                names = list(self.params_raw) + (list(self.coords) if coordinate_ok else [])
                raise self.error(path, f"expected {kind.article} (e.g. {kind.example}) or a "
                                       f'parameter name, found "{p}", which is not a '
                                       f"parameter{S.did_you_mean(p, names)}")
            self.resolved[path] = p
            return p
        try:
            si = to_si(p, kind)
        except UnitError as e:
            raise self.error(path, f"{e}, found {S.show(v)}") from None
        if flag and not _FLAGS[flag][0](si):
            raise self.error(path, f"expected {_FLAGS[flag][1](kind)}, found {S.show(v)}")
        problem = _span(kind, flag, si)
        if problem:
            raise self.error(path, f"{problem}, found {S.show(v)}")
        self.resolved[path] = si
        return si

    def use_coordinate(self, path, c, kind):
        prev = self.coord_kind.get(c)
        if prev and prev[0] is not kind:
            raise self.error(path, f'the coordinate "{c}" is used as {kind.article} here but '
                                   f"as {prev[0].article} at {key_path(prev[1])}")
        self.coord_kind.setdefault(c, (kind, path))

    def coordinate_field(self, path, c, kind):
        if c not in self.coords:
            raise self.error(path, f"expected a generalized coordinate (one of: "
                                   f"{', '.join(self.coords)}), found {S.show(c)}"
                                   f"{S.did_you_mean(c, self.coords)}")
        self.use_coordinate(path, c, kind)

    def kind_of_coordinate(self, c):
        return self.coord_kind.get(c, (LENGTH,))[0]

    def position(self, path, table):
        """A position ``{coordinate = value, …}`` naming every coordinate."""
        path = tuple(path)
        for c in table:
            if c not in self.coords:
                raise self.error(path + (c,), f'unknown coordinate "{c}": expected one of the '
                                               f'coordinates ({", ".join(self.coords)})'
                                               f"{S.did_you_mean(c, self.coords)}")
        missing = [c for c in self.coords if c not in table]
        if missing:
            raise self.error(path, f"expected the position of every coordinate "
                                   f"({', '.join(self.coords)}), missing {', '.join(missing)}")
        return {c: self.value(path + (c,), table[c], self.kind_of_coordinate(c))
                for c in self.coords}

    def uses(self):
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
                raise self.error(path, _unreadable(e, 'a value (a number, or a number with its '
                                                      'unit such as "0.48 m")', v)) from None
            if isinstance(p, str):
                raise self.error(path, f'expected a value (a number, or a number with its unit '
                                       f'such as "0.48 m"), found {S.show(v)}: a parameter '
                                       f"cannot refer to another")
            self.params_raw[name] = p
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
        # the kind of each coordinate, from the input groups that it drives
        for i, g in enumerate(self.groups):
            for f in _fields(g, "coordinate"):
                self.coordinate_field(("groups", i, f.name), getattr(g, f.name),
                                      _QUANTITY[f.quantity])
        for name, fp in sp.frame.items():
            if isinstance(fp, dict):  # polar: origin + length∠angle
                self.value(("frame", name, "length"), fp["length"], LENGTH, "positive")
                self.value(("frame", name, "angle"), fp["angle"], ANGLE)
            else:
                self.value(("frame", name, 0), fp[0], LENGTH)
                self.value(("frame", name, 1), fp[1], LENGTH)
        for i, g in enumerate(self.groups):
            for field, (kind, flag, coord_ok) in _group_values(g).items():
                if field in g.model_fields_set:
                    self.value(("groups", i, field), getattr(g, field), kind, flag, coord_ok)
            for f in _fields(g, "position"):
                if f.name in g.model_fields_set:
                    self.position(("groups", i, f.name), getattr(g, f.name))
        for j, c in enumerate(self.coords):  # only groups have used coordinates so far
            if c not in self.coord_kind:
                raise self.error(("model", "coordinates", j),
                                 f'the coordinate "{c}" is not used by any group: nothing moves '
                                 f"with it (drive an input group with it, or remove it)")
        self.motion_uses()
        for i, ld in enumerate(self.loads):
            for field, (kind, flag) in _LOAD_VALUES[ld.type].items():
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
            for field, (kind, flag) in _CYLINDER_VALUES.items():
                if field in c.model_fields_set:
                    self.value(("cylinders", i, field), getattr(c, field), kind, flag)
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
        for c, r in sp.range.items():
            if c not in self.coords:
                raise self.error(("range", c), f'unknown coordinate "{c}": expected one of the '
                                               f'coordinates ({", ".join(self.coords)})'
                                               f"{S.did_you_mean(c, self.coords)}")
            kind = self.kind_of_coordinate(c)
            if "values" in r.model_fields_set:
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
        points = list(sp.frame) + [getattr(g, f) for g in self.groups
                                   for f in _group_outputs(g)]
        quantities = {f"{a}{p}": LENGTH for p in points for a in "XY"}
        quantities.update({f"phi{l}": ANGLE for l in sp.links})
        quantities.update({f"phi{d[2]}": ANGLE for d in sp.distances.values() if d[2]})
        quantities.update({d: LENGTH for d in sp.distances})
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

    def motions(self, mech):
        for c, ms in self.spec.motion.items():
            mp = ("motion", c)
            kw = {}
            if isinstance(ms.speed, dict):
                w = "omega" if "omega" in ms.speed else "v"
                kw["t"] = [self.number(mp + ("speed", "t", k)) for k in range(len(ms.speed["t"]))]
                kw["omega"] = [self.number(mp + ("speed", w, k))
                               for k in range(len(ms.speed[w]))]
            elif ms.speed is not None:
                kw["speed"] = self.number(mp + ("speed",))
            if ms.start is not None:
                kw["start"] = self.number(mp + ("start",))
            if ms.law is not None:
                kw["law_t"] = [self.number(mp + ("law", "t", k))
                               for k in range(len(ms.law["t"]))]
                kw["law_q"] = [self.number(mp + ("law", "q", k))
                               for k in range(len(ms.law["q"]))]
            direction = ms.direction or (None if ms.law is not None else
                                         "ccw" if self.kind_of_coordinate(c) is ANGLE
                                         else "extend")
            mech = self.guarded(mp, lambda: mech.with_motion(c, direction, **kw))
        return mech

    # ---- pass 2: parameters ---------------------------------------------------------------
    def parameters(self):
        out = {}
        self.units = {}
        for name, raw in self.params_raw.items():
            path = ("params", name)
            use = self.param_use.get(name)
            kind = use[0] if use else None
            shown = S.show(self.spec.params[name])
            try:
                si = to_si(raw, kind)
            except UnitError as e:
                used = (f" ({name} is used as {kind.article} at {key_path(use[1])})" if use
                        else "")
                raise self.error(path, f"{e}, found {shown}{used}") from None
            flags = self.param_flag.get(name, ())
            for flag, where in flags:
                if not _FLAGS[flag][0](si):
                    raise self.error(path, f"expected {_FLAGS[flag][1](kind)}, found "
                                           f"{shown} ({name} is used at {key_path(where)})")
            for flag, where in tuple(flags) or ((None, use[1] if use else None),):
                problem = _span(kind or (unit_kind(raw) if raw.unit else None), flag, si)
                if problem:
                    at = f" ({name} is used at {key_path(where)})" if where else ""
                    raise self.error(path, f"{problem}, found {shown}{at}")
            out[name] = si
            self.units[name] = display_unit(raw, kind)
        self.params = out
        self.param_kind = {n: (u[0] if u else (unit_kind(r) if r.unit else None))
                           for n, r in self.params_raw.items() for u in [self.param_use.get(n)]}

    # ---- pass 3: the mechanism --------------------------------------------------------------
    def r(self, *path):
        return self.resolved[tuple(path)]

    def point(self, path, p, known, later=None):
        """Check that ``p`` is a point of ``known``; ``later`` (while adding groups) maps
        the points that later groups define to their group."""
        if p in known:
            return
        if later and p in later:
            raise self.error(path, f'point "{p}" is defined later, by {later[p]}: a group may '
                                   f"only use points of the frame and of earlier groups")
        what = ("a point of the frame or of an earlier group" if later is not None else
                "a point of the mechanism")
        raise self.error(path, f'unknown point "{p}": expected {what} ({", ".join(known)}), '
                               f'found "{p}"{S.did_you_mean(p, known)}')

    def guarded(self, path, make):
        try:
            return make()
        except (ModelError, ValueError, TypeError) as e:
            raise self.error(path, str(e)) from None

    def mechanism(self) -> Mechanism:
        sp = self.spec
        mech = self.guarded(("model",), lambda: Mechanism(
            sp.model.name, coordinates=self.coords, params=self.params, units=self.units,
            title=text(sp.model.title), notes=tuple(text(n) for n in sp.model.notes)))
        known = {}  # point -> where defined
        frame_names = list(sp.frame)
        for name, fp in sp.frame.items():
            if isinstance(fp, dict):
                o = fp["origin"]
                if o not in known:
                    if o in frame_names:
                        raise self.error(("frame", name, "origin"),
                                         f'frame point "{o}" is not defined before "{name}": '
                                         f"a polar frame point is placed from a frame point "
                                         f"written before it")
                    raise self.error(("frame", name, "origin"),
                                     f'unknown frame point "{o}": expected one of the frame '
                                     f'points written before it ({", ".join(known)})'
                                     f"{S.did_you_mean(o, frame_names)}")
                mech = self.guarded(("frame", name), lambda: mech.frame(
                    name, origin=o, length=self.r("frame", name, "length"),
                    angle=self.r("frame", name, "angle")))
            else:
                mech = self.guarded(("frame", name), lambda: mech.frame(
                    name, self.r("frame", name, 0), self.r("frame", name, 1)))
            known[name] = "the frame"
        # every point a group defines, to tell "defined later" from "unknown"
        later = {}
        for i, g in enumerate(self.groups):
            for f in _group_outputs(g):
                later.setdefault(getattr(g, f), f"groups[{i}] ({g.name})")
        names = {n: "the frame" for n in sp.frame}
        for i, g in enumerate(self.groups):
            gp = ("groups", i)
            if g.name in names:
                raise self.error(gp + ("name",), f'the name "{g.name}" is already used by '
                                                 f"{names[g.name]}")
            for path, p in _group_inputs(g, gp):
                self.point(path, p, known, {q: w for q, w in later.items() if q not in known})
            outs = [(gp + (f,), getattr(g, f)) for f in _group_outputs(g)]
            for path, p in outs:
                if p in known:
                    raise self.error(path, f'point "{p}" is already defined by {known[p]}')
            want = _group_type(g).link_roles
            if g.links and ((want is None and len(g.links) > 1) or
                            (want is not None and len(g.links) != len(want))):
                expect = ("at most one link name (the link that carries the point)"
                          if want is None else
                          f"{len(want)} link name{'s' if len(want) > 1 else ''} "
                          f"({', '.join(want)})")
                raise self.error(gp + ("links",), f"expected {expect}, found {S.show(g.links)}")
            kw = {f: getattr(g, f) for f in g.model_fields_set - {"type", "name"}}
            for f in _group_values(g):
                if (gp + (f,)) in self.resolved:
                    kw[f] = self.resolved[gp + (f,)]
            for f in _fields(g, "line"):
                if kw.get(f.name) is not None:
                    kw[f.name] = tuple(kw[f.name])
            for f in _fields(g, "position"):
                if f.name in kw:
                    kw[f.name] = tuple(self.resolved[gp + (f.name, c)] for c in self.coords)
            if "links" in kw:
                kw["links"] = tuple(kw["links"])
            mech = self.guarded(gp, lambda: mech.add_group(g.type, g.name, **kw))
            names[g.name] = f"groups[{i}]"
            for _, p in outs:
                known[p] = f"groups[{i}] ({g.name})"
        points = list(known)
        for section, add in (("links", "link"), ("distances", "distance")):
            for name, ends in getattr(sp, section).items():
                form = isinstance(self.data[section][name], dict)
                for k, p in enumerate(ends[:2]):
                    self.point((section, name) + (("ab"[k],) if form else (k,)), p, points)
                if section == "distances" and name in sp.links:
                    raise self.error((section, name), f'the name "{name}" is already a link '
                                                      f"in [links]")
                if section == "distances" and ends[2] is not None and \
                        ends[2] in set(sp.links) | set(sp.distances):
                    raise self.error((section, name, "angle"),
                                     f'the name "{ends[2]}" is already a link or a distance')
                mech = self.guarded((section, name), lambda: getattr(mech, add)(name, *ends))
        bodies = list(mech.bodies)

        def body(path, b):
            if b not in bodies:
                raise self.error(path, f'unknown link "{b}": expected a link of the mechanism '
                                       f'({", ".join(bodies)}), found "{b}"'
                                       f"{S.did_you_mean(b, bodies)}")

        for i, ld in enumerate(self.loads):
            lp = ("loads", i)
            for f in _LOAD_POINTS[ld.type]:
                self.point(lp + (f,), getattr(ld, f), points)
            for f in LOAD_TYPES[ld.type].link_fields:
                value = getattr(ld, f, None)
                if isinstance(value, str):
                    body(lp + (f,), value)
                elif value is not None:
                    for k, b in enumerate(value):
                        body(lp + (f, k), b)
            kw = {f: getattr(ld, f) for f in ld.model_fields_set - {"type"}}
            for f in _LOAD_VALUES[ld.type]:
                if lp + (f,) in self.resolved:
                    kw[f] = self.resolved[lp + (f,)]
            for f in LOAD_TYPES[ld.type].link_fields:  # a list of links is a tuple inside
                if isinstance(kw.get(f), list):
                    kw[f] = tuple(kw[f])
            add = getattr(mech, ld.type)
            mech = self.guarded(lp, lambda: add(**kw))
        seen = {}
        for i, c in enumerate(sp.cylinders):
            cp = ("cylinders", i)
            if c.name in seen:
                raise self.error(cp + ("name",), f'the cylinder name "{c.name}" is already used '
                                                 f"by cylinders[{seen[c.name]}]")
            seen[c.name] = i
            kw = {f: self.resolved[cp + (f,)] for f in _CYLINDER_VALUES if cp + (f,) in
                  self.resolved}
            for f in ("side", "distance", "supply"):
                if f in c.model_fields_set:
                    kw[f] = getattr(c, f)
            if c.side == "rod":  # the annulus π(D² − d²)/4 needs 0 < d < D
                bore = self.number(cp + ("bore",))
                rod = self.number(cp + ("rod",)) if cp + ("rod",) in self.resolved else 0.0
                if not 0 < rod < bore:
                    raise self.error(cp + ("rod",) if cp + ("rod",) in self.resolved else cp,
                                     f"a rod-side cylinder needs 0 < rod < bore, found rod "
                                     f"{S.show(c.rod)} = {rod:.6g} m and bore {S.show(c.bore)} = "
                                     f"{bore:.6g} m")
            if c.distance is not None and c.distance not in sp.distances:
                raise self.error(cp + ("distance",), f'unknown distance "{c.distance}": a '
                                                     f"passive cylinder's length is a name of "
                                                     f"[distances] ({', '.join(sp.distances)})"
                                                     f"{S.did_you_mean(c.distance, list(sp.distances))}")
            mech = self.guarded(cp, lambda: mech.cylinder(c.name, c.coordinate, **kw))
        if sp.machine is not None:
            mech = self.machine(mech, points)
        if sp.tables is not None:
            mech = self.tables(mech, points, bodies)
            mech = self.extra_columns(mech)
        mech = self.motions(mech)
        if self._uses_gravity:
            gv, gp = self.spec.model.gravity, ("model", "gravity")
            if gv == "none":
                g, d = "none", None
            elif isinstance(gv, dict):
                g = self.number(gp + ("value",)) if "value" in gv else GRAVITY
                d = self.number(gp + ("direction",)) if "direction" in gv else None
            else:
                g, d = self.number(gp), None
            mech = self.guarded(gp, lambda: mech.with_gravity(g, d))
        return mech

    def terms(self, path, v, kind):
        """Resolve a machine value: a value, a parameter name with an optional leading
        "-", or a list of such terms (added). Records ``[(sign, SI number or name)]``."""
        path = tuple(path)
        items = v if isinstance(v, list) else [v]
        out = []
        for i, t in enumerate(items):
            sub = path + (i,) if isinstance(v, list) else path
            sign = 1.0
            if isinstance(t, str) and t.strip().startswith("-") and is_name(t.strip()[1:]):
                sign, t = -1.0, t.strip()[1:]
            out.append((sign, self.value(sub, t, kind)))
        self.resolved[path] = ("terms", out)
        return out

    def number(self, path):
        """A resolved value as a number (a parameter name gives its value; terms add)."""
        v = self.resolved[tuple(path)]
        if isinstance(v, tuple) and v[:1] == ("terms",):
            return sum(s * float(ref_value(self.params, r))
                       for s, r in v[1])
        return float(ref_value(self.params, v))

    def refs(self, path):
        """The terms of a machine value as ``((sign, number or parameter name), …)``."""
        v = self.resolved[tuple(path)]
        return tuple(v[1])

    def machine(self, mech, points):
        m = self.spec.machine
        mp = ("machine",)
        if len(m.axles) != 2:
            raise self.error(mp + ("axles",), f"expected exactly two axles, found "
                                              f"{len(m.axles)} ({', '.join(m.axles) or 'none'})")
        if m.steered not in m.axles:
            raise self.error(mp + ("steered",), f"expected one of the axles "
                                                f"({', '.join(m.axles)}), found "
                                                f"{S.show(m.steered)}"
                                                f"{S.did_you_mean(m.steered, m.axles)}")
        self.point(mp + ("implement", "point"), m.implement.point, points)
        axles = {a: self.number(mp + ("axles", a)) for a in m.axles}

        def items(part):
            return [(w.name, self.number(mp + (part, k, "P")), self.number(mp + (part, k, "x")))
                    for k, w in enumerate(getattr(m, part))]

        kw = {}
        if "min_share" in m.model_fields_set:
            kw["min_share"] = self.number(mp + ("min_share",))
        machine = self.guarded(mp, lambda: Machine(axles, steered=m.steered,
                                                   weights=items("weights"),
                                                   counterweights=items("counterweights"),
                                                   **kw))
        weight = self.resolved[mp + ("implement", "weight")]
        refs = {"axles": {a: self.refs(mp + ("axles", a)) for a in m.axles}}
        for part in ("weights", "counterweights"):
            refs[part] = tuple((w.name, self.refs(mp + (part, k, "P")),
                                self.refs(mp + (part, k, "x")))
                               for k, w in enumerate(getattr(m, part)))
        return self.guarded(mp, lambda: mech.with_machine(machine, m.implement.point, weight,
                                                          refs=refs))

    def tables(self, mech, points, bodies):
        t = self.spec.tables
        tp = ("tables",)
        links = [l.name for l in mech.links]
        out = {}
        if t.ratios is not None:
            for k, pair in enumerate(t.ratios):
                for j, l in enumerate(pair):
                    if l not in links:
                        raise self.error(tp + ("ratios", k, j),
                                         f'unknown link "{l}": expected a link of [links] '
                                         f'({", ".join(links)}), found "{l}"'
                                         f"{S.did_you_mean(l, links)}")
            out["ratios"] = [tuple(p) for p in t.ratios]
        if t.transmissions is not None:
            for k, p in enumerate(t.transmissions):
                self.point(tp + ("transmissions", k), p, points)
            out["transmissions"] = list(t.transmissions)
        if t.reactions is not None:
            for name, (i, j) in t.reactions.items():
                for k, b in enumerate((i, j)):
                    if b not in bodies:
                        raise self.error(tp + ("reactions", name, k),
                                         f'unknown link "{b}": expected a link of the '
                                         f'mechanism ({", ".join(bodies)}), found "{b}"'
                                         f"{S.did_you_mean(b, bodies)}")
            out["reactions"] = {n: tuple(v) for n, v in t.reactions.items()}
        if t.symbols is not None:
            out["symbols"] = dict(t.symbols)
        for key in ("angles", "analogs", "second_order"):
            if getattr(t, key) is not None:
                out[key] = getattr(t, key)
        if t.dead_loads is not None:  # links whose loads every capacity carries
            from ..core.loads import load_link
            for k, b in enumerate(t.dead_loads):
                path = tp + ("dead_loads", k)
                if b not in bodies or b == "0":
                    moving = [x for x in bodies if x != "0"]
                    raise self.error(path, f'unknown link "{b}": expected a moving link of the '
                                           f'mechanism ({", ".join(moving)}), found "{b}"'
                                           f"{S.did_you_mean(b, moving)}")
                if not any(load_link(mech, ld) == b for ld in mech.loads):
                    raise self.error(path, f'no load acts on link "{b}": a dead load is the '
                                           f"weight or mass of a link ([[loads]] on it)")
            out["dead_loads"] = list(t.dead_loads)
        return mech.with_tables(**out)

    def extra_columns(self, mech):
        """``[[tables.formulas]]`` and ``[[tables.signs]]``: :mod:`assur.core.columns`."""
        from ..core.columns import Formula, FormulaError, SignMap
        from ..core.columns import TABLE_IDS
        t = self.spec.tables
        tp = ("tables",)
        out = {}
        if t.formulas is not None:
            formulas, seen = [], {}
            for k, f in enumerate(t.formulas):
                fp = tp + ("formulas", k)
                if f.name in seen:
                    raise self.error(fp + ("name",), f'the formula name "{f.name}" is already '
                                                     f"used by tables.formulas[{seen[f.name]}]")
                seen[f.name] = k
                if f.table is not None and f.table not in TABLE_IDS:
                    raise self.error(fp + ("table",), f"expected the id of a table "
                                                      f"({', '.join(TABLE_IDS)}), found "
                                                      f"{S.show(f.table)}"
                                                      f"{S.did_you_mean(f.table, TABLE_IDS)}")
                scale = self.display_scale(fp + ("unit",), f.unit)
                try:
                    formula = Formula(f.name, f.expr, unit=f.unit, scale=scale, table=f.table,
                                      label=text(f.label),
                                      flags=tuple(text(x) for x in f.flags))
                    formula.check(mech)
                except FormulaError as e:
                    raise self.error(fp + ("expr",), str(e)) from None
                formulas.append(formula)
            out["formulas"] = tuple(formulas)
        if t.signs is not None:
            out["signs"] = tuple(SignMap(tuple(m.columns), m.sign, text(m.note)) for m in t.signs)
        return mech.with_tables(**out) if out else mech

    def display_scale(self, path, unit):
        """SI value of one ``unit`` (``"N"``, ``"kN"``, ``"deg"``, ``"-"``) a column is
        shown in."""
        if unit.strip() in ("-", ""):
            return 1.0
        try:
            raw = parse(f"1 {unit}")
            if isinstance(raw, str):
                raise UnitError("")
            return float(to_si(raw, None))
        except UnitError as e:
            raise self.error(path, _unreadable(e, 'a unit (e.g. "N", "kN", "deg", "-")',
                                               unit)) from None

    # ---- pass 4: design conditions and the range ------------------------------------------
    def quantities(self, mech):
        q = {f"{a}{p}": LENGTH for p in mech.points for a in "XY"}
        q.update({f"phi{l.name}": ANGLE for l in mech.links})
        q.update({d.name: LENGTH for d in mech.distances})
        return q

    def conditions(self, mech):
        from ..synthesis.conditions import Condition
        conds = []
        solved_by = {}
        quantities = self.quantities(mech)
        for i, s in enumerate(self.spec.solve):
            sp = ("solve", i)
            if s.unknown not in self.params:
                raise self.error(sp + ("unknown",),
                                 f"expected a parameter name, found {S.show(s.unknown)}"
                                 f"{S.did_you_mean(s.unknown, self.params)}")
            if s.unknown in solved_by:
                raise self.error(sp + ("unknown",), f'"{s.unknown}" is already solved by '
                                                    f"solve[{solved_by[s.unknown]}]")
            solved_by[s.unknown] = i
            if s.quantity not in quantities:
                raise self.error(sp + ("quantity",),
                                 f"expected X<point>, Y<point>, phi<link> or a distance name, "
                                 f"found {S.show(s.quantity)}"
                                 f"{S.did_you_mean(s.quantity, quantities)}")
            bracket = [self.bracket_value(sp + ("bracket", k), v, s.unknown)
                       for k, v in enumerate(s.bracket)]
            if not bracket[0] < bracket[1]:
                raise self.error(sp + ("bracket",), f"expected [low, high] with low < high, "
                                                    f"found {S.show(list(s.bracket))}")
            target = self.resolved[sp + ("equals",)]
            raw = parse(s.equals)
            if isinstance(target, str):
                shown = self.units.get(signed_name(target) or target)
                target = ref_value(self.params, target)
            else:
                shown = display_unit(raw, quantities[s.quantity])
            at = {c: self.resolved[sp + ("at", c)] for c in self.coords}
            line = self.line(sp)
            file = getattr(line, "file", None) or self.file
            conds.append(Condition(s.unknown, tuple(bracket), at, s.quantity, float(target),
                                   source=f"{file}:{int(line)}", unit=shown))
        return conds

    def bracket_value(self, path, v, unknown):
        """One end of a ``[[solve]]`` bracket: a value of the unknown's kind, or another
        parameter of that kind (its start value)."""
        kind = self.param_kind.get(unknown)
        what = kind.article if kind else "a value"
        try:
            p = parse(v)
        except UnitError as e:
            raise self.error(path, _unreadable(e, f"{what} for {unknown}", v)) from None
        if isinstance(p, str):
            if p not in self.params or p == unknown:
                raise self.error(path, f"expected {what} for {unknown} (a number with its unit, "
                                       f"or another parameter), found {S.show(v)}"
                                       + ("" if p == unknown else
                                          S.did_you_mean(p, self.params)))
            pk = self.param_kind.get(p)
            if pk is not kind:
                raise self.error(path, f"expected a parameter of the kind of {unknown} "
                                       f"({kind.name if kind else 'unknown'}), found "
                                       f"{S.show(v)}, "
                                       f"{pk.article if pk else 'a parameter of unknown kind'}")
            return float(self.params[p])
        if kind is None and p.unit is not None and self.params_raw[unknown].unit is not None \
                and unit_kind(p) is not unit_kind(self.params_raw[unknown]):
            raise self.error(path, f"expected a value of the kind of {unknown} "
                                   f"({self.spec.params[unknown]}), found {S.show(v)}")
        try:
            return to_si(p, kind)
        except UnitError as e:
            raise self.error(path, _unreadable(e, f"{what} for {unknown}", v)) from None

    def solve(self, mech):
        from ..synthesis.conditions import DesignError, solve_conditions
        from . import _solve_cache
        conds = self.conditions(mech)
        if not conds:
            return mech, []
        try:  # roots cached per file (verified by their residuals before use)
            return _solve_cache.solve(self.data, mech, conds, solve_conditions)
        except (DesignError, AssemblyError, ModelError) as e:
            msg = str(e)
            i = next((k for k, c in enumerate(conds) if f"({c.source})" in msg), 0)
            for c in conds:
                msg = msg.replace(f" ({c.source})", "")
            raise self.error(("solve", i), msg) from None

    def memory(self, mech, paths, count, counts):
        """Refuse a range whose grid (with the coordinates before it, ``counts``) would
        need more memory than :func:`assur.core.inputs.max_memory`, before allocating."""
        total = count
        for c in counts.values():
            total = max(total, c) if self.paired else total * c
        try:
            check_memory(total, bytes_per_position(mech),
                         "the range" if len(self.coords) == 1 else "the grid of the ranges")
        except ModelError as e:
            raise self.error(paths[0], str(e)) from None

    def positions(self, mech):
        params = mech.params
        axes = {}
        counts = {}
        for c in self.coords:
            r = self.spec.range[c]
            rp = ("range", c)

            def val(path):
                return float(ref_value(params, self.resolved[path]))

            if "values" in r.model_fields_set:
                a = np.array([val(rp + ("values", k)) for k in range(len(r.values))])
            else:
                lo, hi = val(rp + ("from",)), val(rp + ("to",))
                if lo == hi:
                    raise self.error(rp + ("to",), f"expected a value different from "
                                                   f"from = {S.show(r.from_)}, found "
                                                   f"{S.show(r.to)}")
                count = r.count
                if count is not None:
                    self.memory(mech, [rp + ("count",)], float(count), counts)
                else:  # from, to and step: the step must divide the span
                    step = val(rp + ("step",))
                    n = (hi - lo) / step if step else -1.0
                    if n > 0:  # before rounding: a step of 1e-300 m gives inf positions
                        self.memory(mech, [rp + ("step",)], n + 1, counts)
                    if not (math.isfinite(n) and n > 0
                            and abs(n - round(n)) <= 1e-9 * max(1.0, abs(n))):
                        raise self.error(rp + ("step",),
                                         f"expected a step that divides to − from = "
                                         f"{hi - lo:.6g} into whole intervals (with the sign "
                                         f"of to − from), found {S.show(r.step)}")
                    count = int(round(n)) + 1
                a = np.linspace(lo, hi, count)
            counts[c] = a.size
            if "values" in r.model_fields_set:
                self.memory(mech, [rp + ("values",)], a.size, {k: v for k, v in counts.items()
                                                               if k != c})
            a.setflags(write=False)
            axes[c] = a
        if self.paired:  # paired paths: position i of every coordinate together
            if len(self.coords) < 2:
                raise self.error(("range", "paired"), "paired paths need two or more "
                                                      "coordinates; this model has one")
            sizes = {c: axes[c].size for c in self.coords}
            if len(set(sizes.values())) > 1:
                raise self.error(("range", "paired"),
                                 "paired paths need the same number of positions for every "
                                 "coordinate, found " + ", ".join(f"{c}: {n}"
                                                                  for c, n in sizes.items()))
            grid = np.stack([axes[c] for c in self.coords], axis=-1)
            grid.setflags(write=False)
        elif len(self.coords) == 1:
            grid = axes[self.coords[0]]
        else:
            mesh = np.meshgrid(*(axes[c] for c in self.coords), indexing="ij")
            grid = np.stack([g.ravel() for g in mesh], axis=-1)
            grid.setflags(write=False)
        return grid, axes

    def precheck_memory(self, mech):
        """Refuse ranges given by ``count`` or ``values`` that are too large before the
        ``[[solve]]`` conditions run (a step's count needs the solved parameters)."""
        counts, paths = {}, []
        for c in self.coords:
            r = self.spec.range[c]
            if "values" in r.model_fields_set:
                counts[c] = len(r.values)
                paths.append(("range", c, "values"))
            elif r.count is not None:
                counts[c] = r.count
                paths.append(("range", c, "count"))
        if paths:
            self.memory(mech, paths[::-1], 1.0, counts)

    def unused_parameters(self, mech):
        """Warnings (``file:line: params.<name>: …``) for the parameters that nothing
        uses: no group, frame point, load, cylinder, machine value, range, motion,
        ``[[solve]]`` condition (unknown, bracket, target) or table formula."""
        from ..core.columns import formulas_of
        used = set(self.param_use)
        for s in self.spec.solve:
            used.add(s.unknown)
            used.update(v for v in s.bracket if isinstance(v, str))
        for f in formulas_of(mech):
            used.update(f.names)
        out = []
        for name in self.params_raw:
            if name not in used:
                path = ("params", name)
                line = self.line(path)
                file = getattr(line, "file", None) or self.file
                out.append(f"{file}:{int(line)}: {key_path(path)}: the parameter {name!r} is "
                           f"not used by any group, frame point, load, condition or table "
                           f"(a misspelt name?)")
        return out

    def build(self):
        self.validate()
        self.uses()
        self.parameters()
        mech = self.mechanism()
        from ._dynamics import build_dynamics
        self.dynamics = build_dynamics(self, mech)  # [dynamics]: io/_dynamics.py
        from ._lift_test import build_lift_test
        self.lift_test = build_lift_test(self, mech)  # [lift_test]: io/_lift_test.py
        from ._tolerances import build_tolerances
        self.tolerances = build_tolerances(self, mech)  # [tolerances]: io/_tolerances.py
        self.drive = self.simulation = None
        if "drive" in self.data or "simulation" in self.data:  # [[drive]]: io/_drive.py
            from ._drive import build_drive
            self.drive, self.simulation = build_drive(self, mech)
        self.warnings = self.unused_parameters(mech)
        self.precheck_memory(mech)
        conds_mech, solved = self.solve(mech)
        grid, axes = self.positions(conds_mech)
        return conds_mech, grid, axes, solved
