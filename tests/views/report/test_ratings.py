"""A figure per rating in the report, in the user's units."""

import numpy as np

from assur import io
from assur.views.report.ratings import rating_figures
from tests.helpers.ratings import ARM, TIPPING


def test_a_ratings_figure_in_the_users_units():
    a = io.loads(ARM + TIPPING).analyze()
    ax = rating_figures(a, units="engineering")["loader_tipping"].axes[0]
    assert ax.get_title() == "Tipping of the test loader"
    assert ax.get_xlabel() == "reach of T [mm]" and ax.get_ylabel() == "tipping load at T [kN]"
    x, y = ax.lines[0].get_data()
    np.testing.assert_allclose(x, a.ratings[0]["x"] * 1000.0, rtol=1e-15)
    np.testing.assert_allclose(y, a.ratings[0]["W_tip"] / 1000.0, rtol=1e-15)


def test_no_ratings_no_tables_or_figures():
    a = io.loads(ARM).analyze()
    assert rating_figures(a) == {}


def test_a_held_path_is_one_curve_and_a_three_coordinate_grid_is_points():
    """The self-levelling loader's lift chart: its tilt cylinder moves at every position
    (a held path), so one curve, not one single-point curve per position; the
    excavator's 5 × 5 × 5 grid over S1: points, not a line through the grid's order."""
    from assur import io
    from assur.views.report.ratings import rating_figures

    loader = rating_figures(io.load(io.bundled("frontloader_zbar")).analyze())
    lines = loader["loader_lift"].axes[0].get_lines()
    assert len(lines) == 1 and len(lines[0].get_xdata()) == 13
    assert lines[0].get_linestyle() == "-"
    arm = rating_figures(io.load(io.bundled("backhoe_arm")).analyze())
    for line in arm["excavator_digging"].axes[0].get_lines():
        assert line.get_linestyle() == "None" and line.get_marker() == "o"
