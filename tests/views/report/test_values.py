"""The user's units and language in reports (issue 9; DESIGN.md §12).

* every parameter is shown in the unit the model file gave it (seed 003:
  17.5 MPa, 80 mm, 27.5 kN, 22°), solved conditions in those units
  (φ6(S = Sp) = 90°, not 1.5708), and files by their name, not an absolute path;
* the Russian report is Russian throughout: the model's title, notes, flags and sign
  notes given in both languages (``{ en = "…", ru = "…" }``) appear in the report's
  language only;
* a parameter's quantity follows from each concept's own declaration (group fields,
  loads', cylinders' and the machine's ``quantities``), so a mechanism built in
  Python shows SI units without a list of types in the report.
"""

import html
import pickle
import re

import numpy as np
import pytest

from assur import Mechanism, io
from assur.analysis import analyze
from assur.io import ModelFileError
from assur.core.cylinders import Cylinder
from assur.core.loads import Weight
from assur.core.quantities import Unit, display_units, parameter_quantities, unit_text
from assur.views.report.html import render_html
from assur.views.report.labels import unit
from assur.views.report.values import solved_line
from assur.texts import Text, localize, text


@pytest.fixture(scope="module")
def hitch():
    model = io.load(io.bundled("hitch_003"))
    a = analyze(model.mechanism, model.range)
    a.solved = tuple(model.solved)
    return model, a


def visible(page):
    """The visible text of an HTML page (no styles, scripts or image data)."""
    page = re.sub(r"<(style|script).*?</\1>", "", page, flags=re.S)
    page = re.sub(r"<img[^>]*>", "", page)
    return html.unescape(re.sub(r"<[^>]+>", "\n", page))


def param_rows(text):
    """{name: (value, unit)} of the parameter table of a report's visible text."""
    lines = [s.strip() for s in text.splitlines() if s.strip()]
    i = lines.index("Parameters") if "Parameters" in lines else lines.index("Параметры")
    rows, k = {}, i + 4
    while k + 2 < len(lines) and not lines[k].startswith(("Structural", "Структурные")):
        rows[lines[k]] = (lines[k + 1], lines[k + 2])
        k += 3
    return rows


@pytest.mark.parametrize("lang, kn, mpa, mm", [("en", "kN", "MPa", "mm"),
                                                ("ru", "кН", "МПа", "мм")])
def test_parameters_in_the_units_the_file_gave(hitch, lang, kn, mpa, mm):
    """hitch_003.toml writes P6 = "27.5 kN", Pgc_max = "17.5 MPa", Dgc = "80 mm",
    phiBD = 22 (degrees), P_mcxa = "56 kN"; the report shows exactly these."""
    _, a = hitch
    rows = param_rows(visible(render_html(a, lang=lang, figures={}, animation=False)))
    point = "," if lang == "ru" else "."  # the decimal comma in Russian
    assert rows["P6"] == (f"27{point}5", kn)
    assert rows["P_mcxa"] == ("56", kn)
    assert rows["Pgc_max"] == (f"17{point}5", mpa)
    assert rows["Dgc"] == ("80", mm)
    assert rows["phiBD"] == ("22", "°")
    assert rows["L4"][0] == f"0{point}661283167"  # solved, in the unit of its start value
    assert rows["Smin"] == (f"0{point}42", "m" if lang == "en" else "м")


def test_solved_conditions_in_the_files_units_and_named_by_file_name(hitch):
    model, a = hitch
    page = render_html(a, lang="en", figures={}, animation=False)
    text_ = visible(page)
    assert "φ6(S = Sp) = 90° (hitch_003.toml:" in text_
    assert "Y56(S = Smin) = 0.2 m (hitch_003.toml:" in text_
    assert "1.5708" not in text_
    src = model.solved[0].condition.source
    folder = src.rsplit("/", 1)[0]
    assert folder and folder not in page  # the absolute path of this machine: nowhere
    ru = visible(render_html(a, lang="ru", figures={}, animation=False))
    assert re.search(r"L7 = 0,752169525 м: φ6\(S = Sp\) = 90° \(hitch_003\.toml:\d+; "
                     r"невязка [-0-9,e]+°\)", ru)


def test_russian_report_is_russian_throughout(hitch):
    """Title, notes, sign note, formula label and flags of hitch_003.toml are given in
    both languages; each report shows its language's text and not the other's."""
    _, a = hitch
    mech = a.mechanism
    en = visible(render_html(a, lang="en", figures={}, animation=False))
    ru = visible(render_html(a, lang="ru", figures={}, animation=False))
    from assur.core.columns import formulas_of, signs_of
    texts = [mech.title, *mech.notes, *(m.note for m in signs_of(mech)),
             *(x for f in formulas_of(mech) for x in f.flags)]
    assert len(texts) >= 6
    for t_ in texts:
        assert t_.translations["ru"], t_
        assert t_.translations["ru"] in ru and str(t_) not in ru
        assert str(t_) in en and t_.translations["ru"] not in en
    assert "Механизм навески мини-трактора" in ru
    # nothing of the report's own words is left in English
    for english in ("residual", " for L", "the seed prints", "Warnings", "Parameters"):
        assert english not in ru


def test_a_model_may_give_its_texts_in_one_language_or_both(tmp_path):
    src = io.bundled("header_000_fixed").read_text(encoding="utf-8")
    model = io.loads(src.replace('extends = "header_000.toml"',
                                 f'extends = "{io.bundled("header_000").as_posix()}"'),
                     name="fixed.toml")
    assert model.mechanism.title.startswith("Combine header lift")
    assert localize(model.mechanism.title, "ru").startswith("Механизм подъёма жатки")
    hitch = io.bundled("hitch_003").read_text(encoding="utf-8")
    plain = io.loads(re.sub(r"(?m)^title = .*$", 'title = "only one"', hitch), name="x.toml")
    assert localize(plain.mechanism.title, "ru") == "only one"


@pytest.mark.parametrize("bad", ['{ de = "Titel" }', "{ }", '{ en = 3 }', "3"])
def test_a_bad_text_is_an_error_with_its_line(bad):
    src = f'[model]\nname = "x"\ncoordinates = ["S"]\ntitle = {bad}\n[frame]\nA = [0, 0]\n'
    with pytest.raises(ModelFileError) as e:
        io.loads(src, name="bad.toml")
    msg = str(e.value)
    assert "bad.toml:4" in msg and "model.title" in msg and "text" in msg


def test_text_is_a_string_that_keeps_its_translations():
    t_ = text({"en": "closure", "ru": "замыкание"})
    assert t_ == "closure" and isinstance(t_, str)
    assert localize(t_, "ru") == "замыкание" and localize(t_, "en") == "closure"
    back = pickle.loads(pickle.dumps(t_))
    assert back == t_ and localize(back, "ru") == "замыкание"
    assert localize(text({"ru": "только"}), "en") == "только"
    assert text("plain") == "plain" and localize("plain", "ru") == "plain"
    assert repr(Text("a", ru="б")) == "'a'"  # a name in a message: its identifying string


def test_quantities_come_from_each_concepts_declaration():
    """A mechanism built in Python (no file, no units): every parameter gets its
    quantity from the group fields, the loads and the cylinders, and is shown in SI
    (angles in degrees)."""
    m = (Mechanism("lift", coordinates=("S",),
                   params={"L3": 0.2, "ang": 0.384, "P": 1000.0, "D": 0.08, "pr": 17.5e6,
                           "k": 2, "unused": 1.0})
         .frame("01", 0.415, 0.563).frame("03", 0.25, 1.112)
         .cylinder_lever("I", base="01", pivot="03", out="23", lever="L3", s="S",
                         branch=-1, links=("2", "3"))
         .rigid_point("arm", origin="03", toward="23", out="34", length=0.325, angle="ang"))
    m = m._with(loads=(Weight("34", "P"),),
                cylinders=(Cylinder("C", "S", bore="D", count="k", p_relief="pr"),))
    q = parameter_quantities(m)
    assert q == {"L3": "length", "ang": "angle", "P": "force", "D": "length",
                 "pr": "pressure", "k": "number"}
    u = display_units(m)
    assert u["ang"].is_degrees and u["P"] == Unit("N") and u["pr"] == Unit("Pa")
    assert u["unused"] == Unit("-")
    # a caller may give display units too
    m2 = m.with_units(P=Unit("kN", 1e3))
    assert display_units(m2)["P"] == Unit("kN", 1e3)
    assert m2.units["P"].of(m2.params["P"]) == 1.0


def test_unit_spelling():
    assert unit_text("kN*m") == "kN·m" and unit_text("kg*m^2") == "kg·m²"
    assert unit_text("m/s**2") == "m/s²" and unit_text("degree") == "deg"
    assert unit("kN·m", "ru") == "кН·м" and unit("l/min", "ru") == "л/мин"
    assert unit("MPa", "ru") == "МПа" and unit("mm", "en") == "mm"


def test_check_prints_solved_conditions_in_the_files_units(hitch):
    model, _ = hitch
    line = solved_line(model.solved[2], model.mechanism, "en")
    assert re.fullmatch(r"L7 = 0\.752169525 m: φ6\(S = Sp\) = 90° \(hitch_003\.toml:\d+; "
                        r"residual [-0-9.e]+°\)", line), line
    assert np.isclose(model.solved[2].condition.unit.scale, np.pi / 180)


def _bundled():
    from pathlib import Path
    return sorted(p.stem for p in Path(io.bundled("hitch_003")).parent.glob("*.toml"))


@pytest.mark.parametrize("name", _bundled())
def test_every_bundled_model_speaks_russian(name):
    """The Russian report of a bundled model is Russian throughout: its title, notes,
    formula labels and flags, and sign notes all carry a Russian text."""
    from assur.core.columns import formulas_of, signs_of
    mech = io.load(io.bundled(name)).mechanism
    texts = [mech.title, *mech.notes, *(m.note for m in signs_of(mech) if m.note),
             *(x for f in formulas_of(mech) for x in (f.label, *f.flags) if x)]
    for t_ in texts:
        ru = localize(t_, "ru")
        assert ru != str(t_) and re.search("[а-яА-Я]", ru), f"{name}: {t_!r} has no Russian"


def test_column_names_unique_when_a_coordinate_is_named_like_a_link(tmp_path):
    """A crank coordinate named phi1 beside the angle of its link 1: the link's column
    becomes phi1_link (noted), every header of the CSV is unique."""
    from assur.views.report import seed_tables, write_report
    text = io.bundled("cleaning_lab3").read_text(encoding="utf-8")
    text = re.sub(r'\bj1\b', "phi1", text)
    model = io.loads(text, name="c.toml")
    a = model.mechanism.analyze(model.range)
    t21 = seed_tables(a)[0]
    assert t21.symbols[:3] == ["phi1", "phi1_link", "phi2"]
    np.testing.assert_allclose(t21["phi1_link"] % 360, t21["phi1"] % 360, atol=1e-9)
    assert any("phi1_link" in n["en"] for n in t21.notes)
    for tab in seed_tables(a):
        assert len(set(tab.symbols)) == len(tab.symbols), tab.id
    files = write_report(a, tmp_path, formats=("csv",))["csv"]
    for f in files:
        header = f.read_text(encoding="utf-8").splitlines()[0].split(",")
        assert len(set(header)) == len(header), f.name


def test_no_negative_zero_in_files_or_terminal(tmp_path):
    from assur.views.report.numbers import decimals, number
    from assur.views.report.tables import Column, Table, write_csv, write_xlsx
    tab = Table("2.1", {"en": "t", "ru": "t"}, (Column("S", "m", np.array([-0.0, 1.0])),
                                                 Column("phi3", "deg", np.array([0.0, -0.0]))))
    text = write_csv(tab, tmp_path / "t.csv").read_text(encoding="utf-8")
    assert "-0.0" not in text and "0.0" in text
    import openpyxl
    ws = openpyxl.load_workbook(write_xlsx([tab], tmp_path / "t.xlsx")).active
    vals = [c.value for row in ws.iter_rows(min_row=2) for c in row]
    assert all(not (v == 0 and np.signbit(v)) for v in vals)
    # the terminal and the HTML print with the column's decimals: never "-0"
    assert number(-0.0, 0) == "0" and number(-2.0, 0) == "-2" and number(-1e-9, 3) == "0.000"
    assert [number(v, decimals([-2.0, -1.0, -0.149])) for v in (-2.0, -1.0, -0.149)] == \
        ["-2.000", "-1.000", "-0.149"]  # one count of decimals per column


def test_an_undefined_value_is_an_empty_cell(tmp_path):
    """An undefined value (NaN: a singular ratio) is an empty cell in the CSV, in both
    dialects, and in the workbook — never the word nan."""
    import csv

    import openpyxl

    from assur.views.report.tables import Column, Table, write_csv, write_xlsx
    tab = Table("3.1", {"en": "t", "ru": "t"}, (Column("S", "m", np.array([0.42, 0.5])),
                                                 Column("U", "-", np.array([np.nan, 1.5]))))
    with open(write_csv(tab, tmp_path / "t.csv"), encoding="utf-8") as f:
        assert list(csv.reader(f))[1:] == [["0.42", ""], ["0.5", "1.5"]]
    with open(write_csv(tab, tmp_path / "r.csv", "ru"), encoding="utf-8-sig") as f:
        assert list(csv.reader(f, delimiter=";"))[1:] == [["0,42", ""], ["0,5", "1,5"]]
    ws = openpyxl.load_workbook(write_xlsx([tab], tmp_path / "t.xlsx")).active
    assert [ws.cell(4, 2).value, ws.cell(5, 2).value] == [None, 1.5]
