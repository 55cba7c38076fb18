"""The reverse pass's context (:mod:`assur.core.reactions`): loads applied to a body
sum to its wrench about the origin — ΣF and Σ(x·Fy − y·Fx) + ΣM, computed here from
the solved points — whatever the points, forces and couples; a point's owner is the
body the topology says."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import examples
from assur.core.statics import ReactionContext
from tests.helpers import examples as n_examples

HITCH = examples.hitch_003()
KIN = HITCH.solve(np.array([0.42, 0.55, 0.67]))
POINTS = sorted(HITCH.topology.bodies["6"])  # the implement's points


@settings(max_examples=n_examples(60), deadline=None)
@given(st.lists(st.tuples(st.sampled_from(POINTS), st.floats(-1e4, 1e4),
                          st.floats(-1e4, 1e4)), min_size=1, max_size=5),
       st.floats(-500, 500))
def test_the_wrench_is_the_sum_of_the_loads_about_the_origin(loads, M):
    r = ReactionContext(KIN, set())
    fx = fy = mo = 0.0
    for p, x, y in loads:
        r.apply("6", p, x, y)
        P = KIN.point(p)
        fx, fy = fx + x, fy + y
        mo = mo + P[:, 0] * y - P[:, 1] * x
    r.apply_moment("6", M)
    Wx, Wy, Wm = (np.asarray(w, float).reshape(-1) for w in r.wrench("6"))
    scale = 1.0 + sum(abs(x) + abs(y) for _, x, y in loads)
    np.testing.assert_allclose(Wx, fx, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(Wy, fy, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(Wm, mo + M, rtol=0, atol=1e-11 * (scale + abs(M)))


def test_owners_are_the_topologys():
    r = ReactionContext(KIN, set())
    for point, body in HITCH.topology.owner.items():
        assert r.owner(point) == body
    assert r.is_coord("S") and not r.is_coord("L4")
    with pytest.raises(Exception):
        r.owner("nowhere")
