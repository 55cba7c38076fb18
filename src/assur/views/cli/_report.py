"""The commands of a model's worksheet: ``assur check``, ``assur analyze``,
``assur tables``, ``assur demo`` (:mod:`assur.views.cli`)."""

from __future__ import annotations

import time
from pathlib import Path

import typer
from rich.table import Table

from ._common import (DEFAULT_FORMATS, LANG_HELP, UNITS_HELP, _assemble, _check_lang, _fail,
                      _formats, _lang, _load, _ok, _output_dir, _positions, _shape_text,
                      _summary, _units, console)
from ._types import COUNT, Count, Numbers


def check(file: Path = typer.Argument(..., help="Model file (TOML)."),
          units: str = typer.Option("", "--units", help=UNITS_HELP)):
    """Validate a model file, solve its conditions and assemble it over its range."""
    from ...core.display import parameter_units
    from ..report.numbers import quantity
    from ..report.values import solved_line

    t0 = time.perf_counter()
    model = _load(file)
    du = _units(model, units)
    _assemble(model)
    m = model.mechanism
    tab = Table(title=f"{m.title}", show_header=True, header_style="bold")
    tab.add_column("item")
    tab.add_column("value")
    tab.add_row("groups", str(len(m.groups)))
    tab.add_row("links", ", ".join(l.name for l in m.links))
    if m.distances:
        tab.add_row("distances", ", ".join(d.name + (f" (angle {d.angle})" if d.angle else "")
                                           for d in m.distances))
    rng = model.range
    for j, c in enumerate(m.coordinates):
        col = rng if rng.ndim == 1 else model.ranges[c]  # its own values, not the grid
        kind = "angle" if m.coordinate_kind(c) == "angle" else "length"

        def q(v):
            return quantity(float(v), kind, du, "en", 6)

        if kind == "angle":
            tab.add_row(f"range of {c}", f"{q(col[0])} … {q(col[-1])} ({col.size} "
                                         f"positions, {q(col.min())} … {q(col.max())})")
        else:
            tab.add_row(f"range of {c}", f"{q(col.min())} … {q(col.max())} ({col.size} "
                                         f"positions)")
    if len(m.coordinates) > 1:  # the grid's shape, or paired paths
        tab.add_row("positions", _shape_text(model))
    for mo in m.motions:
        tab.add_row(f"motion of {mo.coordinate}", mo.describe())
    for s in model.solved:
        tab.add_row(f"solved {s.condition.unknown}",
                    solved_line(s, m, "en", parameter_units(m, du), du))
    console.print(tab)
    _ok(f"{file} assembles at every position ({time.perf_counter() - t0:.2f} s)")


def _run_report(model, output: str, lang: str, fmts, draw_at=None, frames=30, units="",
                jobs=0):
    from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

    from ...errors import AssemblyError, ModelError, SingularPositionError
    from ..report import report_steps, write_report
    from ..report.pdf import PdfError

    du = _units(model, units)
    lang = _lang(model, lang)
    analysis = _assemble(model)
    positions = _positions(analysis, draw_at, du)
    out = _output_dir(output)
    # redrawn at each step, not by rich's refresh thread: the report forks its figures'
    # renderers only from a process with no other thread (report.forkable)
    with Progress(SpinnerColumn(), TextColumn("{task.description}", markup=False,
                                              style="progress.description"),
                  BarColumn(), TimeElapsedColumn(), console=console, transient=True,
                  auto_refresh=False) as prog:
        task = prog.add_task("writing the report", total=len(report_steps(fmts, frames)))
        prog.refresh()

        def step(name):
            prog.update(task, description=f"writing: {name}", advance=1, refresh=True)

        try:
            files = write_report(analysis, out, formats=fmts, lang=lang, progress=step,
                                 positions=positions, frames=frames, units=du, jobs=jobs)
        except OSError as e:  # disk full, permissions changed: one message, no traceback
            _fail(f"{output}: cannot write the report: {e.strerror or e}")
        except PdfError as e:  # Chromium failed or timed out printing the report
            _fail(f"{output}: {e}")
        except (AssemblyError, ModelError, SingularPositionError) as e:
            _fail(f"{model.source}: {e}")
    return analysis, files


def analyze(file: Path = typer.Argument(..., help="Model file (TOML)."),
            output: str = typer.Option("assur-report", "-o", "--output",
                                       help="Output directory."),
            lang: str = typer.Option("", "--lang", help=LANG_HELP),
            units: str = typer.Option("", "--units", help=UNITS_HELP),
            format: str = typer.Option(",".join(DEFAULT_FORMATS), "--format",
                                       help="Comma-separated: csv,xlsx,html,png,svg,gif,pdf "
                                            "(pdf: the HTML report printed on A4 by "
                                            "Chromium, which must be installed)."),
            draw_at: str = typer.Option("", "--draw-at", parser=Numbers(),
                                        help="Coordinate values to draw the mechanism at, "
                                             "in the units shown (--units): cylinder "
                                             "lengths (0.42,0.55 in m), crank angles "
                                             "(14.679,188.229 in degrees); default: first "
                                             "and last."),
            frames: int = typer.Option(30, "--frames", parser=Count(0),
                                       help="Frames of the mechanism's animation (GIF, "
                                            "HTML report), at most; 0: no animation. "
                                            "A whole number ≥ 0."),
            jobs: int = typer.Option(0, "--jobs", parser=Count(0),
                                     help="Processes rendering the figures; 0: one per "
                                          "core. A whole number ≥ 0.")):
    """Analyze a model over its range and write tables, figures and the HTML report."""
    if lang:
        _check_lang(lang)
    fmts = _formats(format)
    if frames == 0 and "gif" in fmts:
        _fail("--frames 0 writes no animation: leave gif out of --format")
    if "pdf" in fmts:  # a missing browser fails before the analysis, not after
        from ..report.pdf import PdfError, find_chromium
        try:
            find_chromium()
        except PdfError as e:
            _fail(str(e))
    model = _load(file)
    _, files = _run_report(model, output, lang, fmts, draw_at, frames, units, jobs)
    _summary(files, output)


def tables(file: Path = typer.Argument(..., help="Model file (TOML)."),
           table: str = typer.Option("", "--table", help="Only these tables, e.g. 2.1,4.1."),
           lang: str = typer.Option("", "--lang", help=LANG_HELP),
           units: str = typer.Option("", "--units", help=UNITS_HELP),
           columns: int = typer.Option(6, "--columns", parser=COUNT,
                                       help="Columns per printed block (≥ 1).")):
    """Print the seed-like tables of a model in the terminal."""
    import numpy as np

    from ..report.labels import unit as unit_label
    from ..report.numbers import decimals, number
    from ..report.tables import seed_tables

    if lang:
        _check_lang(lang)
    model = _load(file)
    du = _units(model, units)
    lang = _lang(model, lang)
    analysis = _assemble(model)
    tabs = seed_tables(analysis, lang=lang, units=du)
    wanted = [t.strip() for t in table.split(",") if t.strip()]
    known = [t.id for t in tabs]
    bad = [w for w in wanted if w not in known]
    if bad:
        _fail(f"--table {bad}: this model has tables {known}")
    for t in tabs:
        if wanted and t.id not in wanted:
            continue
        first, rest = t.columns[0], t.columns[1:]
        for k in range(0, max(len(rest), 1), columns):
            part = [first] + list(rest[k:k + columns])
            rt = Table(title=f"{t.label} — {t.title(lang)}" if k == 0 else None,
                       header_style="bold", title_justify="left")
            for c in part:
                rt.add_column(f"{c.symbol} [{unit_label(c.unit, lang)}]", justify="right",
                              no_wrap=True, overflow="fold")
            n = len(np.atleast_1d(first.values))
            digits = [decimals(c.values) for c in part]  # one count of decimals per column
            for i in range(n):
                rt.add_row(*[number(np.atleast_1d(c.values)[i], d, lang)
                             for c, d in zip(part, digits)])
            console.print(rt)


def demo(output: str = typer.Option("assur-demo", "-o", "--output"),
         lang: str = typer.Option("", "--lang", help=LANG_HELP),
         units: str = typer.Option("", "--units", help=UNITS_HELP)):
    """Analyze the bundled seed-003 hitch into ./assur-demo/."""
    from ...io import bundled

    if lang:
        _check_lang(lang)
    model = _load(bundled("hitch_003"))
    _, files = _run_report(model, output, lang, DEFAULT_FORMATS, units=units)
    _summary(files, output)
