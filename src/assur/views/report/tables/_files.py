"""The tables' files: CSV (exact ``repr`` numbers) and XLSX (one sheet per table)
(:mod:`assur.views.report.tables`)."""

from __future__ import annotations

import csv
import functools
import math
import re
from pathlib import Path

import numpy as np

from ..labels import check_lang, t, unit

__all__ = ["TABLE_CONTENTS", "table_filename", "write_csv", "write_frame_csv", "write_xlsx",
           "sheet_name", "number_format"]


#: what each table holds, in a file name (by the table's id)
TABLE_CONTENTS = {"2.1": "link_angles", "2.2": "points", "3.1": "analogs", "4.1": "cylinders",
            "G": "capacity_maps", "5.1": "reactions", "5.2": "reactions_with_inertia",
            "D": "crank_dynamics", "V": "velocities", "6.1": "axle_loads", "IC": "ic_check", "L": "lift_test",
            "F": "formulas"}


def table_filename(table, ext="csv") -> str:
    """The file of a table: its number as the report shows it (:attr:`Table.label`) and
    what it holds (its :attr:`~Table.contents`, else :data:`TABLE_CONTENTS` by its id) —
    ``table_4_cylinders.csv``, ``table_6_crane_chart.csv``; a table numbered as
    its seed's worksheet (``[tables] numbering = "seed"``) by that number alone,
    ``table_2_1.csv``, ``table_ic.csv``.

    Examples
    --------
    >>> from assur import examples, io
    >>> from assur.views.report import seed_tables
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> [table_filename(t) for t in seed_tables(a)][::3]
    ['table_2_1.csv', 'table_4_1.csv', 'table_ic.csv']
    >>> table_filename(seed_tables(a)[0], "xlsx")
    'table_2_1.xlsx'
    >>> tabs = seed_tables(io.load(io.bundled("steering_lab4")).analyze())
    >>> [table_filename(t) for t in tabs][:4]
    ['table_1_link_angles.csv', 'table_2_points.csv', 'table_3_analogs.csv', 'table_4_cylinders.csv']
    """
    if not table.number or table.number == table.id:
        return f"table_{table.id.replace('.', '_').lower()}.{ext}"
    what = table.contents or TABLE_CONTENTS.get(table.id, re.sub(r"\W+", "_", table.id.lower()))
    return f"table_{table.number.replace('.', '_')}_{what}.{ext}"


def _cell(v, lang="en"):
    if isinstance(v, (bool, np.bool_)):
        return str(int(v))
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if math.isnan(v):  # undefined (a singular ratio): an empty cell, as the workbook's
        return ""
    text = repr(float(v) + 0.0)  # + 0.0: never "-0.0"
    return text.replace(".", ",") if lang == "ru" else text


#: the CSV dialect of each language: separator, decimal mark, encoding (a Russian
#: Excel reads ``;`` and the decimal comma as a table, and UTF-8 only after a BOM)
CSV_DIALECTS = {"en": (",", ".", "utf-8"), "ru": (";", ",", "utf-8-sig")}


def write_frame_csv(frame, path, lang="en") -> Path:
    """Write a pandas DataFrame (a simulation's time series, a list of verdicts) as CSV
    in ``lang``'s dialect (:data:`CSV_DIALECTS`, as :func:`write_csv`): in Russian
    ``;``, the decimal comma and a byte-order mark.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> import pandas as pd
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = write_frame_csv(pd.DataFrame({"t [s]": [0.5]}), Path(d) / "t.csv", "ru")
    ...     text = p.read_text(encoding="utf-8-sig")
    >>> text.splitlines()
    ['t [s]', '0,5']
    """
    sep, mark, encoding = CSV_DIALECTS[check_lang(lang)]
    path = Path(path)
    frame.to_csv(path, index=False, sep=sep, decimal=mark, encoding=encoding)
    return path


def write_csv(table, path, lang="en") -> Path:
    """Write one table as CSV: a header ``symbol [unit]`` per column and every number
    exact (``repr``: a float read back is the same float).

    In English the separator is ``,`` and the decimal point ``.`` (UTF-8); in Russian
    (``lang="ru"``) the separator is ``;``, the decimal mark a comma and the units
    Russian, in UTF-8 with a byte-order mark, so that a Russian Excel opens the file
    as a table (:data:`CSV_DIALECTS`). An undefined value (NaN, e.g. a singular
    ratio) is an empty cell, as in the workbook and the report.

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
    ...     p = write_csv(t, Path(d) / "table_4_1_ru.csv", lang="ru")
    ...     with open(p, encoding="utf-8-sig") as f:
    ...         ru = list(csv.reader(f, delimiter=";"))
    >>> rows[0]
    ['S [m]', 'Fgc [N]', 'Pgc [Pa]', 'G56 [N]', 'GS6 [N]', 'dGS65 [%]']
    >>> len(rows), float(rows[1][0]), round(float(rows[1][1]))  # S [m], Fgc [N]; seed: 129614
    (11, 0.42, 129614)
    >>> float(rows[-1][5]) == float(t["dGS65"][-1])  # exact: written with repr [%]
    True
    >>> ru[0][:3], ru[1][0]
    (['S [м]', 'Fgc [Н]', 'Pgc [Па]'], '0,42')
    """
    sep, _, encoding = CSV_DIALECTS[lang]
    path = Path(path)
    with open(path, "w", newline="", encoding=encoding) as f:
        w = csv.writer(f, delimiter=sep)
        w.writerow([f"{c.symbol} [{unit(c.unit, lang)}]" for c in table.columns])
        for row in zip(*(c.values for c in table.columns)):
            w.writerow([_cell(x, lang) for x in row])
    return path


#: characters Excel refuses in a sheet name
_SHEET_BAD = set('[]:*?/\\')


def sheet_name(table, lang="en", taken=()) -> str:
    """The sheet of ``table``: its number and the words of its title that Excel's 31
    characters hold (without the characters Excel refuses), unique among ``taken``.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.views.report import seed_tables
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> [sheet_name(t) for t in seed_tables(a)][:2]
    ['2.1 Geometric analysis link', '2.2 Geometric analysis point']
    >>> sheet_name(seed_tables(a)[3], "ru")
    '4.1 Результаты анализа на'
    """
    text = "".join(ch for ch in f"{table.label} {table.title(lang)}" if ch not in _SHEET_BAD)
    name = " ".join(text.split())
    if len(name) > 31:  # whole words (the number at least)
        cut = name[:32].rfind(" ")
        name = name[:cut] if cut > len(table.label) else name[:31]
    k = 2
    base = name
    used = {n.casefold() for n in taken}  # Excel's sheet names ignore case
    while name.casefold() in used:
        tag = f" ({k})"
        name = base[:31 - len(tag)].rstrip() + tag
        k += 1
    return name


def number_format(values) -> str:
    """Excel's display format of a column: the decimals every view shows it with
    (:func:`assur.views.report.numbers.decimals`: integers as such, else fixed
    decimals that show four significant digits of the column's largest magnitude;
    e-notation for a column of tiny values); the cells keep every digit.

    Examples
    --------
    >>> import numpy as np
    >>> number_format(np.array([0.42, 0.67])), number_format(np.array([129614.2, 3.1]))
    ('0.0000', '0')
    >>> number_format(np.array([1, 0])), number_format(np.array([np.nan, 15.348]))
    ('0', '0.00')
    >>> number_format(np.array([1e-16, 3e-16]))   # closure residuals [m]
    '0.0E+00'
    """
    from ..numbers import decimals

    d = decimals(values)
    if d is None:
        return "0.0E+00"
    return "0." + "0" * d if d else "0"


def write_xlsx(tables, path, lang="en", inputs=None) -> Path:
    """Write the tables into one workbook: a sheet per table, named by its id and
    title (:func:`sheet_name`), and first, given ``inputs``, a sheet of the inputs.

    A table's sheet: row 1 the table's title, row 2 the symbols (bold), row 3 their
    units (in ``lang``: м, кН in Russian), then a row per position — numbers stored as numbers (every digit; integers
    for flags) with a display format per column (:func:`number_format`), NaN and
    infinite values (which Excel cannot store) as empty cells — and below them the
    table's notes. The three header rows and the first column stay in view (frozen).

    Parameters
    ----------
    tables : sequence of Table
    path : str or Path
        The ``.xlsx`` file to write.
    lang : {"en", "ru"}
        Language of the titles and notes.
    inputs : sequence of (str, sequence of tuple), optional
        Sections of the inputs sheet: a heading and its rows (e.g. a parameter's name,
        value and unit as given in the model file).

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> from openpyxl import load_workbook
    >>> from assur import examples
    >>> from assur.views.report import seed_tables
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> tables = seed_tables(a)
    >>> inputs = [("Parameters", [("P6", 27.5, "kN")])]
    >>> with tempfile.TemporaryDirectory() as d:
    ...     wb = load_workbook(write_xlsx(tables, Path(d) / "tables.xlsx", inputs=inputs))
    ...     ws = wb[wb.sheetnames[4]]
    ...     rows = [[c.value for c in row] for row in ws.iter_rows(max_row=4, max_col=2)]
    ...     fmt, first = ws["B4"].number_format, wb["Inputs"]["A2"].value
    ...     wb.close()
    >>> wb.sheetnames[:2], first
    (['Inputs', '2.1 Geometric analysis link'], 'P6')
    >>> rows[0][0], rows[1:3]  # title, symbols, units
    ('Table 4.1 — Lift capacity: cylinder force, pressure, capacity, reserve', [['S', 'Fgc'], ['m', 'N']])
    >>> rows[3][0], round(rows[3][1]), fmt  # S [m], Fgc [N]; seed 003 table 4.1: 129614
    (0.42, 129614, '0')
    """
    import xlsxwriter

    path = Path(path)
    # streamed row by row (a crank turn's 361 rows of 30 columns keep no cell object);
    # a text is a text (never read as a formula or a link); numbers as _exact_sheet_class
    # writes them
    wb = xlsxwriter.Workbook(str(path), {"constant_memory": True,
                                         "strings_to_formulas": False,
                                         "strings_to_urls": False})
    bold = wb.add_format({"bold": True})
    title_font = wb.add_format({"bold": True, "font_size": 12})
    unit_font = wb.add_format({"italic": True, "font_color": "#57606A"})
    formats: dict = {}

    def fmt(number_format):
        if number_format not in formats:
            formats[number_format] = wb.add_format({"num_format": number_format})
        return formats[number_format]

    def put(ws, r, c, value, cell_format=None):
        if isinstance(value, str):
            ws.write_string(r, c, value, cell_format)
        elif value is not None:  # None (NaN, infinite): an empty cell
            ws.write_number(r, c, value, cell_format)

    taken = []
    try:
        if inputs:
            ws = wb.add_worksheet(t("inputs_sheet", lang), worksheet_class=_exact_sheet_class())
            taken.append(ws.name)
            width = [12, 14, 10]
            for _, rows in inputs:
                for row in rows:
                    for j, v in enumerate(row[:len(width)]):
                        width[j] = max(width[j], min(60, len(str(v)) + 2))
            for j, w in enumerate(width):
                ws.set_column(j, j, w)
            r = 0
            for heading, rows in inputs:
                put(ws, r, 0, heading, title_font)
                r += 1
                for row in rows:
                    for j, v in enumerate(row):
                        put(ws, r, j, v if isinstance(v, str) else _xlsx_value(v))
                    r += 1
                r += 1  # a blank row between the sections
        for tab in tables:
            ws = wb.add_worksheet(sheet_name(tab, lang, taken), worksheet_class=_exact_sheet_class())
            taken.append(ws.name)
            ws.freeze_panes(3, 1)  # B4: the title, symbols and units rows, the first column
            for j, c in enumerate(tab.columns):
                ws.set_column(j, j, max(10, len(c.symbol) + 3, len(c.unit) + 3))
            put(ws, 0, 0, f"{t('table', lang)} {tab.label} — {tab.title(lang)}", title_font)
            # row by row: a row once left is written (constant_memory)
            for j, c in enumerate(tab.columns):
                put(ws, 1, j, c.symbol, bold)
            for j, c in enumerate(tab.columns):
                put(ws, 2, j, unit(c.unit, lang), unit_font)
            shown = [fmt(number_format(c.values)) for c in tab.columns]
            r = 3
            for row in zip(*(c.values for c in tab.columns)):
                for j, (x, f) in enumerate(zip(row, shown)):
                    put(ws, r, j, _xlsx_value(x), f)
                r += 1
            notes = [n.get(lang, n.get("en", "")) for n in tab.notes]
            r += 1  # a blank row, then the notes
            for n in notes:
                put(ws, r, 0, n)
                r += 1
    finally:
        wb.close()
    return path


def _xlsx_value(x):
    """A number as Excel stores it: integers as such, floats finite (no -0.0) or None."""
    if isinstance(x, (bool, np.bool_, int, np.integer)):
        return int(x)
    x = float(x)
    return x + 0.0 if math.isfinite(x) else None


@functools.cache
def _exact_sheet_class():
    """The worksheet class of :func:`write_xlsx` (made once, when xlsxwriter is imported)."""
    from xlsxwriter.worksheet import Worksheet

    class ExactSheet(Worksheet):
        """A worksheet whose numbers are written with ``repr`` (the shortest text
        that reads back as the same double; integers as such) instead of
        xlsxwriter's ``"%.16G"``, which rounds some doubles (0.47555555555555556
        becomes 0.4755555555555556, one ulp off)."""

        def _xml_number_element(self, number, attributes=()):
            attr = "".join(f' {k}="{self._escape_attributes(v)}"' for k, v in attributes)
            text = repr(float(number)) if isinstance(number, float) else str(int(number))
            self.fh.write(f"<c{attr}><v>{text}</v></c>")

    return ExactSheet
