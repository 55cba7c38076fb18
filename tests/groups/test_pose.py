"""Pose points (:mod:`assur.groups.pose`): seed 003's implement centre of mass S6 is at
its offset (X6, Y6) from the suspension axis 56 at the pose S = Sp, and turns with
the implement 56 → 67 everywhere else (distance and angle to the link kept)."""

import numpy as np

from assur import examples


def test_offset_at_the_pose_and_rigid_with_the_link():
    m = examples.hitch_003()
    g = m.group("centre of mass S6")
    Sp = float(m.params["Sp"])
    S = np.concatenate([[Sp], np.linspace(0.42, 0.67, 9)])
    kin = m.solve(S)
    o, t, p = kin.point(g.origin), kin.point(g.toward), kin.point(g.out)
    np.testing.assert_allclose(p[0] - o[0], [m.params[g.dx], m.params[g.dy]], rtol=0,
                               atol=1e-12)
    r = p - o
    np.testing.assert_allclose(np.hypot(*r.T), np.hypot(m.params[g.dx], m.params[g.dy]),
                               rtol=0, atol=1e-12)
    link = t - o
    cross = link[:, 0] * r[:, 1] - link[:, 1] * r[:, 0]
    turn = np.arctan2(cross, np.einsum("ij,ij->i", link, r))
    np.testing.assert_allclose(turn, turn[0], rtol=0, atol=1e-12)
