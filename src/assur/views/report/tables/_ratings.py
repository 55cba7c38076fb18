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
    >>> t.id, t.contents, [c.symbol for c in t.columns][-3:], t.column("M").unit
    ('R1', 'crane_chart', ['G', 'governing', 'M'], 'N·m')
    """
    from ....core.display import unit_system
    du = unit_system(analysis.mechanism, units)
    out = []
    from ....machines.ratings import names_of
    ratings = list(getattr(analysis, "ratings", None) or ())
    for i, (r, name) in enumerate(zip(ratings, names_of(ratings))):
        cols = tuple(Column(s.symbol, s.unit, _values(s),
                            {lang: localize(s.label, lang) for lang in LANGS})
                     for s in r.series)
        notes = tuple({lang: localize(n, lang) for lang in LANGS} for n in r.notes) + tuple(
            {lang: f"{localize(v.label, lang)}: "
                   f"{quantity(float(v.values[0]), v.quantity, du, lang)}"
             for lang in LANGS} for v in r.scalars)
        titles = {lang: r.rating.heading(lang) for lang in LANGS}
        out.append(Table(f"R{i + 1}", titles, cols, notes, contents=name))
    return out


def _values(series):
    """A series' values for its column: an index or a count (a number, every value
    whole: the governing limit's key) as integers, printed without decimals; any
    other as floats [SI]."""
    v = np.asarray(series.values, float)
    if series.quantity == "number" and v.size and np.all(np.isfinite(v)) \
            and np.all(v == np.round(v)):
        return v.astype(np.int64)
    return v
