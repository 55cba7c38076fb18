"""The worksheet's tables of an analysis, in order, with the model's extra formulas,
sign maps and unique column names (:mod:`assur.views.report.tables`)."""

from __future__ import annotations

import dataclasses

from ..labels import TEXT, check_lang
from ._data import Column, Table, _both, _same, in_units
from ._forces import _table_4_1, _table_5_1, _table_5_2, _table_g
from ._kinematics import _table_2_1, _table_2_2, _table_3_1, _table_ic
from ._machines import _table_6_1, _table_d, _table_l, _table_v
from ._ratings import rating_tables
from ._view import _View

__all__ = ["seed_tables", "numbered", "NUMBERINGS"]

#: id of the table of extra formulas that name no table
FORMULAS_ID = "F"


_BUILDERS = (_table_2_1, _table_2_2, _table_3_1, _table_4_1, _table_g, _table_5_1, _table_5_2,
             _table_d, _table_v, _table_6_1, _table_ic, _table_l)


def seed_tables(analysis, lang="en", design=None, angles=None, analogs=None,
                units=None) -> list:
    """The worksheet's tables of an analysis, as data.

    Parameters
    ----------
    analysis : Analysis
        Result of :meth:`assur.Mechanism.analyze`.
    lang : {"en", "ru"}
        Checked only; every table carries both languages (``Table.title(lang)``).
    design : int, optional
        Which design of a batch to tabulate (required for a batch).
    angles : {"continuous", "wrapped"}, optional
        Angle columns (link angles, crank angles) continuous along the positions, or
        wrapped to [0°, 360°) as the seeds print them (default: the model's
        ``tables["angles"]``, else continuous).
    analogs : {"coordinate", "rotation"}, optional
        Analogs with respect to a crank angle as they are (d/dφ1), or along the
        crank's direction of rotation (d/dφ1 · sign φ1', the seeds' convention:
        seed 002 writes φ1' = −1 for its clockwise crank); default: the model's
        ``tables["analogs"]``, else per coordinate.
    units : str or DisplayUnits, optional
        Show every column in these display units (a system of
        :data:`assur.core.display.SYSTEMS` or a
        :class:`assur.core.display.DisplayUnits`). Default: the columns in SI (angles
        in degrees, capacity reserves in %), the data the seeds' tests compare; the
        notes are written in the model file's display units either way.

    Returns
    -------
    list of Table
        In the seed's order: 2.1, 2.2, 3.1, 4.1, 5.1, 6.1, IC — those whose data
        exist.

    Examples
    --------
    >>> from assur import examples
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> [t.id for t in seed_tables(a)]
    ['2.1', '2.2', '3.1', '4.1', '5.1', '6.1', 'IC']
    >>> round(float(seed_tables(a)[2]["IS6"][0]), 3)
    4.713
    """
    check_lang(lang)
    v = _View(analysis, design, angles=angles, analogs=analogs, units=units)
    tables = [t for t in (b(v) for b in _BUILDERS) if t is not None]
    tables += rating_tables(analysis, v.units)  # [[rating]]: tables/_ratings.py
    tables = _with_formulas(v, tables)
    # the model may name columns as its seed does (``tables.symbols``: F_S → Fgc …)
    rename = dict(analysis.mechanism.tables.get("symbols", {}))
    if rename:
        tables = [dataclasses.replace(t, columns=tuple(
            dataclasses.replace(c, symbol=rename.get(c.symbol, c.symbol)) for c in t.columns))
            for t in tables]
    tables = _unique(v, _with_signs(v, tables))
    if units is not None:
        tables = [in_units(t, v.units) for t in tables]
    return numbered(tables, analysis.mechanism.tables.get("numbering", "report"))


#: how tables may be numbered (``[tables] numbering``)
NUMBERINGS = ("report", "seed")


def numbered(tables, numbering="report") -> list:
    """``tables`` with the numbers the report shows (:attr:`Table.label`): 1, 2, … in
    their order (``"report"``), or the seed-003 worksheet's ids 2.1 … 6.1 (``"seed"``,
    the bundled hitch's ``[tables] numbering``).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report.tables import numbered, seed_tables
    >>> tabs = seed_tables(examples.hitch_003().analyze(examples.hitch_003_range()))
    >>> [t.label for t in tabs]  # hitch_003.toml: numbering = "seed"
    ['2.1', '2.2', '3.1', '4.1', '5.1', '6.1', 'IC']
    >>> [t.label for t in numbered(tabs)]
    ['1', '2', '3', '4', '5', '6', '7']
    >>> numbered(tabs, "page")
    Traceback (most recent call last):
    ...
    ValueError: numbering must be one of: ['report', 'seed']; got 'page'
    """
    if numbering not in NUMBERINGS:
        raise ValueError(f"numbering must be one of: {list(NUMBERINGS)}; got {numbering!r}")
    return [dataclasses.replace(t, number=t.id if numbering == "seed" else str(k))
            for k, t in enumerate(tables, start=1)]


def _unique(v, tables):
    """Column names unique within each table: a column that takes a coordinate's name
    (a crank coordinate ``phi1`` beside the angle of link 1) gets a suffix — ``_link``
    for a link angle, ``_point`` for a point's coordinate, ``_2`` otherwise — and the
    table says so."""
    coords = set(v.coords)
    out = []
    for t in tables:
        k = 0  # the leading coordinate columns keep their names
        while (k < len(t.columns) and t.columns[k].symbol in coords
               and t.columns[k].symbol not in {c.symbol for c in t.columns[:k]}):
            k += 1
        seen, cols, notes = set(), [], list(t.notes)
        for i, c in enumerate(t.columns):
            sym = c.symbol
            if i >= k and (sym in coords or sym in seen):
                suffix = ("_link" if sym.startswith("phi") else
                          "_point" if sym[:1] in "XY" else "_2")
                new = sym + suffix
                while new in seen:
                    new += "_2"
                notes.append(_both("renamed", sym, new))
                c = dataclasses.replace(c, symbol=new)
            seen.add(c.symbol)
            cols.append(c)
        out.append(dataclasses.replace(t, columns=tuple(cols), notes=tuple(notes))
                   if notes != list(t.notes) else t)
    return out


def _with_formulas(v, tables):
    """Append the model's extra formulas (:class:`assur.core.columns.Formula`) to the tables
    they name — or to a table "F" of their own when they name none or that table is
    not made (e.g. 6.1 without machine data) — with their flags as notes."""
    from ....core.columns import formulas_of
    formulas = formulas_of(v.mech)
    if not formulas:
        return tables
    by_id = {t.id: t for t in tables}
    extra = {}
    for f in formulas:
        col = Column(f.name, f.unit, v.pick(f.evaluate(v.kin)) / f.scale,
                     _same(f.label) if f.label else _both("c_formula", f.name, f.expr))
        tid = f.table if f.table in by_id else FORMULAS_ID
        extra.setdefault(tid, ([], []))
        extra[tid][0].append(col)
        extra[tid][1].extend(_same(x) for x in f.flags)
    out = []
    for t in tables:
        if t.id in extra:
            cols, notes = extra.pop(t.id)
            t = dataclasses.replace(t, columns=t.columns + tuple(cols),
                                    notes=t.notes + tuple(notes))
        out.append(t)
    if FORMULAS_ID in extra:
        cols, notes = extra.pop(FORMULAS_ID)
        out.append(Table(FORMULAS_ID, _both("tF"), tuple(v.coord_columns()) + tuple(cols),
                         tuple(notes)))
    return out


def _with_signs(v, tables):
    """Mark the columns of the model's sign maps (:class:`assur.core.columns.SignMap`) with
    their printed sign and add each map's note to the tables that have its columns."""
    from ....core.columns import signs_of
    maps = signs_of(v.mech)
    if not maps:
        return tables
    out = []
    for t in tables:
        cols, notes = list(t.columns), list(t.notes)
        for m in maps:
            hit = [c.symbol for c in cols if c.symbol in m.columns]
            if not hit:
                continue
            cols = [dataclasses.replace(c, printed_sign=m.sign) if c.symbol in m.columns else c
                    for c in cols]
            if m.sign < 0:
                notes.append({lang: f"{', '.join(hit)}: {TEXT['printed_sign'][lang]}."
                              for lang in TEXT["printed_sign"]})
            if m.note:
                notes.append(_same(m.note))
        out.append(dataclasses.replace(t, columns=tuple(cols), notes=tuple(notes)))
    return out
