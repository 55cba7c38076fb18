"""Actuator forces by virtual work (:mod:`assur.core.virtual_work`): a weight P at a
point asks of the cylinder F = P·dY/dS (its power balance, the transmission number),
forces and moments add up, and a spring's tension follows its length."""

import numpy as np
import pytest

from assur import examples
from assur.core.virtual_work import applied_loads, spring_states, virtual_work_forces


def test_a_weight_asks_its_transmission_times_itself():
    m = examples.hitch_003()
    S = np.linspace(0.42, 0.67, 6)
    base = m.solve(S)
    one = m.with_loads([]).weight("56", 1000.0).solve(S)
    F = virtual_work_forces(one)["S"]
    np.testing.assert_allclose(F.ravel(), 1000.0 * base.dy("56"), rtol=1e-12)
    both = m.with_loads([]).weight("56", 1000.0).force("67", 200.0, -50.0).solve(S)
    extra = 200.0 * base.dx("67") - 50.0 * base.dy("67")
    np.testing.assert_allclose(virtual_work_forces(both)["S"].ravel(),
                               1000.0 * base.dy("56") - extra, rtol=1e-12)
    forces, moments, *_ = applied_loads(one)
    assert forces == [("5", "56", 0.0, pytest.approx(-1000.0))] and moments == []


def test_spring_tension_follows_its_length():
    m = examples.hitch_003().with_loads([]).spring("k", "01", "56", 1e4, 0.5, 100.0)
    kin = m.solve(np.linspace(0.42, 0.67, 4))
    length, tension = spring_states(kin)["k"][:2]
    L = np.hypot(*(kin.point("56") - kin.point("01")).T)
    np.testing.assert_allclose(np.ravel(length), L, rtol=1e-12)
    np.testing.assert_allclose(np.ravel(tension), 100.0 + 1e4 * (L - 0.5), rtol=1e-12)
