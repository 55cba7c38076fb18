"""The memory guard of a simulation's animation
(:func:`assur.views.report.simulation.write_simulation_report`, issue 27): a frame
every 0.1 s of the simulated time, each a raster image for the GIF and a vector
frame for the HTML player, estimated and refused before anything is computed or
written (a simulated year: 3.2e8 frames); ``assur simulate`` says so in one line;
a normal report is still written."""

from __future__ import annotations

import pytest
from typer.testing import CliRunner

from assur import io
from assur.dynamics import simulate
from assur.errors import ModelError
from assur.views.cli import app
from assur.views.report.simulation import check_frames, write_simulation_report
from tests.helpers.memory import allocates_little, assert_refusal

YEAR = 365.25 * 86400  # [s]


@pytest.fixture(scope="module")
def model():
    return io.load(io.bundled("adapter_lab6"))  # seed 001 lab 6


@pytest.fixture(scope="module")
def result(model):
    return simulate(model.mechanism, model.drive, 1.0, t_eval=[0.0, 0.5, 1.0])  # t [s]


def test_a_year_of_frames_is_refused_under_the_default_limit(model, monkeypatch):
    monkeypatch.delenv("ASSUR_MAX_MEMORY", raising=False)
    with allocates_little(), pytest.raises(ModelError) as e:
        check_frames(YEAR, mechanism=model.mechanism)
    assert "3.156e+08 frames" in str(e.value)
    assert "reduce [simulation] duration (or --duration)" in str(e.value)


def test_the_report_refuses_before_writing_anything(model, result, tmp_path, monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")  # 11 frames of 1 s: about 9 MiB
    with allocates_little(), pytest.raises(ModelError) as e:
        write_simulation_report(result, tmp_path, model=model)
    assert_refusal(str(e.value), "[simulation] duration")
    assert "the animation of 1 s, a frame every 0.1 s: 11 frames" in str(e.value)
    assert list(tmp_path.iterdir()) == []


def test_without_an_animation_nothing_is_refused(model, result, tmp_path, monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    files = write_simulation_report(result, tmp_path, formats=("csv",), model=model)
    assert [p.name for p in files] == ["simulation.csv", "simulation_summary.csv"]


def test_a_normal_report_is_still_written(model, result, tmp_path, monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "64 MiB")
    files = write_simulation_report(result, tmp_path, formats=("gif",), model=model)
    assert [p.name for p in files] == ["simulation.gif"]


def test_assur_simulate_says_so_in_one_line(tmp_path, monkeypatch):
    # the results of 2251 output times fit (1.5 MiB), 21 frames of 2 s do not (17 MiB)
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "4 MiB")
    r = CliRunner().invoke(app, ["simulate", str(io.bundled("adapter_lab6")), "-o",
                                 str(tmp_path / "out"), "--duration", "2"])
    assert r.exit_code == 1, r.output
    assert "Traceback" not in r.output and "please report" not in r.output
    assert "21 frames would need about" in r.output and "--duration" in r.output
