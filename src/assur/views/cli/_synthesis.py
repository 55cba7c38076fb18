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
    from ...core.inputs import check_table
    try:  # no NaN or infinity printed as a result
        check_table("fitted parameters [SI]", {n: [v] for n, v in res.params.items()},
                    key="")
    except ModelError as e:
        _fail(f"{file}: {e}")
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


def _executor(scheduler, workers, chunk, progress, phase=None, scheduler_file=None,
              timeout=None):
    """The executor of ``--scheduler``/``--scheduler-file``/``--workers``/``--chunk``:
    in this process by default; a scheduler's port must answer within
    :data:`CONNECT_TIMEOUT` (else one message, exit 1)."""
    from ...synthesis.search.scale import TIMEOUT, Executor
    from ...errors import ModelError
    if scheduler is not None and scheduler_file is not None:
        _fail("give either --scheduler or --scheduler-file, not both", 2)
    if scheduler_file is not None:
        if not Path(scheduler_file).is_file():
            _fail(f"--scheduler-file {scheduler_file}: no such file (the file `dask scheduler "
                  f"--scheduler-file` writes)", 2)
        scheduler = str(scheduler_file)
    if scheduler is not None:
        if workers:
            _fail(f"give either --scheduler or --workers, not both (--scheduler {scheduler} "
                  f"--workers {workers})", 2)
        workers = 0
        if scheduler_file is None:
            _reachable(scheduler)
    try:
        return Executor(scheduler=scheduler, workers=workers or 0, chunk=chunk,
                        progress=progress, phase=phase, timeout=timeout or TIMEOUT)
    except ModelError as e:
        _fail(str(e), 2)


@contextlib.contextmanager
def _quiet_dask():
    """Dask's own log records (a worker lost, a reconnection tried) stay out of the
    terminal while a command runs: what matters reaches the user as one message."""
    import logging
    names = ("distributed", "tornado", "asyncio")
    levels = {n: logging.getLogger(n).level for n in names}
    for n in names:
        logging.getLogger(n).setLevel(logging.CRITICAL + 1)
    try:
        yield
    finally:
        for n, lv in levels.items():
            logging.getLogger(n).setLevel(lv)


@contextlib.contextmanager
def _running(ex, scheduler):
    """``with ex`` whose connection to a ``scheduler`` fails in one message (exit 1)
    naming the address, within :data:`CONNECT_TIMEOUT` seconds — also when what
    answers there is not a Dask scheduler."""
    if not ex.distributed:
        with ex:
            yield ex
        return
    import dask
    import distributed  # noqa: F401 - its config defaults first: set() then restores them

    from ...errors import ModelError
    with _quiet_dask():
        try:
            with dask.config.set({"distributed.comm.timeouts.connect": f"{CONNECT_TIMEOUT:g}s"}):
                ex.__enter__()
        except ModelError as e:  # another assur version on a worker
            _fail(str(e))
        except Exception as e:  # refused, timed out, garbage for a handshake
            why = " ".join(str(e).split())[:200]
            _fail(f"cannot connect to the Dask scheduler at {scheduler}: "
                  f"{type(e).__name__}{': ' + why if why else ''} (is a Dask scheduler "
                  f"listening there?)")
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
                        help="Worker processes of a Dask LocalCluster started here, a whole "
                             "number ≥ 0; default 0: in this process.")
_SCHED = typer.Option(None, "--scheduler", parser=Address(),
                      help="An existing Dask scheduler, [tcp://|tls://]host:port, e.g. "
                           "tcp://host:8786 (instead of --workers); it must answer within "
                           "10 s. TLS: Dask's configuration (distributed.comm.tls).")
_SCHED_FILE = typer.Option(None, "--scheduler-file",
                           help="The file `dask scheduler --scheduler-file` wrote (instead "
                                "of --scheduler).")
_TIMEOUT = typer.Option(60.0, "--timeout", parser=Positive("s"),
                        help="Seconds without any Dask worker before the run ends with a "
                             "message (the finished parts are kept).")
_CHUNK = typer.Option(16384, "--chunk", parser=COUNT, help="Designs per task (≥ 1).")
_POSITIONS_HELP = ("Positions over the range, a whole number ≥ 2 (default: [design] "
                   "positions, else the range).")
_SEED_HELP = "Seed of the random generator, 0 … 2**32 − 1."

#: seconds between two progress lines when stderr is not a terminal
LINE_EVERY = 10.0


class _Progress:
    """A command's progress: a bar on a terminal; else lines (phase, percent,
    rate, ETA) every :data:`LINE_EVERY` seconds and at the end."""

    def __init__(self, what, total, unit):
        self.what, self.total, self.unit = what, total, unit
        self.terminal = err.is_terminal
        self.t0 = time.perf_counter()
        self.t_first = None
        self.last = -LINE_EVERY
        self.done = 0
        self.bar = None

    def __enter__(self):
        if self.terminal:
            from rich.progress import (BarColumn, Progress, SpinnerColumn, TextColumn,
                                       TimeElapsedColumn, TimeRemainingColumn)
            self.bar = Progress(SpinnerColumn(), TextColumn("{task.description}", markup=False),
                                BarColumn(), TextColumn("{task.completed}/{task.total}"),
                                TimeElapsedColumn(), TimeRemainingColumn(), console=err,
                                transient=True)
            self.bar.__enter__()
            self.task = self.bar.add_task(self.what, total=self.total)
        return self

    def __exit__(self, *exc):
        if self.bar is not None:
            self.bar.__exit__(*exc)

    def phase(self, text):
        if self.bar is not None:
            self.bar.update(self.task, description=f"{self.what}: {text}")
        else:
            err.print(Text(f"{self.what}: {text} ({time.perf_counter() - self.t0:.1f} s)"),
                      soft_wrap=True)

    def __call__(self, done, total=None):
        now = time.perf_counter()
        if total is not None:  # a resumed sweep computes only the missing designs
            self.total = total
        if self.t_first is None:
            self.t_first, self.done_first = now, done
        self.done = done
        if self.bar is not None:
            self.bar.update(self.task, completed=done, total=self.total)
            return
        if now - self.last < LINE_EVERY and done < self.total:
            return
        self.last = now
        pct = 100.0 * done / max(1, self.total)
        dt = now - self.t_first
        rate = (done - self.done_first) / dt if dt > 0 else 0.0
        eta = (self.total - done) / rate if rate > 0 else float("nan")
        eta_text = f", ETA {eta:.0f} s" if eta == eta and done < self.total else ""
        err.print(Text(f"{self.what}: {pct:.0f} % ({done}/{self.total} {self.unit}), "
                       f"{rate:.4g} {self.unit}/s{eta_text}"), soft_wrap=True)


def sweep(file: Path = typer.Argument(..., help="Model file (TOML) with [design] or --var."),
          samples: int = typer.Option(10000, "--samples", parser=COUNT,
                                      help="Designs drawn uniformly within the bounds "
                                           "(≥ 1; 2e7 accepted)."),
          seed: int = typer.Option(0, "--seed", parser=SEED, help=_SEED_HELP),
          var: list[str] = _VAR,
          positions: int = typer.Option(None, "--positions", parser=Count(2),
                                        help=_POSITIONS_HELP),
          workers: int = _WORKERS, scheduler: str = _SCHED,
          scheduler_file: Path = _SCHED_FILE, timeout: float = _TIMEOUT,
          chunk: int = _CHUNK,
          resume: bool = typer.Option(False, "--resume",
                                      help="Keep the parts an earlier run of the same file, "
                                           "variables, positions, seed and samples finished "
                                           "in the output, and compute only the rest."),
          output: str = typer.Option("assur-sweep.parquet", "-o", "--output",
                                     help="The results: a Parquet dataset (a folder of "
                                          "parts and its _manifest.json).")):
    """Evaluate many designs (in this process or on Dask) and write every design's
    criteria, feasibility and reason to a Parquet dataset, part by part as the chunks
    complete."""
    from ...synthesis.search.scale import sweep_to
    from ...errors import AssemblyError, ModelError

    pb = _design_problem(file, var, positions)
    t0 = time.perf_counter()
    with _Progress("designs", samples, "designs") as prog:
        ex = _executor(scheduler, workers, chunk, prog, prog.phase, scheduler_file, timeout)
        try:
            with _running(ex, scheduler or scheduler_file):
                r = sweep_to(pb, output, samples=samples, seed=seed, executor=ex,
                             resume=resume)
        except (ModelError, AssemblyError) as e:
            kept = _parts_kept(output)
            _fail(f"{e}" + (f"; {kept}" if kept else ""))
        except OSError as e:
            _fail(f"{output}: {e.strerror or e}")
    done = f"{r.computed} designs" + (f" (and {r.resumed} of an earlier run)" if r.resumed
                                      else "")
    _ok(f"{done} × {len(pb.positions)} positions on {ex.describe()} in "
        f"{time.perf_counter() - t0:.1f} s; {r.feasible} feasible; table: {output}")
    if r.best is not None:
        c = pb.objectives[0]
        console.print(Text(f"best sampled design: #{r.best[0]}, {c.sense} {c.name} = "
                           f"{c.show(r.best[1])}"))
    for k, n in sorted(r.reasons.items(), key=lambda kv: -kv[1])[:5]:
        console.print(Text(f"  {n} infeasible: {k}"))


def _parts_kept(output) -> str:
    """What a failed sweep left in ``output``, in words ("" when nothing)."""
    from ...synthesis.search.dataset import MANIFEST
    p = Path(output)
    if not (p / MANIFEST).is_file():
        return ""
    n = len(list(p.glob("part-*.parquet")))
    return (f"{n} finished parts are kept in {output}: rerun the same command with --resume "
            f"to compute only the rest") if n else ""


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
             scheduler_file: Path = _SCHED_FILE, timeout: float = _TIMEOUT,
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
    res, ex, dt = _search(pb, popsize, maxiter, seed, workers, scheduler, chunk, polish,
                          scheduler_file, timeout)
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


def _search(pb, popsize, maxiter, seed, workers, scheduler, chunk, polish,
            scheduler_file=None, timeout=None):
    """Differential evolution (one objective) or NSGA-II (several) on the executor,
    with a progress bar: the result, the executor and the time taken [s]."""
    from ...synthesis.search.search import optimize as run_de, pareto
    from ...errors import AssemblyError, ModelError

    t0 = time.perf_counter()
    with _Progress("generations", maxiter, "generations") as prog:
        ex = _executor(scheduler, workers, chunk, None, prog.phase, scheduler_file, timeout)
        try:
            with _running(ex, scheduler or scheduler_file):
                def run(X):
                    return ex.evaluate(pb, X)
                if len(pb.objectives) > 1:
                    res = pareto(pb, pop_size=popsize * len(pb.variables), generations=maxiter,
                                 seed=seed, evaluate=run, callback=lambda g, n: prog(g))
                else:
                    res = run_de(pb, popsize=popsize, maxiter=maxiter, seed=seed, evaluate=run,
                                 callback=lambda g, v: prog(g), polish=polish)
        except (ModelError, AssemblyError) as e:
            _fail(str(e))
        except OSError as e:  # the scheduler went away, or did not speak Dask
            _fail(f"{scheduler or ex.describe()}: {e}")
    return res, ex, time.perf_counter() - t0


def _pareto_written(pb, res, out: Path, dt):
    """The Pareto front's figure and table written to ``out``, and said so."""
    from ..report.design import pareto_figure

    from ...core.inputs import check_table
    from ...errors import ModelError
    try:  # the front's designs and objectives: no NaN or infinity in a file
        check_table("pareto.parquet [SI]", {
            **{v.name: res.X[:, j] for j, v in enumerate(pb.variables)},
            **{f"{c.sense} {c.name}": res.batch.objectives[:, j]
               for j, c in enumerate(pb.objectives)}}, key="")
    except ModelError as e:
        _fail(str(e))
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
    from ...core.inputs import check_table
    try:  # the model file and the report: no NaN or infinity written
        check_table(f"{name} (best design) [SI]", {
            **{k: [x] for k, x in values.items()}, f"{c.sense} {c.name}": [res.value],
            f"{c.sense} {c.name} of the original": [res.original.objectives[0, 0]]}, key="")
    except ModelError as e:
        _fail(f"{file}: {e}")
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
    try:
        files = write_tolerance(r, model.mechanism, out, lang)
    except ModelError as e:  # no machine assembles: nothing to report
        _fail(f"{file}: {e}")
    tab = Table(title=f"{model.mechanism.name}: {samples} machines, seed {seed}",
                show_header=True, header_style="bold")
    for col in ("output", "unit", "nominal", "P5", "P50", "P95", "σ MC", "σ lin"):
        tab.add_column(col)
    for o in r.outputs:  # each machine's worst value over the range
        j = r.outputs.index(o)
        k, u = display_scale(r, o)
        how = worst_kind(o)
        nom = r.nominal[:, j].min() if how == "min" else r.nominal[:, j].max()
        p = r.worst_percentiles(o)  # some machine assembles (write_tolerance said so)
        iw = int(np.argmin(r.nominal[:, j]) if how == "min" else np.argmax(r.nominal[:, j]))
        sd = f"{r.std(o)[iw] / k:.5g}" if r.assembled.sum() > 1 else "—"  # σ of one: none
        tab.add_row(f"{o} {how}", u, *(f"{v / k:.5g}" for v in (nom, p[1], p[2], p[3])), sd,
                    f"{r.linear_sigma[iw, j] / k:.5g}")
    console.print(tab)
    console.print(f"does not assemble: {100 * r.failure_share:.3g} % of the machines")
    for d, _g, msg in r.reasons[:5]:
        console.print(f"  machine {d}: {msg}", soft_wrap=True)
    _summary({"tolerance": [f for f in files if not str(f).endswith(".html")],
              "html": [f for f in files if str(f).endswith(".html")]}, output)
