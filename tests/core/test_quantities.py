"""Quantities and display units of parameters (:mod:`assur.core.quantities`): every
parameter a mechanism uses has the quantity of its use (a length, an angle, a force
…); a model file's parameters are shown in the unit the file wrote them in — the
shown number times the unit's scale is the SI value, and the shown number is the
one in the file — and a mechanism built in Python in the default units."""

import re

import pytest

from assur import examples, io
from assur.core.quantities import DEFAULT_UNITS, Unit, display_units, parameter_quantities, \
    unit_text
from tests.helpers.mechanisms import python_fourbar


def test_quantities_follow_the_use_and_have_default_units():
    q = parameter_quantities(examples.hitch_003())
    assert q["L4"] == "length" and q["phiBD"] == "angle" and q["P6"] == "force"
    assert q["Pgc_max"] == "pressure" and q["kgc"] == "number"
    assert set(q.values()) <= set(DEFAULT_UNITS)


def test_file_units_reproduce_the_written_numbers():
    path = io.bundled("hitch_003")
    written = dict(re.findall(r'^(\w+) = "([-0-9.]+) [^"]+"', path.read_text(encoding="utf-8"),
                              re.M))
    model = io.load(path)
    units = display_units(model.mechanism)
    checked = 0
    for name, number in written.items():
        if name not in model.mechanism.params or name in ("L4", "Sp", "L7"):  # solved
            continue
        u = units[name]
        assert model.mechanism.params[name] / u.scale == pytest.approx(float(number),
                                                                       rel=1e-12), name
        checked += 1
    assert checked >= 25
    assert units["Dgc"] == Unit("mm", 1e-3) and units["P6"].text == "kN"


def test_python_mechanisms_show_default_units_and_units_read_well():
    units = display_units(python_fourbar())
    assert units["r"] == DEFAULT_UNITS["length"] and units["a"] == DEFAULT_UNITS["angle"]
    assert unit_text("kN*m") == "kN·m" and unit_text("m**2") == "m²"
