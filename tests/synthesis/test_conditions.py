"""Design solving (Given/Find): seed 003 §2.2–2.3 fixes L4, Sp and L7 by conditions;
the roots are found in dependency order whatever order they are given in, and a
bracket without a root, or with several, is an error that says so."""

import math

import numpy as np
import pytest

from assur import examples
from assur.synthesis.conditions import Condition, DesignError, solve_conditions

SEED_003_CONDITIONS = [
    # φ6(Sp) = 90°  (L7 := Find(L7_0), L7_0 = 0.56)
    Condition("L7", (0.56, 1.05), {"S": "Sp"}, "phi6", math.pi / 2),
    # Y56(Sp) = Y_P56 = 0.4 m  (Sp := Find(Sp), start 0.5·(Smax + Smin))
    Condition("Sp", (0.42, 0.67), {"S": "Sp"}, "Y56", 0.4),
    # Y56(Smin) = 0.2 m  (L4 := Find(L4_0), L4_0 = 0.48)
    Condition("L4", (0.48, 0.9), {"S": 0.42}, "Y56", 0.2),
]


def test_seed_003_find_blocks():
    """The three Find blocks give the printed L4 = 0.6613, Sp = 0.4694, L7 = 0.7522 m,
    and the exact roots the seed's tables were computed with."""
    m = examples.hitch_003(L4=0.6, L7=0.7, Sp=0.5 * (0.67 + 0.42))  # the seed's start values
    m2, solved = solve_conditions(m, SEED_003_CONDITIONS)
    assert [s.condition.unknown for s in solved] == ["L4", "Sp", "L7"]  # dependency order
    p = m2.params
    assert (round(p["L4"], 4), round(p["Sp"], 4), round(p["L7"], 4)) == (0.6613, 0.4694, 0.7522)
    for k, v in examples.HITCH_003_FOUND.items():
        assert p[k] == pytest.approx(v, abs=1e-9)
    for s in solved:
        assert abs(s.residual) < 1e-12
    r = m2.solve([0.42, p["Sp"]])
    assert r.y("56")[0] == pytest.approx(0.2, abs=1e-12)
    assert r.y("56")[1] == pytest.approx(0.4, abs=1e-12)
    assert r.phi("6")[1] == pytest.approx(math.pi / 2, abs=1e-12)


def test_no_root_in_bracket_is_an_error():
    m = examples.hitch_003()
    with pytest.raises(DesignError, match=r"no root for L4 in the bracket \[0\.7, 0\.8\]"):
        solve_conditions(m, [Condition("L4", (0.7, 0.8), {"S": 0.42}, "Y56", 0.2)])


def test_several_roots_are_named():
    """X56 at S = 0.42 passes 1.13 twice as L4 grows (it peaks near L4 ≈ 0.7)."""
    m = examples.hitch_003()
    L4 = np.linspace(0.5, 0.85, 200)
    x = examples.hitch_003(L4=L4).solve([0.42], on_failure="report").x("56")[:, 0]
    target = 0.5 * (x.max() + x[0])
    with pytest.raises(DesignError, match=r"2 roots for L4 in the bracket"):
        solve_conditions(m, [Condition("L4", (0.5, 0.85), {"S": 0.42}, "X56", target)])


def test_unknown_must_be_a_parameter_and_matter():
    m = examples.hitch_003()
    with pytest.raises(DesignError, match="'Lx' is not a parameter"):
        solve_conditions(m, [Condition("Lx", (0.5, 0.8), {"S": 0.42}, "Y56", 0.2)])
    with pytest.raises(DesignError, match="does not depend on 'L7'"):
        solve_conditions(m, [Condition("L7", (0.5, 0.8), {"S": 0.42}, "Y56", 0.2)])
    with pytest.raises(DesignError, match="bracket must be"):
        solve_conditions(m, [Condition("L4", (0.8, 0.5), {"S": 0.42}, "Y56", 0.2)])


def test_circular_conditions_are_refused():
    m = examples.hitch_003()
    conds = [Condition("L4", (0.48, 0.9), {"S": "Sp"}, "Y56", 0.2),
             Condition("Sp", (0.42, 0.67), {"S": 0.5}, "YS6", 0.7)]
    # the first needs Sp (its position), the second L4 (S6 hangs on dyad II's output):
    # solvable only together, not one at a time
    with pytest.raises(DesignError, match="cannot be solved one at a time"):
        solve_conditions(m, conds)


def test_a_failing_condition_speaks_the_files_units():
    """A ``[[solve]]`` written in inches and degrees that cannot be met says so in inches
    and degrees (the bracket, the target, the residual's range), not in m and rad."""
    from assur import io
    from assur.io import ModelFileError

    text = io.bundled("hitch_003").read_text(encoding="utf-8")
    bad = text.replace('bracket = ["0.56 m", "1.05 m"]', 'bracket = ["22 in", "26 in"]') \
        .replace('equals = "90 deg"', 'equals = "120 deg"')
    assert bad.count("22 in") == 1 and bad.count("120 deg") == 1
    with pytest.raises(ModelFileError) as exc:
        io.loads(bad, name="hitch.toml")
    msg = str(exc.value)
    assert "phi6(S = Sp) = 120 deg for L7" in msg
    assert "no root for L7 in the bracket [22 in, 26 in]" in msg
    lo, hi = (float(x) for x in
              __import__("re").search(r"between (\S+) deg and (\S+) deg", msg).groups())
    # φ6 − 120° stays negative over the bracket: φ6 stays below 120° there
    assert -90 < lo < hi < 0
    assert "rad" not in msg and " m]" not in msg
