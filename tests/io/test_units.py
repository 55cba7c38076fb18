"""The table of common units (:data:`assur.io._units.COMMON_UNITS`) gives bitwise the
factors and dimensions pint gives, so a file reads the same whether a unit comes from
the table or from pint; and a file with only common units never builds pint's
registry (which costs ~0.2 s of every command's start)."""

import subprocess
import sys

import pytest

from assur.io import _drive, _units
from assur.io._units import ANGLE, COMMON_UNITS, NUMBER, Raw

#: every kind a model file's key can have (the mechanism's and the drive's)
KINDS = {**_units.KINDS, **_drive.KINDS}


def _pint(unit):
    ureg = _units.registry()
    u = ureg.parse_units(_units._normalise(unit))
    q = ureg.Quantity(1.0, u)
    return ureg, u, q


#: products of two non-metric units: pint multiplies their factors in the order of its
#: parsed unit dictionary, which depends on what it parsed before (lbf*ft is 1.35…4006
#: in a fresh process, 1.35…4001 after some other units), so one ulp either way
_ORDER_DEPENDENT = {"lbf*ft", "ft*lbf", "lbf*in", "lb*ft**2", "lb*ft**2/rad"}


def _same_as_pint(table, pint_value, unit):
    if unit in _ORDER_DEPENDENT:
        return abs(table - pint_value) <= 2 * abs(pint_value) * 2.0 ** -52
    return table == pint_value  # bitwise


@pytest.mark.parametrize("unit", sorted(COMMON_UNITS))
def test_table_entry_is_pints(unit):
    ureg, u, q = _pint(unit)
    c = COMMON_UNITS[unit]
    assert _same_as_pint(c.factor, float(q.to_base_units().magnitude), unit)
    dims = q.dimensionality
    assert c.dimension == (dims.get("[length]", 0), dims.get("[mass]", 0),
                           dims.get("[time]", 0))
    assert set(dims) <= {"[length]", "[mass]", "[time]"}
    root = ureg.get_root_units(u)[1]
    assert c.is_angle == (root == ureg.radian)
    assert c.is_number == (root == ureg.dimensionless)
    assert _units._is_degree(unit) == (u == ureg.degree)


@pytest.mark.parametrize("unit", sorted(COMMON_UNITS))
@pytest.mark.parametrize("kind", sorted(KINDS))
def test_table_reads_as_pint(unit, kind):
    """Kind compatibility and the SI value through the table = through pint."""
    kind = KINDS[kind]
    ureg, u, q = _pint(unit)
    root = ureg.get_root_units(u)[1]
    if kind is ANGLE:
        want = root == ureg.radian
    elif kind is NUMBER:
        want = root == ureg.dimensionless
    else:
        want = root != ureg.radian and \
            q.dimensionality == ureg.parse_units(kind.si).dimensionality
    assert _units._compatible_unit(unit, kind) == want
    if want:
        raw = Raw(2.5, unit, f"2.5 {unit}")
        if kind is ANGLE and u == ureg.degree:
            pint_si = _units.math.radians(2.5)
        else:
            pint_si = 2.5 * float(q.to(kind.si or "dimensionless").magnitude)
        assert _same_as_pint(_units.to_si(raw, kind), pint_si, unit)


@pytest.mark.parametrize("text", ["kN * m", "kN*m", " kg*m^2", "kg·m²", "m/s^2", "22°"])
def test_spellings_find_the_table(text):
    unit = text if not text[0].isdigit() else text[2:]
    assert _units.common_unit(unit) is not None


def test_uncommon_units_still_read_by_pint():
    raw = _units.parse("3 yd")
    assert _units.common_unit("yd") is None
    assert _units.to_si(raw, _units.LENGTH) == pytest.approx(2.7432)
    with pytest.raises(_units.UnitError, match="expected a length"):
        _units.to_si(_units.parse("3 kN"), _units.LENGTH)


def test_bundled_models_do_not_build_pints_registry():
    """Every unit the bundled models write is a common one."""
    code = ("import sys\nfrom importlib import resources\nfrom assur import io\n"
            "for f in sorted(resources.files('assur.models').iterdir()):\n"
            "    if f.name.endswith('.toml'):\n"
            "        io.load(io.bundled(f.name[:-5]))\n"
            "print('pint' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "False"
