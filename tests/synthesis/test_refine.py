"""The one local refiner (issue 22): :func:`assur.synthesis.refine.refine`, SLSQP with
exact gradients, and its two users — :func:`~assur.synthesis.refine.local_refine` (the
max–min of an output over the positions) and
:func:`~assur.synthesis.search.polish.polish` (a design problem's criteria)."""

import warnings

import numpy as np
import pytest
import scipy.optimize

from assur import examples, io
from assur.errors import AssemblyError, ModelError
from assur.synthesis import refine as refine_module
from assur.synthesis.refine import Refinement, Scaled, local_refine, refine

Q3 = [0.42, 0.545, 0.67]      # positions of the seed-003 hitch's cylinder [m]


def _disc(x):
    """(x − 2)² + (y − 1)² with x + y ≤ 2 (scaled by 2): the criteria of a small problem."""
    d = x - np.array([2.0, 1.0])
    return d @ d, 2 * d, np.array([(2.0 - x.sum()) / 2.0]), np.array([[-0.5, -0.5]])


def test_known_optimum_with_bounds_and_a_constraint():
    """min (x − 2)² + (y − 1)² subject to x + y ≤ 2 within [0, 1.5]²: the optimum
    (1.5, 0.5), the projection of (2, 1) on the line, the constraint active; with
    x ≤ 1.2 the bound binds too: (1.2, 0.8). Maximising the negated objective is the
    same problem."""
    r = refine(_disc, [0.0, 0.0], [(0.0, 1.5), (0.0, 1.5)], names=("x", "y"),
               constraint_names=("x + y ≤ 2",))
    assert isinstance(r, Refinement)
    assert r.success, r.message
    np.testing.assert_allclose(r.x, [1.5, 0.5], atol=1e-8)
    assert r.value == pytest.approx(0.5, abs=1e-8)
    assert r.start_value == 5.0 and r.improved
    assert r.feasible and r.start_feasible and r.note == "" and r.start_note == ""
    assert r.g[0] == pytest.approx(0.0, abs=1e-9)          # active
    # a bound that binds: x ≤ 1.2 — the optimum (1.2, 0.8) on the line x + y = 2
    r = refine(_disc, [0.0, 0.0], [(0.0, 1.2), (0.0, 1.5)])
    np.testing.assert_allclose(r.x, [1.2, 0.8], atol=1e-8)
    assert r.value == pytest.approx(0.8 ** 2 + 0.2 ** 2, abs=1e-8)
    assert ((r.x >= [0.0, 0.0]) & (r.x <= [1.2, 1.5])).all()
    # maximising the negated objective is the same problem
    m = refine(lambda x: tuple(-v if i < 2 else v for i, v in enumerate(_disc(x))),
               [0.0, 0.0], [(0.0, 1.2), (0.0, 1.5)], maximize=True)
    np.testing.assert_allclose(m.x, r.x, atol=1e-8)
    assert m.value == pytest.approx(-r.value, abs=1e-8) and m.improved


def test_epigraph_form_of_the_largest_objective():
    """An array objective: its largest element is minimised (max(|x − 1|², |x + 1|²)
    at x = 0, with a constraint x ≥ 0.25 it moves there), its smallest maximised."""
    def two(x):
        d = x - np.array([1.0, -1.0])
        return d ** 2, 2 * d[:, None], np.array([x[0] - 0.25]), np.array([[1.0]])
    r = refine(two, [-1.5], [(-2.0, 2.0)])
    assert r.success and r.feasible and not r.start_feasible
    assert r.x[0] == pytest.approx(0.25, abs=1e-8)
    assert r.value == pytest.approx(1.25 ** 2, abs=1e-8)
    assert r.start_value == pytest.approx(2.5 ** 2)
    up = refine(lambda x: (-two(x)[0], -two(x)[1], two(x)[2], two(x)[3]), [-1.5],
                [(-2.0, 2.0)], maximize=True)
    assert up.x[0] == pytest.approx(0.25, abs=1e-8)
    assert up.value == pytest.approx(-(1.25 ** 2), abs=1e-8)


def _captured(monkeypatch):
    """Record what refine hands to scipy's minimize (it imports it when called)."""
    calls = []
    real = scipy.optimize.minimize

    def spy(fun, x0, **kw):
        calls.append((fun, np.array(x0, float), kw))
        return real(fun, x0, **kw)
    monkeypatch.setattr(scipy.optimize, "minimize", spy)
    return calls


def _central(fn, w, h=1e-6):
    """Central differences of ``fn`` at ``w`` (columns: the variables), the step ``h``
    relative to a variable's magnitude above 1 (the epigraph variable is in N)."""
    cols = []
    for i in range(len(w)):
        e = np.zeros_like(w)
        e[i] = h * max(1.0, abs(w[i]))
        cols.append((np.atleast_1d(fn(w + e)) - np.atleast_1d(fn(w - e))) / (2 * e[i]))
    return np.stack(cols, axis=-1)


def _check(got, ref, label):
    scale = max(np.abs(ref).max(), 1e-12)
    err = np.abs(np.asarray(got) - ref).max()
    assert err <= 1e-6 * scale, f"{label}: exact {got} against central {ref} ({err:.3g})"


def test_exact_gradients_agree_with_central_differences(monkeypatch):
    """The objective, the constraints and their gradients SLSQP is given (the
    variables scaled to [0, 1], the epigraph variable, the limits scaled by their
    value): the exact gradients — the sensitivities of the seed-003 hitch, two frame
    pivots and the bore, capacity at 56 maximised with a pressure limit — agree with
    central differences of the values, at the start and at points inside the bounds."""
    calls = _captured(monkeypatch)
    m = examples.hitch_003()
    b = {p: (float(m.params[p]) - 0.02, float(m.params[p]) + 0.02) for p in ("X01", "Y03")}
    b["Dgc"] = (0.075, 0.085)
    local_refine(m, Q3, "G(ГЦ, 56)", b, limits=[("p(ГЦ)", "<=", 16e6)], maxiter=3)
    (fun, w0, kw), = calls
    con = kw["constraints"][0]
    rng = np.random.default_rng(0)
    for w in [w0] + [np.append(rng.uniform(0.2, 0.8, 3), w0[-1] * 0.99) for _ in range(3)]:
        _check(kw["jac"](w), _central(fun, w)[0], "objective")
        _check(con["jac"](w), _central(con["fun"], w), "constraints")
    assert con["jac"](w0).shape == (2 * len(Q3), 4)  # capacity and pressure at 3 positions


def test_exact_gradient_of_a_scalar_maximised_objective(monkeypatch):
    """A number objective, maximised: the gradient SLSQP gets is the negated, scaled
    one (central differences of what it minimises)."""
    calls = _captured(monkeypatch)

    def crit(x):
        f = np.sin(x[0]) * x[1] ** 2
        return f, [np.cos(x[0]) * x[1] ** 2, 2 * np.sin(x[0]) * x[1]], \
            [1.0 - x[1]], [[0.0, -1.0]]
    r = refine(crit, [0.3, 0.4], [(0.0, 3.0), (-1.0, 2.0)], maximize=True)
    fun, w0, kw = calls[0]
    for w in (w0, np.array([0.4, 0.7]), np.array([0.1, 0.2])):
        _check(kw["jac"](w), _central(fun, w)[0], "objective")
        con = kw["constraints"][0]
        _check(con["jac"](w), _central(con["fun"], w), "constraint")
    assert r.x[0] == pytest.approx(np.pi / 2, abs=1e-6) and r.x[1] == pytest.approx(1.0)
    # to SLSQP's constraint tolerance: scipy ≥ 1.16's SLSQP ends 1.3e-9 beyond x1 ≤ 1
    assert r.value == pytest.approx(1.0, abs=1e-8) and r.feasible


def test_an_infeasible_start_is_reported_in_words():
    """A start that breaks a constraint: the refiner runs from it (SLSQP may start
    outside the feasible set), says which constraint the start broke and by how much,
    and that the result holds it; a result that cannot hold it is reported too."""
    r = refine(_disc, [1.5, 1.5], [(0.0, 1.5), (0.0, 1.5)], names=("x", "y"),
               constraint_names=("x + y ≤ 2",))
    assert not r.start_feasible and r.feasible
    assert r.start_note == ("the start is not feasible: x + y ≤ 2 does not hold: its scaled "
                            "margin is -0.5")
    assert r.note == ""
    assert "the start is not feasible: x + y ≤ 2" in r.summary()
    np.testing.assert_allclose(r.x, [1.5, 0.5], atol=1e-8)
    # x + y ≥ 3 within [0, 1] × [0, 1]: never
    r = refine(lambda x: (x.sum(), [1.0, 1.0], [x.sum() - 3.0, x[0] + 1.0], [[1, 1], [1, 0]]),
               [0.5, 0.5], [(0.0, 1.0), (0.0, 1.0)],
               constraint_names=("x + y ≥ 3", "x ≥ −1"))
    assert not r.feasible
    assert r.note == "the result is not feasible: x + y ≥ 3 does not hold: its scaled margin is -1"
    assert r.start_note.startswith("the start is not feasible: x + y ≥ 3 does not hold")
    # two broken: the worst is named and the others counted
    r = refine(lambda x: (x[0], [1.0], [x[0] - 3.0, x[0] - 2.0], [[1.0], [1.0]]), [0.0],
               [(0.0, 1.0)])
    assert r.start_note == ("the start is not feasible: constraint 0 does not hold: its "
                            "scaled margin is -3 (and 1 more)")


def test_local_refine_reports_an_infeasible_start():
    """local_refine from the seed's design, which breaks a 16 MPa pressure limit at the
    end of the stroke (16.06 MPa): its note names the limit and the position; the
    refined design holds it (solved again by the kernel)."""
    m = examples.hitch_003()
    r = local_refine(m, Q3, "G(ГЦ, 56)", {"X01": (0.40, 0.43)}, limits=[("p(ГЦ)", "<=", 16e6)])
    assert r.success, r.message
    assert r.note.startswith("the start is not feasible: p(ГЦ) ≤ 16000000 Pa at position 2 "
                             "does not hold: its scaled margin is -0.00398")
    assert "the result" not in r.note
    p = m.evaluate(Q3, r.params, outputs=["p(ГЦ)"])["p(ГЦ)"]
    assert p.max() <= 16e6 * (1 + 1e-9)


def test_a_trial_that_cannot_be_evaluated_ends_at_the_last_iterate():
    """A criterion raising one of ``stop_on`` at a trial design: the result is the last
    iterate, with a message; raised at the start it propagates, and exceptions not in
    ``stop_on`` propagate."""
    seen = []

    def crit(x):
        seen.append(x.copy())
        if len(seen) > 3:
            raise AssemblyError("a test refusal")
        return _disc(x)
    r = refine(crit, [0.0, 0.0], [(0.0, 1.5), (0.0, 1.5)], stop_on=(AssemblyError,))
    assert r.stopped and not r.success
    assert r.message == "stopped: a trial design could not be evaluated (a test refusal)"
    assert r.nfev == 3
    assert any(np.array_equal(r.x, s) for s in seen[:3])
    assert r.value <= r.start_value
    with pytest.raises(AssemblyError, match="at the start"):
        refine(lambda x: (_ for _ in ()).throw(AssemblyError("at the start")), [0.0],
               [(0.0, 1.0)], stop_on=(AssemblyError,))
    seen.clear()
    with pytest.raises(AssemblyError, match="a test refusal"):
        refine(crit, [0.0, 0.0], [(0.0, 1.5), (0.0, 1.5)])


def test_bounds_and_shapes_are_checked():
    """Bounds that are not finite pairs with low ≤ high, and criteria of the wrong
    shapes: a ModelError naming the variable or the shapes."""
    with pytest.raises(ModelError, match="the bounds of L4 must be finite with low ≤ high, "
                                         "got \\[0.0, inf\\]"):
        refine(_disc, [0.0, 0.0], [(0.0, 1.0), (0.0, np.inf)], names=("X01", "L4"))
    with pytest.raises(ModelError, match="2 variables need 2 names and 2 bounds"):
        refine(_disc, [0.0, 0.0], [(0.0, 1.0)])
    with pytest.raises(ModelError, match="criteria gave an objective of shape \\(\\), its "
                                         "gradient of shape \\(3,\\)"):
        refine(lambda x: (0.0, [1.0, 2.0, 3.0], [], []), [0.0, 0.0], [(0, 1), (0, 1)])
    with pytest.raises(ModelError, match="1 constraint names for 2 constraints"):
        refine(lambda x: (0.0, [0.0], [1.0, 1.0], [[0.0], [0.0]]), [0.0], [(0, 1)],
               constraint_names=("a",))


def test_a_variable_with_equal_bounds_stays_and_the_start_is_clipped():
    """A variable whose bounds are equal keeps its value; a start outside the bounds
    starts on them (the start reported is that point)."""
    r = refine(_disc, [5.0, 0.3], [(0.0, 1.5), (0.3, 0.3)])
    np.testing.assert_array_equal(r.start, [1.5, 0.3])
    assert r.x[1] == 0.3 and r.x[0] == pytest.approx(1.5)


def test_local_refine_keeps_a_parameter_with_equal_bounds():
    """The seed-003 hitch's Y01 given equal bounds stays there while X01 moves (it used
    to be free over 1 m above them, and the hitch then failed to assemble)."""
    m = examples.hitch_003()
    y01 = float(m.params["Y01"])
    r = local_refine(m, Q3, "G(ГЦ, 56)", {"X01": (0.40, 0.43), "Y01": (y01, y01)})
    assert r.success, r.message
    assert r.params == {"X01": 0.4, "Y01": y01} and round(r.value) == 34209


def test_scaled_maps_and_evaluates_once_per_point():
    """Scaled: z in [0, 1] over the bounds, a fixed variable scaled by 1, clipping,
    one evaluation per distinct point."""
    ev = Scaled([0.40, 1.0], [0.43, 1.0], lambda x: float(x.sum()), clip=True)
    np.testing.assert_allclose(ev.span, [0.03, 1.0])
    np.testing.assert_allclose(ev.x([1.5, 0.0]), [0.43, 1.0])
    np.testing.assert_allclose(ev.z(ev.x([0.25, 0.0])), [0.25, 0.0])
    assert ev([0.5, 0.0]) == ev([0.5, 0.0]) and ev.count == 1
    ev([0.6, 0.0])
    assert ev.count == 2


def test_both_call_sites_use_the_one_refiner(monkeypatch):
    """local_refine and the search's polish both run refine (a spy counts the calls)."""
    from assur.io import load_problem
    from assur.synthesis.search import Problem
    from assur.synthesis.search import polish as polish_module

    calls = []
    real = refine_module.refine

    def spy(*a, **k):
        calls.append(k.get("maximize"))
        return real(*a, **k)
    monkeypatch.setattr(refine_module, "refine", spy)
    monkeypatch.setattr(polish_module, "refine", spy)
    m = examples.hitch_003()
    r = local_refine(m, Q3, "G(ГЦ, 56)", {"X01": (0.40, 0.43)})
    assert r.params == {"X01": 0.4} and round(r.value) == 34209
    pb = load_problem(io.bundled("hitch_003_design"))
    top = Problem(pb.original, pb.positions[::5], pb.variables[6:], pb.constraints,
                  pb.objectives)
    p = polish_module.polish(top, top.x0)
    assert p.accepted and round(p.value, 2) == 17.18
    assert calls == [True, True]


def test_the_old_import_path_warns_and_gives_the_same_objects():
    """assur.synthesis.sensitivity.refine's names moved to assur.synthesis.refine: the old
    path works for one release with a DeprecationWarning naming the new one."""
    import assur.synthesis.sensitivity.refine as old

    for name in ("local_refine", "Refined", "Scaled"):
        with pytest.warns(DeprecationWarning, match=f"assur.synthesis.sensitivity.refine.{name} "
                                                    f"moved to assur.synthesis.refine.{name}"):
            assert getattr(old, name) is getattr(refine_module, name)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(AttributeError):
            old.refine  # noqa: B018 — never there
        assert old.__all__ == []


def smallest_capacity(m, q, **params):
    """min over q of the lift capacity at 56 by the cylinder, through analyze()."""
    return float(np.min(m.with_params(**params).analyze(q).cylinder().capacity("56")))


def test_the_refined_design_is_a_local_optimum():
    """local_refine's optimum checked by another route: analyses of the refined design
    and of its neighbours along each variable within the bounds."""
    m = examples.hitch_003()
    q = [0.42, 0.545, 0.67]
    bounds = {"X01": (0.40, 0.43), "Y01": (0.55, 0.58)}
    r = local_refine(m, q, "G(ГЦ, 56)", bounds)
    assert r.success and r.value >= r.start_value
    assert r.start_value == pytest.approx(smallest_capacity(m, q), rel=1e-9)
    assert r.value == pytest.approx(smallest_capacity(m, q, **r.params), rel=1e-9)
    for name, (lo, hi) in bounds.items():
        assert lo <= r.params[name] <= hi
        for step in (-1e-4, 1e-4):
            moved = r.params[name] + step
            if lo <= moved <= hi:
                other = smallest_capacity(m, q, **{**r.params, name: moved})
                assert other <= r.value * (1 + 1e-7), (name, step)
