"""Drive cylinders (:mod:`assur.dynamics.drive.cylinder`): the piston and annulus
areas of identical cylinders in parallel against πD²/4 and π(D² − d²)/4, and the
dimensions a cylinder refuses."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assur.dynamics.drive import DriveCylinder
from assur.errors import ModelError
from tests.helpers import examples


@settings(max_examples=examples(50), deadline=None)
@given(st.floats(0.02, 0.3), st.floats(0.05, 0.95), st.integers(1, 4))
def test_areas_of_cylinders_in_parallel(bore, rod_share, count):
    rod = bore * rod_share
    cyl = DriveCylinder("S", bore=bore, rod=rod, s_min=0.5, s_max=0.9, count=count)
    assert cyl.piston_area == pytest.approx(math.pi * bore ** 2 / 4, rel=1e-14)
    assert cyl.rod_side_area == pytest.approx(math.pi * (bore ** 2 - rod ** 2) / 4, rel=1e-12)
    assert cyl.area == pytest.approx(count * cyl.piston_area, rel=1e-14)


def test_seed_001_lab_6_cylinder():
    """Lab 6: D = 125 mm, its piston 122.7 cm²."""
    cyl = DriveCylinder("S", bore=0.125, rod=0.05, s_min=0.55, s_max=0.8)
    assert round(cyl.piston_area * 1e4, 1) == 122.7


@pytest.mark.parametrize("kw, match", [(dict(bore=0.05, rod=0.125), "rod"),
                                       (dict(bore=0.0, rod=0.0), "bore"),
                                       (dict(s_min=0.9, s_max=0.5), "s_max")])
def test_impossible_cylinders_are_refused(kw, match):
    args = dict(bore=0.1, rod=0.05, s_min=0.5, s_max=0.9) | kw
    with pytest.raises(ModelError, match=match):
        DriveCylinder("S", **args)
