"""Every bundled model's HTML report (:mod:`assur.views.report.html`) in a real headless
Chromium (tests/views/conftest.py), as a document on the screen and on A4 paper.

On the screen, 1280 px wide: the page is screenshotted (under the test's tmp_path),
at most :data:`HEIGHT` px tall with its long tables collapsed to their key rows (the
crank machines' full turns of 361 positions and the loader's 13 × 8 grid made pages
of 33,000–67,000 px before), never wider than the window (wide tables scroll inside
their boxes), and a long table opens to every row when its summary is clicked.

On paper (print media, the window as wide as the content box of the A4 page that
report.css gives the content: portrait, or landscape for the tables section when it
is printed on the "wide" named page): no table reaches past the page's right edge,
every row of every table is printed (collapsed ones too) and every column of a table
cut into parts is in one of its parts; the animation is not printed. One report is
printed to a real PDF and has the pages its rows need, in both orientations.

Reports are in English, in Russian for :data:`RUSSIAN`; figures and the drawing are in,
the animation is not (its player has its own test, test_report_browser.py), but for
the one test that checks the print stylesheet hides it.
"""

import math
import re
from importlib.resources import files

import pytest

from assur import io
from assur.errors import AssemblyError
from assur.views.report import write_report
from assur.views.report.html import stylesheet
from tests.helpers.reports import SAME_REPORT

pytestmark = pytest.mark.slow

#: every bundled model but the variants whose report is their base's (SAME_REPORT)
MODELS = sorted(p.name[:-len(".toml")] for p in files("assur.models").iterdir()
                if p.name.endswith(".toml") and p.name[:-len(".toml")] not in SAME_REPORT)
#: reports rendered in Russian (the others in English)
RUSSIAN = {"hitch_003", "cleaning_lab3"}
#: the page's height bound at 1280 px [px] (measured: 5,000–14,500 px, the loader's
#: maps the tallest; before the long tables were collapsed, up to 66,600 px)
HEIGHT = 20_000
#: CSS px per mm (96 dpi)
PX_PER_MM = 96 / 25.4


def page_widths():
    """The content widths of the report's A4 pages [CSS px]: (portrait, landscape),
    from the left and right margins of its ``@page`` rules."""
    css = stylesheet()

    def width(rule, paper_mm):
        m = re.search(rule + r"\s*\{[^}]*margin:\s*([\d.]+)mm\s+([\d.]+)mm"
                            r"(?:\s+[\d.]+mm\s+([\d.]+)mm)?", css)
        assert m, f"report.css has no {rule} rule with margins in mm"
        right = float(m.group(2))
        left = float(m.group(3) or m.group(2))
        return math.floor((paper_mm - left - right) * PX_PER_MM)

    return width(r"@page", 210), width(r"@page\s+wide", 297)


_rendered = {}


def report_file(name, tmp_path_factory, frames=0):
    """The model's report.html (written once per process), or a skip for a bundled
    model that cannot assemble (those kept as their seed prints them)."""
    key = (name, frames)
    if key not in _rendered:
        try:
            analysis = io.load(io.bundled(name)).analyze()
        except AssemblyError as e:
            _rendered[key] = e
        else:
            out = tmp_path_factory.mktemp(name)
            lang = "ru" if name in RUSSIAN else "en"
            _rendered[key] = write_report(analysis, out, formats=("html",), lang=lang,
                                          frames=frames)["html"][0]
    got = _rendered[key]
    if isinstance(got, AssemblyError):
        pytest.skip(f"{name} cannot assemble (kept as its seed prints it): {got}")
    return got


#: per visible table: its section's heading, its header symbols, its rows (all and
#: displayed) and its right edge [px]
TABLES_JS = """sel => [...document.querySelectorAll(sel)]
  .filter(t => t.getClientRects().length > 0)
  .map(t => ({
    tab: t.closest('section.tab') ? t.closest('section.tab').querySelector('h3').id : null,
    symbols: [...t.tHead.rows[t.tHead.rows.length - 1].cells].map(c => c.firstChild.textContent),
    rows: t.tBodies[0].rows.length,
    shown: [...t.tBodies[0].rows].filter(r => r.getClientRects().length > 0).length,
    right: t.getBoundingClientRect().right }))"""


@pytest.mark.parametrize("name", MODELS, ids=MODELS)
def test_the_report_reads_on_the_screen_and_prints_on_a4(name, browser, tmp_path_factory,
                                                         tmp_path):
    path = report_file(name, tmp_path_factory)
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(path.as_uri())

    # ---- the screen, 1280 px ---------------------------------------------------------
    shot = tmp_path / f"{name}.png"
    page.screenshot(path=str(shot), full_page=True)
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    height = page.evaluate("document.documentElement.scrollHeight")
    assert height <= HEIGHT, f"{name}: the report is {height} px tall at 1280 px"
    assert page.evaluate("document.documentElement.scrollWidth") <= 1280  # no overflow
    screen = {t["tab"]: t for t in page.evaluate(TABLES_JS, "#tables table")}
    longs = page.locator("section.tab .long")
    for k in range(longs.count()):  # collapsed: the key rows, the summary says how many
        box = longs.nth(k)
        tid = box.evaluate("e => e.closest('section.tab').querySelector('h3').id")
        t = screen[tid]
        assert t["rows"] > 15 and 2 <= t["shown"] <= 9, (tid, t)
        assert f" {t['rows']} " in box.locator("summary").inner_text()
    if longs.count():  # opened: every row, in a box that scrolls (the page stays 1280 px)
        first = longs.first
        first.locator("summary").click()
        tid = first.evaluate("e => e.closest('section.tab').querySelector('h3').id")
        t = {t["tab"]: t for t in page.evaluate(TABLES_JS, "#tables table")}[tid]
        assert t["shown"] == t["rows"]
        assert page.evaluate("document.documentElement.scrollWidth") <= 1280
        first.locator("summary").click()

    # ---- A4 paper ----------------------------------------------------------------------
    page.emulate_media(media="print")
    portrait, landscape = page_widths()
    wide = page.evaluate("document.querySelector('#tables.wide') !== null")
    checks = [(portrait, "table:not(#tables table)")]
    checks.append((landscape if wide else portrait, "#tables table"))
    printed = {}
    for width, sel in checks:
        page.set_viewport_size({"width": width, "height": 1000})
        for t in page.evaluate(TABLES_JS, sel):
            assert t["right"] <= width + 0.5, \
                f"{name}: a table of {t['tab'] or 'the model'} is cut: {t['right']} > {width} px"
            assert t["shown"] == t["rows"], f"{name}: {t['tab']} prints {t['shown']} of " \
                                            f"{t['rows']} rows"
            if t["tab"]:
                printed.setdefault(t["tab"], []).append(t)
    assert set(printed) == set(screen)  # every table is printed …
    for tid, parts in printed.items():  # … with every column (parts repeat the first)
        symbols = [s for k, t in enumerate(parts) for s in t["symbols"][(k > 0):]]
        assert symbols == screen[tid]["symbols"], tid
        assert all(t["symbols"][0] == screen[tid]["symbols"][0] for t in parts)
    assert not errors


def test_print_leaves_the_animation_out(browser, tmp_path_factory):
    path = report_file("combine_002", tmp_path_factory, frames=3)
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    page.goto(path.as_uri())
    shown = "document.getElementById('animation').getClientRects().length > 0"
    assert page.evaluate(shown)
    page.emulate_media(media="print")
    assert not page.evaluate(shown)
    assert page.evaluate("document.querySelector('#drawing img').getClientRects().length > 0")


def test_a_pdf_holds_every_row_of_the_long_tables(browser, tmp_path_factory):
    """A full crank turn (361 positions in 3 tables) printed by Chromium: every row, on
    portrait pages and on the landscape pages of the tables section."""
    path = report_file("combine_002_turn", tmp_path_factory)
    page = browser.new_page()
    page.goto(path.as_uri())
    rows = page.evaluate("[...document.querySelectorAll('#tables section.tab')].map("
                         "s => s.querySelector('table').tBodies[0].rows.length)")
    assert sum(rows) >= 3 * 361
    pdf = page.pdf(format="A4", prefer_css_page_size=True)
    assert pdf[:5] == b"%PDF-"
    boxes = [tuple(round(float(v)) for v in m.split()[2:])
             for m in re.findall(rb"/MediaBox\s*\[([^\]]*)\]", pdf)]
    assert (595, 842) in boxes and (842, 595) in boxes  # A4 portrait and landscape [pt]
    # a landscape page's content box (186 mm) holds at most ~60 rows of 7.5 pt
    assert boxes.count((842, 595)) >= sum(rows) / 60
