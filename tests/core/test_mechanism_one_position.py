"""One position at a time (as dynamics and the page call it) gives what the array
path gives: ``Mechanism.analyze`` of single positions — after
:data:`assur.core.statics.FUSED_AFTER` calls through the fused statics kernel (static
loads; with a rod's [motion] the array pass with inertia loads), with the
cylinders' constants and the stability machine made once per mechanism — equals the
analysis of all the positions at once with the array pass of the statics, for the
kinematics, every joint reaction, the actuator forces by both routes, every
cylinder's force, pressure and largest force, and the axle reactions, shares and
implement limits."""

from __future__ import annotations

import numpy as np
import pytest

from assur import io
from assur.core import statics

MODELS = ["hitch_003", "header_000_fixed", "steering_lab4", "spout_lab5", "adapter_lab6",
          "combine_002"]


def _close(a, b, what):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = max(1.0, float(np.abs(b).max(initial=0.0)))
    assert a.shape == b.shape, (what, a.shape, b.shape)
    assert np.allclose(a, b, rtol=1e-9, atol=1e-9 * scale), (what, a, b)


@pytest.mark.parametrize("name", MODELS)
def test_one_position_equals_the_array_path(name, monkeypatch):
    model = io.load(io.bundled(name))
    mech = model.mechanism.with_params(**dict(model.mechanism.params))  # a fresh cache
    assert len(mech.coordinates) == 1
    q = np.asarray(model.range, dtype=float)
    q = q[np.linspace(0, q.size - 1, min(q.size, 6)).astype(int)]
    ref = mech.analyze(q)
    qdot, qddot = ref.rates or (None, None)  # a rod's [motion]: inertia loads
    ref_st = statics.solve(ref.kinematics, qdot, qddot, g=mech.g, method="array")

    fused_calls = []
    real = statics._solve_fused
    monkeypatch.setattr(statics, "_solve_fused",
                        lambda kin, g: fused_calls.append(1) or real(kin, g))
    for _ in range(statics.FUSED_AFTER):  # the array pass, then the fused kernel
        mech.analyze(q[:1])
    c = model.mechanism.coordinates[0]
    fused_calls.clear()
    for i, qi in enumerate(q):
        one = mech.analyze(np.array([qi]))
        kin, k0 = one.kinematics, ref.kinematics
        for p in mech.points:
            _close(kin.value(p)[..., 0], k0.value(p)[..., i], f"position of {p}")
            _close(kin.jacobian(p)[..., 0], k0.jacobian(p)[..., i], f"analogs of {p}")
        for _, a, b in ref_st.joints:
            _close(one.statics.reaction(a, b)[0], ref_st.reaction(a, b)[i],
                   f"reaction ({a}, {b})")
            _close(one.statics.reaction_moment(a, b)[0], ref_st.reaction_moment(a, b)[i],
                   f"moment ({a}, {b})")
        _close(one.statics.actuator_force(c)[0], ref_st.actuator_force(c)[i], "F")
        try:
            want = ref_st.actuator_force_from_reactions(c)[i]
        except KeyError:
            want = None
        if want is not None:
            _close(one.statics.actuator_force_from_reactions(c)[0], want, "F from reactions")
        for cname, cyl in ref.cylinders.items():
            got = one.cylinders[cname]
            for attr in ("force", "force_required", "pressure", "force_max"):
                if hasattr(cyl, attr):
                    _close(np.ravel(np.broadcast_to(getattr(got, attr), (1,))),
                           np.ravel(np.broadcast_to(getattr(cyl, attr), q.shape))[i:i + 1],
                           f"{cname} {attr}")
        if ref.stability is not None:
            s1, s0 = one.stability, ref.stability
            for axle in s0.reactions:
                _close(s1.reaction(axle)[0], s0.reaction(axle)[i], f"axle {axle}")
                _close(s1.share(axle)[0], s0.share(axle)[i], f"share {axle}")
            _close(s1.max_implement_weight[0], s0.max_implement_weight[i], "G max")
    # every single position of a static analysis went through the fused kernel (with
    # inertia loads the array pass serves both)
    assert len(fused_calls) == (q.size if ref.rates is None else 0)


def _limit_reference(r0, w0, c, m):
    """The 20 % rule's limit as first written (before the one-position work)."""
    excess = r0 - m * w0
    den = m - c
    pos = den > 0
    finite = np.divide(max(excess, 0.0), den, out=np.zeros(np.shape(den)), where=pos)
    unbounded = (den < 0) | ((den == 0) & (excess >= 0))
    return np.where(pos, finite, np.where(unbounded, np.inf, 0.0))


@pytest.mark.parametrize("r0, w0", [(5000.0, 20000.0), (4000.0, 20000.0), (3000.0, 20000.0),
                                    (0.0, 0.0), (-0.0, 0.0), (1e-300, 0.0)])
def test_stability_limit_equals_its_first_form(r0, w0):
    from assur.machines.stability import _limit
    c = np.array([-1.0, 0.0, 0.1, 0.2, 0.2 + 1e-17, 0.3, 1.0, 5.0])
    for cc in (c, c[:1].reshape(()), c.reshape(2, 4)):
        got, want = _limit(r0, w0, cc, 0.2), _limit_reference(r0, w0, cc, 0.2)
        assert got.shape == want.shape and np.array_equal(got, want), (r0, w0, cc)
