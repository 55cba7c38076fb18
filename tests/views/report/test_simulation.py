"""The simulation report (:mod:`assur.views.report.simulation`) of seed 001 lab 6's
lift: the time series are the result's arrays in the units their column names say,
every figure draws those columns, the summary says the same numbers in both
languages, and the written report holds the time series."""

import numpy as np
import pandas as pd
import pytest

from assur import io
from assur.dynamics import simulate
from assur.views.report.simulation import FIGURES, figures, summary, time_series, \
    write_simulation_report


@pytest.fixture(scope="module")
def result():
    model = io.load(io.bundled("adapter_lab6"))
    return simulate(model.mechanism, model.drive, 1.0, t_eval=np.linspace(0.0, 1.0, 11))


def test_time_series_are_the_results_arrays_in_their_units(result):
    df = time_series(result)
    np.testing.assert_array_equal(df["t [s]"], result.t)
    for col, arr, scale in (("S [m]", result.q, 1.0), ("dS/dt [m/s]", result.qdot, 1.0),
                            ("p1 [MPa]", result.p1, 1e6), ("p2 [MPa]", result.p2, 1e6)):
        np.testing.assert_allclose(df[col], np.asarray(arr).reshape(len(df), -1)[:, 0] / scale,
                                   rtol=1e-12)


def test_figures_draw_the_columns_and_the_summary_says_the_same_in_both_languages(result):
    df = time_series(result)
    figs = figures(result)
    assert tuple(figs) == FIGURES
    (p1, p2) = figs["pressure"].axes[0].lines[:2]
    np.testing.assert_allclose(p1.get_ydata(), df["p1 [MPa]"], rtol=1e-12)
    np.testing.assert_allclose(p2.get_xdata(), df["t [s]"], rtol=1e-12)
    en, ru = summary(result), summary(result, "ru")
    assert len(en) == len(ru) and en[0][0] != ru[0][0]
    # the same numbers, with the decimal comma in Russian
    assert [row[1] for row in en] == [row[1].replace(",", ".") for row in ru]
    assert all("." not in row[1] for row in ru)


def test_the_written_report_holds_the_time_series(result, tmp_path):
    write_simulation_report(result, tmp_path, title="lab 6", formats=("csv",))
    back = pd.read_csv(tmp_path / "simulation.csv")
    pd.testing.assert_frame_equal(back.drop(columns="phase"),
                                  time_series(result).drop(columns="phase"), rtol=1e-12,
                                  check_dtype=False)
