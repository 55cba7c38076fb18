"""The gear pump (:mod:`assur.dynamics.drive.pump`): its flow is displacement ×
revolutions per second × volumetric efficiency, for any values; bad values are
refused."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assur.dynamics.drive import GearPump
from assur.errors import ModelError
from tests.helpers import examples


@settings(max_examples=examples(50), deadline=None)
@given(st.floats(1e-6, 2e-4), st.floats(10.0, 400.0), st.floats(0.5, 1.0))
def test_flow_is_displacement_times_turns_times_efficiency(displacement, omega, eta):
    pump = GearPump(displacement, omega, eta)
    assert pump.flow() == pytest.approx(displacement * omega / (2 * math.pi) * eta, rel=1e-14)


def test_seed_001_lab_6_pump():
    """НШ-32 at 1800 rpm with η_v = 0.9: 32 cm³ · 30 1/s · 0.9 = 51.84 l/min."""
    pump = GearPump(32e-6, 1800 * 2 * math.pi / 60, 0.9)
    assert pump.flow() * 60e3 == pytest.approx(51.84, rel=1e-12)


@pytest.mark.parametrize("args, match", [((0.0, 100.0), "displacement"),
                                         ((32e-6, -1.0), "speed"),
                                         ((32e-6, 100.0, 1.5), "eta_volumetric")])
def test_bad_pumps_are_refused(args, match):
    with pytest.raises(ModelError, match=match):
        GearPump(*args)
