"""Branch-free selects (:mod:`assur.kernel.select`): lines with nested conditional
expressions, rewritten with ``_sel``, compute what they computed — in Python with
``_sel`` as the conditional it replaces, and compiled with numba's intrinsic, which
also discards the unused operand's inf or NaN, bit for bit."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assur.kernel.select import branchless
from tests.helpers import examples

ATOMS = ["x", "y", "1.0", "-2.5", "(x * y)", "(x - y)"]


@st.composite
def expressions(draw, depth=3):
    if depth == 0 or draw(st.booleans()):
        return draw(st.sampled_from(ATOMS))
    a, b = draw(expressions(depth=depth - 1)), draw(expressions(depth=depth - 1))
    kind = draw(st.sampled_from(["if", "+", "*"]))
    if kind == "if":
        test = draw(st.sampled_from(["x > y", "(x < 0.5) & (y > -1.0)", "x == y"]))
        return f"({a} if {test} else {b})"
    return f"({a} {kind} {b})"


@settings(max_examples=examples(200), deadline=None)
@given(expressions(), st.floats(-3, 3), st.floats(-3, 3))
def test_rewritten_lines_compute_the_same(expr, x, y):
    line = f"    v = {expr}"
    out = branchless(line)
    assert out.startswith("    v = ") and (" if " in line) == ("_sel(" in out)
    assert " if " not in out
    ns = {"x": x, "y": y}
    exec(line.strip(), ns)
    want = ns["v"]
    ns = {"x": x, "y": y, "_sel": lambda c, a, b: a if c else b}
    exec(out.strip(), ns)
    assert ns["v"] == want


def test_the_intrinsic_selects_without_a_branch():
    from numba import njit

    from assur.kernel.select import sel

    @njit(error_model="numpy")  # as the generated kernels: 1/0 is inf, sqrt(−1) NaN
    def guarded(r):
        return sel(r > 0.0, 1.0 / r, 0.0), sel(r >= 0.0, math.sqrt(r), -1.0)

    for r in (2.0, 0.0, -4.0):
        inv, root = guarded(r)
        assert inv == (1.0 / r if r > 0.0 else 0.0)
        assert root == (math.sqrt(r) if r >= 0.0 else -1.0)
    assert guarded(float("nan")) == (0.0, -1.0)  # the selected operands, not the NaNs
    assert branchless("    # a comment if any else") == "    # a comment if any else"
    with pytest.raises(AttributeError):
        import assur.kernel.select as S
        S.nothing_here
