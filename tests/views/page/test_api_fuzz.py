"""API fuzz run (issue 13): hypothesis sends arbitrary JSON to every route of the
page's application (TestClient, no network) and nothing answers 500.

Bodies are drawn from any JSON (the valid shape with arbitrary names and values,
and arbitrary JSON), including numbers at the edges (±1e12, 0, tiny, negative),
out-of-range positions and unknown keys. A 200 answer is a result or a message
(``ok`` false with a kind); 4xx answers are refusals with a message.
"""

import json

import pytest
from fastapi.testclient import TestClient
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from assur.io import bundled

pytestmark = pytest.mark.slow

_client = None


def client():
    global _client
    if _client is None:
        from assur.views.page.server import create_app
        _client = TestClient(create_app(bundled("hitch_003")), raise_server_exceptions=False)
    return _client


NAMES = ["L5", "L3", "L6", "L34", "L56", "phiBD", "X05", "Y07", "P6", "Dgc", "Pgc_max", "eta",
         "kgc", "Smin", "Smax", "L4", "a", "b", "L"]
numbers = st.one_of(st.floats(allow_nan=False, allow_infinity=False, width=64),
                    st.integers(-10**13, 10**13),
                    st.sampled_from([0.0, -0.0, 1e-300, -1.0, 1e12, -1e12, 0.48, 0.3]))
json_values = st.recursive(
    st.none() | st.booleans() | numbers | st.text(max_size=20),
    lambda kids: st.lists(kids, max_size=4) | st.dictionaries(st.text(max_size=8), kids,
                                                             max_size=4),
    max_leaves=12)
params = st.dictionaries(st.sampled_from(NAMES) | st.text(max_size=12),
                         numbers | json_values, max_size=4)
bodies = st.one_of(
    st.fixed_dictionaries({"params": params},
                          optional={"positions": st.integers(-5, 2000) | json_values,
                                    "lang": st.sampled_from(["en", "ru", "de", ""]),
                                    "table": st.text(max_size=20) | json_values,
                                    "at": st.lists(numbers, max_size=70) | json_values,
                                    "extra": json_values}),
    json_values)
routes = st.sampled_from(["/api/analyze", "/api/export/csv", "/api/export/xlsx",
                          "/api/export/toml", "/api/export/dxf", "/api/export/x",
                          "/api/model"])


def _check(r):
    assert r.status_code != 500, r.text
    assert r.status_code in (200, 400, 404, 405, 413, 422), (r.status_code, r.text)
    if r.headers.get("content-type", "").startswith("application/json"):
        out = r.json()
        if isinstance(out, dict) and out.get("ok") is False:
            assert out["error"]["kind"] in ("model", "assembly", "singular", "validation")
            assert "Traceback" not in out["error"]["message"]


@settings(max_examples=120, deadline=None, suppress_health_check=list(HealthCheck))
@given(route=routes, body=bodies)
def test_no_500_on_any_json(route, body):
    # positions are the costly input: keep the valid ones small so the run stays short
    if isinstance(body, dict) and isinstance(body.get("positions"), int) \
            and 2 <= body["positions"] <= 1001:
        body = dict(body, positions=min(body["positions"], 21))
    if route == "/api/model":
        _check(client().get(route))
        return
    _check(client().post(route, content=json.dumps(body).encode(),
                         headers={"content-type": "application/json"}))


@settings(max_examples=60, deadline=None, suppress_health_check=list(HealthCheck))
@given(data=st.binary(max_size=300), ctype=st.sampled_from(
    ["application/json", "text/plain", "application/x-www-form-urlencoded", ""]))
def test_no_500_on_any_bytes(data, ctype):
    _check(client().post("/api/analyze", content=data, headers={"content-type": ctype}))


@settings(max_examples=40, deadline=None, suppress_health_check=list(HealthCheck))
@given(name=st.sampled_from(["L5", "L3", "L6", "L34", "L56", "X05", "Y07", "phiBD"]),
       value=st.floats(-5, 5, allow_nan=False))
def test_any_length_is_a_drawing_or_a_message(name, value):
    r = client().post("/api/analyze", json={"params": {name: value}, "positions": 11})
    _check(r)
    out = r.json()
    assert out["ok"] or out["error"]["kind"] in ("model", "assembly", "singular")


#: positions the export routes get at and beyond their edges: repeated, extreme,
#: non-finite written as JSON can (strings), many, empty
EXPORT_POSITIONS = [[0.5, 0.5], [0.5] * 64, [1e308, -1e308], [0.42, 0.67, 0.42],
                    [-1e12, 1e12], [], [0.5, "nan"], [0.5, None], list(range(65)),
                    [5e-324], [0.55, 0.550000000000001]]


@settings(max_examples=80, deadline=None, suppress_health_check=list(HealthCheck))
@given(route=st.sampled_from(["/api/export/dxf", "/api/export/csv", "/api/export/xlsx",
                              "/api/export/toml"]),
       at=st.sampled_from(EXPORT_POSITIONS),
       positions=st.sampled_from([None, 2, 3, 1, 0, -1, 1001, 1002, 10**9, 2.5, "11"]),
       params=st.sampled_from([{}, {"L5": 0.5}, {"L5": 1e6}, {"L5": -0.48}]))
def test_exports_at_repeated_and_extreme_positions(route, at, positions, params):
    """Issue 27: the export routes with repeated (``[0.5, 0.5]`` was the page's one 500),
    extreme, too many and non-numeric positions and position counts: a file or a
    message, never 500."""
    body = {"params": params, "at": at}
    if positions is not None:
        body["positions"] = positions
    r = client().post(route, json=body)
    _check(r)
    if r.status_code == 200 and route == "/api/export/dxf" \
            and r.headers.get("content-type", "").startswith("image/vnd.dxf"):
        assert b"SECTION" in r.content[:200]
