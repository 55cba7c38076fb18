"""The command reference, generated from typer's app (:data:`assur.views.cli.app`).

Every command the app has gets a section with its usage, its help text and a table
of its arguments and options, so a new command appears here by itself.
"""

from __future__ import annotations

from pathlib import Path

import typer

from assur.views import cli


def _cell(text) -> str:
    return " ".join(str(text).split()).replace("|", "\\|")


def _param_row(p) -> str:
    if p.param_type_name == "argument":
        name = f"`{p.name.upper()}`"
        kind = "argument"
    else:
        name = ", ".join(f"`{o}`" for o in (*p.opts, *p.secondary_opts))
        kind = "flag" if getattr(p, "is_flag", False) else "option"
    help_ = _cell(getattr(p, "help", "") or "")
    default = p.default
    if callable(default) or default in (None, "", ()) or getattr(p, "is_flag", False):
        shown = ""
    elif isinstance(default, (list, tuple)):
        shown = ", ".join(map(str, default))
    else:
        shown = str(default)
    req = "yes" if p.required else ""
    return f"| {name} | {kind} | {req} | {_cell(shown)} | {help_} |"


def render() -> str:
    """The Markdown page of every command of ``assur``."""
    group = typer.main.get_command(cli.app)
    ctx = typer.Context(group, info_name="assur")
    lines = ["# Command reference", "",
             "Generated from the command-line app (`assur.views.cli.app`) when the documentation "
             "is built: every command of `assur` and every option, as `assur COMMAND --help` "
             "prints them. `python -m assur` is the same command.", "",
             "Exit status: 0 on success, 1 for every failure a user can cause (a malformed "
             "file, a design that cannot assemble, a condition without a root, an output "
             "that cannot be written) with one message and never a traceback, 2 for usage "
             "errors, 130 when interrupted by Ctrl+C.", "",
             "```text", f"assur [--version] COMMAND [ARGS]...", "```", ""]
    notes = ["## Ranges of the options", "",
             "Every numeric option is checked before the command runs; a value outside its "
             "range is a usage error (exit status 2) that names the option and the range:",
             "",
             "| option | accepted |",
             "|---|---|",
             "| counts: `--samples` (sweep), `--popsize`, `--maxiter`, `--chunk`, `--screen`, "
             "`--starts`, `--columns` | a whole number ≥ 1, also written `2e7` or `20_000` |",
             "| `--positions` (sweep, optimize), `--samples` (tolerance) | a whole number ≥ 2 |",
             "| `--workers`, `--frames`, `--jobs` | a whole number ≥ 0 (0: in this process; no "
             "animation; one process per core) |",
             "| `--seed` | a whole number 0 … 4294967295 (2³² − 1, the range of the seeds "
             "SciPy and pymoo pass to numpy) |",
             "| `--duration` (simulate) | a finite number of seconds > 0 (`nan`, `inf`, 0 and "
             "negative values are refused, never replaced by the file's duration) |",
             "| `--outlier` (fit) | a finite number > 0 |",
             "| `--port` (serve) | 0 … 65535 |",
             "| `--at` (dxf), `--draw-at` (analyze) | comma-separated finite numbers (dxf draws each "
             "position once); outside the model's range: exit status 1 |",
             "| `--scheduler` | `[tcp://]host:port` (or `tls://`, `ws://`, `wss://`, "
             "`ucx://`); it must answer within 10 s, else one message naming the address; "
             "not together with `--workers` |",
             "",
             "## Internal errors and the log file", "",
             "Anything else a command raises is a defect of assur. It prints one line, "
             "`assur COMMAND: internal error: TYPE: MESSAGE — please report it with the log "
             "PATH`, and exits with status 1; the full traceback, the command's options and "
             "the versions are in that log file, never on the terminal. Running out of "
             "memory says which options or file settings to reduce. The log files are in "
             "`$ASSUR_CACHE_DIR/logs` when that is set, else `$XDG_CACHE_HOME/assur/logs`, "
             "else `~/.cache/assur/logs` (`%LOCALAPPDATA%\\assur\\logs` on Windows); the "
             "newest 50 are kept.", ""]
    top = [p for p in group.params if p.name not in ("help",)]
    if top:
        lines += ["Options of `assur` itself:", "",
                  "| name | kind | required | default | meaning |",
                  "|---|---|---|---|---|"]
        lines += [_param_row(p) for p in top]
        lines.append("")
    lines += notes
    for name in sorted(group.list_commands(ctx)):
        cmd = group.get_command(ctx, name)
        args = [p.name.upper() + ("..." if p.nargs == -1 else "")
                for p in cmd.params if p.param_type_name == "argument"]
        usage = " ".join(["[OPTIONS]", *args])
        lines += [f"## `assur {name}`", "", "```text", f"assur {name} {usage}", "```", ""]
        lines += [(cmd.help or "").strip(), ""]
        params = [p for p in cmd.params if p.name != "help"]
        if params:
            lines += ["| name | kind | required | default | meaning |",
                      "|---|---|---|---|---|"]
            lines += [_param_row(p) for p in params]
            lines.append("")
    return "\n".join(lines) + "\n"


def write(path: Path) -> None:
    """Write the page to ``path`` (only when it changed, so Sphinx rebuilds nothing else)."""
    text = render()
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")
