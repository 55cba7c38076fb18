"""The tables' data: :class:`Column`, :class:`Table`, the full grid of two
coordinates and the labels of both languages (:mod:`assur.views.report.tables`)."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from ....texts import LANGS, Text, localize
from ..labels import TEXT, check_lang

__all__ = ["Column", "Table", "grid_of", "wrap_degrees", "in_units"]


def _both(key, *args):
    """{lang: text} for a label key (a model's name given in several languages, a
    :class:`assur.texts.Text`, in each language's)."""
    return {lang: (txt.format(*(localize(a, lang) if isinstance(a, Text) else a
                                for a in args)) if args else txt)
            for lang, txt in TEXT[key].items()}


def _same(text):
    """{lang: text} of a model's own text (a :class:`assur.texts.Text` carries its
    translations; a plain string is the same in every language)."""
    return {lang: localize(text, lang) for lang in LANGS}


def wrap_degrees(a):
    """Angles [°] wrapped to [0°, 360°) (the seeds' printing), any shape."""
    w = np.mod(np.asarray(a, dtype=float), 360.0)
    return np.where(w >= 360.0, w - 360.0, w)  # np.mod(-1e-17, 360) rounds to 360


@dataclass(frozen=True)
class Column:
    """One column of a table.

    Attributes
    ----------
    symbol : str
        Seed-like symbol (module notes), e.g. ``"phi3"``, ``"I56"``.
    unit : str
        SI unit symbol: ``m``, ``deg``, ``-``, ``N``, ``Pa``, ``%``, ``rad/m``…
    values : ndarray, shape (n,)
        One value per position (NaN where undefined).
    label : dict of str to str
        Description by language (``"en"``, ``"ru"``).
    printed_sign : int
        +1, or −1 where the model's source prints these values with the opposite
        sign (its sign map, ``tables["signs"]``).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report import seed_tables
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> phi3 = seed_tables(a)[0].column("phi3")  # table 2.1
    >>> phi3.unit, phi3.label["en"], len(phi3.values)
    ('deg', 'angle of link 3', 10)
    >>> round(float(phi3.values[0]), 1)  # φ3 at S = 0.420 m [deg], seed 003 table 2.1: -40.2
    -40.2
    >>> r05x = seed_tables(a)[4].column("R05x")  # table 5.1: the seed prints R05 negated
    >>> r05x.printed_sign, phi3.printed_sign
    (-1, 1)
    """

    symbol: str
    unit: str
    values: np.ndarray
    label: dict = field(default_factory=dict)
    printed_sign: int = 1

    @property
    def header(self) -> str:
        """``symbol [unit]``, the CSV and XLSX header.

        Examples
        --------
        >>> import numpy as np
        >>> Column("phi3", "deg", np.zeros(3)).header
        'phi3 [deg]'
        >>> Column("U43", "-", np.zeros(3)).header  # a ratio: no unit
        'U43 [-]'
        """
        return f"{self.symbol} [{self.unit}]"


@dataclass(frozen=True)
class Table:
    """A seed-like table: id, titles and columns over the positions.

    Attributes
    ----------
    id : str
        Seed numbering: ``"2.1"``, ``"2.2"``, ``"3.1"``, ``"4.1"``, ``"5.1"``,
        ``"6.1"``, ``"IC"`` (instantaneous-centre check), ``"F"`` (the model's
        extra formulas that name no table).
    titles : dict of str to str
        Title by language.
    columns : tuple of Column
        The first column(s) are the generalized coordinate(s).
    notes : tuple of dict
        Notes by language (singular positions, seed signs, flagged formulas).
    number : str
        The number the report shows (``"3"``; the seed-003 hitch: ``"4.1"``, its
        worksheet's), given by :func:`seed_tables` from ``[tables] numbering``;
        empty: the id. :attr:`label` is the one shown.
    contents : str
        What the table holds, in its file's name (:func:`table_filename`:
        ``table_6_crane_chart.csv``); empty: :data:`TABLE_CONTENTS` by its id.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report import seed_tables
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> t = seed_tables(a)[3]
    >>> t.id, len(t), t.symbols  # 10 positions of S
    ('4.1', 10, ['S', 'Fgc', 'Pgc', 'G56', 'GS6', 'dGS65'])
    >>> round(float(t["dGS65"][-1]), 1)  # reserve at S = 0.670 m [%], seed 003 table 4.1: 8.9
    8.9
    """

    id: str
    titles: dict
    columns: tuple
    notes: tuple = ()
    number: str = ""
    contents: str = ""

    @property
    def label(self) -> str:
        """The number the report shows (:attr:`number`, else the :attr:`id`).

        Examples
        --------
        >>> from assur import io
        >>> from assur.views.report import seed_tables
        >>> tabs = seed_tables(io.load(io.bundled("loader_lab1")).analyze())
        >>> [(t.id, t.label) for t in tabs][:4]  # numbered in the report's order
        [('2.1', '1'), ('2.2', '2'), ('3.1', '3'), ('4.1', '4')]
        """
        return self.number or self.id

    def title(self, lang="en") -> str:
        """The title in ``lang`` ("en" or "ru").

        Examples
        --------
        >>> from assur import examples
        >>> from assur.views.report import seed_tables
        >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
        >>> seed_tables(a)[0].title("en")
        'Geometric analysis: link angles'
        >>> seed_tables(a)[0].title("de")
        Traceback (most recent call last):
        ...
        ValueError: lang must be one of: ['en', 'ru']; got 'de'
        """
        return self.titles[check_lang(lang)]

    @property
    def title_en(self) -> str:
        """The English title.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.views.report import seed_tables
        >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
        >>> seed_tables(a)[6].title_en
        'Check of the kinematics through the instantaneous centre'
        """
        return self.titles["en"]

    @property
    def title_ru(self) -> str:
        """The Russian title.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.views.report import seed_tables
        >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
        >>> seed_tables(a)[0].title_ru
        'Результаты геометрического анализа (углы наклона звеньев)'
        """
        return self.titles["ru"]

    @property
    def symbols(self) -> list:
        """The columns' symbols, in order.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.views.report import seed_tables
        >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
        >>> seed_tables(a)[0].symbols  # table 2.1: S [m], then link angles [deg]
        ['S', 'phi2', 'phi3', 'phi34', 'phi4', 'phi5', 'phi6', 'phi7']
        """
        return [c.symbol for c in self.columns]

    def column(self, symbol) -> Column:
        """The column of ``symbol``; KeyError naming the table's columns if none.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.views.report import seed_tables
        >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
        >>> t = seed_tables(a)[3]  # table 4.1
        >>> c = t.column("Pgc")
        >>> c.unit, round(float(c.values[0]) / 1e6, 2)  # [MPa] at S = 0.420 m, seed: 15.35
        ('Pa', 15.35)
        >>> t.column("p")
        Traceback (most recent call last):
        ...
        KeyError: "table 4.1 has no column 'p'; columns: ['S', 'Fgc', 'Pgc', 'G56', 'GS6', 'dGS65']"
        """
        for c in self.columns:
            if c.symbol == symbol:
                return c
        raise KeyError(f"table {self.id} has no column {symbol!r}; columns: {self.symbols}")

    def __getitem__(self, symbol) -> np.ndarray:
        return self.column(symbol).values

    def __len__(self):
        return len(self.columns[0].values) if self.columns else 0

    def to_frame(self):
        """pandas DataFrame with the ``symbol [unit]`` headers.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.views.report import seed_tables
        >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
        >>> df = seed_tables(a)[3].to_frame()  # table 4.1
        >>> df.shape, list(df.columns[:3])
        ((10, 6), ['S [m]', 'Fgc [N]', 'Pgc [Pa]'])
        >>> round(float(df["Fgc [N]"].iloc[-1]))  # at S = 0.670 m [N], seed 003 table 4.1: 135652
        135652
        """
        import pandas as pd
        return pd.DataFrame({c.header: c.values for c in self.columns})


def grid_of(q1, q2):
    """The full grid behind positions ``(q1, q2)``, shape (n,) each: ``(u1, u2, i1, i2)``
    with the sorted distinct values of each coordinate and every position's indices
    into them — or None when the positions are not a full grid (paired paths).

    Examples
    --------
    >>> u1, u2, i1, i2 = grid_of([0.4, 0.5, 0.4, 0.5], [1.0, 1.0, 2.0, 2.0])  # S1, S2 [m]
    >>> u1.tolist(), u2.tolist(), i1.tolist(), i2.tolist()
    ([0.4, 0.5], [1.0, 2.0], [0, 1, 0, 1], [0, 0, 1, 1])
    >>> grid_of([0.4, 0.5, 0.6], [1.0, 1.5, 2.0]) is None  # a path: both move together
    True
    """
    q1, q2 = np.asarray(q1, dtype=float), np.asarray(q2, dtype=float)
    u1, u2 = np.unique(q1), np.unique(q2)
    if len(u1) < 2 or len(u2) < 2 or len(u1) * len(u2) != q1.size:
        return None
    i1, i2 = np.searchsorted(u1, q1), np.searchsorted(u2, q2)
    if np.unique(i2 * len(u1) + i1).size != q1.size:
        return None
    return u1, u2, i1, i2


def in_units(table, units):
    """``table`` with every column shown in ``units`` (a
    :class:`assur.core.display.DisplayUnits`): values converted from the column's unit
    to the display unit of its kind, the unit renamed; a column of no known kind (a
    count, a ratio) stays as it is.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.display import unit_system
    >>> from assur.views.report import seed_tables
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> t = in_units(seed_tables(a)[3], unit_system(None, "engineering"))   # table 4.1
    >>> [c.unit for c in t.columns]
    ['mm', 'kN', 'MPa', 'kN', 'kN', '%']
    >>> round(float(t["Fgc"][0]), 3)  # seed 003 table 4.1: 129614 N [kN]
    129.614
    """
    cols = []
    for c in table.columns:
        values, text = units.convert(c.values, c.unit)
        cols.append(c if text == c.unit else
                    dataclasses.replace(c, values=np.asarray(values), unit=text))
    return dataclasses.replace(table, columns=tuple(cols))
