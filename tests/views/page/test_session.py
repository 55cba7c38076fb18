"""The page's model (:mod:`assur.views.page.session`): the edited model file keeps its
comments and loads as the same model but for the edited values; parameters that are
not finite numbers are refused; the bounds of a request."""

import pytest

from assur.io import bundled
from assur.views.page.session import PageModel


def test_page_model_rejects_non_numbers():
    from assur.errors import ModelError
    pm = PageModel.from_path(bundled("hitch_003"))
    with pytest.raises(ModelError, match="finite number"):
        pm.edited_text({"L5": float("inf")})
    with pytest.raises(ModelError, match="finite number"):
        pm.edited_text({"L5": True})



def test_the_edited_file_keeps_comments_and_loads_as_the_same_model():
    from assur import io
    pm = PageModel.from_path(bundled("hitch_003"))
    text = pm.edited_text({"L5": 0.49})
    original = bundled("hitch_003").read_text(encoding="utf-8")
    comments = [ln for ln in original.splitlines() if ln.lstrip().startswith("#")]
    assert all(c in text for c in comments)
    edited = io.loads(text, name="edited.toml").mechanism
    base = io.load(bundled("hitch_003")).mechanism
    assert edited.params["L5"] == 0.49
    solved = {"L4", "Sp", "L7"}  # solved again from the file's conditions with the new L5
    assert {k: v for k, v in edited.params.items() if k not in solved | {"L5"}} == \
        {k: v for k, v in base.params.items() if k not in solved | {"L5"}}
    assert edited.params["L4"] != base.params["L4"]
    assert pm.load({"L5": 0.49}).mechanism.params["L5"] == 0.49


def test_the_bounds_of_a_request():
    from assur.errors import ModelError
    from assur.views.page.session import MAX_PARAMS, MAX_POSITIONS
    pm = PageModel.from_path(bundled("hitch_003"))
    with pytest.raises(ModelError, match=f"at most {MAX_PARAMS} parameters"):
        pm.check_params({f"p{i}": 1.0 for i in range(MAX_PARAMS + 1)})
    with pytest.raises(ValueError, match=f"positions must be in 2…{MAX_POSITIONS}"):
        pm.compute({}, positions=MAX_POSITIONS + 1)


# ---- issue 24: the page for every kind of machine -----------------------------------

@pytest.mark.parametrize("name, way", [("cleaning_lab3", 1.0), ("combine_002", -1.0),
                                       ("combine_002_turn", -1.0)])
def test_a_crank_is_shown_over_one_whole_turn_in_the_files_direction(name, way):
    import numpy as np
    pm = PageModel.from_path(bundled(name))
    r = np.asarray(pm.model.range, dtype=float)
    q = np.asarray(pm.model_on(pm.model, 90).range)
    assert pm.turns(pm.model)
    assert q[0] == r[0]
    assert np.allclose(np.diff(q), way * 2 * np.pi / 90)     # evenly, the end left out


def test_a_partial_swing_is_resampled_between_its_extremes():
    import dataclasses

    import numpy as np
    pm = PageModel.from_path(bundled("combine_002"))
    rocker = dataclasses.replace(pm.model, range=np.radians([30.0, 90.0, 60.0]))  # unordered
    assert not pm.turns(rocker)
    q = np.degrees(pm.model_on(rocker, 5).range)
    assert np.allclose(q, [30, 45, 60, 75, 90])


def test_physical_spans_of_parameters():
    pm = PageModel.from_path(bundled("loader_lab1"))
    p = {q["name"]: q for q in pm.parameters()}
    assert (p["eta"]["min"], p["eta"]["max"]) == (0, 1)                  # an efficiency
    assert p["p_relief"]["min"] == 0 and p["p_relief"]["max"] is None   # a pressure
    assert p["X01"]["min"] is None                                      # a coordinate
    crane = {q["name"]: q for q in PageModel.from_path(bundled("crane_lv185")).parameters()}
    assert crane["n_boom"]["integer"] and crane["n_boom"]["min"] == 0    # a count
    assert crane["Jpk"]["unit_text"] == {"en": "kg·m²", "ru": "кг·м²"}  # as tables write it


def test_a_cranks_speed_is_an_input_in_rpm_written_back_into_motion():
    import numpy as np
    pm = PageModel.from_path(bundled("cleaning_lab3"))       # j1: speed = "30 rad/s"
    p = {q["name"]: q for q in pm.parameters()}["speed-j1"]
    assert p["unit"] == "rpm" and p["value"] == pytest.approx(30 * 60 / (2 * np.pi))
    text = pm.edited_text({"speed-j1": 300})
    assert 'j1 = { direction = "cw", speed = "300 rpm" }' in text
    motion = pm.load({"speed-j1": 300}).mechanism.motion("j1")
    assert motion.speed == pytest.approx(300 * 2 * np.pi / 60)   # [rad/s]
    assert motion.direction == -1                                 # still clockwise
    assert not any(q["name"].startswith("speed-")
                   for q in PageModel.from_path(bundled("hitch_003")).parameters())


def test_two_coordinates_come_with_their_grid_and_default_plots_from_the_content():
    pm = PageModel.from_path(bundled("loader_lab1"))
    out = pm.compute({})
    g = out["grid"]
    assert (len(g["x"]), len(g["y"])) == (13, 8)
    t = out["tables"][0]
    for k in (0, 40, 103):                    # every position at its grid indices
        assert t["columns"][0]["values"][k] == g["x"][g["i"][k]]
        assert t["columns"][1]["values"][k] == g["y"][g["j"][k]]
    plots = [(p["table"], p["symbol"]) for p in out["defaults"]]
    assert ("4.1", "p_S") in plots and ("4.1", "p_S1") in plots      # the cylinders' pressures
    assert any(s.startswith("G") for _, s in plots)                  # a capacity
    assert any(s.startswith("R0") for _, s in plots)                 # a reaction on the frame
    crank = PageModel.from_path(bundled("cleaning_lab3")).compute({})
    assert {"Xc", "Yc"} <= {p["symbol"] for p in crank["defaults"]}  # the centre of mass
    assert crank["grid"] is None and crank["turn"]


def test_exports_are_made_at_the_pages_positions():
    import csv
    import io
    pm = PageModel.from_path(bundled("hitch_003"))
    data, _, _ = pm.export_tables({}, "csv", table="2.1", positions=101)
    rows = list(csv.reader(io.StringIO(data.decode("utf-8-sig"))))
    assert len(rows) == 1 + 101
    data, _, _ = pm.export_tables({}, "csv", table="2.1")      # the file's own 10
    assert len(data.decode("utf-8-sig").splitlines()) == 1 + 10


def test_the_plots_a_file_declares_come_first():
    pm = PageModel.from_path(bundled("steering_lab4"))     # [display] plots: β over α
    out = pm.compute({})
    assert out["defaults"][0] == {"table": "F", "symbol": "beta", "x": "alpha",
                                  "with": ["beta_ideal"]}
    assert not out["warnings"]
    text = pm.text.replace('y = ["beta", "beta_ideal"]', 'y = ["beta", "gamma"]')
    out = PageModel(text, name="steer.toml", source=bundled("steering_lab4")).compute({})
    assert out["defaults"][0]["symbol"] != "beta"
    assert "[display] plots: no table holds the columns ['beta', 'gamma', 'alpha']" in \
        " ".join(out["warnings"])


def test_a_declared_plot_is_checked_with_its_key_and_line():
    from assur.errors import ModelError
    text = bundled("steering_lab4").read_text(encoding="utf-8").replace(
        'plots = [{ x = "alpha", y = ["beta", "beta_ideal"] }]', 'plots = [{ x = "alpha", y = [] }]')
    with pytest.raises(ModelError, match=r"steer\.toml:\d+: display\.plots\[0\]\.y"):
        PageModel(text, name="steer.toml", source=bundled("steering_lab4"))


def test_too_few_positions_for_a_cranks_flywheel_is_a_message_not_a_crash():
    pm = PageModel.from_path(bundled("cleaning_lab3"))        # [dynamics]: a flywheel
    out = pm.compute({}, positions=11)
    assert not out["ok"] and out["error"]["kind"] == "model"
    assert "use more positions" in out["error"]["message"]


@pytest.mark.parametrize("name", ["hitch_003", "loader_lab1", "cleaning_lab3", "steering_lab4"])
def test_a_packed_answer_carries_the_same_values_as_bytes(name):
    """``packed``: every column's values as little-endian float64 in base64, equal bit
    for bit to the plain answer's list (NaN where it says null); so are the drawing's
    points (x, y by position), coordinates and wheels' headings; the rest unchanged."""
    import base64

    import numpy as np

    pm = PageModel.from_path(bundled(name))
    plain, packed = pm.compute({}, 101), pm.compute({}, 101, packed=True)
    assert plain["ok"] and packed["ok"]
    for tp, tk in zip(plain["tables"], packed["tables"], strict=True):
        assert tp["id"] == tk["id"]
        for cp, ck in zip(tp["columns"], tk["columns"], strict=True):
            got = np.frombuffer(base64.b64decode(ck["values"]["f64"]), "<f8")
            want = np.array([np.nan if v is None else v for v in cp["values"]])
            np.testing.assert_array_equal(got, want)
    def values(p):
        return np.frombuffer(base64.b64decode(p["f64"]), "<f8")

    gp, gk = plain["geometry"], packed["geometry"]
    assert gp["points"].keys() == gk["points"].keys() and gp["q"].keys() == gk["q"].keys()
    for p, xy in gp["points"].items():
        np.testing.assert_array_equal(values(gk["points"][p]).reshape(-1, 2), np.array(xy))
    for c, q in gp["q"].items():
        np.testing.assert_array_equal(values(gk["q"][c]), np.array(q))
    assert len(gp["wheels"]) == len(gk["wheels"])
    for wp, wk in zip(gp["wheels"], gk["wheels"]):
        np.testing.assert_array_equal(values(wk["heading"]), np.array(wp["heading"]))
        assert {k: v for k, v in wp.items() if k != "heading"} == \
            {k: v for k, v in wk.items() if k != "heading"}
    assert {k: v for k, v in gp.items() if k not in ("points", "q", "wheels")} == \
        {k: v for k, v in gk.items() if k not in ("points", "q", "wheels")}
    for key in ("grid", "defaults", "solved", "warnings"):
        assert plain[key] == packed[key]


def test_a_file_that_loads_is_never_scanned_for_lines():
    """The line index is built only when a message needs a line (the page's answers
    do not pay for it); an error still names its line."""
    from assur.io import ModelFileError, loads
    from assur.io._lines import LazyIndex

    text = bundled("cleaning_lab3").read_text()   # no [[solve]]: no line is asked for
    made = []
    real = LazyIndex._scan

    def scan(self):
        if not self.scanned:
            made.append(1)
        return real(self)

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(LazyIndex, "_scan", scan)
        loads(text, name="cleaning_lab3.toml")
        assert not made
        bad = text.replace("[range]", "[range]\nnot_a_coordinate = 1", 1)
        with pytest.raises(ModelFileError) as e:
            loads(bad, name="cleaning_lab3.toml")
    assert made == [1]
    assert e.value.line == bad[:bad.index("not_a_coordinate")].count("\n") + 1


def test_a_file_that_extends_another_edits_the_bases_parameters():
    """``hitch_003_design`` extends ``hitch_003``: the page offers the base's parameters
    (with its groups) and an edit gives the same answer as the same edit of the base;
    the TOML written back holds the edit in the child's own [params]."""
    import tomllib

    child, base = PageModel.from_path(bundled("hitch_003_design")), \
        PageModel.from_path(bundled("hitch_003"))
    got = {p["name"]: p for p in child.parameters()}
    want = {p["name"]: p for p in base.parameters()}
    assert set(got) == set(want)
    assert got["L5"]["group"] == "§1.2 links" and got["L5"]["editable"]
    assert got["L4"]["solved"] and not got["L4"]["editable"]
    a, b = child.compute({"L5": 0.5}, 11), base.compute({"L5": 0.5}, 11)
    assert a["ok"] and b["ok"]
    assert a["solved"] == b["solved"]
    assert [c["values"] for c in a["tables"][0]["columns"]] == \
        [c["values"] for c in b["tables"][0]["columns"]]
    text = child.edited_text({"L5": 0.5})
    doc = tomllib.loads(text)
    assert doc["extends"] == "hitch_003.toml" and "design" in doc
    assert doc["params"]["L5"] == "0.5 m"
