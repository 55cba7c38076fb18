"""Emitted element code (:mod:`assur.kernel.emit`): the unit vector of a turning rigid
link, with its first and second analogs, as the emitted lines compute it, equals the
closed form (u = (cos, sin)(θ + β), u' = R90·u, u'' = −u) for any link and turn; a
coincident pair of points records the group's failure code, and an earlier failure
is kept; the jets' names follow one scheme."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assur.kernel.emit import CODES_PER_OP, FAIL_COINCIDENT, Emitter, d, dd, emit_unit, \
    emit_zero_jets, pt
from tests.helpers import examples


def run(E, **values):
    ns = {"math": math, "st": -1, **values}
    exec("\n".join(line.strip() for line in E.lines), ns)
    return ns


def turning_link(px, py, ell, theta):
    """Points 0 = P (fixed) and 1 = Q = P + ℓ(cos θ, sin θ) with their jets in θ."""
    c, s = math.cos(theta), math.sin(theta)
    return {"x0": px, "y0": py, "x1": px + ell * c, "y1": py + ell * s,
            d("x0", 0): 0.0, d("y0", 0): 0.0, d("x1", 0): -ell * s, d("y1", 0): ell * c,
            dd("x0", 0, 0): 0.0, dd("y0", 0, 0): 0.0,
            dd("x1", 0, 0): -ell * c, dd("y1", 0, 0): -ell * s}


@settings(max_examples=examples(100), deadline=None)
@given(st.floats(-2, 2), st.floats(-2, 2), st.floats(0.01, 3.0),
       st.floats(-math.pi, math.pi), st.floats(-math.pi, math.pi))
def test_the_unit_of_a_turning_link_and_its_analogs(px, py, ell, theta, beta):
    E = Emitter(1)
    emit_unit(E, 3, 0, 1, f"{math.cos(beta)!r}", f"{math.sin(beta)!r}")
    ns = run(E, **turning_link(px, py, ell, theta))
    c, s = math.cos(theta + beta), math.sin(theta + beta)
    want = {"u3x": c, "u3y": s, d("u3x", 0): -s, d("u3y", 0): c,
            dd("u3x", 0, 0): -c, dd("u3y", 0, 0): -s}
    for name, value in want.items():
        assert ns[name] == pytest.approx(value, abs=1e-12), name
    assert ns["st"] == -1


def test_coincident_points_fail_with_the_groups_code_and_the_first_failure_stays():
    E = Emitter(1)
    emit_unit(E, 3, 0, 1, "1.0", "0.0")
    values = turning_link(0.5, 0.5, 0.0, 0.0)
    assert run(E, **values)["st"] == 3 * CODES_PER_OP + FAIL_COINCIDENT
    ns = {"math": math, "st": 7, **values}  # an earlier group failed already
    exec("\n".join(line.strip() for line in E.lines), ns)
    assert ns["st"] == 7


def test_names_of_values_and_jets():
    assert pt(4) == ("x4", "y4")
    assert d("x4", 1) == "x4_1" and dd("x4", 1, 0) == dd("x4", 0, 1)
    E = Emitter(2)
    emit_zero_jets(E, "v")
    ns = run(E)
    assert {k: ns[k] for k in (d("v", 0), d("v", 1), dd("v", 0, 1), dd("v", 1, 1))} == \
        dict.fromkeys((d("v", 0), d("v", 1), dd("v", 0, 1), dd("v", 1, 1)), 0.0)
