"""The verdicts of a report's first page: what the analysis says about the machine.

Each :class:`Verdict` is one sentence in the report's language and, where it rests
on a number, the table, column and row that number is read from — the value exactly
as that column holds it, in the report's display units — and the HTML anchor of that
table, so the first page can link every verdict to what shows it.

The verdicts are derived from the content of the analysis and of its tables
(:func:`assur.views.report.tables.seed_tables`), never from a model's name:

``assembly``
    the mechanism assembles at every analysed position (``fail`` with the
    kinematics' failures), with the largest closure residual of table 2.2;
``capacity_<symbol>``
    the smallest lift capacity of each capacity column of table 4.1 and where
    (``info``; ``warn`` below zero, with what that means: the cylinder holds no
    downward load at the point there);
``reserve_<symbol>``
    the smallest capacity reserve of each reserve column of table 4.1 (``ok`` at
    ≥ 0 %, ``fail`` below: the capacity is below the weight);
``pressure_<cylinder>``
    the largest pressure of each cylinder (one for the cylinders of a supply line)
    against its relief pressure p_max (``fail`` above it, ``warn`` above
    :data:`PRESSURE_WARN` of it, ``ok`` otherwise);
``stability``
    the smallest share of the steered axle (table 6.1) against the machine's least
    share (``ok``/``fail``);
``gmax``
    the smallest implement-weight limit by steerability of table 6.1 (``info``);
``driving_moment``
    the largest driving moment on the crank (table D) by magnitude (``info``);
``slips``
    how many notes the model file gives on its seed — the slips it resolves and
    its assumptions (``info``; linked to the warnings section);
``warnings``
    how many warnings the model file and the analysis give (``warn`` when any).

Numbers are printed by :mod:`assur.views.report.numbers` and units by
:func:`assur.views.report.labels.unit`: Russian texts use the decimal comma and
Russian unit symbols.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ...core.display import kind_of, unit_system
from ...texts import localize
from .labels import TEXT, check_lang
from .numbers import number, quantity, value_text

__all__ = ["Verdict", "verdicts", "anchor_of", "PRESSURE_WARN", "STATUSES"]

#: a pressure above this share of the relief pressure is a warning [-]
PRESSURE_WARN = 0.9
#: the statuses of a verdict, from good to bad; ``info`` states a figure
STATUSES = ("ok", "info", "warn", "fail")
#: the anchor of the report's section of warnings and notes
WARNINGS = "warnings"

#: the sentences, by key and language ({…}: filled by :func:`verdicts`)
_TEXT = {
    "assembly_ok": {"en": "the mechanism assembles at all {n} positions analysed ({range})",
                    "ru": "механизм собирается во всех {n} рассчитанных положениях ({range})"},
    "assembly_closure": {"en": "; largest closure residual {value}",
                         "ru": "; наибольшая невязка замыкания {value}"},
    "assembly_fail": {"en": "the mechanism does not assemble at every position: {failures}",
                      "ru": "механизм собирается не во всех положениях (сообщений: {count}), "
                            "см. раздел «Предупреждения и примечания»"},
    "capacity": {"en": "smallest {label} ({symbol}): {value} at {at}",
                 "ru": "наименьшая {label} ({symbol}): {value} при {at}"},
    "capacity_negative": {
        "en": " — below zero: there the cylinder at its relief pressure holds no downward "
              "load at the point (its working stroke lowers the point at that position, "
              "or the dead loads alone exceed its force)",
        "ru": " — меньше нуля: в этом положении гидроцилиндр при давлении настройки "
              "клапана не удерживает направленную вниз нагрузку в точке (его рабочий ход "
              "здесь опускает точку либо одни постоянные нагрузки превышают его усилие)"},
    "reserve": {"en": "smallest {label} ({symbol}): {value} at {at}",
                "ru": "наименьший {label} ({symbol}): {value} при {at}"},
    "reserve_fail": {"en": " — the capacity is below the weight",
                     "ru": " — грузоподъёмность меньше веса"},
    "pressure": {"en": "largest pressure in cylinder {name} ({symbol}): {value} at {at}, "
                       "{share} of its relief pressure p_max = {p_max}",
                 "ru": "наибольшее давление в гидроцилиндре {name} ({symbol}): {value} при "
                       "{at}, {share} от давления настройки предохранительного клапана "
                       "{p_max}"},
    "pressure_line": {"en": "largest pressure of the supply line {line} (cylinders {name}; "
                            "{symbol}): {value} at {at}, {share} of its relief pressure "
                            "p_max = {p_max}",
                      "ru": "наибольшее давление в напорной линии {line} (гидроцилиндры "
                            "{name}; {symbol}): {value} при {at}, {share} от давления "
                            "настройки предохранительного клапана {p_max}"},
    "pressure_free": {"en": "largest pressure in cylinder {name} ({symbol}): {value} at {at} "
                            "(the model gives no relief pressure to compare it with)",
                      "ru": "наибольшее давление в гидроцилиндре {name} ({symbol}): {value} при "
                            "{at} (давление настройки предохранительного клапана в модели не "
                            "задано)"},
    "pressure_warn": {"en": " — within {margin} of the relief pressure",
                      "ru": " — до давления настройки меньше {margin}"},
    "pressure_fail": {"en": " — above the relief pressure",
                      "ru": " — выше давления настройки"},
    "stability": {"en": "smallest share of the load on the steered axle {axle} ({symbol}): "
                        "{value} at {at}, against the least {least} steering needs",
                  "ru": "наименьшая доля нагрузки на управляемую ось {axle} ({symbol}): "
                        "{value} при {at}; наименьшая допустимая доля {least}"},
    "stability_fail": {"en": " — the machine cannot be steered there",
                       "ru": " — машина там неуправляема"},
    "gmax": {"en": "smallest implement-weight limit by steerability ({symbol}): {value} at {at}",
             "ru": "наименьший предельный вес орудия по условию управляемости ({symbol}): "
                   "{value} при {at}"},
    "driving_moment": {"en": "largest driving moment on the crank by magnitude ({symbol}): "
                             "{value} at {at}",
                       "ru": "наибольший по модулю движущий момент на кривошипе ({symbol}): "
                             "{value} при {at}"},
    "slips": {"en": "notes of the model file on its seed (slips resolved, assumptions): {count}",
              "ru": "примечания файла модели к исходному расчёту (исправленные ошибки, "
                    "допущения): {count}"},
    "warnings": {"en": "warnings of the model file and the analysis: {count}",
                 "ru": "предупреждения файла модели и расчёта: {count}"},
    "no_warnings": {"en": "no warnings from the model file or the analysis",
                    "ru": "предупреждений файла модели и расчёта нет"},
}


@dataclass(frozen=True)
class Verdict:
    """One verdict of the report's first page.

    Attributes
    ----------
    key : str
        Stable id: ``"assembly"``, ``"capacity_<symbol>"``, ``"reserve_<symbol>"``,
        ``"pressure_<cylinder>"``, ``"stability"``, ``"gmax"``,
        ``"driving_moment"``, ``"slips"``, ``"warnings"``.
    status : str
        One of :data:`STATUSES`: ``"ok"``, ``"warn"``, ``"fail"`` or ``"info"``.
    text : str
        One sentence in the report's language, values with their display units.
    anchor : str or None
        The HTML id it links to: a table's (:func:`anchor_of`), or ``"warnings"``.
    table : str or None
        Id of the table the value is read from.
    column : str or None
        Symbol of its column.
    row : int or None
        Its row (the position's index).
    value : float or None
        The value exactly as that column holds it (display units).

    Examples
    --------
    >>> from assur import io
    >>> from assur.core.display import unit_system
    >>> from assur.views.report.tables import seed_tables
    >>> a = io.load(io.bundled("hitch_003")).analyze()
    >>> du = unit_system(a.mechanism, "file")
    >>> v = next(v for v in verdicts(a, seed_tables(a, units=du), du) if v.key == "reserve_dGS65")
    >>> v.status, v.anchor, v.table, v.column, v.row
    ('ok', 'table-4-1', '4.1', 'dGS65', 9)
    >>> print(v.text)   # seed 003 table 4.1 prints 8.9 % at S = 0.67 m
    Smallest capacity reserve at S6 against P6 = 27.5 kN (dGS65): 8.941 % at S = 0.67 m.
    """

    key: str
    status: str
    text: str
    anchor: str | None
    table: str | None = None
    column: str | None = None
    row: int | None = None
    value: float | None = None


def anchor_of(table_id) -> str:
    """The HTML id of a table in the report: ``"table-"`` and its id lowercased, every
    character that is not a letter or a digit replaced by ``-``.

    Examples
    --------
    >>> anchor_of("4.1"), anchor_of("IC"), anchor_of("D")
    ('table-4-1', 'table-ic', 'table-d')
    """
    return "table-" + "".join(ch if ch.isalnum() else "-" for ch in str(table_id)).lower()


def _sentence(text):
    """``text`` as a sentence: its first letter a capital, a full stop at its end."""
    text = text[:1].upper() + text[1:]
    return text if text.endswith(".") else text + "."


def _find(table, label_key, *args, prefix=False):
    """The columns of ``table`` whose English label is the text ``label_key`` (with
    ``args``), or starts with its text before its first field (``prefix``): found by
    what they hold, whatever the model renamed them to."""
    en = TEXT[label_key]["en"]
    if prefix:
        head = en.split("{", 1)[0]
        return [c for c in table.columns if c.label.get("en", "").startswith(head)]
    want = en.format(*args)
    return [c for c in table.columns if c.label.get("en") == want]


def _scalar(p):
    """A relief pressure [Pa] as one number (the smallest of an array over designs)."""
    a = np.ravel(np.asarray(p, dtype=float))
    return float(a[0]) if np.all(a == a[0]) else float(np.min(a))


class _Page:
    """What the verdicts are made from: the tables by id, the units, the language."""

    def __init__(self, analysis, tables, units, lang):
        self.a = analysis
        self.mech = analysis.mechanism
        self.coords = tuple(analysis.kinematics.coordinates)
        self.tables = {t.id: t for t in tables}
        self.units = units
        self.lang = lang

    def t(self, key, **fields):
        return _TEXT[key][self.lang].format(**fields)

    def value(self, column, x=None):
        """A value of ``column`` (its display unit) with the unit, for the language."""
        return value_text(column.values if x is None else x, column.unit, self.units, self.lang)

    def at(self, table, row):
        """'S = 0.67 m' (every coordinate) of position ``row``, as ``table`` shows it."""
        parts = []
        for c in self.coords:
            try:
                col = table.column(c)
            except KeyError:
                continue
            parts.append(f"{c} = {self.value(col, col.values[row])}")
        return ", ".join(parts) if parts else f"№ {row + 1}"

    def span(self):
        """'S = 0.42 … 0.67 m' of every coordinate over the analysed positions (as the
        report's summary gives the range)."""
        kin, parts = self.a.kinematics, []
        for c in self.coords:
            q = np.asarray(kin.q(c), dtype=float)
            kind = "angle" if self.mech.coordinate_kind(c) == "angle" else "length"
            lo = number(self.units.value(float(q.min()), kind), None, self.lang)
            parts.append(f"{c} = {lo} … {quantity(float(q.max()), kind, self.units, self.lang)}")
        return ", ".join(parts)

    def locate(self, col, which):
        """``(row, value)`` of the smallest (``which`` "min"), largest ("max") or
        largest by magnitude ("abs") value of ``col``, the value exactly as the column
        holds it; None when the column holds no number."""
        v = np.asarray(col.values, dtype=float)
        if not np.any(np.isfinite(v)):
            return None
        pick = np.nanargmin if which == "min" else np.nanargmax
        row = int(pick(np.abs(v) if which == "abs" else v))
        return row, float(col.values[row])

    def extreme(self, key, status, text_key, table, col, which, **fields):
        """The verdict of an extreme of ``col`` (:meth:`locate`) with the text
        ``text_key``; None when the column holds no number."""
        found = self.locate(col, which)
        if found is None:
            return None
        row, value = found
        text = self.t(text_key, symbol=col.symbol, value=self.value(col, value),
                      at=self.at(table, row), **fields)
        return Verdict(key, status, text, anchor_of(table.id), table.id, col.symbol, row, value)


def verdicts(analysis, tables, units, lang="en") -> list:
    """The verdicts of the report's first page, each linked to what shows it.

    Parameters
    ----------
    analysis : Analysis
        One design (:meth:`assur.io.Model.analyze`, :meth:`assur.Mechanism.analyze`).
    tables : list of Table
        The report's tables in the display units ``units``
        (:func:`assur.views.report.tables.seed_tables` with ``units=units``).
    units : DisplayUnits or str
        The display units (:func:`assur.core.display.unit_system`), or a system's
        name.
    lang : {"en", "ru"}
        The language of the texts.

    Returns
    -------
    list of Verdict
        In the order of the module's list, those whose data exist: no capacity
        verdict for a mechanism without capacity columns, no stability verdict
        without table 6.1. Each verdict read from a table carries its table, column,
        row and the value exactly as the column holds it (display units: MPa, kN,
        mm, % …).

    Examples
    --------
    The seed-003 hitch over the range of its model file, in the file's units (MPa,
    kN, m):

    >>> from assur import io
    >>> from assur.core.display import unit_system
    >>> from assur.views.report.tables import seed_tables
    >>> a = io.load(io.bundled("hitch_003")).analyze()
    >>> du = unit_system(a.mechanism, "file")
    >>> found = verdicts(a, seed_tables(a, units=du), du)
    >>> [(v.key, v.status) for v in found]   # doctest: +NORMALIZE_WHITESPACE
    [('assembly', 'ok'), ('capacity_G56', 'info'), ('capacity_GS6', 'info'),
     ('reserve_dGS65', 'ok'), ('pressure_ГЦ', 'warn'), ('stability', 'ok'),
     ('gmax', 'info'), ('slips', 'info'), ('warnings', 'ok')]
    >>> p = found[4]
    >>> p.anchor, p.column, round(p.value, 4)   # the largest Pgc of table 4.1 [MPa]
    ('table-4-1', 'Pgc', 16.0637)
    >>> print(p.text)   # doctest: +NORMALIZE_WHITESPACE
    Largest pressure in cylinder ГЦ (Pgc): 16.06 MPa at S = 0.67 m, 91.8 % of its relief
    pressure p_max = 17.5 MPa — within 10 % of the relief pressure.
    >>> ru = verdicts(a, seed_tables(a, units=du), du, "ru")
    >>> print(ru[4].text)   # doctest: +NORMALIZE_WHITESPACE
    Наибольшее давление в гидроцилиндре ГЦ (Pgc): 16,06 МПа при S = 0,67 м, 91,8 % от
    давления настройки предохранительного клапана 17,5 МПа — до давления настройки меньше 10 %.
    """
    check_lang(lang)
    units = unit_system(analysis.mechanism, units)
    page = _Page(analysis, tables, units, lang)
    out = [_assembly(page)]
    out += _capacities(page)
    out += _pressures(page)
    out += _stability(page)
    out += _dynamics(page)
    out += _notes(page)
    return [v for v in out if v is not None]


def _assembly(page):
    kin = page.a.kinematics
    failures = list(getattr(kin, "failures", []) or [])
    if failures:
        text = page.t("assembly_fail", failures="; ".join(map(str, failures)),
                      count=len(failures))
        return Verdict("assembly", "fail", _sentence(text), WARNINGS)
    tab = page.tables.get("2.2")
    closure = _find(tab, "c_closure") if tab is not None else []
    text = page.t("assembly_ok", n=kin.n, range=page.span())
    if not closure:
        return Verdict("assembly", "ok", _sentence(text),
                       anchor_of(tab.id) if tab is not None else None)
    col = closure[0]
    v = np.abs(np.asarray(col.values, dtype=float))
    if not np.any(np.isfinite(v)):
        return Verdict("assembly", "ok", _sentence(text), anchor_of(tab.id))
    row = int(np.nanargmax(v))
    value = float(col.values[row])
    text += page.t("assembly_closure", value=page.value(col, value))
    return Verdict("assembly", "ok", _sentence(text), anchor_of(tab.id), tab.id, col.symbol,
                   row, value)


def _capacities(page):
    tab = page.tables.get("4.1")
    if tab is None:
        return []
    out = []
    for col in _find(tab, "c_G", prefix=True):
        if kind_of(col.unit) != "force":
            continue
        v = page.extreme(f"capacity_{col.symbol}", "info", "capacity", tab, col, "min",
                         label=col.label.get(page.lang, ""))
        if v is not None and v.value < 0:
            v = _flagged(v, "warn", page.t("capacity_negative"))
        out.append(v)
    for col in _find(tab, "c_dG", prefix=True):
        if col.unit != "%":
            continue
        v = page.extreme(f"reserve_{col.symbol}", "ok", "reserve", tab, col, "min",
                         label=col.label.get(page.lang, ""))
        if v is None:
            continue
        if v.value < 0:
            v = _flagged(v, "fail", page.t("reserve_fail"))
        out.append(v)
    return [_done(v) for v in out if v is not None]


def _done(v):
    """``v`` with its text made a sentence."""
    return replace(v, text=_sentence(v.text))


def _flagged(v, status, why):
    """``v`` with the status ``status`` and ``why`` added to its text."""
    return replace(v, status=status, text=v.text + why)


def _pressure_column(page, tab, name, res):
    """The column of table 4.1 with the pressure of cylinder ``name``: the symbol
    ``p_<coordinate>`` as the model renames it (``tables.symbols``), checked by its
    label; else the column labelled as its pressure."""
    rename = dict(page.mech.tables.get("symbols", {}) or {})
    length = getattr(res.cylinder, "length", None) or res.cylinder.coordinate
    want = TEXT["c_p"]["en"].format(name)
    sym = rename.get(f"p_{length}", f"p_{length}")
    try:
        col = tab.column(sym)
    except KeyError:
        col = None
    if col is None or col.label.get("en") != want:
        found = _find(tab, "c_p", name)
        col = found[0] if found else None
    if col is None or kind_of(col.unit) != "pressure":
        return None
    return col


def _pressures(page):
    tab = page.tables.get("4.1")
    if tab is None or not page.a.cylinders:
        return []
    # the cylinders of a supply line share its pressure: one verdict per line
    lines = {}
    for name, res in page.a.cylinders.items():
        line = getattr(res, "supply_line", None)
        lines.setdefault(line if line is not None else ("", name), []).append((name, res))
    out = []
    for line, members in lines.items():
        if isinstance(line, str):  # the driving cylinder's column first (it has a coordinate)
            members = sorted(members, key=lambda m: m[1].cylinder.coordinate is None)
        name, res = members[0]
        col = _pressure_column(page, tab, name, res)
        if col is None:
            continue
        found = page.locate(col, "max")
        if found is None:
            continue
        row, value = found
        p_max = min(_scalar(r.p_max) for _, r in members)   # the lowest setting
        if not p_max > 0.0:  # no relief setting in the model: the figure, no verdict
            text = page.t("pressure_free",
                          name=", ".join(localize(n, page.lang) for n, _ in members),
                          symbol=col.symbol, value=page.value(col, value),
                          at=page.at(tab, row))
            out.append(Verdict(f"pressure_{str(name)}", "info", _sentence(text),
                               anchor_of(tab.id), tab.id, col.symbol, row, value))
            continue
        shown_max = float(page.units.convert(p_max, "Pa")[0])
        ratio = value / shown_max if shown_max > 0 else float("inf")
        text = page.t("pressure_line" if isinstance(line, str) else "pressure",
                      line=localize(line, page.lang) if isinstance(line, str) else "",
                      name=", ".join(localize(n, page.lang) for n, _ in members),
                      symbol=col.symbol,
                      value=page.value(col, value), at=page.at(tab, row),
                      share=f"{number(100.0 * ratio, None, page.lang, 3)} %",
                      p_max=value_text(p_max, "Pa", page.units, page.lang))
        if ratio > 1.0:
            status, text = "fail", text + page.t("pressure_fail")
        elif ratio > PRESSURE_WARN:
            margin = f"{number(100.0 * (1.0 - PRESSURE_WARN), None, page.lang, 3)} %"
            status, text = "warn", text + page.t("pressure_warn", margin=margin)
        else:
            status = "ok"
        out.append(Verdict(f"pressure_{str(name)}", status, _sentence(text), anchor_of(tab.id),
                           tab.id, col.symbol, row, value))
    return out


def _machine(page):
    carry = getattr(page.mech, "machine", None)
    return getattr(carry, "machine", None) if carry is not None else None


def _stability(page):
    tab = page.tables.get("6.1")
    if tab is None:
        return []
    out = []
    mc = _machine(page)
    if mc is not None and getattr(mc, "steered", None) is not None:
        shares = [c for c in _find(tab, "c_dRaxle", mc.steered) if c.unit == "%"]
        if shares:
            col = shares[0]
            least = 100.0 * float(mc.min_share)
            v = page.extreme("stability", "ok", "stability", tab, col, "min",
                             axle=localize(mc.steered, page.lang),
                             least=value_text(least, "%", page.units, page.lang))
            if v is not None:
                if v.value < least:
                    v = _flagged(v, "fail", page.t("stability_fail"))
                out.append(_done(v))
    for col in _find(tab, "c_Gmax", prefix=True)[:1]:
        if kind_of(col.unit) != "force":
            continue
        v = page.extreme("gmax", "info", "gmax", tab, col, "min")
        if v is not None:
            out.append(_done(v))
    return out


def _dynamics(page):
    tab = page.tables.get("D")
    if tab is None:
        return []
    out = []
    for col in _find(tab, "c_Md")[:1]:
        v = page.extreme("driving_moment", "info", "driving_moment", tab, col, "abs")
        if v is not None:
            out.append(_done(v))
    return out


def _notes(page):
    out = []
    notes = [localize(n, page.lang) for n in (page.mech.notes or ())]
    if notes:
        out.append(Verdict("slips", "info", _sentence(page.t("slips", count=len(notes))),
                           WARNINGS))
    # the model file's problems (an unused parameter …); the analysis' own notes (the
    # motion its inertia loads are taken at) inform, and stand in the warnings section
    warnings = list(page.a.model_warnings or ())
    if warnings:
        out.append(Verdict("warnings", "warn",
                           _sentence(page.t("warnings", count=len(warnings))), WARNINGS))
    else:
        out.append(Verdict("warnings", "ok", _sentence(page.t("no_warnings")), WARNINGS))
    return out
