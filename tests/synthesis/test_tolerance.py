"""Tolerance analysis (:mod:`assur.synthesis.tolerance`) on the seed 003 hitch: the Monte Carlo
over manufacturing tolerances against the first-order stack-up from the exact
sensitivities, the model file's ``[tolerances]`` section and its errors, and the
command ``assur tolerance``.

Why the comparison can fail: the Monte Carlo evaluates every drawn machine through
the compiled fused kernel; the stack-up uses derivatives from the dual numbers
(:mod:`assur.synthesis.sensitivity`). For an output linear in the toleranced parameters
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
from assur.synthesis.tolerance import Tolerance, monte_carlo

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


# ---------------------------------------------------------------------------------
# the [tolerances] section
# ---------------------------------------------------------------------------------
def _hitch_with(section: str):
    text = io.bundled("hitch_003").read_text(encoding="utf-8")
    return io.loads(text + "\n[tolerances]\n" + section, name="t.toml")


def test_bundled_file_reads_its_tolerances():
    """hitch_003_tolerances.toml extends hitch_003.toml: units of each parameter's
    quantity (mm, deg, MPa), normal by ±3σ or uniform."""
    m = io.load(io.bundled("hitch_003_tolerances"))
    tol = {t.param: t for t in m.tolerances}
    assert tol["X01"].dist == "normal" and tol["X01"].sigma == pytest.approx(0.5e-3 / 3)
    assert tol["phiBD"].pm == pytest.approx(np.radians(0.2))
    assert tol["Pgc_max"].dist == "uniform" and tol["Pgc_max"].pm == pytest.approx(0.5e6)
    assert tol["Dgc"].sigma == pytest.approx(0.037e-3 / np.sqrt(3))
    assert m.mechanism.params["L4"] == pytest.approx(0.661283167, abs=1e-9)


def test_stdform():
    m = _hitch_with('X01 = { sigma = "0.1 mm" }\nL5 = "+-0.2 mm"\n')
    assert [t.sigma for t in m.tolerances] == pytest.approx([1e-4, 0.2e-3 / 3])


@pytest.mark.parametrize("section, key, problem", [
    ('X1 = "±0.5 mm"', "tolerances.X1", "did you mean"),
    ('X01 = "±0.5 kN"', "tolerances.X01", "length"),
    ('X01 = "-0.5 mm"', "tolerances.X01", "non-negative"),
    ('X01 = { pm = "1 mm", dist = "triangle" }', "tolerances.X01.dist", "normal, uniform"),
    ('X01 = { pm = "1 mm", sigma = "1 mm" }', "tolerances.X01", "either pm"),
    ('X01 = { sigma = "1 mm", dist = "uniform" }', "tolerances.X01.sigma", "uniform"),
    ('X01 = { pn = "1 mm" }', "tolerances.X01.pn", "unknown key"),
    ('X01 = true', "tolerances.X01", "expected"),
])
def test_errors_name_the_key_and_line(section, key, problem):
    text = io.bundled("hitch_003").read_text(encoding="utf-8")
    line = text.count("\n") + 3
    with pytest.raises(ModelError) as e:
        _hitch_with(section)
    msg = str(e.value)
    assert f"t.toml:{line}:" in msg and key in msg and problem in msg, msg


@pytest.mark.slow
def test_cli_writes_tables_histograms_and_report(tmp_path):
    from typer.testing import CliRunner

    from assur.views.cli import app
    out = tmp_path / "tol"
    res = CliRunner().invoke(app, ["tolerance", str(io.bundled("hitch_003_tolerances")), "-o",
                                   str(out), "--samples", "300", "--seed", "2", "--lang", "ru"])
    assert res.exit_code == 0, res.output
    names = sorted(p.name for p in out.iterdir())
    assert names == ["tolerance.html", "tolerance.xlsx", "tolerance_hist_1.png",
                     "tolerance_hist_2.png", "tolerance_hist_3.png", "tolerance_positions.csv",
                     "tolerance_worst.csv"]
    html = (out / "tolerance.html").read_text(encoding="utf-8")
    assert "Анализ допусков" in html and "P95" in html
    import pandas as pd
    worst = pd.read_csv(out / "tolerance_worst.csv")
    assert worst.shape == (3, 10)
    m = io.load(io.bundled("hitch_003_tolerances"))
    g = m.mechanism.evaluate(m.range, outputs=["G(ГЦ, 56)"])["G(ГЦ, 56)"]
    assert worst["номинал"][1] == pytest.approx(g.min() / 1e3, rel=1e-12)  # kN
    assert worst["P5"][1] < worst["P50"][1] < worst["P95"][1]
    res = CliRunner().invoke(app, ["tolerance", str(io.bundled("hitch_003")), "-o", str(out)])
    assert res.exit_code == 1 and "no [tolerances]" in res.output
