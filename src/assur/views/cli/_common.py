"""The command line's app, consoles and the steps every command shares: loading a
model file, the output directory, the options' checks — each user error one message
and exit status 1 (:mod:`assur.views.cli`)."""

from __future__ import annotations

import sys
from pathlib import Path

import typer
from rich.console import Console
from rich.text import Text

__all__ = ["app", "console", "err"]

class _App(typer.Typer):
    """The app, whose run ends every unexpected exception in one line (:mod:`._guard`):
    the commands are guarded themselves; this catches what escapes typer's parsing."""

    def __call__(self, *args, **kwargs):
        try:
            return super().__call__(*args, **kwargs)
        except BaseException as e:
            if isinstance(e, (typer.Exit, typer.Abort, typer.TyperException)):
                raise
            from ._guard import handle
            argv = kwargs.get("args")
            argv = list(sys.argv[1:] if argv is None else argv)
            known = {c.name or c.callback.__name__ for c in self.registered_commands}
            command = next((a for a in argv if a in known), "")
            code = handle(command, e, {"argv": argv})
            if code is None:
                raise
            sys.exit(code)


app = _App(add_completion=False, no_args_is_help=True, rich_markup_mode=None,
           help="Hydraulic-cylinder driven planar linkages solved by Assur groups.")
# markup=False, emoji=False: "[/x]" in a title or ":100:" in a message stay as written
console = Console(stderr=False, markup=False, emoji=False, highlight=False)
err = Console(stderr=True, markup=False, emoji=False, highlight=False)
LANGS = ("ru", "en")

FORMATS = ("csv", "xlsx", "html", "png", "svg", "gif", "pdf")  # = assur.views.report.FORMATS
DEFAULT_FORMATS = FORMATS[:-1]  # = assur.views.report.DEFAULT_FORMATS (pdf needs Chromium)


def _version(value: bool):
    if value:
        from ... import __version__
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
    from ...errors import AssemblyError, ModelError
    from ...io import load

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
    from ...errors import AssemblyError, ModelError, SingularPositionError

    try:
        return model.analyze()
    except (AssemblyError, ModelError, SingularPositionError) as e:
        _fail(f"{model.source}: {e}")


def _shape_text(model) -> str:
    """'grid S × S1: 13 × 8 = 104 positions', 'paired paths S, S1: 9 positions' or, for
    held coordinates, 'path along S, 11 positions: S1 holds phi9 = 75 deg'."""
    cs = list(model.mechanism.coordinates)
    if model.path is not None:
        return model.path.describe()
    if model.paired:
        return f"paired paths {', '.join(cs)}: {len(model.range)} positions"
    shape = model.shape
    return (f"grid {' × '.join(cs)}: {' × '.join(str(n) for n in shape)} = "
            f"{len(model.range)} positions")


def _formats(value: str):
    fmts = tuple(f.strip().lower() for f in value.split(",") if f.strip())
    bad = [f for f in fmts if f not in FORMATS]
    if bad or not fmts:
        _fail(f"--format must be a comma-separated subset of {', '.join(FORMATS)}; got {value!r}")
    return fmts


def _positions(analysis, draw_at, du=None, option="--draw-at"):
    """Indices of the positions nearest to the coordinate values ``draw_at`` (one
    coordinate; floats, or their text), written in the display units ``du`` (default:
    the model file's; e.g. "0.42,0.67" [m] for a cylinder, "14.679,188.229" [°] for a
    crank). A crank angle matches its positions modulo one turn
    (188.229° finds the position written −171.771°)."""
    if not draw_at:
        return None
    from ...core.display import unit_system
    from ..report.numbers import number
    from ..report.labels import unit as unit_label

    kin = analysis.kinematics
    if kin.k != 1 or len(kin.shape) != 1:
        _fail(f"{option} needs a model with one coordinate and one design")
    import numpy as np
    du = du if du is not None else unit_system(analysis.mechanism)
    angle = analysis.mechanism.coordinate_kind(kin.coordinates[0]) == "angle"
    u = du["angle" if angle else "length"]
    shown = "°" if u.is_degrees else unit_label(u.text, "en")
    if isinstance(draw_at, str):  # a caller's text; the option gives floats (_types.Numbers)
        from ._types import Numbers
        try:
            draw_at = Numbers()(draw_at)
        except typer.BadParameter as e:
            _fail(f"{option}: {e} ({shown})", 2)
    values = [float(v) for v in draw_at]
    if not values or not np.isfinite(values).all():
        _fail(f"{option} must name at least one position by finite numbers ({shown}), "
              f"got {draw_at!r}", 2)
    si = np.asarray(values) * u.scale  # [m or rad]
    q = kin.q()
    lo, hi = float(q.min()), float(q.max())

    def span():
        return (f"{number(u.of(lo), None, 'en', 6)} … {number(u.of(hi), None, 'en', 6)} "
                f"{shown}")

    if not angle:
        bad = [v for v, s in zip(values, si) if not lo - 1e-12 <= s <= hi + 1e-12]
        if bad:
            _fail(f"{option} {bad} is outside the range {span()}")
        return [int(abs(q - s).argmin()) for s in si]
    # crank angles: the nearest position on the circle; a value farther from every
    # position than the largest step between neighbouring positions is not in the range
    step = float(np.max(np.abs(np.diff(q)))) if q.size > 1 else 0.0
    out, bad = [], []
    for v, s in zip(values, si):
        d = np.abs((q - s + np.pi) % (2 * np.pi) - np.pi)
        i = int(d.argmin())
        if d[i] > max(step, 1e-9):
            bad.append(v)
        out.append(i)
    if bad:
        _fail(f"{option} {bad} [{shown}] is outside the positions of "
              f"{kin.coordinates[0]}: {span()} ({q.size} positions)")
    return out


def _unique(indices):
    """``indices`` without repeats, in their order: two values nearest to one position
    draw it once (a DXF group, a figure's curve, each named once)."""
    return list(dict.fromkeys(indices))


#: the options every command that writes documents shares
UNITS_HELP = ("Units shown: file (each quantity in the unit the model file writes it in), "
              "engineering (mm, deg, kN, MPa), si (m, rad, N, Pa) or imperial (in, lbf, "
              "psi); default: the file's [display] units, else file.")
LANG_HELP = "Language: ru or en; default: the file's [display] lang, else en."


def _units(model, units: str):
    """The display units of a command: ``--units`` (checked), else the model file's
    ``[display] units``, else the file's own units."""
    from ...core.display import SYSTEMS, unit_system

    if units and units not in SYSTEMS:
        _fail(f"--units must be one of: {', '.join(SYSTEMS)}; got {units!r}")
    return unit_system(model.mechanism, units or None)


def _lang(model, lang: str) -> str:
    """``--lang`` (checked), else the model file's ``[display] lang``, else English."""
    if lang:
        _check_lang(lang)
        return lang
    return model.mechanism.display.get("lang") or "en"


def _summary(files, output: str):
    n = sum(len(v) for v in files.values())
    console.print(Text.assemble((f"wrote {n} files", "green"), f" to {output}/"))
    html = [p for p in files.get("html", [])]
    if html:
        console.print(f"report: {Path(html[0]).resolve()}")
