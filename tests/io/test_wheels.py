"""``[[wheels]]`` of a model file (:mod:`assur.io._wheels`, the schema's ``WheelSpec``):
values in SI with the kind of their use, parameters named, and every error — an
unknown link or point, a missing or wrong value, an unknown key — names the key path
and the line."""

import math

import pytest

from assur import io
from assur.io import ModelFileError

BASE = io.bundled("steering_lab4").read_text(encoding="utf-8")
LEFT = '''[[wheels]]
name = { en = "left wheel", ru = "левое колесо" }
link = "w3"
at = "03"
heading = "0 deg"         # rolling direction = the lever's direction
diameter = "D_wheel"      # illustrative
width = "B"               # the lab's tyre width
'''


def _load(left):
    assert LEFT in BASE
    return io.loads(BASE.replace(LEFT, left), name="steer.toml")


def _line(text, needle):
    return next(k for k, ln in enumerate(text.splitlines(), 1) if ln.startswith(needle))


def test_the_bundled_wheels_in_si():
    m = io.load(io.bundled("steering_lab4")).mechanism
    left, right = m.wheels
    assert (str(left.name), left.name.translations) == ("left wheel", {"ru": "левое колесо"})
    assert (left.link, left.at, right.link, right.at) == ("w3", "03", "w5", "05")
    assert (left.diameter, left.width, left.heading) == ("D_wheel", "B", 0.0)
    assert m.params["D_wheel"] == pytest.approx(1.1) and m.params["B"] == pytest.approx(0.5)


def test_literal_values_and_defaults():
    m = _load('[[wheels]]\nname = "L"\nlink = "w3"\nat = "03"\nheading = -90\n'
              'diameter = "1.2 m"\nwidth = "16 in"\n\n'
              '[[wheels]]\nname = "fixed"\nat = "01"\ndiameter = "900 mm"\nwidth = 0.3\n'
              ).mechanism
    a, b = m.wheels[:2]
    assert a.heading == pytest.approx(-math.pi / 2)          # a plain angle is in degrees
    assert (a.diameter, a.width) == (pytest.approx(1.2), pytest.approx(0.4064))
    assert (b.link, b.heading, b.diameter, b.width) == (None, 0.0, pytest.approx(0.9), 0.3)


@pytest.mark.parametrize("old,new,key,needle,message", [
    ('link = "w3"', 'link = "w9"', "wheels[0].link", 'link = "w9"',
     'unknown link "w9": expected a link of [links] (w3, w5, c2, t4, a5)'),
    ('at = "03"', 'at = "3"', "wheels[0].at", 'at = "3"', 'unknown point "3"'),
    ('diameter = "D_wheel"      # illustrative\n', "", "wheels[0].diameter", "[[wheels]]",
     'missing required key "diameter"'),
    ('diameter = "D_wheel"', 'diameter = "22 deg"', "wheels[0].diameter",
     'diameter = "22 deg"', "expected a length"),
    ('diameter = "D_wheel"', 'diameter = "-1 m"', "wheels[0].diameter", 'diameter = "-1 m"',
     "expected a positive length"),
    ('width = "B"', 'width = "Bw"', "wheels[0].width", 'width = "Bw"',
     'found "Bw", which is not a parameter'),
    ('heading = "0 deg"', 'heading = "0 m"', "wheels[0].heading", 'heading = "0 m"',
     "expected an angle"),
    ('width = "B"', 'width = "B"\ncolour = "red"', "wheels[0].colour", 'colour = "red"',
     'unknown key "colour"'),
])
def test_errors_name_the_key_and_the_line(old, new, key, needle, message):
    text = BASE.replace(LEFT, LEFT.replace(old, new))
    assert text != BASE
    with pytest.raises(ModelFileError) as exc:
        io.loads(text, name="steer.toml")
    e = exc.value
    line = _line(text, needle)
    assert (e.key_path, e.line) == (key, line), str(e)
    assert message in str(e) and str(e).startswith(f"steer.toml:{line}: {key}: "), str(e)


def test_a_parameter_used_by_a_wheel_only_is_used():
    m = io.load(io.bundled("steering_lab4"))
    assert not any("D_wheel" in str(w) for w in m.warnings)


def test_models_without_wheels_have_none():
    for name in ("hitch_003", "loader_lab1", "combine_002"):
        assert io.load(io.bundled(name)).mechanism.wheels == ()
