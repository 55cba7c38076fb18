"""Equations of motion from the exact analogs (:mod:`assur.dynamics.eom`) on random
mechanisms (the hypothesis builders of tests.helpers.analogs / tests.helpers.statics)
with random masses on every moving link:

1. ∂M/∂q (from the second analogs) against fourth-order central differences of M
   (from the first analogs) at neighbouring positions;
2. inverse dynamics M·q̈ + h − Q against the d'Alembert route of
   :func:`assur.core.statics.virtual_work_forces` (inertia forces −m·a_S, moments −J·ε
   of every link from a = J·q̈ + q̇ᵀ·H·q̇: no mass matrix involved);
3. the kinetic-energy identity dT/dt = q̇ᵀ·(M·q̈ + h) with dT/dt by central
   differences of T = ½·q̇ᵀ·M·q̇ along q(t) = q0 + q̇·t + ½·q̈·t², and the
   skew property q̇ᵀ·h = ½·q̇ᵀ·Ṁ·q̇;
4. forward dynamics inverts inverse dynamics;
5. k = 1: M and dM/dq are :func:`assur.dynamics.crank.reduced_inertia`'s J_red, J_red'.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import event, given
from hypothesis import strategies as st

from assur import io
from assur.core import statics
from assur.dynamics import equations_of_motion
from assur.errors import ModelError
from assur.dynamics.crank import reduced_inertia
from tests.helpers.analogs import SETTINGS, _floats, analogs, fd_steps
from tests.helpers.statics import crank_family, cylinder_lever_family, cylinder_radius_family, \
    draw_rates, prepare, slider_family

FAMILIES = {"cylinder-lever": cylinder_lever_family, "crank": crank_family,
            "slider": slider_family, "k = 2": cylinder_radius_family}
#: relative tolerance of the exact quantities against each other (routes 2, 4, 5)
RTOL_EXACT = 1e-9
#: relative tolerance against finite differences (routes 1, 3)
RTOL_FD = 1e-6
#: absolute floor [N, W, m/s²] where a drawn motion moves next to no mass (masses of
#: 1–100 kg on links of ~1 m: rounding is ~1e-13 there)
ABS_FLOOR = 1e-9


def with_random_masses(data, case):
    """The case's mechanism with a mass (m ∈ [1, 100] kg, J ∈ [0.01, 5] kg·m²) on every
    moving body, its centre at one of the body's points."""
    mech = case.mech
    for body, pts in sorted(mech.topology.bodies.items()):
        if body == "0" or not pts:
            continue
        p = data.draw(st.sampled_from(sorted(pts)), label=f"centre of {body}")
        m = data.draw(_floats(1.0, 100.0), label=f"m{body}")
        J = data.draw(_floats(0.01, 5.0), label=f"J{body}")
        mech = mech.mass(body, m, p, J)
    return mech


def solve(mech, case, Q):
    return mech.solve(case.api_q(Q), on_failure="report", check_continuity=False)


def shaped(case, a, tail):
    return np.asarray(a).reshape(case.Q.shape[:2] + np.shape(a)[np.ndim(a) - tail:])


def full(case, eom):
    """(M (M, n, k, k), dM (M, n, k, k, k), Q (M, n, k)) whatever k."""
    return (shaped(case, eom.mass_matrix, 2), shaped(case, eom.mass_matrix_derivative, 3),
            shaped(case, eom.generalized_forces if case.k > 1
                   else eom.generalized_forces[..., None], 1))


def rates(case, x):
    """(M, n, k) → the API's shape (k = 1: no trailing axis)."""
    return case.api_q(x)


def check_eom(case, data):
    mech = with_random_masses(data, case)
    kin = solve(mech, case, case.Q)
    assert kin.ok.all()
    g = data.draw(_floats(0.0, 10.0), label="g")
    eom = equations_of_motion(kin, g=g)
    M, dM, Q = full(case, eom)
    scale_M = np.abs(M).max(axis=(-2, -1), keepdims=True)

    # 1. dM/dq against 4th-order central differences of M, with steps h and h/2 (at
    # q ± h/2, q ± h, q ± 2h): their disagreement bounds the differences' own error —
    # truncation, or the rounding of M divided by a small step near a dead point, where
    # ∂M/∂q is 1e4 times M/q's scale and the differences agree with it to ~1e-8 only
    h = fd_steps(case, analogs(case, kin))  # (M, n, k)
    k = case.k
    for l in range(k):
        e = np.zeros(k)
        e[l] = 1.0
        Ms = {}
        for s in (-2, -1, -0.5, 0.5, 1, 2):
            r = solve(mech, case, case.Q + s * h[..., l:l + 1] * e)
            if not r.ok.all():
                event("a shifted position does not assemble: checks 1-5 skipped")
                return
            Ms[s] = full(case, equations_of_motion(r, g=g))[0]
        hl = h[..., l, None, None]
        fd_h = (8 * (Ms[1] - Ms[-1]) - (Ms[2] - Ms[-2])) / (12 * hl)
        fd = (8 * (Ms[0.5] - Ms[-0.5]) - (Ms[1] - Ms[-1])) / (6 * hl)
        own = np.abs(fd_h - fd)
        sc = scale_M / np.minimum(case.scale[:, None, l, None, None], 1.0)
        err = np.abs(dM[..., l] - fd)
        assert (err <= RTOL_FD * sc + 1e-9 * np.abs(fd) + 4.0 * own).all(), (
            f"dM/dq{l}: worst {float((err / sc).max()):.3g} relative, the differences' "
            f"own error {float((own / sc).max()):.3g}")

    qd, qdd = draw_rates(data, case)
    # 2. inverse dynamics against the d'Alembert route of statics
    F = shaped(case, eom.actuator_forces(rates(case, qd), rates(case, qdd)), 1 if k > 1 else 0)
    F = F if k > 1 else F[..., None]
    vw = statics.virtual_work_forces(kin, rates(case, qd), rates(case, qdd), g=g)
    F_ref = np.stack([shaped(case, vw[c], 0) for c in mech.coordinates], -1)
    sc = (np.abs(np.einsum("mnij,mnj->mni", M, qdd)).max() + np.abs(Q).max()
          + np.abs(np.einsum("mnijl,mnj,mnl->mni", dM, qd, qd)).max())
    assert np.abs(F - F_ref).max() <= RTOL_EXACT * sc + ABS_FLOOR

    # 4. forward dynamics inverts it
    try:
        acc = eom.accelerations(rates(case, qd), rates(case, F))
    except ModelError:  # only where M is singular indeed
        assert np.linalg.cond(M).max() > 1e10
        return
    acc = shaped(case, acc, 1 if k > 1 else 0)
    acc = acc if k > 1 else acc[..., None]
    hq = np.einsum("mnijl,mnj,mnl->mni", dM, qd, qd)
    parts = [np.linalg.solve(M, x[..., None])[..., 0] for x in (hq, Q)]
    asc = max(np.abs(qdd).max(), *(np.abs(x).max() for x in parts))
    assert np.abs(acc - qdd).max() <= 1e-7 * asc + ABS_FLOOR

    # 3. kinetic-energy identity along q(t) = q0 + q̇t + ½q̈t²
    hv = shaped(case, eom.velocity_terms(rates(case, qd)), 1 if k > 1 else 0)
    hv = hv if k > 1 else hv[..., None]
    Mdot = np.einsum("mnijl,mnl->mnij", dM, qd)
    assert np.allclose(np.einsum("mni,mni->mn", qd, hv),
                       0.5 * np.einsum("mni,mnij,mnj->mn", qd, Mdot, qd),
                       rtol=0, atol=RTOL_EXACT * (np.abs(Mdot).max() * np.abs(qd).max() ** 2))
    dt = 1e-4 * np.min(case.scale[:, None, :] / np.maximum(np.abs(qd), 1e-300)
                       * np.minimum(1.0, h / (1e-4 * case.scale[:, None, :])), axis=-1)
    T = {}
    for s in (-2, -1, 1, 2):
        t = s * dt[..., None]
        qs = case.Q + qd * t + 0.5 * qdd * t ** 2
        vs = qd + qdd * t
        r = solve(mech, case, qs)
        if not r.ok.all():
            event("a position along q(t) does not assemble: checks 3, 5 skipped")
            return
        T[s] = shaped(case, equations_of_motion(r, g=g).kinetic_energy(rates(case, vs)), 0)
    dTdt = (8 * (T[1] - T[-1]) - (T[2] - T[-2])) / (12 * dt)
    power = np.einsum("mni,mni->mn", qd, np.einsum("mnij,mnj->mni", M, qdd) + hv)
    psc = np.abs(np.einsum("mni,mnij,mnj->mni", qd, M, qdd)).max() + np.abs(
        np.einsum("mni,mni->mn", qd, hv)).max()
    assert np.abs(dTdt - power).max() <= RTOL_FD * psc + ABS_FLOOR

    event("all checks")
    # 5. k = 1: the reduced inertia of assur.dynamics.crank
    if k == 1:
        Jr, dJr = reduced_inertia(kin)
        m, dm = eom.reduced_mass()
        assert np.allclose(shaped(case, m, 0), Jr, rtol=RTOL_EXACT, atol=0)
        assert np.allclose(shaped(case, dm, 0), dJr, rtol=0,
                           atol=RTOL_EXACT * np.abs(dJr).max())


@pytest.mark.parametrize("family", list(FAMILIES))
@SETTINGS
@given(data=st.data())
def test_equations_of_motion_on_random_mechanisms(family, data):
    check_eom(prepare(FAMILIES[family](data)), data)


def test_lab3_cleaning_mechanism_reduced_inertia():
    """The bundled lab-3 crank machine: M = J_red, ∂M/∂φ = J_red' (assur.dynamics.crank),
    and h = ½·J_red'·ω² at ω = −30 rad/s."""
    model = io.load(io.bundled("cleaning_lab3"))
    kin = model.mechanism.solve(model.range)
    eom = equations_of_motion(kin)
    Jr, dJr = reduced_inertia(kin)
    m, dm = eom.reduced_mass()
    np.testing.assert_allclose(m, Jr.reshape(m.shape), rtol=1e-12)
    np.testing.assert_allclose(dm, dJr.reshape(dm.shape), rtol=0, atol=1e-12 * abs(dJr).max())
    np.testing.assert_allclose(eom.velocity_terms(-30.0), 0.5 * dm * 900.0, rtol=0,
                               atol=1e-12 * 900 * abs(dJr).max())


def test_no_masses_is_an_error():
    model = io.load(io.bundled("hitch_003"))
    kin = model.mechanism.solve(model.range)
    with pytest.raises(ModelError, match="no masses"):
        equations_of_motion(kin)
