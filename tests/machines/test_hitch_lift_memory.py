"""The memory guard of the lift test (:func:`assur.machines.hitch_lift.lift_test`,
issue 27): ``[lift_test] positions`` estimated (kinematics and statics at every
position) and refused before the positions are allocated; a normal test still runs."""

from __future__ import annotations

import pytest

from assur import io
from assur.errors import ModelError
from assur.machines.hitch_lift import LiftTest, check_lift_memory, lift_test
from tests.helpers.memory import allocates_little, assert_refusal


@pytest.fixture(scope="module")
def model():
    return io.load(io.bundled("hitch_003"))


def test_many_positions_are_refused_before_the_heights(model, monkeypatch):
    test = LiftTest("56", "F610", positions=100_000)
    lift_test(model.mechanism, LiftTest("56"), (0.42, 0.67))  # compiled beforehand
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "1 MiB")
    # 1e5 positions × 2480 B: 237 MiB of analysis without the guard
    with allocates_little(), pytest.raises(ModelError) as e:
        lift_test(model.mechanism, test, (0.42, 0.67))
    assert_refusal(str(e.value), "[lift_test] positions")
    assert "lift test of 'hitch_003': positions = 100000: 1e+05 positions" in str(e.value)


def test_a_billion_positions_under_the_default_limit(model, monkeypatch):
    monkeypatch.delenv("ASSUR_MAX_MEMORY", raising=False)
    with allocates_little(), pytest.raises(ModelError, match=r"\[lift_test\] positions"):
        check_lift_memory(model.mechanism, 10**9)


def test_a_normal_lift_test_still_runs(model, monkeypatch):
    monkeypatch.setenv("ASSUR_MAX_MEMORY", "64 MiB")
    r = lift_test(model.mechanism, model.lift_test, (0.42, 0.67))
    assert len(r.s) == 6
