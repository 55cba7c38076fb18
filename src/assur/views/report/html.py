"""One self-contained HTML file: model, tables, diagrams, drawing, animation, notes.

Everything is inside the file: styles and the small animation player are inline,
images are ``data:`` URIs (base64 PNG), the animation an inline SVG of vector frames. It links to nothing outside itself (no
CSS, scripts, fonts or network addresses), so it can be mailed or archived as is.

Every value is shown in the report's display units (:mod:`assur.core.display`: the
model file's, engineering, SI or imperial) and language (Russian with the decimal
comma). The numbers of a table column share one count of decimals that shows four
significant digits of its largest magnitude
(:func:`assur.views.report.numbers.decimals`); the closure residuals are one check
line under their table, not a column of 1e-16 noise. The CSV and XLSX files keep
full precision.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import base64

import numpy as np

from ...core.display import parameter_units, unit_system
from ...texts import localize
from .labels import TEXT, check_lang, t, unit
from .numbers import decimals, number, numbers, quantity
from .values import parameter_value, solved_line

__all__ = ["write_html", "render_html", "model_inputs", "stylesheet"]

def data_uri(data: bytes, mime: str = "image/png") -> str:
    """``data:`` URI of an image, for embedding it in an HTML report."""
    return f"data:{mime};base64," + base64.b64encode(data).decode("ascii")


def _anchor(prefix, ident):
    return prefix + "".join(ch if ch.isalnum() else "-" for ch in str(ident)).lower()


def _kind(g, lang):
    """A group's kind in the report's language (the group type's own words)."""
    return g.kind if lang == "en" else g.kind_ru


def unit_text(u, lang):
    """A display unit as a parameter's row shows it (``°`` for degrees)."""
    return "°" if u.is_degrees else unit(u.text, lang)


def parameter_rows(mech, du, lang) -> list:
    """``(name, value, unit)`` of every parameter as the reports show it: the value in
    its display unit (the file's, for the ``file`` system) with the report's number
    notation, the unit in ``lang`` (the analysis report's and the other documents'
    inputs)."""
    units = parameter_units(mech, du)
    return [(n, parameter_value(v, units[n], lang), unit_text(units[n], lang))
            for n, v in mech.params.items()]


def _summary(analysis, lang, du):
    mech = analysis.mechanism
    kin = analysis.kinematics
    params = parameter_rows(mech, du, lang)
    units = parameter_units(mech, du)
    coords = []
    for c in kin.coordinates:
        q = np.asarray(kin.q(c), dtype=float)
        kind = "angle" if mech.coordinate_kind(c) == "angle" else "length"
        # over several coordinates: each one's own values, not the grid's positions
        n = q.shape[-1] if kin.k == 1 else np.unique(q.reshape(-1, q.shape[-1])[0]).size
        coords.append(f"{c}: {number(du.value(q.min(), kind), None, lang, 6)} … "
                      f"{quantity(q.max(), kind, du, lang, 6)} ({n} {t('positions', lang)})")
    coords += [_motion_line(mo, du, lang) for mo in mech.motions]
    if kin.k > 1:  # the grid's shape, or paired paths
        shape = [np.unique(np.asarray(kin.q(c), float).reshape(-1, kin.n)[0]).size
                 for c in kin.coordinates]
        coords.append(f"{' × '.join(kin.coordinates)}: "
                      + (f"{' × '.join(map(str, shape))} = " if np.prod(shape) == kin.n
                         else t("paired", lang) + ", ")
                      + f"{kin.n} {t('positions', lang)}")
    groups = [(localize(g.name, lang), _kind(g, lang), ", ".join(g.inputs()),
               ", ".join(g.outputs()),
               ", ".join(g.group_links())) for g in mech.groups if g.type_name != "frame"]
    links = []
    for b, v in mech.bodies.items():
        kind = t("frame", lang) if b == "0" else (t("variable", lang) if v["variable"]
                                                  else t("rigid", lang))
        links.append((b, kind, ", ".join(v["points"])))
    machine = []
    carry = mech.machine
    if carry is not None and getattr(carry, "machine", None) is not None:
        mc = carry.machine
        for name, x in mc.axles.items():
            tag = " (steered)" if name == mc.steered and lang == "en" else (
                " (управляемая)" if name == mc.steered else "")
            machine.append(f"{'axle' if lang == 'en' else 'ось'} {name}{tag}: "
                           f"x = {quantity(x, 'length', du, lang, 6)}")
        for name, p, x in tuple(mc.weights) + tuple(mc.counterweights):
            machine.append(f"{localize(name, lang)}: {quantity(p, 'force', du, lang, 6)}, "
                           f"x = {quantity(x, 'length', du, lang, 6)}")
        share = number(100 * mc.min_share, None, lang, 6)
        machine.append(f"min share: {share} %" if lang == "en"
                       else f"минимальная доля: {share} %")
    solved = [solved_line(sc, mech, lang, units, du) for sc in getattr(analysis, "solved", ())]
    return dict(params=params, coords=coords, groups=groups, links=links, machine=machine,
                solved=solved, dynamics=_dynamics_lines(analysis, lang, du))


#: the directions of a motion in the report's languages
_DIRECTIONS = {"cw": {"en": "clockwise", "ru": "по часовой стрелке"},
               "ccw": {"en": "counter-clockwise", "ru": "против часовой стрелки"},
               "extend": {"en": "extending", "ru": "выдвижение"},
               "retract": {"en": "retracting", "ru": "втягивание"}}


def _motion_line(mo, du, lang):
    """A coordinate's motion ([motion]) in the display units: ``j1: clockwise, |ω| =
    31.42 rad/s``; a speed or law given over time as its span."""
    direction = _DIRECTIONS[mo.direction_name][lang]
    rate = "velocity" if mo.kind == "length" else "angular_velocity"
    sym = "|v|" if mo.kind == "length" else "|ω|"
    if mo.law_t:
        coord = "length" if mo.kind == "length" else "angle"
        span = (f"{quantity(mo.law_q[0], coord, du, lang)} … "
                f"{quantity(mo.law_q[-1], coord, du, lang)}, "
                f"{quantity(mo.law_t[0], 'time', du, lang)} … "
                f"{quantity(mo.law_t[-1], 'time', du, lang)}")
        return f"{mo.coordinate}: {direction}, q(t): {span}"
    if mo.speed is not None:
        return f"{mo.coordinate}: {direction}, {sym} = {quantity(mo.speed, rate, du, lang)}"
    if mo.t:
        return (f"{mo.coordinate}: {direction}, {sym}(t) = "
                f"{quantity(min(mo.omega), rate, du, lang)} … "
                f"{quantity(max(mo.omega), rate, du, lang)}")
    return f"{mo.coordinate}: {direction}"


def _dynamics_lines(analysis, lang, du):
    """The crank dynamics in a few lines: speed, reduced moment of inertia, driving
    moment, the common centre of mass, the flywheel and the balancing (lab 3)."""
    dyn = getattr(analysis, "dynamics", None)
    if dyn is None:
        return []

    def q(si, kind):
        return quantity(si, kind, du, lang)

    w = float(np.mean(np.abs(np.ravel(dyn.qdot))))
    c = dyn.centre
    out = [t("dyn_speed", lang, dyn.coordinate, q(w, "angular_velocity")),
           t("dyn_jred", lang, q(float(np.min(dyn.reduced_inertia)), "inertia"),
             q(float(np.max(dyn.reduced_inertia)), "inertia")),
           t("dyn_md", lang, q(float(np.min(dyn.driving_moment)), "moment"),
             q(float(np.max(dyn.driving_moment)), "moment")),
           t("dyn_centre", lang, q(float(c.amplitude_x), "length"),
             q(float(c.amplitude_y), "length"), q(float(c.area), "area"),
             q(float(c.mass), "mass"))]
    fw = getattr(analysis, "flywheel", None)
    if fw is not None:
        out.append(t("dyn_flywheel", lang, number(fw.delta, None, lang),
                     q(fw.J_flywheel, "inertia"), q(fw.omega_min, "angular_velocity"),
                     q(fw.omega_max, "angular_velocity"), q(fw.driving_moment, "moment"),
                     q(fw.J_classical, "inertia"), q(fw.J_mertsalov, "inertia")))
    b = getattr(analysis, "balancing", None)
    if b is not None:
        placed = "; ".join(t("dyn_mass", lang, m.link, q(float(m.m), "mass"),
                             q(float(m.along), "length"), q(float(m.offset), "length"))
                           for m in b.masses) or "—"
        out.append(t("dyn_balance", lang, t(f"objective_{b.objective}", lang), placed,
                     q(float(b.after.amplitude_x), "length"),
                     q(float(b.after.amplitude_y), "length"), q(float(b.after.area), "area")))
    return out


#: the tables' column of closure residuals, shown in the report as one check line
CLOSURE = "closure"


def table_view(tab, lang):
    """A table as the reports show it (:attr:`Table.label`, title, symbols with their
    units, every number with its column's decimals, the closure residuals as one check
    line among the notes), for the templates."""
    cols, shown, checks = [], [], []
    for c in tab.columns:
        if c.symbol == CLOSURE:  # noise of 1e-16: one line, not a column
            # np.max, not nanmax: a residual that is not a number shows as "—"
            worst = float(np.max(np.abs(c.values))) if len(c.values) else 0.0
            checks.append(t("closure_check", lang,
                            f"{number(worst, None, lang, 2)} {unit(c.unit, lang)}"))
            continue
        mark = "*" if c.printed_sign < 0 else ""
        tip = c.label.get(lang, "") + (f" — {t('printed_sign', lang)}" if mark else "")
        cols.append(dict(symbol=c.symbol + mark, unit=unit(c.unit, lang), tip=tip))
        shown.append((c, decimals(c.values)))
    texts = [numbers(c.values, d, lang) for c, d in shown]  # column by column
    rows = [list(r) for r in zip(*texts)] if texts else [[] for _ in range(len(tab))]
    return dict(id=tab.id, label=tab.label, anchor=_anchor("table-", tab.id),
                title=tab.title(lang), cols=cols, rows=rows, cells=_cells(rows),
                parts=_print_parts(rows, len(cols)),
                notes=checks + [n.get(lang, n.get("en", "")) for n in tab.notes])


#: a table of more columns than this has a print-only copy cut into parts of at most
#: this many columns, each repeating the first column (the coordinate)
PART_COLS = 16


def _print_parts(rows, n):
    """The parts of the print-only copy of a table of ``n`` columns (none when it fits
    on the page): the columns of each (the first one, then an equal share of the
    others) and its rows' cells (:func:`_cells`)."""
    if n <= PART_COLS:
        return []
    count = -(-(n - 1) // (PART_COLS - 1))
    per = -(-(n - 1) // count)
    parts = []
    for k in range(count):
        idx = [0] + list(range(1 + k * per, min(n, 1 + (k + 1) * per)))
        parts.append(dict(cols=idx, cells=_cells([[r[j] for j in idx] for r in rows])))
    return parts


def _cells(rows):
    """Each row's cells as one piece of HTML (``<td>…</td>…``, every text escaped): a
    table of a crank turn has tens of thousands of cells, escaped here once each
    instead of once per copy the template prints."""
    from html import escape

    from markupsafe import Markup
    return [Markup("".join(f"<td>{escape(s, quote=False)}</td>" for s in r)) for r in rows]


def figure_items(figures, lang):
    """``{name: Figure or PNG bytes or (either, caption)}`` as the templates' numbered
    figures: anchor, ``data:`` URI and the caption "Figure k — …" (a figure's caption
    by default: its first axes' title)."""
    from ._canvas import to_png_bytes

    items = []
    for k, (name, obj) in enumerate(figures.items(), start=1):
        caption = None
        if isinstance(obj, tuple):
            obj, caption = obj
        if not isinstance(obj, (bytes, bytearray)):
            if caption is None and obj.axes:
                caption = obj.axes[0].get_title()
            obj = to_png_bytes(obj)
        if caption is None:
            key = f"f_{name}"
            caption = TEXT[key][lang].replace("{0}", "").strip() if key in TEXT else name
        items.append(dict(name=name, anchor=_anchor("fig-", name), src=data_uri(bytes(obj)),
                          caption=f"{t('figure', lang)} {k} — {caption}"))
    return items


#: the order of the verdicts on the first page: what fails, what is near its limit, then
#: the rest as the analysis gives them
_FIRST = {"fail": 0, "warn": 1}


def _verdicts(analysis, tables, du, lang):
    """The first page's verdicts (:func:`assur.views.report.verdicts.verdicts`) on the
    tables as the report shows them, each linking to its table or section."""
    from .verdicts import verdicts
    out = verdicts(analysis, tables, du, lang)
    out = sorted(out, key=lambda v: _FIRST.get(v.status, 2))
    return [dict(status=v.status, text=v.text, href=v.anchor) for v in out]


def _file_names(text):
    """``text`` with each path of a model file cut to its file name (a report names the
    file, not the folders of the machine that ran it)."""
    import re
    return re.sub(r"(?:[A-Za-z]:)?[^\s:]*[/\\]([^/\\\s:]+\.toml)", r"\1", str(text))


def _warnings(analysis, tables, lang):
    mech = analysis.mechanism
    groups = []
    model_notes = ([localize(n, lang) for n in mech.notes]
                   + list(getattr(analysis.kinematics, "failures", []))
                   + [_file_names(localize(w, lang)) for w in analysis.model_warnings]
                   + [localize(n, lang) for n in getattr(analysis, "notes", ())])
    groups.append((t("model_notes", lang), model_notes))
    from ...core.columns import formulas_of, signs_of
    sign_notes = [localize(m.note, lang) for m in signs_of(mech) if m.note]
    groups.append((t("statics_flags", lang), sign_notes))
    stab = [localize(x, lang) for f in formulas_of(mech) for x in f.flags]
    groups.append((t("stability_flags", lang), stab))
    seen = set(model_notes) | set(sign_notes) | set(stab)
    other = []
    for tab in tables:
        for n in tab.notes:
            txt = n.get(lang, n.get("en", ""))
            if txt not in seen and n.get("en") not in seen:
                seen.add(txt)
                other.append(f"{t('table', lang)} {tab.label}: {txt}")
    groups.append((t("table_notes", lang), other))
    return [dict(title=g, entries=items) for g, items in groups if items]




@lru_cache(maxsize=None)
def template(name="report.html.j2"):
    """A jinja2 template of the reports beside this module: ``report.html.j2`` (the
    analysis) or ``document.html.j2`` (:mod:`assur.views.report.document`)."""
    import jinja2

    env = jinja2.Environment(loader=jinja2.PackageLoader("assur.views.report", ""),
                             autoescape=True, undefined=jinja2.StrictUndefined)
    return env.get_template(name)


def stylesheet() -> str:
    """The report's stylesheet (``report.css`` beside this module), inlined into every
    report so that the file stays self-contained.

    Examples
    --------
    >>> from assur.views.report.html import stylesheet
    >>> "@media print" in stylesheet() or "table" in stylesheet()
    True
    """
    from importlib.resources import files

    return files(__package__).joinpath("report.css").read_text(encoding="utf-8")


def _units(analysis, units):
    """The report's :class:`DisplayUnits` (a system's name, or None: the file's choice)."""
    return unit_system(analysis.mechanism, units)


def model_inputs(analysis, lang="en", units=None) -> list:
    """The inputs of the analysis as sections of rows, for the workbook's inputs sheet
    (:func:`assur.views.report.tables.write_xlsx`): the model (title, name), the
    generalized coordinates over the analysed range, every parameter with its value
    in its display unit (``units``: a system or :class:`DisplayUnits`; the default,
    the model file's: each parameter in the unit the file gave it), and the design
    conditions solved.

    Examples
    --------
    >>> from assur import io
    >>> from assur.views.report.html import model_inputs
    >>> a = io.load(io.bundled("hitch_003")).analyze()
    >>> sections = model_inputs(a)
    >>> [h for h, _ in sections]
    ['Model', 'Generalized coordinates', 'Parameters', 'Design conditions solved (Given/Find)']
    >>> sections[0][1][-1]   # the file, not its folders
    ('model file', 'hitch_003.toml')
    >>> params = dict((n, (v, u)) for n, v, u in sections[2][1])
    >>> params["P6"], round(params["L4"][0], 9), params["L4"][1]  # as given; L4 solved [m]
    ((27.5, 'kN'), 0.661283167, 'm')
    >>> dict((n, (v, u)) for n, v, u in model_inputs(a, units="imperial")[2][1])["P6"]
    (6182.245935242037, 'lbf')
    """
    du = _units(analysis, units)
    s = _summary(analysis, lang, du)
    mech = analysis.mechanism
    units = parameter_units(mech, du)
    params = []
    for n, v in mech.params.items():
        a = np.asarray(v, dtype=float)
        # a number in its display unit, every digit; a batch of designs: count and span
        value = float(units[n].of(a.reshape(-1)[0])) if a.size == 1 else \
            parameter_value(v, units[n], lang)
        params.append((n, value, unit_text(units[n], lang)))
    model = [(localize(mech.title, lang),), (mech.name,)]
    if getattr(analysis, "source", None):
        model.append((t("model_file", lang), analysis.source))
    out = [(t("summary", lang), model),
           (t("coordinates", lang), [(c,) for c in s["coords"]]),
           (t("parameters", lang), [(t("name", lang), t("value", lang), t("unit", lang))]
            + params)]
    if s["solved"]:
        out.append((t("solved", lang), [(line,) for line in s["solved"]]))
    return out


def render_html(analysis, lang="en", figures=None, tables=None, drawing=None, animation=None,
                design=None, interval=120, units=None) -> str:
    """The report as an HTML string (see :func:`write_html`).

    Examples
    --------
    >>> import re
    >>> from assur import examples
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> from assur.views.report.html import render_html
    >>> page = render_html(a, figures={}, drawing=False, animation=False)  # tables only
    >>> re.search(r"<title>(.*?)</title>", page).group(1)
    'Mini-tractor mounted-implement hitch (seed 003) — Analysis report'
    >>> rows = re.findall(r"<tr><td>0\\.4200</td>.*?</tr>", page)  # S = 0.42 m in each table
    >>> re.findall(r"<td>(.*?)</td>", rows[3])  # table 4.1 in the file's units [m, kN, MPa, kN, kN, %]
    ['0.4200', '129.6', '15.35', '33.14', '31.35', '14.02']
    >>> '<html lang="ru"' in render_html(a, "ru", figures={}, drawing=False, animation=False)
    True
    """
    from . import drawing as _drawing
    from . import figures as _figures
    from .tables import seed_tables

    check_lang(lang)
    du = _units(analysis, units)
    if tables is None:
        tables = seed_tables(analysis, lang, design=design, units=du)
    if figures is None:
        figures = _figures.figures(analysis, lang, design=design, units=du)
    if drawing is None:
        drawing = _drawing.draw(analysis, lang=lang, design=design, units=du)
    if animation is None:
        animation = _drawing.animation(analysis, lang=lang, design=design, units=du)
    drawing_uri = None
    if drawing is not False:
        png = drawing if isinstance(drawing, (bytes, bytearray)) else _figures.to_png_bytes(drawing)
        drawing_uri = data_uri(bytes(png))
    tpl = template()
    L = {k: v[lang] for k, v in TEXT.items()}
    mech = analysis.mechanism
    return tpl.render(
        lang=lang, L=L, css=stylesheet(), title=localize(mech.title, lang), name=mech.name,
        source=getattr(analysis, "source", None),
        summary=_summary(analysis, lang, du),
        tables=[table_view(tab, lang) for tab in tables],
        figures=figure_items(dict(figures), lang),
        drawing=drawing_uri,
        player=(_drawing.player(animation, lang, interval) if animation else None),
        warnings=_warnings(analysis, tables, lang),
        verdicts=_verdicts(analysis, tables, du, lang))


def write_html(analysis, path, lang="en", figures=None, tables=None, drawing=None,
               animation=None, design=None, units=None) -> Path:
    """Write the whole report as one self-contained HTML file.

    Parameters
    ----------
    analysis : Analysis
    path : str or Path
        The ``.html`` file to write.
    lang : {"en", "ru"}
        Language of every label.
    figures : mapping of str to Figure, bytes or (bytes, caption), optional
        The diagrams (PNG bytes or matplotlib figures); default: all of
        :func:`assur.views.report.figures.figures`.
    tables : list of Table, optional
        In the display units; default: :func:`assur.views.report.tables.seed_tables`
        in ``units``.
    drawing : Figure, bytes or False, optional
        The drawing of the mechanism; default :func:`assur.views.report.drawing.draw`;
        False leaves it out.
    animation : dict or False, optional
        The animation as vector frames (``{"svg", "captions"}``, played by an inline
        script); default :func:`assur.views.report.drawing.animation`; False leaves
        it out.
    design : int, optional
        Design of a batch.
    units : str or DisplayUnits, optional
        The display units (:data:`assur.core.display.SYSTEMS`); default: the model
        file's ``[display] units``, else ``"file"``.

    Returns
    -------
    Path

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> from assur import examples
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> from assur.views.report.html import write_html
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = write_html(a, Path(d) / "report.html", lang="ru", figures={}, drawing=False,
    ...                    animation=False)
    ...     page = p.read_text(encoding="utf-8")
    >>> p.name, page.startswith("<!DOCTYPE html>"), 'src="http' in page  # self-contained
    ('report.html', True, False)
    >>> "Механизм навески мини-трактора" in page  # the model's title in Russian
    True
    """
    text = render_html(analysis, lang, figures, tables, drawing, animation, design,
                       units=units)
    path = Path(path)
    path.write_text(text, encoding="utf-8")
    return path

