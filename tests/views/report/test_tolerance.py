"""The tolerance report (:mod:`assur.views.report.tolerance`) of a Monte Carlo on the
seed-003 hitch: the tables hold the nominal values of an analysis of the nominal
design and the samples' spread and percentiles, in the units shown; the written CSV
files hold the tables."""

import numpy as np
import pandas as pd
import pytest

from assur import examples
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
