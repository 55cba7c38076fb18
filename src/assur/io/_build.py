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
   mechanism itself refuses is reported at the entry being added; then the wheels
   drawn on it (``[[wheels]]``, :mod:`assur.io._wheels`, whose values' uses join
   pass 1).
4. *Solve and range.* The ``[[solve]]`` conditions become
   :class:`~assur.synthesis.conditions.Condition` objects solved by
   :func:`~assur.synthesis.conditions.solve_conditions`; a failure is reported at its
   ``[[solve]]`` entry. The range is evaluated with the solved parameters.

This module holds the :class:`Builder` with the structural pass (0), the resolution of
values shared by all passes and the parameters (pass 2); the uses (pass 1,
:mod:`assur.io._uses`), the mechanism (pass 3, :mod:`assur.io._assemble`) and the
conditions and range (pass 4, :mod:`assur.io._positions`) are its other parts; what
they share about values and entries is :mod:`assur.io._entries`.
"""

from __future__ import annotations

from ..errors import ModelError
from ..groups.base import ref_value, signed_name
from . import _schema as S
from ._assemble import Assembly
from ._entries import FLAGS, span, unreadable
from ._errors import ModelFileError, key_path
from ._lines import line_of
from ._positions import Conditions
from ._units import LENGTH, UnitError, display_unit, is_name, parse, to_si, unit_kind
from ._uses import Uses


class Builder(Uses, Assembly, Conditions):
    """Builds one model file; every error is a :class:`ModelFileError` located by
    its key path and the file's line index. Its passes are its parts: :class:`Uses`
    (pass 1), :class:`Assembly` (pass 3), :class:`Conditions` (pass 4)."""

    def __init__(self, file: str, data: dict, index: dict):
        self.file = file
        self.data = data
        self.index = index
        self.resolved: dict = {}      # key path -> SI value or a name
        self.param_use: dict = {}     # parameter -> (kind, path of the first use)
        self.param_flag: dict = {}    # parameter -> [(flag, path)]
        self.coord_kind: dict = {}    # coordinate -> (kind, path)
        self.literal_units: list = []  # the Unit of each value written with a unit

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
        self.groups, errs = self.typed_entries("groups", S.group_types())
        errors += errs
        self.loads, errs = self.typed_entries("loads", S.load_types())
        errors += errs
        if errors:
            # a misspelt key is both unknown and missing: report what was written first
            errors.sort(key=lambda e: (e[1].startswith("missing"), self.line(e[0])))
            path, problem = errors[0]
            raise self.error(path, problem)
        self.spec = spec

    def typed_entries(self, section, types):
        """The entries of the array of tables ``section`` validated by the model of their
        ``type`` (``types``: by name), and the errors ``[(path, message)]``."""
        out, errors = [], []
        raw = self.data.get(section, [])
        if not isinstance(raw, list):
            return out, errors
        options = ", ".join(types)
        for i, entry in enumerate(raw):
            if not isinstance(entry, dict):
                continue
            t = entry.get("type")
            where = (section, i, "type")
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
        return out, errors

    # ---- values (every pass) ----------------------------------------------------------
    def value(self, path, v, kind, flag=None, coordinate_ok=False):
        """Resolve the value ``v`` at ``path`` used as ``kind``: an SI number or a
        parameter/coordinate name (whose use is recorded)."""
        path = tuple(path)
        base = signed_name(v)
        if base is not None and base != str(v).strip():  # "-Mc": −(the parameter Mc)
            if flag or base not in self.params_raw:
                why = (f"expected {FLAGS[flag][1](kind)}" if flag else
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
            raise self.error(path, unreadable(e, f"{kind.article} (e.g. {kind.example}) or "
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
        if p.unit:  # the units the file writes its values in (the "file" display units)
            self.literal_units.append(display_unit(p, kind))
        if flag and not FLAGS[flag][0](si):
            raise self.error(path, f"expected {FLAGS[flag][1](kind)}, found {S.show(v)}")
        problem = span(kind, flag, si)
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

    # ---- pass 2: parameters ---------------------------------------------------------------
    def parameters(self):
        """Each parameter in SI with the kind of its uses (its unit must have that
        dimension; a plain number is SI, or degrees for an angle), its flags and span
        checked; an unused one keeps the kind of its unit."""
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
                if not FLAGS[flag][0](si):
                    raise self.error(path, f"expected {FLAGS[flag][1](kind)}, found "
                                           f"{shown} ({name} is used at {key_path(where)})")
            for flag, where in tuple(flags) or ((None, use[1] if use else None),):
                problem = span(kind or (unit_kind(raw) if raw.unit else None), flag, si)
                if problem:
                    at = f" ({name} is used at {key_path(where)})" if where else ""
                    raise self.error(path, f"{problem}, found {shown}{at}")
            out[name] = si
            self.units[name] = display_unit(raw, kind)
        self.params = out
        self.param_kind = {n: (u[0] if u else (unit_kind(r) if r.unit else None))
                           for n, r in self.params_raw.items() for u in [self.param_use.get(n)]}

    # ---- checks and resolved values (pass 3 and after) -----------------------------------
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

    def build(self):
        self.validate()
        self.uses()
        from ._wheels import build_wheels, use_wheels
        use_wheels(self)  # [[wheels]]: io/_wheels.py
        self.parameters()
        mech = build_wheels(self, self.mechanism())
        # the optional sections' readers are imported only for a file that has the
        # section (each returns its empty value without it): `assur check` of a file
        # without them imports none of their modules
        self.dynamics, self.lift_test, self.ratings, self.tolerances = None, None, (), ()
        if "dynamics" in self.data:
            from ._dynamics import build_dynamics
            self.dynamics = build_dynamics(self, mech)  # [dynamics]: io/_dynamics.py
        if "lift_test" in self.data:
            from ._lift_test import build_lift_test
            self.lift_test = build_lift_test(self, mech)  # [lift_test]: io/_lift_test.py
        if "rating" in self.data:
            from ._ratings import build_ratings
            self.ratings = build_ratings(self, mech)  # [[rating]]: io/_ratings.py
        if "tolerances" in self.data:
            from ._tolerances import build_tolerances
            self.tolerances = build_tolerances(self, mech)  # [tolerances]: io/_tolerances.py
        self.drive = self.simulation = None
        if "drive" in self.data or "simulation" in self.data:  # [[drive]]: io/_drive.py
            from ._drive import build_drive
            self.drive, self.simulation = build_drive(self, mech)
        self.warnings = self.unused_parameters(mech)
        self.precheck_memory(mech)
        # the units of every value written with one, the drive's too (the "file" display)
        mech = mech._with(display=dict(mech.display, given=tuple(self.literal_units)))
        conds_mech, solved = self.solve(mech)
        grid, axes = self.positions(conds_mech)
        return conds_mech, grid, axes, solved
