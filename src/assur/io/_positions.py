"""Pass 4 of the file loader (:class:`assur.io._build.Builder`): the ``[[solve]]``
conditions become :class:`~assur.synthesis.conditions.Condition` objects solved by
:func:`~assur.synthesis.conditions.solve_conditions` (a failure reported at its
``[[solve]]`` entry); the range is evaluated with the solved parameters, its memory
checked before anything is allocated; the parameters nothing uses are warned about.
"""

from __future__ import annotations

import math

import numpy as np

from ..core.inputs import bytes_per_position, check_memory
from ..errors import AssemblyError, ModelError
from ..groups.base import ref_value, signed_name
from . import _schema as S
from ._entries import unreadable
from ._errors import key_path
from ..texts import Text
from ._units import ANGLE, LENGTH, UnitError, display_unit, parse, to_si, unit_kind


class Conditions:
    """The conditions and range pass, a part of :class:`~assur.io._build.Builder`."""

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
            # the unknown in the unit its bracket is written in (else the parameter's)
            written = [parse(v) for v in s.bracket]
            given = [p for p in written if not isinstance(p, str) and p.unit is not None]
            unknown_unit = (display_unit(given[0], self.param_kind.get(s.unknown)) if given
                            else self.units.get(s.unknown))
            conds.append(Condition(s.unknown, tuple(bracket), at, s.quantity, float(target),
                                   source=f"{file}:{int(line)}", unit=shown,
                                   unknown_unit=unknown_unit))
        return conds

    def bracket_value(self, path, v, unknown):
        """One end of a ``[[solve]]`` bracket: a value of the unknown's kind, or another
        parameter of that kind (its start value)."""
        kind = self.param_kind.get(unknown)
        what = kind.article if kind else "a value"
        try:
            p = parse(v)
        except UnitError as e:
            raise self.error(path, unreadable(e, f"{what} for {unknown}", v)) from None
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
            raise self.error(path, unreadable(e, f"{what} for {unknown}", v)) from None

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

    def held(self):
        """The coordinates of ``[range]`` held by a condition (``hold``/``equals``)."""
        return [c for c in self.coords if self.spec.range[c].hold is not None]

    def unit_of(self, v, kind):
        """The unit a value was written in (a parameter's: its own), for messages."""
        p = parse(v)
        if isinstance(p, str):
            return self.units.get(signed_name(p) or p)
        return display_unit(p, kind)

    def held_path(self, mech, axes):
        """The held coordinates solved at every position of the one coordinate given
        (:func:`assur.core.held.hold_path`), a failure reported at its ``hold`` key."""
        from ..core.held import Hold, hold_path
        held = self.held()
        free = [c for c in self.coords if c not in held]
        if len(free) != 1:
            raise self.error(("range", held[0], "hold"),
                             f"a held coordinate needs a path: one coordinate given by from/to "
                             f"or values and every other one held; given "
                             f"{', '.join(free) or 'none'}")
        along = free[0]
        quantities = self.quantities(mech)
        holds = []
        for c in held:
            r, rp = self.spec.range[c], ("range", c)
            target = self.resolved[rp + ("equals",)]
            # the parameters a design search reads each design's target and limits from
            refs = (target,) + tuple(self.resolved[rp + ("within", k)] for k in range(2))
            refs = tuple(v if isinstance(v, str) else None for v in refs)
            if isinstance(target, str):
                shown = self.units.get(signed_name(target) or target)
                target = ref_value(mech.params, target)
            else:
                shown = display_unit(parse(r.equals), quantities.get(r.hold))
            kind = self.kind_of_coordinate(c)
            within = tuple(float(ref_value(mech.params, self.resolved[rp + ("within", k)]))
                           for k in range(2))
            if not within[0] < within[1]:
                raise self.error(rp + ("within",), f"expected [low, high] with low < high, "
                                                   f"found {S.show(list(r.within))}")
            line = self.line(rp + ("hold",))
            file = getattr(line, "file", None) or self.file
            holds.append(Hold(c, r.hold, float(target), within, unit=shown,
                              coordinate_unit=self.unit_of(r.within[0], kind),
                              source=f"{file}:{int(line)}", refs=refs))
        ar = self.spec.range[along]
        aunit = self.unit_of(ar.values[0] if "values" in ar.model_fields_set else ar.from_,
                             self.kind_of_coordinate(along))
        try:
            check_memory(axes[along].size * 41, bytes_per_position(mech),
                         "the scan of the held coordinate's limits (41 samples a position)")
        except ModelError as e:
            raise self.error(("range", held[0], "hold"), str(e)) from None
        try:
            path = hold_path(mech, along, axes[along], holds, along_unit=aunit)
        except (AssemblyError, ModelError) as e:
            msg = str(e)
            i = next((k for k, h in enumerate(holds) if f"({h.source})" in msg), 0)
            raise self.error(("range", held[i], "hold"),
                             msg.replace(f" ({holds[i].source})", "")) from None
        return path

    def positions(self, mech):
        params = mech.params
        axes = {}
        counts = {}
        held = self.held()
        self.path = None
        for c in self.coords:
            if c in held:
                continue
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
        if held:  # a path: the held coordinates solved at each position of the given one
            self.path = self.held_path(mech, axes)
            self.paired = True
            axes = {c: np.ascontiguousarray(self.path.q[:, j])
                    for j, c in enumerate(self.coords)}
            for a in axes.values():
                a.setflags(write=False)
            return self.path.q, axes
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
            if r.hold is not None:
                continue
            if "values" in r.model_fields_set:
                counts[c] = len(r.values)
                paths.append(("range", c, "values"))
            elif r.count is not None:
                counts[c] = r.count
                paths.append(("range", c, "count"))
        if paths:
            self.memory(mech, paths[::-1], 1.0, counts)

    def unused_parameters(self, mech):
        """Warnings (``file:line: params.<name>: …``, :class:`assur.texts.Text` in English
        and Russian) for the parameters that nothing
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
                where = f"{file}:{int(line)}: {key_path(path)}"
                out.append(Text(f"{where}: the parameter {name!r} is not used by any group, "
                                f"frame point, load, condition or table (a misspelt name?)",
                                ru=f"{where}: параметр {name!r} не используется ни группой, ни "
                                   f"точкой стойки, ни нагрузкой, ни условием, ни таблицей "
                                   f"(опечатка в имени?)"))
        return out
