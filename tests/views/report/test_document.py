"""The simulation and work-cycle reports are documents of the analysis report's look
(:mod:`assur.views.report.document`, issue 23): the model's inputs first — its file's
name, every parameter in the file's units, every drive component with its values —
then the verdicts, the results, numbered tables and figures with captions; in Russian
with the decimal comma and no English word (the model's own names and symbols aside)."""

from __future__ import annotations

import re

import numpy as np
import pytest

from assur import io
from assur.dynamics import simulate
from assur.views.report.cycles import tables, write_cycles_report
from assur.views.report.document import drive_rows, model_rows
from assur.views.report.simulation import write_simulation_report
from tests.helpers.documents import latin_words, model_symbols, model_texts, visible, without


def _checked(page, model, lang, figures, tabs=()):
    """What every such document shows, in ``lang`` (``tabs``: its tables, whose column
    symbols it may show)."""
    text = visible(page)
    word = {"en": ("Inputs", "Figure", "model file"),
            "ru": ("Исходные данные", "Рисунок", "файл модели")}[lang]
    assert word[0] in text and f"{word[2]} {model.source.name}" in text
    assert str(model.source.parent) not in page
    # the figures numbered 1 … n, each with a caption
    assert re.findall(rf"{word[1]} (\d+) — \S", text) == [str(k) for k in
                                                           range(1, figures + 1)]
    # every parameter in the unit the file gives it
    for name, value, unit in model_rows(model.mechanism, lang)[1][2]:
        assert f"{name} {value} {unit}" in re.sub(r"\s+", " ", text), (name, value, unit)
    if lang == "ru":
        own = without(text, model_texts(model.mechanism, lang))
        symbols = model_symbols(model.mechanism, tabs)
        own = without(own, [s for s in symbols if "/" in s])  # F1_max_a/comb, as it is
        assert not latin_words(own, symbols), latin_words(own, symbols)
        assert not re.search(r"\d\.\d", own), re.search(r".{30}\d\.\d.{30}", own)
    return text


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_the_simulation_report_is_a_document(tmp_path, lang):
    model = io.load(io.bundled("adapter_lab6"))
    r = simulate(model.mechanism, model.drive, 1.0, t_eval=np.linspace(0.0, 1.0, 11))
    files = write_simulation_report(r, tmp_path, lang=lang, formats=("png", "html"),
                                    model=model)
    pngs = [p for p in files if p.suffix == ".png"]
    assert pngs and all(p.name.startswith("simulation_") for p in pngs)
    page = (tmp_path / "simulation.html").read_text(encoding="utf-8")
    text = _checked(page, model, lang, len(pngs))
    # the drive's components and their values as the file writes them (16 MPa relief)
    setting = {"en": "relief valve setting 16 MPa",
               "ru": "предохранительный клапан давление настройки 16 МПа"}[lang]
    assert setting in re.sub(r"\s+", " ", text)
    assert "✓" in text  # the run reached its end


@pytest.mark.slow
def test_the_cycles_report_is_a_document(tmp_path):
    model = io.load(io.bundled("crane_lv184a"))
    df, verdicts, files = write_cycles_report(model, tmp_path, "ru", formats=("png", "html"))
    pngs = [p for p in files if p.suffix == ".png"]
    page = (tmp_path / "cycles.html").read_text(encoding="utf-8")
    text = _checked(page, model, "ru", len(pngs), tables(df, "ru"))
    # the paper's conclusions as verdicts: agrees ✓, does not ✗, one each
    assert text.count("✓") == sum(v.agrees for v in verdicts)
    assert text.count("✗") == sum(not v.agrees for v in verdicts)
    # the tables numbered 1 … n with their units under the symbols
    assert re.findall(r"Таблица (\d+) — ", text)[:3] == ["1", "2", "3"]


def test_drive_rows_name_every_component_in_the_display_units():
    model = io.load(io.bundled("crane_lv184a"))
    _, header, rows = drive_rows(model.drive, "ru", "engineering", model.mechanism)
    assert header == ("элемент", "ключ", "значение", "ед.")
    flow = [r for r in rows if r[1] == "номинальный расход"]
    assert flow and all(r[2:] == ("80", "л/мин") for r in flow)
    bores = {r[0]: r[2:] for r in rows if r[1] == "диаметр поршня"}
    assert bores == {"гидроцилиндр «ГЦ стрелы»": ("100", "мм"),
                     "гидроцилиндр «ГЦ рукояти»": ("80", "мм")}
    _, _, si = drive_rows(model.drive, "en", "si", model.mechanism)
    assert [r[2:] for r in si if r[1] == "setting"] == [("25000000", "Pa")]


def test_the_simulation_in_every_unit_system():
    """The time series, the summary and the figures in the units chosen: each column's
    values are the SI ones through its unit's factor (COMMON_UNITS, pint's); a rate
    (psi/s) or a mass per length (lb/in) in the system's units of its parts."""
    from assur.core.display import SYSTEMS, unit_system
    from assur.core.units import common_unit
    from assur.views.report.simulation import figures, summary, time_series
    from tests.helpers.documents import allowed_units, axis_units

    model = io.load(io.bundled("adapter_lab6"))
    r = simulate(model.mechanism, model.drive, 0.5, t_eval=np.linspace(0.0, 0.5, 6))
    si = time_series(r, "si", model.mechanism)
    assert {"S [m]", "p1 [Pa]", "F [N]", "Q_pump [m³/s]", "m' [kg/m]"} <= set(si.columns)
    for system in SYSTEMS:
        allowed = allowed_units(unit_system(model.mechanism, system), "en")

        def factor(u):  # SI per unit; a unit outside the system: None
            if u in allowed:
                return common_unit(u).factor
            top, _, bottom = u.rpartition("/")
            if top in allowed and bottom in allowed:
                return common_unit(top).factor / common_unit(bottom).factor
            return None

        df = time_series(r, system, model.mechanism)
        for name in df.columns:
            if name.startswith("phase"):
                continue
            base, u = re.fullmatch(r"(.+) \[(.+)\]", name).groups()
            assert factor(u) is not None, (system, name)
            ref = si[next(c for c in si.columns if c.startswith(base + " ["))]
            np.testing.assert_allclose(df[name].to_numpy(float) * factor(u),
                                       ref.to_numpy(float), rtol=1e-12, atol=1e-300,
                                       err_msg=f"{system}: {name}")
        units = {row[2] for row in summary(r, "en", system, model.mechanism) if row[2]}
        assert all(factor(u) for u in units), (system, units)
        for fig in figures(r, "en", system, model.mechanism).values():
            assert all(factor(u) for u in axis_units(fig)), (system, axis_units(fig))


def test_cli_simulate_and_cycles_take_units_and_the_files_language(tmp_path):
    import pandas as pd
    from typer.testing import CliRunner

    from assur.views.cli import app
    r = CliRunner().invoke(app, ["simulate", str(io.bundled("adapter_lab6")), "-o",
                                 str(tmp_path / "sim"), "--duration", "0.3",
                                 "--units", "imperial"])
    assert r.exit_code == 0, r.output
    df = pd.read_csv(tmp_path / "sim" / "simulation.csv")
    assert {"S [in]", "p1 [psi]", "F [lbf]", "Q_pump [gal/min]"} <= set(df.columns)
    page = visible((tmp_path / "sim" / "simulation.html").read_text(encoding="utf-8"))
    assert "psi" in page and "MPa" not in page
    r = CliRunner().invoke(app, ["simulate", str(io.bundled("adapter_lab6")), "-o",
                                 str(tmp_path / "bad"), "--units", "cgs"])
    assert r.exit_code != 0 and "--units must be one of" in r.output
