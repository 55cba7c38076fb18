"""Balancing a crank mechanism by counter-masses (:mod:`assur.dynamics.balancing`;
seed 001 lab 3): the bundled example's centre-of-mass amplitudes drop (stated below),
the mechanism re-solved with the counter-masses has the predicted path, the area
objective and the bounds hold. On the bundled ``cleaning_lab3.toml``
(tests/dynamics/conftest.py)."""

from __future__ import annotations

import numpy as np
import pytest

from assur.dynamics.balancing import CounterMass, balance, common_centre, shoelace
from assur.dynamics.crank import with_masses
from assur.errors import ModelError


def test_balancing_reduces_the_example_amplitudes(example):
    """Counter-masses ≤ 30 kg on the rocker 3 and ≤ 20 kg on the crank 1, within
    ±0.3 m and ±0.1 m of their pivots: A_x from 3.95 mm to ≤ 0.5 mm and A_y from
    3.74 mm to ≤ 1.5 mm (the rest of A_y is the hangers' second harmonic, which no
    mass on the crank or the rocker can cancel)."""
    model, kin = example
    cms = [CounterMass("3", (0.0, 30.0), (-0.3, 0.3), (-0.1, 0.1)),
           CounterMass("1", (0.0, 20.0), (-0.1, 0.1), (-0.1, 0.1))]
    b = balance(kin, cms, objective="amplitudes", seed=1)
    assert b.success, b.message
    assert b.before.amplitude_x > 3.5e-3 and b.before.amplitude_y > 3.3e-3
    assert b.after.amplitude_x <= 0.5e-3
    assert b.after.amplitude_y <= 1.5e-3
    assert b.value == pytest.approx(b.after.amplitude_x + b.after.amplitude_y)
    # the mechanism with the counter-masses has the predicted centre-of-mass path
    kin2 = with_masses(model.mechanism, b.masses).solve(model.range)
    c2 = common_centre(kin2)
    assert np.allclose(c2.x, b.after.x, rtol=0, atol=1e-12)
    assert np.allclose(c2.y, b.after.y, rtol=0, atol=1e-12)



def test_balancing_by_area_and_bounds(example):
    _, kin = example
    b = balance(kin, [CounterMass("3", (0.0, 30.0), (-0.3, 0.3), (-0.1, 0.1))],
                objective="area", seed=0)
    assert abs(b.after.area) < 0.05 * abs(b.before.area)
    assert abs(b.after.area) == pytest.approx(abs(shoelace(b.after.x, b.after.y)))
    (cm,) = b.masses
    assert 0 <= cm.m <= 30 and -0.3 <= cm.along <= 0.3 and -0.1 <= cm.offset <= 0.1
    with pytest.raises(ValueError, match="objective must be one of"):
        balance(kin, [CounterMass("3", (0.0, 1.0))], objective="volume")
    with pytest.raises(ModelError, match="unknown or fixed link"):
        balance(kin, [CounterMass("42", (0.0, 1.0))])

