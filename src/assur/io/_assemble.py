"""Pass 3 of the file loader (:class:`assur.io._build.Builder`): the frame, the groups
in order, links, distances, loads, cylinders, machine, tables, motions and gravity are
added one at a time to a :class:`~assur.Mechanism`, each point and link name checked
against those defined before it; anything the mechanism itself refuses is reported at
the entry being added (:meth:`~assur.io._build.Builder.guarded`).
"""

from __future__ import annotations

from ..core.gravity import GRAVITY
from ..core.mechanism import Mechanism
from ..machines.stability import Machine
from ..texts import text
from . import _schema as S
from ._entries import CYLINDER_VALUES, fields, group_inputs, group_links, group_outputs, \
    group_values, load_links, load_points, load_values, unreadable
from ._links import derived_links
from ._units import ANGLE, UnitError, parse, to_si


class Assembly:
    """The mechanism pass, a part of :class:`~assur.io._build.Builder`."""

    def mechanism(self) -> Mechanism:
        """The mechanism of the file, part by part."""
        sp = self.spec
        shown = sp.display
        display = {"units": (shown.units if shown is not None else None) or "file",
                   "lang": shown.lang if shown is not None else None,
                   "plots": tuple({"y": tuple(p.y), "x": p.x}
                                  for p in ((shown.plots if shown is not None else None) or ())),
                   "given": tuple(self.literal_units)}
        mech = self.guarded(("model",), lambda: Mechanism(
            sp.model.name, coordinates=self.coords, params=self.params, units=self.units,
            title=text(sp.model.title), notes=tuple(text(n) for n in sp.model.notes),
            display=display))
        mech, known = self.add_frame(mech)
        mech = self.add_groups(mech, known)
        points = list(known)
        mech = self.add_links(mech, points)
        bodies = list(mech.bodies)
        mech = self.add_loads(mech, points, bodies)
        mech = self.add_cylinders(mech)
        if sp.machine is not None:
            mech = self.machine(mech, points)
        if sp.tables is not None:
            mech = self.tables(mech, points, bodies)
            mech = self.extra_columns(mech)
        mech = self.motions(mech)
        if self._uses_gravity:
            mech = self.add_gravity(mech)
        return mech

    def add_frame(self, mech):
        """``[frame]``: Cartesian or polar points (a polar point from one written
        before it); returns the mechanism and ``{point: where defined}``."""
        sp = self.spec
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
        return mech, known

    def add_groups(self, mech, known):
        """``[[groups]]`` in order: names once, points defined before use and once, the
        number of links the type adds; ``known`` grows with the points they add."""
        sp = self.spec
        # every point a group defines, to tell "defined later" from "unknown"
        later = {}
        for i, g in enumerate(self.groups):
            for f in group_outputs(g):
                later.setdefault(getattr(g, f), f"groups[{i}] ({g.name})")
        names = {n: "the frame" for n in sp.frame}
        for i, g in enumerate(self.groups):
            gp = ("groups", i)
            if g.name in names:
                raise self.error(gp + ("name",), f'the name "{g.name}" is already used by '
                                                 f"{names[g.name]}")
            for path, p in group_inputs(g, gp):
                self.point(path, p, known, {q: w for q, w in later.items() if q not in known})
            outs = [(gp + (f,), getattr(g, f)) for f in group_outputs(g)]
            for path, p in outs:
                if p in known:
                    raise self.error(path, f'point "{p}" is already defined by {known[p]}')
            want = group_links(g)
            if g.links and ((want is None and len(g.links) > 1) or
                            (want is not None and len(g.links) != len(want))):
                expect = ("at most one link name (the link that carries the point)"
                          if want is None else
                          f"{len(want)} link name{'s' if len(want) > 1 else ''} "
                          f"({', '.join(want)})")
                raise self.error(gp + ("links",), f"expected {expect}, found {S.show(g.links)}")
            kw = self.group_keywords(g, gp)
            mech = self.guarded(gp, lambda: mech.add_group(g.type, g.name, **kw))
            names[g.name] = f"groups[{i}]"
            for _, p in outs:
                known[p] = f"groups[{i}] ({g.name})"
        return mech

    def group_keywords(self, g, gp):
        """The builder's keywords of group entry ``g`` at ``gp``: its keys with resolved
        values, pairs and positions as tuples."""
        kw = {f: getattr(g, f) for f in g.model_fields_set - {"type", "name"}}
        for f in group_values(g):
            if (gp + (f,)) in self.resolved:
                kw[f] = self.resolved[gp + (f,)]
        for f in fields(g, "line"):
            if kw.get(f.name) is not None:
                kw[f.name] = tuple(kw[f.name])
        for f in fields(g, "position"):
            if f.name in kw:
                kw[f.name] = tuple(self.resolved[gp + (f.name, c)] for c in self.coords)
        if "links" in kw:
            kw["links"] = tuple(kw["links"])
        return kw

    def add_links(self, mech, points):
        """``[links]`` and ``[distances]``: ends among ``points``, names unique. A file
        without ``[links]`` gets the links of its named bodies
        (:func:`~assur.io._links.derived_links`), listed in ``tables["derived_links"]``
        for the reports to say so."""
        sp = self.spec
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
        if "links" not in self.data:  # no [links]: one per named body (io/_links.py)
            derived = derived_links(mech)
            for link in derived:
                mech = self.guarded(("groups",), lambda: mech.link(link.name, link.tail,
                                                                   link.head))
            if derived:
                mech = mech.with_tables(derived_links=tuple(l.name for l in derived))
        return mech

    def add_loads(self, mech, points, bodies):
        """``[[loads]]``: the points and links their types' fields name, then the load
        with its resolved values (:meth:`Mechanism.add_load`)."""

        def body(path, b):
            if b not in bodies:
                raise self.error(path, f'unknown link "{b}": expected a link of the mechanism '
                                       f'({", ".join(bodies)}), found "{b}"'
                                       f"{S.did_you_mean(b, bodies)}")

        for i, ld in enumerate(self.loads):
            lp = ("loads", i)
            for f in load_points(ld):
                self.point(lp + (f,), getattr(ld, f), points)
            for f in load_links(ld):
                value = getattr(ld, f, None)
                if isinstance(value, str):
                    body(lp + (f,), value)
                elif value is not None:
                    for k, b in enumerate(value):
                        body(lp + (f, k), b)
            kw = {f: getattr(ld, f) for f in ld.model_fields_set - {"type"}}
            for f in load_values(ld):
                if lp + (f,) in self.resolved:
                    kw[f] = self.resolved[lp + (f,)]
            mech = self.guarded(lp, lambda: mech.add_load(ld.type, **kw))
        return mech

    def add_cylinders(self, mech):
        """``[[cylinders]]``: names once, a rod-side cylinder's rod within its bore, a
        passive cylinder's distance named in ``[distances]``."""
        sp = self.spec
        seen = {}
        for i, c in enumerate(sp.cylinders):
            cp = ("cylinders", i)
            if c.name in seen:
                raise self.error(cp + ("name",), f'the cylinder name "{c.name}" is already used '
                                                 f"by cylinders[{seen[c.name]}]")
            seen[c.name] = i
            kw = {f: self.resolved[cp + (f,)] for f in CYLINDER_VALUES if cp + (f,) in
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
        return mech

    def add_gravity(self, mech):
        """``[model] gravity``: a value, ``"none"``, or a value and a direction."""
        gv, gp = self.spec.model.gravity, ("model", "gravity")
        if gv == "none":
            g, d = "none", None
        elif isinstance(gv, dict):
            g = self.number(gp + ("value",)) if "value" in gv else GRAVITY
            d = self.number(gp + ("direction",)) if "direction" in gv else None
        else:
            g, d = self.number(gp), None
        return self.guarded(gp, lambda: mech.with_gravity(g, d))

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
        for key in ("angles", "analogs", "second_order", "numbering"):
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
            raise self.error(path, unreadable(e, 'a unit (e.g. "N", "kN", "deg", "-")',
                                               unit)) from None
