"""Design problems (:mod:`assur.synthesis.search.problem`) on the bundled seed-003
hitch problem: a batch's criterion values are what an analysis of each design gives
(the fused kernel's reductions against the array path), its margins and status
follow from them, designs are evaluated independently of their batch, and a design
that cannot assemble says so in words."""

import numpy as np
import pytest

from assur import io
from assur.io.problems import load_problem
from assur.synthesis.search.problem import ASSEMBLY, CONSTRAINT, FAILURE_TEXT, FEASIBLE


@pytest.fixture(scope="module")
def problem():
    return load_problem(io.bundled("hitch_003_design"))


@pytest.fixture(scope="module")
def designs(problem):
    X = problem.sample(12, seed=4)
    X = np.vstack([problem.x0, X])
    X[3, problem.names.index("X03")] += 0.8  # cannot assemble
    return X, problem.evaluate(X)


def test_values_are_those_of_an_analysis_of_each_design(problem, designs):
    X, b = designs
    names = [c.name for c in problem.constraints]
    assert names == ["min Y(56)", "max Y(56)", "max p(ГЦ)"]
    for i in (0, 1, 2):
        a = problem.with_design(X[i]).analyze(problem.positions)
        y = a.kinematics.y("56")
        want = [y.min(), y.max(), a.cylinder().pressure.max()]
        np.testing.assert_allclose(b.values[i], want, rtol=1e-9)


def test_status_follows_the_margins(problem, designs):
    X, b = designs
    assert b.status[0] == FEASIBLE and b.status[3] == ASSEMBLY
    assert "does not assemble" in b.reasons[3]
    assert any(text in b.reasons[3] for text in FAILURE_TEXT.values())
    ok = b.status != ASSEMBLY
    violated = (b.margins[ok] < 0).any(axis=1)
    assert ((b.status[ok] == CONSTRAINT) == violated).all()
    assert ((b.status[ok] == FEASIBLE) == ~violated).all()
    assert (b.feasible == (b.status == FEASIBLE)).all()


def test_designs_do_not_depend_on_their_batch(problem, designs):
    X, b = designs
    for i in (1, 3, 7):
        one = problem.evaluate(X[i:i + 1])
        assert one.status[0] == b.status[i]
        np.testing.assert_array_equal(one.values[0], b.values[i])
        np.testing.assert_array_equal(one.objectives[0], b.objectives[i])
