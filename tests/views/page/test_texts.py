"""The page's labels (:mod:`assur.views.page.texts`): every key the page's HTML and
script ask for (``data-t="…"``, ``T("…")``) has its text in both languages, and the
model information the server sends carries them."""

import re

from fastapi.testclient import TestClient

from assur.io import bundled
from assur.views.page.server import create_app
from assur.views.page.texts import PAGE_TEXT, page_texts
from tests.helpers import ROOT

STATIC = ROOT / "src" / "assur" / "views" / "page" / "static"


def test_every_key_the_page_uses_has_both_languages():
    html = (STATIC / "index.html").read_text(encoding="utf-8")
    js = (STATIC / "page.js").read_text(encoding="utf-8")
    used = set(re.findall(r'data-t="([a-z_0-9]+)"', html))
    used |= set(re.findall(r'\bT\("([a-z_0-9]+)"\)', js))
    texts = page_texts()
    assert len(used) > 10
    assert used <= set(texts), sorted(used - set(texts))
    for key, value in texts.items():
        assert set(value) == {"en", "ru"} and all(value.values()), key
    assert set(PAGE_TEXT) <= set(texts)


def test_the_server_sends_them():
    client = TestClient(create_app(bundled("hitch_003")))
    assert client.get("/api/model").json()["texts"] == page_texts()
