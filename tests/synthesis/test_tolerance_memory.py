"""The memory guard of the Monte Carlo over tolerances
(:func:`assur.synthesis.tolerance.monte_carlo`, issue 27): ``samples`` machines ×
positions × outputs estimated and refused before a machine is drawn; a normal run
still passes."""

from __future__ import annotations

import numpy as np
import pytest

from assur import examples
from assur.errors import ModelError
from assur.synthesis.tolerance import Tolerance, monte_carlo
from tests.helpers.memory import allocates_little, assert_refusal

Q = np.linspace(0.425, 0.665, 6)
TOL = [Tolerance("P6", 2000.0), Tolerance("L4", 0.5e-3)]


def test_too_many_machines_are_refused_before_drawing(monkeypatch):
    m = examples.hitch_003()
    m.evaluate(Q, outputs=["p(ГЦ)"])  # compiled before the measurement
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    # 1e5 machines × 6 positions: about 20 MB of values without the guard
    with allocates_little(), pytest.raises(ModelError) as e:
        monte_carlo(m, Q, TOL, outputs=["p(ГЦ)"], samples=100_000, seed=0)
    assert_refusal(str(e.value), "--samples")
    assert "samples = 100000 over 6 positions" in str(e.value)
    assert "1e+05 machines" in str(e.value)


def test_a_billion_samples_under_the_default_limit(monkeypatch):
    m = examples.hitch_003()
    monkeypatch.delenv("ASSUR_MAX_MEMORY", raising=False)
    with allocates_little(), pytest.raises(ModelError, match="--samples"):
        monte_carlo(m, Q, TOL, outputs=["p(ГЦ)"], samples=10**9, seed=0)


def test_a_normal_run_still_passes(monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "64 MiB")
    r = monte_carlo(examples.hitch_003(), Q, TOL, outputs=["p(ГЦ)"], samples=200, seed=1)
    assert r.samples.shape == (200, 6, 1) and r.assembled.all()
