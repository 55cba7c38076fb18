"""Tables numbered by the report, not by one seed (issue 23): a machine's tables are
Table 1, 2, … in the report's order — in the HTML headings and contents, the
workbook's sheets and titles, the CSV file names (with what the table holds) and the
terminal — while the seed-003 hitch keeps its worksheet's 2.1 … 6.1 because its file
says so (``[tables] numbering = "seed"``). A table's key (a formula's ``table =``,
the page's selection, the anchors) stays its worksheet id either way. The report names
its model file (not the folders it lies in)."""

from __future__ import annotations

import re

import pytest
from openpyxl import load_workbook

from assur import examples, io
from assur.io import ModelFileError
from assur.texts import localize
from assur.views.report.html import model_inputs, render_html
from assur.views.report.tables import numbered, seed_tables, sheet_name, table_filename, \
    write_xlsx
from assur.views.report.tables import TABLE_CONTENTS


def _html(analysis, lang="en"):
    return render_html(analysis, lang, figures={}, drawing=False, animation=False)


def test_a_machine_that_is_not_the_seed_numbers_its_tables_in_order(tmp_path):
    a = io.load(io.bundled("steering_lab4")).analyze()
    tabs = seed_tables(a)
    assert [t.label for t in tabs] == [str(k) for k in range(1, len(tabs) + 1)]
    assert tabs[0].id == "2.1" and tabs[0].label == "1"   # the key stays the worksheet's
    names = [table_filename(t) for t in tabs]
    assert len(set(names)) == len(names)
    for t, name in zip(tabs, names):
        assert name == f"table_{t.label}_{TABLE_CONTENTS[t.id]}.csv"
    for lang, word in (("en", "Table"), ("ru", "Таблица")):
        html = _html(a, lang)
        for t in tabs:
            assert f"{word} {t.label} — {t.title(lang)}" in html
        # no heading, contents line or note names a table by the seed's number
        assert not re.search(rf"{word} [2-6]\.[12]\b", html)
    path = write_xlsx(tabs, tmp_path / "tables.xlsx", lang="ru", inputs=model_inputs(a, "ru"))
    wb = load_workbook(path)
    for t in tabs:
        ws = wb[sheet_name(t, "ru")]
        assert ws.title.startswith(f"{t.label} ")
        assert ws["A1"].value == f"Таблица {t.label} — {t.title('ru')}"


def test_the_seed_hitch_keeps_its_worksheets_numbers():
    a = examples.hitch_003().analyze(examples.hitch_003_range())
    tabs = seed_tables(a)
    assert [t.label for t in tabs] == [t.id for t in tabs] == \
        ["2.1", "2.2", "3.1", "4.1", "5.1", "6.1", "IC"]
    assert table_filename(tabs[3]) == "table_4_1.csv"
    assert "Table 4.1 — " in _html(a)
    # the same tables numbered by the report
    assert [t.label for t in numbered(tabs)] == ["1", "2", "3", "4", "5", "6", "7"]
    assert table_filename(numbered(tabs)[3]) == "table_4_cylinders.csv"


def test_numbering_is_checked_in_the_file():
    text = io.bundled("hitch_003").read_text(encoding="utf-8")
    bad = text.replace('numbering = "seed"', 'numbering = "worksheet"')
    assert bad != text
    with pytest.raises(ModelFileError) as exc:
        io.loads(bad, name="hitch.toml")
    assert exc.value.key_path == "tables.numbering"
    assert "report" in exc.value.problem and "seed" in exc.value.problem
    model = io.loads(text.replace('numbering = "seed"', 'numbering = "report"'), name="h.toml")
    assert [t.label for t in seed_tables(model.analyze())][:2] == ["1", "2"]


def test_the_report_names_its_model_file_not_its_folders():
    a = io.load(io.bundled("steering_lab4")).analyze()
    assert a.source == "steering_lab4.toml"
    html = _html(a, "ru")
    assert "файл модели steering_lab4.toml" in html
    assert str(io.bundled("steering_lab4").parent) not in html
    assert ("model file", "steering_lab4.toml") in model_inputs(a)[0][1]
    # an analysis of a mechanism built in Python has no file to name
    b = examples.hitch_003().analyze(examples.hitch_003_range())
    assert b.source is None and "· model file" not in _html(b)


def test_drive_components_are_named_in_both_languages():
    crane = io.load(io.bundled("crane_lv184a"))
    names = {str(c.name): localize(c.name, "ru") for c in crane.drive.components if c.name}
    assert names["boom valve"] == "распределитель стрелы"
    assert all(re.fullmatch(r"[а-яё ГЦ]+", ru) for ru in names.values()), names
    text = io.bundled("crane_lv184a").read_text(encoding="utf-8")
    bad = text.replace('name = { en = "boom hose", ru = "рукав стрелы" }', "name = 7")
    assert bad != text
    with pytest.raises(ModelFileError) as exc:
        io.loads(bad, name="crane.toml")
    assert re.fullmatch(r"drive\[\d+\]\.name", exc.value.key_path)
    assert "table of languages" in exc.value.problem
