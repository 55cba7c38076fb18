"""The oil volume (:mod:`assur.dynamics.drive.volume`): the pressure line's oil
lumped at the cylinder, V = V0 + A·(stroke from the stop); lab 6 eq. (2): with the
piston held, the pressure rises at E·Q/V."""

import math

import pytest

from assur.dynamics.drive import OilVolume
from assur.dynamics.drive.volume import BULK_MODULUS
from assur.errors import ModelError


def test_volume_grows_with_the_stroke_and_the_pressure_rate():
    oil = OilVolume(volume=3e-3)
    assert oil.bulk_modulus == BULK_MODULUS == 2e8
    area = math.pi * 0.125 ** 2 / 4
    for stroke in (0.0, 0.1, 0.25):
        assert oil.volume_at(area, stroke) == pytest.approx(3e-3 + area * stroke, rel=1e-14)
    q = 8.64e-4  # the pump's flow [m³/s]
    assert oil.bulk_modulus * q / oil.volume_at(area, 0.0) / 1e6 == pytest.approx(57.6)


def test_bad_volumes_are_refused():
    with pytest.raises(ModelError, match="volume"):
        OilVolume(volume=0.0)
    with pytest.raises(ModelError, match="bulk_modulus"):
        OilVolume(volume=1e-3, bulk_modulus=-1.0)
