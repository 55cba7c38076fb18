"""Frame points (:mod:`assur.groups.frame`): at fixed coordinates, or in polar form
``origin + length·(cos, sin)(angle)`` — seed 002's O3 — whose parameters may differ
per design and which stays where it is over the range."""

import math

import numpy as np
import pytest

from assur import examples
from assur.errors import ModelError
from assur.groups import Frame


def test_polar_frame_point_of_seed_002_per_design():
    m = examples.combine_002()
    g = m.group("O3")
    assert (g.origin, g.length, g.angle) == ("O1", "l10", "j10")
    l10 = m.params["l10"]
    j10 = np.array([m.params["j10"], m.params["j10"] + 0.1])
    kin = m.solve(np.tile(examples.combine_002_range(), (2, 1)), params={"j10": j10})
    O1, O3 = kin.point("O1"), kin.point("O3")  # (designs, positions, 2)
    want = O1 + l10 * np.stack([np.cos(j10), np.sin(j10)], -1)[:, None, :]
    np.testing.assert_allclose(O3, want, rtol=0, atol=1e-12)
    assert np.ptp(O3, axis=1).max() == 0.0  # a frame point does not move


def test_cartesian_frame_points_and_errors():
    pts = {}
    Frame("01", x=0.415, y=0.563).evaluate(pts, float)
    Frame("P", origin="01", length=2.0, angle=math.pi / 6).evaluate(pts, float)
    assert pts["01"] == (0.415, 0.563)
    assert pts["P"][0] == pytest.approx(0.415 + math.sqrt(3)) and \
        pts["P"][1] == pytest.approx(1.563)
    with pytest.raises(ModelError):
        examples.hitch_003().frame("Z", 0.0)  # no y
