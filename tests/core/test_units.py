"""The table of units (:mod:`assur.core.units`): reading and showing use the same
factors (bitwise pint's: tests/io/test_units.py compares every entry)."""

from assur.core.units import COMMON_UNITS, common_unit


def test_lookup_normalises_what_a_user_writes():
    assert common_unit("kN·m") is common_unit("kN*m") is common_unit("kN * m")
    assert common_unit("kg·m²") is COMMON_UNITS["kg*m**2"]
    assert common_unit("m^-2") is COMMON_UNITS["m**-2"]
    assert common_unit("furlong") is None


def test_imperial_units_are_there():
    for u in ("in", "ft", "lbf", "psi", "lbf*ft", "lb", "gal/min", "hp"):
        assert u in COMMON_UNITS, u
    assert COMMON_UNITS["in"].factor == 0.0254 and COMMON_UNITS["in"].dimension == (1, 0, 0)
