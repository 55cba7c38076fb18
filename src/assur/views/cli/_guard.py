"""The command line's last-resort handler (:mod:`assur.views.cli`).

Every command runs inside :func:`guarded`. The errors a user can cause are caught by
the commands themselves (one message, exit status 1); what escapes them is a defect
of assur. It never shows a traceback: one line on stderr names the command, the
exception and the log file that holds the full traceback, and the exit status is 1.
A :class:`MemoryError` says which options or file settings to reduce; Ctrl+C prints
one line and exits with 130 (the shell's convention, 128 + SIGINT).

The log files go to ``$ASSUR_CACHE_DIR/logs`` when that is set, else
``$XDG_CACHE_HOME/assur/logs``, else ``~/.cache/assur/logs`` (on Windows
``%LOCALAPPDATA%\\assur\\logs``) — the directory of assur's other caches; the newest
50 are kept.
"""

from __future__ import annotations

import functools
import os
import sys
import time
import traceback
from pathlib import Path

import typer
from rich.console import Console
from rich.text import Text

__all__ = ["guarded", "handle", "log_dir", "MEMORY_HINTS"]

#: what to reduce, per command, when memory runs out
MEMORY_HINTS = {
    "check": "the positions of [range]",
    "analyze": "the positions of [range] or --frames",
    "tables": "the positions of [range]",
    "demo": "--frames",
    "fit": "--screen or the rows of the table",
    "simulate": "--duration or the file's [simulation] duration",
    "cycles": "the positions of [range]",
    "sweep": "--samples, --positions or --chunk",
    "optimize": "--popsize, --positions or --chunk",
    "tolerance": "--samples or the positions of [range]",
    "serve": "the positions of [range]",
    "dxf": "the positions of --at",
}

#: log files kept in the directory (the oldest are removed)
KEEP = 50


def log_dir() -> Path:
    """The directory of the command line's log files (not created here).

    Examples
    --------
    >>> import os
    >>> from assur.views.cli._guard import log_dir
    >>> log_dir().name, log_dir().parent.name == os.path.basename(
    ...     os.environ.get("ASSUR_CACHE_DIR", "assur"))
    ('logs', True)
    """
    base = os.environ.get("ASSUR_CACHE_DIR")
    if not base:
        if sys.platform == "win32" and os.environ.get("LOCALAPPDATA"):
            root = os.environ["LOCALAPPDATA"]
        else:
            root = os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache")
        base = os.path.join(root, "assur")
    return Path(base) / "logs"


def _one_line(text: str, limit: int = 300) -> str:
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[:limit - 1] + "…"


def _write_log(command: str, exc: BaseException, options: dict):
    """The traceback of ``exc`` and the command's ``options`` written to a new log
    file: its path, or the reason it could not be written (a str)."""
    from ... import __version__
    try:
        d = log_dir()
        d.mkdir(parents=True, exist_ok=True)
        now = time.time()
        stamp = time.strftime("%Y%m%d-%H%M%S", time.localtime(now)) + f"{now % 1:.6f}"[1:]
        path = d / f"assur-{command}-{stamp}-{os.getpid()}.log"
        for k in range(1, 100):  # two in one microsecond: the next free name
            if not path.exists():
                break
            path = d / f"assur-{command}-{stamp}-{os.getpid()}-{k}.log"
        body = "".join(traceback.format_exception(type(exc), exc, exc.__traceback__))
        path.write_text(
            f"assur {__version__} {command}\n"
            f"python {sys.version.split()[0]} on {sys.platform}\n"
            f"argv: {sys.argv!r}\n"
            f"options: {options!r}\n"
            f"time: {time.strftime('%Y-%m-%d %H:%M:%S %z')}\n\n{body}",
            encoding="utf-8")
        _prune(d)
        return path
    except Exception as e:  # a read-only home, a full disk: say so, still one line
        return f"{type(e).__name__}: {_one_line(e, 120)}"


def _prune(d: Path):
    try:
        logs = sorted(d.glob("assur-*.log"), key=lambda p: p.stat().st_mtime)
        for p in logs[:-KEEP]:
            p.unlink(missing_ok=True)
    except OSError:  # pragma: no cover - another process pruning at the same time
        pass


def _say(line: str, prefix: str = ""):
    """One line on stderr (``prefix`` in bold red before it)."""
    err = Console(stderr=True, markup=False, emoji=False, highlight=False)  # = _common.err
    err.print(Text.assemble((prefix, "bold red"), " " if prefix else "", line),
              soft_wrap=True)


def handle(command: str, exc: BaseException, options=None):
    """Say what ``exc``, escaped from the command ``command``, means in one line on
    stderr and return the exit status: 130 for Ctrl+C, 1 otherwise (the traceback in
    a new log file); None for what must propagate (SystemExit, GeneratorExit).

    Examples
    --------
    >>> import contextlib, io, os, tempfile
    >>> from unittest import mock
    >>> from assur.views.cli._guard import handle
    >>> with tempfile.TemporaryDirectory() as d, \\
    ...         mock.patch.dict(os.environ, {"ASSUR_CACHE_DIR": d}), \\
    ...         contextlib.redirect_stderr(io.StringIO()):
    ...     codes = [handle("sweep", e) for e in (KeyboardInterrupt(), MemoryError(),
    ...                                            ZeroDivisionError("x"), SystemExit(0))]
    ...     logs = len(os.listdir(os.path.join(d, "logs")))
    >>> codes, logs                         # two tracebacks written
    ([130, 1, 1, None], 2)
    """
    options = options or {}
    name = command or "assur"
    prog = f"assur {command}" if command else "assur"
    if isinstance(exc, (SystemExit, GeneratorExit)):
        return None
    if isinstance(exc, KeyboardInterrupt):
        _say(f"{prog}: interrupted (Ctrl+C)")
        return 130
    if isinstance(exc, MemoryError):
        where = _write_log(name, exc, options)
        what = MEMORY_HINTS.get(command, "the sizes of the model")
        detail = _one_line(exc) or "no memory left"
        log = (f"the log is {where}" if isinstance(where, Path)
               else f"the traceback could not be written: {where}")
        _say(f"{prog}: out of memory ({detail}): reduce {what} — {log}")
        return 1
    from ...errors import AssemblyError, MissingExtraError, ModelError, SingularPositionError

    if isinstance(exc, (ModelError, AssemblyError, SingularPositionError, MissingExtraError)):
        _say(str(exc), "error:")  # a typed error no command caught: its message
        return 1
    where = _write_log(name, exc, options)
    detail = _one_line(exc)
    said = f"{type(exc).__name__}: {detail}" if detail else type(exc).__name__
    if isinstance(where, Path):
        _say(f"{prog}: internal error: {said} — please report it with the log {where}")
    else:
        _say(f"{prog}: internal error: {said} — please report it (the traceback could "
             f"not be written: {where})")
    return 1


def guarded(command):
    """``command`` wrapped in the last-resort handler: an unexpected exception becomes
    one line on stderr and exit status 1, its traceback a log file (:func:`log_dir`);
    a ``MemoryError`` says what to reduce; Ctrl+C exits with 130. Exits, usage errors
    and the typed errors of assur pass as they were.

    Parameters
    ----------
    command : callable
        A command function of the app; its name is the command's.

    Returns
    -------
    callable
        The guarded command, with the same signature (typer reads its options).

    Examples
    --------
    >>> import os, tempfile
    >>> import typer
    >>> from typer.testing import CliRunner
    >>> from assur.views.cli._guard import guarded
    >>> def boom():
    ...     raise RuntimeError("a defect")
    >>> app = typer.Typer()
    >>> _ = app.command()(guarded(boom))
    >>> from unittest import mock
    >>> with tempfile.TemporaryDirectory() as d, \\
    ...         mock.patch.dict(os.environ, {"ASSUR_CACHE_DIR": d}):
    ...     r = CliRunner().invoke(app, [])
    ...     logs = os.listdir(os.path.join(d, "logs"))
    >>> r.exit_code, len(logs), "Traceback" in r.stderr
    (1, 1, False)
    >>> r.stderr.split(" — ")[0]
    'assur boom: internal error: RuntimeError: a defect'
    """
    name = command.__name__

    @functools.wraps(command)
    def run(*args, **kwargs):
        try:
            return command(*args, **kwargs)
        except (typer.Exit, typer.Abort, typer.TyperException, SystemExit):
            raise  # an exit, a usage error: as typer handles them
        except BaseException as e:  # Ctrl+C, MemoryError, a defect
            code = handle(name, e, kwargs)
            if code is None:
                raise
            raise typer.Exit(code) from None

    return run
