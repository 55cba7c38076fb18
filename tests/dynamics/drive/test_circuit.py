"""Hydraulic circuits (:mod:`assur.dynamics.drive.circuit`) of the bundled models:
seed 004's crane feeds its boom (raised: the piston side) and its stick (lowered:
the annulus) through a divider, half the pump's flow each; a branch's loss
coefficients are the sums of its parts' (hose and valve); lab 6's circuit has one branch."""

import math

import pytest

from assur import io


@pytest.fixture(scope="module")
def crane():
    return io.load(io.bundled("crane_lv184a")).drive


def test_crane_branches(crane):
    boom, stick = crane.branches
    assert (boom.coordinate, stick.coordinate) == ("S1", "S2")
    assert (boom.sense, stick.sense) == (1, -1)
    assert boom.area == pytest.approx(boom.cylinder.count * math.pi
                                      * boom.cylinder.bore ** 2 / 4, rel=1e-14)
    c = stick.cylinder
    assert stick.area == pytest.approx(c.count * math.pi * (c.bore ** 2 - c.rod ** 2) / 4,
                                       rel=1e-14)
    assert (boom.stop, stick.stop) == (boom.cylinder.s_min, stick.cylinder.s_max)
    Q = crane.pump_flow()
    assert Q * 60e3 == pytest.approx(80.0, rel=1e-9)  # seed 004: Q_h = 80 l/min
    assert boom.flow(Q) + stick.flow(Q) == pytest.approx(Q, rel=1e-14)


def test_branch_losses_are_the_sums_of_its_parts(crane):
    Q = crane.pump_flow()
    for b in crane.branches:
        assert b.valve in b.lines and len(b.lines) >= 2  # the valve and the hose
        parts = [c.loss_coefficients(b.area, b.flow(Q)) for c in b.lines]
        want = [sum(p[i] for p in parts) for i in range(3)]
        assert b.loss_coefficients(Q) == pytest.approx(want, rel=1e-12)


def test_lab_6_has_one_branch():
    drive = io.load(io.bundled("adapter_lab6"), warn=True).drive
    (branch,) = drive.branches
    assert branch.share == 1.0 and branch.flow(drive.pump_flow()) == drive.pump_flow()
