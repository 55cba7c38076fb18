"""The design report (:mod:`assur.views.report.design`) on the bundled seed-003 design
problem: the curves it draws for a design are what an analysis of that design gives
(the report path, not the fused kernel the search uses), for the original and for a
moved design; the comparison page names the result's design and its own counts."""

import numpy as np
import pytest

from assur import io
from assur.io import load_problem
from assur.views.report.design import comparison_html, curves


@pytest.fixture(scope="module")
def problem():
    return load_problem(io.bundled("hitch_003_design"))


@pytest.mark.parametrize("shift", [0.0, 0.01])
def test_curves_are_an_analysis_of_the_design(problem, shift):
    x = problem.x0 + shift
    c = curves(problem, x)
    a = problem.with_design(x).analyze(problem.positions)
    np.testing.assert_allclose(c["Y(56)"], a.kinematics.y("56"), rtol=1e-9)
    np.testing.assert_allclose(c["p(ГЦ)"], a.cylinder().pressure, rtol=1e-9)
    np.testing.assert_allclose(c["I(S6)"], a.kinematics.transmission("S6"), rtol=1e-9)


def test_the_comparison_page(problem):
    from assur.synthesis.search.search import optimize
    res = optimize(problem, popsize=3, maxiter=1, seed=0, polish=False)
    page = comparison_html(problem, res)
    assert f"{res.evaluations} designs" in page and "<figure>" in page
    ru = comparison_html(problem, res, lang="ru")
    assert ru != page and "<figure>" in ru
    with pytest.raises(ValueError):
        comparison_html(problem, res, lang="de")
