"""The flow divider (:mod:`assur.dynamics.drive.divider`): seed 004's flow-divider
speeds (eqs. 63–68) at the paper's printed precision, and its printed f2 a digit swap."""

from __future__ import annotations

import math

import numpy as np
import pytest

from assur.dynamics.drive import FlowDivider


# seed 004 (004_4ff0af19c30e8a3a.txt), text after eq. (66) and (68): Q_h = 80 l/min,
# written 1,33·10⁻³ m³/s (the paper computes with this rounded value); the piston areas
# f1 (boom), f2 (stick) and the stick's rod-side area f2m [m²]
Q_H = 1.33e-3



CRANES = {
    # crane: (f1, f2, f2m), divider V1, V2, (V2 rod side); separate V1, V2, (V2 rod side)
    "ЛВ-184А": ((7.85e-3, 5.024e-3, 3.062e-3), (0.085, 0.13, 0.22), (0.17, 0.26, 0.43)),
    # f2 = 12.666e-3 printed: a digit swap of 12.266e-3 (bore 125 mm, BRIEF.md)
    "ЛВ-185/215": ((15.7e-3, 12.266e-3, 9.15e-3), (0.042, 0.054, 0.072), (0.085, 0.11, 0.15)),
}



def _printed(value, printed):
    """|value − printed| within half a unit of the printed last digit."""
    digits = len(f"{printed}".split(".")[1])
    return abs(value - printed) <= 0.5 * 10 ** -digits + 1e-12



@pytest.mark.parametrize("crane", list(CRANES))
def test_seed004_flow_divider_speeds(crane):
    """Eqs. (63)–(66): a divider feeding both cylinders equal flows (V1/V2 = f2/f1,
    Q = V1·f1 + V2·f2) gives V1 = Q/(2f1), V2 = Q/(2f2); eqs. (67)–(68): separate
    motion, the whole flow to one cylinder, V = Q/f."""
    (f1, f2, f2m), combined, separate = CRANES[crane]
    div = FlowDivider((0.5, 0.5))
    V1, V2 = div.speeds(Q_H, (f1, f2))
    assert V1 / V2 == pytest.approx(f2 / f1, rel=1e-12)  # (63)
    assert V1 * f1 + V2 * f2 == pytest.approx(Q_H, rel=1e-12)  # (64)
    V2m = div.speeds(Q_H, (f1, f2m))[1]
    got = (V1, V2, V2m)
    for g, p, what in zip(got, combined, ("V1", "V2", "V2 rod side")):
        if crane == "ЛВ-185/215" and what == "V2 rod side":
            # printed 0.072; Q/(2·f2m) = 0.0727 reads 0.073: the paper's last digit is
            # one low (truncated) — reported, not matched
            assert abs(g - p) < 1e-3 and not _printed(g, p)
            continue
        assert _printed(g, p), f"{crane} combined {what}: {g:.4f} vs printed {p}"
    for g, p, what in zip((Q_H / f1, Q_H / f2, Q_H / f2m), separate, ("V1", "V2", "V2m")):
        assert _printed(g, p), f"{crane} separate {what}: {g:.4f} vs printed {p}"



def test_seed004_printed_f2_is_a_digit_swap():
    """With the printed f2 = 12.666e-3 m² the combined V2 would read 0.053, not the
    paper's 0.054; 12.266e-3 m² is π·0.125²/4 = 12.27e-3 m² (bore 125 mm)."""
    V2_printed_f2 = Q_H / (2 * 12.666e-3)
    assert not _printed(V2_printed_f2, 0.054)
    assert math.pi * 0.125 ** 2 / 4 == pytest.approx(12.266e-3, rel=1e-3)
    assert np.isclose(FlowDivider((0.5, 0.5)).speeds(Q_H, (15.7e-3, 12.266e-3))[1], 0.0542,
                      atol=1e-4)

