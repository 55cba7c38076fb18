"""The cylinder–lever input group (:mod:`assur.groups.cylinder_lever`): the lever end
is at the cylinder's length from its base and at the lever's length from the pivot,
on the branch's side — over the seed-003 hitch's stroke, by the kernel."""

import numpy as np

from assur import examples
from assur.groups import CylinderLever


def test_the_lever_end_closes_the_triangle_over_the_stroke():
    m = examples.hitch_003()
    (g,) = [g for g in m.groups if isinstance(g, CylinderLever)]
    S = np.linspace(0.42, 0.67, 26)
    kin = m.solve(S)
    base, pivot, out = kin.point(g.base), kin.point(g.pivot), kin.point(g.out)
    np.testing.assert_allclose(np.hypot(*(out - base).T), S, rtol=0, atol=1e-12)
    np.testing.assert_allclose(np.hypot(*(out - pivot).T), m.params[g.lever], rtol=0,
                               atol=1e-12)
    u, w = pivot - base, out - base
    side = u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]  # > 0: out left of base → pivot
    assert (np.sign(side) == g.branch).all()
    # the cylinder's length is the coordinate: d|out − base|/dS = 1 by the analogs
    d_out = np.stack([kin.dx(g.out), kin.dy(g.out)], -1)
    np.testing.assert_allclose(np.einsum("ij,ij->i", w, d_out) / S, 1.0, rtol=0, atol=1e-12)
    assert g.coordinates_driven() == ("S",) and g.links == ("2", "3")
