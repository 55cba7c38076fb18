"""Issue 12: "minimise the variation of a quantity over the range (lab 2: roller
pressure; lab 3: centre-of-mass excursion)".

Two outputs of the fused kernel make them design quantities:

* ``Xc``, ``Yc`` — the common centre of mass of the masses on moving links
  (001 lab 3), equal to :func:`assur.dynamics.balancing.common_centre`;
* a formula of the model's ``[[tables.formulas]]`` by its name — lab 2's specific
  roller pressure ``p_c`` (eq. 4) — equal to its report column.

Both carry exact sensitivities (the same formulas over dual numbers), and the two
bundled design files ``conditioner_lab2_design.toml`` and
``cleaning_lab3_design.toml`` minimise their span; each optimum is checked by code
that does not go through the fused kernel (:mod:`assur.machines.conditioner`,
:mod:`assur.dynamics.balancing` over :meth:`Mechanism.solve`).
"""
from __future__ import annotations

import numpy as np
import pytest

from assur import io
from assur.dynamics.balancing import common_centre
from assur.core.columns import formulas_of
from assur.machines.conditioner import specific_pressure
from assur.io import load_problem
from assur.synthesis.search.search import optimize
from assur.errors import ModelError
from assur.synthesis.sensitivity import sensitivities

LAB2 = io.bundled("conditioner_lab2")
LAB3 = io.bundled("cleaning_lab3")


@pytest.fixture(scope="module")
def lab2():
    return io.load(LAB2).mechanism


@pytest.fixture(scope="module")
def lab3():
    return io.load(LAB3).mechanism


def test_centre_of_mass_outputs_equal_the_balancing_path(lab3):
    q = np.radians(np.arange(0.0, 360.0, 7.5))
    f = lab3.evaluate(q, outputs=["Xc", "Yc"])
    c = common_centre(lab3.solve(q))
    np.testing.assert_allclose(f["Xc"], c.x, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(f["Yc"], c.y, rtol=1e-12, atol=1e-15)
    assert f.units == {"Xc": "m", "Yc": "m"}
    # reduced in the kernel: the span is twice the lab's amplitude A_x
    r = lab3.evaluate(q, outputs=["Xc"], reduce=True)
    span = float(r.max("Xc")[0] - r.min("Xc")[0])
    assert span == pytest.approx(2 * float(c.amplitude_x), rel=1e-12)


def test_formula_output_equals_its_report_column(lab2):
    Y = np.linspace(0.205, 0.240, 8)
    f = lab2.evaluate(Y, outputs=["p_c", "I", "F(Y)"])
    kin = lab2.solve(Y)
    by_name = {x.name: x for x in formulas_of(lab2)}
    np.testing.assert_allclose(f["p_c"], by_name["p_c"].evaluate(kin), rtol=1e-12)
    np.testing.assert_allclose(f["I"], by_name["I"].evaluate(kin), rtol=1e-12)
    # eq. 4 by the conditioner module's own path (spring stroke and tension)
    _, p = specific_pressure(kin, "sp", lab2.value_of("Lr"))
    np.testing.assert_allclose(f["p_c"], p, rtol=1e-12)
    # and by virtual work: the force of the layer on the rollers over their length
    np.testing.assert_allclose(f["p_c"], f["F(Y)"] / lab2.value_of("Lr"), rtol=1e-12)
    assert f.units["p_c"] == "N/m"


def _central(mech, q, output, name, h):
    v = mech.value_of(name)
    up = mech.with_params(**{name: v + h}).evaluate(q, outputs=[output])[output]
    dn = mech.with_params(**{name: v - h}).evaluate(q, outputs=[output])[output]
    return (up - dn) / (2 * h)


@pytest.mark.parametrize("model, q, output, params", [
    ("lab2", np.linspace(0.205, 0.240, 5), "p_c", ("c", "F0", "L5s", "X01", "Lr")),
    ("lab3", np.radians(np.arange(0.0, 360.0, 45.0)), "Xc", ("LD", "XH4", "m4", "L2")),
    ("lab3", np.radians(np.arange(0.0, 360.0, 45.0)), "Yc", ("LE", "YH6", "m6")),
])
def test_sensitivities_of_the_new_outputs_equal_central_differences(model, q, output,
                                                                     params, request):
    mech = request.getfixturevalue(model)
    s = sensitivities(mech, q, params, [output])
    jac = s.jacobian[..., 0, :]
    for j, name in enumerate(params):
        h = 1e-6 * max(abs(mech.value_of(name)), 1e-3)
        fd = _central(mech, q, output, name, h)
        np.testing.assert_allclose(jac[:, j], fd, rtol=1e-5,
                                   atol=1e-7 * np.abs(fd).max() + 1e-12, err_msg=name)


def test_unknown_outputs_name_the_formulas_and_outputs(lab2, lab3):
    with pytest.raises(ModelError, match=r"no formula of that name.*'p_c'"):
        lab2.evaluate([0.21], outputs=["p_x"])
    with pytest.raises(ModelError, match="has no masses on moving links"):
        lab2.evaluate([0.21], outputs=["Xc"])
    with pytest.raises(ModelError, match=r"Xc\(\) .*|takes 0 argument"):
        lab3.evaluate([0.1], outputs=["Xc(1)"])


def test_lab2_roller_pressure_varies_least():
    """001 lab 2: the pressing device keeps the specific pressure of the rollers as
    constant as it can over the gap range; the search minimises the span of p_c."""
    pb = load_problem(io.bundled("conditioner_lab2_design"))
    original = float(pb.evaluate(pb.x0[None]).objectives[0, 0])
    res = optimize(pb, popsize=8, maxiter=40, seed=1)
    print(f"\nlab 2: span of p_c {original:.1f} N/m (the file's design) → "
          f"{res.value:.1f} N/m ({res.evaluations} designs)")
    assert res.feasible and res.verified == ""
    assert original == pytest.approx(1093.1, abs=0.1)   # the file's spring (flattest_spring)
    assert res.value < 0.5 * original
    # checked without the fused kernel, on a finer grid than the search used
    mech = pb.with_design(res.x)
    Y = np.linspace(mech.value_of("Ymin"), mech.value_of("Ymax"), 71)
    _, p = specific_pressure(mech.solve(Y), "sp", mech.value_of("Lr"))
    assert float(np.ptp(p)) == pytest.approx(res.value, rel=0.02)
    assert 19e3 - 1.0 <= p.min() and p.max() <= 21e3 + 1.0


def test_lab3_centre_of_mass_excursion_least():
    """001 lab 3: the common centre of mass oscillates over a crank turn; the search
    changes the rocker's arms and the hangers' pivots to make its horizontal
    excursion least, keeping the vertical one and every stroke."""
    pb = load_problem(io.bundled("cleaning_lab3_design"))
    original = float(pb.evaluate(pb.x0[None]).objectives[0, 0])
    res = optimize(pb, popsize=6, maxiter=30, seed=1)
    print(f"\nlab 3: span of Xc {original * 1e3:.2f} mm → {res.value * 1e3:.2f} mm "
          f"({res.evaluations} designs)")
    assert res.feasible and res.verified == ""
    assert res.value < 0.25 * original
    # checked by the balancing module over solved positions (every 5° of the turn)
    q = pb.positions
    before, after = pb.mechanism.solve(q), pb.with_design(res.x).solve(q)
    c0, c1 = common_centre(before), common_centre(after)
    assert 2 * float(c0.amplitude_x) == pytest.approx(original, rel=1e-9)
    assert 2 * float(c1.amplitude_x) == pytest.approx(res.value, rel=1e-9)
    assert float(c1.amplitude_y) <= float(c0.amplitude_y) * (1 + 1e-9)
    for p in ("C4", "C6", "C8"):
        assert np.ptp(after.x(p)) >= np.ptp(before.x(p)) * (1 - 1e-9), p
