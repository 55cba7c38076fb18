"""Capacity in the working direction (issue 25): a cylinder's capacity and reserve are
the load it lifts at the relief pressure with the chamber of the stroke's working
direction — declared (``side = "piston"``/``"extend"``, ``"rod"``/``"retract"``) or
``"auto"``, once per stroke from the sign of the payload's virtual work — never
switched per position by the sign of the load; the reserve is against the payload
alone, the dead loads carried by G.

The models are a lever written here as a model file: pivot O, the cylinder from the
frame pin B to the lever's pin A (r = 0.3 m from O), the tip T 1 m from O. Its mirror
image has B on the other side of the lever: the cylinder pulls instead of pushing.
The hand formulas solve the lever's triangle in closed form, S² = r² + |OB|² −
2·r·(B_x·cos θ + B_y·sin θ), and differentiate it by complex step.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from assur import io
from assur.core import cylinders as C
from assur.views.report.tables import seed_tables

S = np.linspace(0.42, 0.58, 9)          # cylinder lengths [m]; the lever near horizontal
R_LEVER, P_REL, ETA_H, ETA_M = 0.3, 16e6, 0.9, 0.95


def lever(tmp_path, *, side="auto", mirror=False, bore="60 mm", rod="30 mm", loads="",
          params="", dead="", name="lever"):
    """The lever's model file (payload W = 10 kN at the tip T unless ``loads`` says
    otherwise), loaded with :func:`assur.io.load`."""
    loads = loads or '[[loads]]\ntype = "weight"\npoint = "T"\nP = "W"\nname = "W"\n'
    text = f'''
[model]
name = "{name}"
coordinates = ["S"]

[params]
r = "{R_LEVER} m"
W = "10 kN"
p_rel = "16 MPa"
{params}

[range]
S = {{ from = "0.42 m", to = "0.58 m", count = 9 }}

[frame]
O = ["0 m", "0 m"]
B = ["0.3 m", "{'0.5' if mirror else '-0.5'} m"]

[[groups]]
type = "cylinder_lever"
name = "lever"
base = "B"
pivot = "O"
out = "A"
lever = "r"
s = "S"
branch = {1 if mirror else -1}
links = ["2", "3"]

[[groups]]
type = "rigid_point"
name = "tip"
origin = "O"
toward = "A"
out = "T"
length = "1.0 m"
angle = 0
links = ["3"]

[[groups]]
type = "rigid_point"
name = "bucket"
origin = "O"
toward = "A"
out = "P"
length = "0.5 m"
angle = "85 deg"
links = ["3"]

[links]
"2" = ["B", "A"]
"3" = ["O", "A"]

{loads}
[[cylinders]]
name = "C"
coordinate = "S"
bore = "{bore}"
rod = "{rod}"
side = "{side}"
p_relief = "p_rel"
eta_hyd = {ETA_H}
eta_mech = {ETA_M}

[tables]
transmissions = ["T", "A"]
{dead}
'''
    path = tmp_path / f"{name}{'_mirror' if mirror else ''}.toml"
    path.write_text(text, encoding="utf-8")
    return io.load(path).mechanism


def hand(S_, mirror=False):
    """θ(S) of the lever [rad] and dθ/dS [rad/m] in closed form (complex step)."""
    bx, by = 0.3, (0.5 if mirror else -0.5)
    r, R = R_LEVER, math.hypot(bx, by)

    def theta(s):
        c = (r * r + R * R - s * s) / (2.0 * r * R)
        return np.arctan2(by, bx) + (-1.0 if mirror else 1.0) * np.arccos(c)

    h = 1e-30
    th = theta(np.asarray(S_, float))
    dth = np.imag(theta(np.asarray(S_, complex) + 1j * h)) / h
    return th, dth


def area(D, d=0.0):
    return math.pi * (D * D - d * d) / 4.0


def test_the_hand_geometry_is_the_models(tmp_path):
    """The closed form the other tests use describes the model (so they test G)."""
    for mirror in (False, True):
        kin = lever(tmp_path, mirror=mirror).solve(S)
        th, dth = hand(S, mirror)
        np.testing.assert_allclose(kin.y("T"), np.sin(th), atol=1e-12)
        np.testing.assert_allclose(kin.transmission("T"), np.cos(th) * dth, rtol=1e-9)


@pytest.mark.parametrize("sides", [("auto", "auto"), ("piston", "rod"),
                                   ("extend", "retract")])
def test_a_pulling_and_a_pushing_cylinder_have_the_same_positive_capacity(tmp_path, sides):
    """Mirror images on one lever, equal working areas (the pusher's piston side of
    D = 60 mm, the puller's annulus of D = 100 mm, d = 80 mm): the same capacity at
    the same cylinder length, positive for both, = F_max·η_m/|I|."""
    push = lever(tmp_path, side=sides[0])
    pull = lever(tmp_path, side=sides[1], mirror=True, bore="100 mm", rod="80 mm")
    assert area(0.06) == pytest.approx(area(0.1, 0.08), rel=1e-12)
    cp, cq = push.analyze(S).cylinder("C"), pull.analyze(S).cylinder("C")
    assert np.all(cp.working_sign == 1.0) and np.all(cq.working_sign == -1.0)
    assert np.all(cp.force > 0) and np.all(cq.force < 0)     # it does pull
    Gp, Gq = cp.capacity("T"), cq.capacity("T")
    th, dth = hand(S)
    want = P_REL * area(0.06) * ETA_H * ETA_M / (np.cos(th) * dth)
    np.testing.assert_allclose(Gp, want, rtol=1e-9)
    np.testing.assert_allclose(Gq, Gp, rtol=1e-9)
    assert np.all(Gq > 0)
    for m, G in ((push, Gp), (pull, Gq)):   # the kernel: the same numbers
        f = m.evaluate(S, outputs=["G(C, T)", "reserve(C, T, W)"])
        np.testing.assert_allclose(f["G(C, T)"], G, rtol=1e-12)
        np.testing.assert_allclose(f["reserve(C, T, W)"], (G - 1e4) / 1e4 * 100, rtol=1e-9)


def test_dead_loads_that_outweigh_the_payload_do_not_turn_the_capacity_negative(tmp_path):
    """Issue 25's first report: a small payload and a larger dead load the other way
    (an upward balancing force on the cylinder's rod end): the force of all the loads
    is a pull, yet the working direction lifts the payload — extend, piston side —
    and the capacity is positive and = (F_max,p·η_m − F_dead)/I. The old per-position
    chamber (the rod side where F < 0) gave a negative capacity here."""
    loads = ('[[loads]]\ntype = "weight"\npoint = "T"\nP = "W"\nname = "W"\n\n'
             '[[loads]]\ntype = "force"\npoint = "A"\nfy = "Fup"\nlink = "2"\nname = "balancer"\n')
    m = lever(tmp_path, loads=loads, params='Fup = "15 kN"',
              dead='dead_loads = ["2"]').with_params(W=3000.0)   # W [N]
    cyl = m.analyze(S).cylinder("C")
    assert np.all(cyl.force < 0)                         # all the loads: a pull
    th, dth = hand(S)
    I_T, I_A = np.cos(th) * dth, R_LEVER * np.cos(th) * dth
    F_dead = -15000.0 * I_A                              # the upward force's actuator force
    Fp, Fr = P_REL * area(0.06) * ETA_H, P_REL * area(0.06, 0.03) * ETA_H
    want = (Fp * ETA_M - F_dead) / I_T
    np.testing.assert_allclose(cyl.capacity("T"), want, rtol=1e-9)
    assert np.all(want > 0)
    assert np.all((-Fr * ETA_M - F_dead) / I_T < 0)      # what the rod side would give
    np.testing.assert_allclose(m.evaluate(S, outputs=["G(C, T)"])["G(C, T)"], want, rtol=1e-9)
    np.testing.assert_allclose(cyl.reserve("T", 3000.0), (want - 3000.0) / 3000.0 * 100,
                               rtol=1e-9)


def _bucket(tmp_path, side="auto"):
    """A payload Wp at the bucket point P (85° from the lever) whose force along S
    changes sign within the stroke, and a small one at the tip."""
    loads = ('[[loads]]\ntype = "weight"\npoint = "T"\nP = "Wt"\nname = "Wt"\n\n'
             '[[loads]]\ntype = "weight"\npoint = "P"\nP = "Wp"\nname = "Wp"\n')
    return lever(tmp_path, side=side, loads=loads, params='Wt = "0.5 kN"\nWp = "20 kN"',
                 name="bucket")


def test_the_chamber_does_not_switch_when_only_the_loads_sign_changes(tmp_path):
    """A Z-bar-like stroke: the payload's force changes sign along it while the
    working direction stays; ``auto`` keeps one chamber — that of the sign of the
    payload's force summed over the stroke — at every position, as the declared side
    does, and the capacity is the hand formula of that chamber at every position."""
    m = _bucket(tmp_path)
    cyl = m.analyze(S).cylinder("C")
    F = cyl.force
    assert F.min() < 0 < F.max()                          # the load's sign changes
    assert np.sum(F) > 0                                  # its work along the stroke: extend
    assert np.all(cyl.working_sign == 1.0)
    assert set(np.sign(cyl.sign)) == {-1.0, 1.0}          # the pressure's chamber holds
    th, dth = hand(S)
    want = P_REL * area(0.06) * ETA_H * ETA_M / (np.cos(th) * dth)
    np.testing.assert_allclose(cyl.capacity("T"), want, rtol=1e-9)
    declared = _bucket(tmp_path, side="extend").analyze(S).cylinder("C").capacity("T")
    np.testing.assert_allclose(declared, want, rtol=1e-12)
    f = m.evaluate(S, outputs=["G(C, T)"])
    np.testing.assert_allclose(f["G(C, T)"], want, rtol=1e-9)
    # the stroke, not the position: a single position where the force pulls takes the
    # chamber that position's own work asks for
    k = int(np.argmin(F))
    one = m.analyze(S[k:k + 1]).cylinder("C")
    assert float(np.ravel(one.working_sign)[0]) == -1.0


def test_each_design_of_a_batch_has_its_own_working_direction(tmp_path):
    """The kernel's first pass gives W per design: a batch whose second design's
    payload asks for the other direction uses the rod side there, like the array
    path and the dual numbers."""
    from assur.synthesis.sensitivity import sensitivities

    m = _bucket(tmp_path).with_params(Wt=[5000.0, 0.0], Wp=[20000.0, 60000.0])
    q = np.tile(np.linspace(0.5, 0.58, 9), (2, 1))       # there P's force pulls mostly
    cyl = m.analyze(q).cylinder("C")
    sig = np.asarray(cyl.working_sign)
    assert sig[0, 0] != sig[1, 0] and np.all(sig == sig[:, :1])
    G = cyl.capacity("T")
    f = m.evaluate(q, outputs=["G(C, T)", "reserve(C, T, Wp)"])
    np.testing.assert_allclose(f["G(C, T)"], G, rtol=1e-12)
    r = m.evaluate(q, outputs=["G(C, T)"], reduce=True)
    np.testing.assert_allclose(r.min("G(C, T)"), G.min(axis=1), rtol=1e-12)
    for d in range(2):
        one = _bucket(tmp_path).with_params(Wt=[5000.0, 0.0][d], Wp=[20000.0, 60000.0][d])
        s = sensitivities(one, q[d], params=["r"], outputs=["G(C, T)"])
        np.testing.assert_allclose(s.value[:, 0], G[d], rtol=1e-12)


def test_reserve_with_dead_loads_is_the_hand_formula(tmp_path):
    """ΔG = (G − W)/W·100 with G = (F_max·η_m − F_dead)/I: the dead load (a weight Wd
    at the rod end A, carried by the cylinder 2, ``dead_loads = ["2"]``) is paid for in
    G, never taken as the load to lift; table 4.1 has the reserve against the payload
    at T and none at A, where only the dead load acts."""
    loads = ('[[loads]]\ntype = "weight"\npoint = "T"\nP = "W"\nname = "W"\n\n'
             '[[loads]]\ntype = "weight"\npoint = "A"\nP = "Wd"\nlink = "2"\nname = "Wd"\n')
    m = lever(tmp_path, loads=loads, params='Wd = "4 kN"', dead='dead_loads = ["2"]')
    a = m.analyze(S)
    cyl = a.cylinder("C")
    th, dth = hand(S)
    I_T, I_A = np.cos(th) * dth, R_LEVER * np.cos(th) * dth
    G = (P_REL * area(0.06) * ETA_H * ETA_M - 4000.0 * I_A) / I_T
    dG = (G - 10000.0) / 10000.0 * 100.0
    np.testing.assert_allclose(cyl.capacity("T"), G, rtol=1e-9)
    np.testing.assert_allclose(cyl.reserve("T", 10000.0), dG, rtol=1e-9)
    f = m.evaluate(S, outputs=["reserve(C, T, W)", "G(C, A)"])
    np.testing.assert_allclose(f["reserve(C, T, W)"], dG, rtol=1e-9)
    t41 = {t.id: t for t in seed_tables(a)}["4.1"]
    np.testing.assert_allclose(t41["dGT"], dG, rtol=1e-9)
    assert "GA" in t41.symbols and "dGA" not in t41.symbols


def test_stroke_work_decides_by_the_payload_then_by_all_the_loads():
    """W sums the payload's force over the positions; without a payload, all the
    loads' (dead loads only)."""
    W = C.stroke_work([[3.0, -1.0], [0.0, 0.0]], [[1.0, -5.0], [-2.0, 1.0]], axis=1)
    assert W.tolist() == [[2.0], [-1.0]]
