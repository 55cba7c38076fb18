"""The tolerance report (:mod:`assur.views.report.tolerance`) of a Monte Carlo on the
seed-003 hitch: the tables hold the nominal values of an analysis of the nominal
design and the samples' spread and percentiles, in the units shown; the written CSV
files hold the tables."""

import numpy as np
import pandas as pd
import pytest

from assur import examples
from assur.errors import ModelError
from assur.synthesis.tolerance import Tolerance, monte_carlo
from assur.views.report.tolerance import display_scale, tolerance_tables, write_tolerance

Q = [0.45, 0.6]


@pytest.fixture(scope="module")
def run():
    m = examples.hitch_003()
    tol = [Tolerance("X01", 0.5e-3), Tolerance("L4", 1e-3, "uniform")]
    return m, monte_carlo(m, Q, tol, outputs=["p(ГЦ)", "Y(56)"], samples=200, seed=1)


def test_tables_in_the_units_shown(run):
    m, r = run
    tabs = tolerance_tables(r)
    a = m.analyze(Q)  # the nominal design, by the report path
    nominal = {"p(ГЦ)": a.cylinder().pressure, "Y(56)": a.kinematics.y("56")}
    pos = tabs["tolerance_positions"]
    assert pos["q"].tolist() == Q
    for o, unit in (("p(ГЦ)", "MPa"), ("Y(56)", "mm")):
        scale, shown = display_scale(r, o)
        assert shown == unit
        np.testing.assert_allclose(pos[f"{o} nominal [{unit}]"], nominal[o] / scale, rtol=1e-9)
        values = r.values(o) / scale   # machines × positions
        assert values.shape == (200, 2)
        np.testing.assert_allclose(pos[f"{o} σ (MC) [{unit}]"], values.std(axis=0, ddof=1),
                                   rtol=1e-9)
        for k in (5, 50, 95):
            np.testing.assert_allclose(pos[f"{o} P{k} [{unit}]"],
                                       np.percentile(values, k, axis=0), rtol=1e-9)
    worst = tabs["tolerance_worst"].set_index("unit")
    assert worst.loc["MPa", "nominal"] == pytest.approx(nominal["p(ГЦ)"].max() / 1e6, rel=1e-9)


def test_the_written_tables(run, tmp_path):
    m, r = run
    write_tolerance(r, m, tmp_path, formats=("csv",))
    tabs = tolerance_tables(r)
    for name, df in tabs.items():
        back = pd.read_csv(tmp_path / f"{name}.csv")
        np.testing.assert_allclose(back.select_dtypes("number"), df.select_dtypes("number"),
                                   rtol=1e-12)


def _drawn(assembling):
    """Two seed-003 hitches drawn with ±3 m on the pivot X01 (most do not assemble),
    the first seed of which ``assembling`` assemble."""
    from assur.synthesis.tolerance import Tolerance as T
    m = examples.hitch_003()
    for seed in range(50):
        r = monte_carlo(m, [0.45, 0.6], [T("X01", 3.0)], outputs=["p(ГЦ)"], samples=2,
                        seed=seed)
        if int(r.assembled.sum()) == assembling:
            return m, r
    raise AssertionError(f"no seed below 50 draws {assembling} machines that assemble")


def test_one_machine_that_assembles_is_reported_without_nan(tmp_path):
    """Of two machines drawn one assembles: its values are the percentiles, σ (MC) —
    undefined for one — is an empty cell, "—" in the report with a note; nothing
    written holds a NaN, and no numpy warning is raised."""
    import re
    import warnings

    m, r = _drawn(1)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a σ of one value would warn (ddof = 1)
        files = write_tolerance(r, m, tmp_path, formats=("csv", "xlsx", "html"))
    worst = pd.read_csv(tmp_path / "tolerance_worst.csv")
    assert worst["σ (MC)"].isna().all()  # empty cells
    w = r.worst("p(ГЦ)")[0] / 1e6
    assert worst.loc[0, "P5"] == pytest.approx(w) and worst.loc[0, "P95"] == pytest.approx(w)
    page = (tmp_path / "tolerance.html").read_text(encoding="utf-8")
    page = re.sub(r"data:[^'\"]*", "", page)
    assert "one machine assembles" in page and "<td>—</td>" in page
    assert not re.search(r"\b(nan|NaN|inf)\b", page)
    for f in files:
        if f.suffix == ".csv":
            assert "nan" not in f.read_text(encoding="utf-8").lower()
    with pytest.raises(ModelError, match="two or more that assemble; 1 of 2 did"):
        r.std("p(ГЦ)")


def test_no_machine_that_assembles_is_one_message(tmp_path):
    m, r = _drawn(0)
    with pytest.raises(ModelError, match=r"none of the 2 machines drawn assembles: no "
                                         r"distribution to report \(machine 0: "):
        write_tolerance(r, m, tmp_path)
    with pytest.raises(ModelError, match="no drawn machine assembles"):
        r.worst_percentiles("p(ГЦ)")
