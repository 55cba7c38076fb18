"""The page's server (:mod:`assur.views.page.server`): the page in either language and
its static files, the API's routes, and ``running`` — a real server on a free
loopback port answering in a thread, stopped on exit."""

import json
import urllib.request

import pytest
from fastapi.testclient import TestClient

from assur.io import bundled
from assur.views.page.server import create_app, running


def test_the_page_and_its_files():
    client = TestClient(create_app(bundled("hitch_003")))
    page = client.get("/")
    assert page.status_code == 200 and "text/html" in page.headers["content-type"]
    assert 'data-lang="ru"' in client.get("/", params={"lang": "ru"}).text
    assert 'data-lang="en"' in page.text
    assert client.get("/static/page.js").status_code == 200
    assert client.get("/static/nothing.js").status_code == 404
    paths = {r.path for r in create_app(bundled("hitch_003")).routes}
    assert {"/", "/api/model", "/api/analyze", "/api/export/dxf"} <= paths
    with pytest.raises(ValueError, match="lang must be one of"):
        create_app(bundled("hitch_003"), lang="de")


def test_running_serves_on_loopback_until_stopped():
    with running(create_app(bundled("hitch_003"))) as url:
        assert url.startswith("http://127.0.0.1:")
        with urllib.request.urlopen(url + "/api/model", timeout=30) as r:
            info = json.loads(r.read())
        assert info["file"] == "hitch_003.toml"
    with pytest.raises(OSError):
        urllib.request.urlopen(url + "/api/model", timeout=2)


def test_the_dxf_of_two_coordinates_is_the_position_asked_for():
    import io

    import ezdxf
    from fastapi.testclient import TestClient

    from assur.io import bundled
    from assur.views.page.server import create_app
    client = TestClient(create_app(bundled("loader_lab1"), warm=False))
    r = client.post("/api/export/dxf", json={"at": [1.2165, 0.851429]})   # S, S1 [m]
    assert r.status_code == 200, r.text
    doc = ezdxf.read(io.StringIO(r.content.decode("utf-8")))
    [name] = [g for g, _ in doc.groups]
    assert "S=1.21651" in name and "S1=0.851429" in name
    r = client.post("/api/export/dxf", json={"at": [1.2165]})
    assert "one value per coordinate" in r.json()["error"]["message"]
    r = client.post("/api/export/dxf", json={"at": [9.0, 0.85]})
    assert "outside the range of S" in r.json()["error"]["message"]


def test_a_position_asked_twice_is_drawn_once():
    """Issue 27: ``{"at": [0.5, 0.5]}`` was the page's only HTTP 500 (a DXF group named
    twice)."""
    import io

    import ezdxf
    from fastapi.testclient import TestClient

    from assur.io import bundled
    from assur.views.page.server import create_app
    client = TestClient(create_app(bundled("hitch_003"), warm=False))
    r = client.post("/api/export/dxf", json={"at": [0.5, 0.5, 0.6]})   # S [m]
    assert r.status_code == 200, r.text
    doc = ezdxf.read(io.StringIO(r.content.decode("utf-8")))
    assert len([g for g, _ in doc.groups]) == 2


def test_the_page_says_in_its_language_when_the_api_does_not_answer():
    from fastapi.testclient import TestClient

    from assur.io import bundled
    from assur.views.page.server import create_app
    from assur.views.page.texts import page_texts
    client = TestClient(create_app(bundled("hitch_003"), warm=False))
    for lang in ("en", "ru"):
        html = client.get("/", params={"lang": lang}).text
        assert f'data-server-down="{page_texts()["server_down"][lang]}"' in html
