"""The command line: check, analyze, demo — exit codes, messages, files written."""

import pytest
from typer.testing import CliRunner

from assur.views.cli import app
from assur.io import bundled

from tests.helpers import TESTS
from tests.helpers.seed_tables import T003_2_1, T003_3_1a, T003_4_1, assert_printed

runner = CliRunner()


def test_check_bundled_hitch_ok():
    r = runner.invoke(app, ["check", str(bundled("hitch_003"))])
    assert r.exit_code == 0, r.output
    out = " ".join(r.output.split())  # rich wraps long lines (a long checkout path)
    assert "assembles at every position" in out
    assert "solved L4" in out and "0.661283167" in out


def test_check_header_000_fails_with_the_triangle_message():
    r = runner.invoke(app, ["check", str(bundled("header_000"))])
    assert r.exit_code == 1
    out = " ".join(r.output.split())
    assert "L4 exceeds L3 + L34 = 0.65234 m by 4.66 mm" in out
    assert "Traceback" not in r.output


def test_check_missing_file():
    r = runner.invoke(app, ["check", "no/such/model.toml"])
    assert r.exit_code == 1 and "no such file" in r.output


def test_analyze_writes_seed_tables_and_the_report_lists_the_solved_conditions(tmp_path):
    out = tmp_path / "rep"
    r = runner.invoke(app, ["analyze", str(bundled("hitch_003")), "-o", str(out),
                            "--format", "csv,html"])
    assert r.exit_code == 0, r.output
    csvs = sorted(p.name for p in out.glob("*.csv"))
    assert csvs, r.output
    text = (out / "report.html").read_text(encoding="utf-8")
    assert "Design conditions solved" in text
    assert "L4 = 0.661283167" in text and "L7 = 0.752169525" in text


def test_bad_options_exit_1(tmp_path):
    r = runner.invoke(app, ["analyze", str(bundled("hitch_003")), "--lang", "de"])
    assert r.exit_code == 1 and "--lang must be one of" in r.output
    r = runner.invoke(app, ["analyze", str(bundled("hitch_003")), "--format", "doc"])
    assert r.exit_code == 1 and "--format must be" in r.output


MALFORMED = sorted((TESTS / "io" / "malformed").glob("*.toml"))


def _expect(path):
    first = path.read_text(encoding="utf-8", errors="replace").splitlines()[0]
    key, line = first.split("expect:")[1].rsplit("@", 1)
    return key.strip(), int(line)


@pytest.mark.parametrize("path", MALFORMED, ids=lambda p: p.stem)
def test_check_malformed_file_exits_1_with_key_path_and_line(path):
    """Issue 4: each malformed file gives exit code 1 and one message naming the file,
    the line and the key path — never a traceback."""
    key, line = _expect(path)
    r = runner.invoke(app, ["check", str(path)])
    assert r.exit_code == 1, r.output
    out = " ".join(r.output.split())
    assert f"{path.name}:{line}" in out, out
    if key != "-":
        assert key in out, out
    assert "Traceback" not in r.output
    assert r.exception is None or isinstance(r.exception, SystemExit)


def test_analyze_csv_values_are_the_seed_tables(tmp_path):
    """File → solve (L4, Sp, L7 from the [[solve]] conditions) → engine → CSV, end to end
    through the command line: the written tables carry seed 003's printed numbers."""
    out = tmp_path / "rep"
    r = runner.invoke(app, ["analyze", str(bundled("hitch_003")), "-o", str(out),
                            "--format", "csv"])
    assert r.exit_code == 0, r.output
    import pandas as pd
    t21 = pd.read_csv(out / "table_2_1.csv")
    t31 = pd.read_csv(out / "table_3_1.csv")
    t41 = pd.read_csv(out / "table_4_1.csv")
    assert_printed(t21["phi6 [deg]"].to_numpy(), T003_2_1, "phi6")
    assert_printed(t21["phi34 [deg]"].to_numpy(), T003_2_1, "phi34")
    assert_printed(t31["IS6 [-]"].to_numpy(), T003_3_1a, "IS6")
    assert_printed(t31["U65 [-]"].to_numpy(), T003_3_1a, "U65")
    # in the units hitch_003.toml writes pressures and forces in (MPa, kN)
    assert_printed(t41["Pgc [MPa]"].to_numpy() * 1e6, T003_4_1, "Pgc")
    assert_printed(t41["Fgc [kN]"].to_numpy() * 1e3, T003_4_1, "Fgc")
    assert_printed(t41["GS6 [kN]"].to_numpy() * 1e3, T003_4_1, "GS6")
    # --units: the same numbers in another system; in Russian, ';' and the decimal comma
    r = runner.invoke(app, ["analyze", str(bundled("hitch_003")), "-o", str(out / "imp"),
                            "--format", "csv", "--units", "imperial", "--lang", "ru"])
    assert r.exit_code == 0, r.output
    t41 = pd.read_csv(out / "imp" / "table_4_1.csv", sep=";", decimal=",", encoding="utf-8-sig")
    assert list(t41.columns)[:3] == ["S [дюйм]", "Fgc [фунт-сила]", "Pgc [фунт/дюйм²]"]
    assert_printed(t41["Pgc [фунт/дюйм²]"].to_numpy() * 6894.7572931683635, T003_4_1, "Pgc")
    r = runner.invoke(app, ["analyze", str(bundled("hitch_003")), "-o", str(out / "x"),
                            "--format", "csv", "--units", "metric"])
    assert r.exit_code == 1 and "--units must be one of: file, engineering, si, imperial" in \
        r.output


def test_draw_at_chosen_positions(tmp_path):
    out = tmp_path / "d"
    r = runner.invoke(app, ["analyze", str(bundled("hitch_003")), "-o", str(out), "--format",
                            "png", "--draw-at", "0.476,0.614"])
    assert r.exit_code == 0, r.output
    assert (out / "mechanism.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    r = runner.invoke(app, ["analyze", str(bundled("hitch_003")), "-o", str(out), "--format",
                            "png", "--draw-at", "0.9"])
    assert r.exit_code == 1 and "outside the range" in r.output


def test_tables_prints_the_seed_tables():
    r = runner.invoke(app, ["tables", str(bundled("hitch_003")), "--table", "4.1"])
    assert r.exit_code == 0, r.output
    assert "4.1" in r.output and "Fgc [kN]" in r.output and "129.6" in r.output  # file's units
    r = runner.invoke(app, ["tables", str(bundled("hitch_003")), "--table", "4.1", "--units",
                            "si", "--lang", "ru"])
    assert r.exit_code == 0, r.output
    assert "Fgc [Н]" in r.output and "129614" in r.output and "0,4200" in r.output
    r = runner.invoke(app, ["tables", str(bundled("hitch_003")), "--table", "9.9"])
    assert r.exit_code == 1 and "this model has tables" in r.output


def test_analyze_frames_option(tmp_path):
    """``--frames 0``: the HTML report without its animation; with a GIF asked for, one
    message and exit 1; a negative count is refused by the option."""
    model = str(bundled("hitch_003"))
    for frames in ("0", "2"):
        r = CliRunner().invoke(app, ["analyze", model, "-o", str(tmp_path / frames),
                                     "--format", "html", "--frames", frames])
        assert r.exit_code == 0, r.output
        html = (tmp_path / frames / "report.html").read_text(encoding="utf-8")
        assert "<img" in html                                # the figures, the drawing
        assert ('id="animation"' in html) == (frames != "0")
    r = CliRunner().invoke(app, ["analyze", model, "-o", str(tmp_path / "b"), "--format",
                                 "gif", "--frames", "0"])
    assert r.exit_code == 1 and "--frames 0" in r.output and "Traceback" not in r.output
    r = CliRunner().invoke(app, ["analyze", model, "-o", str(tmp_path / "c"), "--frames", "-1"])
    assert r.exit_code != 0 and "Traceback" not in r.output


def test_analyze_prints_the_report_to_pdf(tmp_path, monkeypatch):
    """``--format pdf``: the HTML report printed on A4 by Chromium (installed by the
    project, make chromium); without a browser, one message before any analysis."""
    out = tmp_path / "pdf"
    r = runner.invoke(app, ["analyze", str(bundled("hitch_003")), "-o", str(out), "--format",
                            "csv,pdf", "--lang", "ru"])
    assert r.exit_code == 0, r.output
    data = (out / "report.pdf").read_bytes()
    assert data.startswith(b"%PDF") and data.count(b"/Type /Page") >= 3
    assert not (out / "report.html").exists()  # printed from a report of its own
    monkeypatch.setenv("ASSUR_CHROMIUM", str(tmp_path / "no-such-browser"))
    monkeypatch.setenv("PATH", str(tmp_path))
    r = runner.invoke(app, ["analyze", str(bundled("hitch_003")), "-o", str(tmp_path / "x"),
                            "--format", "pdf"])
    assert r.exit_code == 1 and "chromium" in r.output.lower() and "Traceback" not in r.output
