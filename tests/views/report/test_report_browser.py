"""The HTML report in a real headless Chromium (tests/views/conftest.py): the animation's
player shows one vector frame at a time, its caption that frame's position, and moves
with its slider; the page raises no script error."""

import pytest

from assur.views.report import write_report

pytestmark = pytest.mark.slow


def test_the_animation_plays_its_frames(browser, hitch_analysis, tmp_path):
    files = write_report(hitch_analysis, tmp_path, formats=("html",), frames=5)
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(files["html"][0].as_uri())
    frames = page.locator("#anim-svg > g.frame")
    assert frames.count() == 5

    def shown():  # the frames drawn, read at one instant (the player may be running)
        drawn = frames.evaluate_all("els => els.map(e => e.getClientRects().length > 0)")
        return [k for k, d in enumerate(drawn) if d]

    assert len(shown()) == 1  # playing: one frame at a time
    page.click("#anim-play")  # pause
    page.fill("#anim-pos", "3")
    page.dispatch_event("#anim-pos", "input")
    assert shown() == [3]
    assert page.text_content("#anim-q") == "S = 0.6075 m"  # S at frame 3 of 5 [m]
    page.fill("#anim-pos", "0")
    page.dispatch_event("#anim-pos", "input")
    assert shown() == [0] and page.text_content("#anim-q") == "S = 0.42 m"
    assert not errors
