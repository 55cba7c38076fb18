"""The commands of motion in time: ``assur simulate``, ``assur cycles``
(:mod:`assur.views.cli`)."""

from __future__ import annotations

from pathlib import Path

import typer
from rich.text import Text

from ._common import LANG_HELP, UNITS_HELP, _fail, _lang, _load, _ok, _output_dir, \
    _summary, _units, console
from ._types import DURATION


def simulate(file: Path = typer.Argument(..., help="Model file (TOML) with [[drive]] and "
                                                   "[simulation]."),
             output: str = typer.Option("assur-simulation", "-o", "--output",
                                        help="Output directory."),
             lang: str = typer.Option("", "--lang", help=LANG_HELP),
             units: str = typer.Option("", "--units", help=UNITS_HELP),
             duration: float = typer.Option(None, "--duration", parser=DURATION,
                                            help="Simulated time in s, a finite number > 0 "
                                                 "(default: the file's [simulation] "
                                                 "duration).")):
    """Simulate the hydraulic drive and the mechanism in time (seed 001 lab 6; seed
    004's crane, two cylinders through a flow divider): time series (CSV), figures
    (PNG), the mechanism's motion (GIF) and an HTML report."""
    from ...dynamics import simulate_model
    from ...errors import AssemblyError, ModelError
    from ..report.simulation import write_simulation_report
    from ...texts import localize

    model = _load(file)
    lang, du = _lang(model, lang), _units(model, units)
    out = _output_dir(output)
    options = {"t_end": duration} if duration is not None else {}
    try:
        result = simulate_model(model, **options)
    except (ModelError, AssemblyError, ValueError) as e:
        _fail(f"{file}: {e}")
    try:
        files = write_simulation_report(result, out, localize(model.mechanism.title, lang),
                                        lang, model=model, units=du)
    except ModelError as e:  # an animation too long for the memory limit, a NaN or inf
        _fail(f"{file}: {e}" + ("" if result.success else f" ({result.message})"))
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


def cycles(file: Path = typer.Argument(..., help="Model file (TOML) of two cylinder "
                                                 "coordinates with [[drive]]."),
           output: str = typer.Option("assur-cycles", "-o", "--output",
                                      help="Output directory."),
           lang: str = typer.Option("", "--lang", help=LANG_HELP),
           units: str = typer.Option("", "--units", help=UNITS_HELP)):
    """Seed 004's work cycles: max cylinder forces with their static and dynamic parts
    for combined and separate motion, cycle times 4–20 s (CSV, XLSX, PNG) and an HTML
    report that sets them against the paper's conclusions."""
    from ...errors import AssemblyError, ModelError
    from ..report.cycles import verdict_word, write_cycles_report

    model = _load(file)
    lang, du = _lang(model, lang), _units(model, units)
    out = _output_dir(output)
    try:
        _, verdicts, files = write_cycles_report(model, out, lang, units=du)
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
