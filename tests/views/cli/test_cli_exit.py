"""The ``assur`` console script's ending (:mod:`assur.__main__`): the process ends with
the command's status and its whole output, after every exit handler the command
registered, without Python's teardown — and as Python ends it when an error that is
not an exit escapes. Each case runs as its own process and is compared with the
command line run by a plain ``app()`` (Python's own ending)."""

from __future__ import annotations

import os
import subprocess
import sys
import tomllib

import pytest

from assur import io

from tests.helpers import ROOT

HITCH = str(io.bundled("hitch_003"))
#: the command line as the console script runs it, and as a plain call of the app
SCRIPT = "from assur.__main__ import main\nmain()\n"
PLAIN = "from assur.views.cli import app\napp(prog_name='assur')\n"


def _run(code, args, tmp_path):
    env = dict(os.environ, ASSUR_CACHE_DIR=str(tmp_path / "cache"), COLUMNS="100")
    return subprocess.run([sys.executable, "-c", code, *args], capture_output=True,
                          text=True, env=env, cwd=tmp_path, timeout=300)


def test_the_console_script_is_the_ending_entry():
    scripts = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    assert scripts["project"]["scripts"]["assur"] == "assur.__main__:main"


@pytest.mark.parametrize("args, status", [
    (["tables", HITCH], 0),                       # a long answer: every line printed
    (["check", "no-such-model.toml"], 1),         # a user's error: one line on stderr
    (["check", HITCH, "--units", "furlongs"], 1),
    (["check"], 2),                               # a usage error
    (["--version"], 0),
])
def test_status_and_output_as_python_ends_them(tmp_path, args, status):
    ended, plain = _run(SCRIPT, args, tmp_path), _run(PLAIN, args, tmp_path)
    assert ended.returncode == plain.returncode == status, ended.stderr
    assert ended.stdout == plain.stdout and ended.stderr == plain.stderr
    assert len(ended.stdout) + len(ended.stderr) > 0


def test_written_files_are_whole(tmp_path):
    out = tmp_path / "out"
    r = _run(SCRIPT, ["analyze", HITCH, "-o", str(out), "--format", "csv,xlsx"], tmp_path)
    assert r.returncode == 0, r.stderr
    from openpyxl import load_workbook
    book = load_workbook(out / "tables.xlsx", read_only=True)
    assert len(book.sheetnames) > 3
    for path in out.glob("*.csv"):
        text = path.read_text(encoding="utf-8")
        assert text.endswith("\n") and text.count("\n") >= 2, path.name


def test_exit_handlers_of_the_command_run_first(tmp_path):
    """A handler registered while the command runs (as a library registers one) runs
    before the process ends; its output is flushed with the command's."""
    code = ("import atexit\nimport assur.views.cli as cli\nreal = cli.app\n"
            "def app(**kw):\n"
            "    atexit.register(print, 'handler ran')\n"
            "    return real(**kw)\n"
            "cli.app = app\n" + SCRIPT)
    r = _run(code, ["check", HITCH], tmp_path)
    assert r.returncode == 0, r.stderr
    assert r.stdout.rstrip().endswith("handler ran")
    assert "assembles at every position" in r.stdout


def test_an_error_that_is_not_an_exit_ends_as_python_ends_it(tmp_path):
    code = ("import assur.views.cli as cli\n"
            "def app(**kw):\n    raise MemoryError('out of memory in a test')\n"
            "cli.app = app\n" + SCRIPT)
    r = _run(code, ["check", HITCH], tmp_path)
    assert r.returncode == 1
    assert "Traceback" in r.stderr and "MemoryError: out of memory in a test" in r.stderr
