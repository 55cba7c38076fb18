"""Every bundled model's documents in every unit system and both languages (issue 23):
the tables and their CSV files (each system in each language) and a workbook hold
every value in the unit the system gives its kind and read back to the same numbers
(a Russian CSV with ``;`` and the decimal comma); the HTML report (each system once,
each language twice) writes no value in another unit, no NaN or infinity, and in
Russian no English word (symbols, names and file names aside).

A variant that only adds design or tolerance sections to a bundled model is reported as
its base (tests.helpers.reports.SAME_REPORT, checked in test_models.py). The diagrams of
each machine in each system are checked by
tests/views/report/test_figures_labels.py and tests/views/report/test_html_browser.py.
"""

from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest

from assur import io
from assur.core.display import SYSTEMS, unit_system
from assur.texts import LANGS
from assur.views.report.html import model_inputs, render_html
from assur.views.report.labels import unit
from assur.views.report.tables import seed_tables, table_filename, write_csv, write_xlsx
from tests.helpers.documents import (allowed_units, latin_words, model_symbols, model_texts,
                                     unit_violations, visible, without)
from tests.helpers.reports import SAME_REPORT, read_report_csv

MODELS = sorted(p.stem for p in Path(io.bundled("hitch_003")).parent.glob("*.toml"))
#: the bundled files kept as their seed prints them: they cannot assemble
AS_PRINTED = {"header_000", "combine_002_printed"}
#: every bundled model that assembles, but the variants whose report is their base's
REPORTED = [m for m in MODELS if m not in AS_PRINTED and m not in SAME_REPORT]


@lru_cache(maxsize=None)
def _analysis(name):
    return io.load(io.bundled(name)).analyze()


def _check_tables(name, tabs, du, lang, out):
    allowed = allowed_units(du, lang)
    for t in tabs:
        for c in t.columns:
            assert unit(c.unit, lang) in allowed, (name, du.system, t.id, c.symbol, c.unit)
        rows = read_report_csv(write_csv(t, out / table_filename(t), lang), lang)
        assert rows[0] == [f"{c.symbol} [{unit(c.unit, lang)}]" for c in t.columns]
        for j, c in enumerate(t.columns):
            back = np.array([float(r[j]) if r[j] else np.nan for r in rows[1:]])  # '': undefined
            assert np.array_equal(back, np.asarray(c.values, dtype=float), equal_nan=True), \
                (name, du.system, lang, t.id, c.symbol)


def _check_workbook(name, a, tabs, du, lang, out):
    from openpyxl import load_workbook

    path = write_xlsx(tabs, out / "tables.xlsx", lang=lang, inputs=model_inputs(a, lang, du))
    wb = load_workbook(path, read_only=True)
    for t, ws in zip(tabs, wb.worksheets[1:]):
        sheet = [list(r) for r in ws.iter_rows(values_only=True)]
        assert [unit(c.unit, lang) for c in t.columns] == sheet[2][:len(t.columns)]
        for j, c in enumerate(t.columns):
            col = [r[j] for r in sheet[3:3 + len(t)]]
            want = np.asarray(c.values, dtype=float)
            got = np.array([np.nan if v is None else float(v) for v in col])
            assert np.array_equal(got, want, equal_nan=True), (name, t.id, c.symbol)
    wb.close()


@pytest.mark.slow
@pytest.mark.parametrize("name", REPORTED)
def test_documents_in_every_unit_system_and_language(name, tmp_path):
    a = _analysis(name)
    mech = a.mechanism
    # the workbook of one of the eight pairs (its writer is the same for every system; the
    # units are the tables'), each system in each language across the models
    i = REPORTED.index(name)
    workbooks = {(SYSTEMS[i % 4], LANGS[(i // 4) % 2])}
    for system in SYSTEMS:
        for lang in LANGS:
            du = unit_system(mech, system)
            out = tmp_path / f"{system}-{lang}"
            out.mkdir()
            tabs = seed_tables(a, lang, units=du)
            _check_tables(name, tabs, du, lang, out)
            if (system, lang) in workbooks:
                _check_workbook(name, a, tabs, du, lang, out)
            if (SYSTEMS.index(system) + LANGS.index(lang)) % 2:
                continue  # the report in each system once, in each language twice
            page = render_html(a, lang, figures={}, drawing=False, animation=False,
                               tables=tabs, units=du)
            text = visible(page)
            assert not re.search(r"\b(nan|inf|NaN)\b", text), (name, system, lang)
            own = without(text, model_texts(mech, lang))  # the file's own texts: as written
            assert not unit_violations(own, du, lang), \
                (name, system, lang, unit_violations(own, du, lang)[:5])
            if lang == "ru":
                assert not latin_words(own, model_symbols(mech, tabs)), \
                    (name, system, latin_words(own, model_symbols(mech, tabs)))
