"""Dual numbers (:mod:`assur.synthesis.sensitivity.dual`): random expressions of two
variables — arithmetic and the numpy functions the group and load code uses — give
on duals the value the expression gives on numbers and the derivatives the complex
step gives (:class:`~assur.synthesis.sensitivity.cstep.CStep`, exact to rounding,
another implementation); ``where`` takes value and derivatives from the chosen
side; nested duals (a dual of duals) carry the mixed second derivative."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from assur.synthesis.sensitivity.cstep import CStep
from assur.synthesis.sensitivity.dual import Dual, base, variables, where
from tests.helpers import examples

OPS = [lambda a, b: a + b, lambda a, b: a - b, lambda a, b: a * b,
       lambda a, b: a / (b * b + 1.5), lambda a, b: np.hypot(a, b * b + 1.0),
       lambda a, b: np.arctan2(a, b * b + 0.5), lambda a, b: np.sin(a) * np.cos(b),
       lambda a, b: np.sqrt(a * a + 0.3), lambda a, b: np.exp(0.2 * np.sin(a)) - b]
H = 1e-30


def run(program, x, y):
    vals = [x, y]
    for op, i, j in program:
        vals.append(OPS[op](vals[i % len(vals)], vals[j % len(vals)]))
    return vals[-1]


programs = st.lists(st.tuples(st.integers(0, len(OPS) - 1), st.integers(0, 9),
                              st.integers(0, 9)), min_size=1, max_size=6)


@settings(max_examples=examples(200), deadline=None)
@given(programs, st.floats(-2, 2), st.floats(-2, 2))
def test_derivatives_are_those_of_the_complex_step(program, x0, y0):
    x, y = variables([np.array([x0]), np.array([y0])])
    out = run(program, x, y)
    if not isinstance(out, Dual):
        out = Dual(np.asarray(out, float), np.zeros(np.shape(out) + (2,)))
    value = run(program, np.array([x0]), np.array([y0]))
    np.testing.assert_allclose(out.val, value, rtol=1e-13, atol=1e-13)
    for k in range(2):
        zx = np.array([x0 + (1j * H if k == 0 else 0)]).view(CStep)
        zy = np.array([y0 + (1j * H if k == 1 else 0)]).view(CStep)
        ref = np.asarray(run(program, zx, zy)).imag / H
        np.testing.assert_allclose(out.der[..., k], ref, rtol=1e-10,
                                   atol=1e-10 * (1 + np.abs(ref).max()))


def test_where_takes_both_parts_from_the_chosen_side():
    x, = variables([np.array([-2.0, 3.0])])
    y = where(x.val > 0, x * x, -x)
    assert y.val.tolist() == [2.0, 9.0] and y.der[:, 0].tolist() == [-1.0, 6.0]


def test_a_dual_of_duals_carries_the_mixed_second_derivative():
    """f = sin(x)·y² + hypot(x, y): ∂²f/∂x∂y = 2y·cos(x) − x·y/r³."""
    x0, y0 = 0.7, -1.3
    x = Dual(Dual(np.array([x0]), np.array([[1.0]])),        # in x …
             Dual(np.zeros((1, 1)), np.zeros((1, 1, 1))))    # … and (constant) in y
    y = Dual(Dual(np.array([y0]), np.array([[0.0]])),
             Dual(np.ones((1, 1)), np.zeros((1, 1, 1))))
    f = np.sin(x) * y * y + np.hypot(x, y)
    r = np.hypot(x0, y0)
    assert np.isclose(f.der.der[0, 0, 0], 2 * y0 * np.cos(x0) - x0 * y0 / r ** 3, rtol=1e-12)
    assert np.isclose(base(f)[0], np.sin(x0) * y0 ** 2 + r, rtol=1e-14)
