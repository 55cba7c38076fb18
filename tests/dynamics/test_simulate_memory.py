"""The memory guard of a simulation (:func:`assur.dynamics.simulate.simulate`, issue 27):
the output times × the states, rates, pressures, flows and the mass matrix, estimated
and refused before the integration; a normal simulation still runs."""

from __future__ import annotations

import numpy as np
import pytest

from assur import io
from assur.dynamics import simulate, simulate_model
from assur.errors import ModelError
from tests.helpers.memory import allocates_little, assert_refusal


@pytest.fixture(scope="module")
def model():
    return io.load(io.bundled("adapter_lab6"))  # seed 001 lab 6


def test_too_many_output_times_are_refused_before_integrating(model, monkeypatch):
    simulate(model.mechanism, model.drive, 0.1, t_eval=[0.0, 0.1])  # tables built
    t_eval = np.linspace(0.0, 1.0, 100_000)
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    # 1e5 output times: about 66 MB of results without the guard
    with allocates_little(), pytest.raises(ModelError) as e:
        simulate(model.mechanism, model.drive, 1.0, t_eval=t_eval)
    assert_refusal(str(e.value), "[simulation] outputs")
    assert "simulation: 1e+05 output times" in str(e.value)


def test_the_file_outputs_key_is_named(model, monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    text = io.bundled("adapter_lab6").read_text(encoding="utf-8")
    assert "outputs = 2251" in text
    text = text.replace("outputs = 2251", "outputs = 1000000")
    m = io.loads(text, name="lab6.toml")
    with pytest.raises(ModelError, match=r"reduce \[simulation\] outputs"):
        simulate_model(m)


def test_a_normal_simulation_still_runs(model, monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "64 MiB")
    r = simulate_model(model)
    assert r.success and len(r.t) == model.simulation.outputs
