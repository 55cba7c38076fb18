"""The verdicts of seed 004's cycle report (:mod:`assur.views.report.cycles`): each of
the paper's conclusions is judged from the sweep's numbers — changing the numbers, or
the claim, changes the verdict; the pump's verdicts rest on the drive's own speeds."""

import numpy as np
import pytest

from assur import io
from assur.dynamics.cycles import sweep


@pytest.fixture(scope="module")
def lv184a_sweep():
    from assur.dynamics.cycles import strokes
    model = io.load(io.bundled("crane_lv184a"))
    return sweep(model.mechanism, *strokes(model.drive))



def test_verdicts_follow_the_numbers(lv184a_sweep):
    """Each verdict is computed from the sweep: claim 1's excess is the ratio of the
    max forces at 6 s; changing the numbers (or the claim) changes the verdict."""
    from assur.views.report.cycles import ABOUT, conclusions
    df = lv184a_sweep
    v = {x.key: x for x in conclusions(df)}
    at6 = df[df["T"] == 6.0].set_index("scenario")
    for j, key in ((1, "boom_excess"), (2, "stick_excess")):
        ex = at6.loc["separate_second", f"F{j}_max"] / at6.loc["combined_equal", f"F{j}_max"] - 1
        assert v[key].numbers["excess"]["separate_second"] == pytest.approx(ex, rel=1e-12)
        target = v[key].numbers["target"]
        assert v[key].agrees == any(abs(e - target) <= ABOUT * target
                                    for e in v[key].numbers["excess"].values())
    assert v["boom_excess"].agrees and not v["stick_excess"].agrees  # +79 %, +13 %
    assert v["dynamic_fall"].agrees and v["dynamic_fall"].numbers["spread"] < 1e-9
    # the stick's force of separate motion 15 % higher: +30 % as the paper says
    changed = df.copy()
    sep = changed["scenario"] == "separate_second"
    changed.loc[sep, "F2_max"] *= 1.15
    assert {x.key: x for x in conclusions(changed)}["stick_excess"].agrees
    # a claim of +50 % for the boom is not what the model gives
    paper = {"period": 6.0, "excess": (0.5, 0.3), "dynamic": (3.0, 8.0),
             "effective_below": 9.0}
    v2 = {x.key: x for x in conclusions(df, paper=paper)}
    assert not v2["boom_excess"].agrees
    assert v2["effective_below"].agrees == (abs(v["effective_below"].numbers["T_star"] - 9.0)
                                            <= 1.0)



def test_pump_verdicts_follow_the_drives_speeds():
    """The paper's conclusion 3: the standard pump with the divider (V = Q/(2f))
    against the whole flow to one cylinder at a time (V = Q/f). The cycles run at the
    drive's speeds, and the verdicts rest on their forces' ratios."""
    from assur.dynamics.cycles import drive_cycles
    from assur.views.report.cycles import drive_sweep, pump_conclusions
    model = io.load(io.bundled("crane_lv184a"))
    cs = drive_cycles(model.drive)
    Q = model.drive.pump_flow()
    speeds = [Q / (2 * b.area) for b in model.drive.branches]
    np.testing.assert_allclose(np.abs(cs["divider"].qdot[0]), speeds, rtol=1e-12)
    assert np.count_nonzero(cs["pump_first"].qdot[0]) == 1
    assert abs(cs["pump_first"].qdot[0, 0]) == pytest.approx(2 * speeds[0], rel=1e-12)
    dd = drive_sweep(model)
    v = {x.key: x for x in pump_conclusions(dd)}
    d = dd.set_index("scenario")
    r = d.loc["pump_second", "F1_max"] / d.loc["divider", "F1_max"]
    assert v["pump_forces"].numbers["ratios"]["pump_second"][0] == pytest.approx(r, rel=1e-12)
    assert v["pump_forces"].agrees == any(all(1.16 <= round(x, 2) <= 2.0 for x in rs)
                                          for rs in v["pump_forces"].numbers["ratios"].values())
    # a claimed fall of 10 times is not what the model gives
    paper = {"pump_forces": (1.16, 2.0), "pump_dynamic": 10.0}
    assert not {x.key: x for x in pump_conclusions(dd, paper=paper)}["pump_dynamic"].agrees

