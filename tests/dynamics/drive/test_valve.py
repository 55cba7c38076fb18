"""The directional valve (:mod:`assur.dynamics.drive.valve`): its position sets the
sense of the motion, and its loss Δp = Δp_nom·(Q/Q_nom)² referred to the rod's speed
(Q = A·v) gives the quadratic coefficient a3 = Δp_nom·(A/Q_nom)²."""

import pytest

from assur.dynamics.drive import DirectionalValve
from assur.dynamics.drive.valve import POSITIONS
from assur.errors import ModelError


def test_positions_and_their_sense():
    assert POSITIONS == ("raise", "lower")
    assert [DirectionalValve(p).sense for p in POSITIONS] == [1, -1]
    with pytest.raises(ModelError, match="position must be one of"):
        DirectionalValve("hold")


@pytest.mark.parametrize("area, v", [(0.0123, 0.07), (0.005, 0.2)])
def test_the_quadratic_loss_at_the_rods_speed(area, v):
    valve = DirectionalValve("raise", dp_nominal=0.3e6, nominal_flow=1e-3)
    a1, a2, a3 = valve.loss_coefficients(area, None)
    assert (a1, a2) == (0.0, 0.0)
    dp = 0.3e6 * (area * v / 1e-3) ** 2  # the valve's loss at the flow A·v
    assert a3 * v ** 2 == pytest.approx(dp, rel=1e-12)
