"""The page's API (:mod:`assur.views.page.api`, issue 13): the model's information,
analyses, refused requests, the edited model file and the downloads (tables, TOML,
DXF), against the seed-003 hitch; other machines on the page. (The DXF writer:
test_dxf.py; the inline displays: tests/views/test_notebook.py.)"""

import io as _io
import math

import numpy as np
import pytest
from fastapi.testclient import TestClient

from assur import io as aio
from assur.io import bundled
from assur.views.report.tables import seed_tables, sheet_name


@pytest.fixture(scope="module")
def client():
    from assur.views.page.server import create_app
    return TestClient(create_app(bundled("hitch_003")), raise_server_exceptions=False)


def test_model_info_groups_parameters_with_units(client):
    r = client.get("/api/model")
    assert r.status_code == 200
    info = r.json()
    by = {p["name"]: p for p in info["parameters"]}
    assert by["phiBD"]["unit"] == "deg" and by["phiBD"]["value"] == 22
    assert by["P6"]["unit"] == "kN" and by["P6"]["value"] == 27.5
    assert by["Dgc"]["unit"] == "mm" and by["eta"]["unit"] == "-"
    assert by["L5"]["group"] == "§1.2 links"
    assert by["X01"]["group"] == "§1.1 frame pivots"
    # the Find unknowns are shown with their roots, not editable (seed 003 §2.2–2.3)
    assert by["L4"]["solved"] and not by["L4"]["editable"]
    assert by["L4"]["value"] == pytest.approx(0.661283167, abs=1e-9)
    assert info["texts"]["parameters"]["ru"] == "Параметры"


def test_analyze_payload_matches_the_engine(client):
    r = client.post("/api/analyze", json={"params": {}, "positions": 11})
    out = r.json()
    assert r.status_code == 200 and out["ok"]
    g = out["geometry"]
    kin = aio.load(bundled("hitch_003")).mechanism.solve(np.linspace(0.42, 0.67, 11))
    assert np.allclose(np.array(g["points"]["56"])[:, 1], kin.y("56"), rtol=0, atol=1e-12)
    assert g["points"]["56"][0][1] == pytest.approx(0.2, abs=1e-9)  # seed 003: Y56(Smin)
    t41 = next(t for t in out["tables"] if t["id"] == "4.1")
    assert len(t41["columns"][0]["values"]) == 11
    assert {s["name"] for s in out["solved"]} == {"L4", "Sp", "L7"}


def test_parameter_change_changes_the_result(client):
    a = client.post("/api/analyze", json={"params": {"P6": 27.5}, "positions": 5}).json()
    b = client.post("/api/analyze", json={"params": {"P6": 30.0}, "positions": 5}).json()

    def col(out, tid, sym):
        t = next(t for t in out["tables"] if t["id"] == tid)
        return np.array(next(c for c in t["columns"] if c["symbol"] == sym)["values"])
    # the cylinder force is proportional to the implement's weight (virtual work)
    assert np.allclose(col(b, "4.1", "Fgc") / col(a, "4.1", "Fgc"), 30.0 / 27.5, rtol=1e-12)


def test_infeasible_length_is_a_message_not_a_traceback(client):
    r = client.post("/api/analyze", json={"params": {"L5": 0.3}, "positions": 101})
    out = r.json()
    assert r.status_code == 200 and out["ok"] is False
    assert out["error"]["kind"] == "assembly"
    msg = out["error"]["message"]
    assert msg.startswith("RRR dyad 'II (4,5)' (links 4, 5) cannot assemble at position 82 "
                          "(S = 0.625)")
    assert "Traceback" not in msg
    # a condition without a root names the file's line and the condition
    out = client.post("/api/analyze", json={"params": {"X05": 0.5}}).json()
    assert out["error"]["kind"] == "model"
    assert out["error"]["message"].startswith("hitch_003.toml:")
    assert "no root for L4" in out["error"]["message"]


@pytest.mark.parametrize("body, where", [
    ({"params": {"L5": "0.3 m; import os"}}, "params.L5"),
    ({"params": {"L5": None}}, "params.L5"),
    ({"params": {"bad name": 1.0}}, "params"),
    ({"params": {}, "positions": 10**6}, "positions"),
    ({"params": {}, "positions": 1}, "positions"),
    ({"params": {}, "lang": "de"}, "lang"),
    ({"params": {}, "code": "print(1)"}, "code"),
    ({"params": {"L5": 1e300}}, "params.L5"),
])
def test_invalid_requests_are_refused_with_422(client, body, where):
    r = client.post("/api/analyze", json=body)
    assert r.status_code == 422
    out = r.json()
    assert out["ok"] is False and out["error"]["kind"] == "validation"
    assert where in out["error"]["message"]


def test_nan_and_unknown_names_are_refused(client):
    r = client.post("/api/analyze", content=b'{"params": {"L5": NaN}}',
                    headers={"content-type": "application/json"})
    assert r.status_code == 422
    out = client.post("/api/analyze", json={"params": {"L55": 0.4}}).json()
    assert out["ok"] is False and 'did you mean "L5' in out["error"]["message"]
    out = client.post("/api/analyze", json={"params": {"L4": 0.7}}).json()
    assert "unknown of [[solve]]" in out["error"]["message"]


def test_bodies_and_arrays_are_bounded(client):
    from assur.views.page.api import MAX_BODY
    r = client.post("/api/analyze", content=b"{" + b" " * MAX_BODY + b"}",
                    headers={"content-type": "application/json"})
    assert r.status_code == 413
    many = {f"p{i}": 1.0 for i in range(600)}
    assert client.post("/api/analyze", json={"params": many}).status_code == 422
    assert client.post("/api/export/dxf", json={"at": [0.5] * 65}).status_code == 422


def test_edited_toml_keeps_comments_and_loads_as_the_same_model(client):
    r = client.post("/api/export/toml", json={"params": {"L5": 0.49, "phiBD": 23.5,
                                                         "kgc": 2}})
    assert r.status_code == 200
    assert r.headers["content-disposition"] == 'attachment; filename="hitch_003.toml"'
    text = r.text
    assert 'L5 = "0.49 m"' in text and 'phiBD = "23.5 deg"' in text
    assert "kgc = 2\n" in text
    assert "# §1.2 links" in text and "# the seed writes [м]: it is an angle" in text
    m = aio.loads(text, name="edited.toml")
    assert m.mechanism.params["L5"] == 0.49
    assert m.mechanism.params["phiBD"] == pytest.approx(math.radians(23.5), abs=1e-15)


def test_tables_download_equals_the_report_tables(client):
    ref = seed_tables(aio.load(bundled("hitch_003")).analyze(), units="file")  # the file's
    r = client.post("/api/export/csv", json={"table": "4.1"})
    assert r.status_code == 200 and r.headers["content-type"].startswith("text/csv")
    lines = r.text.strip().splitlines()
    t41 = next(t for t in ref if t.id == "4.1")
    assert lines[0].split(",") == [c.header for c in t41.columns]
    got = np.array([[float(x) for x in ln.split(",")] for ln in lines[1:]])
    assert np.array_equal(got[:, 1], t41["Fgc"])
    r = client.post("/api/export/xlsx", json={"params": {}})
    import openpyxl
    wb = openpyxl.load_workbook(_io.BytesIO(r.content))
    assert wb.sheetnames == ["Inputs"] + [sheet_name(t) for t in ref]
    ws = wb[sheet_name(t41)]
    assert [c.value for c in ws[2]][:2] == ["S", "Fgc"] and ws["B4"].value == t41["Fgc"][0]
    out = client.post("/api/export/csv", json={"table": "9.9"}).json()
    assert out["ok"] is False and "this model has tables" in out["error"]["message"]
    assert client.post("/api/export/pdf", json={}).status_code == 404


def test_dxf_download_reads_back_with_pivots_at_the_solved_points(client, tmp_path):
    import ezdxf
    r = client.post("/api/export/dxf", json={"at": [0.42]})
    assert r.status_code == 200
    p = tmp_path / "h.dxf"
    p.write_bytes(r.content)
    doc = ezdxf.readfile(p)
    kin = aio.load(bundled("hitch_003")).mechanism.solve(np.array([0.42]))
    pts = {round(e.dxf.location.x, 6): e.dxf.location.y for e in doc.modelspace().query("POINT")}
    assert pts[round(kin.x("56")[0] * 1e3, 6)] == pytest.approx(kin.y("56")[0] * 1e3, abs=1e-9)
    out = client.post("/api/export/dxf", json={"at": [0.1]}).json()
    assert out["ok"] is False and "outside the range" in out["error"]["message"]


def test_cli_serve_refuses_bad_options():
    from typer.testing import CliRunner

    from assur.views.cli import app
    r = CliRunner().invoke(app, ["serve", str(bundled("hitch_003")), "--lang", "de"])
    assert r.exit_code == 1 and "--lang must be one of" in r.output
    r = CliRunner().invoke(app, ["serve", str(bundled("hitch_003")), "--port", "70000"])
    assert r.exit_code == 2 and "--port" in r.output
    r = CliRunner().invoke(app, ["serve", "no-such-model.toml", "--no-browser"])
    assert r.exit_code == 1 and "no-such-model.toml: no such file" in r.output


@pytest.mark.slow
@pytest.mark.parametrize("name, ok", [("combine_002", True), ("loader_lab1", True),
                                      ("crane_lv184a", True), ("header_000", False)])
def test_other_machines_on_the_page(name, ok):
    """A crank (angles), a grid of two cylinders, the crane, and a file that cannot
    assemble as printed (seed 000: its message, not a drawing)."""
    from assur.views.page.server import create_app
    c = TestClient(create_app(bundled(name)), raise_server_exceptions=False)
    info = c.get("/api/model").json()
    out = c.post("/api/analyze", json={"params": {}, "positions": 21}).json()
    assert out["ok"] is ok
    if ok:
        n = out["geometry"]["n"]
        model = aio.load(bundled(name))
        k = len(model.mechanism.coordinates)
        assert n == (21 if k == 1 else len(model.range))
        assert [c["name"] for c in out["coordinates"]] == list(model.mechanism.coordinates)
        assert all(len(v) == n for v in out["geometry"]["points"].values())
    else:
        assert "cannot close" in out["error"]["message"]
        assert info["parameters"]
