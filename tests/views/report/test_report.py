"""Reports (``assur.views.report``): the seed-003 tables written as CSV and XLSX match the
printed tables of ``003_b1551261b108abd1.txt`` at the printed precision (read back
from the files), the HTML report is one self-contained file, the figures are valid
PNG and SVG files, Russian labels with ``lang="ru"``, and mechanisms without
cylinders, loads or machine data get only the tables whose data exist.

Symbols (``assur.views.report.tables``): the CSV columns carry the seed's symbols — the
generic ``F_S``, ``p_S``, ``dGS6``, ``I56_ic``/``IS6_ic`` are renamed Fgc, Pgc, dGS65,
Imp, lsp by the model file's ``[tables] symbols``. Reactions are assur's force of link i on link j; seed 003 prints R05, R34,
R45 with the opposite sign (the model file's sign map, ``mechanism.tables["signs"]``).
"""

import csv
import html
import re
import time
import xml.etree.ElementTree as ET
from html.parser import HTMLParser

import numpy as np
import pandas as pd
import pytest

from assur import Mechanism, examples
from assur.core.columns import column_signs, formulas_of, signs_of
from assur.core.display import factor
from assur.views.report import DEFAULT_FORMATS, report_steps, seed_tables, write_report
from assur.views.report.tables import table_filename
from assur.views.report import figures as report_figures
from assur.views.report.html import write_html

from tests.helpers.seed_tables import (T003_6_1, T003_2_1, T003_2_2a, T003_2_2b, T003_2_2c, T003_2_2d, T003_3_1a,
                         T003_3_1b, T003_4_1, T003_5_1, T003_IC, assert_printed, table)

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def report(hitch_analysis, tmp_path_factory):
    out = tmp_path_factory.mktemp("report") / "hitch"
    steps = []
    t0 = time.perf_counter()
    # every format; an animation of 12 frames (the default 30 render the same code)
    files = write_report(hitch_analysis, out, progress=steps.append, frames=12)
    return dict(out=out, files=files, steps=steps, seconds=time.perf_counter() - t0)


def as_unit(values, unit, target):
    """Values written in ``unit`` (a CSV header's) in the seed's printed ``target``."""
    return np.asarray(values, dtype=float) * (factor(unit) / factor(target))


def read_csv(path):
    """{symbol: array} from a report CSV (header ``symbol [unit]``), and the units."""
    df = pd.read_csv(path)
    cols, units = {}, {}
    for h in df.columns:
        sym, u = h.split(" [")
        cols[sym] = df[h].to_numpy(dtype=float)
        units[sym] = u.rstrip("]")
    return cols, units


# ---- seed 003 tables from the CSV files -----------------------------------------------
def test_files_and_progress(report):
    files, out = report["files"], report["out"]
    assert set(files) == set(DEFAULT_FORMATS)  # the PDF only when asked for
    names = {p.name for ps in files.values() for p in ps}
    for n in ["table_2_1.csv", "table_2_2.csv", "table_3_1.csv", "table_4_1.csv",
              "table_5_1.csv", "table_6_1.csv", "table_ic.csv", "tables.xlsx", "report.html",
              "fig_capacity.png", "fig_capacity.svg", "mechanism.png", "mechanism.gif"]:
        assert n in names and (out / n).stat().st_size > 0, n
    assert report["steps"] == report_steps(DEFAULT_FORMATS)


def test_csv_table_2_1_link_angles(report):
    """Seed 003, Таблица 2.1 [deg]."""
    c, u = read_csv(report["out"] / "table_2_1.csv")
    assert u["S"] == "m" and u["phi3"] == "deg"
    assert_printed(c["S"], T003_2_1, "S")
    for col in ["phi34", "phi3", "phi4", "phi5", "phi6", "phi7"]:
        assert_printed(c[col], T003_2_1, col)


@pytest.mark.parametrize("text,cols", [
    (T003_2_2a, ["X23", "Y23", "X34", "Y34"]),
    (T003_2_2b, ["X45", "Y45"]),
    (T003_2_2c, ["X56", "Y56", "X67", "Y67"]),
    (T003_2_2d, ["XS6", "YS6"]),
])
def test_csv_table_2_2_points(report, text, cols):
    """Seed 003, Таблица 2.2 [m]; the seed's loop checks X34s, X45s, X67s equal the
    points (its X23s, Y23s is its own slip, see test_seed_003)."""
    c, u = read_csv(report["out"] / "table_2_2.csv")
    for col in cols:
        assert u[col] == "m"
        assert_printed(c[col], text, col)
    for col in [k for k in table(text) if k.endswith("s") and not k.startswith(("X23", "Y23"))]:
        assert_printed(c[col[:-1]], text, col)
    assert c["closure"].max() < 1e-9


def test_csv_table_3_1_kinematics(report):
    """Seed 003, Таблица 3.1: U43…U75, I56, IS6 and the analogs dφ3…dφ7 (its φ41…φ71)."""
    c, u = read_csv(report["out"] / "table_3_1.csv")
    for col in ["U43", "U53", "U65", "U75", "I56", "IS6"]:
        assert u[col] == "-"
        assert_printed(c[col], T003_3_1a, col)
    for col in ["dphi3", "dphi4", "dphi5", "dphi6", "dphi7"]:
        assert u[col] == "rad/m"
        assert_printed(c[col], T003_3_1b, col)


def test_csv_table_4_1_capacity(report):
    """Seed 003, Таблица 4.1: Fgc [N], Pgc [Pa], G56, GS6 [N], ΔGS65 [%]; the report
    writes them in the units hitch_003.toml gives forces and pressures in (kN, MPa)."""
    c, u = read_csv(report["out"] / "table_4_1.csv")
    printed = {"Fgc": "N", "Pgc": "Pa", "G56": "N", "GS6": "N", "dGS65": "%"}
    shown = {"Fgc": "kN", "Pgc": "MPa", "G56": "kN", "GS6": "kN", "dGS65": "%"}
    for sym, seed_unit in printed.items():
        assert u[sym] == shown[sym]
        assert_printed(as_unit(c[sym], u[sym], seed_unit), T003_4_1, sym)


def test_csv_table_5_1_reactions(report, hitch_analysis):
    """Seed 003, Таблица 5.1 [N]: every printed column; components of R05, R34, R45
    compared with the documented opposite sign, magnitudes and Fgc as printed."""
    c, u = read_csv(report["out"] / "table_5_1.csv")
    signs = column_signs(hitch_analysis.mechanism)
    assert {n for n, s in signs.items() if s < 0} == {"R05x", "R05y", "R34x", "R34y", "R45x",
                                                      "R45y"}
    printed = table(T003_5_1)
    for col in printed:
        if col == "S":
            continue
        if col == "Fgc":
            assert_printed(as_unit(c["Fgc"], u["Fgc"], "N"), T003_5_1, col)
            continue
        sign = signs.get(col, 1)
        assert u[col] == "kN"  # the file's unit of force
        assert_printed(sign * as_unit(c[col], u[col], "N"), T003_5_1, col)
    # the table itself marks the flipped columns and says why
    t51 = next(t for t in seed_tables(hitch_analysis) if t.id == "5.1")
    assert {col.symbol for col in t51.columns if col.printed_sign < 0} == {
        "R05x", "R05y", "R34x", "R34y", "R45x", "R45y"}
    assert any("opposite sign" in n["en"] for n in t51.notes)


def test_csv_table_6_1_stability(report):
    """Seed 003, Таблица 6.1: Ra, Rb [N], ΔRa, ΔRb [%] and the seed's flagged GS6max."""
    c, u = read_csv(report["out"] / "table_6_1.csv")
    for col, seed_unit in (("Ra", "N"), ("Rb", "N"), ("dRa", "%"), ("dRb", "%"),
                           ("GS6max", "N")):
        assert_printed(as_unit(c[col], u[col], seed_unit), T003_6_1, col)
    # every force in the file's unit, the model's formula column (declared in N) too
    assert u["dRa"] == "%" and u["Ra"] == u["GS6max"] == u["G_max"] == "kN"
    assert np.all(c["steerable"] == 1)
    assert np.all(c["G_max"] < c["GS6max"] - 10.0)  # the correct limit is far below [kN]


def test_csv_instantaneous_centre_check(report):
    """Seed 003, last table: I56, IS6 and Imp = φ6'·(X56 − Xp), lsp = φ6'·(XS6 − Xp)."""
    c, _ = read_csv(report["out"] / "table_ic.csv")
    for seed in ("I56", "IS6", "Imp", "lsp"):
        assert_printed(c[seed], T003_IC, seed)
    assert np.allclose(c["Imp"], c["I56"], atol=1e-9)


def test_csv_round_trips_exactly(report, hitch_analysis):
    """Full precision: every number read back is the float in the table (in the
    report's display units)."""
    for tab in seed_tables(hitch_analysis, units="file"):
        with open(report["out"] / f"table_{tab.id.replace('.', '_').lower()}.csv",
                  newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        assert rows[0] == [f"{col.symbol} [{col.unit}]" for col in tab.columns]
        for j, col in enumerate(tab.columns):
            back = np.array([float(r[j]) for r in rows[1:]])
            assert np.array_equal(back, np.asarray(col.values, dtype=float)), (tab.id, col.symbol)


def test_xlsx_holds_the_csv_numbers(report, hitch_analysis):
    """A sheet of the inputs first, then a sheet per table named by its id and title:
    the title, the symbols and the units of the CSV's header above the CSV's numbers
    (stored as numbers, every digit), the table's notes below."""
    from openpyxl import load_workbook

    from assur.views.report.tables import sheet_name
    tables = seed_tables(hitch_analysis, units="file")
    wb = load_workbook(report["out"] / "tables.xlsx", read_only=True)
    assert wb.sheetnames == ["Inputs"] + [sheet_name(tab) for tab in tables]
    inputs = [r for r in wb["Inputs"].iter_rows(values_only=True)]
    assert ("P6", 27.5, "kN") in [tuple(r[:3]) for r in inputs]  # as the file gives it
    for tab in tables:
        with open(report["out"] / table_filename(tab), newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        sheet = [list(r) for r in wb[sheet_name(tab)].iter_rows(values_only=True)]
        assert sheet[0][0] == f"Table {tab.id} — {tab.title('en')}"
        assert [f"{s} [{u}]" for s, u in zip(sheet[1], sheet[2])] == rows[0]
        data = sheet[3:3 + len(rows) - 1]
        for srow, crow in zip(data, rows[1:]):
            for sv, cv in zip(srow, crow):
                assert isinstance(sv, (int, float)) and not isinstance(sv, bool)
                assert float(sv) == float(cv)
        notes = [r[0] for r in sheet[3 + len(data) + 1:]]
        assert notes == [n["en"] for n in tab.notes]
    wb.close()


# ---- HTML ---------------------------------------------------------------------------
class _Refs(HTMLParser):
    def __init__(self):
        super().__init__()
        self.refs, self.ids, self.imgs = [], set(), []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        for k in ("src", "href", "srcset", "poster", "data"):
            if k in a:
                self.refs.append((tag, k, a[k]))
        if tag == "img":
            self.imgs.append(a.get("src", ""))


def test_html_is_one_self_contained_file(report, hitch_analysis):
    import base64

    text = (report["out"] / "report.html").read_text(encoding="utf-8")
    p = _Refs()
    p.feed(text)
    assert p.refs and p.imgs
    for tag, attr, val in p.refs:
        assert val.startswith("data:") or val.startswith("#"), (tag, attr, val[:60])
        if val.startswith("#"):
            assert val[1:] in p.ids, f"anchor {val} has no target"
    for src in p.imgs:
        assert base64.b64decode(src.split(",", 1)[1])[:8] == PNG_SIGNATURE
    # no address anywhere outside the base64 payloads (which may spell "hTtP" by chance)
    bare = re.sub(r"data:[a-z/+]+;base64,[A-Za-z0-9+/=]+", "", text).lower()
    assert "http" not in bare and "//" not in bare.replace("://", "")
    assert "<link" not in bare and "@import" not in bare and "url(" not in bare
    plain = html.unescape(text)
    for tab in seed_tables(hitch_analysis):
        assert f"Table {tab.id} — {tab.title_en}" in plain
    for note in hitch_analysis.mechanism.notes:
        assert note in plain
    notes = [m.note for m in signs_of(hitch_analysis.mechanism)]
    flags = [x for f in formulas_of(hitch_analysis.mechanism) for x in f.flags]
    assert len(notes) == 1 and len(flags) == 3
    for flag in notes + flags:
        assert flag in plain
    assert "Warnings and notes" in plain
    assert len(p.imgs) >= 9 + 1  # the diagrams, the drawing
    # the animation: vector frames in one inline SVG (no address), its player's captions
    frames = re.findall(r'<g class="frame"', text)
    assert len(frames) > 1 and 'id="anim-svg"' in text and 'id="anim-q">S = 0.42 m<' in text


def test_figures_are_valid_png_and_svg(report):
    files = report["files"]
    # every figure but "distances" (the hitch names no distance), and the drawing
    assert len(files["png"]) == len(files["svg"]) == len(report_figures.FIGURES) - 1 + 1
    for path in files["png"]:
        data = path.read_bytes()
        assert data[:8] == PNG_SIGNATURE and len(data) > 5000, path.name
    for path in files["svg"]:
        root = ET.parse(path).getroot()
        assert root.tag.endswith("svg") and len(list(root.iter())) > 20, path.name
    gif = files["gif"][0].read_bytes()
    assert gif[:6] == b"GIF89a"
    from PIL import Image
    with Image.open(files["gif"][0]) as im:
        assert im.n_frames > 10


# ---- Russian ------------------------------------------------------------------------
def test_russian_labels(hitch_analysis, tmp_path):
    figs = report_figures.figures(hitch_analysis, "ru", names=["capacity", "stability"])
    ax = figs["capacity"].axes[0]
    assert ax.get_title() == "Грузоподъёмность"
    assert "длина гидроцилиндра S [м]" == ax.get_xlabel() and "[кН]" in ax.get_ylabel()
    tabs = seed_tables(hitch_analysis, "ru")
    assert tabs[0].title("ru").startswith("Результаты геометрического анализа")
    path = write_html(hitch_analysis, tmp_path / "ru.html", lang="ru", figures=figs, animation=False)
    text = html.unescape(path.read_text(encoding="utf-8"))
    for s in ["Таблица 2.1", "Таблица 6.1", "Предупреждения и примечания", "Параметры",
              "Рисунок 1 — Грузоподъёмность", "Схема механизма", "[МПа]", "[°]"]:
        assert s in text, s
    assert "Warnings and notes" not in text


# ---- other mechanisms ---------------------------------------------------------------
def lift_without_loads():
    """README's lift: a cylinder–lever group and a dyad, no loads, cylinders or machine."""
    return (Mechanism("lift", coordinates=("S",), params={"L3": 0.2, "L4": 0.66, "L5": 0.48})
            .frame("01", 0.415, 0.563).frame("03", 0.25, 1.112).frame("05", 0.135, 0.48)
            .cylinder_lever("I", base="01", pivot="03", out="23", lever="L3", s="S",
                            branch=-1, links=("2", "3"))
            .rigid_point("arm", origin="03", toward="23", out="34", length=0.325, angle=0.384)
            .dyad("II", a="34", b="05", out="45", ra="L4", rb="L5", branch=+1,
                  links=("4", "5"))
            .link("3", "03", "23").link("5", "05", "45"))


def test_only_tables_whose_data_exist(tmp_path):
    a = lift_without_loads().analyze(np.linspace(0.42, 0.67, 6))
    assert [t.id for t in seed_tables(a)] == ["2.1", "2.2", "3.1"]
    files = write_report(a, tmp_path / "lift", formats=("csv", "html", "png"), frames=4)
    # numbered in the report's order, named by what they hold (no [tables] numbering)
    assert sorted(p.name for p in files["csv"]) == [
        "table_1_link_angles.csv", "table_2_points.csv", "table_3_analogs.csv"]
    figs = {p.name for p in files["png"]}
    assert {"fig_angles.png", "fig_analogs.png", "mechanism.png"} <= figs
    assert not figs & {"fig_capacity.png", "fig_reactions.png", "fig_stability.png"}
    text = (tmp_path / "lift" / "report.html").read_text(encoding="utf-8")
    assert "Table 4" not in text and "Table 1 — Geometric analysis: link angles" in text


def crank_rocker(positions):
    """Grashof crank-rocker: crank 1 (r = 1) about O, coupler 2 (3.5), rocker 3 (2.5)
    about B = (4, 0), a weight on the rocker's end C."""
    return (Mechanism("crank-rocker", coordinates=("q",), params=dict(ra=3.5, rb=2.5, P=100.0),
                      tables={"ratios": [("1", "3")], "transmissions": ["C"]})
            .frame("O", 0.0, 0.0).frame("B", 4.0, 0.0)
            .crank("crank", pivot="O", out="A", radius=1.0, q="q", links=("1",))
            .dyad("II", a="A", b="B", out="C", ra="ra", rb="rb", branch=1, links=("2", "3"))
            .link("1", "O", "A").link("2", "A", "C").link("3", "B", "C")
            .weight("C", "P")).analyze(positions)


def test_crank_angle_in_degrees_and_singular_ratio_flagged(tmp_path):
    """A crank coordinate is tabulated in degrees and its analogs in rad/rad; the ratio
    U13 = φ1'/φ3' at the rocker's dead position (φ3' = 0) is left empty and reported."""
    from scipy.optimize import brentq

    q = np.linspace(0.2, 6.0, 59)
    d3 = crank_rocker(q).kinematics.dphi("3")
    k = int(np.flatnonzero(np.sign(d3[:-1]) != np.sign(d3[1:]))[0])
    q0 = brentq(lambda x: float(crank_rocker([x]).kinematics.dphi("3")[0]), q[k], q[k + 1],
                xtol=1e-15)
    pos = np.sort(np.append(q, q0))
    a = crank_rocker(pos)
    tabs = {t.id: t for t in seed_tables(a)}
    assert list(tabs) == ["2.1", "2.2", "3.1", "5.1", "IC"]  # no cylinder, no machine
    col = tabs["2.1"].column("q")
    assert col.unit == "deg" and np.allclose(col.values, np.degrees(pos))
    assert tabs["3.1"].column("dphi3").unit == "-"
    u13 = tabs["3.1"]["U13"]
    assert np.isnan(u13).sum() == 1 and np.isfinite(u13).sum() == len(pos) - 1
    assert any("U13 is singular at 1 position" in n["en"] for n in tabs["3.1"].notes)
    # the rocker turns about its pivot B = (4, 0): the instantaneous-centre check finds it,
    # except at its dead position, where it is undefined
    ic = tabs["IC"]
    ok = np.isfinite(ic["Xp"])
    assert (~ok).sum() == 1 and np.allclose(ic["Xp"][ok], 4.0) and np.allclose(ic["Yp"][ok], 0.0)
    assert np.allclose(ic["IC_ic"][ok], ic["IC"][ok])
    path = write_html(a, tmp_path / "crank.html", animation=False)
    assert "U13 is singular at 1 position" in path.read_text(encoding="utf-8")


def test_batch_needs_a_design(hitch_analysis):
    s = examples.hitch_003_range()
    batch = examples.hitch_003(P6=np.array([20000.0, 27500.0])).analyze(s)
    with pytest.raises(ValueError, match="design="):
        seed_tables(batch)
    one = {t.id: t for t in seed_tables(hitch_analysis)}
    for t in seed_tables(batch, design=1):
        for col in t.columns:
            assert np.allclose(col.values, one[t.id][col.symbol], rtol=1e-12, equal_nan=True)


def test_bad_options(hitch_analysis, tmp_path):
    with pytest.raises(ValueError, match="lang must be one of"):
        seed_tables(hitch_analysis, lang="de")
    with pytest.raises(ValueError, match="formats must be among"):
        write_report(hitch_analysis, tmp_path, formats=("doc",))
    fig = report_figures.force(hitch_analysis)
    with pytest.raises(ValueError, match="suffix must be one of"):
        report_figures.save(fig, tmp_path / "f.jpg")


def test_each_figure_is_built_once_for_png_svg_and_html(tmp_path, monkeypatch):
    """Issue 28: a figure is built once and drawn from that one object as PNG, SVG and
    the HTML report's image (each of its PNG bytes is the report's)."""
    import base64

    import assur.views.report as report
    from assur import io

    built = []
    real = report._build

    def counted(job, *args, **kwargs):
        built.append(job)
        return real(job, *args, **kwargs)

    monkeypatch.setattr(report, "_build", counted)
    a = io.load(io.bundled("steering_lab4")).analyze()
    files = write_report(a, tmp_path, formats=("png", "svg", "html"), frames=0, jobs=1)
    assert len(built) == len(set(built)) == len(report._figure_jobs(a)) + 1  # + the drawing
    assert len(files["svg"]) == len(files["png"])
    page = files["html"][0].read_text(encoding="utf-8")
    for p in files["png"]:
        assert base64.b64encode(p.read_bytes()).decode() in page, p.name
