"""The reverse-order pass (:mod:`assur.core.reverse_pass`) on the seed-003 hitch with
its implement's weight: the whole machine is in equilibrium — the frame's reactions,
the cylinder's base and the weight sum to zero force and moment — and the force of
link i on link j is minus that of j on i."""

import numpy as np

from assur import examples
from assur.core.reverse_pass import reverse_pass


def test_the_frame_holds_the_weight():
    m = examples.hitch_003()
    kin = m.solve(np.linspace(0.42, 0.67, 6))
    forces, joints, actuators, residual = reverse_pass(kin)
    P6 = m.params["P6"]
    S6 = kin.point("S6")
    fx = fy = mo = 0.0
    for (i, j), (pt, rx, ry, rm) in joints.items():
        if i == "0":  # the frame's force on a moving link
            x, y = kin.point(pt)[:, 0], kin.point(pt)[:, 1]
            fx, fy = fx + rx[0], fy + ry[0]
            mo = mo + x * ry[0] - y * rx[0] + rm[0]
    np.testing.assert_allclose(fx, 0.0, atol=1e-7 * P6)
    np.testing.assert_allclose(fy, P6, rtol=1e-10)
    np.testing.assert_allclose(mo, P6 * S6[:, 0], rtol=1e-10)
    for (i, j), (pt, rx, ry, rm) in joints.items():
        if (j, i) in joints:
            np.testing.assert_array_equal(joints[(j, i)][1], -rx)
    assert residual()[0].max() < 1e-6 * P6
