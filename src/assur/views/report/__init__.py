"""Reports: the seed worksheets' tables, diagrams, drawings and an HTML report.

Views of an :class:`~assur.analysis.Analysis` (DESIGN.md §6): nothing here
computes the mechanism, and the computing modules never import this package or
matplotlib.

* :mod:`assur.views.report.tables` — seed-like tables as data; CSV and XLSX files;
* :mod:`assur.views.report.figures` — diagrams against the generalized coordinate;
* :mod:`assur.views.report.drawing` — drawings and animation of the mechanism;
* :mod:`assur.views.report.html` — one self-contained HTML file.

>>> import tempfile
>>> from pathlib import Path
>>> from assur import examples
>>> a = examples.hitch_003().analyze(examples.hitch_003_range())
>>> with tempfile.TemporaryDirectory() as d:
...     files = write_report(a, Path(d) / "hitch-report", formats=("csv",), lang="ru")
...     names = [p.name for p in files["csv"]]
>>> len(names) > 5, names[0]
(True, 'table_2_1.csv')
"""

from __future__ import annotations

from pathlib import Path

from .labels import check_lang
from .tables import Column, Table, seed_tables, table_filename, write_csv, write_xlsx

__all__ = ["write_report", "report_steps", "FORMATS", "DEFAULT_FORMATS", "seed_tables",
           "write_csv", "write_xlsx", "Table", "Column"]

#: every output format :func:`write_report` knows (``pdf``: printed from the HTML report
#: by Chromium, :mod:`assur.views.report.pdf`)
FORMATS = ("csv", "xlsx", "html", "png", "svg", "gif", "pdf")
#: the formats written unless others are asked for (the PDF needs a browser)
DEFAULT_FORMATS = FORMATS[:-1]


def report_steps(formats=DEFAULT_FORMATS, frames=30) -> list:
    """Names of the steps :func:`write_report` announces to ``progress``, in order
    (so a progress bar can know its length).

    Examples
    --------
    >>> from assur.views.report import report_steps
    >>> report_steps(("csv",))
    ['tables', 'csv']
    >>> report_steps()  # the default formats
    ['tables', 'csv', 'xlsx', 'figures', 'drawing', 'animation', 'html']
    >>> report_steps(("pdf",))  # printed from the report, without its animation
    ['tables', 'figures', 'drawing', 'pdf']
    >>> report_steps(("html",), frames=0)  # no animation
    ['tables', 'figures', 'drawing', 'html']
    """
    fm = set(formats)
    steps = ["tables"]
    if "csv" in fm:
        steps.append("csv")
    if "xlsx" in fm:
        steps.append("xlsx")
    if fm & {"png", "svg", "html", "pdf"}:
        steps += ["figures", "drawing"]
    if fm & {"gif", "html"} and frames > 0:
        steps.append("animation")
    if "html" in fm:
        steps.append("html")
    if "pdf" in fm:
        steps.append("pdf")
    return steps


def write_report(analysis, outdir, formats=DEFAULT_FORMATS, lang=None, progress=None,
                 design=None,
                 frames=30, positions=None, units=None, jobs=1) -> dict:
    """Write tables, diagrams, the drawing, the animation and the HTML report.

    Parameters
    ----------
    analysis : Analysis
        Result of :meth:`assur.Mechanism.analyze`.
    outdir : str or Path
        Output directory (created if missing).
    formats : iterable of str
        Any of :data:`FORMATS`: ``csv`` (``table_2_1.csv``…), ``xlsx``
        (``tables.xlsx``), ``png``/``svg`` (``fig_<name>.png``… and
        ``mechanism.png``), ``gif`` (``mechanism.gif``), ``html`` (``report.html``,
        self-contained).
    lang : {"en", "ru"}, optional
        Language of titles, labels, units and numbers (Russian: Russian unit symbols,
        the decimal comma, CSV files separated by ``;``); default: the model file's
        ``[display] lang``, else English.
    progress : callable, optional
        ``progress(step_name)`` is called as each step starts (see
        :func:`report_steps`).
    design : int, optional
        Design of a batch to report.
    frames : int
        Frames of the animation over the range, at most (0: no animation: neither the
        GIF nor the HTML report's).
    positions : sequence of int, optional
        Indices of the positions drawn (default: the first and the last).
    units : str or DisplayUnits, optional
        The display units of every table, file, figure and text: ``"file"`` (each
        kind of quantity in the unit the model file writes it in), ``"engineering"``,
        ``"si"`` or ``"imperial"`` (:mod:`assur.core.display`); default: the model
        file's ``[display] units``, else ``"file"``.
    jobs : int
        Processes that render the figures (on Linux forked from this one, each
        rendering some of them; 0: one per core; elsewhere this process renders them).
        ``assur analyze`` uses every core; 1 (the default here) this process alone.

    Returns
    -------
    dict of str to list of Path
        Files written, by format.

    Examples
    --------
    >>> import tempfile
    >>> from assur import examples
    >>> from assur.views.report import write_report
    >>> a = examples.hitch_003().analyze(examples.hitch_003_range())
    >>> steps = []
    >>> with tempfile.TemporaryDirectory() as d:
    ...     files = write_report(a, d, formats=("csv", "xlsx"), progress=steps.append)
    ...     sizes = [p.stat().st_size > 0 for p in files["csv"] + files["xlsx"]]
    >>> steps
    ['tables', 'csv', 'xlsx']
    >>> [p.name for p in files["csv"]][:3], files["xlsx"][0].name, all(sizes)
    (['table_2_1.csv', 'table_2_2.csv', 'table_3_1.csv'], 'tables.xlsx', True)
    >>> write_report(a, "unused", formats=("doc",))
    Traceback (most recent call last):
    ...
    ValueError: formats must be among: ['csv', 'xlsx', 'html', 'png', 'svg', 'gif', 'pdf']; got ['doc']
    """
    from . import drawing as _drawing
    from . import figures as _figures
    from . import html as _html

    from ...core.display import unit_system

    mech = analysis.mechanism
    lang = check_lang(lang or mech.display.get("lang") or "en")
    du = unit_system(mech, units)
    formats = tuple(formats)
    bad = [f for f in formats if f not in FORMATS]
    if bad:
        raise ValueError(f"formats must be among: {list(FORMATS)}; got {bad}")
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    written = {f: [] for f in formats}

    def step(name):
        if progress is not None:
            progress(name)

    step("tables")
    tables = seed_tables(analysis, lang, design=design, units=du)
    if "csv" in formats:
        step("csv")
        written["csv"] = [write_csv(tab, out / table_filename(tab), lang) for tab in tables]
    if "xlsx" in formats:
        step("xlsx")
        written["xlsx"] = [write_xlsx(tables, out / "tables.xlsx", lang=lang,
                                      inputs=_html.model_inputs(analysis, lang, du))]
    pngs, drawing_png = {}, None
    if {"png", "svg", "html", "pdf"} & set(formats):
        step("figures")
        figs = _figure_set(analysis, lang, design, du)
        svg_dir = out if "svg" in formats else None
        for name, png, caption, svg in _render_figures(figs, svg_dir, jobs):
            pngs[name] = (png, caption)
            if "png" in formats:
                p = out / f"fig_{name}.png"
                p.write_bytes(png)
                written["png"].append(p)
            if svg is not None:
                written["svg"].append(svg)
        step("drawing")
        fig = _drawing.draw(analysis, positions=positions, lang=lang, design=design, units=du)
        drawing_png = _figures.to_png_bytes(fig)
        if "png" in formats:
            p = out / "mechanism.png"
            p.write_bytes(drawing_png)
            written["png"].append(p)
        if "svg" in formats:
            fig.set_layout_engine("none")  # laid out for the PNG
            written["svg"].append(_figures.save(fig, out / "mechanism.svg"))
    anim = False
    if "gif" in formats and frames <= 0:
        raise ValueError(f"frames = {frames}: the GIF animation needs at least one frame")
    if {"gif", "html"} & set(formats) and frames > 0:
        step("animation")
        if "gif" in formats:  # raster frames only for the GIF; the HTML plays vectors
            imgs = _drawing.render_frames(analysis, frames=frames, lang=lang, design=design,
                                          units=du)
            written["gif"] = [_drawing.write_gif(imgs, out / "mechanism.gif")]
        if "html" in formats:
            anim = _drawing.animation(analysis, frames=frames, lang=lang, design=design,
                                      units=du)
    if "html" in formats:
        step("html")
        written["html"] = [_html.write_html(analysis, out / "report.html", lang=lang,
                                            figures=pngs, tables=tables, drawing=drawing_png,
                                            animation=anim, design=design, units=du)]
    if "pdf" in formats:
        step("pdf")
        from .pdf import write_pdf
        if "html" in formats:
            written["pdf"] = [write_pdf(written["html"][0], out / "report.pdf")]
        else:  # printed from the HTML report (no animation is printed)
            import tempfile
            with tempfile.TemporaryDirectory() as tmp:
                page = _html.write_html(analysis, Path(tmp) / "report.html", lang=lang,
                                        figures=pngs, tables=tables, drawing=drawing_png,
                                        animation=False, design=design, units=du)
                written["pdf"] = [write_pdf(page, out / "report.pdf")]
    return written


def _figure_set(analysis, lang, design, du) -> dict:
    """Every diagram of the report, ``{name: Figure}`` in its order: the analysis'
    (:func:`assur.views.report.figures.figures`), the crank dynamics', the lift test's."""
    from . import figures as _figures
    figs = dict(_figures.figures(analysis, lang, design=design, units=du))
    if getattr(analysis, "dynamics", None) is not None:  # crank dynamics (lab 3)
        from . import dynamics as _dynamics
        figs.update(_dynamics.figures(analysis.dynamics, lang, flywheel=analysis.flywheel,
                                      balancing=analysis.balancing, units=du))
    if getattr(analysis, "lift_test", None) is not None:  # ISO 789-2 lift test
        from .lift import lift_test_figure
        figs["lift_test"] = lift_test_figure(analysis, lang, units=du)
    return figs


def _render_one(figs, name, svg_dir):
    """``(name, PNG bytes, caption, SVG path or None)`` of one figure."""
    from . import figures as _figures
    fig = figs[name]
    # a figure of maps (two coordinates) has its title above the panels
    caption = fig.get_suptitle() or (fig.axes[0].get_title() if fig.axes else name)
    png = _figures.to_png_bytes(fig)
    svg = None
    if svg_dir is not None:
        fig.set_layout_engine("none")  # laid out for the PNG: the SVG keeps its places
        svg = _figures.save(fig, Path(svg_dir) / f"fig_{name}.svg")
    return name, png, caption, svg


#: what the forked renderers read: the parent's figures (inherited, not pickled)
_JOB: dict = {}


def _render_part(names):
    return [_render_one(_JOB["figs"], n, _JOB["svg"]) for n in names]


def _render_figures(figs, svg_dir, jobs=1) -> list:
    """Every figure of ``figs`` rendered (:func:`_render_one`), in order; with ``jobs``
    > 1 (0: a process per core) by that many processes forked from this one, each
    rendering a share of them (balanced by their panels), on Linux (where forking is
    the processes' own way to start; elsewhere in this process)."""
    import multiprocessing as mp
    import os
    import sys

    names = list(figs)
    jobs = (os.cpu_count() or 1) if jobs == 0 else int(jobs)
    jobs = min(jobs, len(names))
    if jobs <= 1 or not sys.platform.startswith("linux"):
        return [_render_one(figs, n, svg_dir) for n in names]
    parts, load = [[] for _ in range(jobs)], [0] * jobs
    for n in sorted(names, key=lambda n: -len(figs[n].axes)):
        k = load.index(min(load))
        parts[k].append(n)
        load[k] += len(figs[n].axes) + 1
    _JOB.update(figs=figs, svg=svg_dir)
    try:
        with mp.get_context("fork").Pool(jobs) as pool:
            done = {r[0]: r for part in pool.map(_render_part, parts) for r in part}
    finally:
        _JOB.clear()
    return [done[n] for n in names]
