"""The drawing as data (:mod:`assur.views.geometry`): the points of every position are
the kinematics' points, bodies and frame follow the topology, the bounds hold every
point, a pose is one position; the convex hull of any set of points holds them all
and turns counter-clockwise."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import examples
from assur.views.geometry import convex_hull, geometry, pose
from tests.helpers import examples as n_examples


def test_points_bodies_and_bounds_are_the_mechanisms():
    m = examples.hitch_003()
    S = np.linspace(0.42, 0.67, 4)
    kin = m.solve(S)
    g = geometry(kin)
    assert g["n"] == 4 and g["q"] == {"S": pytest.approx(S.tolist())}
    for p in m.points:
        np.testing.assert_allclose(g["points"][p], kin.point(p), rtol=0, atol=1e-12)
    assert {b["name"]: tuple(b["points"]) for b in g["bodies"]} == dict(m.topology.bodies)
    assert sorted(g["frame"]) == sorted(m.frame_points)
    xs = np.array([v for pts in g["points"].values() for v in pts])
    x0, y0, x1, y1 = g["bounds"]
    assert x0 <= xs[:, 0].min() and xs[:, 0].max() <= x1
    assert y0 <= xs[:, 1].min() and xs[:, 1].max() <= y1
    assert pose(g, 2)["56"] == pytest.approx(kin.point("56")[2].tolist())
    with pytest.raises(ValueError, match=r"position must be in 0…3"):
        pose(g, 4)


@settings(max_examples=n_examples(100), deadline=None)
@given(st.lists(st.tuples(st.integers(-20, 20), st.integers(-20, 20)), min_size=1,
                max_size=30))
def test_the_hull_holds_every_point_and_turns_counter_clockwise(pts):
    hull = [tuple(map(float, p)) for p in convex_hull([tuple(map(float, p)) for p in pts])]
    assert set(hull) <= {tuple(map(float, p)) for p in pts}
    if len(hull) < 3:
        return
    for i in range(len(hull)):
        (ax, ay), (bx, by) = hull[i], hull[(i + 1) % len(hull)]
        for px, py in pts:  # every point on the left of (or on) each edge
            assert (bx - ax) * (py - ay) - (by - ay) * (px - ax) >= 0
