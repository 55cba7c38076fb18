"""The reports of a model other than its analysis — the simulation in time
(:mod:`assur.views.report.simulation`) and the work-cycle sweep
(:mod:`assur.views.report.cycles`) — as documents of the same look as the analysis
report (``report.css``): the model's inputs first (the model file's name, every
parameter in the display units, the hydraulic drive's components), the verdicts, the
results, numbered tables and figures with captions, the motion and the notes
(``document.html.j2``).
"""

from __future__ import annotations

import dataclasses

from ...core.display import unit_system
from ...texts import localize
from .labels import TEXT, check_lang, t, unit
from .numbers import number

__all__ = ["render_document", "model_rows", "drive_rows", "table_items"]


def model_rows(mechanism, lang="en", units=None, source=None) -> list:
    """The inputs of a model as sections ``(heading, header, rows)``: the model (title,
    name, file) and every parameter in its display unit (``units``: a system or
    :class:`~assur.core.display.DisplayUnits`; default: the file's).

    Examples
    --------
    >>> from assur import io
    >>> from assur.views.report.document import model_rows
    >>> model = io.load(io.bundled("adapter_lab6"))
    >>> (h1, _, rows1), (h2, header, rows2) = model_rows(model.mechanism, source="a.toml")
    >>> h1, rows1[-1], h2, header
    ('Model', ('model file', 'a.toml'), 'Parameters', ('name', 'value', 'unit'))
    >>> [r for r in rows2 if r[0] in ("L3", "m6")]   # as the file gives them
    [('L3', '250', 'mm'), ('m6', '1000', 'kg')]
    """
    from .html import parameter_rows
    check_lang(lang)
    du = unit_system(mechanism, units)
    model = [(t("title", lang), localize(mechanism.title, lang)), (t("name", lang),
                                                                  mechanism.name)]
    if source:
        model.append((t("model_file", lang), str(source)))
    params = parameter_rows(mechanism, du, lang)
    return [(t("summary", lang), None, model),
            (t("parameters", lang), (t("name", lang), t("value", lang), t("unit", lang)),
             params)]


#: the quantities of a drive component (:attr:`quantities`) whose kind the display
#: units know, by their name there
_DRIVE_KINDS = {"length": "length", "pressure": "pressure", "volume": "volume",
                "flow": "flow", "angular velocity": "angular_velocity", "time": "time"}


#: the SI unit of the drive's quantities that have no display kind (a number: "-")
_SI = {"density": "kg/m³", "kinematic viscosity": "m²/s", "inertance": "Pa·s²/m³",
       "resistance": "Pa·s/m³", "turbulent resistance": "Pa·s²/m⁶"}


def drive_rows(circuit, lang="en", units=None, mechanism=None) -> tuple:
    """The hydraulic drive's components as one input section ``(heading, header,
    rows)``: a row per component and value — its type and name, the key, the value in
    its display unit (a pressure in MPa where the file writes MPa, …); quantities the
    display units have no kind for (density, viscosity, a line's coefficients) in SI.

    Examples
    --------
    >>> from assur import io
    >>> from assur.views.report.document import drive_rows
    >>> model = io.load(io.bundled("adapter_lab6"))
    >>> heading, header, rows = drive_rows(model.drive, mechanism=model.mechanism)
    >>> heading, header
    ('Hydraulic drive', ('component', 'key', 'value', 'unit'))
    >>> [r for r in rows if r[1] == "setting"]   # the relief valve's, as the file writes it
    [('relief valve', 'setting', '16', 'MPa')]
    """
    from .html import unit_text
    check_lang(lang)
    du = unit_system(mechanism, units) if mechanism is not None else unit_system(None, units
                                                                              or "si")
    rows = []
    for comp in circuit.components:
        who = localize(getattr(comp, "title", comp.type_name), lang)  # the type's own words
        if comp.name:
            who += f" «{localize(comp.name, lang)}»"
        for f in dataclasses.fields(comp):
            v = getattr(comp, f.name)
            if f.name == "name" or v is None:
                continue
            key = t(f"dk_{f.name}", lang) if f"dk_{f.name}" in TEXT else f.name
            q = comp.quantities.get(f.name)
            if q in _DRIVE_KINDS:
                u = du[_DRIVE_KINDS[q]]
                rows.append((who, key, number(float(u.of(float(v))), None, lang),
                             unit_text(u, lang)))
            elif isinstance(v, (int, float)) and not isinstance(v, bool):
                rows.append((who, key, number(float(v), None, lang),
                             unit(_SI.get(q, "-"), lang)))
            elif isinstance(v, tuple):
                rows.append((who, key, "; ".join(number(float(x), None, lang) for x in v),
                             unit("-", lang)))
            else:  # a word of the file ("raise"), in the component's words where it has them
                rows.append((who, key, localize(getattr(comp, "words", {}).get(v, v), lang),
                             ""))
    return (t("drive_section", lang), (t("component", lang), t("key", lang), t("value", lang),
                                        t("unit", lang)), rows)


def table_items(tables, lang="en") -> list:
    """The tables as the report shows them (numbered 1, 2, … in order; per-column
    decimals; a units row), for :func:`render_document`.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.views.report.document import table_items
    >>> from assur.views.report.tables import Column, Table
    >>> tab = Table("pump", {"en": "Pump", "ru": "Насос"},
    ...             (Column("T", "s", np.array([4.0, 6.0])), Column("F", "N", np.array([1e5, 2e5]))))
    >>> item = table_items([tab], "ru")[0]
    >>> item["label"], item["title"], item["rows"][1], [c["unit"] for c in item["cols"]]
    ('1', 'Насос', ['6,000', '200000'], ['с', 'Н'])
    """
    from .html import table_view
    from .tables import numbered
    return [table_view(tab, lang) for tab in numbered(list(tables))]


def render_document(*, lang, title, kind, name, source=None, inputs=(), verdicts=(),
                    verdicts_title=None, verdicts_notes=(), sections=(), tables=(),
                    figures=None, player=None, notes=()) -> str:
    """A report of a model as one self-contained HTML document (``document.html.j2``,
    ``report.css``).

    Parameters
    ----------
    lang : {"en", "ru"}
    title, kind, name : str
        The model's title, what the report is ("Simulation report"), the model's name.
    source : str, optional
        The model file's name.
    inputs : sequence of (heading, header or None, rows)
        The inputs (:func:`model_rows`, :func:`drive_rows`).
    verdicts : sequence of dict
        ``{"status": "ok"|"warn"|"fail"|"info", "text": str, "href": anchor or None}``.
    sections : sequence of dict
        Results as rows: ``{"anchor", "title", "header", "rows", "notes"}``.
    tables : sequence of Table
        Numbered in order (:func:`table_items`).
    figures : dict, optional
        ``{name: Figure or PNG bytes or (either, caption)}``, numbered in order.
    player : str, optional
        The motion's player (:func:`assur.views.report.drawing.player`).
    notes : sequence of str
        The warnings and notes.

    Examples
    --------
    >>> from assur.views.report.document import render_document
    >>> page = render_document(lang="ru", title="Погрузчик", kind="Отчёт", name="loader",
    ...                        source="loader.toml", inputs=[("Модель", None, [("имя", "loader")])],
    ...                        sections=[{"anchor": "energy", "title": "Энергия", "header": None,
    ...                                   "rows": [("работа насоса", "1,5", "Дж")], "notes": []}])
    >>> "файл модели loader.toml" in page, "<td>1,5</td>" in page, page.count("<section")
    (True, True, 2)
    """
    from .html import figure_items, stylesheet, template
    check_lang(lang)
    L = {k: v[lang] for k, v in TEXT.items()}
    return template("document.html.j2").render(
        lang=lang, L=L, css=stylesheet(), title=title, kind=kind, name=name, source=source,
        inputs=list(inputs), verdicts=list(verdicts), verdicts_title=verdicts_title,
        verdicts_notes=list(verdicts_notes), sections=list(sections),
        tables=table_items(tables, lang), figures=figure_items(dict(figures or {}), lang),
        player=player, notes=[str(n) for n in notes])
