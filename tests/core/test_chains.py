"""Which coordinate moves what (:mod:`assur.core.chains`): with one coordinate every
moving point and link is moved by it and the frame by none; with two (the bundled
loader of seed 001 lab 1: tests/seeds/test_loader_lab1.py) each chain by its own."""

import pytest


def test_chains_of_one_coordinate_machines():
    """With one coordinate every moving point is moved by it and the frame by none —
    nothing is left out of the seed machines' tables (hitch 003, combine 002)."""
    from assur import examples
    from assur.core.chains import link_coordinates, point_coordinates
    for mech in (examples.hitch_003(), examples.combine_002()):
        (c,) = mech.coordinates
        for p in mech.points:
            want = frozenset() if p in mech.frame_points else {c}
            assert point_coordinates(mech, p) == want, (mech.name, p)
        for l in mech.links:
            assert link_coordinates(mech, l.name) == {c}
    with pytest.raises(KeyError, match="no point 'nowhere'"):
        point_coordinates(examples.hitch_003(), "nowhere")

