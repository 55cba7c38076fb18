"""The tables' files: CSV (exact ``repr`` numbers) and XLSX (one sheet per table)
(:mod:`assur.views.report.tables`)."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np

__all__ = ["table_filename", "write_csv", "write_xlsx"]


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
