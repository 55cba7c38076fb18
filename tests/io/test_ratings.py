"""``[[rating]]`` tables: parsed at their keys and lines (io/_ratings.py)."""

import pytest

from assur import io
from tests.helpers.ratings import ARM, MACHINE

CHART = '''
[[rating]]
type = "crane_chart"
point = "T"
axis = "O"
'''


def _error(text):
    with pytest.raises(io.ModelFileError) as e:
        io.loads(text, name="arm.toml")
    return e.value


def _line(text, needle):
    return text.splitlines().index(needle) + 1


def test_a_rating_reaches_the_model_and_its_analysis():
    model = io.loads(ARM + CHART + 'name = { en = "Chart", ru = "График" }\n')
    (r,) = model.ratings
    assert (r.point, r.axis, r.self_weight, r.cylinders) == ("T", "O", True, None)
    assert r.heading("ru") == "График"
    (res,) = model.analyze().ratings
    assert res.rating is r and len(res["G"]) == len(model.range)
    assert io.loads(ARM).ratings == ()


def test_an_unknown_type_lists_the_types_at_its_line():
    text = ARM + CHART.replace('"crane_chart"', '"crane_chrt"')
    e = _error(text)
    assert e.key_path == "rating[0].type" and e.line == _line(text, 'type = "crane_chrt"')
    assert "crane_chart" in str(e) and "did you mean" in str(e)


def test_an_unknown_point_is_refused_at_its_key():
    text = ARM + CHART.replace('point = "T"', 'point = "TT"')
    e = _error(text)
    assert e.key_path == "rating[0].point" and e.line == _line(text, 'point = "TT"')
    assert "expected a point of the model, found 'TT'" in str(e)


def test_an_unknown_cylinder_is_refused_at_its_key():
    text = ARM + CHART + 'cylinders = ["c1", "c3"]\n'
    e = _error(text)
    assert e.key_path == "rating[0].cylinders"
    assert "'c3'" in str(e) and "c1, c2" in str(e)


def test_unknown_and_missing_keys_and_wrong_values():
    e = _error(ARM + CHART + 'reach = "2 m"\n')
    assert e.key_path == "rating[0].reach" and "unknown key" in str(e)
    e = _error(ARM + CHART.replace('axis = "O"\n', ""))
    assert e.key_path == "rating[0]" and 'missing the key "axis"' in str(e)
    e = _error(ARM + CHART + "self_weight = 1\n")
    assert e.key_path == "rating[0].self_weight" and "true or false" in str(e)
    e = _error(ARM + "\n[[rating]]\npoint = \"T\"\n")
    assert 'missing the key "type"' in str(e)
    e = _error(ARM + "\nrating = 3\n".replace("rating = 3", "[rating]\ntype = 3"))
    assert e.key_path == "rating" and "array of tables" in str(e)


def test_a_value_takes_units_and_parameters():
    text = ARM + MACHINE + '''
[[rating]]
type = "loader_breakout"
edge = "T"
back = "O1"
lift_cylinder = "c1"
tilt_cylinder = "c2"
offset = "4 in"
'''
    (r,) = io.loads(text).ratings
    assert r.offset == pytest.approx(0.1016, rel=1e-12)
    e = _error(text.replace('offset = "4 in"', 'offset = "4 kN"'))
    assert e.key_path == "rating[0].offset"


def test_a_chart_whose_cylinders_do_not_move_its_point_is_refused_at_the_point():
    text = ARM + CHART.replace('point = "T"', 'point = "A"')   # a frame point
    e = _error(text)
    assert e.key_path == "rating[0].point" and "no cylinder of the chart moves 'A'" in str(e)
