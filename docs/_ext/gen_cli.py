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
             "errors.", "",
             "```text", f"assur [--version] COMMAND [ARGS]...", "```", ""]
    top = [p for p in group.params if p.name not in ("help",)]
    if top:
        lines += ["Options of `assur` itself:", "",
                  "| name | kind | required | default | meaning |",
                  "|---|---|---|---|---|"]
        lines += [_param_row(p) for p in top]
        lines.append("")
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
