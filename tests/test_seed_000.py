"""Seed 000 (``000_04e80bfff5466283.txt``), combine header lift.

Its input cannot assemble: the bell-crank triangle L3 = 0.17194, L34 = 0.4804,
L4 = 0.657 m cannot close (L4 > L3 + L34 = 0.65234 m), so DELFI = acos(1.0199) is
complex — the source of every ``…i`` in its tables. The engine must say exactly
that, name the group and links, and give the first failing position, instead of
returning complex numbers or NaN.
"""

import re

import numpy as np
import pytest

from assur import AssemblyError, examples

from seed_tables import T000_DFI3, T000_FI3, assert_printed


def test_header_000_raises_the_triangle_error():
    m = examples.header_000()
    with pytest.raises(AssemblyError) as exc:
        m.solve(examples.header_000_range())
    err = exc.value
    msg = str(err)
    # the three sides with their values, the violated inequality and by how much
    assert "L3 = 0.17194" in msg and "L34 = 0.4804" in msg and "L4 = 0.657" in msg
    assert re.search(r"L4 exceeds L3 \+ L34 = 0\.65234 m by 4\.66 mm", msg), msg
    # the group, its link and the first failing position
    assert "arm 46" in msg and "links 3" in msg
    assert "S = 0.65" in msg and "16 of 16 positions fail" in msg
    assert err.group == "arm 46" and err.links == ("3",)
    assert err.coordinate == {"S": pytest.approx(0.65)}
    assert err.amount == pytest.approx(0.657 - 0.65234, abs=1e-12)


def test_header_000_report_mode_has_no_nan_and_flags_everything():
    r = examples.header_000().solve(examples.header_000_range(), on_failure="report")
    assert not r.ok.any()
    assert r.failures and "cannot close" in r.failures[0]
    assert np.all(np.isfinite(r.x("56"))) and np.all(np.isreal(r.x("56")))


def test_header_000_cylinder_lever_matches_the_seed_where_it_is_real():
    """FI3 and DFI3 do not depend on the broken triangle: they are real in the seed
    (Табл. 1, Табл. 4) and the engine reproduces them (corrected geometry L4 = 0.652 m,
    which leaves the lever untouched)."""
    r = examples.header_000(L4=0.652).solve(examples.header_000_range())
    assert_printed(r.phi("3", degrees=True), T000_FI3, "FI3")
    assert_printed(r.dphi("3")[:6], T000_DFI3, "DFI3")


def test_header_000_intermediate_seed_constants():
    """L0 = 0.651, L2 = 0.839, T1 = 13.054°, T2 = 73.811° (seed 000 §2.2)."""
    p = examples.header_000().params
    L0 = np.hypot(p["X01"] - p["X03"], p["Y01"] - p["Y03"])
    L2 = np.hypot(p["X03"] - p["X05"], p["Y03"] - p["Y05"])
    T1 = np.degrees(np.arctan((p["X01"] - p["X03"]) / (p["Y03"] - p["Y01"])))
    T2 = 90 - np.degrees(np.arctan((p["X05"] - p["X03"]) / (p["Y03"] - p["Y05"])))
    assert round(L0, 3) == 0.651 and round(L2, 3) == 0.839
    assert round(T1, 3) == 13.054 and round(T2, 3) == 73.811
    # the seed's DELFI argument: (L3² + L4² − L34²)/(2·L3·L4) = 1.0199 > 1
    arg = (p["L3"] ** 2 + p["L4"] ** 2 - p["L34"] ** 2) / (2 * p["L3"] * p["L4"])
    assert round(arg, 4) == 1.0199
