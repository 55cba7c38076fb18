"""Numbers as documents print them (:mod:`assur.views.report.numbers`): one count of
decimals per column, never "-0", the decimal comma in Russian, quantities in the
display units."""

import math

import numpy as np
import pytest
from hypothesis import given, strategies as st

from assur.core.display import unit_system
from assur.views.report.numbers import decimals, number, numbers, quantity, value_text


@given(st.lists(st.floats(min_value=-1e12, max_value=1e12, allow_nan=False), min_size=1,
                max_size=20))
def test_a_column_shows_four_significant_digits_of_its_largest_value(values):
    d = decimals(values)
    big = max(abs(v) for v in values)
    texts = [number(v, d) for v in values]
    assert all(not t.startswith("-") or float(t) != 0.0 for t in texts)  # no "-0"
    if d is not None and big >= 1e-6:
        assert len({len(t.split(".")[1]) if "." in t else 0 for t in texts}) == 1
        # the largest magnitude keeps at least four significant digits (0 decimals: all)
        t = number(big, d)
        assert abs(float(t) - big) <= 0.5 * 10 ** -d * (1 + 1e-9)
        assert d == 0 or big < 10 ** (4 - d)


def test_russian_decimal_comma_and_special_values():
    assert number(0.4213, 4, "ru") == "0,4213" and number(1234.5, 1, "ru") == "1234,5"
    assert number(math.nan) == "—" and number(math.inf) == "∞" and number(-math.inf) == "−∞"
    assert number(np.int64(3)) == "3" and number(False, lang="ru") == "нет"
    assert number(-0.0, 2) == "0.00" and number(-1e-9, 3) == "0.000"


@pytest.mark.parametrize("system, want", [("file", "27.5 kN"), ("si", "27500 N"),
                                          ("engineering", "27.5 kN"),
                                          ("imperial", "6182 lbf")])
def test_quantity_in_each_system(system, want):
    from assur import io
    m = io.load(io.bundled("hitch_003")).mechanism
    assert quantity(27500.0, "force", unit_system(m, system)) == want


def test_value_text_converts_a_column_unit():
    eng = unit_system(None, "engineering")
    assert value_text(0.42, "m", eng, "ru") == "420 мм"
    assert value_text(90.0, "deg", eng) == "90°"
    assert value_text(90.0, "deg", unit_system(None, "si")) == "1.571 rad"


@given(st.lists(st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.floats(-1e-3, 1e-3),                      # what rounds to zero, of either sign
    st.sampled_from([0.0, -0.0, -1e-12, 0.5, -0.5, 2.5, -2.5, 1e15, -1e300])),
    max_size=30), st.one_of(st.none(), st.integers(0, 8)), st.sampled_from(["en", "ru"]))
def test_a_column_prints_as_each_of_its_numbers(values, digits, lang):
    """numbers() is number() at once: the same string for every value."""
    a = np.array(values, dtype=float)
    assert numbers(a, digits, lang) == [number(x, digits, lang) for x in values]


def test_columns_of_integers_and_flags_print_as_number_prints_them():
    for a in (np.array([3, -2, 0]), np.array([True, False]), np.array([], dtype=float)):
        for lang in ("en", "ru"):
            assert numbers(a, 2, lang) == [number(x, 2, lang) for x in a.tolist()]
