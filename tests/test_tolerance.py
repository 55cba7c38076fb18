"""Tolerance analysis (:mod:`assur.tolerance`) on the seed 003 hitch: the Monte Carlo
over manufacturing tolerances against the first-order stack-up from the exact
sensitivities, the model file's ``[tolerances]`` section and its errors, and the
command ``assur tolerance``.

Why the comparison can fail: the Monte Carlo evaluates every drawn machine through
the compiled fused kernel; the stack-up uses derivatives from the dual numbers
(:mod:`assur.sensitivity`). For an output linear in the toleranced parameters
(the pressure in the implement's weight P6, the capacity in the relief setting) the
sample σ and the first-order σ with the sample's own covariance agree to rounding;
for small geometric tolerances they agree within the sampling error of σ
(≈ 1/√(2N) ≈ 1.6 % for N = 2000: 5 % allowed), and for large ones they must not
(the nonlinearity shows).
"""

from __future__ import annotations

import numpy as np
import pytest

from assur import examples, io
from assur.errors import ModelError
from assur.tolerance import Tolerance, monte_carlo

Q = np.linspace(0.425, 0.665, 6)


def test_linear_output_agrees_exactly():
    """p ∝ P6 (the implement is the only load), G ∝ p_max: the Monte Carlo σ equals the
    first-order σ from the sample's covariance to rounding."""
    m = examples.hitch_003()
    tol = [Tolerance("P6", 2000.0), Tolerance("Pgc_max", 0.5e6, "uniform")]
    r = monte_carlo(m, Q, tol, outputs=["p(ГЦ)", "G(ГЦ, S6)"], samples=500, seed=3)
    assert r.assembled.all()
    for o in ("p(ГЦ)", "G(ГЦ, S6)"):
        np.testing.assert_allclose(r.std(o), r.linear_std(o, sigma="sample"), rtol=1e-9)


def test_small_geometric_tolerances_agree_with_the_stack_up():
    m = examples.hitch_003()
    tol = [Tolerance(p, 0.2e-3) for p in ("X01", "Y01", "X03", "Y03", "X05", "Y05", "L3",
                                           "L34", "L4", "L5")]
    tol.append(Tolerance("Dgc", 0.05e-3, "uniform"))
    r = monte_carlo(m, Q, tol, samples=2000, seed=7)
    assert r.assembled.all() and r.failure_share == 0.0
    for o in r.outputs:
        np.testing.assert_allclose(r.std(o), r.linear_sigma[:, r.outputs.index(o)], rtol=0.05,
                                   err_msg=o)
        np.testing.assert_allclose(r.mean(o), r.nominal[:, r.outputs.index(o)], rtol=2e-3)
        p = r.percentiles(o)
        assert p.shape == (len(Q), 5) and (np.diff(p, axis=1) >= 0).all()


def test_seeded_and_reproducible():
    m = examples.hitch_003()
    tol = [Tolerance("X01", 1e-3)]
    a = monte_carlo(m, Q, tol, samples=50, seed=11)
    b = monte_carlo(m, Q, tol, samples=50, seed=11)
    np.testing.assert_array_equal(a.samples, b.samples)


def test_machines_that_fail_are_counted_with_their_reasons():
    """A tolerance on L4 of ±15 cm: some braces cannot close (dyad II); the share is the
    count of failing machines and each reason names the group."""
    m = examples.hitch_003()
    r = monte_carlo(m, Q, [Tolerance("L4", 0.30, "uniform")], outputs=["p(ГЦ)"],
                    samples=200, seed=5)
    assert 0.0 < r.failure_share < 1.0
    assert r.failure_share == pytest.approx((~r.assembled).sum() / 200)
    assert r.reasons and all(g for _, g, _ in r.reasons)
    assert all(msg for *_, msg in r.reasons)
    assert (r.samples[~r.assembled] == 0).all()


def test_errors():
    m = examples.hitch_003()
    with pytest.raises(ModelError, match="not parameters"):
        monte_carlo(m, Q, [Tolerance("nope", 1e-3)])
    with pytest.raises(ModelError, match="twice"):
        monte_carlo(m, Q, [Tolerance("X01", 1e-3), Tolerance("X01", 2e-3)])
    with pytest.raises(ModelError, match="dist must be one of"):
        Tolerance("X01", 1e-3, "triangular")
    with pytest.raises(ModelError, match="not negative"):
        Tolerance("X01", -1e-3)
