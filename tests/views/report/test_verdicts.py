"""The verdicts of the report's first page (issue 23): each equal to the value in its
table, linked to that table, in the display units and the language of the report —
for the hitch, the loader, the crank machines and the steering drive."""

from __future__ import annotations

import copy
import re
from functools import lru_cache

import numpy as np
import pytest

from assur import io
from assur.texts import localize
from assur.core.display import unit_system
from assur.views.report.html import _anchor
from assur.views.report.tables import seed_tables
from assur.views.report.verdicts import STATUSES, Verdict, anchor_of, verdicts
from tests.helpers import by_numpy

MODELS = ("hitch_003", "loader_lab1", "cleaning_lab3", "combine_002", "steering_lab4")
SYSTEMS = ("file", "imperial")
LANGS = ("en", "ru")

#: the verdicts each model gets: derived from what its analysis holds
KEYS = {
    "hitch_003": ["assembly", "capacity_G56", "capacity_GS6", "reserve_dGS65", "pressure_ГЦ",
                  "stability", "gmax", "slips", "warnings"],
    "loader_lab1": ["assembly", "capacity_G09_S", "capacity_GS3_S", "capacity_GS9_S",
                    "capacity_GS9_S1", "reserve_dGS9_S", "reserve_dGS9_S1", "pressure_MPS",
                    "pressure_MPT", "stability", "gmax", "slips", "warnings"],
    "cleaning_lab3": ["assembly", "driving_moment", "slips", "warnings"],
    "combine_002": ["assembly", "slips", "warnings"],
    "steering_lab4": ["assembly", "pressure_ГЦ1", "slips", "warnings"],
}
#: how each kind of verdict picks its row of the column
EXTREME = {"capacity": "min", "reserve": "min", "stability": "min", "gmax": "min",
           "pressure": "max", "driving_moment": "absmax", "assembly": "absmax"}


@lru_cache(maxsize=None)
def _analysis(name):
    """The bundled model's analysis as ``assur analyze`` makes it (numpy kernels: no
    compilation for one load)."""
    return by_numpy(lambda: io.load(io.bundled(name)).analyze())


@lru_cache(maxsize=None)
def _page(name, system, lang):
    a = _analysis(name)
    du = unit_system(a.mechanism, system)
    tables = seed_tables(a, lang, units=du)
    return a, du, tables, verdicts(a, tables, du, lang)


def _names(a, tables):
    """Every name of the model and symbol of its tables (Latin letters allowed in a
    Russian text): coordinates, column symbols, parameters, points, links, cylinders,
    supply lines, axles and weights."""
    mech = a.mechanism
    names = set(a.kinematics.coordinates) | set(mech.params)
    names |= {c.symbol for t in tables for c in t.columns}
    for b, body in mech.bodies.items():
        names.add(b)
        names |= set(body["points"])
    for c in mech.cylinders:
        names |= {c.name, str(c.supply)}
    carry = mech.machine
    if carry is not None and carry.machine is not None:
        names |= set(carry.machine.axles)
        names |= {w[0] for w in carry.machine.weights + carry.machine.counterweights}
    return names | {localize(n, "ru") for n in names}


@pytest.mark.parametrize("name", MODELS)
def test_the_verdicts_are_derived_from_the_content(name):
    a, _, _, found = _page(name, "file", "en")
    assert [v.key for v in found] == KEYS[name]
    assert all(isinstance(v, Verdict) and v.status in STATUSES for v in found)


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("system", SYSTEMS)
@pytest.mark.parametrize("name", MODELS)
def test_every_verdict_is_the_value_of_its_table(name, system, lang):
    a, du, tables, found = _page(name, system, lang)
    by_id = {t.id: t for t in tables}
    anchors = {_anchor("table-", t.id) for t in tables} | {"warnings"}
    assert [v.key for v in found] == KEYS[name]   # the same verdicts in every system
    for v in found:
        assert v.anchor in anchors, v
        assert v.text[0].isupper() and v.text.endswith("."), v.text
        if v.table is None:
            assert v.anchor == "warnings" and v.column is None and v.value is None
            continue
        assert v.anchor == anchor_of(v.table) == _anchor("table-", v.table)
        col = by_id[v.table].column(v.column)
        values = np.asarray(col.values, dtype=float)
        assert v.value == by_id[v.table][v.column][v.row]   # exactly, as the table holds it
        how = EXTREME[v.key.split("_")[0] if not v.key.startswith("driving") else
                      "driving_moment"]
        if how == "min":
            assert v.value == np.nanmin(values)
        elif how == "max":
            assert v.value == np.nanmax(values)
        else:
            assert abs(v.value) == np.nanmax(np.abs(values))
        # the position is named by the coordinates as the table shows them
        for c in a.kinematics.coordinates:
            assert f"{c} = " in v.text


@pytest.mark.parametrize("system", SYSTEMS)
@pytest.mark.parametrize("name", MODELS)
def test_russian_verdicts_have_no_english_and_the_decimal_comma(name, system):
    a, du, tables, found = _page(name, system, "ru")
    names = _names(a, tables)
    for v in found:
        left = [w for w in re.findall(r"[A-Za-z0-9_]+", v.text)
                if re.search(r"[A-Za-z]{3,}", w) and w not in names]
        assert not left, (v.key, left, v.text)
        assert not re.search(r"\d\.\d", v.text), v.text   # the decimal comma
        assert re.search(r"[А-Яа-я]", v.text)


@pytest.mark.parametrize("system", ("file", "engineering", "si", "imperial"))
def test_values_are_shown_in_the_systems_units(system):
    a = _analysis("hitch_003")
    du = unit_system(a.mechanism, system)
    found = {v.key: v for v in verdicts(a, seed_tables(a, units=du), du)}
    p = found["pressure_ГЦ"]
    assert p.text.count(f" {du['pressure'].text}") == 2   # the pressure and p_max
    assert f" {du['force'].text} " in found["capacity_GS6"].text
    assert f" {du['length'].text}" in found["assembly"].text


def test_the_hitch_pressure_is_the_largest_pgc_against_its_relief_pressure():
    a, du, tables, found = _page("hitch_003", "file", "en")
    p = next(v for v in found if v.key == "pressure_ГЦ")
    table = {t.id: t for t in tables}["4.1"]
    assert (p.table, p.column, p.anchor) == ("4.1", "Pgc", "table-4-1")
    assert p.value == table["Pgc"].max() == table["Pgc"][p.row]
    assert table.column("Pgc").unit == "MPa" and round(p.value, 2) == 16.06
    # 16.06 MPa is 91.8 % of the 17.5 MPa relief setting: above PRESSURE_WARN (90 %)
    assert p.status == "warn"
    assert "16.06 MPa at S = 0.67 m, 91.8 % of its relief pressure p_max = 17.5 MPa" in p.text


@pytest.mark.parametrize("relief, status", [(15e6, "fail"), (20e6, "ok")])
def test_the_pressure_verdict_follows_the_relief_pressure(relief, status):
    m = by_numpy(io.load, io.bundled("hitch_003"))
    a = m.mechanism.with_params(Pgc_max=relief).analyze(m.range)
    du = unit_system(a.mechanism, "engineering")
    found = {v.key: v for v in verdicts(a, seed_tables(a, units=du), du, "ru")}
    assert found["pressure_ГЦ"].status == status
    assert ("выше давления настройки" in found["pressure_ГЦ"].text) == (status == "fail")
    # below the pressure the weight needs, the capacity falls below the weight too
    assert found["reserve_dGS65"].status == ("fail" if status == "fail" else "ok")
    assert (found["reserve_dGS65"].value < 0) == (status == "fail")


def test_a_heavier_implement_fails_the_stability():
    m = by_numpy(io.load, io.bundled("hitch_003"))
    a = m.mechanism.with_params(P_gr=0.0).analyze(m.range)   # no counterweights
    du = unit_system(a.mechanism, "file")
    tables = seed_tables(a, units=du)
    v = next(v for v in verdicts(a, tables, du) if v.key == "stability")
    assert v.status == "fail" and v.column == "dRa" and v.value < 20.0
    assert v.value == {t.id: t for t in tables}["6.1"]["dRa"].min()


def test_the_steering_drive_has_one_pressure_per_supply_line_and_no_capacity():
    a, du, tables, found = _page("steering_lab4", "file", "en")
    (p,) = [v for v in found if v.key.startswith("pressure_")]
    assert p.column == "p_S1" and "supply line P (cylinders ГЦ1, ГЦ2" in p.text
    assert p.status == "ok"
    assert not [v for v in found if v.key.split("_")[0] in ("capacity", "reserve", "stability")]


def test_the_crank_machine_names_its_largest_driving_moment():
    a, du, tables, found = _page("cleaning_lab3", "file", "ru")
    v = next(v for v in found if v.key == "driving_moment")
    assert (v.table, v.column, v.anchor) == ("D", "M_d", "table-d")
    assert "Н·м при j1 = " in v.text and v.text.endswith("°.")


def test_failures_warnings_and_notes():
    a = _analysis("combine_002")
    du = unit_system(a.mechanism, "file")
    tables = seed_tables(a, units=du)

    class Failing:   # kinematics that record assembly failures
        failures = ["dyad 1 does not close at j1 = 14.68 deg"]

        def __getattr__(self, attr):
            return getattr(a.kinematics, attr)

    b = copy.copy(a)
    b.kinematics = Failing()
    b.model_warnings = ("unused parameter 'x'",)
    found = {v.key: v for v in verdicts(b, tables, du)}
    assert found["assembly"].status == "fail" and "dyad 1 does not close" in found["assembly"].text
    assert found["assembly"].anchor == "warnings"
    assert found["warnings"].status == "warn" and found["warnings"].text.endswith(": 1.")
    assert found["slips"].text.endswith(f": {len(a.mechanism.notes)}.")
    ru = {v.key: v for v in verdicts(b, tables, du, "ru")}
    assert ru["assembly"].status == "fail" and "сообщений: 1" in ru["assembly"].text
    assert {v.key: v.status for v in verdicts(a, tables, du)}["warnings"] == "ok"


def test_the_units_may_be_named_and_the_language_is_checked():
    a, du, tables, found = _page("hitch_003", "file", "en")
    assert verdicts(a, tables, "file") == found
    with pytest.raises(ValueError, match="lang must be one of"):
        verdicts(a, tables, du, "de")


def test_a_cylinder_without_a_relief_setting_is_not_above_it():
    """spout_lab5.toml gives its cylinder no relief pressure: its largest pressure is a
    key figure (info), not a failure against p_max = 0."""
    from assur import io
    from assur.core.display import unit_system
    from assur.views.report.tables import seed_tables
    from assur.views.report.verdicts import verdicts

    a = io.load(io.bundled("spout_lab5")).analyze()
    du = unit_system(a.mechanism)
    for lang in ("en", "ru"):
        tabs = seed_tables(a, lang, units=du)
        (p,) = [v for v in verdicts(a, tabs, du, lang) if v.key.startswith("pressure")]
        assert p.status == "info" and "∞" not in p.text
        t41 = next(t for t in tabs if t.id == p.table)
        assert p.value == max(t41[p.column])  # the column's largest value
    # its analysis notes the motion its inertia loads are taken at: a note, not a warning
    assert a.notes and not a.model_warnings
    assert {v.key: v.status for v in verdicts(a, tabs, du)}["warnings"] == "ok"


@pytest.mark.parametrize("lang, says", [("en", "below zero: there the cylinder"),
                                        ("ru", "меньше нуля: в этом положении")])
def test_a_capacity_below_zero_is_a_warning_that_says_what_it_means(lang, says):
    """The excavator's arm cylinder lowers the bucket pivot over part of its stroke:
    its smallest capacity there is below zero, a warning with what that means; a
    positive smallest capacity stays a plain figure."""
    a = _analysis("backhoe_arm")
    du = unit_system(a.mechanism, "file")
    tables = seed_tables(a, lang, units=du)
    caps = [v for v in verdicts(a, tables, du, lang) if v.key.startswith("capacity_")]
    assert {v.status for v in caps} == {"info", "warn"}
    for v in caps:
        assert (v.value < 0) == (v.status == "warn") == (says in v.text), v.text
        assert v.value == {t.id: t for t in tables}[v.table][v.column].min()
