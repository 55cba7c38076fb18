"""Named measures (:mod:`assur.groups.measures`): a link's angle is the direction of
its tail → head, continuous over the range; a distance is |a – b| and, with an
angle, its direction — on seed 002's six-bar over a whole turn."""

import numpy as np

from assur import examples


def test_link_angles_and_distances_over_a_turn():
    m = examples.combine_002()
    kin = m.solve(examples.combine_002_turn_range())
    for link in m.links:
        d = kin.point(link.head) - kin.point(link.tail)
        phi = kin.phi(link.name)
        np.testing.assert_allclose(np.cos(phi), d[:, 0] / np.hypot(*d.T), rtol=0, atol=1e-12)
        np.testing.assert_allclose(np.sin(phi), d[:, 1] / np.hypot(*d.T), rtol=0, atol=1e-12)
        assert np.abs(np.diff(phi)).max() < np.pi  # continuous (unwrapped)
    assert m.distances
    for dist in m.distances:
        d = kin.point(dist.b) - kin.point(dist.a)
        np.testing.assert_allclose(kin.length(dist.name), np.hypot(*d.T), rtol=0, atol=1e-12)
        if dist.angle:
            assert dist.angle in [link.name for link in m.links]
