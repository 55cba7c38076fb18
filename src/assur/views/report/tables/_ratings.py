"""The ratings' tables (``[[rating]]``, :mod:`assur.machines.ratings`): one per
rating, its columns the rating's named arrays (:mod:`assur.views.report.tables`)."""

from __future__ import annotations

import numpy as np

from ....texts import LANGS, localize
from ..numbers import quantity
from ._data import Column, Table

__all__ = ["rating_tables"]


def rating_tables(analysis, units=None) -> list:
    """One :class:`~assur.views.report.tables.Table` per rating of ``analysis``
    (ids ``R1``, ``R2`` … in the file's order), columns in SI as the other tables';
    its single values (a static tipping load) written under it in ``units`` (a
    :class:`assur.core.display.DisplayUnits`; default: the model file's).

    Examples
    --------
    >>> from assur import io
    >>> from assur.views.report.tables._ratings import rating_tables
    >>> a = io.load(io.bundled("crane_lv184a")).analyze()
    >>> t = rating_tables(a)[0]
    >>> t.id, [c.symbol for c in t.columns][-3:], t.column("M").unit
    ('R1', ['G', 'governing', 'M'], 'N·m')
    """
    from ....core.display import unit_system
    du = unit_system(analysis.mechanism, units)
    out = []
    for i, r in enumerate(getattr(analysis, "ratings", None) or ()):
        cols = tuple(Column(s.symbol, s.unit, np.asarray(s.values, float),
                            {lang: localize(s.label, lang) for lang in LANGS})
                     for s in r.series)
        notes = tuple({lang: localize(n, lang) for lang in LANGS} for n in r.notes) + tuple(
            {lang: f"{localize(v.label, lang)}: "
                   f"{quantity(float(v.values[0]), v.quantity, du, lang)}"
             for lang in LANGS} for v in r.scalars)
        titles = {lang: r.rating.heading(lang) for lang in LANGS}
        out.append(Table(f"R{i + 1}", titles, cols, notes))
    return out
