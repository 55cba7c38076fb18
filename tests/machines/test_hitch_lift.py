"""The standard lift test of a three-point hitch (ISO 789-2 / SAE J283) on the bundled
seed-003 hitch: six heights of the hitch point evenly spaced over the lift range, the
force available there and on the frame 610 mm behind at 90 % of the relief pressure,
checked against an independent finite-difference virtual-work computation."""

import numpy as np
import pytest

from assur import io
from assur.analysis import add_lift_test
from assur.errors import ModelError
from assur.io import ModelFileError
from assur.machines.hitch_lift import LiftTest, lift_test
from assur.views.report import seed_tables

HITCH = io.bundled("hitch_003").read_text(encoding="utf-8")


@pytest.fixture(scope="module")
def model():
    return io.load(io.bundled("hitch_003"))


@pytest.fixture(scope="module")
def result(model):
    return lift_test(model.mechanism, model.lift_test, (0.42, 0.67))


def test_positions_evenly_spaced_over_the_lift_range(model, result):
    assert len(result.s) == 6
    y = model.mechanism.solve(result.s).y("56")
    np.testing.assert_allclose(y, result.height, rtol=0, atol=1e-12)
    np.testing.assert_allclose(np.diff(result.height), np.diff(result.height)[0], rtol=1e-12)
    assert result.s[0] == pytest.approx(0.42) and result.s[-1] == pytest.approx(0.67)
    # the lowest and highest heights of the hitch point over the cylinder's travel
    dense = model.mechanism.solve(np.linspace(0.42, 0.67, 2001)).y("56")
    assert result.height[0] == pytest.approx(dense.min(), abs=1e-12)
    assert result.height[-1] == pytest.approx(dense.max(), abs=1e-12)


def _by_finite_differences(mech, s, point, force):
    """F·η_m / (dY/dS) with dY/dS by central differences of the positions alone."""
    h = 1e-6
    dy = (mech.solve(s + h).y(point) - mech.solve(s - h).y(point)) / (2 * h)
    return force / dy


def test_forces_by_virtual_work_from_the_positions_alone(model, result):
    p = model.mechanism.params
    pressure = 0.9 * p["Pgc_max"]  # 90 % of 17.5 MPa
    force = p["kgc"] * pressure * np.pi * p["Dgc"] ** 2 / 4 * p["eta"]
    assert result.pressure == pytest.approx(15.75e6)
    assert result.force_cylinder == pytest.approx(force, rel=1e-12)
    np.testing.assert_allclose(result.hitch_force,
                               _by_finite_differences(model.mechanism, result.s, "56", force),
                               rtol=1e-7)
    np.testing.assert_allclose(result.frame_force,
                               _by_finite_differences(model.mechanism, result.s, "F610", force),
                               rtol=1e-7)
    assert result.hitch_minimum == pytest.approx(result.hitch_force.min())
    # 90 % of the seed's G56 at S = Smin (table 4.1 prints 33139 N at full pressure)
    assert result.hitch_force[0] == pytest.approx(0.9 * 33139, rel=1e-4)


def test_frame_point_is_610_mm_behind_square_to_the_mast(model, result):
    kin = model.mechanism.solve(result.s)
    d = np.hypot(kin.x("F610") - kin.x("56"), kin.y("F610") - kin.y("56"))
    np.testing.assert_allclose(d, 0.610, rtol=1e-12)
    sp = model.mechanism.params["Sp"]
    k = model.mechanism.solve([sp])  # the mast is vertical at Sp: the frame point is level
    assert float(k.y("F610")[0]) == pytest.approx(float(k.y("56")[0]), abs=1e-9)
    assert float(k.x("F610")[0]) - float(k.x("56")[0]) == pytest.approx(0.610, abs=1e-9)


def test_table_l_in_the_report(model):
    a = add_lift_test(model.mechanism.analyze(model.range), model.lift_test)
    tab = {t.id: t for t in seed_tables(a)}["L"]
    assert tab.symbols == ["S", "Y56", "G56_test", "GF610_test"]
    assert len(tab) == 6 and np.isfinite(tab["GF610_test"]).all()
    assert any("15.75 MPa" in n["en"] for n in tab.notes)
    assert any("МПа" in n["ru"] for n in tab.notes)


@pytest.mark.parametrize("edit, key", [
    ("positions = 6", "lift_test.positions"),
    ('frame = "F610"', "lift_test.frame"),
    ("pressure_share = 0.9", "lift_test.pressure_share"),
    ('hitch = "56"', "lift_test.hitch"),
])
def test_errors_name_the_key_and_line(edit, key):
    bad = {"positions = 6": "positions = 4", 'frame = "F610"': 'frame = "F611"',
           "pressure_share = 0.9": "pressure_share = 1.5",
           'hitch = "56"': 'hitch = "01"'}[edit]   # a frame point (was an IndexError)
    text = HITCH.replace(edit, bad)
    line = text.splitlines().index(bad) + 1
    with pytest.raises(ModelFileError) as e:
        io.loads(text, name="h.toml")
    assert f"h.toml:{line}" in str(e.value) and key in str(e.value)


def test_a_hitch_point_that_does_not_rise_monotonically_is_an_error():
    # a point on the lever 3 square to it: it passes its top where φ3 = 0 inside the range
    top = ('[[groups]]\ntype = "rigid_point"\nname = "top"\norigin = "03"\ntoward = "23"\n'
           'out = "T"\nlength = "0.2 m"\nangle = 90\nlinks = ["3"]\n\n[links]')
    text = HITCH.replace("[links]", top, 1).replace('hitch = "56"', 'hitch = "T"')
    model = io.loads(text, name="top.toml")
    with pytest.raises(ModelError, match=r"'T' does not rise monotonically with S .*changes "
                                          r"sign near S = 0\.5"):
        lift_test(model.mechanism, model.lift_test, (0.42, 0.67))
    with pytest.raises(ModelError, match="at least 6 positions"):
        LiftTest("56", positions=5)


def test_a_hitch_point_the_cylinder_does_not_move_is_an_error():
    """A point the cylinder does not drive (the lever's pivot 03 as a frame point is
    refused at load; through the API, any point that stands still) is one message,
    not an IndexError."""
    model = io.loads(HITCH, name="h.toml")
    with pytest.raises(ModelError, match="'03' does not move with S"):
        lift_test(model.mechanism, LiftTest("03"), (0.42, 0.67))
