"""The ratings' tables among the report's, in the user's units (tables/_ratings.py)."""

import numpy as np

from assur import io
from assur.core.display import unit_system
from assur.views.report import seed_tables
from assur.views.report.tables import table_filename
from assur.views.report.tables._ratings import rating_tables
from tests.helpers.ratings import ARM, TIPPING


def test_the_crane_charts_table_is_among_the_reports_tables():
    a = io.load(io.bundled("crane_lv184a")).analyze()
    tables = seed_tables(a)
    t = next(t for t in tables if t.id == "R1")
    r = a.ratings[0]
    np.testing.assert_array_equal(t["G"], r["G"])
    assert t.title("en").startswith("Load chart") and t.column("M").unit == "N·m"
    assert table_filename(t).endswith("_rating_1.csv")
    eng = next(t for t in seed_tables(a, units="engineering") if t.id == "R1")
    assert eng.column("M").unit == "kN·m"
    np.testing.assert_allclose(eng["M"], r["M"] / 1000.0, rtol=1e-15)


def test_a_ratings_title_and_single_values_in_the_users_units():
    a = io.loads(ARM + TIPPING).analyze()
    (t,) = rating_tables(a, unit_system(a.mechanism, "engineering"))
    assert t.title("ru") == "Опрокидывание"
    static = a.ratings[0].scalars[0].values[0]
    note = t.notes[0]["en"]
    assert note.startswith("static tipping load") and f"{static / 1000:.4g} kN" in note
    assert rating_tables(io.loads(ARM).analyze()) == []
