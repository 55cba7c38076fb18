"""The command line's last-resort handler (issue 27): an unexpected exception inside a
command is one line on stderr with "please report" and the log file, exit status 1,
never a traceback on the terminal; the traceback is in the log; MemoryError says what
to reduce; Ctrl+C exits with 130."""

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from assur.errors import ModelError
from assur.io import bundled
from assur.views.cli import _guard, app

from tests.helpers import ROOT

runner = CliRunner()


@pytest.fixture
def logs(tmp_path, monkeypatch):
    """The log directory, under a temporary ``$ASSUR_CACHE_DIR``."""
    monkeypatch.setenv("ASSUR_CACHE_DIR", str(tmp_path / "cache"))
    return tmp_path / "cache" / "logs"


def _raise(exc):
    def boom(*args, **kwargs):
        raise exc
    return boom


def _log_named(line: str) -> Path:
    m = re.search(r"(?:the log is|with the log) (\S+\.log)$", line)
    assert m, line
    return Path(m[1])


def test_runtime_error_is_one_line_and_the_traceback_is_in_the_log(logs, monkeypatch):
    monkeypatch.setattr("assur.io.load", _raise(RuntimeError("the engine broke\nbadly")))
    r = runner.invoke(app, ["check", str(bundled("hitch_003"))])
    assert r.exit_code == 1
    assert isinstance(r.exception, SystemExit)
    line = r.stderr.strip()
    assert "\n" not in line, r.stderr
    assert line.startswith("assur check: internal error: RuntimeError: the engine broke "
                           "badly — please report it with the log "), line
    assert "Traceback" not in r.output and "Traceback" not in r.stderr
    log = _log_named(line)
    assert log.parent == logs and log.is_file()
    text = log.read_text(encoding="utf-8")
    assert "Traceback (most recent call last)" in text
    assert "RuntimeError: the engine broke" in text and "def boom" not in text
    assert "in boom" in text and "hitch_003" in text  # the frame and the options


def test_memory_error_says_what_to_reduce(logs, monkeypatch):
    monkeypatch.setattr("assur.io.load", _raise(MemoryError("Unable to allocate 7.45 GiB")))
    r = runner.invoke(app, ["tolerance", str(bundled("hitch_003_tolerances"))])
    assert r.exit_code == 1
    line = r.stderr.strip()
    assert "\n" not in line and "Traceback" not in r.stderr
    assert line.startswith("assur tolerance: out of memory (Unable to allocate 7.45 GiB): "
                           "reduce --samples"), line
    assert "MemoryError" in _log_named(line).read_text(encoding="utf-8")


def test_numpy_memory_error_in_a_sweep(logs, monkeypatch):
    import numpy as np

    def huge(*args, **kwargs):
        return np.empty(2**47)  # 1 PiB
    monkeypatch.setattr("assur.synthesis.search.scale.sweep_to", huge)
    r = runner.invoke(app, ["sweep", str(bundled("hitch_003_design")), "--workers", "0",
                            "--samples", "3", "-o", str(logs.parent / "x.parquet")])
    assert r.exit_code == 1, r.output
    line = r.stderr.strip()
    assert "out of memory (Unable to allocate" in line and "reduce --samples, --positions or "\
        "--chunk" in line, line
    assert "Traceback" not in r.output


def test_keyboard_interrupt_exits_130_with_one_line(logs, monkeypatch):
    monkeypatch.setattr("assur.io.load", _raise(KeyboardInterrupt()))
    r = runner.invoke(app, ["check", str(bundled("hitch_003"))])
    assert r.exit_code == 130
    assert r.stderr.strip() == "assur check: interrupted (Ctrl+C)"
    assert not logs.exists()  # nothing to report


def test_a_typed_error_no_command_caught_keeps_its_message(logs, monkeypatch):
    """The typed errors of assur stay one 'error:' line of their own, with no log."""
    monkeypatch.setattr("assur.views.report.tables.seed_tables",
                        _raise(ModelError("hitch_003.toml:12: [range] is empty")))
    r = runner.invoke(app, ["tables", str(bundled("hitch_003"))])
    assert r.exit_code == 1
    assert r.stderr.strip() == "error: hitch_003.toml:12: [range] is empty"
    assert not logs.exists()


def test_usage_errors_and_exits_pass_through(logs):
    r = runner.invoke(app, ["check", "no/such.toml"])
    assert r.exit_code == 1 and "no such file" in r.output and "internal" not in r.output
    r = runner.invoke(app, ["sweep", "x.toml", "--samples", "0"])
    assert r.exit_code == 2 and "internal" not in r.output
    assert not logs.exists()


def test_an_unwritable_log_directory_is_said_in_the_line(tmp_path, monkeypatch):
    (tmp_path / "file").write_text("not a directory")
    monkeypatch.setenv("ASSUR_CACHE_DIR", str(tmp_path / "file"))
    monkeypatch.setattr("assur.io.load", _raise(ZeroDivisionError("division by zero")))
    r = runner.invoke(app, ["check", str(bundled("hitch_003"))])
    assert r.exit_code == 1
    line = r.stderr.strip()
    assert "\n" not in line and "Traceback" not in line
    assert line.startswith("assur check: internal error: ZeroDivisionError: division by zero "
                           "— please report it (the traceback could not be written: "), line


def test_the_log_directory_honours_xdg_cache_home(tmp_path, monkeypatch):
    monkeypatch.delenv("ASSUR_CACHE_DIR", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert _guard.log_dir() == tmp_path / "xdg" / "assur" / "logs"
    monkeypatch.setattr("assur.io.load", _raise(RuntimeError("x")))
    r = runner.invoke(app, ["check", str(bundled("hitch_003"))])
    assert r.exit_code == 1
    assert _log_named(r.stderr.strip()).parent == tmp_path / "xdg" / "assur" / "logs"


def test_old_logs_are_pruned(logs, monkeypatch):
    monkeypatch.setattr(_guard, "KEEP", 3)
    monkeypatch.setattr("assur.io.load", _raise(RuntimeError("x")))
    for _ in range(5):
        assert runner.invoke(app, ["check", str(bundled("hitch_003"))]).exit_code == 1
    assert len(list(logs.glob("assur-check-*.log"))) == 3


def test_every_command_is_guarded():
    names = []
    for c in app.registered_commands:
        assert c.callback.__code__ is _guard.guarded(lambda: None).__code__, c.callback
        names.append(c.callback.__wrapped__.__name__)
    assert {"check", "analyze", "sweep", "optimize", "tolerance", "fit", "simulate", "cycles",
            "dxf", "serve", "tables", "demo"} <= set(names)


def test_an_exception_while_parsing_is_one_line_too(logs, monkeypatch, capsys):
    """What escapes typer itself (here: a parser that breaks) is caught by the app."""
    from assur.views.cli import _types

    monkeypatch.setattr(_types.Count, "__call__", _raise(ArithmeticError("parser broke")))
    with pytest.raises(SystemExit) as e:
        app(args=["tables", str(bundled("hitch_003")), "--columns", "3"], prog_name="assur")
    assert e.value.code == 1
    err = capsys.readouterr().err.strip()
    assert err.startswith("assur tables: internal error: ArithmeticError: parser broke — "
                          "please report it with the log "), err
    assert "Traceback" not in err


def test_the_console_script_prints_no_traceback(tmp_path):
    """The installed entry point (``assur.__main__:main``) in its own process, with the
    loader broken: one line on the real stderr, exit 1, the traceback in the log."""
    code = ("import sys, assur.io as io\n"
            "def boom(*a, **k):\n    raise RuntimeError('broken in a subprocess')\n"
            "io.load = boom\n"
            "from assur.__main__ import main\n"
            "main()\n")
    env = dict(os.environ, ASSUR_CACHE_DIR=str(tmp_path), COLUMNS="60")
    p = subprocess.run([sys.executable, "-c", code, "check", str(bundled("hitch_003"))],
                       capture_output=True, text=True, env=env, cwd=ROOT, timeout=120)
    assert p.returncode == 1, p.stderr
    line = p.stderr.strip()
    assert "\n" not in line and "Traceback" not in p.stderr, p.stderr
    assert "internal error: RuntimeError: broken in a subprocess" in line
    assert "broken in a subprocess" in _log_named(line).read_text(encoding="utf-8")
