"""The page end to end in a real headless Chromium (issue 13).

The browser is tests/views/conftest.py's (Debian's chromium). The server is ``assur serve``'s application on loopback with
the seed-003 hitch. The page logs "assur: redrawn in … ms" after every parameter
change (the time from the input event to the new drawing); the test prints those
times — measured, not asserted (benchmarks/page.py measures them too).
"""

import re
from pathlib import Path

import pytest

from assur.io import bundled

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def url():
    from assur.views.page.server import create_app, running
    with running(create_app(bundled("hitch_003"))) as u:
        yield u


def _redraws(logs):
    return [float(m.group(1)) for m in (re.search(r"redrawn in ([\d.]+) ms", s) for s in logs)
            if m]


def test_hitch_page_end_to_end(browser, url, page_log):
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    logs, errors = [], []
    page.on("console", lambda m: logs.append(m.text))
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(url + "/")
    page.wait_for_selector("#pt-56")
    assert "Mini-tractor mounted-implement hitch" in page.text_content("#title")

    # the stroke slider moves the drawing and the table's values
    page.select_option("#table-select", "2.2")
    y0 = float(page.get_attribute("#pt-56", "data-y"))
    cell0 = page.text_content("#value-Y56")
    row0 = page.get_attribute("#table tr.current", "data-row")
    assert abs(y0 - 0.2) < 1e-9   # seed 003 §2.2: Y56(Smin) = 0.2 m (the Find condition)
    assert page.text_content("#position-text").startswith("S = 0.42 m")
    page.fill("#stroke", "50")
    y1 = float(page.get_attribute("#pt-56", "data-y"))
    assert y1 > y0 + 0.05          # the lift rises with the stroke
    assert page.text_content("#value-Y56") != cell0
    assert float(page.text_content("#value-Y56")) == pytest.approx(y1, rel=1e-4)
    assert page.get_attribute("#table tr.current", "data-row") == "50" != row0
    assert page.text_content("#position-text").startswith("S = 0.545 m")

    # the units shown: engineering (mm) for the position and the tables, then the file's
    page.select_option("#units", "engineering")
    page.wait_for_function("document.getElementById('position-text').textContent"
                           ".startsWith('S = 545 mm')")
    assert float(page.text_content("#value-Y56")) == pytest.approx(1e3 * y1, rel=1e-4)
    page.select_option("#units", "file")
    page.wait_for_function("document.getElementById('position-text').textContent"
                           ".startsWith('S = 0.545 m')")

    # a link length that cannot assemble: the message in place of the drawing
    n = len(logs)
    page.fill("#input-L5", "0.3")
    page.wait_for_selector("#error-panel:not([hidden])")
    message = page.text_content("#error-message")
    assert "RRR dyad 'II (4,5)'" in message and "L4 + L5 = 0.626167 + 0.3" in message
    assert "cannot assemble" in message
    assert "Traceback" not in message
    assert not page.is_visible("#drawing")

    # restored: the drawing is back where it was
    page.fill("#input-L5", "0.48")
    page.wait_for_selector("#error-panel", state="hidden")
    page.wait_for_function("!document.getElementById('drawing-box').classList.contains('failed')")
    assert page.is_visible("#drawing")
    page.wait_for_function(
        "Math.abs(Number(document.getElementById('pt-56').dataset.y) - %r) < 1e-12" % y1)

    # a feasible change re-solves the Find conditions and redraws
    page.fill("#input-L5", "0.5")
    page.wait_for_function("document.getElementById('param-L5').classList.contains('changed')")
    page.wait_for_function("!document.getElementById('drawing-box').classList.contains("
                           "'failed') && document.querySelectorAll('#plots svg').length > 0")

    # the edited model file is downloaded with the new value
    with page.expect_download() as dl:
        page.click("[data-export=toml]")
    text = Path(dl.value.path()).read_text(encoding="utf-8")
    assert 'L5 = "0.5 m"' in text and "# §1.2 links" in text

    # animated: play moves the stroke and the drawing with it; a second click stops it
    s0 = page.input_value("#stroke")
    ya = page.get_attribute("#pt-56", "data-y")
    page.click("#play")
    page.wait_for_function("document.getElementById('stroke').value !== %r" % s0)
    page.wait_for_function("document.getElementById('pt-56').dataset.y !== %r" % ya)
    page.click("#play")
    stopped = page.input_value("#stroke")
    page.wait_for_timeout(300)          # five ticks of the 60 ms timer, had it run on
    assert page.input_value("#stroke") == stopped

    # Russian labels
    page.click("#lang-toggle")
    page.wait_for_function("document.getElementById('title').textContent.includes('навески')")
    assert page.text_content("h2[data-t=parameters]") == "Параметры"

    page.wait_for_timeout(300)
    times = _redraws(logs)
    assert len(times) > len(_redraws(logs[:n]))
    assert not errors, errors
    page_log(f"\npage e2e (seed 003): {len(times)} redraws after a parameter change, "
             f"times from the input event to the new drawing [ms]: "
             f"{', '.join(f'{t:.0f}' for t in times)}")
    page.close()



@pytest.mark.parametrize("name, native", [("hitch_003", True), ("steering_lab4", True),
                                          ("hitch_003", False)])   # steering: wheels
def test_a_packed_answer_reads_in_the_page_as_the_plain_one(browser, name, native):
    """The page asks for packed answers (tables' columns, the drawing's points,
    coordinates and wheels' headings as float64 bytes): read by its ``unpack``, an
    answer is the plain JSON answer — the same keys, lists and texts, the same numbers
    (to 1e-12: two analyses of one model may differ in the last bit); with the
    browser's own base64 decoder and without it (before 2025)."""
    from assur.views.page.server import create_app, running
    with running(create_app(bundled(name), warm=False)) as u:
        page = browser.new_page()
        page.goto(u + "/")
        page.wait_for_selector("#drawing circle.point")
        if not native:
            page.evaluate("Uint8Array.fromBase64 = undefined")
        diffs, numbers = page.evaluate("""async () => {
            const ask = async (packed) => (await fetch('/api/analyze', {method: 'POST',
                headers: {'Content-Type': 'application/json'},
                body: JSON.stringify({params: {}, positions: 101, packed})})).json();
            const plain = await ask(false), packed = unpack(await ask(true));
            delete plain.ms; delete packed.ms;
            const diffs = [];
            let numbers = 0;
            const walk = (a, b, path) => {
              if (typeof a !== typeof b || Array.isArray(a) !== Array.isArray(b)
                  || (a === null) !== (b === null)) { diffs.push(path); return; }
              if (a !== null && typeof a === 'object') {
                const ka = Object.keys(a), kb = Object.keys(b);
                if (ka.join() !== kb.join()) { diffs.push(path); return; }
                for (const k of ka) walk(a[k], b[k], path + '.' + k);
              } else if (typeof a === 'number') {
                numbers++;
                if (Math.abs(a - b) > 1e-12 * Math.max(1, Math.abs(a))) diffs.push(path);
              } else if (a !== b) diffs.push(path);
            };
            walk(plain, packed, '');
            return [diffs.slice(0, 5), numbers];
        }""")
        page.close()
    assert diffs == [] and numbers > 1000


def test_the_table_out_of_view_is_brought_up_to_date_when_seen(browser, url):
    """An answer that comes while the long table is scrolled out of view leaves its cells
    (they are not seen); scrolled into view, the table shows the answer's values."""
    page = browser.new_page(viewport={"width": 1400, "height": 700})
    page.goto(url + "/")
    page.wait_for_selector("#pt-56")
    page.select_option("#table-select", "2.2")
    shown = """() => { const t = currentTable(), tab = document.getElementById('table');
        let same = 0, all = 0;
        t.columns.forEach((c, k) => c.values.forEach((v, i) => {
            all++; if (tab.rows[i + 1].cells[k].textContent === fmt(v)) same++; }));
        return [same, all]; }"""
    same, cells = page.evaluate(shown)
    assert same == cells > 100
    assert not page.evaluate("state.tableInView")      # below the drawing and the plots
    page.fill("#input-L5", "0.49")
    page.wait_for_function("state.tableStale === true")
    assert page.evaluate("state.values.L5") == 0.49
    same, cells = page.evaluate(shown)
    assert same < cells                                  # Y56 moved: those cells are old
    page.eval_on_selector("#table-box", "e => e.scrollIntoView()")
    page.wait_for_function("state.tableStale === false")
    same, cells = page.evaluate(shown)
    assert same == cells
    page.close()
