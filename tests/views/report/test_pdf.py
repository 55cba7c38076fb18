"""The report as a PDF (:mod:`assur.views.report.pdf`): Chromium's print of the HTML
report is a PDF of A4 pages (portrait, and landscape for the tables section), and every
way it can fail says so in a :class:`PdfError`: no Chromium (with what to install, and
that ``--format html`` needs none), a browser that fails (with its standard error), one
that hangs (stopped at the timeout), one that writes no PDF."""

import re
import shutil
import stat
import time

import pytest

from assur.views.report.html import write_html
from assur.views.report.pdf import PdfError, find_chromium, write_pdf
from tests.helpers import python_output


@pytest.fixture(scope="module")
def small_report(hitch_analysis, tmp_path_factory):
    """The hitch's report without figures, drawing or animation (its 8 tables)."""
    path = tmp_path_factory.mktemp("pdf") / "report.html"
    return write_html(hitch_analysis, path, lang="ru", figures={}, drawing=False,
                      animation=False)


def fake_browser(tmp_path, body):
    """An executable shell script standing in for Chromium."""
    exe = tmp_path / "fake-chromium"
    exe.write_text("#!/bin/sh\n" + body + "\n")
    exe.chmod(exe.stat().st_mode | stat.S_IXUSR)
    return exe


def test_a_small_report_prints_to_a4_pages(small_report, tmp_path):
    out = write_pdf(small_report, tmp_path / "report.pdf")
    data = out.read_bytes()
    assert out == tmp_path / "report.pdf" and data[:5] == b"%PDF-"
    boxes = [tuple(round(float(v)) for v in m.split()[2:])
             for m in re.findall(rb"/MediaBox\s*\[([^\]]*)\]", data)]
    assert len(re.findall(rb"/Type\s*/Page\b", data)) == len(boxes) >= 2
    # the model on portrait A4, the tables (table 5.1 has 29 columns) on landscape [pt]
    assert set(boxes) == {(595, 842), (842, 595)}
    assert not list(tmp_path.glob("*.html"))  # nothing else written beside it


def test_without_chromium_the_error_says_what_to_install(small_report, tmp_path,
                                                        monkeypatch):
    monkeypatch.delenv("ASSUR_CHROMIUM", raising=False)
    monkeypatch.setattr(shutil, "which", lambda name, *a, **k: None)
    with pytest.raises(PdfError) as e:
        write_pdf(small_report, tmp_path / "report.pdf")
    msg = str(e.value)
    assert "apt-get install chromium" in msg and "--format html" in msg
    assert "ASSUR_CHROMIUM" in msg and "chromium-browser" in msg
    assert isinstance(e.value, RuntimeError)
    assert not (tmp_path / "report.pdf").exists()


def test_assur_chromium_names_the_browser(tmp_path, monkeypatch):
    exe = fake_browser(tmp_path, "exit 0")
    monkeypatch.setenv("ASSUR_CHROMIUM", str(exe))
    assert find_chromium() == str(exe)
    monkeypatch.setenv("ASSUR_CHROMIUM", str(tmp_path / "missing"))
    with pytest.raises(PdfError, match="ASSUR_CHROMIUM=.*missing.*is not an executable"):
        find_chromium()


def test_a_failing_browser_is_reported_with_its_stderr(small_report, tmp_path):
    exe = fake_browser(tmp_path, "echo 'noise' >&2\necho 'cannot open display' >&2\nexit 3")
    with pytest.raises(PdfError, match=r"exit code 3\)(.|\n)*cannot open display$"):
        write_pdf(small_report, tmp_path / "report.pdf", chromium=exe)
    assert not (tmp_path / "report.pdf").exists()


def test_a_browser_that_writes_no_pdf(small_report, tmp_path):
    exe = fake_browser(tmp_path, "echo done >&2\nexit 0")
    with pytest.raises(PdfError, match="exited without writing a PDF"):
        write_pdf(small_report, tmp_path / "report.pdf", chromium=exe)


def test_a_hanging_browser_is_stopped_at_the_timeout(small_report, tmp_path):
    exe = fake_browser(tmp_path, "sleep 30 &\nsleep 30")  # a child of its own too
    t0 = time.perf_counter()
    with pytest.raises(PdfError, match=r"within 0\.5 s \(stopped\)"):
        write_pdf(small_report, tmp_path / "report.pdf", chromium=exe, timeout=0.5)
    assert time.perf_counter() - t0 < 10


def test_the_html_file_must_exist(tmp_path):
    with pytest.raises(FileNotFoundError, match="no such HTML file"):
        write_pdf(tmp_path / "missing.html", tmp_path / "report.pdf")


def test_the_module_imports_neither_matplotlib_nor_the_cli():
    code = ("import sys, assur.views.report.pdf; "
            "print(sorted(m for m in sys.modules if m.split('.')[0] == 'matplotlib' "
            "or m.startswith('assur.views.cli')))")
    assert python_output(code) == "[]"
