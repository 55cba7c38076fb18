"""Exact sensitivities (:mod:`assur.synthesis.sensitivity`) against complex step and against
central differences of the compiled kernel.

References and why they are independent of the code under test:

* **complex step**: the same plain-numpy group, load and reaction code run with one
  parameter given an imaginary step ``1e-30j`` (``Im/h``, exact to rounding) and no
  parameter jets at all — it checks the chain rule of every dual operation and the
  jets' plumbing (values, analogs, virtual work, cylinders, reverse pass);
* **central differences of the fused kernel** (``Mechanism.evaluate`` at p ± h):
  a separate implementation of positions (generated code), analogs (hand-written jet
  code per group) and reactions (traced), so an error shared by the plain-numpy
  formulas and the duals would show there (tolerance of a difference quotient).

Tolerances: complex step ``1e-9 × scale`` with scale the largest |derivative| of
that output over the parameters and positions (a derivative that vanishes is judged
against its output's others); central differences ``1e-5 × scale``.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from assur import examples
from assur.errors import AssemblyError, ModelError
from assur.synthesis.sensitivity import numeric_parameters, sensitivities
from assur.synthesis.sensitivity.cstep import H as H_CS
from assur.synthesis.sensitivity.cstep import complex_step
from assur.synthesis.sensitivity.dual import Dual, base, variables
from assur.core.statics import solve
from tests.helpers import examples as n_examples
from tests.helpers import statics as TS  # the random mechanism families and loads

RTOL_CS = 1e-9
RTOL_FD = 1e-5

HITCH_OUTPUTS = ["G(ГЦ, S6)", "G(ГЦ, 56)", "p(ГЦ)", "Y(S6)", "Y(56)", "X(67)", "dY(S6)",
                 "phi(6)", "dphi(5)", "F(S)", "Fr(S)", "Rx(0, 5)", "Ry(0, 5)", "R(5, 6)",
                 "reserve(ГЦ, S6, P6)"]


def assert_close(got, ref, rtol, what, families=None, values=None):
    """|got − ref| ≤ rtol × scale, scale per output: the largest |ref| of that output
    over positions and parameters, at least 1e-3 of the largest of its family
    (``families``: a label per output; a derivative that vanishes identically is
    judged against its family, not against its own rounding noise) and 1e-3 of the
    family's largest value per unit parameter (lengths of order 1 m: a mechanism
    without loads has force derivatives of rounding size only), and 1e-250."""
    scale = np.max(np.abs(ref), axis=tuple(i for i in range(ref.ndim) if i != ref.ndim - 2),
                   keepdims=True)
    if families is not None:
        fam = np.array(families)
        flat = scale.reshape(-1).copy()
        vmax = np.abs(values).reshape(-1, values.shape[-1]).max(axis=0)
        for f in set(families):
            floor = max(1e-3 * flat[fam == f].max(), 1e-3 * vmax[fam == f].max())
            flat[fam == f] = np.maximum(flat[fam == f], floor)
        scale = flat.reshape(scale.shape)
    # an absolute floor: the strategies draw values down to the subnormal range
    # (1e-313), and a derivative below 1e-250 in SI units is the rounding of such
    # intermediates — one route gives 8.6e-306 where the other gives −0.0
    scale = np.maximum(scale, 1e-250)
    assert got.shape == ref.shape, (got.shape, ref.shape)
    err = np.abs(got - ref) / scale
    if not (err <= rtol).all():
        i = np.unravel_index(np.argmax(err), err.shape)
        raise AssertionError(f"{what}: worst relative error {err[i]:.3g} at {i}: "
                             f"{got[i]!r} vs {ref[i]!r}")
    return float(err.max())


# ---------------------------------------------------------------------------------
# dual numbers
# ---------------------------------------------------------------------------------
def _pick(cond, a, b):
    return np.where(np.real(cond), a, b)


#: (function on duals, the same function written for complex numbers where numpy
#: has no complex version: the real branch offsets and signs are constants)
RULES = [(np.sqrt, None), (np.sin, None), (np.cos, None), (np.tan, None), (np.arctan, None),
         (np.exp, None), (np.log, None), (lambda x: np.arcsin(x / 3), None),
         (lambda x: np.arccos(x / 3), None),
         (lambda x: np.hypot(x, 0.7 * x + 1), lambda x: np.sqrt(x * x + (0.7 * x + 1) ** 2)),
         (lambda x: np.arctan2(x, 2 - x),
          lambda x: np.arctan(x / (2 - x)) + np.pi * (np.real(x) > 2)),
         (lambda x: x ** 3.5, None), (lambda x: 1 / x, None),
         (lambda x: np.abs(x - 1.5), lambda x: np.sign(np.real(x) - 1.5) * (x - 1.5)),
         (lambda x: np.maximum(x, 1.2), lambda x: _pick(np.real(x) >= 1.2, x, 1.2)),
         (lambda x: np.copysign(x, 1.3 - x), lambda x: _pick(np.real(x) < 1.3, x, -x)),
         (lambda x: x ** 2 - 3 * x / (x + 1), None)]


@pytest.mark.parametrize("rule", range(len(RULES)))
def test_dual_rules_against_complex_step(rule):
    """Every rule of the dual numbers, one and two levels deep, against complex step:
    first derivative, and the mixed derivative of a nested dual in two variables."""
    f, fc = RULES[rule]
    fc = fc or f
    x = np.array([0.3, 0.8, 1.1, 2.5])
    d = f(Dual(x, np.ones((4, 1))))
    ref = np.imag(fc(x + 1j * H_CS)) / H_CS
    np.testing.assert_allclose(d.val, f(x), rtol=1e-15)
    np.testing.assert_allclose(d.der[:, 0], ref, rtol=1e-12, atol=1e-14)
    # nested: y = f(x·t) at t = 1 as dual in t inside dual in x: ∂²/∂x∂t = f' + x·t·f''
    xx = Dual(Dual(x, np.ones((4, 1))), 0.0)
    t = Dual(Dual(np.ones(4), np.zeros((4, 1))), Dual(np.ones((4, 1)), np.zeros((4, 1, 1))))
    y = f(xx * t)
    # ∂y/∂t = x·f'(x) (outer der value); ∂/∂x of that = f'(x) + x·f''(x)
    fp = ref
    np.testing.assert_allclose(base(y.der)[:, 0], x * fp, rtol=1e-12, atol=1e-14)
    h = 1e-5  # f'' by central difference of the complex-step f'
    fpp = (np.imag(fc(x + h + 1j * H_CS)) - np.imag(fc(x - h + 1j * H_CS))) / (2 * h * H_CS)
    np.testing.assert_allclose(y.der.der[:, 0, 0], fp + x * fpp, rtol=1e-6, atol=1e-8)


def test_variables_and_where():
    a, b = variables([1.5, np.array([2.0, 3.0])])
    np.testing.assert_array_equal(a.der, [1.0, 0.0])
    np.testing.assert_array_equal(b.der, [[0.0, 1.0], [0.0, 1.0]])
    c = a * b
    np.testing.assert_array_equal(c.der, [[2.0, 1.5], [3.0, 1.5]])
    assert (c > 3.5).tolist() == [False, True]


# ---------------------------------------------------------------------------------
# the seed 003 hitch
# ---------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def hitch():
    m = examples.hitch_003()
    q = np.linspace(0.425, 0.665, 7)
    return m, q, sensitivities(m, q, outputs=HITCH_OUTPUTS)


def test_hitch_values_equal_the_kernel(hitch):
    """The jets' values equal the fused kernel's outputs (seed 003 tables' quantities)."""
    m, q, s = hitch
    fz = m.evaluate(q, outputs=[o for o in HITCH_OUTPUTS if not o.startswith("phi")])
    for o in fz.outputs:
        np.testing.assert_allclose(s.values(o), fz[o], rtol=1e-10, atol=1e-9, err_msg=o)
    np.testing.assert_allclose(np.cos(s.values("phi(6)")), np.cos(m.solve(q).phi("6")),
                               atol=1e-12)


def test_hitch_against_complex_step(hitch):
    """Capacity, pressure, Y of S6 and 56, reactions… with respect to every numeric
    parameter of hitch_003.toml (29) against complex step."""
    m, q, s = hitch
    assert s.jacobian.shape == (len(q), len(HITCH_OUTPUTS), len(numeric_parameters(m)))
    ref = complex_step(m, q, s.params, HITCH_OUTPUTS).reshape(s.jacobian.shape)
    assert_close(s.jacobian, ref, RTOL_CS, "hitch vs complex step")


@pytest.mark.parametrize("param", ["X01", "Y03", "L3", "L4", "L56", "phiBD", "Sp", "X6",
                                   "Dgc", "Pgc_max", "P6", "eta", "L7"])
def test_hitch_against_kernel_central_differences(hitch, param):
    """The same derivatives against central differences of the compiled fused kernel
    (a separate implementation of positions, analogs and reactions)."""
    m, q, s = hitch
    v0 = float(m.params[param])
    h = 1e-6 * max(abs(v0), 1.0)
    outs = [o for o in HITCH_OUTPUTS if not o.startswith("phi")]
    a = m.evaluate(q, {param: v0 + h}, outputs=outs)
    b = m.evaluate(q, {param: v0 - h}, outputs=outs)
    fd = np.stack([(a[o] - b[o]) / (2 * h) for o in outs], -1)
    got = np.stack([s.d(o, param) for o in outs], -1)
    scale = np.maximum(np.abs(s.jacobian[..., [HITCH_OUTPUTS.index(o) for o in outs], :])
                       .max(axis=(0, 2)), 1e-12)
    err = np.abs(got - fd) / scale
    assert (err <= RTOL_FD).all(), (param, err.max(), outs[int(np.argmax(err.max(0)))])


def test_hitch_physics_checks(hitch):
    """Exact zeros and closed forms: Y does not depend on the bore; the pressure is
    inversely proportional to D² (∂p/∂D = −2p/D) and to the efficiency; the capacity is
    proportional to p_max (∂G/∂p_max = G/p_max); a weight enters the pressure
    linearly (p = P6·∂p/∂P6: the implement is the only load)."""
    m, q, s = hitch
    D, pm, P6 = (float(m.params[k]) for k in ("Dgc", "Pgc_max", "P6"))
    assert np.all(s.d("Y(S6)", "Dgc") == 0.0)
    np.testing.assert_allclose(s.d("p(ГЦ)", "Dgc"), -2 * s.values("p(ГЦ)") / D, rtol=1e-13)
    np.testing.assert_allclose(s.d("G(ГЦ, S6)", "Pgc_max"), s.values("G(ГЦ, S6)") / pm,
                               rtol=1e-13)
    np.testing.assert_allclose(s.d("p(ГЦ)", "P6") * P6, s.values("p(ГЦ)"), rtol=1e-13)
    assert s.unit("p(ГЦ)", "Dgc") == "Pa/m"
    assert s.unit("G(ГЦ, S6)", "phiBD") == "N/rad"


def test_batch_of_designs_equals_single_designs():
    """Parameters over designs: (m, n, outputs, params), each design as alone."""
    m = examples.hitch_003()
    q = np.linspace(0.43, 0.66, 4)
    x01 = np.array([0.405, 0.415, 0.43])
    s = sensitivities(m, q, params=["X01", "L5"], outputs=["G(ГЦ, 56)", "Rx(0, 5)"],
                      values={"X01": x01})
    assert s.jacobian.shape == (3, 4, 2, 2)
    for i, x in enumerate(x01):
        one = sensitivities(m, q, params=["X01", "L5"], outputs=["G(ГЦ, 56)", "Rx(0, 5)"],
                            values={"X01": x})
        np.testing.assert_allclose(s.jacobian[i], one.jacobian, rtol=1e-14)


def test_errors_name_what_is_wrong():
    m = examples.hitch_003()
    with pytest.raises(ModelError, match="not parameters"):
        sensitivities(m, [0.5], params=["X99"], outputs=["Y(56)"])
    with pytest.raises(ModelError, match="unknown output"):
        sensitivities(m, [0.5], params=["X01"], outputs=["Z(56)"])
    with pytest.raises(ModelError, match="no cylinder"):
        sensitivities(m, [0.5], params=["X01"], outputs=["p(nope)"])
    with pytest.raises(AssemblyError):
        sensitivities(m, [0.5], params=["X01"], outputs=["Y(56)"], values={"L4": 0.2})


# ---------------------------------------------------------------------------------
# random mechanisms of every family (strategies of the statics property tests)
# ---------------------------------------------------------------------------------
def _random_outputs(mech, joints):
    outs = []
    for p in mech.points:
        outs += [f"X({p})", f"Y({p})"]
        outs += [f"dY({p}, {c})" for c in mech.coordinates] if len(mech.coordinates) > 1 \
            else [f"dY({p})"]
    outs += [f"F({c})" for c in mech.coordinates]
    outs += [f"{f}({i}, {j})" for _, i, j in joints for f in ("Rx", "Ry")]
    return outs


@pytest.mark.slow
@pytest.mark.parametrize("family", ["cylinder-lever", "crank", "slider",
                                    "cylinder radius (k = 2)", "RRP", "RPR", "PRP"])
@settings(max_examples=n_examples(25), deadline=None,
          phases=[Phase.explicit, Phase.reuse, Phase.generate])
@given(data=st.data())
def test_random_mechanisms_against_complex_step(family, data):
    """Random assemblable mechanisms of every group family with random static loads:
    positions, analogs, actuator forces and joint reactions with respect to every
    parameter against complex step."""
    case = TS.prepare(TS.FAMILIES[family](data))
    loads = [ld for ld in TS.draw_loads(data, case.mech, "loads") if ld[0] != "mass"]
    TS.assume_springs_long(case, loads)
    mech = TS.with_loads(case.mech, loads)
    q = case.api_q(case.Q)
    if case.b.batch:
        q = q[0]
        mech = mech.with_params(**{k: np.asarray(v, float).reshape(-1)[0]
                                   for k, v in mech.params.items()})
    joints = solve(mech.solve(q, check_continuity=False), method="array").joints
    outs = _random_outputs(mech, joints)
    params = numeric_parameters(mech)
    s = sensitivities(mech, q, params=params, outputs=outs, check=False)
    ref = complex_step(mech, q, params, outs).reshape(s.jacobian.shape)
    fams = ["force" if o.startswith(("F(", "Rx(", "Ry(")) else "geometry" for o in outs]
    assert_close(s.jacobian, ref, RTOL_CS, f"{family} vs complex step", fams, s.value)


# ---------------------------------------------------------------------------------
# gradients for scipy's optimizers
# ---------------------------------------------------------------------------------
def test_slsqp_with_exact_gradients_refines_the_hitch():
    """SLSQP (scipy.optimize.minimize, jac = the exact sensitivities) on the epigraph
    form: the smallest capacity at S6 over the stroke, frame pivots 01 and 03 within
    ±30 mm, pressure ≤ 17.5 MPa at every position. It converges, the design is
    feasible (solved again by the kernel), and better than the seed's."""
    from assur.synthesis.refine import local_refine

    m = examples.hitch_003()
    q = np.linspace(0.42, 0.67, 26)
    b = {p: (float(m.params[p]) - 0.03, float(m.params[p]) + 0.03)
         for p in ("X01", "Y01", "X03", "Y03")}
    r = local_refine(m, q, "G(ГЦ, S6)", b, limits=[("p(ГЦ)", "<=", 17.5e6)])
    assert r.success, r.message
    fz = m.evaluate(q, r.params, outputs=["G(ГЦ, S6)", "p(ГЦ)"])
    assert fz["p(ГЦ)"].max() <= 17.5e6 * (1 + 1e-9)
    assert fz["G(ГЦ, S6)"].min() == pytest.approx(r.value, rel=1e-12)
    assert r.value > 1.05 * r.start_value
    assert all(lo - 1e-12 <= r.params[p] <= hi + 1e-12 for p, (lo, hi) in b.items())


def test_gradient_is_what_scipy_check_grad_sees():
    """scipy.optimize.check_grad of a scalar objective (capacity at one position) built
    from the sensitivities: the exact gradient against scipy's own differences."""
    from scipy.optimize import approx_fprime

    m = examples.hitch_003()
    names = ("X01", "Y03", "L4", "phiBD")
    x0 = np.array([float(m.params[p]) for p in names])

    def f(x):
        return float(m.evaluate([0.5], dict(zip(names, x)), outputs=["G(ГЦ, S6)"])
                     ["G(ГЦ, S6)"][0])

    def jac(x):
        return sensitivities(m, [0.5], params=names, outputs=["G(ГЦ, S6)"],
                             values=dict(zip(names, x))).jacobian[0, 0]

    fd = approx_fprime(x0, f, 1e-7)
    np.testing.assert_allclose(jac(x0), fd, rtol=2e-5)
