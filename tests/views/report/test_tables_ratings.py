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
    assert table_filename(t).endswith("_crane_chart.csv")
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


def test_the_governing_limits_key_prints_as_whole_numbers(tmp_path):
    """The governing limit (1 = the first cylinder, 2 = the second …) is an index: its
    column holds integers, printed without decimals in the report, the CSV and the
    workbook."""
    from assur.views.report import write_csv
    from assur.views.report.html import table_view

    a = io.load(io.bundled("crane_lv184a")).analyze()
    t = next(t for t in seed_tables(a) if t.id == "R1")
    gov = t.column("governing").values
    assert gov.dtype.kind == "i" and set(gov.tolist()) <= {1, 2, 3}
    np.testing.assert_array_equal(gov, a.ratings[0]["governing"])
    k = [c.symbol for c in t.columns].index("governing")
    assert {row[k] for row in table_view(t, "ru")["rows"]} <= {"1", "2", "3"}
    lines = write_csv(t, tmp_path / "chart.csv", "ru").read_text(encoding="utf-8-sig").splitlines()
    assert {line.split(";")[k] for line in lines[1:]} <= {"1", "2", "3"}


def test_the_ratings_files_are_named_by_their_kind():
    """Tables and figures of a machine's ratings are named by the rating's kind (two of
    a kind numbered), not by their place in the file."""
    from assur.views.report.ratings import rating_figures

    a = io.load(io.bundled("frontloader_zbar")).analyze()
    names = [table_filename(t) for t in seed_tables(a) if t.id.startswith("R")]
    assert [n.split("_", 2)[2] for n in names] == ["loader_tipping.csv", "loader_breakout.csv",
                                                   "loader_lift.csv"]
    assert list(rating_figures(a)) == ["loader_tipping", "loader_breakout", "loader_lift"]
