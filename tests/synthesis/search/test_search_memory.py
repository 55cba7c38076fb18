"""The memory guard of the searches (:func:`assur.synthesis.search.search.optimize`,
:func:`~assur.synthesis.search.search.pareto`, issue 27): the population
(``--popsize`` × variables designs) estimated and refused before scipy or pymoo
allocates it; a normal search still runs."""

from __future__ import annotations

import pytest

from assur import io
from assur.errors import ModelError
from assur.io import load_problem
from assur.synthesis.search import Problem, criterion
from assur.synthesis.search.search import optimize, pareto
from tests.helpers.memory import allocates_little, assert_refusal


@pytest.fixture(scope="module")
def problem():
    import pymoo.algorithms.moo.nsga2  # noqa: F401  (imported before the measurements)
    import pymoo.optimize  # noqa: F401
    import scipy.optimize  # noqa: F401
    from assur.synthesis.search import polish  # noqa: F401
    return load_problem(io.bundled("hitch_003_design"))  # seed-003 hitch, pivots ±30 mm


def test_a_huge_population_is_refused_before_scipy_allocates_it(problem, monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    # popsize 1e4 × 8 variables: 8e4 designs (scipy's population, its trial copy, …)
    with allocates_little(), pytest.raises(ModelError) as e:
        optimize(problem, popsize=10_000, maxiter=1, seed=0, polish=False)
    assert_refusal(str(e.value), "--popsize")
    assert "popsize = 10000 (a population of 8e+04 designs)" in str(e.value)


def test_popsize_a_million_under_the_default_limit(problem, monkeypatch):
    monkeypatch.delenv("ASSUR_MAX_MEMORY", raising=False)
    with allocates_little(), pytest.raises(ModelError, match="--popsize"):
        optimize(problem, popsize=10**6, maxiter=1, seed=0, polish=False)


def test_a_huge_pareto_population_is_refused(problem, monkeypatch):
    lift = criterion("bound", {"quantity": "Y(56)", "of": "span"}, problem.original,
                     sense="maximize")
    two = Problem(problem.original, problem.positions[::5], problem.variables[:2],
                  [problem.constraints[2]], [problem.objectives[0], lift])
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    with allocates_little(), pytest.raises(ModelError) as e:
        pareto(two, pop_size=10_000, generations=1, seed=0)
    assert_refusal(str(e.value), "--popsize")
    assert "pop_size = 10000" in str(e.value)


def test_a_normal_search_still_runs(problem, monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "64 MiB")
    top = Problem(problem.original, problem.positions[::5], problem.variables[6:],
                  problem.constraints, problem.objectives)  # the top-link pivot 07 moves
    r = optimize(top, popsize=5, maxiter=3, seed=0, polish=False)
    assert r.feasible and r.value >= float(r.original.objectives[0, 0])
