"""The relief valve (:mod:`assur.dynamics.drive.relief`): its linear regulation
characteristic — no flow up to the setting, the nominal flow at the setting plus the
regulation range, linear between and beyond — and its conductance, the slope."""

import numpy as np
import pytest

from assur.dynamics.drive import ReliefValve
from assur.errors import ModelError


def test_characteristic_and_conductance():
    valve = ReliefValve(setting=16e6, regulation_range=1e6)
    q = 51.84 / 60e3  # lab 6's pump [m³/s]
    p = np.linspace(10e6, 20e6, 101)
    flow = valve.flow(p, q)
    assert (flow[p <= 16e6] == 0).all()
    assert valve.flow(17e6, q) == pytest.approx(q, rel=1e-14)
    above = p > 16e6
    np.testing.assert_allclose(np.diff(flow[above]) / np.diff(p[above]),
                               valve.conductance(q), rtol=1e-9)
    assert valve.conductance(q) == pytest.approx(q / 1e6, rel=1e-14)


def test_its_own_nominal_flow_wins():
    valve = ReliefValve(16e6, 1e6, nominal_flow=1e-3)
    assert valve.flow(17e6, 5e-4) == pytest.approx(1e-3)
    assert valve.conductance(5e-4) == pytest.approx(1e-9)
    with pytest.raises(ModelError, match="regulation_range"):
        ReliefValve(16e6, 0.0)
