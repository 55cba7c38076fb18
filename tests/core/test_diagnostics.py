"""Messages of assembly failures (:mod:`assur.core.diagnostics`): what a failure
message says — the group, its links, the position and coordinate, the violated
inequality and by how much — agrees with the geometry computed independently (the
plain-numpy position formulas), one message per failed element; coordinates are
written in their own units (a crank angle in degrees)."""

import math

import numpy as np
import pytest

from assur import examples
from assur.core.diagnostics import assembly_error, coordinate_text, describe_failures, \
    failure_message
from assur.core.program import execute
from assur.errors import AssemblyError


@pytest.fixture(scope="module")
def failing():
    """The hitch with a brace L4 = 0.95 m: its dyad III cannot close at the lowest
    strokes. Returns the mechanism, the positions and the kernel's raw result."""
    m = examples.hitch_003(L4=0.95)
    prog = m.program()
    ptab, trig, _ = m.prepared(prog)
    q = np.array([[0.42, 0.43, 0.67]])
    return m, prog, ptab, q, execute(prog, ptab, q, 3, trig=trig)


def test_the_amount_is_the_gap_of_the_geometry(failing):
    m, prog, ptab, q, res = failing
    msg, amount, group = failure_message(m, prog, ptab, q, res["status"], res["amount"], 3, 0)
    # the outer joints of dyad III from the position formulas, independently of the kernel
    with np.errstate(invalid="ignore"):  # the dyad's own joint: NaN (it cannot close)
        pts = m.evaluate_positions({"S": np.array([0.42])}, {})
    (ax, ay), (bx, by) = pts[group.a], pts[group.b]
    gap = math.hypot(float(np.squeeze(bx)) - float(np.squeeze(ax)),
                     float(np.squeeze(by)) - float(np.squeeze(ay)))
    reach = m.params[group.ra] + m.params[group.rb]
    assert amount == pytest.approx(gap - reach, rel=1e-9)
    assert f"{gap:.5f} m exceeds" in msg and f"by {1e3 * (gap - reach):.1f} mm" in msg
    assert group.name in msg and "links 6, 7" in msg and "(S = 0.42)" in msg


def test_one_message_per_failed_element_and_the_error_of_the_first(failing):
    m, prog, ptab, q, res = failing
    failed = np.flatnonzero(res["status"] >= 0).tolist()
    assert failed == [0, 1]  # S = 0.67 assembles
    texts = describe_failures(m, prog, ptab, q, res["status"], res["amount"], 3)
    assert [f"position {i} (S = {q[0, i]:g})" in t for i, t in zip(failed, texts)] == [True] * 2
    assert describe_failures(m, prog, ptab, q, res["status"], res["amount"], 3, limit=1) \
        == texts[:1]
    err = assembly_error(m, prog, ptab, q, res["status"], res["amount"], 3, res["status"] < 0)
    assert isinstance(err, AssemblyError) and str(err).startswith(texts[0])
    assert err.position == 0 and err.coordinate == {"S": 0.42}


def test_coordinates_in_their_units():
    assert coordinate_text(examples.hitch_003(), "S", 0.4200000001) == "S = 0.42"
    # seed 002's crank: degrees, continuous (not wrapped)
    assert coordinate_text(examples.combine_002(), "j1", math.radians(374.679)) == \
        "j1 = 374.679°"
