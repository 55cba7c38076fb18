"""Exact gradients of the design criteria and the SLSQP polish after differential
evolution (issue 12: docs/design.md, "Polishing with exact gradients") on the seed 003
hitch design problem."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import io
from assur.synthesis.search import CRITERIA, Limit, Problem, Variable, criterion
from assur.io import load_problem
from assur.synthesis.search.criteria import _Kind
from assur.synthesis.search.problem import CONSTRAINT, FEASIBLE
from assur.synthesis.search.polish import missing_gradients, polish
from assur.synthesis.search.search import optimize
from assur.errors import ModelError
from tests.helpers import examples as n_examples

HITCH = io.bundled("hitch_003_design")
H = 1e-6          # central-difference step [m] (the bounds span 60 mm)
RTOL = 1e-5


@pytest.fixture(scope="module")
def problem():
    return load_problem(HITCH)


@pytest.fixture(scope="module")
def wide(problem):
    """The hitch problem with one criterion of every kind that has a gradient: the
    file's (bounds min/max of Y(56), the pressure, the reserve objective) and a
    capacity, a span, a box of a moving point and a box of a frame pivot, two
    transmission angles (rocker 4–5 at 45, links 6–7 at 67); the relief
    setting a variable too (the pressure limit's own gradient)."""
    mech = problem.original
    extra = [
        criterion("capacity", {"cylinder": "ГЦ", "point": "S6"}, mech,
                  limit=Limit(20e3, "at_least")),
        criterion("bound", {"quantity": "Y(S6)", "of": "span"}, mech,
                  limit=Limit(2.0, "at_most")),
        criterion("bound", {"quantity": "p(ГЦ)", "of": "min"}, mech,
                  limit=Limit(0.0, "at_least")),
        criterion("box", {"point": "56", "x": [-2.0, 2.0], "y": [0.0, 1.2]}, mech,
                  limit=Limit(0.0, "at_least")),
        criterion("box", {"point": "01", "x": [0.3, 0.5], "y": [0.5, 0.6]}, mech,
                  limit=Limit(0.0, "at_least")),
        criterion("transmission_angle", {"links": ["4", "5"]}, mech,
                  limit=Limit(0.3, "at_least")),
        criterion("transmission_angle", {"links": ["6", "7"]}, mech,
                  limit=Limit(0.3, "at_least")),
    ]
    relief = problem.constraints[2].args["relief"]
    p0 = float(mech.params[relief])
    variables = problem.variables + (Variable(relief, 0.9 * p0, 1.2 * p0),)
    return Problem(mech, problem.positions, variables, problem.constraints + tuple(extra),
                   problem.objectives)


def _feasible_design(pb, seed):
    """A design drawn uniformly within the bounds that assembles and lifts over the
    whole range, so that every criterion has a value (a constraint may not hold: the
    file's lift-range constraints are tight at the original, most draws miss them)."""
    X = pb.sample(64, seed=seed)
    b = pb.evaluate(X)
    ok = np.flatnonzero((b.status == FEASIBLE) | (b.status == CONSTRAINT))
    assert len(ok), "no design among 64 draws assembles and lifts"
    return X[ok[0]]


def _central(pb, x, what):
    """Central differences of the criteria's values (``what``: "values" or
    "objectives"), one batch of the 2·(number of variables) neighbours, step H in the
    lengths and H·(scale of the variable) otherwise."""
    nv = len(x)
    h = np.array([H * max(1.0, abs(v)) if abs(v) > 10 else H for v in x])
    X = np.repeat(x[None], 2 * nv, axis=0)
    X[np.arange(nv), np.arange(nv)] += h
    X[nv + np.arange(nv), np.arange(nv)] -= h
    b = pb.evaluate(X)
    v = getattr(b, what)
    return ((v[:nv] - v[nv:]) / (2 * h[:, None])).T  # (criteria, variables)


def _close(got, ref, label, scale):
    """|got − ref| ≤ RTOL · the gradient's largest component (a partial of 0 — a pivot
    that does not move an output — is compared at that scale)."""
    err = np.abs(got - ref).max()
    assert err <= RTOL * scale, (f"{label}: exact {got} against central differences {ref}: "
                                 f"worst error {err:.3g}, scale {scale:.3g}")


@settings(max_examples=n_examples(10))
@given(seed=st.integers(0, 2**31 - 1))
def test_criteria_gradients_equal_central_differences(wide, seed):
    """Every criterion with a gradient (bound min/max/span, capacity, pressure, box of a
    moving point and of a frame pivot, transmission angle, the reserve objective): the
    exact gradient (the
    sensitivity at the active position) equals central differences of the value the
    batch evaluation gives, at random designs within the bounds that assemble and lift
    over the range; the
    pressure constraint's margin gradient includes its limit's (the relief setting)."""
    pb = wide
    x = _feasible_design(pb, seed)
    sens, red = pb.jet(x)
    fd = _central(pb, x, "values")
    for i, c in enumerate(pb.constraints):
        assert c.gradient is not None, c.name
        # the jets' value is the kernel's
        assert float(c.value(red)[0]) == pytest.approx(pb.evaluate(x[None]).values[0, i],
                                                       rel=1e-9, abs=1e-12)
        g = c.gradient(sens, red)
        _close(g, fd[i], c.name, max(np.abs(fd[i]).max(), 1e-12))
    fo = _central(pb, x, "objectives")
    o = pb.objectives[0]
    _close(o.gradient(sens, red), fo[0], o.name, np.abs(fo[0]).max())
    # the margin of "max p ≤ relief (a variable)": −∂p/∂x + e_relief
    j = pb.names.index(pb.constraints[2].args["relief"])
    mg = pb.constraints[2].margin_gradient(sens, red, pb.names)
    assert mg[j] == pytest.approx(1.0 - fd[2][j], abs=1e-9)
    np.testing.assert_allclose(np.delete(mg, j), -np.delete(fd[2], j),
                               atol=RTOL * np.abs(fd[2]).max())


def test_polish_from_a_short_search_improves_strictly(problem):
    """A small DE budget (popsize 5, 5 generations, seed 0) leaves room: the polish
    (SLSQP with the exact gradients) finds a strictly better design that the batch
    evaluation finds feasible over the whole range."""
    de = optimize(problem, popsize=5, maxiter=5, seed=0, polish=False)
    assert de.feasible and de.polished is None
    res = optimize(problem, popsize=5, maxiter=5, seed=0)
    p = res.polished
    assert p.ran and p.accepted, p.summary()
    np.testing.assert_array_equal(p.start, de.x)
    assert p.start_value == de.value
    assert res.feasible and res.value == p.value
    assert res.value > de.value, f"DE {de.value} → polished {res.value}"
    assert res.verified == ""
    assert p.nit >= 1 and p.njev >= 1 and p.nfev >= p.njev
    lo, hi = problem.bounds.T
    assert ((res.x >= lo) & (res.x <= hi)).all()
    b = problem.evaluate(res.x[None])
    assert b.feasible[0] and b.objectives[0, 0] == res.value
    assert "→" in p.summary() and "gradient evaluations" in p.summary()


def test_polish_of_the_bundled_problem_is_feasible_and_not_worse(problem):
    """The bundled run of the tests (popsize 10, 60 generations, seed 1): the polish
    keeps a feasible design at least as good as the DE optimum it starts from."""
    res = optimize(problem, popsize=10, maxiter=60, seed=1)
    p = res.polished
    assert res.feasible and p is not None and p.ran
    assert res.value >= p.start_value, f"DE {p.start_value} → polished {res.value}"
    if p.accepted:
        assert res.value == p.value
    else:
        assert p.note and res.value == p.start_value, p.summary()


def test_polish_keeps_the_start_when_the_polished_design_fails(problem):
    """The polished design is judged by the batch evaluation: one that says every
    design fails a constraint makes the polish keep the start and say why."""
    x = problem.x0
    b0 = problem.evaluate(x[None])

    def judge(X):
        b = problem.evaluate(X)
        b.status[:] = 4
        b.detail[:] = 1
        b.where[:] = 49
        return b
    p = polish(problem, x, start_batch=b0, evaluate=judge)
    assert p.ran and not p.accepted
    np.testing.assert_array_equal(p.x, x)
    assert p.note.startswith("the polished design is not feasible: constraint max Y(56)")
    assert "kept the start" in p.summary()


class _NoGradient(_Kind):
    """A criterion kind without an exact gradient (the contract's default): the
    smallest Y of a point over the range."""

    name = "no_gradient"

    def make(self, args, mech):
        q = f"Y({args['point']})"
        return f"min {q}", (q,), (), "length"

    def value(self, c, red):
        return red.mins[c.outputs[0]]


def test_a_criterion_without_gradient_skips_the_polish(monkeypatch):
    """A criterion of a kind without an exact gradient: the polish is skipped with a
    note naming it, not an exception, and the DE result stands."""
    monkeypatch.setitem(CRITERIA, "no_gradient", _NoGradient())
    base = load_problem(HITCH)
    mech = base.original
    low = criterion("no_gradient", {"point": "56"}, mech, limit=Limit(0.25, "at_most"))
    assert low.gradient is None
    pb = Problem(mech, base.positions, base.variables, base.constraints + (low,),
                 base.objectives)
    assert missing_gradients(pb) == [f"no_gradient {low.name}"]
    res = optimize(pb, popsize=4, maxiter=2, seed=0)
    p = res.polished
    assert not p.ran and not p.accepted
    assert p.note == "no exact gradient for no_gradient min Y(56)"
    assert p.summary() == f"polish skipped: {p.note}"
    np.testing.assert_array_equal(res.x, p.start)
    with pytest.raises(ModelError, match="min Y\\(56\\): a no_gradient criterion has no "
                                         "exact gradient"):
        low.margin_gradient(*base.jet(base.x0), base.names)


def test_transmission_angle_in_line_has_no_derivative():
    """Links in line at the active position: the transmission angle's gradient is a
    ModelError naming the criterion and the position, not an infinite number."""
    from assur.synthesis.search.criteria import Reductions
    mech = io.load(io.bundled("hitch_003")).mechanism
    mu = criterion("transmission_angle", {"links": ["4", "5"]}, mech,
                   limit=Limit(0.3, "at_least"))
    oa, ob, od = mu.outputs
    one = {oa: np.array([0.3]), ob: np.array([0.4]), od: np.array([0.7])}
    at = {o: np.array([3]) for o in one}
    red = Reductions(one, dict(one), at, dict(at), lambda ref: np.zeros(1))
    assert mu.value(red)[0] == pytest.approx(0.0, abs=1e-7)
    with pytest.raises(ModelError, match="transmission angle 4–5 at 45: the links are in "
                                         "line at position 3"):
        mu.gradient(None, red)


def test_cli_optimize_polish_and_no_polish(tmp_path):
    """``assur optimize FILE --polish`` writes the model file and says DE → polished
    with the iterations and gradient evaluations (in its output, the file's header
    and the report); ``--no-polish`` does not polish."""
    from typer.testing import CliRunner

    from assur.views.cli import app
    args = ["optimize", str(HITCH), "--popsize", "5", "--maxiter", "5", "--seed", "0",
            "--workers", "0"]
    r = CliRunner().invoke(app, args + ["--polish", "-o", str(tmp_path / "a")])
    assert r.exit_code == 0, r.output
    out = " ".join(r.output.split())
    assert "polish (SLSQP, exact gradients):" in out and "gradient evaluations" in out
    f = tmp_path / "a" / "hitch_003_design_best.toml"
    assert "# polish (SLSQP, exact gradients):" in f.read_text(encoding="utf-8")
    assert "Polish (SLSQP with exact gradients)" in (tmp_path / "a" / "design.html").read_text(
        encoding="utf-8")
    best = io.load(f)
    pb = load_problem(HITCH)
    x = np.array([best.mechanism.params[n] for n in pb.names])
    assert pb.evaluate(x[None]).feasible[0]
    r = CliRunner().invoke(app, args + ["--no-polish", "-o", str(tmp_path / "b")])
    assert r.exit_code == 0, r.output
    assert "SLSQP" not in r.output and "polish skipped" not in r.output
    assert "SLSQP" not in (tmp_path / "b" / "hitch_003_design_best.toml").read_text(
        encoding="utf-8")
    assert "SLSQP" not in (tmp_path / "b" / "design.html").read_text(encoding="utf-8")


def test_design_polish_key_and_its_override(tmp_path):
    """``[design] polish = false`` turns the polish off for ``optimize`` and for the
    command; ``--polish`` and ``polish=True`` override it; a non-boolean value is an
    error naming the key."""
    from typer.testing import CliRunner

    from assur.views.cli import app
    text = HITCH.read_text(encoding="utf-8").replace(
        'extends = "hitch_003.toml"', f'extends = "{(HITCH.parent / "hitch_003.toml").as_posix()}"')
    f = tmp_path / "off.toml"
    f.write_text(text.replace("[design]\n", "[design]\npolish = false\n"), encoding="utf-8")
    pb = load_problem(f)
    assert pb.polish is False and load_problem(HITCH).polish is True
    assert optimize(pb, popsize=4, maxiter=2, seed=0).polished is None
    assert optimize(pb, popsize=4, maxiter=2, seed=0, polish=True).polished.ran
    args = ["optimize", str(f), "--popsize", "4", "--maxiter", "2", "--workers", "0"]
    r = CliRunner().invoke(app, args + ["-o", str(tmp_path / "a")])
    assert r.exit_code == 0 and "SLSQP" not in r.output, r.output
    r = CliRunner().invoke(app, args + ["--polish", "-o", str(tmp_path / "b")])
    assert r.exit_code == 0 and "SLSQP" in r.output, r.output
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace("[design]\n", "[design]\npolish = \"yes\"\n"),
                   encoding="utf-8")
    with pytest.raises(ModelError, match="design.polish"):
        load_problem(bad)


def test_polish_stops_at_the_last_iterate_when_a_trial_fails(monkeypatch):
    """A trial design the sensitivities cannot evaluate (one that does not assemble;
    here the 6th evaluation refuses) ends SLSQP: its last iterate is judged by the
    batch evaluation like any polished design, and the message says it stopped."""
    pb = load_problem(HITCH)
    de = optimize(pb, popsize=5, maxiter=5, seed=0, polish=False)
    jet, calls = pb.jet, [0]

    def failing(x):
        calls[0] += 1
        if calls[0] > 5:
            raise ModelError("a test refusal")
        return jet(x)
    monkeypatch.setattr(pb, "jet", failing)
    p = polish(pb, de.x, start_batch=de.batch)
    assert p.ran and p.message.startswith("stopped: a trial design could not be evaluated "
                                          "(a test refusal)")
    assert p.nfev == 5
    b = pb.evaluate(p.x[None])
    assert b.feasible[0] and b.objectives[0, 0] >= de.value, p.summary()
    if p.accepted:
        assert p.value >= de.value
