"""The common contract of the structural group types (:mod:`assur.groups.base`),
checked for **every** type in :func:`assur.groups.registry`.

Each registered type has a sample here (:data:`SAMPLES`): a small mechanism that
contains the group, drawn at a random reference pose by the builder of
``tests.helpers.analogs`` (hypothesis; single designs and batches of 1–3, the
reference pose and 1–4 positions around it, 25 examples per type). A type without
a sample fails :func:`test_every_registered_type_has_a_sample` — adding a type
means adding its sample. For each sample:

1. **positions**: ``closure_residual() <= 1e-9 m`` and the group's constraints
   recomputed from the solved points, first-order analogs against the complex
   step of ``Mechanism.evaluate_positions`` (h = 1e-30) to 1e-7 relative, and
   second-order analogs against central differences of the kernel's first order —
   :func:`tests.helpers.analogs.check` (its docstring gives the method, the scales and
   why the references are independent of the kernel's derivative code); positions
   within the dead-point margin are replaced by the reference pose there;
2. **loads**: a weight and a force at points of each link of the group (the link
   the group puts its point on, for a point-only group; the driven link, for a
   frame point) and a moment on it, drawn at random:
   ``actuator_force == actuator_force_from_reactions`` within 1e-9·S·τ (S the sum of
   the load magnitudes, moments / 1 m; τ the largest |∂r/∂q| of a point or
   1 m·|∂φ/∂q| of a named link), and ``equilibrium_residual()`` ≤ 1e-9·R for the
   forces and ≤ 1e-9·R·ℓ for the moments (R = the larger of S and the largest
   reaction — near a dead point reactions exceed the loads by 1/sin μ; ℓ = the
   larger of 1 m and the largest |position|, assur sums moments about the origin).
   A type that documents a ``ModelError`` for its reactions (a telescopic arm, a
   crank of variable radius) would be skipped here; no sample uses one;
3. **failure**: parameters that make the group unable to assemble at the reference
   pose (a dyad that cannot reach, an offset larger than the distance, parallel
   slider lines…) raise :class:`assur.AssemblyError` with ``group`` equal to the
   group's name and a message naming the group's ``kind``, its name, its links, at
   least one number and the word "position". Types that cannot fail by
   construction (a frame point, a crank, a slider input, a pose point: explicit
   formulas) say so with ``breaks=None``;
4. **metadata** (:func:`test_contract_metadata`): ``type_name`` unique and equal to
   its registry key, a ``Mechanism`` builder method of that name (except
   ``frame``, built by ``Mechanism.frame(name, x, y)``), every ``Field.name`` a
   dataclass field, ``kind`` and ``kind_ru`` non-empty.
"""

from __future__ import annotations

import dataclasses
import math
import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assur import AssemblyError, Mechanism
from assur.core import statics
from assur.groups import registry

from tests.helpers import examples
from tests.helpers.analogs import SETTINGS, _point, check
from tests.helpers.groups import SAMPLES
from tests.helpers.statics import prepare

#: relative tolerances of the load checks (see the module docstring)
RTOL_VW = 1e-9
RTOL_EQ = 1e-9
#: characteristic length converting moments to forces [m]
ELL0 = 1.0

CONTRACT_SETTINGS = settings(SETTINGS, max_examples=examples(25))


def test_every_registered_type_has_a_sample():
    """A registered type without a sample here fails (and a sample of a type no
    longer registered)."""
    assert set(SAMPLES) == set(registry()), (
        f"types without a sample: {sorted(set(registry()) - set(SAMPLES))}; "
        f"samples of unknown types: {sorted(set(SAMPLES) - set(registry()))}")


def test_contract_metadata():
    names = [cls.type_name for cls in registry().values()]
    assert len(names) == len(set(names)), f"type_name not unique: {names}"
    for key, cls in registry().items():
        assert cls.type_name == key, (key, cls)
        if key != "frame":
            assert callable(getattr(Mechanism, key, None)), f"no Mechanism.{key} builder"
        fields = {f.name for f in dataclasses.fields(cls)}
        for f in cls.fields:
            assert f.name in fields, f"{key}: Field {f.name!r} is not a dataclass field"
        assert isinstance(cls.kind, str) and cls.kind.strip(), key
        assert isinstance(cls.kind_ru, str) and cls.kind_ru.strip(), key


def _sample(type_name):
    if type_name not in SAMPLES:
        pytest.fail(f"group type {type_name!r} has no sample in SAMPLES")
    return SAMPLES[type_name]


def _the_group(mech, type_name, name):
    g = mech.group(name)
    assert type(g) is registry()[type_name], f"sample {name!r} is a {type(g).__name__}"
    return g


def _loaded_links(mech, sample):
    if sample.loaded is not None:
        return sample.loaded
    links = mech.topology.group_links.get(sample.group, ())
    if not links:  # a point put on an existing link: that link
        g = mech.group(sample.group)
        links = tuple(mech.owner(p) for p in g.outputs())
    return tuple(dict.fromkeys(l for l in links if l != "0"))


@pytest.mark.parametrize("type_name", sorted(registry()))
@CONTRACT_SETTINGS
@given(data=st.data())
def test_positions_and_analogs(type_name, data):
    """1: closure, first order vs complex step, second order vs central differences."""
    sample = _sample(type_name)
    case = sample.build(data).build()
    _the_group(case.mech, type_name, sample.group)
    check(case)


@pytest.mark.parametrize("type_name", sorted(registry()))
@CONTRACT_SETTINGS
@given(data=st.data())
def test_loads_virtual_work_equals_reactions(type_name, data):
    """2: with a weight, a force and a moment on each link of the group, the
    actuator force by virtual work equals the one from the reactions and every
    moving link is in equilibrium."""
    sample = _sample(type_name)
    # positions that fail or are near a dead point are replaced by the reference pose
    case = prepare(sample.build(data))
    mech = case.mech
    _the_group(mech, type_name, sample.group)
    S = 0.0
    for link in _loaded_links(mech, sample):
        pts = mech.bodies[link]["points"]
        for kind in ("weight", "force"):
            p = data.draw(st.sampled_from(pts), label=f"{kind} on {link}: point")
            on = None if mech.owner(p) == link else link
            if kind == "weight":
                P = data.draw(st.floats(0.0, 2000.0), label="P")
                mech, S = mech.weight(p, P, link=on), S + P
            else:
                fx = data.draw(st.floats(-1000.0, 1000.0), label="fx")
                fy = data.draw(st.floats(-1000.0, 1000.0), label="fy")
                mech, S = mech.force(p, fx, fy, link=on), S + math.hypot(fx, fy)
        M = data.draw(st.floats(-500.0, 500.0), label=f"moment on {link}")
        mech, S = mech.moment(link, M), S + abs(M) / ELL0
    kin = mech.solve(case.api_q(case.Q), on_failure="report", check_continuity=False)
    assert kin.ok.all(), f"the sample does not assemble\n{case.reproducer()}"
    stt = statics.solve(kin)

    def where():
        return case.reproducer() + "\n# loads: " + repr(mech.loads)

    # τ: the largest |∂r/∂q| of a point and 1 m·|∂φ/∂q| of a named link
    tau = np.zeros(case.Q.shape[:2])
    for p in mech.points:
        tau = np.maximum(tau, np.hypot(case.shaped(kin.dx(p)), case.shaped(kin.dy(p))))
    for l in mech.links:
        tau = np.maximum(tau, ELL0 * np.abs(case.shaped(kin.dphi(l.name))))
    for c in mech.coordinates:
        vw = case.shaped(stt.actuator_force(c))
        rx = case.shaped(stt.actuator_force_from_reactions(c))
        tol = RTOL_VW * max(S, 1e-300) * tau
        assert (np.abs(vw - rx) <= tol).all(), (
            f"actuator force {c}: virtual work {vw.ravel()} != from reactions {rx.ravel()}, "
            f"|diff| {np.abs(vw - rx).max():.3g} > {tol.max():.3g}\n{where()}")
    R = np.full(case.Q.shape[:2], S)
    ell = np.full(case.Q.shape[:2], ELL0)
    for p, i, j in stt.joints:
        R = np.maximum(R, np.linalg.norm(case.shaped(stt.reaction(i, j), 1), axis=-1))
    for p in mech.points:
        ell = np.maximum(ell, np.linalg.norm(_point(case, kin, p), axis=-1))
    fres, mres = (case.shaped(a) for a in stt.equilibrium_residual())
    assert (fres <= RTOL_EQ * R).all(), f"|ΣF| {fres.max():.3g} N\n{where()}"
    assert (mres <= RTOL_EQ * R * ell).all(), f"|ΣM| {mres.max():.3g} N·m\n{where()}"


#: a number in a message: 0.123, 1e-05, 12 mm…
_NUMBER = re.compile(r"\d+(\.\d+)?(e[-+]?\d+)?")


@pytest.mark.parametrize("type_name", sorted(registry()))
@CONTRACT_SETTINGS
@given(data=st.data())
def test_failure_names_the_group(type_name, data):
    """3: parameters that make the group unable to assemble raise AssemblyError
    naming the group (kind, name, links), a value and the position."""
    sample = _sample(type_name)
    if sample.breaks is None:
        return  # cannot fail by construction (module docstring, item 3)
    b = sample.build(data)
    case = b.build()
    g = _the_group(case.mech, type_name, sample.group)
    bad = {k: (np.asarray(v, dtype=float) if b.batch else float(np.asarray(v).ravel()[0]))
           for k, v in sample.breaks(b).items()}
    mech = case.mech.with_params(**bad)
    q0 = case.q0[:, None, :]
    with pytest.raises(AssemblyError) as info:
        mech.solve(case.api_q(q0))
    err = info.value
    msg = str(err)
    assert err.group == g.name, (err.group, msg)
    assert g.kind in msg, f"kind {g.kind!r} not in: {msg}"
    assert repr(g.name) in msg or g.name in msg, f"name {g.name!r} not in: {msg}"
    # the links the group creates (group_links lists them first, then e.g. guides);
    # a point-only group names the link it puts its point on
    links = mech.topology.group_links.get(g.name, ())
    if g.link_roles is not None:
        links = links[:len(g.link_roles)]
    for link in links:
        # a whole word: link "1" must not match the digit of a number
        assert re.search(rf"(?<![\w.]){re.escape(link)}(?![\w.])", msg), \
            f"link {link!r} not in: {msg}"
    assert err.links == links, (err.links, links)
    assert _NUMBER.search(msg), f"no number in: {msg}"
    assert "position" in msg, f"no 'position' in: {msg}"


def test_failure_names_default_and_carrier_links():
    """Regression (found by this file, fixed in assur.core.diagnostics): an assembly
    failure named only the links given by the user (``Group.group_links()``): with
    ``links=`` omitted the message and ``AssemblyError.links`` named none (the
    topology calls them "bad:a", "bad:b"), and a rigid point never named the link
    it sits on. Minimal reproducer::

        from assur import Mechanism
        m = (Mechanism("x", coordinates=("th",)).frame("A0", 0, 0).frame("B0", 1, 0)
             .crank("c", pivot="A0", out="A", radius=0.3, q="th")
             .dyad("bad", a="A", b="B0", out="E", ra=5.0, rb=0.1, branch=1))
        m.solve([0.1])  # AssemblyError: RRR dyad 'bad' cannot assemble at position 0
                        # (th = 0.1): … — no links; err.links == ()

    Fix: messages and ``AssemblyError.links`` take the group's links from the
    topology (:func:`assur.core.diagnostics.group_links`)."""
    base = (Mechanism("x", coordinates=("th",)).frame("A0", 0.0, 0.0).frame("B0", 1.0, 0.0)
            .crank("c", pivot="A0", out="A", radius=0.3, q="th"))
    with pytest.raises(AssemblyError) as info:
        base.dyad("bad", a="A", b="B0", out="E", ra=5.0, rb=0.1, branch=1).solve([0.1])
    assert info.value.links == ("bad:a", "bad:b")
    assert "(links bad:a, bad:b)" in str(info.value)
    with pytest.raises(AssemblyError) as info:
        base.rigid_point("T", origin="A0", toward="A", out="T", length=0.3, base=0.3,
                         opposite=1.0).solve([0.1])
    assert info.value.links == ("c:a",)
    assert "(link c:a)" in str(info.value)
