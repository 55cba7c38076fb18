"""Errors of the ``[design]`` section at the key that is wrong (issue 27's one-offs):
a constraint on a point the mechanism lacks is refused when the file loads, at its
``quantity`` line, naming the points (it was told at optimization as "the original
design does not assemble"); a limit that is not a number (``"nan m"``) at its own
line with what was expected and found (the message was empty); a variable given as
a table with other keys than ``within`` names those keys, not pydantic's name of the
array alternative."""

from __future__ import annotations

import pytest

from assur import io
from assur.io import ModelFileError

BASE = io.bundled("hitch_003_design").as_posix()


def _load(tmp_path, body):
    path = tmp_path / "design.toml"
    path.write_text(f'extends = "{BASE}"\n' + body, encoding="utf-8")
    with pytest.raises(ModelFileError) as e:
        io.load(path)
    return " ".join(str(e.value).split())


def test_an_unknown_point_is_told_at_the_quantity(tmp_path):
    msg = _load(tmp_path, '\n[[design.constraints]]\nquantity = "Y(99)"\nof = "min"\n'
                          'at_most = "1 m"\n')
    assert "design.toml:4: design.constraints[3].quantity: Y(99): unknown point '99'" in msg
    assert "points: 01, 03" in msg and "does not assemble" not in msg


@pytest.mark.parametrize("limit", ["nan m", "inf m", "a lot"])
def test_a_limit_that_is_no_number_is_told_at_its_key(tmp_path, limit):
    msg = _load(tmp_path, '\n[[design.constraints]]\nquantity = "Y(56)"\nof = "min"\n'
                          f'at_most = "{limit}"\n')
    assert "design.toml:6: design.constraints[3].at_most: " in msg, msg
    assert "expected a length" in msg


def _variable(tmp_path, form):
    path = tmp_path / "design.toml"
    path.write_text(io.bundled("hitch_003_design").read_text(encoding="utf-8").replace(
        'X01 = { within = "30 mm" }', f"X01 = {form}")
        .replace('extends = "hitch_003.toml"', f'extends = "{io.bundled("hitch_003").as_posix()}"'),
        encoding="utf-8")
    return path


def test_a_variable_by_low_and_high_equals_the_array_form(tmp_path):
    by_name = io.load_problem(_variable(tmp_path, '{ low = "-1.1 m", high = "-1000 mm" }'))
    (tmp_path / "b").mkdir()
    as_array = io.load_problem(_variable(tmp_path / "b", '["-1.1 m", "-1000 mm"]'))
    assert by_name.bounds.tolist() == as_array.bounds.tolist()
    assert by_name.bounds[0].tolist() == [-1.1, -1.0]  # X01 [m]


@pytest.mark.parametrize("form, said", [
    ('{ low = "0.5 m", top = "0.6 m" }', 'missing required key "high"'),
    ('{ wide = "0.1 m" }', 'missing required key "within"'),
    ('{ low = "0.5 m" }', 'missing required key "high"'),
    ('{ low = "0.5 m", high = "3 kg" }', "expected a length"),
])
def test_a_variable_table_that_is_wrong_names_its_keys(tmp_path, form, said):
    with pytest.raises(ModelFileError) as e:
        io.load(_variable(tmp_path, form))
    msg = str(e.value)
    assert 'design.variables.X01' in msg and "list[" not in msg and "function-after" not in msg
    assert said in msg, msg


@pytest.mark.parametrize("form", ['{ low = "-1.0 m", high = "-1100 mm" }',
                                  '["-1.0 m", "-1100 mm"]',
                                  '{ low = "-1.0 m", high = "-1.0 m" }'])
def test_low_not_below_high_is_told_at_the_variables_line(tmp_path, form):
    """Either form, with units: low must be below high, told at X01's own line."""
    path = _variable(tmp_path, form)
    line = path.read_text(encoding="utf-8").splitlines().index(f"X01 = {form}") + 1
    with pytest.raises(ModelFileError) as e:
        io.load_problem(path)
    msg = " ".join(str(e.value).split())
    assert f"design.toml:{line}: design.variables.X01:" in msg, msg
    assert "low < high" in msg and "[-1.0, -1." in msg, msg
