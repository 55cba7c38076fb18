"""The fused kinematics + statics kernel (:mod:`assur.core.outputs`) against the
separate reverse pass over arrays (:func:`assur.core.statics.solve`): random mechanisms
of every family with random static loads (the builders and scales of
:mod:`tests.helpers.statics`), the seed-003 hitch over a large range, and the switch
of small analyses to the fused kernel."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import examples
from assur.core import statics
from tests.helpers import examples as n_examples
from tests.helpers.analogs import SETTINGS
from tests.helpers.statics import ELL0, FAMILIES, WORST, Solved, _assert_close, \
    assume_springs_long, draw_loads, fixed_loads, prepare, reproducer


# ---------------------------------------------------------------------------------
# the fused kinematics + statics kernel (assur.core.outputs) against the array pass
# ---------------------------------------------------------------------------------
#: relative tolerance of the fused kernel against the separate reverse pass
RTOL_FUSED = 1e-9


# the fused kernel is generated and compiled per structure *with its loads' places*
# (their values are run-time data): the family tests keep one load placement per
# mechanism structure (fixed_loads), so that their examples share kernels; random
# placements are a test of their own with few examples (each one a new kernel)
FUSED_SETTINGS = settings(SETTINGS, max_examples=n_examples(30))
PLACEMENT_SETTINGS = settings(SETTINGS, max_examples=7)


def check_fused(case, data, random_placement=False):
    """The fused kernel's reactions (every joint: Rx, Ry, Rm) and actuator forces (F by
    virtual work, Fr from the reactions) equal those of :func:`assur.core.statics.solve`
    (the separate reverse pass over arrays) to RTOL_FUSED × the reaction scale R or
    the actuator scale A of the module docstring (static loads: the fused kernel has
    no inertia). The loads: one of every kind at fixed places with random values
    (:func:`tests.helpers.statics.fixed_loads`), or 1–4 of random kinds at random
    places (:func:`tests.helpers.statics.draw_loads`)."""
    loads = (draw_loads(data, case.mech, "loads") if random_placement
             else fixed_loads(data, case.mech, "loads"))
    assume_springs_long(case, loads)
    full = Solved(case, loads, None, None)
    outs = [f"{f}({i}, {j})" for _, i, j in full.st.joints for f in ("Rx", "Ry", "Rm")]
    outs += [f"{f}({c})" for c in case.mech.coordinates for f in ("F", "Fr")]
    fz = full.mech.evaluate(case.api_q(case.Q), outputs=outs, on_failure="report")
    assert fz.ok.all()

    def where():
        return reproducer(case, loads, None, None)

    w = 0.0
    for _, i, j in full.st.joints:
        got = np.stack([case.shaped(fz[f"Rx({i}, {j})"]), case.shaped(fz[f"Ry({i}, {j})"])], -1)
        w = max(w, _assert_close(f"fused reaction of {i} on {j}", got, full.reaction(i, j),
                                 RTOL_FUSED * full.R, where))
        w = max(w, _assert_close(f"fused moment of {i} on {j}",
                                 case.shaped(fz[f"Rm({i}, {j})"]) / ELL0,
                                 full.moment(i, j) / ELL0, RTOL_FUSED * full.R, where))
    for jc, c in enumerate(case.mech.coordinates):
        tol = RTOL_FUSED * full.A[..., jc]
        w = max(w, _assert_close(f"fused actuator force {c} (virtual work)",
                                 case.shaped(fz[f"F({c})"]), full.vw(c), tol, where))
        w = max(w, _assert_close(f"fused actuator force {c} (reactions)",
                                 case.shaped(fz[f"Fr({c})"]), full.rx(c), tol, where))
    WORST["fused vs array pass"] = max(WORST.get("fused vs array pass", 0.0), w)


@pytest.mark.slow
@pytest.mark.parametrize("family", list(FAMILIES))
@FUSED_SETTINGS
@given(data=st.data())
def test_fused_kernel_reactions_equal_the_reverse_pass(family, data):
    """Random mechanisms of every family with random static loads of every kind: the
    fused kernel (one generated loop: positions, jets, loads, reactions in reverse
    order) gives the reactions and actuator forces of the separate array pass to 1e-9
    relative."""
    check_fused(prepare(FAMILIES[family](data)), data)


@pytest.mark.slow
@PLACEMENT_SETTINGS
@given(data=st.data())
def test_fused_kernel_with_loads_at_random_places(data):
    """The same with 1–4 loads of random kinds at random places, on a mechanism of a
    random family."""
    family = data.draw(st.sampled_from(sorted(FAMILIES)), label="family")
    check_fused(prepare(FAMILIES[family](data)), data, random_placement=True)


def test_fused_kernel_shared_by_load_values_with_other_coincidences():
    """Regression: the fused kernel of a load structure is shared by load values, and
    its table rows must not depend on which of those values happen to be equal (a
    weight and a force of 1 N shared a row, and the kernel cached for them then read
    the wrong row for a weight of 1 N and a force of 2 N)."""
    from assur import Mechanism
    base = (Mechanism("crank-dyad", coordinates=("q",))
            .frame("O", 0.0, 0.0).frame("B", 0.0, 3.0)
            .crank("crank", pivot="O", out="A", radius=1.0, q="q", links=("1",))
            .dyad("II", a="A", b="B", out="C", ra=2.65, rb=0.6, branch=1, links=("2", "3")))
    q = np.linspace(0.0, 1.0, 7)
    for P, fx, M in ((1.0, 1.0, 1.0), (1.0, 2.0, 3.0), (2.0, 2.0, 1.0)):
        m = base.weight("C", P).force("A", fx, 0.5).moment("2", M)
        kin = m.solve(q)
        fz = statics.solve(kin, method="fused")
        ar = statics.solve(kin, method="array")
        for _, i, j in ar.joints:
            assert np.allclose(fz.reaction(i, j), ar.reaction(i, j), rtol=1e-12, atol=1e-9)
        assert np.allclose(fz.actuator_force("q"), ar.actuator_force("q"), rtol=1e-12)


def test_statics_uses_the_fused_kernel_on_large_ranges():
    """analyze() on ≥ FUSED_MIN elements takes the fused kernel (static loads); it
    equals the array pass on the seed-003 hitch to 1e-9 relative."""
    from assur import examples
    m = examples.hitch_003()
    kin = m.solve(np.linspace(0.42, 0.67, statics.FUSED_MIN + 1))
    st = statics.solve(kin)
    ar = statics.solve(kin, method="array")
    scale = max(float(np.max(np.abs(ar.reaction(i, j)))) for _, i, j in ar.joints)
    for _, i, j in ar.joints:
        assert np.max(np.abs(st.reaction(i, j) - ar.reaction(i, j))) <= 1e-9 * scale
    for c in m.coordinates:
        assert np.allclose(st.actuator_force(c), ar.actuator_force(c), rtol=1e-9)
        assert np.allclose(st.actuator_force_from_reactions(c),
                           ar.actuator_force_from_reactions(c), rtol=1e-9)
    assert max(float(np.max(r)) for r in st.equilibrium_residual()) <= 1e-9 * scale


def test_statics_switch_to_the_fused_kernel_after_a_few_calls(monkeypatch):
    calls = []
    real = statics._solve_fused

    def counting(kin, g):
        calls.append(kin.n)
        return real(kin, g)

    monkeypatch.setattr(statics, "_solve_fused", counting)
    m = examples.hitch_003().with_params(L5=0.48)  # a mechanism of this test alone
    q = np.array([0.5])
    res = [m.analyze(q).statics for _ in range(statics.FUSED_AFTER + 2)]
    assert calls == [1, 1]  # the calls after FUSED_AFTER
    a, b = res[0], res[-1]
    for _, i, j in a.joints:
        ra, rb = a.reaction(i, j), b.reaction(i, j)
        assert np.allclose(rb, ra, rtol=1e-9, atol=1e-9 * np.abs(ra).max()), (i, j)
    assert np.allclose(b.actuator_force(), a.actuator_force(), rtol=1e-9)



# ---------------------------------------------------------------------------------
# the compiled fused kernel and its numpy evaluation (the tests' default backend)
# ---------------------------------------------------------------------------------
def _both_backends(fn):
    """``fn()`` with the compiled kernels, then with their numpy evaluation (the test
    around it runs with numpy: building its case compiles nothing)."""
    from assur.kernel import vector as KV
    out = []
    for name in ("numba", "numpy"):
        KV.set_backend(name)
        try:
            out.append(fn())
        finally:
            KV.set_backend(None)
    return out


@pytest.mark.slow
@pytest.mark.parametrize("family", list(FAMILIES))
@settings(SETTINGS, max_examples=1)   # each example compiles a kernel; the formulas are
@given(data=st.data())                # the other tests' (30 examples per family)
def test_compiled_fused_kernel_equals_its_numpy_evaluation(family, data):
    """Random mechanisms of every family with static loads of every kind: the compiled
    fused kernel and the numpy evaluation of the same code (which the other tests run)
    give the same reactions and actuator forces to 1e-12 of their scale and the same
    failures (the reductions: the next test)."""
    case = prepare(FAMILIES[family](data))
    loads = fixed_loads(data, case.mech, "loads")
    assume_springs_long(case, loads)
    full = Solved(case, loads, None, None)
    outs = [f"{f}({i}, {j})" for _, i, j in full.st.joints for f in ("Rx", "Ry", "Rm")]
    outs += [f"{f}({c})" for c in case.mech.coordinates for f in ("F", "Fr")]
    q = case.api_q(case.Q)
    compiled, numpy_ = _both_backends(
        lambda: full.mech.evaluate(q, outputs=outs, on_failure="report"))
    assert np.array_equal(compiled.ok, numpy_.ok)
    for o in outs:
        a, b = np.asarray(compiled[o]), np.asarray(numpy_[o])
        scale = max(float(np.max(np.abs(a))), 1e-300)
        assert np.max(np.abs(a - b)) <= 1e-12 * scale, (o, reproducer(case, loads, None, None))


def test_reductions_over_several_work_items_equal_compiled():
    """Reductions over more positions than a work item of the compiled kernel (CHUNK)
    and over designs of which some positions do not assemble: the numpy evaluation
    reduces per work item as the compiled kernel does (min, max and where)."""
    from assur.kernel.source import CHUNK
    m = examples.hitch_003()
    n = 2 * CHUNK + 37
    S = np.linspace(0.40, 0.67, n)   # below Smin = 0.42 m the hitch may not assemble
    q = np.stack([S, S[::-1], np.full(n, 0.5)])
    outs = ["p(ГЦ)", "G(ГЦ, S6)", "Y(56)"]
    lens = {"L3": np.array([m.params["L3"], m.params["L3"] * 1.01, m.params["L3"]])}
    red = _both_backends(lambda: m.evaluate(q, params=lens, outputs=outs, reduce=True,
                                            on_failure="report"))
    assert red[0].failures.tolist() == red[1].failures.tolist()
    for o in outs:
        for op in ("min", "max", "argmin", "argmax"):
            a, b = getattr(red[0], op)(o), getattr(red[1], op)(o)
            assert np.array_equal(a, b) if op.startswith("arg") else np.allclose(a, b, rtol=1e-13), \
                (o, op, a, b)
