"""Lift capacity helpers (:mod:`assur.machines.capacity`) on seed 001 lab 1's loader of
two cylinders: a cylinder lifts a point exactly where the point's height changes with
that cylinder's length (the analogs say so, independently of the chains); the dead
loads every capacity carries are those on the declared links; the farthest reach is
the position of the largest x."""

import numpy as np
import pytest

from assur import examples
from assur.errors import ModelError
from assur.machines.capacity import check_lifts, dead_load_links, dead_load_mechanism, \
    farthest_reach, lifts


@pytest.fixture(scope="module")
def loader():
    m = examples.loader_lab1()
    return m, m.solve(examples.loader_lab1_range())


def test_a_cylinder_lifts_where_the_height_follows_its_length(loader):
    m, kin = loader
    moving = [p for p in m.points if p not in m.frame_points]
    for c in m.coordinates:
        for p in moving:
            follows = bool(np.abs(kin.dy(p, wrt=c)).max() > 1e-12)
            assert lifts(m, c, p) == follows, (c, p)
    check_lifts(m, "S", "S9")
    with pytest.raises(ModelError):
        check_lifts(m, "S1", "S3", name="MPT")


def test_dead_loads_and_the_farthest_reach(loader):
    m, kin = loader
    links = dead_load_links(m)
    dead = dead_load_mechanism(m)
    assert links and all(ld.link in links for ld in dead.loads)
    assert [ld for ld in m.loads if getattr(ld, "link", None) in links] == list(dead.loads)
    assert dead_load_mechanism(examples.hitch_003()) is None
    i = farthest_reach(kin, "S9")
    assert kin.x("S9")[i] == kin.x("S9").max()
