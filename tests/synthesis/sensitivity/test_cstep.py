"""The complex step (:mod:`assur.synthesis.sensitivity.cstep`): the ufuncs numpy lacks
for complex numbers (arctan2, hypot, comparisons by the real part) carry exact
derivatives in their imaginary parts, and ``complex_step`` of the seed-003 hitch's
outputs equals central differences of the compiled kernel's outputs."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import examples
from assur.synthesis.sensitivity.cstep import H, CStep, complex_step
from tests.helpers import examples as n_examples


@settings(max_examples=n_examples(100), deadline=None)
@given(st.floats(-3, 3), st.floats(-3, 3))
def test_the_missing_ufuncs_carry_exact_derivatives(x, y):
    r2 = x * x + y * y
    if r2 < 1e-6:
        return
    zy = np.array([y + 1j * H]).view(CStep)  # a step in y
    zx = np.array([x + 1j * H]).view(CStep)  # a step in x
    assert np.arctan2(zy, x).real[0] == pytest.approx(np.arctan2(y, x), abs=1e-15)
    assert np.arctan2(zy, x).imag[0] / H == pytest.approx(x / r2, rel=1e-12, abs=1e-14)
    assert np.arctan2(y, zx).imag[0] / H == pytest.approx(-y / r2, rel=1e-12, abs=1e-14)
    assert np.hypot(zx, y).imag[0] / H == pytest.approx(x / np.sqrt(r2), rel=1e-12,
                                                        abs=1e-14)
    assert bool((zx > y)[0]) == (x > y)
    assert np.maximum(zx, y).real[0] == max(x, y)


def test_complex_step_of_the_kernel_outputs_is_central_differences():
    m = examples.hitch_003()
    S = np.linspace(0.43, 0.66, 5)
    names, outputs = ["L4", "L5", "X01"], ["Y(56)", "dY(56)", "F(S)"]
    j = complex_step(m, S, names, outputs)
    assert j.shape == (5, 3, 3)
    h = 1e-6
    for k, name in enumerate(names):
        p = m.params[name]
        hi = m.with_params(**{name: p + h}).evaluate(S, outputs=outputs)
        lo = m.with_params(**{name: p - h}).evaluate(S, outputs=outputs)
        for i, o in enumerate(outputs):
            fd = (np.asarray(hi[o]) - np.asarray(lo[o])) / (2 * h)
            scale = np.abs(fd).max() + 1e-12
            np.testing.assert_allclose(j[:, i, k], fd, rtol=0, atol=1e-6 * scale)
