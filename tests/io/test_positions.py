"""The ``[range]`` pass of the loader (``assur.io._positions``): a held coordinate
``S1 = { hold = "phi9", equals = "75 deg", within = [low, high] }`` solved at every
position of the other (``assur.core.held``), its errors at the key and line that are
wrong, in the file's units."""

import math
import re

import numpy as np
import pytest

from assur import io
from assur.core.held import Hold, hold_path
from assur.io import ModelFileError

BASE = io.bundled("loader_lab1").read_text(encoding="utf-8")
RANGE = re.search(r"\[range\]\n(?:.+\n)+?\n", BASE).group(0)


def with_range(*lines):
    """loader_lab1.toml with its [range] replaced by ``lines``."""
    return BASE.replace(RANGE, "[range]\n" + "\n".join(lines) + "\n\n")


def line_of(text, start):
    return next(i for i, l in enumerate(text.splitlines(), 1) if l.startswith(start))


def fails(text):
    with pytest.raises(ModelFileError) as e:
        io.loads(text, name="loader.toml")
    return e.value


LEVEL = ('S = { from = "Smin", to = "1.25 m", count = 6 }',
         'S1 = { hold = "phi9", equals = "75 deg", within = ["0.77 m", "0.98 m"] }')


def test_a_held_range_is_the_path_the_api_solves():
    model = io.loads(with_range(*LEVEL), name="loader.toml")
    mech = model.mechanism
    path = hold_path(mech, "S", np.linspace(mech.params["Smin"], 1.25, 6),
                     [Hold("S1", "phi9", math.radians(75), (0.77, 0.98))])
    np.testing.assert_array_equal(model.range, path.q)
    np.testing.assert_array_equal(model.path.dq, path.dq)
    assert model.shape == (6,) and model.paired
    np.testing.assert_array_equal(model.ranges["S1"], path.q[:, 1])
    assert np.abs(mech.solve(model.range).phi("9") - math.radians(75)).max() < 1e-10


def test_a_target_given_by_a_parameter():
    text = with_range(LEVEL[0], 'S1 = { hold = "phi9", equals = "Th", within = ["0.77 m", '
                                '"0.98 m"] }').replace("[params]\n", '[params]\nTh = "75 deg"\n')
    model = io.loads(text, name="loader.toml")
    assert model.path.holds[0].target == pytest.approx(math.radians(75), abs=1e-15)
    assert not [w for w in model.warnings if "'Th'" in w]   # Th is used


def test_the_bundled_self_levelling_lift():
    model = io.load(io.bundled("loader_lab1_level"))
    assert model.path.holds[0].quantity == "phi9"
    assert model.shape == (11,)
    assert not model.warnings


def test_an_unreachable_target_is_told_at_the_hold_key_with_the_position():
    text = with_range('S = { from = "Smin", to = "Smax", count = 4 }', LEVEL[1])
    e = fails(text)
    assert e.key_path == "range.S1.hold" and e.line == line_of(text, "S1 = { hold")
    assert re.search(r"at S = 1\.43197 m \(position 3 of the path\) no S1 in \[0\.77 m, "
                     r"0\.98 m\] reaches phi9 = 75 deg", e.problem), e.problem


def test_a_held_range_that_does_not_assemble_names_the_group():
    text = with_range(LEVEL[0], 'S1 = { hold = "phi9", equals = "75 deg", within = '
                                '["500 mm", "600 mm"] }')
    e = fails(text)
    assert e.key_path == "range.S1.hold"
    assert "at S = 1.00106 m (position 1 of the path)" in e.problem
    assert "for S1 in [500 mm, 600 mm]" in e.problem and "MPT (4,5)" in e.problem


@pytest.mark.parametrize("entry, key, problem", [
    ('S1 = { hold = "phi99", equals = "75 deg", within = ["0.77 m", "0.98 m"] }',
     "range.S1.hold", 'expected X<point>, Y<point>, phi<link> or a distance name, found '
                      '"phi99"'),
    ('S1 = { hold = "phi9", equals = "0.7 m", within = ["0.77 m", "0.98 m"] }',
     "range.S1.equals", "angle"),
    ('S1 = { hold = "phi9", equals = "75 deg", within = ["0.77 m", "5 deg"] }',
     "range.S1.within[1]", "length"),
    ('S1 = { hold = "phi9", equals = "75 deg", within = ["0.98 m", "0.77 m"] }',
     "range.S1.within", "expected [low, high] with low < high"),
    ('S1 = { hold = "phi9", equals = "75 deg" }',
     "range.S1", "a held coordinate needs hold (the output held), equals (its value) and "
                 "within = [low, high] (the coordinate's limits); missing within"),
    ('S1 = { hold = "phi9", equals = "75 deg", within = ["0.77 m", "0.98 m"], from = '
     '"0.8 m" }', "range.S1", "not both hold and from"),
])
def test_a_held_range_key_errors_at_its_key_and_line(entry, key, problem):
    text = with_range(LEVEL[0], entry)
    e = fails(text)
    assert e.key_path == key, e
    assert e.line == line_of(text, "S1 = {"), e
    assert problem in e.problem, e.problem


def test_a_path_needs_one_coordinate_given():
    text = with_range('S = { hold = "phi3", equals = "20 deg", within = ["1 m", "1.6 m"] }',
                      LEVEL[1])
    e = fails(text)
    assert e.key_path == "range.S.hold" and e.line == line_of(text, "S = {")
    assert "one coordinate given by from/to or values and every other one held; given none" \
        in e.problem


def test_design_search_along_a_held_range_loads():
    """A [design] over a held path is no longer refused: the path is the model's and
    the design search solves each design's own (tests/synthesis/search/
    test_problem_held.py)."""
    text = with_range(*LEVEL) + '\n[design]\nvariables = { L35 = { within = "5 mm" } }\n'
    model = io.loads(text, name="loader.toml")
    assert model.path is not None and model.path.holds[0].coordinate == "S1"
    assert [v.name for v in model.design.variables] == ["L35"]


def test_a_held_point_height_over_listed_positions():
    """``values`` for the given coordinate and a length held (Y of the tool's centre of
    mass S9): S1 follows so that Y_S9 stays put."""
    text = with_range('S = { values = ["1095 mm", "1100 mm", "1105 mm"] }',
                      'S1 = { hold = "YS9", equals = "0.9734 m", within = ["0.77 m", '
                      '"0.98 m"] }')
    model = io.loads(text, name="loader.toml")
    np.testing.assert_allclose(model.range[:, 0], [1.095, 1.1, 1.105], rtol=0, atol=1e-15)
    kin = model.mechanism.solve(model.range)
    assert np.abs(kin.y("S9") - 0.9734).max() < 1e-12
    assert np.all(np.diff(model.range[:, 1]) < 0)   # S1 retracts as S extends
    np.testing.assert_allclose(model.path.transmission(kin, "S9"), 0.0, atol=1e-12)
    # a height out of reach: the position in the file's unit (mm)
    e = fails(text.replace('"0.9734 m"', '"5 m"'))
    assert e.key_path == "range.S1.hold"
    assert "at S = 1095 mm (position 1 of the path) no S1 in [0.77 m, 0.98 m] reaches " \
           "YS9 = 5 m" in e.problem, e.problem
