"""The memory guard of a sweep (:func:`assur.synthesis.search.scale.sweep`, issue 27):
``samples`` designs, and one task over them (designs × positions), estimated and
refused before a design is drawn; a normal sweep still runs."""

from __future__ import annotations

import numpy as np
import pytest

from assur import io
from assur.errors import ModelError
from assur.io import load_problem
from assur.synthesis.search.scale import Executor, sweep
from tests.helpers.memory import allocates_little, assert_refusal


@pytest.fixture(scope="module")
def problem():
    return load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm


def test_too_many_samples_are_refused_before_drawing(problem, monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    # 1e5 designs: 8.5 MB of rows and 1e5 kernel evaluations without the guard
    with allocates_little(), pytest.raises(ModelError) as e:
        sweep(problem, samples=100_000, seed=0)
    assert_refusal(str(e.value), "--samples")
    assert "samples = 1e+05" in str(e.value) and "1e+05 designs" in str(e.value)


def test_a_billion_samples_under_the_default_limit(problem, monkeypatch):
    monkeypatch.delenv("ASSUR_MAX_MEMORY", raising=False)
    with allocates_little(), pytest.raises(ModelError, match=r"reduce the samples \(--samples\)"):
        sweep(problem, samples=10**9, seed=0)


def test_a_task_of_designs_times_positions_is_checked_per_task(monkeypatch):
    """A sweep streams its designs task by task: the size of one task counts (here
    40 designs × 200 positions × 24 B = 188 KiB), not the whole sweep's."""
    pb = load_problem(io.bundled("hitch_003_design"), positions=200)
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "150 KiB")
    with allocates_little(), pytest.raises(ModelError) as e:
        sweep(pb, samples=40, seed=0, executor=Executor(chunk=40))
    assert_refusal(str(e.value), "--positions", limit="150 KiB")
    assert "40 designs × 200 positions in one kernel call" in str(e.value)
    # tasks of 20 designs fit (94 KiB each) and the sweep runs in two of them
    b = sweep(pb, samples=40, seed=0, executor=Executor(chunk=20))
    assert len(b) == 40


def test_many_positions_are_refused_before_the_kernel(monkeypatch):
    """``--positions 1e7`` (here 1e5 under a 1 MiB limit): one kernel call of the
    sweep would hold designs × positions; refused, not split design by design."""
    pb = load_problem(io.bundled("hitch_003_design"), positions=100_000)
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    with pytest.raises(ModelError) as e:
        sweep(pb, samples=4, seed=0)
    assert_refusal(str(e.value), "--positions")
    assert "4 designs × 100000 positions" in str(e.value)


def test_a_normal_sweep_still_runs(problem, monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "64 MiB")
    b = sweep(problem, samples=200, seed=1)
    assert len(b) == 200 and int(b.feasible.sum()) == 1
    assert np.isfinite(b.objective()).all()
