"""The display units (:mod:`assur.core.display`): one unit per kind of quantity in each
system, conversions exact to pint's factors, the ``file`` system following the units
a model file writes its values in (its parameters and its other values), and the
parameters shown in the system's units."""

import math

import numpy as np
import pytest
from hypothesis import given, strategies as st

from assur import io
from assur.core.display import (KINDS, SYSTEMS, DisplayUnits, check_system, factor, kind_of,
                                parameter_units, unit_system)
from assur.core.units import COMMON_UNITS


def _pint_factor(text):
    from assur.io import _units
    ureg = _units.registry()
    q = ureg.Quantity(1.0, ureg.parse_units(_units._normalise(text)))
    return float(q.to_base_units().magnitude)


@pytest.mark.parametrize("system", ["si", "engineering", "imperial"])
def test_every_kind_has_a_unit_of_its_dimension(system):
    """Each kind's unit in each fixed system converts with pint's factor and has the
    dimension of the kind's SI unit (a unit table that mixed up kinds would fail)."""
    du = unit_system(None, system)
    for kind, k in KINDS.items():
        u = du[kind]
        assert u.text == getattr(k, system)
        if u.text in ("-", "%"):
            continue
        # pint's own last digit of a product of two imperial units depends on its
        # parse order (tests/io/test_units.py)
        assert u.scale == pytest.approx(_pint_factor(u.text), rel=1e-15), (kind, u.text)
        assert kind_of(u.text) == kind or kind_of(k.si) == kind


def test_the_systems_hold_what_the_issue_names():
    eng, imp, si = (unit_system(None, s) for s in ("engineering", "imperial", "si"))
    assert [eng[k].text for k in ("length", "angle", "force", "pressure", "moment", "flow",
                                  "mass")] == ["mm", "deg", "kN", "MPa", "kN·m", "l/min", "kg"]
    assert [imp[k].text for k in ("length", "angle", "force", "pressure", "moment", "flow",
                                  "mass")] == ["in", "deg", "lbf", "psi", "lbf·ft", "gal/min",
                                               "lb"]
    assert [si[k].text for k in ("length", "angle", "force", "pressure")] == \
        ["m", "rad", "N", "Pa"]


@given(st.floats(min_value=-1e9, max_value=1e9, allow_nan=False),
       st.sampled_from(sorted(KINDS)), st.sampled_from(["si", "engineering", "imperial"]))
def test_convert_round_trips(x, kind, system):
    """SI → a system's unit → SI gives the value back (to rounding)."""
    du = unit_system(None, system)
    shown, text = unit_system(None, "si").convert(x, KINDS[kind].si)
    v, t = du.convert(shown, text)
    assert t == du[kind].text
    back = float(v) * du[kind].scale / factor(KINDS[kind].si)
    assert back == pytest.approx(x, rel=1e-12, abs=1e-300)


def test_a_unit_of_no_kind_is_left_as_it_is():
    du = unit_system(None, "imperial")
    assert du.convert([1.0, 2.0], "furlong") == ([1.0, 2.0], "furlong")
    assert du.convert([1.0, 2.0], "furlong/s") == ([1.0, 2.0], "furlong/s")
    assert kind_of("furlong") is None and kind_of("kN") == "force" and kind_of("J") == "energy"


def test_a_ratio_of_two_kinds_takes_the_systems_units_of_its_parts():
    """A pressure per time (a simulation's dp/dt) or a mass per length (m'), which have
    no kind of their own: each part in the system's unit of its kind, with pint's
    factors."""
    import pint
    ureg = pint.UnitRegistry()
    du = unit_system(None, "imperial")
    v, u = du.convert(np.array([1.0, 2.0]), "MPa/s")
    assert u == "psi/s"
    np.testing.assert_allclose(v, [(1.0 * ureg("MPa/s")).to("psi/s").magnitude,
                                   (2.0 * ureg("MPa/s")).to("psi/s").magnitude], rtol=1e-12)
    v, u = unit_system(None, "engineering").convert(3000.0, "kg/m")
    assert (float(v), u) == (3.0, "kg/mm")


def test_file_system_follows_the_model_file():
    """hitch_003.toml: lengths in m (most), P6 in kN, Pgc_max in MPa; moments derived
    kN·m. adapter_lab6.toml writes its relief pressure and flow in the drive ([[drive]]:
    MPa, l/min) — values that are not parameters count too."""
    hitch = io.load(io.bundled("hitch_003")).mechanism
    u = unit_system(hitch)
    assert [u[k].text for k in ("length", "force", "pressure", "moment", "angle")] == \
        ["m", "kN", "MPa", "kN·m", "deg"]
    adapter = unit_system(io.load(io.bundled("adapter_lab6")).mechanism)
    assert adapter["pressure"].text == "MPa" and adapter["flow"].text == "l/min"
    assert adapter["length"].text == "mm" and adapter["angle_per_length"].text == "rad/mm"


def test_display_section_of_a_model_file(tmp_path):
    text = io.bundled("hitch_003").read_text(encoding="utf-8")
    text = text.replace("[model]", '[display]\nunits = "imperial"\nlang = "ru"\n\n[model]', 1)
    m = io.loads(text, "hitch.toml").mechanism
    assert m.display["units"] == "imperial" and m.display["lang"] == "ru"
    assert unit_system(m).system == "imperial"
    assert unit_system(m, "si").system == "si"  # a command's --units wins
    bad = text.replace('units = "imperial"', 'units = "metric"')
    with pytest.raises(io.ModelFileError, match="display.units"):
        io.loads(bad, "hitch.toml")


def test_parameters_in_the_system_units():
    m = io.load(io.bundled("hitch_003")).mechanism
    file_ = parameter_units(m, unit_system(m, "file"))
    imp = parameter_units(m, unit_system(m, "imperial"))
    assert (file_["P6"].text, file_["Dgc"].text, file_["phiBD"].text) == ("kN", "mm", "deg")
    assert (imp["P6"].text, imp["Dgc"].text, imp["Smin"].text) == ("lbf", "in", "in")
    assert imp["eta"].text == "-"  # a plain number stays one


def test_check_system():
    assert [check_system(s) for s in SYSTEMS] == list(SYSTEMS)
    with pytest.raises(ValueError, match="file, engineering, si, imperial"):
        check_system("cgs")


def test_every_shown_unit_is_in_the_table():
    """The factors come from one table (bitwise pint's, tests/io/test_units.py)."""
    for k in KINDS.values():
        for text in (k.si, k.engineering, k.imperial):
            if text not in ("-", "%"):
                assert factor(text) == COMMON_UNITS[
                    text.replace("·", "*").replace("²", "**2").replace("³", "**3")].factor


def test_display_units_is_plain_data():
    du = unit_system(None, "engineering")
    assert isinstance(du, DisplayUnits) and du.system == "engineering"
    assert math.isclose(du.value(np.pi, "angle"), 180.0)
