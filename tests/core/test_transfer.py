"""Transfer ratios and real-time quantities (:mod:`assur.core.transfer`) from the
analogs, against their definitions: U_ij = φ_i'/φ_j', its derivative the quotient
rule's, v = r'·q̇, a = r''·q̇² + r'·q̈, ω = φ'·q̇, ε = φ''·q̇² + φ'·q̈."""

import numpy as np

from assur import examples


def test_real_time_quantities_and_ratios_by_their_definitions():
    m = examples.hitch_003()
    S = np.linspace(0.47, 0.66, 6)
    kin = m.solve(S)
    qd, qdd = 0.05, -0.2  # rod speed [m/s] and acceleration [m/s²]
    for p in ("56", "S6", "67"):
        r1 = np.stack([kin.dx(p), kin.dy(p)], -1)
        r2 = np.stack([kin.ddx(p), kin.ddy(p)], -1)
        np.testing.assert_allclose(kin.velocity(p, qd), r1 * qd, rtol=1e-14)
        np.testing.assert_allclose(kin.acceleration(p, qd, qdd), r2 * qd ** 2 + r1 * qdd,
                                   rtol=1e-12, atol=1e-15)
    for link in ("5", "6"):
        np.testing.assert_allclose(kin.angular_velocity(link, qd), kin.dphi(link) * qd,
                                   rtol=1e-14)
        np.testing.assert_allclose(kin.angular_acceleration(link, qd, qdd),
                                   kin.ddphi(link) * qd ** 2 + kin.dphi(link) * qdd,
                                   rtol=1e-12, atol=1e-15)
    d5, d3, dd5, dd3 = kin.dphi("5"), kin.dphi("3"), kin.ddphi("5"), kin.ddphi("3")
    np.testing.assert_allclose(kin.ratio("5", "3"), d5 / d3, rtol=1e-14)
    np.testing.assert_allclose(kin.dratio("5", "3"), (dd5 * d3 - d5 * dd3) / d3 ** 2,
                               rtol=1e-10)
