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

#: names this package re-exports from :mod:`assur.views.report.tables`, imported when
#: first asked for (``assur check`` formats numbers with :mod:`.numbers` and need not
#: import the tables' builders)
_FROM_TABLES = ("Column", "Table", "seed_tables", "table_filename", "write_csv",
                "write_xlsx")


def __getattr__(name):
    if name in _FROM_TABLES:
        from . import tables
        return getattr(tables, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

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
    from . import html as _html  # no matplotlib: the tables' inputs and the page
    from ...core.display import unit_system
    from .tables import seed_tables, table_filename, write_csv, write_xlsx

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
    pngs, drawing_png, anim = {}, None, False
    if "gif" in formats and frames <= 0:
        raise ValueError(f"frames = {frames}: the GIF animation needs at least one frame")
    figured = bool({"png", "svg", "html", "pdf"} & set(formats))
    gif = "gif" in formats
    if figured or gif or "html" in formats:  # matplotlib only for figures (not CSV, XLSX)
        from . import drawing as _drawing
    # what the renderers make — each figure built and drawn by the renderer that takes
    # it (the builders run in parallel too): the diagrams, the drawing, the GIF's frames
    jobs_ = (_figure_jobs(analysis) + [("drawing", None)]) if figured else []
    if gif:
        jobs_.insert(0, ("gif", None))  # the longest job of a small machine: first
    render = _Renderers(jobs_, dict(analysis=analysis, lang=lang, design=design, units=du,
                                    positions=positions), out, formats, dict(
        analysis=analysis, frames=frames, lang=lang, design=design, units=du), jobs)
    animate = "html" in formats and frames > 0
    with render:
        if "xlsx" in formats:  # while the renderers draw
            step("xlsx")
            written["xlsx"] = [write_xlsx(tables, out / "tables.xlsx", lang=lang,
                                          inputs=_html.model_inputs(analysis, lang, du))]
        if animate and render.pool is not None:  # the HTML's vector frames, meanwhile too
            anim = _drawing.animation(analysis, frames=frames, lang=lang, design=design,
                                      units=du)
        if figured:
            step("figures")
            for job in jobs_:
                if job[0] in ("gif", "drawing"):
                    continue
                for name, png, caption, svg in render.result(job):
                    pngs[name] = (png, caption)
                    if "png" in formats:
                        p = out / f"fig_{name}.png"
                        p.write_bytes(png)
                        written["png"].append(p)
                    if svg is not None:
                        written["svg"].append(svg)
            step("drawing")
            ((_, drawing_png, _, svg),) = render.result(("drawing", None))
            if "png" in formats:
                p = out / "mechanism.png"
                p.write_bytes(drawing_png)
                written["png"].append(p)
            if svg is not None:
                written["svg"].append(svg)
        if {"gif", "html"} & set(formats) and frames > 0:
            step("animation")
            if gif:  # raster frames only for the GIF; the HTML plays vectors
                written["gif"] = [render.result(("gif", None))]
            if animate and anim is False:  # made here when no renderer runs beside
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


def _figure_jobs(analysis) -> list:
    """The report's diagrams as the renderers' jobs, in the report's order: each of
    :data:`assur.views.report.figures.FIGURES`, then the crank dynamics', the lift
    test's and the ratings' (each job builds its figures, :func:`_build`)."""
    from .figures import FIGURES
    jobs = [("figure", n) for n in FIGURES]
    if getattr(analysis, "dynamics", None) is not None:  # crank dynamics (lab 3)
        jobs.append(("dynamics", None))
    if getattr(analysis, "lift_test", None) is not None:  # ISO 789-2 lift test
        jobs.append(("lift_test", None))
    if getattr(analysis, "ratings", None):  # [[rating]]: views/report/ratings.py
        jobs.append(("ratings", None))
    return jobs


def _build(job, analysis, lang, design, units, positions) -> dict:
    """The figures of one job, ``{name: Figure}`` (none for a diagram with nothing to
    draw for this machine): a diagram (:func:`assur.views.report.figures.figures`),
    the crank dynamics', the lift test's, the ratings' or the mechanism's drawing."""
    kind, name = job
    if kind == "figure":
        from .figures import figures
        return figures(analysis, lang, design=design, names=[name], units=units)
    if kind == "dynamics":
        from .dynamics import figures
        return dict(figures(analysis.dynamics, lang, flywheel=analysis.flywheel,
                            balancing=analysis.balancing, units=units))
    if kind == "lift_test":
        from .lift import lift_test_figure
        return {"lift_test": lift_test_figure(analysis, lang, units=units)}
    if kind == "ratings":
        from .ratings import rating_figures
        return dict(rating_figures(analysis, lang, units=units))
    if kind == "drawing":
        from .drawing import draw
        return {"drawing": draw(analysis, positions=positions, lang=lang, design=design,
                                units=units)}
    raise ValueError(f"unknown report job {job!r}")


def _render(job, build, out, formats, anim):
    """What one renderer makes of ``job``: for a figure job ``[(name, PNG bytes,
    caption, SVG path or None), …]`` in its order (the drawing's files are
    ``mechanism.*``); the GIF's path."""
    from . import figures as _figures
    kind, _ = job
    if kind == "gif":
        from . import drawing as _drawing
        imgs = _drawing.render_frames(**anim)
        return _drawing.write_gif(imgs, out / "mechanism.gif")
    made = []
    for name, fig in _build(job, **build).items():
        # a figure of maps (two coordinates) has its title above the panels
        caption = fig.get_suptitle() or (fig.axes[0].get_title() if fig.axes else name)
        png = _figures.to_png_bytes(fig)
        svg = None
        if "svg" in formats:
            fig.set_layout_engine("none")  # laid out for the PNG: the SVG keeps its places
            svg = _figures.save(fig, out / ("mechanism.svg" if kind == "drawing"
                                            else f"fig_{name}.svg"))
        made.append((name, png, caption, svg))
    return made


def forkable() -> bool:
    """Whether this process may fork its figures' renderers: on Linux (where forking is
    the processes' own way to start), and only while no other thread runs in it — a
    forked child gets a copy of every lock, held ones too, but not the threads that
    would release them.

    Examples
    --------
    >>> import threading
    >>> from assur.views.report import forkable
    >>> stop = threading.Event()
    >>> t = threading.Thread(target=stop.wait); t.start()
    >>> forkable()                        # another thread alive: rendered here
    False
    >>> stop.set(); t.join()
    """
    import sys
    import threading
    return sys.platform.startswith("linux") and threading.active_count() == 1


#: what the forked renderers read: the parent's analysis (inherited, not pickled)
_JOB: dict = {}


def _render_forked(i):
    """Job ``i`` of the renderers' list (an index is sent, not the job)."""
    args = dict(_JOB)
    return _render(args.pop("jobs")[i], **args)


class _Renderers:
    """The figures, the drawing and the GIF rendered while the report's other steps
    run: with ``jobs`` > 1 (0: a process per core) by that many processes forked from
    this one on Linux (where forking is the processes' own way to start; each job
    inherits the figures, nothing is pickled but the files' bytes), the longest jobs
    first, each taken by the first renderer free; else here, as each is asked for.

    Only a process with no other thread is forked (:func:`forkable`): a fork copies the
    locks the other threads hold at that instant — an import half done, a kernel
    compiling in the background, a page's server writing — and a renderer that takes
    one of them waits forever. With other threads alive (a page's server), the
    figures are rendered here, one after another. A renderer that dies (killed, out of
    memory) leaves its jobs to this process: the report is whole either way, and never
    waits for an answer that cannot come."""

    def __init__(self, jobs_, build, out, formats, anim, jobs=1):
        import os
        self.jobs_, self.done, self.pool, self.pending = list(jobs_), {}, None, {}
        self.args = dict(build=build, out=out, formats=formats, anim=anim)
        n = (os.cpu_count() or 1) if jobs == 0 else int(jobs)
        self.n = min(n, len(self.jobs_)) if forkable() else 1

    def __enter__(self):
        if self.n > 1:
            import multiprocessing as mp
            from concurrent.futures import ProcessPoolExecutor
            _JOB.update(self.args, jobs=self.jobs_)
            # every renderer forked here, at once, before the pool's own thread starts
            self.pool = ProcessPoolExecutor(self.n, mp_context=mp.get_context("fork"))
            # in the list's order (the GIF first), each taken by the first renderer free
            self.pending = {job: self.pool.submit(_render_forked, i)
                            for i, job in enumerate(self.jobs_)}
        return self

    def result(self, job):
        """What ``job`` made (waiting for it)."""
        if job not in self.done:
            if job in self.pending:
                from concurrent.futures.process import BrokenProcessPool
                try:
                    self.done[job] = self.pending[job].result()
                except BrokenProcessPool:  # its renderer died: made here instead
                    import logging
                    logging.getLogger("assur.report").warning(
                        "a figure renderer ended without its result; %s %s drawn in "
                        "this process", *job)
                    self.done[job] = _render(job, **self.args)
            else:
                self.done[job] = _render(job, **self.args)
        return self.done[job]

    def __exit__(self, *exc):
        if self.pool is not None:
            # a job failed (its error is raised): the jobs not begun are dropped
            self.pool.shutdown(wait=True, cancel_futures=exc[0] is not None)
            _JOB.clear()
        return False
