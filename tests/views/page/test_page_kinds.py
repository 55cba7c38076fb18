"""The page for every kind of machine, end to end in a real headless Chromium (issue 24).

One test per kind of machine, told by the model's coordinates (not by which seed tables
exist): a crank over a whole turn (the combine six-bar of seed 002), two coordinates
on a full grid (the loader of seed 001 lab 1), a crane of two cylinders (ЛВ-185 of
seed 004), a steering drive (seed 001 lab 4); then the input of numbers as users type
them and the state that survives a reload (the seed-003 hitch). Each page is
screenshotted at 1024 px into the test's tmp_path (the run's artefacts) and checked
for horizontal overflow there.
"""

import io
import json
import re
from pathlib import Path

import numpy as np
import pytest

from assur.io import bundled

pytestmark = pytest.mark.slow

#: the page's width of the overflow check [px] (a small laptop screen)
WIDTH = 1024


@pytest.fixture
def open_page(browser, tmp_path):
    """``open_page(model, query="")`` → ``(page, url, errors)``: the model's page served
    by ``assur serve``'s application, loaded in Chromium at 1024 px, its drawing shown."""
    from assur.views.page.server import create_app, running
    stack = []

    def open_(name, query=""):
        server = running(create_app(bundled(name)))
        url = server.__enter__()
        stack.append(server)
        page = browser.new_page(viewport={"width": WIDTH, "height": 900})
        errors = []
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto(url + "/" + query)
        page.wait_for_selector("#drawing circle.point")
        return page, url, errors

    yield open_
    for s in stack:
        s.__exit__(None, None, None)


def _shoot(page, tmp_path, name):
    """A full-page screenshot kept with the run, and no horizontal overflow at 1024 px."""
    shot = tmp_path / f"page_{name}.png"
    page.screenshot(path=str(shot), full_page=True)
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    width = page.evaluate("document.documentElement.scrollWidth")
    assert width <= WIDTH, f"{name}: the page is {width} px wide at {WIDTH} px"


def _curves(page, selector):
    """The drawn curves of the plots under ``selector``: a list of subpaths, each a list
    of (x, y) [px of the plot's SVG]."""
    out = []
    for d in page.eval_on_selector_all(selector + " path.curve", "ps => ps.map(p => p.getAttribute('d'))"):
        for part in re.split(r"(?=M)", d.strip()):
            pts = [(float(a), float(b)) for a, b in re.findall(r"(-?[\d.e+-]+)[ ,](-?[\d.e+-]+)", part)]
            if pts:
                out.append(pts)
    return out


def _point(page, p):
    return (float(page.get_attribute(f"#pt-{p}", "data-x")),
            float(page.get_attribute(f"#pt-{p}", "data-y")))


def test_a_crank_turns_through_360_degrees_on_one_slider(open_page, tmp_path):
    # seed 002: the file's 13 angles (every 30° clockwise from 14.679° and one more)
    page, _, errors = open_page("combine_002")
    assert page.evaluate("state.data.turn") is True
    n = page.evaluate("state.data.geometry.n")
    q = np.degrees(page.evaluate("state.data.geometry.q.j1"))
    step = np.diff(q)
    assert q[0] == pytest.approx(14.679)
    assert np.allclose(step, -360.0 / n)            # a whole turn, clockwise, evenly
    assert q[0] - q[-1] == pytest.approx(360.0 * (n - 1) / n)

    # the slider moves the crank's end continuously, also from the last angle to the first
    page.fill("#stroke", str(n - 1))
    a_last = _point(page, "A")
    page.fill("#stroke", "0")
    a_first = _point(page, "A")
    l1 = page.evaluate("state.info.parameters.find(p => p.name === 'l1').value")   # [m]
    chord = 2 * l1 * np.sin(np.radians(360.0 / n) / 2)
    assert np.hypot(a_last[0] - a_first[0], a_last[1] - a_first[1]) == pytest.approx(chord, rel=1e-6)
    assert "j1 = 14.679°" in page.text_content("#position-text")

    # a wrapped link angle plotted over the unwrapped crank angle: broken at the wrap,
    # no segment longer than a few steps
    page.select_option("#add-plot", "2.1\u0000phi1")
    page.wait_for_selector("#plot-2\\.1-phi1 path.curve")
    parts = _curves(page, "#plot-2\\.1-phi1")
    assert len(parts) >= 2                           # the wrap breaks the line
    xs = [x for part in parts for x, _ in part]
    height = page.evaluate("document.querySelector('#plot-2\\\\.1-phi1 svg').viewBox.baseVal.height")
    width = max(xs) - min(xs)
    for part in parts:
        for (x0, y0), (x1, y1) in zip(part, part[1:]):
            assert abs(x1 - x0) <= 1.5 * width / (n - 1)
            assert abs(y1 - y0) <= 0.1 * height      # 3.6° of 360° per step
    # the play button turns on past the last position (a crank does not swing back)
    page.fill("#stroke", str(n - 2))
    page.click("#play")
    page.wait_for_function("Number(document.getElementById('stroke').value) < 5")
    page.click("#play")
    _shoot(page, tmp_path, "combine_002")
    assert not errors, errors


def test_two_coordinates_get_two_sliders_and_a_map_that_picks_the_position(open_page,
                                                                              tmp_path):
    import ezdxf

    page, _, errors = open_page("loader_lab1")       # S × S1: 13 × 8 positions
    grid = page.evaluate("state.data.grid")
    assert (len(grid["x"]), len(grid["y"])) == (13, 8)
    assert page.is_visible("#coord-0") and page.is_visible("#coord-1")
    assert not page.is_visible("#stroke")

    # the sliders set the position by grid indices
    page.fill("#coord-0", "4")
    page.fill("#coord-1", "2")
    pos = page.evaluate("state.pos")
    assert (grid["i"][pos], grid["j"][pos]) == (4, 2)

    # a click on a map's cell sets both coordinates
    cell = page.locator(".plot .map rect.cell[data-i='9'][data-j='5']").first
    cell.click()
    page.wait_for_function("document.getElementById('coord-0').value === '9'")
    assert page.input_value("#coord-1") == "5"
    pos = page.evaluate("state.pos")
    assert (grid["i"][pos], grid["j"][pos]) == (9, 5)
    text = page.text_content("#position-text")
    assert text.startswith(f"S = {grid['x'][9]:.5g} m, S1 = {grid['y'][5]:.5g} m".replace(".0 ", " "))

    # the plot beside the map: the quantity over S with S1 held where it is
    legend = page.text_content(".plot .held")
    assert "S1 = " in legend

    # the DXF at this position is this position: its coordinates and its points
    with page.expect_download() as dl:
        page.click("[data-export=dxf]")
    doc = ezdxf.read(io.StringIO(Path(dl.value.path()).read_text(encoding="utf-8")))
    names = [g for g, _ in doc.groups]
    assert len(names) == 1
    q = page.evaluate("[state.data.geometry.q.S[state.pos], state.data.geometry.q.S1[state.pos]]")
    assert names[0] == f"S={q[0]:.6g} m, S1={q[1]:.6g} m" or \
        [float(v) for v in re.findall(r"=([-\d.e]+)", names[0])] == pytest.approx(q, abs=1e-6)
    x, y = _point(page, "09")
    found = [(e.dxf.location.x, e.dxf.location.y) for e in doc.modelspace()
             if e.dxftype() == "POINT"]
    assert any(abs(px - 1e3 * x) < 1e-3 and abs(py - 1e3 * y) < 1e-3 for px, py in found)
    _shoot(page, tmp_path, "loader_lab1")
    assert not errors, errors


def test_a_crane_tabulates_its_link_angles(open_page, tmp_path):
    page, _, errors = open_page("crane_lv185")
    page.select_option("#table-select", "2.1")
    heads = page.eval_on_selector_all("#table th", "ts => ts.map(t => t.textContent)")
    angles = [h for h in heads if h.startswith("phi")]
    assert len(angles) >= 4, heads                  # the boom, the stick, the cylinders…
    cells = page.eval_on_selector_all("#table tr[data-row='0'] td", "ts => ts.map(t => t.textContent)")
    assert all(c.strip() for c in cells)            # every column filled
    # the drawing is scaled to its box: the tall crane gets a tall box
    box = page.evaluate("(() => { const r = document.getElementById('drawing-box')"
                        ".getBoundingClientRect(); return [r.width, r.height]; })()")
    assert box[1] > 0.9 * box[0]
    _shoot(page, tmp_path, "crane_lv185")
    assert not errors, errors


def test_a_steering_drive_draws_its_wheels(open_page, tmp_path):
    page, _, errors = open_page("steering_lab4")
    wheels = page.locator("#drawing polygon.wheel")
    assert wheels.count() == 2
    before = wheels.nth(0).get_attribute("points")
    page.fill("#stroke", "100")                     # the whole stroke: the wheels turn
    after = page.locator("#drawing polygon.wheel").nth(0).get_attribute("points")
    assert before != after
    # β over α beside the Ackermann ideal, the plot the file declares ([display] plots):
    # over another column of its table, kept in the address
    assert page.input_value("#plot-F-beta select.over") == "alpha"
    assert page.locator("#plot-F-beta path.curve").count() == 2     # β and β_ideal
    page.wait_for_function("location.search.includes('F%7Ebeta%7Ealpha%7Ebeta_ideal')")
    alpha = page.evaluate("state.data.tables.find(t => t.id === 'F').columns"
                          ".find(c => c.symbol === 'alpha').values")
    ticks = [float(t.replace("−", "-")) for t in page.eval_on_selector_all(
        "#plot-F-beta text.xtick", "ts => ts.map(t => t.textContent)")]
    assert min(ticks) <= min(alpha) and max(ticks) >= max(alpha)   # the axis is α's [°]
    assert max(ticks) < 90
    _shoot(page, tmp_path, "steering_lab4")
    assert not errors, errors


def test_numbers_are_read_as_users_type_them(open_page):
    page, _, errors = open_page("loader_lab1")       # p_relief = "17 MPa"
    sent = []
    page.on("request", lambda r: sent.append(json.loads(r.post_data))
            if r.url.endswith("/api/analyze") and r.post_data else None)

    page.fill("#input-p_relief", "17,5")             # the decimal comma
    page.wait_for_function("state.values.p_relief === 17.5")
    page.wait_for_function("document.getElementById('status').textContent.length > 0")
    page.wait_for_timeout(300)
    assert sent and sent[-1]["params"]["p_relief"] == 17.5
    assert not page.is_visible("#msg-p_relief")

    for text, words in (("abc", "not a number"), ("", "empty"), ("1e308", "out of range"),
                        ("-3", "out of range")):
        n = len(sent)
        page.fill("#input-p_relief", text)
        msg = page.text_content("#msg-p_relief")
        assert page.is_visible("#msg-p_relief") and words in msg, (text, msg)
        if text != "":
            assert "0 … ∞ MPa" in msg               # the field's range, in its unit
        else:
            assert "17.5 MPa" in msg                # the value kept
        page.wait_for_timeout(200)
        assert len(sent) == n                       # nothing sent
        assert page.evaluate("state.values.p_relief") == 17.5

    # the fields in the page's units: L3 = 0.55 m shown as 21.6535 in, 20 in sent as m
    page.select_option("#units", "imperial")
    page.wait_for_function("document.getElementById('input-L3').value === '21.6535'")
    assert page.text_content("#param-L3 .unit") == "in"
    page.fill("#input-L3", "20")
    page.wait_for_function("Math.abs(state.values.L3 - 0.508) < 1e-12")
    page.wait_for_timeout(300)
    assert sent[-1]["params"]["L3"] == pytest.approx(0.508, abs=1e-12)   # [m], the file's
    assert sent[-1]["units"] == "imperial"
    page.select_option("#units", "file")
    page.wait_for_function("document.getElementById('input-L3').value === '0.508'")

    # a count is whole, an efficiency lies in 0 … 1; slider steps are round numbers
    eta = page.evaluate("state.info.parameters.find(p => p.name === 'eta')")
    assert (eta["min"], eta["max"]) == (0, 1)
    assert float(page.get_attribute("#slider-eta", "max")) <= 1
    step = float(page.get_attribute("#slider-L3", "step"))       # L3 = 0.55 m
    mant = step / 10 ** np.floor(np.log10(step))
    assert round(mant, 9) in (1.0, 2.0, 5.0)
    assert not errors, errors


def test_a_reload_restores_parameters_position_language_and_units(open_page):
    page, url, errors = open_page("hitch_003")
    page.fill("#input-L5", "0.5")
    page.wait_for_function("document.getElementById('param-L5').classList.contains('changed')")
    page.fill("#stroke", "30")
    page.select_option("#units", "engineering")
    page.wait_for_function("document.getElementById('position-text').textContent.includes('mm')")
    page.click("#lang-toggle")
    page.wait_for_function("document.getElementById('title').textContent.includes('навески')")
    page.wait_for_timeout(300)
    pos_text = page.text_content("#position-text")
    assert "p.L5=0.5" in page.url and "units=engineering" in page.url and "lang=ru" in page.url

    page.reload()
    page.wait_for_selector("#drawing circle.point")
    page.wait_for_function("document.getElementById('title').textContent.includes('навески')")
    assert page.input_value("#input-L5") == "500"       # the page's units: mm
    assert page.text_content("#param-L5 .unit") == "мм"
    assert page.input_value("#units") == "engineering"
    assert page.input_value("#stroke") == "30"
    assert page.text_content("#position-text") == pos_text
    assert "changed" in page.get_attribute("#param-L5", "class")

    # undo goes back to the file's value; the compare overlay draws the file's design
    page.click("#undo")
    page.wait_for_function("!document.getElementById('param-L5').classList.contains('changed')")
    page.fill("#input-L5", "0,5")
    page.wait_for_function("document.getElementById('param-L5').classList.contains('changed')")
    page.check("#compare")
    page.wait_for_selector("#drawing g.ghost", state="attached")
    page.wait_for_selector(".plot path.curve[data-series='1']")
    assert not errors, errors


def test_an_unreachable_server_is_said_in_words(open_page):
    page, _, errors = open_page("hitch_003")
    page.route("**/api/analyze", lambda route: route.abort())
    page.fill("#input-L5", "0.49")
    page.wait_for_function("document.getElementById('error-message').textContent"
                           ".includes('not answering')")
    assert "Failed to fetch" not in page.text_content("#error-message")
    page.route("**/api/export/**", lambda route: route.fulfill(
        status=500, content_type="application/json",
        body='{"ok": false, "error": {"kind": "internal", "message": "internal error"}}'))
    page.click("[data-export=xlsx]")
    page.wait_for_function("document.getElementById('download-msg').textContent.length > 0")
    assert "internal error" in page.text_content("#download-msg")
    assert not errors, errors
