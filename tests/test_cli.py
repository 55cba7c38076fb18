"""The command line: check, analyze, demo — exit codes, messages, files written."""

import csv
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from assur.cli import app
from assur.io import bundled

from seed_tables import T003_2_1, T003_3_1a, T003_4_1, assert_printed

runner = CliRunner()


def test_check_bundled_hitch_ok():
    r = runner.invoke(app, ["check", str(bundled("hitch_003"))])
    assert r.exit_code == 0, r.output
    assert "assembles at every position" in r.output
    assert "solved L4" in r.output and "0.661283167" in r.output


def test_check_header_000_fails_with_the_triangle_message():
    r = runner.invoke(app, ["check", str(bundled("header_000"))])
    assert r.exit_code == 1
    out = " ".join(r.output.split())
    assert "L4 exceeds L3 + L34 = 0.65234 m by 4.66 mm" in out
    assert "Traceback" not in r.output


def test_check_missing_file():
    r = runner.invoke(app, ["check", "no/such/model.toml"])
    assert r.exit_code == 1 and "no such file" in r.output


def test_analyze_writes_seed_tables(tmp_path):
    out = tmp_path / "rep"
    r = runner.invoke(app, ["analyze", str(bundled("hitch_003")), "-o", str(out),
                            "--format", "csv,html"])
    assert r.exit_code == 0, r.output
    assert (out / "report.html").exists()
    csvs = sorted(p.name for p in out.glob("*.csv"))
    assert csvs, r.output


def test_bad_options_exit_1(tmp_path):
    r = runner.invoke(app, ["analyze", str(bundled("hitch_003")), "--lang", "de"])
    assert r.exit_code == 1 and "--lang must be one of" in r.output
    r = runner.invoke(app, ["analyze", str(bundled("hitch_003")), "--format", "pdf"])
    assert r.exit_code == 1 and "--format must be" in r.output
