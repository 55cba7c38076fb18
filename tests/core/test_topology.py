"""Bodies of a mechanism (:mod:`assur.core.topology`), checked against the motion:
over the range every two points of a rigid body keep their distance, and the only
body whose points move apart is the one the topology calls variable (a cylinder,
whose length is the coordinate); every point has one owner among the bodies that
hold it, and every group's links are bodies."""

import itertools

import numpy as np
import pytest

from assur import examples
from assur.core.topology import build_topology


@pytest.mark.parametrize("make, q", [
    (examples.hitch_003, np.linspace(0.42, 0.67, 11)),
    (examples.combine_002, examples.combine_002_range()),
])
def test_rigid_bodies_keep_their_distances_and_the_variable_ones_do_not(make, q):
    m = make()
    topo = m.topology
    assert build_topology(m.name, m.coordinates, m.groups) == topo
    kin = m.solve(q)
    for body, points in topo.bodies.items():
        spans = []
        for a, b in itertools.combinations(points, 2):
            d = np.hypot(*(kin.point(b) - kin.point(a)).T)
            spans.append(np.ptp(d))
        rigid = all(s <= 1e-9 for s in spans)
        assert rigid == (body not in topo.variable), (body, spans)


def test_owners_and_group_links():
    m = examples.hitch_003()
    topo = m.topology
    assert topo.variable == frozenset({"2"})  # the cylinder 01–23
    assert topo.bodies["0"] == ("01", "03", "05", "07")  # the frame holds the pivots
    for point, owner in topo.owner.items():
        assert point in topo.bodies[owner]
    held = {p for pts in topo.bodies.values() for p in pts}
    assert held == set(topo.owner) == set(m.points)
    for group, links in topo.group_links.items():
        assert set(links) <= set(topo.bodies), group
