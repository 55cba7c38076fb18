"""The seed worksheets' tables as data, and their CSV and XLSX files.

:func:`seed_tables` turns an :class:`~assur.analysis.Analysis` into the tables a
seed worksheet prints (seed 003: 2.1, 2.2, 3.1, 4.1, 5.1, 6.1 and the check
through the instantaneous centre). Only tables whose data exist are made: a
mechanism without cylinders has no 4.1, without loads no 5.1, without machine
data no 6.1.

Column symbols
--------------
One scheme for every mechanism; for seed 003 it gives the seed's own symbols
except where noted. ``<c>`` is a generalized coordinate, ``<p>`` a point, ``<l>``
a link, ``<i><j>`` a pair of links:

==================  ========  ====================================================
symbol              unit      meaning
==================  ========  ====================================================
``<c>``             m or deg  the generalized coordinate (seed ``S``); crank angles
                              are printed in degrees
``phi<l>``          deg       angle of link l from +x, CCW (seed ``φ3(S)/deg``)
``X<p>``, ``Y<p>``  m         point coordinates (seed ``X23(S)``)
``<d>``             m         a named distance (seed 002 ``l7``, ``l9``); its
                              angle, when named, is a link (``phi7``)
``d<d>``            m/rad, \\-  its analog
``closure``         m         largest closure residual of all groups (assur's
                              check; replaces the seed's ``X23s``… columns)
``U<i><j>``         \\-        transfer ratio φ_i'/φ_j' (seed ``U43``)
``I<p>``            \\-        transmission number dY/dq of point p (seed ``I56``)
``dphi<l>``         rad/m     angular-velocity analog dφ_l/dq (seed ``dφ3``; its
                              ``φ41…φ71`` are ``dphi4…dphi7``)
``F_<c>``           N         cylinder force by virtual work (seed ``Fgc``); in
                              table 5.1 the same force from the reactions
``p_<c>``           Pa        cylinder pressure (seed ``Pgc``)
``G<p>``            N         lift capacity at point p (seed ``G56``, ``GS6``)
``dG<p>``           %         capacity reserve against the weight at p (seed
                              ``ΔGS65``)
``R<ij>x/y``, R…    N         reaction: force of link i on link j and its
                              magnitude; the seed's name when the model gives
                              one (``tables["reactions"]``)
``M<ij>``            N·m       moment of i on j at a driven crank's pivot or a
                              prismatic pair (only where not zero)
``R<axle>``         N         axle reaction (seed ``Ra``, ``Rb``)
``dR<axle>``        %         axle share of the total weight (seed ``ΔRa``)
``G_max``           N         largest implement weight under the 20 % rule
``<name>``          its unit  an extra formula of the model (``tables["formulas"]``,
                              e.g. seed 003's printed ``GS6max``, flagged), in the
                              table it names
``Xp``, ``Yp``      m         instantaneous centre of the checked link
``I<p>_ic``         \\-        φ'·(X<p> − Xp): I<p> through the instantaneous
                              centre (seed ``Imp``, ``lsp``)
==================  ========  ====================================================

Conventions (``tables["angles"]``, ``tables["analogs"]`` of the model, or the
arguments of :func:`seed_tables`): angle columns are continuous along the positions
(default) or wrapped to [0°, 360°) as the seeds print them; analogs with respect to
a crank angle are per the coordinate (default) or along the crank's direction of
rotation, d/dφ1 · sign φ1' (its :class:`assur.core.motion.Motion`; the seeds turn
clockwise and write φ1' = −1). Each table notes the convention in force.

With k > 1 coordinates every analog symbol gets the suffix ``_<c>`` (``dphi3_S1``);
with several cylinders ``G<p>`` and ``dG<p>`` get it too. A quantity along a
coordinate that does not move its point or turn its link (:mod:`assur.core.chains`) has
no column; the table's note says so. Over a full grid of two coordinates table
``G`` holds each capacity of 4.1 as its map: a row per value of the first
coordinate, a column ``G<p>_<c>@<c2>=<value>`` per value of the second. Analogs with respect to
a crank angle are in rad/rad (unit ``-``) and transmission numbers in m/rad.

Sign convention of reactions: ``R<ij>`` is the force of link i on link j (the
frame is link 0). Where the model's sign map says its source prints a column with
the opposite sign (``tables["signs"]``, :class:`assur.core.columns.SignMap`; seed 003
R05, R34, R45) the column carries ``printed_sign = -1`` and the table the model's
note; the numbers are assur's.

Files: :func:`write_csv` writes a header ``symbol [unit]`` per column and every
number with ``repr`` (a float read back is the same float); :func:`write_xlsx`
one sheet per table with the same header and the same numbers as floats
(an empty cell where a value is NaN or infinite, which Excel cannot hold).
"""

from __future__ import annotations

import csv
import dataclasses
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ...core.columns import TABLE_IDS
from ...errors import SingularPositionError
from ...core.loads import Weight
from ...texts import LANGS, localize
from .labels import TEXT, check_lang, unit

__all__ = ["Column", "Table", "seed_tables", "write_csv", "write_xlsx", "table_filename",
           "TABLE_IDS", "grid_of"]

#: id of the table of extra formulas that name no table
FORMULAS_ID = "F"


def _both(key, *args):
    """{lang: text} for a label key."""
    return {lang: (txt.format(*args) if args else txt) for lang, txt in TEXT[key].items()}


def _same(text):
    """{lang: text} of a model's own text (a :class:`assur.texts.Text` carries its
    translations; a plain string is the same in every language)."""
    return {lang: localize(text, lang) for lang in LANGS}




#: how angle columns are shown (``tables["angles"]``)
ANGLE_CONVENTIONS = ("continuous", "wrapped")
#: how analogs with respect to a crank angle are shown (``tables["analogs"]``)
ANALOG_CONVENTIONS = ("coordinate", "rotation")


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



# ---- reading the analysis ---------------------------------------------------------------
class _View:
    """One design of an Analysis as 1-D arrays over the positions."""

    def __init__(self, analysis, design=None, angles=None, analogs=None):
        self.a = analysis
        self.kin = analysis.kinematics
        self.mech = analysis.mechanism
        tabs = self.mech.tables
        #: angle columns: "continuous" (along the positions) or "wrapped" to [0°, 360°)
        self.angles = angles or tabs.get("angles", "continuous")
        #: analogs of a crank angle: per its "coordinate", or along its "rotation"
        self.analogs = analogs or tabs.get("analogs", "coordinate")
        if self.angles not in ANGLE_CONVENTIONS:
            raise ValueError(f"angles must be one of: {list(ANGLE_CONVENTIONS)}; got "
                             f"{self.angles!r}")
        if self.analogs not in ANALOG_CONVENTIONS:
            raise ValueError(f"analogs must be one of: {list(ANALOG_CONVENTIONS)}; got "
                             f"{self.analogs!r}")
        shape = self.kin.shape
        if len(shape) == 2:
            if design is None:
                raise ValueError(f"this analysis holds a batch of {shape[0]} designs: choose one "
                                 f"with design=<index>")
            if not -shape[0] <= design < shape[0]:
                raise ValueError(f"design must be in 0…{shape[0] - 1}, got {design}")
        elif design not in (None, 0):
            raise ValueError(f"this analysis holds one design; design must be None or 0, "
                             f"got {design}")
        self.design = design
        self.n = shape[-1]
        self.k = self.kin.k
        self.coords = self.kin.coordinates

    def pick(self, a):
        """Array over positions, shape (n,), of this design (NaN where masked)."""
        if np.ma.isMaskedArray(a):
            a = np.ma.filled(a.astype(float), np.nan)
        a = np.asarray(a)
        if a.ndim >= 2:
            a = a[self.design]
        if a.ndim == 1 and a.shape[0] not in (1, self.n):
            a = a[self.design]  # an array over designs, shape (m,)
        return np.array(np.broadcast_to(a.reshape(-1) if a.ndim else a, (self.n,)))

    def scalar(self, a):
        """A parameter value (scalar or per design) of this design."""
        a = np.asarray(a, dtype=float)
        if a.ndim and a.size > 1:
            return float(a.reshape(-1)[self.design])
        return float(a.reshape(-1)[0]) if a.ndim else float(a)

    # coordinates ---------------------------------------------------------------------
    def coord_kind(self, c):
        kind = self.mech.coordinate_kind(c)
        if kind != "length":
            return kind
        for cyl in self.mech.cylinders:
            if cyl.coordinate == c:
                return "cylinder"
        return "length"

    def is_angle(self, c):
        return self.coord_kind(c) == "angle"

    def coord_unit(self, c):
        return "deg" if self.is_angle(c) else "m"

    def degrees(self, a):
        """Angles [°] in the view's convention (continuous, or wrapped to [0°, 360°))."""
        return wrap_degrees(a) if self.angles == "wrapped" else np.asarray(a)

    def coord_values(self, c):
        v = self.pick(self.kin.q(c))
        return self.degrees(np.degrees(v)) if self.is_angle(c) else v

    def phi_values(self, link):
        """φ of a link [°] over the positions, in the view's convention."""
        return self.degrees(self.pick(self.kin.phi(link, degrees=True)))

    def rate_sign(self, c):
        """+1, or the sign of the crank's rotation (−1: clockwise) when analogs are shown
        along the direction of rotation (``analogs = "rotation"``) and ``c`` is a crank
        angle with a :class:`assur.core.motion.Motion`."""
        if self.analogs != "rotation" or not self.is_angle(c):
            return 1
        mo = self.mech.motion(c)
        return mo.direction if mo is not None else 1

    def convention_notes(self, analogs=False):
        """Notes of the conventions in force (wrapped angles; analogs along a rotation)."""
        notes = []
        if self.angles == "wrapped":
            notes.append(_both("wrapped"))
        if analogs:
            for c in self.coords:
                if self.analogs == "rotation" and self.is_angle(c):
                    mo = self.mech.motion(c)
                    d = mo.direction if mo is not None else 1
                    notes.append({lang: TEXT["rotation"][lang].format(
                        c, TEXT["cw" if d < 0 else "ccw"][lang], d) for lang in LANGS})
        return notes

    def coord_label(self, c):
        key = {"angle": "c_crank", "slider": "c_slider", "cylinder": "c_cyl_len"}.get(
            self.coord_kind(c), "c_coord")
        return {lang: f"{txt} {c}" for lang, txt in TEXT[key].items()}

    def analog_unit(self, c):
        return "-" if self.is_angle(c) else "rad/m"

    def transmission_unit(self, c):
        return "m/rad" if self.is_angle(c) else "-"

    def wrts(self):
        """[(symbol suffix, wrt argument, coordinate)]"""
        if self.k == 1:
            return [("", None, self.coords[0])]
        return [(f"_{c}", c, c) for c in self.coords]

    def coord_columns(self):
        return [Column(c, self.coord_unit(c), self.coord_values(c), self.coord_label(c))
                for c in self.coords]

    def positions_text(self, bad):
        """'S = 0.42, 0.45' for the positions where ``bad``."""
        idx = np.flatnonzero(bad)
        parts = []
        for i in idx[:6]:
            parts.append(", ".join(f"{c} = {self.coord_values(c)[i]:.6g}" for c in self.coords))
        return "; ".join(parts) + ("; …" if len(idx) > 6 else "")

    # loads ---------------------------------------------------------------------------
    def weights_at(self, point):
        """[(name, P [N])] of the weights acting at ``point``."""
        out = []
        for ld in self.mech.loads:
            if isinstance(ld, Weight) and ld.point == point:
                name = ld.name or (ld.P if isinstance(ld.P, str) else "P")
                out.append((name, self.scalar(self.mech.value_of(ld.P))))
        return out

    # chains: which coordinate moves what (:mod:`assur.core.chains`) ---------------------
    def moves_point(self, c, point):
        """True if coordinate ``c`` moves ``point``."""
        from ...core.chains import point_coordinates
        return c in point_coordinates(self.mech, point)

    def moves_link(self, c, link):
        """True if coordinate ``c`` turns ``link``."""
        from ...core.chains import link_coordinates
        return c in link_coordinates(self.mech, link)

    def absent_note(self, c, points=(), links=(), what="absent_analogs", *args):
        """The note for quantities along ``c`` left out because ``c`` does not move
        ``points`` or turn ``links``; None when nothing is left out."""
        if not points and not links:
            return None
        out = {}
        for lang in LANGS:
            parts = []
            if points:
                parts.append(f"{TEXT['absent_points'][lang]} {', '.join(points)}")
            if links:
                parts.append(f"{TEXT['absent_links'][lang]} {', '.join(links)}")
            out[lang] = TEXT["absent"][lang].format(c, "; ".join(parts),
                                                    TEXT[what][lang].format(*args))
        return out

    def at_text(self, i, lang="en"):
        """'S = 1.2 m, S1 = 0.8 m' of position ``i`` (units spelt for ``lang``)."""
        return ", ".join(f"{c} = {self.coord_values(c)[i]:.6g} {unit(self.coord_unit(c), lang)}"
                         for c in self.coords)

    def transmission_points(self):
        pts = list(self.mech.tables.get("transmissions", ()))
        if not pts:
            pts = [ld.point for ld in self.mech.loads if isinstance(ld, Weight)]
        return list(dict.fromkeys(pts))


def _singular_note(view, what, values):
    bad = ~np.isfinite(values)
    if not bad.any():
        return None
    return {lang: TEXT["singular"][lang].format(what, int(bad.sum()), view.positions_text(bad))
            for lang in TEXT["singular"]}


# ---- the tables -----------------------------------------------------------------------
def _table_2_1(v):
    cols = v.coord_columns()
    for link in v.kin.links:
        cols.append(Column(f"phi{link}", "deg", v.phi_values(link), _both("c_phi", link)))
    for dist in v.mech.distances:  # named distances (their angles are links above)
        cols.append(Column(dist.name, "m", v.pick(v.kin.length(dist.name)),
                           _both("c_dist", dist.name, dist.a, dist.b)))
    notes = v.convention_notes()
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
    cols += _second_order_columns(v)
    for c in v.coords:
        note = v.absent_note(c, *still[c])
        if note:
            notes.append(note)
    notes += v.convention_notes(analogs=True)
    return Table("3.1", _both("t3.1"), tuple(cols), tuple(notes))


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


def _capacity(v, res, point):
    """Capacity at ``point`` [N], NaN where its transmission number is zero."""
    try:
        return v.pick(res.capacity(point)), None
    except SingularPositionError as e:
        # the same formula as CylinderResult.capacity, left empty where I = 0
        kin = v.kin
        I = v.pick(kin.transmission(point, wrt=res.cylinder.coordinate if kin.k > 1 else None))
        num = v.pick(res.force_max * res.eta_mech)
        zero = I == 0.0
        g = np.where(zero, np.nan, num / np.where(zero, 1.0, I))  # NaN = empty cell
        return g, str(e)


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
                if P > 0:
                    cols.append(Column(f"dG{p}{sfx}", "%", (g - P) / P * 100.0,
                                       _both("c_dG", p, wname, P)))
        note = v.absent_note(c, absent, (), "absent_capacity", name)
        if note:
            notes.append(note)
    notes += _capacity_extrema(v, extrema)
    return Table("4.1", _both("t4.1"), tuple(cols), tuple(notes))


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
                cols.append(Column(f"G{p}_{c}@{c2}={val:.6g}", "N", z[:, k],
                                   {lang: f"{TEXT['c_G'][lang].format(p)} ({name}), "
                                          f"{c2} = {val:.6g} {unit(v.coord_unit(c2), lang)}"
                                    for lang in LANGS}))
    if len(cols) == 1:
        return None
    return Table("G", _both("tG", c1, c2), tuple(cols), (_both("g_map", c1, c2),))


def _capacity_extrema(v, extrema):
    """Notes over several coordinates (seed 001 lab 1): the minimum of each capacity
    map and its value at the farthest reach of its point (eq. 14a), and the dead
    loads the capacities carry (eq. 14)."""
    from ...core.loads import dead_load_links
    notes = []
    for sym, p, g in extrema:
        i = int(np.argmin(g))
        notes.append({lang: TEXT["g_min"][lang].format(sym, g[i] / 1e3, v.at_text(i, lang))
                      for lang in LANGS})
        x = v.pick(v.kin.x(p))
        j = int(np.argmax(x))
        notes.append({lang: TEXT["g_reach"][lang].format(sym, p, x[j], g[j] / 1e3,
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
    from ...core.statics import spring_states
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
    note = {"en": f"with the inertia loads at the crank's speed (mean |ω| = {w:.6g} rad/s) "
                  f"and the weights", "ru": f"с силами инерции при скорости кривошипа "
                                            f"(среднее |ω| = {w:.6g} рад/с) и весами"}
    return Table("5.2", _both("t5.2"), tuple(_reaction_columns(v, dyn.statics)),
                 (_REACTION_NOTE, note))


def _table_d(v):
    """The crank dynamics over the positions: rates, reduced moment of inertia, reduced
    moments, driving moment, kinetic energy, common centre of mass (and the motion
    with the flywheel)."""
    dyn = getattr(v.a, "dynamics", None)
    if dyn is None:
        return None
    c = dyn.coordinate
    cols = v.coord_columns()
    cols += [Column("omega", "rad/s", v.pick(dyn.qdot), _both("c_omega", c)),
             Column("eps", "rad/s²", v.pick(dyn.qddot), _both("c_eps", c)),
             Column("J_red", "kg·m²", v.pick(dyn.reduced_inertia), _both("c_Jred")),
             Column("dJ_red", "kg·m²/rad", v.pick(dyn.reduced_inertia_derivative),
                    _both("c_dJred")),
             Column("M_red", "N·m", v.pick(dyn.reduced_moment), _both("c_Mred")),
             Column("M_red_loads", "N·m", v.pick(dyn.reduced_moment_without_inertia),
                    _both("c_Mred_loads")),
             Column("M_red_inertia", "N·m", v.pick(dyn.reduced_moment_of_inertia_loads),
                    _both("c_Mred_inertia")),
             Column("M_d", "N·m", v.pick(dyn.driving_moment), _both("c_Md")),
             Column("T", "J", v.pick(dyn.kinetic_energy), _both("c_T")),
             Column("Xc", "m", v.pick(dyn.centre.x), _both("c_Xc")),
             Column("Yc", "m", v.pick(dyn.centre.y), _both("c_Yc"))]
    fw = getattr(v.a, "flywheel", None)
    if fw is not None and np.shape(fw.omega) == (v.n,):
        cols.append(Column("omega_fw", "rad/s", v.pick(fw.omega), _both("c_omega_fw")))
    notes = [{"en": "M_red: reduced moment on the crank of all loads (inertia included) by "
                    "virtual work; M_d = −M_red, the moment the drive applies",
              "ru": "M_red — приведённый к кривошипу момент всех сил (с силами инерции) по "
                    "принципу возможных перемещений; M_d = −M_red — момент привода"}]
    return Table("D", _both("tD"), tuple(cols), tuple(notes))


def _table_6_1(v):
    st = v.a.stability
    if st is None:
        return None
    cols = v.coord_columns()
    names = list(st.reactions)
    lower = [n.lower() for n in names]
    labels = lower if len(set(lower)) == len(lower) else names  # as StabilityResult.to_frame
    for n, lab in zip(names, labels):
        cols.append(Column(f"R{lab}", "N", v.pick(st.reactions[n]), _both("c_Raxle", n)))
    for n, lab in zip(names, labels):
        cols.append(Column(f"dR{lab}", "%", v.pick(st.shares[n]), _both("c_dRaxle", n)))
    cols.append(Column("G_max", "N", v.pick(st.max_implement_weight),
                       _both("c_Gmax", 100.0 * st.min_share)))
    cols.append(Column("G_max_no_cw", "N", v.pick(st.max_implement_weight_without_counterweights),
                       _both("c_Gmax_no_cw")))
    cols.append(Column("steerable", "-", v.pick(st.steerable).astype(int), _both("c_steerable")))
    notes = []
    if v.k > 1:  # over several coordinates: the limits' minima (seed 001 lab 1 eqs. 16, 18)
        g = v.mech.g
        for sym, vals in (("G_max", st.max_implement_weight),
                          ("G_max_no_cw", st.max_implement_weight_without_counterweights)):
            vals = v.pick(vals)
            i = int(np.argmin(vals))
            if np.isfinite(vals[i]):
                notes.append({lang: TEXT["gmax_min"][lang].format(
                    sym, vals[i] / 1e3, vals[i] / g, g, v.at_text(i, lang)) for lang in LANGS})
    return Table("6.1", _both("t6.1"), tuple(cols), tuple(notes))


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


def _table_l(v):
    """The standard lift test (ISO 789-2 / SAE J283): its own rows, the test positions
    evenly spaced over the lift range of the hitch points."""
    lt = getattr(v.a, "lift_test", None)
    if lt is None:
        return None
    h, f = lt.test.hitch, lt.test.frame
    cols = [Column(lt.coordinate, "m", lt.s, v.coord_label(lt.coordinate)),
            Column(f"Y{h}", "m", lt.height, _both("c_y", h)),
            Column(f"G{h}_test", "N", lt.hitch_force, _both("c_Gtest", h))]
    if f is not None:
        cols.append(Column(f"G{f}_test", "N", lt.frame_force, _both("c_Gtest_frame", f)))
    notes = [_both("lift_test_note", 100 * lt.test.pressure_share, lt.pressure / 1e6,
                   lt.force_cylinder / 1e3, len(lt.s)),
             _both("lift_test_min", h, lt.hitch_minimum / 1e3)]
    if f is not None:
        notes.append(_both("lift_test_min_frame", f, lt.frame_minimum / 1e3))
    return Table("L", _both("tL"), tuple(cols), tuple(notes))


_BUILDERS = (_table_2_1, _table_2_2, _table_3_1, _table_4_1, _table_g, _table_5_1, _table_5_2,
             _table_d, _table_6_1, _table_ic, _table_l)


def seed_tables(analysis, lang="en", design=None, angles=None, analogs=None) -> list:
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
    v = _View(analysis, design, angles=angles, analogs=analogs)
    tables = [t for t in (b(v) for b in _BUILDERS) if t is not None]
    tables = _with_formulas(v, tables)
    # the model may name columns as its seed does (``tables.symbols``: F_S → Fgc …)
    rename = dict(analysis.mechanism.tables.get("symbols", {}))
    if rename:
        tables = [dataclasses.replace(t, columns=tuple(
            dataclasses.replace(c, symbol=rename.get(c.symbol, c.symbol)) for c in t.columns))
            for t in tables]
    return _unique(v, _with_signs(v, tables))


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
    from ...core.columns import formulas_of
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
    from ...core.columns import signs_of
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


# ---- files -------------------------------------------------------------------------
def table_filename(table, ext="csv") -> str:
    """``table_2_1.csv``, ``table_ic.csv``.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report import seed_tables
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> [table_filename(t) for t in seed_tables(a)][::3]
    ['table_2_1.csv', 'table_4_1.csv', 'table_ic.csv']
    >>> table_filename(seed_tables(a)[0], "xlsx")
    'table_2_1.xlsx'
    """
    return f"table_{table.id.replace('.', '_').lower()}.{ext}"


def _cell(v):
    if isinstance(v, (bool, np.bool_)):
        return str(int(v))
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    return repr(float(v) + 0.0)  # + 0.0: never "-0.0"


def write_csv(table, path) -> Path:
    """Write one table as CSV: header ``symbol [unit]``, numbers with ``repr`` (exact).

    NaN (undefined, e.g. a singular ratio) is written ``nan``, infinity ``inf``.

    Examples
    --------
    >>> import csv, tempfile
    >>> from pathlib import Path
    >>> from assur import examples
    >>> from assur.views.report import seed_tables
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> t = seed_tables(a)[3]  # table 4.1
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = write_csv(t, Path(d) / "table_4_1.csv")
    ...     with open(p, encoding="utf-8") as f:
    ...         rows = list(csv.reader(f))
    >>> rows[0]
    ['S [m]', 'Fgc [N]', 'Pgc [Pa]', 'G56 [N]', 'GS6 [N]', 'dGS65 [%]']
    >>> len(rows), float(rows[1][0]), round(float(rows[1][1]))  # S [m], Fgc [N]; seed: 129614
    (11, 0.42, 129614)
    >>> float(rows[-1][5]) == float(t["dGS65"][-1])  # exact: written with repr [%]
    True
    """
    path = Path(path)
    with open(path, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow([c.header for c in table.columns])
        for row in zip(*(c.values for c in table.columns)):
            w.writerow([_cell(x) for x in row])
    return path


def _sheet_name(table):
    return table.id[:31]


def write_xlsx(tables, path) -> Path:
    """Write the tables into one workbook, one sheet per table (named by its id).

    Row 1 holds the ``symbol [unit]`` headers, the rows below the numbers as floats
    (integers for flags); NaN and infinite values, which Excel cannot store, are
    left as empty cells.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> from openpyxl import load_workbook
    >>> from assur import examples
    >>> from assur.views.report import seed_tables
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> tables = seed_tables(a)
    >>> with tempfile.TemporaryDirectory() as d:
    ...     wb = load_workbook(write_xlsx(tables, Path(d) / "tables.xlsx"))
    ...     ws = wb["4.1"]
    ...     head, s, fgc = ws["A1"].value, ws["A2"].value, ws["B2"].value
    ...     wb.close()
    >>> wb.sheetnames
    ['2.1', '2.2', '3.1', '4.1', '5.1', '6.1', 'IC']
    >>> head, s, round(fgc)  # S [m], Fgc [N]; seed 003 table 4.1: 129614
    ('S [m]', 0.42, 129614)
    """
    from openpyxl import Workbook
    from openpyxl.utils import get_column_letter

    wb = Workbook()
    wb.remove(wb.active)
    for tab in tables:
        ws = wb.create_sheet(_sheet_name(tab))
        ws.append([c.header for c in tab.columns])
        for row in zip(*(c.values for c in tab.columns)):
            out = []
            for x in row:
                if isinstance(x, (bool, np.bool_, int, np.integer)):
                    out.append(int(x))
                else:
                    x = float(x)
                    out.append(x + 0.0 if math.isfinite(x) else None)  # no -0.0
            ws.append(out)
        ws.freeze_panes = "B2"
        for j, c in enumerate(tab.columns, start=1):
            ws.column_dimensions[get_column_letter(j)].width = max(10, len(c.header) + 2)
    path = Path(path)
    with _exact_floats():
        wb.save(path)
    return path


class _exact_floats:
    """While saving, write floats with ``repr`` (the shortest text that reads back as
    the same double) instead of openpyxl's ``"%.16g"``, which rounds some doubles
    (e.g. 0.47555555555555556 becomes 0.4755555555555556, one ulp off). Patches
    the cell writer's formatter for the duration of the ``with`` block only."""

    def __enter__(self):
        try:
            from openpyxl.cell import _writer
        except ImportError:  # pragma: no cover - a future openpyxl layout
            self._mod = None
            return self
        self._mod, self._orig = _writer, getattr(_writer, "safe_string", None)
        if self._orig is None:  # pragma: no cover
            self._mod = None
            return self
        orig = self._orig

        def safe_string(value):
            if isinstance(value, float) and math.isfinite(value):
                return repr(value)
            return orig(value)

        _writer.safe_string = safe_string
        return self

    def __exit__(self, *exc):
        if self._mod is not None:
            self._mod.safe_string = self._orig
        return False
