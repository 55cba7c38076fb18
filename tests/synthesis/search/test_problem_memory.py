"""A design problem's memory estimates (:class:`assur.synthesis.search.problem.Problem`,
issue 27): a batch refused before its kernel call when one call's designs ×
positions exceed the limit, rather than split in halves down to single designs."""

from __future__ import annotations

import numpy as np
import pytest

from assur import io
from assur.errors import ModelError
from assur.io import load_problem
from tests.helpers.memory import assert_refusal


@pytest.fixture(scope="module")
def problem():
    return load_problem(io.bundled("hitch_003_design"))  # 8 variables, 50 positions


def test_one_kernel_call_is_checked_before_it_runs(problem, monkeypatch):
    X = problem.sample(100, seed=0)
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "100 KiB")  # 100 × 50 × 24 B = 117 KiB
    with pytest.raises(ModelError) as e:
        problem.evaluate(X)
    assert_refusal(str(e.value), "--positions", limit="100 KiB")
    assert "100 designs × 50 positions in one kernel call" in str(e.value)
    b = problem.evaluate(X[:50])  # 59 KiB: evaluated
    assert len(b) == 50 and np.isin(b.status, [0, 1, 2, 3, 4]).all()


def test_the_estimates(problem):
    assert problem.bytes_per_position == 24  # q and status, one coordinate [bytes]
    nv, nc, no, nout = 8, 3, 1, len(problem.outputs)
    assert problem.bytes_per_design == 16 * (2 * nv + 3 * nc + no + 8 * nout + 10)
