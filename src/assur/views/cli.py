"""Command-line interface: ``assur check``, ``assur analyze``, ``assur tables``,
``assur fit``, ``assur simulate``, ``assur cycles``, ``assur sweep``, ``assur optimize``,
``assur tolerance``, ``assur serve``, ``assur dxf``, ``assur demo``.

Every failure a user can cause (a malformed file, a design that cannot assemble,
a condition without a root, an input that is not a regular file, an output
directory that cannot be written) prints one clear message and exits with status
1 (2 for usage errors, as typer does) — never a traceback.

User text (names, titles, paths, option values, messages quoting them) is printed
literally: the consoles interpret no markup and no emoji codes, and styles are
applied with :class:`rich.text.Text` spans only.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import typer
from rich.console import Console
from rich.table import Table
from rich.text import Text

__all__ = ["app", "main"]

app = typer.Typer(add_completion=False, no_args_is_help=True, rich_markup_mode=None,
                  help="Hydraulic-cylinder driven planar linkages solved by Assur groups.")
# markup=False, emoji=False: "[/x]" in a title or ":100:" in a message stay as written
console = Console(stderr=False, markup=False, emoji=False, highlight=False)
err = Console(stderr=True, markup=False, emoji=False, highlight=False)
LANGS = ("ru", "en")

FORMATS = ("csv", "xlsx", "html", "png", "svg", "gif")  # = assur.views.report.FORMATS


def _version(value: bool):
    if value:
        from .. import __version__
        console.print(f"assur {__version__}")
        raise typer.Exit()


@app.callback()
def _main(version: bool = typer.Option(False, "--version", callback=_version, is_eager=True,
                                       help="Print the version and exit.")):
    """Hydraulic-cylinder driven planar linkages solved by Assur groups."""


def _fail(message: str, code: int = 1):
    err.print(Text.assemble(("error:", "bold red"), " ", str(message)), soft_wrap=True)
    raise typer.Exit(code)


def _ok(message: str):
    console.print(Text.assemble(("ok", "green"), ": ", message))


def _check_lang(lang: str):
    if lang not in LANGS:
        _fail(f"--lang must be one of: {list(LANGS)}; got {lang!r}")


def _load(path: Path):
    """Load and solve a model file; user errors become one message and exit 1."""
    from ..errors import AssemblyError, ModelError
    from ..io import load

    try:
        model = load(path)
    except FileNotFoundError:
        _fail(f"{path}: no such file")
    except (ModelError, AssemblyError) as e:
        _fail(str(e))
    for w in model.warnings:  # parameters nothing uses: file, line, key
        err.print(Text.assemble(("warning:", "bold yellow"), " ", w), soft_wrap=True)
    return model


def _output_dir(output: str) -> Path:
    """The output directory ``output``, created; refused with one message when it is
    empty, a file, under a file, or cannot be created or written."""
    import os

    if not output.strip():
        _fail("-o/--output must name a directory; got an empty string", 2)
    out = Path(output)
    if out.exists() and not out.is_dir():
        _fail(f"{output}: exists and is not a directory; expected an output directory")
    try:
        out.mkdir(parents=True, exist_ok=True)
    except (OSError, ValueError) as e:  # under a file, permissions, name too long
        why = e.strerror if isinstance(e, OSError) and e.strerror else str(e)
        _fail(f"{output}: cannot create the output directory: {why}")
    if not os.access(out, os.W_OK | os.X_OK):
        _fail(f"{output}: the output directory is not writable")
    return out


def _assemble(model):
    from ..errors import AssemblyError, ModelError, SingularPositionError

    try:
        return model.analyze()
    except (AssemblyError, ModelError, SingularPositionError) as e:
        _fail(f"{model.source}: {e}")


def _shape_text(model) -> str:
    """'grid S × S1: 13 × 8 = 104 positions' or 'paired paths S, S1: 9 positions'."""
    cs = list(model.mechanism.coordinates)
    if model.paired:
        return f"paired paths {', '.join(cs)}: {len(model.range)} positions"
    shape = model.shape
    return (f"grid {' × '.join(cs)}: {' × '.join(str(n) for n in shape)} = "
            f"{len(model.range)} positions")


@app.command()
def check(file: Path = typer.Argument(..., help="Model file (TOML).")):
    """Validate a model file, solve its conditions and assemble it over its range."""
    import numpy as np

    from .report.values import solved_line

    t0 = time.perf_counter()
    model = _load(file)
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
        if m.coordinate_kind(c) == "angle":
            deg = np.degrees(col)
            tab.add_row(f"range of {c}", f"{deg[0]:.6g}° … {deg[-1]:.6g}° ({col.size} "
                                         f"positions, {deg.min():.6g}° … {deg.max():.6g}°)")
        else:
            tab.add_row(f"range of {c}", f"{col.min():.6g} … {col.max():.6g} m ({col.size} "
                                         f"positions)")
    if len(m.coordinates) > 1:  # the grid's shape, or paired paths
        tab.add_row("positions", _shape_text(model))
    for mo in m.motions:
        tab.add_row(f"motion of {mo.coordinate}", mo.describe())
    for s in model.solved:
        tab.add_row(f"solved {s.condition.unknown}", solved_line(s, m, "en"))
    console.print(tab)
    _ok(f"{file} assembles at every position ({time.perf_counter() - t0:.2f} s)")


def _formats(value: str):
    fmts = tuple(f.strip().lower() for f in value.split(",") if f.strip())
    bad = [f for f in fmts if f not in FORMATS]
    if bad or not fmts:
        _fail(f"--format must be a comma-separated subset of {', '.join(FORMATS)}; got {value!r}")
    return fmts


def _positions(analysis, draw_at):
    """Indices of the positions nearest to the coordinate values ``draw_at`` (one
    coordinate; e.g. "0.42,0.67" [m] for a cylinder, "14.679,188.229" [°] for a
    crank). A crank angle matches its positions modulo 360° (188.229 finds the
    position written −171.771)."""
    if not draw_at:
        return None
    kin = analysis.kinematics
    if kin.k != 1 or len(kin.shape) != 1:
        _fail("--draw-at needs a model with one coordinate and one design")
    import numpy as np
    angle = analysis.mechanism.coordinate_kind(kin.coordinates[0]) == "angle"
    unit = "°" if angle else "m"
    try:
        values = [float(v.strip().removesuffix("°").removesuffix("deg").strip() if angle
                        else v) for v in draw_at.split(",") if v.strip()]
    except ValueError:
        _fail(f"--draw-at must be comma-separated numbers ({'degrees' if angle else 'm'}), "
              f"got {draw_at!r}")
    if not values:
        _fail(f"--draw-at must name at least one position, got {draw_at!r}")
    q = np.degrees(kin.q()) if angle else kin.q()
    lo, hi = float(q.min()), float(q.max())
    if not angle:
        bad = [v for v in values if not lo <= v <= hi]
        if bad:
            _fail(f"--draw-at {bad} is outside the range {lo:.6g} … {hi:.6g} m")
        return [int(abs(q - v).argmin()) for v in values]
    # crank angles: the nearest position on the circle; a value farther from every
    # position than the largest step between neighbouring positions is not in the range
    step = float(np.max(np.abs(np.diff(q)))) if q.size > 1 else 0.0
    out, bad = [], []
    for v in values:
        d = np.abs((q - v + 180.0) % 360.0 - 180.0)
        i = int(d.argmin())
        if d[i] > max(step, 1e-9):
            bad.append(v)
        out.append(i)
    if bad:
        _fail(f"--draw-at {bad} [{unit}] is outside the positions of "
              f"{kin.coordinates[0]}: {lo:.6g}° … {hi:.6g}° ({q.size} positions)")
    return out


def _run_report(model, output: str, lang: str, fmts, draw_at=None):
    from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

    from ..errors import AssemblyError, ModelError, SingularPositionError
    from .report import report_steps, write_report

    analysis = _assemble(model)
    positions = _positions(analysis, draw_at)
    out = _output_dir(output)
    with Progress(SpinnerColumn(), TextColumn("{task.description}", markup=False,
                                              style="progress.description"),
                  BarColumn(), TimeElapsedColumn(), console=console, transient=True) as prog:
        task = prog.add_task("writing the report", total=len(report_steps(fmts)))

        def step(name):
            prog.update(task, description=f"writing: {name}", advance=1)

        try:
            files = write_report(analysis, out, formats=fmts, lang=lang, progress=step,
                                 positions=positions)
        except OSError as e:  # disk full, permissions changed: one message, no traceback
            _fail(f"{output}: cannot write the report: {e.strerror or e}")
        except (AssemblyError, ModelError, SingularPositionError) as e:
            _fail(f"{model.source}: {e}")
    return analysis, files


@app.command()
def analyze(file: Path = typer.Argument(..., help="Model file (TOML)."),
            output: str = typer.Option("assur-report", "-o", "--output",
                                       help="Output directory."),
            lang: str = typer.Option("en", "--lang", help="Labels: ru or en."),
            format: str = typer.Option(",".join(FORMATS), "--format",
                                       help="Comma-separated: csv,xlsx,html,png,svg,gif."),
            draw_at: str = typer.Option("", "--draw-at",
                                        help="Coordinate values to draw the mechanism at: "
                                             "cylinder lengths in m (0.42,0.55), crank "
                                             "angles in degrees (14.679,188.229); default: "
                                             "first and last.")):
    """Analyze a model over its range and write tables, figures and the HTML report."""
    _check_lang(lang)
    fmts = _formats(format)
    model = _load(file)
    _, files = _run_report(model, output, lang, fmts, draw_at)
    _summary(files, output)


def _summary(files, output: str):
    n = sum(len(v) for v in files.values())
    console.print(Text.assemble((f"wrote {n} files", "green"), f" to {output}/"))
    html = [p for p in files.get("html", [])]
    if html:
        console.print(f"report: {Path(html[0]).resolve()}")


@app.command()
def tables(file: Path = typer.Argument(..., help="Model file (TOML)."),
           table: str = typer.Option("", "--table", help="Only these tables, e.g. 2.1,4.1."),
           lang: str = typer.Option("en", "--lang", help="Titles: ru or en."),
           columns: int = typer.Option(6, "--columns", help="Columns per printed block.")):
    """Print the seed-like tables of a model in the terminal."""
    import numpy as np

    from .report.tables import seed_tables

    _check_lang(lang)
    model = _load(file)
    analysis = _assemble(model)
    tabs = seed_tables(analysis, lang=lang)
    wanted = [t.strip() for t in table.split(",") if t.strip()]
    known = [t.id for t in tabs]
    bad = [w for w in wanted if w not in known]
    if bad:
        _fail(f"--table {bad}: this model has tables {known}")
    for t in tabs:
        if wanted and t.id not in wanted:
            continue
        first, rest = t.columns[0], t.columns[1:]
        for k in range(0, max(len(rest), 1), max(columns, 1)):
            part = [first] + list(rest[k:k + columns])
            rt = Table(title=f"{t.id} — {t.title(lang)}" if k == 0 else None,
                       header_style="bold", title_justify="left")
            for c in part:
                rt.add_column(f"{c.symbol} [{c.unit}]", justify="right", no_wrap=True,
                              overflow="fold")
            n = len(np.atleast_1d(first.values))
            for i in range(n):
                rt.add_row(*[_fmt_cell(np.atleast_1d(c.values)[i]) for c in part])
            console.print(rt)


def _fmt_cell(v):
    import math
    if isinstance(v, (bool,)) or (hasattr(v, "dtype") and v.dtype == bool):
        return "yes" if v else "no"
    v = float(v)
    if math.isnan(v):
        return ""
    if math.isinf(v):
        return "∞" if v > 0 else "−∞"
    if 1e3 <= abs(v) < 1e10:
        out = f"{v:.0f}"  # forces, pressures: whole N, Pa as the seeds print them
    else:
        out = f"{v:.5g}"
    return out.lstrip("-") if float(out) == 0 else out  # never "-0"


@app.command()
def fit(file: Path = typer.Argument(..., help="Model file (TOML)."),
        table: Path = typer.Argument(..., help="The printed table (CSV): the coordinate, "
                                               "then columns 'expression [unit]'."),
        param: list[str] = typer.Option(..., "--fit", help="A parameter to fit and its "
                                        "bounds in SI: NAME=LOW:HIGH (repeat)."),
        screen: int = typer.Option(4096, "--screen", help="Designs screened."),
        starts: int = typer.Option(8, "--starts", help="Least-squares refinements."),
        outlier: float = typer.Option(20.0, "--outlier", help="Residual [tolerances] "
                                      "beyond which a value is an outlier.")):
    """Fit parameters of a model to a printed table (assur.synthesis.fitting): robust least
    squares at the precision each value is printed with; outliers are listed."""
    from ..errors import ModelError
    from ..synthesis.fitting import fit_parameters
    from ..io import read_targets

    model = _load(file)
    mech = model.mechanism
    bounds = {}
    for p in param:
        name, _, rng = p.partition("=")
        lo, _, hi = rng.partition(":")
        try:
            bounds[name.strip()] = (float(lo), float(hi))
        except ValueError:
            _fail(f"--fit {p}: expected NAME=LOW:HIGH (numbers in SI), e.g. L4=0.5:0.8")
    try:
        targets = read_targets(table, mech)
        res = fit_parameters(mech, bounds, targets, screen=screen, starts=starts,
                             outlier=outlier)
    except (ModelError, OSError) as e:
        _fail(str(e))
    rt = Table(title="fitted parameters", header_style="bold", title_justify="left")
    for h in ("parameter", "value [SI]", "bounds [SI]", "in the file's unit"):
        rt.add_column(h, justify="right")
    for n, v in res.params.items():
        u = mech.units.get(n)
        shown = f"{v / u.scale:.7g} {u.text}" if u is not None else ""
        rt.add_row(n, f"{v:.9g}", f"{bounds[n][0]:.6g} … {bounds[n][1]:.6g}", shown)
    console.print(rt)
    console.print(Text(f"largest residual besides the outliers: {res.max_residual():.3g} "
                       f"half-units of the last printed digit"))
    if res.outliers:
        ot = Table(title="outliers (printed values the fit does not follow)",
                   header_style="bold", title_justify="left")
        for h in ("column", mech.coordinates[0], "printed", "fitted"):
            ot.add_column(h, justify="right")
        for name, q, printed, fitted in res.outliers:
            ot.add_row(name, f"{q:.6g}", f"{printed:.6g}", f"{fitted:.6g}")
        console.print(ot)


@app.command()
def demo(output: str = typer.Option("assur-demo", "-o", "--output"),
         lang: str = typer.Option("en", "--lang")):
    """Analyze the bundled seed-003 hitch into ./assur-demo/."""
    from ..io import bundled

    _check_lang(lang)
    model = _load(bundled("hitch_003"))
    _, files = _run_report(model, output, lang, FORMATS)
    _summary(files, output)


@app.command()
def simulate(file: Path = typer.Argument(..., help="Model file (TOML) with [[drive]] and "
                                                   "[simulation]."),
             output: str = typer.Option("assur-simulation", "-o", "--output",
                                        help="Output directory."),
             lang: str = typer.Option("en", "--lang", help="Labels: ru or en."),
             duration: float = typer.Option(0.0, "--duration",
                                            help="Simulated time in s (default: the "
                                                 "file's [simulation] duration).")):
    """Simulate the hydraulic drive and the mechanism in time (seed 001 lab 6; seed
    004's crane, two cylinders through a flow divider): time series (CSV), figures
    (PNG), the mechanism's motion (GIF) and an HTML report."""
    from ..dynamics import simulate_model
    from ..errors import AssemblyError, ModelError
    from .report.simulation import write_simulation_report
    from ..texts import localize

    _check_lang(lang)
    model = _load(file)
    out = _output_dir(output)
    options = {"t_end": duration} if duration > 0 else {}
    try:
        result = simulate_model(model, **options)
    except (ModelError, AssemblyError, ValueError) as e:
        _fail(f"{file}: {e}")
    try:
        files = write_simulation_report(result, out, localize(model.mechanism.title, lang),
                                        lang, mechanism=model.mechanism)
    except OSError as e:
        _fail(f"{output}: cannot write the report: {e.strerror or e}")
    if not result.success:
        _fail(f"{file}: {result.message}")
    _ok(f"{result.message}; {result.nfev} right-hand-side evaluations; "
        f"energy residual {result.energy['residual']:.3g} J of {result.energy['pump']:.6g} J")
    by_format = {}
    for f in files:
        by_format.setdefault(f.suffix.lstrip("."), []).append(f)
    _summary(by_format, output)


@app.command()
def cycles(file: Path = typer.Argument(..., help="Model file (TOML) of two cylinder "
                                                 "coordinates with [[drive]]."),
           output: str = typer.Option("assur-cycles", "-o", "--output",
                                      help="Output directory."),
           lang: str = typer.Option("en", "--lang", help="Labels: ru or en.")):
    """Seed 004's work cycles: max cylinder forces with their static and dynamic parts
    for combined and separate motion, cycle times 4–20 s (CSV, XLSX, PNG) and an HTML
    report that sets them against the paper's conclusions."""
    from ..errors import AssemblyError, ModelError
    from .report.cycles import verdict_word, write_cycles_report

    _check_lang(lang)
    model = _load(file)
    out = _output_dir(output)
    try:
        _, verdicts, files = write_cycles_report(model, out, lang)
    except (ModelError, AssemblyError, ValueError) as e:
        _fail(f"{file}: {e}")
    except OSError as e:
        _fail(f"{output}: cannot write the report: {e.strerror or e}")
    for v in verdicts:
        console.print(Text.assemble((f"{verdict_word(v.agrees, lang)}: ",
                                     "green" if v.agrees else "yellow"), v.claim, " (", v.model,
                                    ")"), soft_wrap=True)
    by_format = {}
    for f in files:
        by_format.setdefault(f.suffix.lstrip("."), []).append(f)
    _summary(by_format, output)


# ---- synthesis (issue 12): assur sweep, assur optimize ---------------------------------
def _design_problem(file: Path, var, positions):
    """The design problem of a model file (+ --var); user errors exit 1."""
    from ..io import load_problem
    from ..errors import AssemblyError, ModelError

    _load(file)  # the file's own errors and warnings, as every command shows them
    try:
        return load_problem(file, variables=tuple(var), positions=positions)
    except (ModelError, AssemblyError) as e:
        _fail(str(e))


def _executor(scheduler, workers, chunk, progress):
    from ..synthesis.search.scale import Executor
    from ..errors import ModelError
    try:
        return Executor(scheduler=scheduler, workers=workers, chunk=chunk, progress=progress)
    except ModelError as e:
        _fail(str(e), 2)


_VAR = typer.Option([], "--var", help='A design variable: NAME=LOW:HIGH or NAME=±DELTA, units '
                                      'as in files (e.g. "L4=0.6 m:0.72 m", "X01=±30 mm"); '
                                      'repeat. Adds to (or replaces) the file\'s [design].')
_WORKERS = typer.Option(2, "--workers", help="Worker processes of a Dask LocalCluster "
                                             "(0: in this process).")
_SCHED = typer.Option(None, "--scheduler", help="An existing Dask scheduler, "
                                                "e.g. tcp://host:8786 (instead of --workers).")


def _bar():
    from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn
    return Progress(SpinnerColumn(), TextColumn("{task.description}", markup=False), BarColumn(),
                    TextColumn("{task.completed}/{task.total}"), TimeElapsedColumn(),
                    console=err, transient=True)


@app.command()
def sweep(file: Path = typer.Argument(..., help="Model file (TOML) with [design] or --var."),
          samples: int = typer.Option(10000, "--samples", help="Designs drawn uniformly "
                                      "within the bounds."),
          seed: int = typer.Option(0, "--seed"),
          var: list[str] = _VAR,
          positions: int = typer.Option(None, "--positions", help="Positions over the range "
                                        "(default: [design] positions, else the range)."),
          workers: int = _WORKERS, scheduler: str = _SCHED,
          chunk: int = typer.Option(16384, "--chunk", help="Designs per task."),
          output: str = typer.Option("assur-sweep.parquet", "-o", "--output",
                                     help="The results table (Parquet).")):
    """Evaluate many designs (on Dask) and write every design's criteria, feasibility
    and reason to Parquet."""
    from ..synthesis.search.scale import sweep as run_sweep, write_parquet
    from ..errors import AssemblyError, ModelError

    if samples < 1:
        _fail(f"--samples must be ≥ 1, got {samples}", 2)
    pb = _design_problem(file, var, positions)
    t0 = time.perf_counter()
    with _bar() as bar:
        task = bar.add_task("designs", total=samples)
        ex = _executor(scheduler, workers, chunk,
                       lambda done, total: bar.update(task, completed=done))
        try:
            with ex:
                batch = run_sweep(pb, samples=samples, seed=seed, executor=ex)
        except (ModelError, AssemblyError, OSError) as e:
            _fail(str(e))
    try:
        write_parquet(batch, output)
    except (OSError, ValueError) as e:
        _fail(f"{output}: cannot write the table: {e}")
    nf = int(batch.feasible.sum())
    _ok(f"{samples} designs × {len(pb.positions)} positions on {ex.describe()} in "
        f"{time.perf_counter() - t0:.1f} s; {nf} feasible; table: {output}")
    i = batch.best()
    if i >= 0:
        c = pb.objectives[0]
        console.print(Text(f"best sampled design: {c.sense} {c.name} = "
                           f"{c.show(batch.objectives[i, 0])}"))
    counts: dict = {}
    for r in batch.reasons:
        if r:
            key = r.split(" at position")[0].split(" = ")[0]
            counts[key] = counts.get(key, 0) + 1
    for k, n in sorted(counts.items(), key=lambda kv: -kv[1])[:5]:
        console.print(Text(f"  {n} infeasible: {k}"))


@app.command()
def optimize(file: Path = typer.Argument(..., help="Model file (TOML) with [design] or --var."),
             var: list[str] = _VAR,
             positions: int = typer.Option(None, "--positions"),
             popsize: int = typer.Option(15, "--popsize", help="Population per variable "
                                         "(differential evolution)."),
             maxiter: int = typer.Option(150, "--maxiter", help="Generations at most."),
             seed: int = typer.Option(0, "--seed"),
             workers: int = _WORKERS,
             scheduler: str = _SCHED,
             chunk: int = typer.Option(16384, "--chunk", help="Designs per task."),
             output: str = typer.Option("assur-optimize", "-o", "--output",
                                        help="Output directory."),
             polish: bool = typer.Option(
                 None, "--polish/--no-polish",
                 help="Polish the differential-evolution optimum by SLSQP with the "
                      "criteria's exact gradients (skipped, with a note, when a criterion "
                      "has none). Default: [design] polish of the file, else on."),
             lang: str = typer.Option("en", "--lang", help="Report labels: ru or en.")):
    """Search for the best design (differential evolution over whole populations, then
    a polish by SLSQP with exact gradients; with two or more objectives, NSGA-II's
    Pareto front); write it as a model file that extends the original, and an HTML
    report comparing the two."""
    from ..synthesis.search.search import optimize as run_de, pareto
    from ..errors import AssemblyError, ModelError
    from ..io import load
    from ..io._design import write_design_file
    from ..core.quantities import display_units
    from .report.design import pareto_figure, write_comparison

    _check_lang(lang)
    pb = _design_problem(file, var, positions)
    if not pb.objectives:
        _fail(f"{file}: no objective: add [[design.objectives]] (maximize = … or minimize = …)")
    out = _output_dir(output)
    t0 = time.perf_counter()
    with _bar() as bar:
        task = bar.add_task("generations", total=maxiter)
        ex = _executor(scheduler, workers, chunk, None)
        try:
            with ex:
                def run(X):
                    return ex.evaluate(pb, X)
                if len(pb.objectives) > 1:
                    res = pareto(pb, pop_size=popsize * len(pb.variables), generations=maxiter,
                                 seed=seed, evaluate=run,
                                 callback=lambda g, n: bar.update(task, completed=g))
                else:
                    res = run_de(pb, popsize=popsize, maxiter=maxiter, seed=seed, evaluate=run,
                                 callback=lambda g, v: bar.update(task, completed=g),
                                 polish=polish)
        except (ModelError, AssemblyError) as e:
            _fail(str(e))
    dt = time.perf_counter() - t0
    if len(pb.objectives) > 1:
        fig = pareto_figure(pb, res, out / "pareto.png")
        if res.batch is not None:
            from ..synthesis.search.scale import write_parquet
            write_parquet(res.batch, out / "pareto.parquet")
        _ok(f"Pareto front of {len(res.X)} feasible designs ({res.evaluations} evaluated, "
            f"{dt:.1f} s): {fig}")
        return
    c = pb.objectives[0]
    if not res.feasible:
        _fail(f"no feasible design found ({res.evaluations} evaluated): the best one "
              f"{res.batch.reason(0)}")
    name = f"{file.stem}_best.toml"
    units = display_units(pb.original)
    values = {v.name: float(x) for v, x in zip(pb.variables, res.x)}
    path = write_design_file(out / name, file, values, units, header=(
        f"The best design of {file.name} found by assur optimize: {c.sense} {c.name} = "
        f"{c.show(res.value)} (original {c.show(res.original.objectives[0, 0])}).",)
        + ((res.polished.summary(c.show) + ".",) if res.polished is not None else ()))
    try:
        best = load(path)  # the file written must load and assemble
        best.mechanism.solve(pb.positions)
    except (ModelError, AssemblyError) as e:
        _fail(f"{path}: the written model does not load: {e}")
    rep = write_comparison(out / "design.html", pb, res, lang=lang)
    rt = Table(title="best design", header_style="bold", title_justify="left")
    for h in ("variable", "original", "best", "bounds"):
        rt.add_column(h, justify="right")
    for j, v in enumerate(pb.variables):
        rt.add_row(v.name, v.show(pb.x0[j]), v.show(res.x[j]),
                   f"{v.show(v.low)} … {v.show(v.high)}")
    console.print(rt)
    console.print(Text(f"{c.sense} {c.name}: {c.show(res.original.objectives[0, 0])} → "
                       f"{c.show(res.value)}"))
    if res.polished is not None:
        console.print(Text(res.polished.summary(c.show)))
    _ok(f"{res.evaluations} designs in {res.calls} batches, {res.generations} generations on "
        f"{ex.describe()}, {dt:.1f} s; model: {path}; report: {rep}")


@app.command()
def tolerance(file: Path = typer.Argument(..., help="Model file (TOML) with [tolerances]."),
              output: str = typer.Option("assur-tolerance", "-o", "--output",
                                         help="Output directory."),
              samples: int = typer.Option(2000, "--samples", help="Machines drawn."),
              seed: int = typer.Option(0, "--seed", help="Seed of the random generator."),
              lang: str = typer.Option("en", "--lang", help="Labels: ru or en.")):
    """Monte Carlo over the model's manufacturing tolerances: distributions of pressure
    and capacity (P1…P99), machines that do not assemble, and the first-order stack-up
    from the exact sensitivities; tables (CSV, XLSX), histograms and an HTML report."""
    import numpy as np

    from ..errors import AssemblyError, ModelError, SingularPositionError
    from .report.tolerance import display_scale, write_tolerance
    from ..synthesis.tolerance import monte_carlo, worst_kind

    _check_lang(lang)
    if samples < 2:
        _fail(f"--samples must be at least 2; got {samples}", 2)
    model = _load(file)
    if not model.tolerances:
        _fail(f"{file}: no [tolerances] section (docs/tolerance.md)")
    out = _output_dir(output)
    try:
        r = monte_carlo(model, None, model.tolerances, samples=samples, seed=seed)
    except (AssemblyError, ModelError, SingularPositionError) as e:
        _fail(f"{file}: {e}")
    files = write_tolerance(r, model.mechanism, out, lang)
    tab = Table(title=f"{model.mechanism.name}: {samples} machines, seed {seed}",
                show_header=True, header_style="bold")
    for col in ("output", "unit", "nominal", "P5", "P50", "P95", "σ MC", "σ lin"):
        tab.add_column(col)
    for o in r.outputs:  # each machine's worst value over the range
        j = r.outputs.index(o)
        k, u = display_scale(r, o)
        how = worst_kind(o)
        nom = r.nominal[:, j].min() if how == "min" else r.nominal[:, j].max()
        p = r.worst_percentiles(o) if r.assembled.any() else [float("nan")] * 5
        iw = int(np.argmin(r.nominal[:, j]) if how == "min" else np.argmax(r.nominal[:, j]))
        sd = r.std(o)[iw] if r.assembled.sum() > 1 else float("nan")
        tab.add_row(f"{o} {how}", u, *(f"{v / k:.5g}" for v in (nom, p[1], p[2], p[3], sd,
                                                              r.linear_sigma[iw, j])))
    console.print(tab)
    console.print(f"does not assemble: {100 * r.failure_share:.3g} % of the machines")
    for d, _g, msg in r.reasons[:5]:
        console.print(f"  machine {d}: {msg}", soft_wrap=True)
    _summary({"tolerance": [f for f in files if not str(f).endswith(".html")],
              "html": [f for f in files if str(f).endswith(".html")]}, output)


@app.command()
def serve(file: Path = typer.Argument(..., help="Model file (TOML)."),
          port: int = typer.Option(8000, "--port", help="TCP port (0: any free port)."),
          host: str = typer.Option("127.0.0.1", "--host",
                                   help="Address to bind (default: loopback only)."),
          no_browser: bool = typer.Option(False, "--no-browser",
                                          help="Do not open the page in a browser."),
          lang: str = typer.Option("en", "--lang", help="The page's language: ru or en.")):
    """Serve an interactive page for a model: parameters as sliders, the mechanism's
    drawing moved by a stroke slider, live plots and tables (docs/page.md)."""
    _check_lang(lang)
    if not 0 <= port <= 65535:
        _fail(f"--port must be in 0…65535, got {port}", 2)
    _load(file)  # one message for a bad file, before the server starts
    from .page.server import create_app
    from ..errors import ModelError

    try:
        application = create_app(file, lang=lang)
    except (ModelError, OSError) as e:
        _fail(str(e))
    import socket

    import uvicorn

    try:  # the port first, so that a busy one is one message and the URL is known
        sock = socket.socket(socket.AF_INET6 if ":" in host else socket.AF_INET)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind((host, port))
    except OSError as e:
        _fail(f"cannot listen on {host}:{port}: {e.strerror or e}")
    port = sock.getsockname()[1]
    shown = f"[{host}]" if ":" in host else host
    url = f"http://{shown}:{port}/?lang={lang}"
    if host not in ("127.0.0.1", "::1", "localhost"):
        err.print(Text.assemble(("warning:", "bold yellow"), " ", f"serving on {host}: "
                                "anyone who can reach this address can use the page"))
    console.print(f"assur: serving {file} at {url} (Ctrl+C stops)", soft_wrap=True)
    if not no_browser:
        import threading
        import webbrowser
        threading.Timer(0.8, lambda: webbrowser.open(url)).start()
    config = uvicorn.Config(application, log_level="warning")
    uvicorn.Server(config).run(sockets=[sock])


@app.command()
def dxf(file: Path = typer.Argument(..., help="Model file (TOML)."),
        at: str = typer.Option("", "--at", help="Coordinate values to draw: cylinder "
                               "lengths in m (0.42,0.67), crank angles in degrees; "
                               "default: first and last."),
        output: str = typer.Option("", "-o", "--output",
                                   help="The DXF file (default: <model>.dxf).")):
    """Write the mechanism's drawing at chosen positions as DXF (millimetres, one layer
    per link, pivots as points; docs/page.md)."""
    import numpy as np

    from .page.dxf import write_dxf
    from ..errors import AssemblyError, ModelError, SingularPositionError

    model = _load(file)
    out = Path(output or (file.stem + ".dxf"))
    if out.exists() and out.is_dir():
        _fail(f"{out}: is a directory; expected a .dxf file name")
    mech = model.mechanism
    kin, idx = None, None
    if at and len(mech.coordinates) == 1 and mech.coordinate_kind(mech.coordinates[0]) != \
            "angle":
        try:
            values = [float(v) for v in at.split(",") if v.strip()]
        except ValueError:
            _fail(f"--at must be comma-separated numbers (m), got {at!r}")
        r = np.asarray(model.range, dtype=float)
        lo, hi = float(r.min()), float(r.max())
        bad = [v for v in values if not lo <= v <= hi]
        if bad or not values:
            _fail(f"--at {bad or at!r}: give values in the range {lo:.6g} … {hi:.6g} m")
        # a fine grid through the values keeps the assembly mode continuous between them
        q = np.unique(np.concatenate([np.linspace(r[0], r[-1], 201), values]))
        q = q if r[-1] >= r[0] else q[::-1]
        try:
            kin = mech.solve(q)
        except (AssemblyError, ModelError, SingularPositionError) as e:
            _fail(f"{file}: {e}")
        idx = [int(np.abs(q - v).argmin()) for v in values]
    else:
        analysis = _assemble(model)
        kin = analysis.kinematics
        idx = _positions(analysis, at) or sorted({0, kin.shape[-1] - 1})
    try:
        write_dxf(kin, out, positions=idx)
    except OSError as e:
        _fail(f"{out}: cannot write the DXF file: {e.strerror or e}")
    _ok(f"wrote {out} ({len(idx)} positions)")


def main(argv=None):  # pragma: no cover - console entry
    """Run the ``assur`` command line with the arguments ``argv`` (default:
    ``sys.argv[1:]``); the console script ``assur`` calls it. It ends with
    :class:`SystemExit`: 0 on success, 1 for a user's error (one message on
    stderr), 2 for a usage error.

    Examples
    --------
    >>> import contextlib, io, pathlib, tempfile
    >>> import ezdxf
    >>> from assur.views.cli import main
    >>> from assur.io import bundled
    >>> with tempfile.TemporaryDirectory() as d:
    ...     out = pathlib.Path(d) / "hitch.dxf"
    ...     argv = ["dxf", str(bundled("hitch_003")), "--at", "0.42,0.67", "-o", str(out)]
    ...     with contextlib.redirect_stdout(io.StringIO()) as shown:
    ...         try:
    ...             main(argv)                  # assur dxf hitch_003.toml --at … -o …
    ...         except SystemExit as e:
    ...             code = e.code
    ...     groups = sorted(g for g, _ in ezdxf.readfile(out).groups)
    >>> code, groups                            # S [m] of the two drawn positions
    (0, ['S=0.42 m', 'S=0.67 m'])
    >>> shown.getvalue().startswith("ok: wrote")
    True
    >>> main(["check", "no-such-model.toml"])  # "error: … no such file" on stderr
    Traceback (most recent call last):
    ...
    SystemExit: 1
    """
    return app(args=argv)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
