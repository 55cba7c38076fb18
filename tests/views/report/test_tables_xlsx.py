"""The workbook in Russian (issue 23): the inputs sheet and the tables' sheets named,
titled and with units in Russian, the numbers read back with openpyxl equal to the
tables' (stored as numbers whatever the language), the headers frozen."""

import numpy as np
from openpyxl import load_workbook

from assur import io
from assur.views.report.html import model_inputs
from assur.views.report.tables import seed_tables, sheet_name, write_xlsx


def test_russian_workbook_reads_back_to_the_tables(tmp_path):
    a = io.load(io.bundled("hitch_003")).analyze()
    tables = seed_tables(a, lang="ru")
    path = write_xlsx(tables, tmp_path / "t.xlsx", lang="ru", inputs=model_inputs(a, "ru"))
    wb = load_workbook(path)
    assert wb.sheetnames[0] == "Исходные данные"
    params = {r[0]: r[1:3] for r in wb["Исходные данные"].iter_rows(values_only=True)}
    assert params["P6"] == (27.5, "кН") and params["L4"][1] == "м"
    for tab in tables:
        ws = wb[sheet_name(tab, "ru")]
        assert ws["A1"].value.startswith(f"Таблица {tab.id} — ") and ws.freeze_panes == "B4"
        assert ws["A2"].font.bold
        n = len(tab)
        for j, col in enumerate(tab.columns, start=1):
            back = [ws.cell(4 + i, j).value for i in range(n)]
            want = np.asarray(col.values, dtype=float)
            got = np.array([np.nan if v is None else v for v in back], dtype=float)
            assert np.array_equal(got, want, equal_nan=True), (tab.id, col.symbol)
    units = [c.value for c in wb[sheet_name(tables[0], "ru")][3]]
    assert units[0] == "м" and "m" not in units
    wb.close()
