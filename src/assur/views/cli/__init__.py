"""Command-line interface: ``assur check``, ``assur analyze``, ``assur tables``,
``assur fit``, ``assur simulate``, ``assur cycles``, ``assur sweep``, ``assur optimize``,
``assur tolerance``, ``assur serve``, ``assur dxf``, ``assur demo``.

Every failure a user can cause (a malformed file, a design that cannot assemble,
a condition without a root, an input that is not a regular file, an output
directory that cannot be written) prints one clear message and exits with status
1 (2 for usage errors, as typer does) — never a traceback. Every numeric option is
range-checked by its type (``_types``: counts ≥ 1, also written ``2e7``; seeds
0 … 2**32 − 1; durations finite and > 0), a value beyond its range a usage error.
Anything else a command raises is a defect: the last-resort handler (``_guard``)
prints one line with the log file that holds the traceback and exits with 1
(Ctrl+C: 130).

User text (names, titles, paths, option values, messages quoting them) is printed
literally: the consoles interpret no markup and no emoji codes, and styles are
applied with :class:`rich.text.Text` spans only.

The commands, by concern: a model's worksheet (``_report``: check, analyze,
tables, demo), synthesis (``_synthesis``: fit, sweep, optimize, tolerance), motion
in time (``_dynamics``: simulate, cycles) and the page (``_page``: serve, dxf); the
app, the consoles and the shared steps in ``_common``. They are registered here, in
the order ``assur --help`` lists them.
"""

from __future__ import annotations

from ._common import app
from ._guard import guarded
from ._dynamics import cycles, simulate
from ._page import dxf, serve
from ._report import analyze, check, demo, tables
from ._synthesis import fit, optimize, sweep, tolerance
# the consoles, the options' values and two helpers, importable from here as before
from ._common import FORMATS, LANGS, _positions, console, err

__all__ = ["app", "main"]

for _command in (check, analyze, tables, fit, demo, simulate, cycles, sweep, optimize,
                 tolerance, serve, dxf):
    app.command()(guarded(_command))  # no traceback: the last-resort handler (_guard)
del _command


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

