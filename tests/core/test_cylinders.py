"""A cylinder's quantities (:mod:`assur.core.cylinders`) from their formulas written
out here: chamber areas (piston, annulus, double rod), the pressure of a force, the
largest force at the working pressure, the lift capacity — at which the pressure is
exactly the working pressure — and the reserve. (The same numbers from every path
that computes them: test_cylinders_one_truth.py.)"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import examples
from assur.core.cylinders import capacity, chamber_area, force_max, piston_area, pressure, \
    reserve, select_array, terms
from tests.helpers import examples as n_examples


@settings(max_examples=n_examples(60), deadline=None)
@given(st.floats(0.02, 0.3), st.floats(0.1, 0.9), st.floats(0.1, 0.9))
def test_chamber_areas(D, r1, r2):
    d, d2 = r1 * D, r2 * D
    assert piston_area(D) == pytest.approx(math.pi * D * D / 4, rel=1e-14)
    assert piston_area(D, d, "rod") == pytest.approx(math.pi * (D * D - d * d) / 4, rel=1e-12)
    assert piston_area(D, rod2=d2) == pytest.approx(math.pi * (D * D - d2 * d2) / 4, rel=1e-12)
    assert chamber_area(D, d, 0.0, "rod") == pytest.approx(piston_area(D, d, "rod"), rel=1e-14)


def test_pressure_force_capacity_and_reserve_of_the_hitch_cylinder():
    m = examples.hitch_003()
    t = terms(m.cylinders[0], m.value_of)
    k, eta_m, eta_h = float(t.count), float(t.eta_mech), float(t.eta_hyd)
    A = math.pi * m.params["Dgc"] ** 2 / 4
    F = np.array([5e3, 4e4, 9e4])  # pushing forces [N]
    p = pressure(t, F, select_array)
    np.testing.assert_allclose(p, F / (eta_m * k * A * eta_h), rtol=1e-14)
    fmax = force_max(t, F, select_array)
    np.testing.assert_allclose(fmax, k * float(t.p_max) * A * eta_h, rtol=1e-14)
    # the capacity at a point of transmission I with a dead load F_dead: loaded with G,
    # the cylinder needs F = F_dead + G·I, and that force needs exactly p_max
    I, F_dead = np.array([0.8, 1.1, 1.6]), np.array([500.0, 0.0, 1200.0])
    G = capacity(t, F, F_dead, I, select_array)
    np.testing.assert_allclose(pressure(t, F_dead + G * I, select_array), float(t.p_max),
                               rtol=1e-12)
    assert reserve(30e3, 25e3) == pytest.approx(20.0) and reserve(20e3, 25e3) == -20.0
