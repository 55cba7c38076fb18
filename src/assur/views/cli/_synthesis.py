"""The commands of synthesis: ``assur fit``, ``assur sweep``, ``assur optimize``,
``assur tolerance`` (:mod:`assur.views.cli`)."""

from __future__ import annotations

import contextlib
import time
from pathlib import Path

import typer
from rich.table import Table
from rich.text import Text

from ._common import (_check_lang, _fail, _load, _ok, _output_dir, _summary, console, err)
from ._types import COUNT, SEED, Address, Count, Positive

#: seconds to wait for a Dask scheduler's port before saying it cannot be reached
CONNECT_TIMEOUT = 10.0


def fit(file: Path = typer.Argument(..., help="Model file (TOML)."),
        table: Path = typer.Argument(..., help="The printed table (CSV): the coordinate, "
                                               "then columns 'expression [unit]'."),
        param: list[str] = typer.Option(..., "--fit", help="A parameter to fit and its "
                                        "bounds in SI: NAME=LOW:HIGH (repeat)."),
        screen: int = typer.Option(4096, "--screen", parser=COUNT,
                                   help="Designs screened (≥ 1; 2e4 accepted)."),
        starts: int = typer.Option(8, "--starts", parser=COUNT,
                                   help="Least-squares refinements (≥ 1)."),
        outlier: float = typer.Option(20.0, "--outlier", parser=Positive(),
                                      help="Residual [tolerances] beyond which a value is "
                                           "an outlier (a finite number > 0).")):
    """Fit parameters of a model to a printed table (assur.synthesis.fitting): robust least
    squares at the precision each value is printed with; outliers are listed."""
    from ...errors import ModelError
    from ...synthesis.fitting import fit_parameters
    from ...io import read_targets

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


def _design_problem(file: Path, var, positions):
    """The design problem of a model file (+ --var); user errors exit 1."""
    from ...io import load_problem
    from ...errors import AssemblyError, ModelError

    _load(file)  # the file's own errors and warnings, as every command shows them
    try:
        return load_problem(file, variables=tuple(var), positions=positions)
    except (ModelError, AssemblyError) as e:
        _fail(str(e))


def _executor(scheduler, workers, chunk, progress):
    """The executor of ``--scheduler``/``--workers``/``--chunk``: the scheduler's port
    must answer within :data:`CONNECT_TIMEOUT` (else one message, exit 1); workers
    default to 2 without a scheduler and to none with one."""
    from ...synthesis.search.scale import Executor
    from ...errors import ModelError
    if scheduler is not None:
        if workers:
            _fail(f"give either --scheduler or --workers, not both (--scheduler {scheduler} "
                  f"--workers {workers})", 2)
        workers = 0
        _reachable(scheduler)
    elif workers is None:
        workers = 2
    try:
        return Executor(scheduler=scheduler, workers=workers, chunk=chunk, progress=progress)
    except ModelError as e:
        _fail(str(e), 2)


@contextlib.contextmanager
def _running(ex, scheduler):
    """``with ex`` whose connection to a ``scheduler`` fails in one message (exit 1)
    naming the address, within :data:`CONNECT_TIMEOUT` seconds — also when what
    answers there is not a Dask scheduler."""
    if scheduler is None:
        with ex:
            yield ex
        return
    import dask
    import distributed  # noqa: F401 - its config defaults first: set() then restores them

    try:
        with dask.config.set({"distributed.comm.timeouts.connect": f"{CONNECT_TIMEOUT:g}s"}):
            ex.__enter__()
    except Exception as e:  # refused, timed out, garbage for a handshake
        why = " ".join(str(e).split())[:200]
        _fail(f"cannot connect to the Dask scheduler at {scheduler}: "
              f"{type(e).__name__}{': ' + why if why else ''} (is a Dask scheduler listening "
              f"there?)")
    with contextlib.ExitStack() as stack:
        stack.push(ex)
        yield ex


def _reachable(address: str):
    """Fail with one message unless something accepts a connection at the scheduler's
    ``address`` within :data:`CONNECT_TIMEOUT` seconds (TCP-based schemes)."""
    import socket

    scheme, host, port = Address().split(address)
    if scheme == "ucx":  # not a TCP port: the client says whether it connects
        return
    try:
        socket.create_connection((host, port), timeout=CONNECT_TIMEOUT).close()
    except socket.timeout:
        _fail(f"cannot reach the Dask scheduler at {address}: no answer within "
              f"{CONNECT_TIMEOUT:g} s")
    except OSError as e:  # refused, unknown host, no route
        _fail(f"cannot reach the Dask scheduler at {address}: {e.strerror or e}")


_VAR = typer.Option([], "--var", help='A design variable: NAME=LOW:HIGH or NAME=±DELTA, units '
                                      'as in files (e.g. "L4=0.6 m:0.72 m", "X01=±30 mm"); '
                                      'repeat. Adds to (or replaces) the file\'s [design].')
_WORKERS = typer.Option(None, "--workers", parser=Count(0),
                        help="Worker processes of a Dask LocalCluster, a whole number ≥ 0 "
                             "(0: in this process); default 2, none with --scheduler.")
_SCHED = typer.Option(None, "--scheduler", parser=Address(),
                      help="An existing Dask scheduler, [tcp://]host:port, e.g. "
                           "tcp://host:8786 (instead of --workers); it must answer within "
                           "10 s.")
_CHUNK = typer.Option(16384, "--chunk", parser=COUNT, help="Designs per task (≥ 1).")
_POSITIONS_HELP = ("Positions over the range, a whole number ≥ 2 (default: [design] "
                   "positions, else the range).")
_SEED_HELP = "Seed of the random generator, 0 … 2**32 − 1."


def _bar():
    from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn, TimeElapsedColumn
    return Progress(SpinnerColumn(), TextColumn("{task.description}", markup=False), BarColumn(),
                    TextColumn("{task.completed}/{task.total}"), TimeElapsedColumn(),
                    console=err, transient=True)


def sweep(file: Path = typer.Argument(..., help="Model file (TOML) with [design] or --var."),
          samples: int = typer.Option(10000, "--samples", parser=COUNT,
                                      help="Designs drawn uniformly within the bounds "
                                           "(≥ 1; 2e7 accepted)."),
          seed: int = typer.Option(0, "--seed", parser=SEED, help=_SEED_HELP),
          var: list[str] = _VAR,
          positions: int = typer.Option(None, "--positions", parser=Count(2),
                                        help=_POSITIONS_HELP),
          workers: int = _WORKERS, scheduler: str = _SCHED,
          chunk: int = _CHUNK,
          output: str = typer.Option("assur-sweep.parquet", "-o", "--output",
                                     help="The results table (Parquet).")):
    """Evaluate many designs (on Dask) and write every design's criteria, feasibility
    and reason to Parquet."""
    from ...synthesis.search.scale import sweep as run_sweep, write_parquet
    from ...errors import AssemblyError, ModelError

    pb = _design_problem(file, var, positions)
    t0 = time.perf_counter()
    with _bar() as bar:
        task = bar.add_task("designs", total=samples)
        ex = _executor(scheduler, workers, chunk,
                       lambda done, total: bar.update(task, completed=done))
        try:
            with _running(ex, scheduler):
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


def optimize(file: Path = typer.Argument(..., help="Model file (TOML) with [design] or --var."),
             var: list[str] = _VAR,
             positions: int = typer.Option(None, "--positions", parser=Count(2),
                                           help=_POSITIONS_HELP),
             popsize: int = typer.Option(15, "--popsize", parser=COUNT,
                                         help="Population per variable (differential "
                                              "evolution), ≥ 1."),
             maxiter: int = typer.Option(150, "--maxiter", parser=COUNT,
                                         help="Generations at most, ≥ 1."),
             seed: int = typer.Option(0, "--seed", parser=SEED, help=_SEED_HELP),
             workers: int = _WORKERS,
             scheduler: str = _SCHED,
             chunk: int = _CHUNK,
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
    from ..report.design import write_comparison

    _check_lang(lang)
    pb = _design_problem(file, var, positions)
    if not pb.objectives:
        _fail(f"{file}: no objective: add [[design.objectives]] (maximize = … or minimize = …)")
    out = _output_dir(output)
    res, ex, dt = _search(pb, popsize, maxiter, seed, workers, scheduler, chunk, polish)
    if len(pb.objectives) > 1:
        _pareto_written(pb, res, out, dt)
        return
    if not res.feasible:
        _fail(f"no feasible design found ({res.evaluations} evaluated): the best one "
              f"{res.batch.reason(0)}")
    path = _best_written(file, pb, res, out)
    rep = write_comparison(out / "design.html", pb, res, lang=lang)
    _show_best(pb, res)
    _ok(f"{res.evaluations} designs in {res.calls} batches, {res.generations} generations on "
        f"{ex.describe()}, {dt:.1f} s; model: {path}; report: {rep}")


def _search(pb, popsize, maxiter, seed, workers, scheduler, chunk, polish):
    """Differential evolution (one objective) or NSGA-II (several) on the executor,
    with a progress bar: the result, the executor and the time taken [s]."""
    from ...synthesis.search.search import optimize as run_de, pareto
    from ...errors import AssemblyError, ModelError

    t0 = time.perf_counter()
    with _bar() as bar:
        task = bar.add_task("generations", total=maxiter)
        ex = _executor(scheduler, workers, chunk, None)
        try:
            with _running(ex, scheduler):
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
        except OSError as e:  # the scheduler went away, or did not speak Dask
            _fail(f"{scheduler or ex.describe()}: {e}")
    return res, ex, time.perf_counter() - t0


def _pareto_written(pb, res, out: Path, dt):
    """The Pareto front's figure and table written to ``out``, and said so."""
    from ..report.design import pareto_figure

    fig = pareto_figure(pb, res, out / "pareto.png")
    if res.batch is not None:
        from ...synthesis.search.scale import write_parquet
        write_parquet(res.batch, out / "pareto.parquet")
    _ok(f"Pareto front of {len(res.X)} feasible designs ({res.evaluations} evaluated, "
        f"{dt:.1f} s): {fig}")


def _best_written(file: Path, pb, res, out: Path) -> Path:
    """The best design written as a model file that extends ``file``; it must load and
    assemble (else one message and exit 1)."""
    from ...errors import AssemblyError, ModelError
    from ...io import load
    from ...io._design import write_design_file
    from ...core.quantities import display_units

    c = pb.objectives[0]
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
    return path


def _show_best(pb, res):
    """The best design against the original, variable by variable, and the objective."""
    c = pb.objectives[0]
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

def tolerance(file: Path = typer.Argument(..., help="Model file (TOML) with [tolerances]."),
              output: str = typer.Option("assur-tolerance", "-o", "--output",
                                         help="Output directory."),
              samples: int = typer.Option(2000, "--samples", parser=Count(2),
                                          help="Machines drawn, a whole number ≥ 2 (2e4 "
                                               "accepted)."),
              seed: int = typer.Option(0, "--seed", parser=SEED, help=_SEED_HELP),
              lang: str = typer.Option("en", "--lang", help="Labels: ru or en.")):
    """Monte Carlo over the model's manufacturing tolerances: distributions of pressure
    and capacity (P1…P99), machines that do not assemble, and the first-order stack-up
    from the exact sensitivities; tables (CSV, XLSX), histograms and an HTML report."""
    import numpy as np

    from ...errors import AssemblyError, ModelError, SingularPositionError
    from ..report.tolerance import display_scale, write_tolerance
    from ...synthesis.tolerance import monte_carlo, worst_kind

    _check_lang(lang)
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
