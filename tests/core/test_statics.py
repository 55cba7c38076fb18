"""Property-based checks of the kinetostatics (:mod:`assur.core.statics`) on random mechanisms.

For random *assemblable* mechanisms (hypothesis; the structures, strategies and
dead-point guard of ``tests.helpers.analogs``: single designs and batches of 1–3,
the reference pose and 1–4 positions around it, every RRR dyad at |sin μ| ≥ 0.05
and every RRP dyad at |cos γ| ≥ 0.05; 200 examples per test) carrying random
loads of every kind, 2–8 per example — weights and point forces at
random points, on the point's owner link or on another link that holds the point
(``link=``), moments on random links (cylinders and slider blocks included),
springs between points of two different links (or a link and the frame; at
least 5 cm long), masses with a moment of inertia, statically or with random
coordinate rates q̇, q̈ —
each test checks, for every mechanism family whose reactions assur models
(cylinder–lever input with rigid points, pose points and an RRR dyad; crank input
with an RRR dyad, rigid points, pose points; slider input with an RRR dyad; RRR
dyads whose radius is a second coordinate and an RRP dyad whose radius is, k = 2;
RRP slider dyads on a fixed line and on a line carried by a moving link; RPR
dyads — the slotted lever — driven by a crank, the sleeve on the crank or the rod;
PRP dyads on fixed lines through a slider block and a frame point, or with a line
carried by a moving rocker):

1. the actuator force by virtual work equals the one from the joint reactions,
   ``actuator_force(c) == actuator_force_from_reactions(c)`` for every coordinate;
2. every moving link is in equilibrium: ``equilibrium_residual()`` (|ΣF|, |ΣM|);
3. with inertia (q̇, q̈ given) 1–2 hold with the d'Alembert loads included, and the
   **power balance** ``Σ F_j·q̇_j = d(T + V)/dt − Σ F·v − Σ M·ω`` holds, T the
   kinetic energy of the masses, V the potential of the weights and springs, the
   last two sums over the point forces and moments, d/dt a fourth-order central
   difference *in time* of T + V along q(t) = q + q̇t + q̈t²/2 (time step: no
   coordinate moves by more than ``fd_steps`` of tests.helpers.analogs, 1e-4 of the
   length over which the analogs change);
4. every reaction ``reaction(i, j)`` (and ``reaction_moment`` at prismatic pairs
   and the crank drive), the list ``joints`` and the actuator forces equal those of
   an **independent global solve** (:func:`reference_statics`): the equilibrium of
   all moving links at once, 3 equations per link, unknown pin forces, prismatic
   normal forces and moments and actuator forces, by ``numpy.linalg.solve``;
5. linearity: with loads A and B, the results for A + B are the sums of those for
   A and for B, and scaling every load by λ (forces, moments, weights, spring rates
   and preloads, masses and inertias) scales every reaction and actuator force by λ.

Why the references are independent of the code under test. assur finds the
actuator forces by virtual work from the analogs, and the reactions group by
group in reverse order with two 2x2 solves per group. The reference of 4 knows
nothing of groups or of their order: it writes the joints of the mechanism from
the groups' definitions (pins at a dyad's three joints, a crank's pivot with its
drive moment, a prismatic pair with normal force and moment, a cylinder split
into its two halves joined by a prismatic pair whose axial force *is* the
actuator force) and solves all links together; the loads enter as they are
documented in :mod:`assur.core.loads` (a spring pulls its ends together with
T = preload + rate·(L − free length); a mass has weight m·g, inertia −m·a and
−J·ε), from the loads this test drew, not from ``Mechanism.loads``. It uses only
the positions of the kinematics and, with inertia, the point accelerations of
``Kinematics.acceleration`` (the analogs, checked by ``tests.helpers.analogs``); the
angular velocity and acceleration of a link are recomputed from two of its points.
The power balance of 3 differentiates the energy in time by finite differences of
positions and velocities solved at neighbouring instants, so it checks the
inertia forces (the q̇ᵀHq̇ terms included) against the motion itself.

Tolerances and scales (per design and position). Load scale S [N]: the sum of the
magnitudes of all point forces (inertia forces and spring tensions included) plus
those of all moments / 1 m. Transmission τ_j [m per unit of q_j]: the largest
|∂r/∂q_j| of any moving point and 1 m × |∂φ/∂q_j| of any link. Actuator force
scale A_j = S·τ_j [N or N·m]; reaction scale R = max(S, largest reaction,
largest prismatic or drive moment / 1 m) [N]; moment scale R·ℓ, ℓ = max(1 m,
largest |position|) (assur sums moments about the origin).

* 1: ``|VW − from reactions| ≤ 1e-9·A_j``; 2: ``|ΣF| ≤ 1e-9·R``, ``|ΣM| ≤ 1e-9·R·ℓ``;
* 4: ``|assur − reference| ≤ 1e-8·R`` (reactions, moments / 1 m) and ``1e-8·A_j``;
* 5: ``1e-9`` times the sum of the scales of the solves compared;
* 3 (power): ``1e-7`` times the sum of the magnitudes of the power terms plus
  S × the largest speed of a point (or 1 m × |ω| of a link) (truncation of the
  difference ~1e-16, rounding ~1e-12 of the terms).

The worst ratio |error| / tolerance of every check over a session is kept in
:data:`WORST`; the worst of all is a hypothesis target (``pytest
--hypothesis-show-statistics``), which the ``deep`` profile (``ASSUR_HYPOTHESIS=deep``)
also hill-climbs towards larger ratios.

Three bugs these tests found are fixed and kept as regression tests (each with a
minimal reproducer): loads at the moving end of a cylinder carried by the cylinder
itself (:func:`test_load_at_a_cylinder_rod_end_carried_by_the_cylinder`); a slider
direction that differs between the designs of a batch
(:func:`test_slider_input_batch_with_a_direction_per_design`); and, with k = 2,
``qdot`` without ``qddot`` (:func:`test_inertia_without_qddot_two_coordinates`). The
family tests themselves still keep to the cases they were written for (no loads at a
cylinder's moving end, one slider direction per batch, both rates given).
"""

from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from assur.core import statics
from tests.helpers.analogs import _floats, prp_family, rpr_family, rrp_family
from tests.helpers.statics import BUG_SETTINGS, SETTINGS, Batch, Solved, assume_springs_long, \
    check_statics, crank_family, cylinder_lever_family, cylinder_radius_family, draw_loads, \
    draw_rates, prepare, reproducer, rod_ends, slider_family


# ---------------------------------------------------------------------------------
# the tests, one per mechanism family (structures shared with tests.helpers.analogs)
# ---------------------------------------------------------------------------------
@SETTINGS
@given(st.data())
def test_cylinder_lever_rigid_and_pose_points_and_dyad(data):
    """Cylinder–lever input (F_S = axial force of the cylinder) with rigid points, a
    pose point and an RRR dyad: checks 1–5 of the module docstring."""
    check_statics(prepare(cylinder_lever_family(data)), data)


@SETTINGS
@given(st.data())
def test_crank_and_rrr_dyad(data):
    """Crank input (driving moment) + RRR dyad, with rigid points or a pose point on
    the coupler carrying a second dyad: checks 1–5."""
    check_statics(prepare(crank_family(data)), data)


@SETTINGS
@given(st.data())
def test_slider_input_and_rrr_dyad(data):
    """Slider input (drive force along its line) + RRR dyad: checks 1–5."""
    check_statics(prepare(slider_family(data)), data)


@SETTINGS
@given(st.data())
def test_cylinder_radius_as_second_coordinate(data):
    """k = 2, both actuator forces checked: an RRR dyad whose radius is a cylinder
    (after a crank or a cylinder–lever input), or an RRP dyad whose radius is:
    checks 1–5."""
    check_statics(prepare(cylinder_radius_family(data)), data)


@SETTINGS
@given(st.data())
def test_rrp_slider_dyads(data):
    """RRP dyads on a fixed line and on a line carried by the moving rocker (normal
    force and moment of the prismatic pair): checks 1–5."""
    check_statics(prepare(rrp_family(data)), data)


@SETTINGS
@given(st.data())
def test_rpr_dyad(data):
    """RPR dyad (slotted lever) driven by a crank, the sleeve pivoted at the crank
    end or the rod pinned there (pins at a and b, prismatic pair rod–sleeve with its
    normal force and moment): checks 1–5."""
    check_statics(prepare(rpr_family(data)), data)


@SETTINGS
@given(st.data())
def test_prp_dyad(data):
    """PRP dyad on fixed lines through a slider block and a frame point (driven by
    the slider input), or with a line carried by the moving rocker (two prismatic
    pairs with normal forces and moments, a pin between the sliders): checks 1–5."""
    check_statics(prepare(prp_family(data)), data)


# ---------------------------------------------------------------------------------
# regressions: bugs these tests found (fixed)
# ---------------------------------------------------------------------------------
@BUG_SETTINGS
@given(st.data())
def test_load_at_a_cylinder_rod_end_carried_by_the_cylinder(data):
    """Regression (found by this file, fixed in assur.core.statics.solve): a load at the moving end of a cylinder that the
    cylinder itself carries (``link=`` the cylinder, or by default where the
    cylinder owns the point: the middle joint of an RRR dyad whose second radius is
    a coordinate, the joint of an RRP dyad whose radius is one) makes
    ``actuator_force_from_reactions`` differ from the virtual-work force by F·u
    (u the cylinder's axis).

    The reactions themselves are right (they agree with the reference and the
    links are in equilibrium); the actuator force taken from them is not. assur
    takes the axial component of the force of the cylinder on the next link at
    the moving end C, ``R_C·u``; with a load F_C on the cylinder at C the rod
    transmits ``(R_C − F_C)·u`` (the rod end is in equilibrium under R_C's
    reaction, F_C and the barrel's push), which is what virtual work and the
    reference's split cylinder give. Minimal reproducer::

        from assur import Mechanism
        from assur.core.statics import solve
        m = (Mechanism("cl", coordinates=("S",), params={"L3": 0.2})
             .frame("01", 0.415, 0.563).frame("03", 0.25, 1.112)
             .cylinder_lever("lever", base="01", pivot="03", out="23", lever="L3",
                             s="S", branch=-1, links=("2", "3")))
        st = solve(m.force("23", 100.0, -300.0, link="2").solve([0.5, 0.6]))
        st.actuator_force()                  # [270.727, 330.461]  (= link="3")
        st.actuator_force_from_reactions()   # [-23.040,  35.562]  (wrong)

    Fix: the actuator force is the axial component of the cylinder's pin force at C
    *minus the load the cylinder itself carries at C* (equivalently, at the other
    end: pin force plus the cylinder's load there); a later group hung from a point
    the cylinder owns is such a load too.
    """
    kind = data.draw(st.sampled_from(["cylinder-lever input", "crank", "cylinder-lever",
                                      "slider radius"]), label="structure")
    if kind == "cylinder-lever input":
        # the cylinder 2 of the cylinder–lever input, named: point 23 is the lever's
        case = prepare(cylinder_lever_family(data))
        at = ("23", "2")
    else:
        case = prepare(cylinder_radius_family(data, kind))
        # crank + dyad with ra = S2: 45 is IIb's, the cylinder IIa named explicitly;
        # cylinder–lever + dyad with rb = S2: 45 is owned by the cylinder IIb;
        # crank + RRP with radius L: X is owned by the cylinder IIr
        at = {"crank": ("45", "IIa"), "cylinder-lever": ("45", "IIb"),
              "slider radius": ("X", "IIr")}[kind]
    fx = data.draw(_floats(-1000.0, 1000.0), label="fx at the rod end")
    fy = data.draw(st.sampled_from((-1.0, 1.0)), label="sign") * \
        data.draw(_floats(100.0, 1000.0), label="|fy| at the rod end")
    check_statics(case, data, extra_loads=[("force", at, fx, fy)], rod_end_loads=True)


@BUG_SETTINGS
@given(st.data())
def test_slider_input_batch_with_a_direction_per_design(data):
    """Regression (found by this file, fixed in the SliderInput branch of assur.core.statics.solve): in a batch of designs whose
    slider direction is a parameter with one value per design, the reactions and
    the reaction-derived drive force use ``cos/sin(direction)`` of shape (m,)
    against arrays of shape (m, n): the directions are broadcast over the
    *positions* (position j gets design j's direction) — wrong forces when m = n,
    ``ValueError: operands could not be broadcast`` otherwise. (The RRP dyad
    branch reshapes ``beta[:, None]``; this one does not.) Minimal reproducer::

        from assur import Mechanism
        from assur.core.statics import solve
        m = (Mechanism("slider", coordinates=("s",), params={"dir": [0.0, 1.0]})
             .frame("O", 0.0, 0.0)
             .slider_input("slider", origin="O", out="B", s="s", direction="dir",
                           links=("1",))
             .weight("B", 1.0))
        st = solve(m.solve([[1.0, 1.2], [1.0, 1.2]]))
        st.actuator_force()                 # [[0, 0], [0.841, 0.841]]  (P·sin dir)
        st.actuator_force_from_reactions()  # [[0, 0.841], [0, 0.841]]  (wrong)
        solve(m.solve([[1.0, 1.2, 1.4], [1.0, 1.2, 1.4]]))  # ValueError
    """
    check_statics(prepare(slider_family(data, Batch)), data)


@BUG_SETTINGS
@given(st.data())
def test_inertia_without_qddot_two_coordinates(data):
    """Regression (found by this file, fixed in assur.core.statics.applied_loads): with k ≥ 2 coordinates, ``qdot`` given and
    ``qddot`` omitted (documented as optional: steady rates) every force is NaN —
    ``np.asarray(qddot, float)`` of None is NaN for k > 1 (k = 1 uses 0). It must
    equal ``qddot = 0``. Minimal reproducer::

        import numpy as np
        from assur import Mechanism
        from assur.core.statics import solve
        m = (Mechanism("k2", coordinates=("th", "S2"))
             .frame("A0", 0.0, 0.0).frame("B0", 0.8, 0.1)
             .crank("c", pivot="A0", out="A", radius=0.3, q="th", links=("1",))
             .dyad("II", a="A", b="B0", out="C", ra="S2", rb=0.7, branch=1,
                   links=("2", "3"))
             .mass("3", 10.0, "C", J=0.5))
        kin = m.solve(np.array([[0.4, 0.8]]))
        solve(kin, qdot=np.array([[1.0, 0.2]]), qddot=np.zeros((1, 2))).actuator_force("th")
        # [1.4506]
        solve(kin, qdot=np.array([[1.0, 0.2]])).actuator_force("th")   # [nan]
    """
    case = prepare(cylinder_radius_family(data))
    loads = draw_loads(data, case.mech, "loads") + [
        ("mass", data.draw(st.sampled_from(sorted(
            (p, b) for b, v in case.mech.bodies.items() if b != "0" for p in v["points"]
            if (p, b) not in rod_ends(case.mech))), label="mass at"),
         data.draw(_floats(0.1, 200.0), label="m"), data.draw(_floats(0.0, 20.0), label="J"))]
    Qd, _ = draw_rates(data, case)
    assume_springs_long(case, loads)
    s0 = Solved(case, loads, Qd, np.zeros_like(Qd))
    s1 = statics.solve(s0.r, qdot=case.api_q(Qd))
    for c in case.mech.coordinates:
        a, b = case.shaped(s1.actuator_force(c)), s0.vw(c)
        assert np.allclose(a, b, rtol=1e-12, atol=1e-9 * s0.A.max()), (
            f"actuator force {c} with qddot omitted: {a.ravel()[:3]} != qddot = 0: "
            f"{b.ravel()[:3]}\n{reproducer(case, loads, Qd, np.zeros_like(Qd))}")


