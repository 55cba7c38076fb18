"""The static tipping load against the moments about the near axle by hand."""

import numpy as np
import pytest

from assur import examples
from assur.errors import ModelError
from assur.machines.ratings import machine_of, tipping_load


def test_the_tipping_load_balances_the_moments_about_the_near_axle():
    m = examples.loader_lab1()
    q = examples.loader_lab1_range()
    kin = m.solve(q)
    mach = machine_of(m)
    x = kin.x("S9").ravel()
    axles = np.array(list(mach.axles.values()))
    near = axles[np.argmin(np.abs(x[:, None] - axles[None, :]), axis=1)]
    fixed = mach.weights + mach.counterweights
    W = tipping_load(m, kin, "S9")
    hand = sum(P * (xi - near) for _, P, xi in fixed) / (near - x)
    unloads = (x - near) * (near - axles.mean()) > 0     # beyond the near axle
    assert unloads.any()
    np.testing.assert_allclose(W[unloads], hand[unloads], rtol=1e-9)
    assert np.isinf(W[~unloads]).all()


def test_a_tipping_load_needs_a_machine():
    m = examples.steering_lab4()
    with pytest.raises(ModelError, match=r"\[machine\]"):
        tipping_load(m, m.solve([0.51]), m.points[0])
