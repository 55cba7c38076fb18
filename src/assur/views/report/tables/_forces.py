"""The tables of the forces: 4.1 (cylinders, capacities), G (capacity maps over two
coordinates), 5.1 and 5.2 (joint reactions) (:mod:`assur.views.report.tables`)."""

from __future__ import annotations

import numpy as np

from ....core.cylinders import reserve
from ....errors import SingularPositionError
from ....texts import LANGS, localize
from ..labels import TEXT
from ..numbers import number
from ._data import Column, Table, _both, _same, grid_of


def _capacity(v, res, point):
    """Capacity at ``point`` [N], NaN where its transmission number is zero."""
    try:
        return v.pick(res.capacity(point)), None
    except SingularPositionError as e:
        # the same formula, left empty (NaN) where I = 0
        return v.pick(res.capacity(point, singular="empty")), str(e)


def _table_4_1(v):
    a = v.a
    if not a.cylinders:
        return None
    cols = v.coord_columns()
    notes = []
    several = len(a.cylinders) > 1
    points = v.transmission_points()
    extrema = []
    for name, res in a.cylinders.items():
        c = res.cylinder.length  # its coordinate, or a passive cylinder's distance
        sfx = f"_{c}" if several else ""
        cols.append(Column(f"F_{c}", "N", v.pick(res.force), _both("c_F", name)))
        cols.append(Column(f"p_{c}", "Pa", v.pick(res.pressure), _both("c_p", name)))
        # capacity only at the points of the chain this cylinder drives (assur.core.chains);
        # none for a cylinder on a supply line (the line has one pressure)
        absent = [p for p in points if not v.moves_point(c, p)]
        for p in points if res.supply_line is None else ():
            if p in absent:
                continue
            g, err = _capacity(v, res, p)
            cols.append(Column(f"G{p}{sfx}", "N", g, _both("c_G", p)))
            if err:
                notes.append(_same(err))
            elif v.k > 1:
                extrema.append((f"G{p}{sfx}", p, g))
            for wname, P in v.weights_at(p)[:1]:
                if P > 0:  # against the payload alone: G carried the dead loads
                    cols.append(Column(f"dG{p}{sfx}", "%", reserve(g, P),
                                       {lang: TEXT["c_dG"][lang].format(
                                           p, localize(wname, lang), v.text(P, "N", lang))
                                        for lang in LANGS}))
        note = v.absent_note(c, absent, (), "absent_capacity", name)
        if note:
            notes.append(note)
    notes += _capacity_extrema(v, extrema)
    # named by what it holds: a machine that lifts nothing (a steering drive, a spout)
    # has its cylinders' forces and pressures only
    lifts = any(c.unit == "%" or c.symbol.startswith("G") for c in cols[len(v.coords):])
    return Table("4.1", _both("t4.1" if lifts else "t4.1_cylinders"), tuple(cols),
                 tuple(notes))


def _table_g(v):
    """Capacity maps over a grid of two coordinates (seed 001 lab 1: G(S, S1), eq. 14):
    one row per value of the first coordinate, one column per capacity and value of
    the second — the map the lab draws, as numbers. None unless the positions are a
    full grid of two coordinates and a cylinder has a capacity."""
    a = v.a
    if v.k != 2 or not a.cylinders:
        return None
    c1, c2 = v.coords
    grid = grid_of(v.coord_values(c1), v.coord_values(c2))
    if grid is None:
        return None
    u1, u2, i1, i2 = grid
    cols = [Column(c1, v.coord_unit(c1), u1, v.coord_label(c1))]
    for name, res in a.cylinders.items():
        c = res.cylinder.coordinate
        for p in v.transmission_points():
            if not v.moves_point(c, p):
                continue
            g, err = _capacity(v, res, p)
            if err:
                continue  # singular somewhere: 4.1 says where; no map with holes
            z = np.full((len(u1), len(u2)), np.nan)
            z[i1, i2] = g
            for k, val in enumerate(u2):
                shown, _ = v.units.convert(val, v.coord_unit(c2))
                cols.append(Column(f"G{p}_{c}@{c2}={number(float(shown), significant=6)}", "N", z[:, k],
                                   {lang: f"{TEXT['c_G'][lang].format(p)} "
                                          f"({localize(name, lang)}), "
                                          f"{c2} = {v.text(val, v.coord_unit(c2), lang)}"
                                    for lang in LANGS}))
    if len(cols) == 1:
        return None
    return Table("G", _both("tG", c1, c2), tuple(cols), (_both("g_map", c1, c2),))


def _capacity_extrema(v, extrema):
    """Notes over several coordinates (seed 001 lab 1): the minimum of each capacity
    map and its value at the farthest reach of its point (eq. 14a), and the dead
    loads the capacities carry (eq. 14)."""
    from ....core.loads import dead_load_links
    notes = []
    for sym, p, g in extrema:
        i = int(np.argmin(g))
        notes.append({lang: TEXT["g_min"][lang].format(sym, v.text(g[i], "N", lang),
                                                       v.at_text(i, lang))
                      for lang in LANGS})
        x = v.pick(v.kin.x(p))
        j = int(np.argmax(x))
        notes.append({lang: TEXT["g_reach"][lang].format(sym, p, v.text(x[j], "m", lang),
                                                         v.text(g[j], "N", lang),
                                                         v.at_text(j, lang))
                      for lang in LANGS})
    dead = dead_load_links(v.mech)
    if dead:
        notes.append(_both("g_dead", ", ".join(dead)))
    return notes


def _reaction_columns(v, st):
    """Columns R<ij>x, R<ij>y, R<ij> (and M<ij>) of every joint, and the actuator force
    from the reactions, of the statics ``st``."""
    cols = v.coord_columns()
    named = {(i, j): name for name, (i, j) in st.named_reactions().items()}
    done = set()
    order = list(named.items()) + [((i, j), f"R{i}{j}") for _, i, j in st.joints]
    for (i, j), name in order:
        if frozenset((i, j)) in done:
            continue
        done.add(frozenset((i, j)))
        r = st.reaction(i, j)
        rx, ry = v.pick(r[..., 0]), v.pick(r[..., 1])
        cols.append(Column(f"{name}x", "N", rx, _both("c_Rx", name)))
        cols.append(Column(f"{name}y", "N", ry, _both("c_Ry", name)))
        cols.append(Column(name, "N", np.hypot(rx, ry), _both("c_R", name, i, j)))
        mz = v.pick(st.reaction_moment(i, j))
        if np.any(mz != 0.0):
            cols.append(Column(f"M{name[1:] if name.startswith('R') else name}", "N·m", mz,
                               _same(f"moment {name}")))
    for c in v.coords:
        try:
            f = st.actuator_force_from_reactions(c)
        except KeyError:
            continue
        u = "N·m" if v.is_angle(c) else "N"
        cols.append(Column(f"F_{c}", u, v.pick(f), _both("c_Frx", c)))
    return cols


_REACTION_NOTE = {"en": "R_ij is the force of link i on link j at their joint; the frame is "
                        "link 0.",
                  "ru": "R_ij — сила звена i на звено j в их шарнире; стойка — звено 0."}


def _table_5_1(v):
    if not v.mech.loads:
        return None
    cols = _reaction_columns(v, v.a.statics) + _spring_columns(v)
    return Table("5.1", _both("t5.1"), tuple(cols), (_REACTION_NOTE,))


def _spring_columns(v):
    """The springs' lengths and forces (:func:`assur.core.statics.spring_states`):
    ``L_<s>`` [m], ``T_<s>`` (one spring) and ``F_<s>`` (all ``count`` springs) [N]."""
    from ....core.statics import spring_states
    cols = []
    for name, (L, T, F) in spring_states(v.kin).items():
        cols.append(Column(f"L_{name}", "m", v.pick(L), _both("c_Lspring", name)))
        cols.append(Column(f"T_{name}", "N", v.pick(T), _both("c_Tspring", name)))
        cols.append(Column(f"F_{name}", "N", v.pick(F), _both("c_Fspring", name)))
    return cols


def _table_5_2(v):
    """Joint reactions with the inertia loads at the crank's speed (the kinetostatics
    of seed 001 lab 3), when the analysis has its dynamics."""
    dyn = getattr(v.a, "dynamics", None)
    if dyn is None:
        return None
    w = float(np.mean(np.abs(v.pick(dyn.qdot))))
    note = {"en": f"with the inertia loads at the crank's speed (mean |ω| = "
                  f"{v.text(w, 'rad/s', 'en')}) and the weights",
            "ru": f"с силами инерции при скорости кривошипа (среднее |ω| = "
                  f"{v.text(w, 'rad/s', 'ru')}) и весами"}
    return Table("5.2", _both("t5.2"), tuple(_reaction_columns(v, dyn.statics)),
                 (_REACTION_NOTE, note))
