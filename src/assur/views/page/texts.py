"""The page's labels in English and Russian.

The report's labels (:data:`assur.views.report.labels.TEXT`: parameters, drawing,
tables, diagrams, warnings, play, position) are reused; the few that only the
page needs are here.

>>> page_texts()["drawing"]["ru"]
'Схема механизма'
"""

from __future__ import annotations

__all__ = ["page_texts", "PAGE_TEXT"]

#: the report's label keys the page shows
_REUSED = ("parameters", "solved", "tables", "figures", "drawing", "warnings", "play",
           "position", "table", "no_warnings", "value", "unit", "name")

#: labels only the page has: key -> {lang: text}
PAGE_TEXT = {
    "stroke": {"en": "Position over the range", "ru": "Положение в диапазоне"},
    "outputs": {"en": "Plotted outputs", "ru": "Выводимые величины"},
    "at_position": {"en": "Values at this position", "ru": "Значения в этом положении"},
    "downloads": {"en": "Downloads", "ru": "Загрузки"},
    "model_file": {"en": "model file (TOML)", "ru": "файл модели (TOML)"},
    "tables_xlsx": {"en": "all tables (XLSX)", "ru": "все таблицы (XLSX)"},
    "table_csv": {"en": "this table (CSV)", "ru": "эта таблица (CSV)"},
    "dxf": {"en": "drawing at this position (DXF)", "ru": "схема в этом положении (DXF)"},
    "reset": {"en": "restore the file's values", "ru": "вернуть значения файла"},
    "error_title": {"en": "The mechanism cannot be drawn", "ru": "Механизм нельзя построить"},
    "redrawn": {"en": "redrawn in", "ru": "перерисовано за"},
    "ms": {"en": "ms", "ru": "мс"},
    "solved_value": {"en": "solved", "ru": "найдено"},
    "language": {"en": "Русский", "ru": "English"},
    "computing": {"en": "computing…", "ru": "расчёт…"},
    "add_plot": {"en": "add a plot", "ru": "добавить график"},
    "remove": {"en": "remove", "ru": "убрать"},
    "positions": {"en": "positions", "ru": "положений"},
    "units_file": {"en": "units of the model file", "ru": "единицы файла модели"},
    "units_engineering": {"en": "mm, kN, MPa", "ru": "мм, кН, МПа"},
    "units_si": {"en": "SI: m, rad, N, Pa", "ru": "СИ: м, рад, Н, Па"},
    "units_imperial": {"en": "in, lbf, psi", "ru": "дюйм, фунт-сила, фунт/дюйм²"},
    "whole": {"en": "a whole number in", "ru": "целое число в пределах"},
    "field_empty": {"en": "empty: the value in force is kept,",
                    "ru": "поле пусто: сохранено действующее значение"},
    "field_nan": {"en": "not a number: enter a value in", "ru": "не число: введите значение"},
    "field_range": {"en": "out of range: enter a value in",
                    "ru": "вне диапазона: введите значение"},
    "server_down": {"en": "the server is not answering — is `assur serve` still running?",
                    "ru": "сервер не отвечает — запущен ли ещё `assur serve`?"},
    "no_server": {"en": "no answer from the server", "ru": "нет ответа сервера"},
    "bad_answer": {"en": "the server's answer could not be read",
                   "ru": "ответ сервера не удалось прочитать"},
    "preparing": {"en": "preparing…", "ru": "подготовка…"},
    "download_failed": {"en": "the download failed", "ru": "загрузка не удалась"},
    "click_trajectory": {"en": "click to show or hide its trajectory",
                         "ru": "щелчок показывает или скрывает траекторию"},
    "edited": {"en": "edited", "ru": "изменённый"},
    "original": {"en": "the file's design", "ru": "проект из файла"},
    "undo": {"en": "undo", "ru": "отменить"},
    "plot_over": {"en": "over", "ru": "по оси абсцисс"},
    "overlay": {"en": "several positions", "ru": "несколько положений"},
    "compare": {"en": "compare with the file's design", "ru": "сравнить с проектом из файла"},
}


def page_texts() -> dict:
    """Every label the page shows: ``{key: {"en": …, "ru": …}}``.

    Examples
    --------
    >>> from assur.views.page.texts import page_texts
    >>> t = page_texts()
    >>> t["play"]["ru"], t["dxf"]["en"]          # one of the report's, one of the page's
    ('пуск / пауза', 'drawing at this position (DXF)')
    >>> all(set(v) == {"en", "ru"} for v in t.values())
    True
    """
    from ..report.labels import TEXT
    out = {k: dict(TEXT[k]) for k in _REUSED if k in TEXT}
    out.update({k: dict(v) for k, v in PAGE_TEXT.items()})
    return out
