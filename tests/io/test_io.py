"""Model files (issue 4): the bundled seed machines load, their [[solve]] conditions give seed 003's Find roots, and every malformed
file in ``tests/io/malformed/`` raises :class:`assur.io.ModelFileError` naming the key
path and the line written in its first line (``# expect: <key path> @ <line>``;
``-`` for a TOML syntax error, which has no key path)."""

import math
import pickle
import re

import numpy as np
import pytest

from assur import AssemblyError, ModelError, io
from assur.io import ModelFileError
from assur.io._lines import line_index, line_of
from tests.helpers import ROOT, TESTS

HERE = TESTS / "io"
MALFORMED = sorted((HERE / "malformed").glob("*.toml"))

#: seed 003: the exact roots of its Find blocks (BRIEF.md)
FOUND_003 = {"L4": 0.661283167, "Sp": 0.469356940, "L7": 0.752169525}


@pytest.fixture(scope="module")
def hitch():
    return io.load(io.bundled("hitch_003"))


# ---- bundled files ---------------------------------------------------------------------------
@pytest.mark.parametrize("name", ["hitch_003", "header_000", "header_000_fixed"])
def test_bundled_files_load(name):
    model = io.load(io.bundled(name))
    assert model.mechanism.name == name and model.name == name
    assert model.source == io.bundled(name) and model.source.suffix == ".toml"
    assert model.range.ndim == 1 and not model.range.flags.writeable
    assert list(model.ranges) == ["S"]


def test_hitch_003_range_and_tables(hitch):
    """The file's range is the seed's (003 §1.3: Smin, Smax, Npol = 10); its kinematics
    reproduce the printed tables (the seed-table tests load the same file through
    ``assur.examples``; one machine, one definition)."""
    seed_range = np.linspace(0.420, 0.670, 10)
    np.testing.assert_array_equal(hitch.range, seed_range)
    r = hitch.mechanism.solve(hitch.range)
    assert np.round(r.phi("6", degrees=True), 1).tolist()[:3] == [88.5, 89.2, 90.3]
    assert np.round(r.transmission("S6"), 3).tolist()[-1] == 4.933


def test_hitch_003_solves_the_seed_find_blocks(hitch):
    p = hitch.mechanism.params
    assert (round(p["L4"], 4), round(p["Sp"], 4), round(p["L7"], 4)) == (0.6613, 0.4694, 0.7522)
    for k, v in FOUND_003.items():
        assert abs(p[k] - v) < 1e-9, k
    assert [s.condition.unknown for s in hitch.solved] == ["L4", "Sp", "L7"]
    assert all(abs(s.residual) < 1e-12 for s in hitch.solved)
    lines = hitch.source.read_text().splitlines()
    for s in hitch.solved:  # each condition's source is its [[solve]] header
        file, line = s.condition.source.rsplit(":", 1)
        assert file == str(hitch.source) and lines[int(line) - 1].startswith("[[solve]]")
    c = hitch.solved[2].condition
    assert (c.quantity, c.at, c.target, c.bracket) == ("phi6", {"S": "Sp"}, math.pi / 2,
                                                        (0.56, 1.05))
    r = hitch.mechanism.solve([0.42, p["Sp"]])
    assert r.y("56") == pytest.approx([0.2, 0.4], abs=1e-12)
    assert r.phi("6")[1] == pytest.approx(math.pi / 2, abs=1e-12)


def test_hitch_003_start_values_are_the_seed_s(hitch):
    text = hitch.source.read_text()
    start = io.loads(re.sub(r"(?ms)^\[\[solve\]\].*", "", text)).mechanism.params
    assert (start["L4"], start["L7"], start["Sp"]) == (0.6, 0.7, 0.5 * (0.42 + 0.67))


def test_header_000_loads_and_solving_raises_the_triangle_error():
    model = io.load(io.bundled("header_000"))
    np.testing.assert_allclose(model.range, np.round(np.arange(0.650, 0.8001, 0.010), 10),
                               rtol=0, atol=1e-15)
    with pytest.raises(AssemblyError) as exc:
        model.mechanism.solve(model.range)
    msg = str(exc.value)
    assert re.search(r"L4 exceeds L3 \+ L34 = 0\.65234 m by 4\.66 mm", msg), msg
    assert exc.value.group == "arm 46" and "16 of 16 positions fail" in msg


def test_header_000_fixed_assembles():
    fixed = io.load(io.bundled("header_000_fixed"))
    m = fixed.mechanism
    assert m.params["L4"] == 0.652
    assert "illustrative" in m.title and any("illustrative" in n for n in m.notes)
    header = io.load(io.bundled("header_000")).mechanism
    assert m.groups == header.groups and m.links == header.links and m.loads == header.loads
    r = m.solve(fixed.range)
    assert r.ok.all() and np.all(np.isfinite(r.x("S6")))


def test_bundled_unknown_name():
    with pytest.raises(ValueError, match='no bundled model .*did you mean "hitch_003"'):
        io.bundled("hitch_03")
    assert io.bundled("hitch_003.toml") == io.bundled("hitch_003")


def test_examples_load_the_bundled_files(hitch):
    from assur import examples
    assert examples.hitch_003().params == hitch.mechanism.params
    assert examples.hitch_003().groups == hitch.mechanism.groups
    assert examples.hitch_003(L4=0.6613).params["L4"] == 0.6613
    np.testing.assert_array_equal(examples.hitch_003_range(), hitch.range)
    assert examples.header_000().name == "header_000"
    assert examples.header_000_fixed().params["L4"] == 0.652
    assert examples.header_000(XN=1.3).params["dXN"] == 1.3 - 0.767
    assert examples.header_000(YN=0.5, L4=0.652).params["dYN"] == 0.5 - 0.355
    assert len(examples.header_000_range()) == 16
    assert set(examples.HITCH_003_FOUND) == {"L4", "Sp", "L7"}


def test_documented_example_loads():
    """The complete example of docs/model-format.md is a valid model."""
    doc = (ROOT / "docs" / "model-format.md").read_text()
    text = re.search(r"```toml\n(.*?)```", doc, re.S).group(1)
    model = io.loads(text, name="lift.toml")
    assert model.source is None and model.name == "lift"
    assert model.mechanism.params["L4"] == pytest.approx(FOUND_003["L4"], abs=1e-9)
    assert model.mechanism.params["phiBD"] == math.radians(22)
    model.mechanism.analyze(model.range)  # loads, cylinder and machine are usable


# ---- malformed files ---------------------------------------------------------------------------
def expectation(path):
    m = re.match(r"# expect: (\S+) @ (\d+)$", path.read_text(encoding="utf-8").splitlines()[0])
    assert m, f"{path.name}: first line must be '# expect: <key path> @ <line>'"
    return ("" if m.group(1) == "-" else m.group(1)), int(m.group(2))


#: what each message must say beyond the location: what was expected and what was found
MESSAGES = {
    "frame_polar_origin_defined_later": 'frame point "O1" is not defined before "O3"',
    "motion_speed_given_as_length": 'expected an angular velocity (e.g. "300 rpm"), found '
                                    '"300 mm"',
    "angle_unit_for_efficiency": 'expected a plain number (e.g. 0.84), found "0.84 deg"',
    "bad_unit": 'unknown unit "mmm": expected a length',
    "branch_value_off": "expected 1 or -1 (the assembly mode",
    "coordinate_not_declared": 'expected a generalized coordinate (one of: S), found "Q"',
    "cylinder_unknown_coordinate": 'expected a generalized coordinate (one of: S), found "T"',
    "duplicate_coordinate": 'the coordinate "S" is listed twice',
    "duplicate_group_name": 'the name "I (2,3)" is already used by groups[0]',
    "duplicate_point": 'point "23" is already defined by groups[0]',
    "efficiency_above_one": "expected a number in (0, 1], found 84",
    "force_given_as_mass": 'expected a force (e.g. "27.5 kN"), found "2800 kg"',
    "link_unknown_point": 'unknown point "46": expected a point of the mechanism',
    "load_unknown_point": 'unknown point "46": expected a point of the mechanism',
    "machine_steered_unknown": 'expected one of the axles (A, B), found "C"',
    "machine_three_axles": "expected exactly two axles, found 3",
    "missing_group_key": 'missing required key "rb"',
    "missing_group_type": 'missing required key "type" (one of: cylinder_lever, dyad',
    "missing_model_name": 'missing required key "name"',
    "multiline_array_item": 'expected a length (e.g. "0.48 m"), found "0.480 deg"',
    "negative_length_literal": 'expected a positive length, found "-0.2 m"',
    "negative_length_param": 'expected a positive length, found "-0.480 m" (L5 is used at '
                             'groups[2].rb)',
    "parameter_is_boolean": "expected a number or a string",
    "parameter_not_finite": "expected a finite number, found inf",
    "load_unknown_link": 'unknown link "9": expected a link of the mechanism (0, 2, 3, 4, 5)',
    "parameter_named_like_coordinate": '"S" is a generalized coordinate',
    "parameter_refers_to_parameter": 'found "L5": a parameter cannot refer to another',
    "parameter_two_kinds": 'expected an angle, found "L3", a parameter used as a length at '
                           'groups[0].lever',
    "point_defined_later": 'point "45" is defined later, by groups[2]',
    "points_not_on_one_link": "points '01' and '23' are not both on link '3'",
    "prp_dyad_direction_given_as_length": 'expected an angle (e.g. "22 deg"), found "150 mm"',
    "range_count_below_two": "expected an integer ≥ 2, found 1",
    "range_two_forms": "not both values and from/to",
    "range_unknown_coordinate": 'unknown coordinate "T": expected one of the coordinates (S)',
    "rigid_point_both_forms": "expected either angle, or base, opposite and branch",
    "rpr_dyad_missing_length": 'missing required key "length"',
    "solve_bracket_reversed": "expected [low, high] with low < high",
    "solve_equals_wrong_dimension": 'expected a length (e.g. "0.48 m"), found "20 deg"',
    "solve_no_root": "no root for L4 in the bracket [0.48 m, 0.9 m]",
    "solve_position_missing": "expected the position of every coordinate (S), missing S",
    "solve_quantity_unknown": 'found "Y46"; did you mean "Y45"',
    "solve_several_roots": "2 roots for L4 in the bracket [0.5 m, 0.85 m]",
    "solve_unknown_not_a_parameter": 'expected a parameter name, found "L44"; did you mean "L4"',
    "syntax_duplicate_key": "TOML syntax error: Cannot overwrite a value",
    "syntax_missing_equals": "TOML syntax error: Expected '='",
    "syntax_unterminated_string": "is a string missing its closing quote?",
    "tables_unknown_link": 'unknown link "9": expected a link of [links] (3, 5), found "9"',
    "unit_wrong_dimension_in_group": 'expected a length (e.g. "0.48 m"), found "22 deg"',
    "unit_wrong_dimension_param": 'expected an angle (e.g. "22 deg"), found "80 mm"',
    "unknown_group_type": 'unknown group type "dyda"; did you mean "dyad"?',
    "unknown_key_in_group": 'unknown key "levr"; did you mean "lever"?',
    "unknown_key_in_model": 'unknown key "coordinate"; did you mean "coordinates"?',
    "unknown_load_type": 'unknown load type "wieght"; did you mean "weight"?',
    "unknown_parameter": 'found "L44", which is not a parameter; did you mean "L4"',
    "unknown_point": 'unknown point "35": expected a point of the frame or of an earlier group',
    "unknown_section": 'unknown key "paramz"; did you mean "params"?',
    "wrong_number_of_links": 'expected 2 link names (link at a, link at b), found ["4"]',
    "wrong_type_branch_string": 'expected 1 or -1 (the assembly mode',
    "wrong_type_name": "expected a string, found 5",
}


def test_there_are_enough_malformed_files():
    assert len(MALFORMED) >= 30
    assert sorted(MESSAGES) == [p.stem for p in MALFORMED]


@pytest.mark.parametrize("path", MALFORMED, ids=[p.stem for p in MALFORMED])
def test_malformed_file_raises_a_located_error(path):
    key, line = expectation(path)
    with pytest.raises(ModelFileError) as exc:
        io.load(path)
    e = exc.value
    assert (e.key_path, e.line) == (key, line), str(e)
    assert e.file == str(path)
    assert str(e).startswith(f"{path}:{line}: " + (f"{key}: " if key else "")), str(e)
    assert MESSAGES[path.stem] in str(e), str(e)


def test_error_is_a_model_error_and_picklable():
    with pytest.raises(ModelError) as exc:
        io.loads('[model]\nname = "x"\ncoordinates = ["S"]\n', name="x.toml")
    e = exc.value
    assert isinstance(e, ValueError)
    assert str(e) == 'x.toml:1: range: missing required key "range"'
    e2 = pickle.loads(pickle.dumps(e))
    assert (e2.file, e2.line, e2.key_path, str(e2)) == (e.file, e.line, e.key_path, str(e))


def test_non_utf8_file(tmp_path):
    f = tmp_path / "bad.toml"
    f.write_bytes(b'[model]\nname = "\xff"\n')
    with pytest.raises(ModelFileError, match=r"bad.toml:2: expected UTF-8"):
        io.load(f)


# every line of a bundled file deleted or cut in half: a located error or a valid model,
# never another exception type
@pytest.mark.parametrize("name", ["header_000", "hitch_003"])
def test_mutilated_files_give_only_model_file_errors(name):
    text = io.bundled(name).read_text()
    text = re.sub(r"(?ms)^\[\[solve\]\].*", "", text)  # keep the sweep fast
    lines = text.split("\n")
    errors = 0
    for i in range(len(lines)):
        for cut in (lines[:i] + lines[i + 1:], lines[:i] + [lines[i][:len(lines[i]) // 2]]
                    + lines[i + 1:]):
            try:
                io.loads("\n".join(cut), name="m.toml")
            except ModelFileError as e:
                errors += 1
                assert 1 <= e.line <= len(lines)
    assert errors > len(lines) // 2


# ---- values and units -------------------------------------------------------------------------
LIFT = (ROOT / "docs" / "model-format.md").read_text()
LIFT = re.search(r"```toml\n(.*?)```", LIFT, re.S).group(1)
LIFT = re.sub(r"(?ms)^\[\[solve\]\].*", "", LIFT)  # no solving: fast


def lift(old, new):
    assert old in LIFT
    return io.loads(LIFT.replace(old, new, 1), name="lift.toml").mechanism


@pytest.mark.parametrize("written,si", [
    ('phiBD = 22', math.radians(22)),            # plain angle: degrees
    ('phiBD = "22 deg"', math.radians(22)),
    ('phiBD = "22°"', math.radians(22)),
    ('phiBD = "0.5 rad"', 0.5),
    ('phiBD = "1320 arcmin"', math.radians(22)),
])
def test_angles(written, si):
    assert lift("phiBD = 22", written).params["phiBD"] == pytest.approx(si, rel=1e-15)


@pytest.mark.parametrize("written,si", [
    ('L3 = 0.2', 0.2), ('L3 = "200 mm"', 0.2), ('L3 = "20 cm"', 0.2), ('L3 = "0.2m"', 0.2),
    ('L3 = "7.874015748 in"', 0.2),
])
def test_lengths(written, si):
    assert lift('L3 = "0.200 m"', written).params["L3"] == pytest.approx(si, rel=1e-9)


def test_units_of_other_kinds():
    m = lift('P = "27.5 kN"', 'P = "2.8 tf"\nQ = "80 l/min"\nM = "2.9 kN·m"\n'
                              'k = "20 kN/m"\nJ = "12 kg*m^2"\np = "175 bar"')
    assert m.params["P"] == pytest.approx(2.8 * 1000 * 9.80665, rel=1e-12)  # tonne-force
    assert m.params["Q"] == pytest.approx(80e-3 / 60)          # unused: by its unit, SI
    assert m.params["M"] == 2900.0 and m.params["k"] == 20000.0 and m.params["J"] == 12.0
    assert m.params["p"] == pytest.approx(17.5e6)
    c = lift("eta_hyd = 0.84", 'eta_hyd = "84 %"').cylinders[0]
    assert c.eta_hyd == pytest.approx(0.84)
    assert c.bore == 0.08 and c.p_relief == 17.5e6 and c.count == 2


def test_a_plain_number_for_an_angle_condition_is_degrees():
    text = LIFT + ('\n[[solve]]\nunknown = "L4"\nbracket = ["0.48 m", "0.9 m"]\n'
                   'at = { S = "Smin" }\nquantity = "phi5"\nequals = -30\n')
    model = io.loads(text)
    assert model.solved[0].condition.target == math.radians(-30)
    assert model.mechanism.solve([0.42]).phi("5")[0] == pytest.approx(math.radians(-30),
                                                                     abs=1e-12)


@pytest.mark.parametrize("value", ['"__import__(\'os\').system(\'true\')"', '"0.2 m; rm"',
                                   '"1 + 1"', '"nan m"', '"inf"', '"0.2 * m"', '"{0.2} m"'])
def test_values_are_never_evaluated(value):
    with pytest.raises(ModelFileError) as exc:
        lift('L3 = "0.200 m"', f"L3 = {value}")
    assert exc.value.key_path == "params.L3"


def test_range_forms_and_two_coordinates():
    one = io.loads(LIFT.replace('S = { from = "Smin", to = "Smax", count = 10 }',
                                'S = { from = "Smin", to = "Smax", step = "25 mm" }'))
    np.testing.assert_allclose(one.range, np.linspace(0.42, 0.67, 11), atol=1e-15)
    vals = io.loads(LIFT.replace('S = { from = "Smin", to = "Smax", count = 10 }',
                                 'S = { values = [0.42, "500 mm", "Smax"] }'))
    np.testing.assert_array_equal(vals.range, [0.42, 0.5, 0.67])
    # two coordinates: the brace 4 is a second cylinder of length S1
    text = (LIFT.replace('coordinates = ["S"]', 'coordinates = ["S", "S1"]')
            .replace('ra = "L4"', 'ra = "S1"')
            .replace('count = 10 }', 'count = 3 }\nS1 = { values = ["0.65 m", "0.67 m"] }'))
    two = io.loads(text)
    assert two.range.shape == (6, 2)
    np.testing.assert_array_equal(two.range[:2], [[0.42, 0.65], [0.42, 0.67]])
    assert list(two.ranges) == ["S", "S1"]
    r = two.mechanism.solve(two.range)
    assert r.ok.all()


def test_crank_range_in_degrees():
    text = """
[model]
name = "crank-rocker"
coordinates = ["q"]
[params]
r = "0.1 m"
[range]
q = { from = 0, to = 360, count = 13 }
[frame]
"0" = [0, 0]
"1" = ["0.3 m", "0 m"]
[[groups]]
type = "crank"
name = "crank"
pivot = "0"
out = "A"
radius = "r"
q = "q"
phase = "90 deg"
[[groups]]
type = "dyad"
name = "II"
a = "A"
b = "1"
out = "B"
ra = "0.3 m"
rb = "0.25 m"
branch = 1
[links]
rocker = ["1", "B"]
"""
    model = io.loads(text)
    np.testing.assert_allclose(model.range, np.radians(np.arange(0, 361, 30)), atol=1e-15)
    assert model.mechanism.group("crank").phase == math.pi / 2
    assert model.mechanism.solve(model.range).ok.all()
    with pytest.raises(ModelFileError, match=r"range.q.to: expected an angle"):
        io.loads(text.replace("to = 360", 'to = "360 mm"'))


# ---- the line index ----------------------------------------------------------------------------
def test_line_index_on_tricky_toml():
    text = '''# comment [not a table]
title = """multi
line [x] = "y"
"""  # trailing
lit = \'\'\'C:\\path\'\'\'
"quoted.key" = 1
dotted.inner = 2   # x = 3

[[groups]]
name = "a#b"
arr = [
  1,  # one
  [2, 3],
  { k = "v", n.m = 4 },
]

[[groups]]
name = 'second'
[groups.sub]
x = 1

[ tables . ratios ]
pairs = [["5", "3"],
         ["6", "5"]]
'''
    import tomllib
    tomllib.loads(text)
    idx = line_index(text)
    assert idx[("title",)] == 2 and idx[("lit",)] == 5 and idx[("quoted.key",)] == 6
    assert idx[("dotted", "inner")] == 7
    assert idx[("groups", 0)] == 9 and idx[("groups", 0, "name")] == 10
    assert idx[("groups", 0, "arr", 0)] == 12 and idx[("groups", 0, "arr", 1, 1)] == 13
    assert idx[("groups", 0, "arr", 2, "n", "m")] == 14
    assert idx[("groups", 1)] == 17 and idx[("groups", 1, "name")] == 18
    assert idx[("groups", 1, "sub", "x")] == 20
    assert idx[("tables", "ratios", "pairs", 1, 0)] == 24
    assert line_of(idx, ("groups", 1, "missing")) == 17
    assert line_of(idx, ("nowhere",)) == 1
