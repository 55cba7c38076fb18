"""The tables of the kinematics: 2.1 (angles), 2.2 (coordinates), 3.1 (analogs) and
the check through the instantaneous centre (:mod:`assur.views.report.tables`)."""

from __future__ import annotations

import numpy as np

from ._data import Column, Table, _both, grid_of
from ._view import _singular_note


def _derived(v):
    """{link: (tail, head)} of the tabulated links a model file without ``[links]``
    got from its groups (:func:`assur.io._links.derived_links`)."""
    names = set(v.mech.tables.get("derived_links", ())) & set(v.kin.links)
    return {l.name: (l.tail, l.head) for l in v.mech.links if l.name in names}


def _table_2_1(v):
    cols = v.coord_columns()
    derived = _derived(v)
    for link in v.kin.links:
        label = (_both("c_phi_dir", link, *derived[link]) if link in derived
                 else _both("c_phi", link))
        cols.append(Column(f"phi{link}", "deg", v.phi_values(link), label))
    for dist in v.mech.distances:  # named distances (their angles are links above)
        cols.append(Column(dist.name, "m", v.pick(v.kin.length(dist.name)),
                           _both("c_dist", dist.name, dist.a, dist.b)))
    notes = v.convention_notes()
    if derived:
        notes.append(_both("derived_links"))
    if v.k > 1 and (v.k > 2 or grid_of(*(v.coord_values(c) for c in v.coords)) is None):
        notes.append(_both("paired"))  # not a full grid: the coordinates move together
    return Table("2.1", _both("t2.1"), tuple(cols), tuple(notes))


def _table_2_2(v):
    cols = v.coord_columns()
    for p in v.kin.points:
        cols.append(Column(f"X{p}", "m", v.pick(v.kin.x(p)), _both("c_x", p)))
        cols.append(Column(f"Y{p}", "m", v.pick(v.kin.y(p)), _both("c_y", p)))
    cols.append(Column("closure", "m", v.pick(v.kin.closure_residual()), _both("c_closure")))
    return Table("2.2", _both("t2.2"), tuple(cols))


def _table_3_1(v):
    kin = v.kin
    cols = v.coord_columns()
    notes = []
    tab = v.mech.tables
    # quantities along a coordinate that does not move a point or turn a link are
    # undefined (0 or 0/0): left out, with one note per coordinate (assur.core.chains)
    still = {c: ([p for p in tab.get("transmissions", ()) if not v.moves_point(c, p)],
                 [l for l in kin.links if not v.moves_link(c, l)]) for c in v.coords}
    for sfx, w, c in v.wrts():
        for i, j in tab.get("ratios", ()):
            if not (v.moves_link(c, i) and v.moves_link(c, j)):
                continue
            vals = v.pick(kin.ratio(i, j, w, singular="mask"))
            cols.append(Column(f"U{i}{j}{sfx}", "-", vals, _both("c_U", i, j)))
            note = _singular_note(v, f"U{i}{j}{sfx}", vals)
            if note:
                notes.append(note)
    for sfx, w, c in v.wrts():
        sign = v.rate_sign(c)
        for p in tab.get("transmissions", ()):
            if p in still[c][0]:
                continue
            cols.append(Column(f"I{p}{sfx}", v.transmission_unit(c),
                               sign * v.pick(kin.transmission(p, wrt=w)), _both("c_I", p, c)))
    for sfx, w, c in v.wrts():
        sign = v.rate_sign(c)
        for link in kin.links:
            if link in still[c][1]:
                continue
            cols.append(Column(f"dphi{link}{sfx}", v.analog_unit(c),
                               sign * v.pick(kin.dphi(link, w)), _both("c_dphi", link, c)))
        for dist in v.mech.distances:
            cols.append(Column(f"d{dist.name}{sfx}", "m/rad" if v.is_angle(c) else "-",
                               sign * v.pick(kin.dlength(dist.name, w)),
                               _both("c_ddist", dist.name, c)))
    cols += _path_columns(v)
    cols += _second_order_columns(v)
    for c in v.coords:
        note = v.absent_note(c, *still[c])
        if note:
            notes.append(note)
    if _derived(v):
        notes.append(_both("derived_links"))
    notes += v.convention_notes(analogs=True)
    return Table("3.1", _both("t3.1"), tuple(cols), tuple(notes))


def _path_columns(v):
    """Along a held path (:mod:`assur.core.held`): the transmission numbers
    ``I<point>_path`` = dY/ds and the analogs ``dphi<link>_path`` = dφ/ds with the held
    coordinates following (the implicit-function rule), beside the partial ones."""
    path = v.kin.path
    if path is None:
        return []
    s = path.along
    held = "; ".join(f"{h.coordinate}: {h.quantity} = {h.shown(h.target)}" for h in path.holds)
    sign = v.rate_sign(s)
    cols = []
    for p in v.mech.tables.get("transmissions", ()):
        cols.append(Column(f"I{p}_path", v.transmission_unit(s),
                           sign * v.pick(path.transmission(v.kin, p)),
                           _both("c_I_path", p, s, held)))
    for link in v.kin.links:
        cols.append(Column(f"dphi{link}_path", v.analog_unit(s),
                           sign * v.pick(path.derivative(v.kin, f"phi{link}")[1]),
                           _both("c_dphi_path", link, s, held)))
    return cols


def _second_order_columns(v):
    """Second-order analogs, when the model asks (``[tables] second_order = true``):
    ``ddphi<l>`` = d²φ_l/dq² of every link, ``dd<d>`` of every named distance and
    ``dU<i><j>`` = dU_ij/dq of every tabulated ratio (with k > 1 coordinates, the
    diagonal ∂²/∂q_c² with the suffix ``_<c>``)."""
    if not v.mech.tables.get("second_order"):
        return []
    kin, cols = v.kin, []
    for sfx, w, c in v.wrts():
        # along the rotation the sign squares away: d²φ/ds² = d²φ/dφ1²
        for link in kin.links:
            cols.append(Column(f"ddphi{link}{sfx}", "-" if v.is_angle(c) else "rad/m²",
                               v.pick(kin.ddphi(link, w)), _both("c_ddphi", link, c)))
        for dist in v.mech.distances:
            cols.append(Column(f"dd{dist.name}{sfx}", "m/rad²" if v.is_angle(c) else "1/m",
                               v.pick(kin.ddlength(dist.name, w)),
                               _both("c_dddist", dist.name, c)))
        sign = v.rate_sign(c)
        for i, j in v.mech.tables.get("ratios", ()):
            vals = v.pick(kin.dratio(i, j, w, singular="mask"))
            cols.append(Column(f"dU{i}{j}{sfx}", "-" if v.is_angle(c) else "1/m",
                               sign * vals, _both("c_dU", i, j, c)))
    return cols


def _checked_body(v):
    """The last rigid moving link carrying a transmission point, with its points."""
    pts = set(v.mech.tables.get("transmissions", ()))
    found = None
    for name, body in v.mech.bodies.items():
        if name == "0" or body["variable"] or len(body["points"]) < 2:
            continue
        if pts & set(body["points"]):
            found = (name, body["points"])
    return found


def _table_ic(v):
    """Instantaneous-centre check (seed 003, last table) for the last rigid link with a
    transmission point: its centre P = A + (−A'_y, A'_x)/φ' from the velocity analog
    of a point A of the link, then I<p> = φ'·(X<p> − Xp) for its transmission points
    (a point turning about P rises at φ'·(X − Xp))."""
    if v.k != 1:
        return None
    found = _checked_body(v)
    if found is None:
        return None
    body, points = found
    kin = v.kin
    A, B = points[0], points[1]
    link = next((l.name for l in v.mech.links
                 if {l.tail, l.head} <= set(points) and l.name in kin.links), None)
    # the centre is the kinematics' (Kinematics.instant_centre); where the link is at
    # rest it has none: an empty cell (NaN), said so in a note
    if link is not None:
        w = v.pick(kin.dphi(link))
        P = kin.instant_centre(link, singular="mask")
    else:
        w = v.pick(kin.direction_rate(A, B))
        P = kin.instant_centre(points=(A, B), singular="mask")
    xp, yp = (v.pick(np.ma.filled(np.ma.asarray(c_, float), np.nan)) for c_ in P)
    c = v.coords[0]
    cols = v.coord_columns()
    cols.append(Column("Xp", "m", xp, _both("c_Xp", body)))
    cols.append(Column("Yp", "m", yp, _both("c_Yp", body)))
    cols.append(Column(f"dphi{body}", v.analog_unit(c), w, _both("c_dphi", body, c)))
    tps = [p for p in v.mech.tables.get("transmissions", ()) if p in points]
    for p in tps:
        cols.append(Column(f"I{p}", v.transmission_unit(c), v.pick(kin.transmission(p)),
                           _both("c_I", p, c)))
    for p in tps:
        cols.append(Column(f"I{p}_ic", v.transmission_unit(c), w * (v.pick(kin.x(p)) - xp),
                           _both("c_Iic", p, body, c)))
    notes = []
    note = _singular_note(v, "Xp", xp)
    if note:
        notes.append(note)
    return Table("IC", _both("tIC"), tuple(cols), tuple(notes))
