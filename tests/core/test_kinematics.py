"""Property-based checks of the exact kinematic analogs on random mechanisms.

For random *assemblable* mechanisms of every structural-group type (hypothesis;
single designs and batches), at scattered positions away from dead points:

1. first-order analogs of :meth:`Mechanism.solve` (dX, dY of every point, dφ of
   every link, d(length) of every distance; the full Jacobian for k = 2) against the
   **complex step** of :meth:`Mechanism.evaluate_positions` (``q + 1j*1e-30``,
   ``Im/h``; an angle is differentiated as ``Im(arctan(Δy/Δx))/h`` or
   ``−Im(arctan(Δx/Δy))/h``, whichever ratio is bounded — the branch offset is a
   real constant);
2. second-order analogs (the full k×k Hessian, mixed terms included) against
   fourth-order **central differences of the kernel's first-order analogs**
   (:func:`fd_hessian`, step chosen by :func:`fd_steps`);
3. ``closure_residual() <= 1e-9 m`` and every group's constraints recomputed from
   the returned points (|out−a| = ra, |out−b| = rb of each RRR dyad; |out−a| = ℓ, the signed
   distance e of the sleeve pivot from the rod's line and the side of the slide of
   each RPR dyad; the pin on both lines of each PRP dyad…) to 1e-9 m,
   plus the solved reference pose equal to the geometry it was built from.

Why the references are independent of the kernel's derivative code: the kernel
propagates a second-order jet by solving each group's closure equations
differentiated once and twice (generated code). Reference 1 differentiates
nothing by hand — it runs the separate plain-numpy *position* formulas of
:mod:`assur.groups` on complex numbers, exact to rounding. Reference 2 uses only
the kernel's *first*-order output at neighbouring positions, which reference 1 has
validated, so an error in the second-order terms cannot hide behind it
(differencing positions twice would lose half the digits; differencing exact
first derivatives does not).

Tolerance: ``|kernel − reference| <= 1e-7 · scale``, ``scale`` = the magnitude of
that analog over the mechanism: the largest |reference| of its family (lengths:
points and distances; or angles) over all points/links and checked positions of
the design, per derivative component — for k = 2 at least the family's largest
component converted with the coordinates' scales (1 rad, or the reference length),
and for second order at least |first-order analogs| / scale². An analog passing
through zero is judged against the mechanism's magnitude, not its own.

Construction: joint positions are drawn at a reference pose and lengths and
branches derived from them (|sin μ| > 0.45 there); positions are drawn around it
and solved with ``on_failure="report"``, ``check_continuity=False``; positions
that fail or come within |sin μ| < 0.05 of a dead point of an RRR dyad (|cos γ| <
0.05, radius against line, of an RRP dyad; slide |s|/|a–b| < 0.05 of an RPR dyad;
|sin| of the angle between the lines < 0.05 of a PRP dyad) are replaced by the
reference pose (where the RPR slide is > 0.45·|a–b| and the PRP lines cross at
more than 0.5 rad).
"""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from tests.helpers.analogs import SETTINGS, Builder, check, cylinder_dyad_family, prp_family, \
    rpr_family, rrp_family


# ---------------------------------------------------------------------------------
# the tests, one per group type
#
# Each distinct *structure* (group types, connections, branch signs, parameter
# order) is a separately generated and numba-compiled kernel (seconds each, cached
# on disk afterwards, ~10–25 s each here), so the discrete choices below are
# deliberately few (1–3 structures per test, 22 in all; both branches of every
# group type are still covered).
# Everything continuous — frame points, lengths, angles, positions, batch size —
# is random.
# ---------------------------------------------------------------------------------
@SETTINGS
@given(st.data())
def test_cylinder_lever_input(data):
    """(a) Cylinder–lever input group: two frame pivots, cylinder length S."""
    b = Builder(data, "cylinder-lever", ("S",))
    b.input("cylinder-lever", "S", sigma=b.branch())
    b.link("2", "01", "23")
    b.link("3", "03", "23")
    b.distance("S=", "01", "23")
    check(b.build())


@SETTINGS
@given(st.data())
def test_crank_and_rrr_dyad(data):
    """(b) Four-bar: crank input (angle coordinate) followed by an RRR dyad."""
    b = Builder(data, "four-bar", ("th",))
    b.fourbar("th", sigma=b.branch())
    b.link("1", "A0", "A")
    b.link("2", "A", "C")
    b.link("3", "B0", "C")
    b.distance("AB0", "A", "B0")
    check(b.build())


@SETTINGS
@given(st.data())
def test_dyad_with_cylinder_radius_two_coordinates(data):
    """(c) RRR dyad whose radius is the second generalized coordinate S2 (a cylinder
    inside the chain), k = 2: full Jacobian and 2x2 Hessian, mixed terms included.
    Crank input → S2 is the dyad's first radius, branch +1; cylinder–lever input →
    S2 is its second radius, branch −1."""
    kind = data.draw(st.sampled_from(["crank", "cylinder-lever"]), label="input")
    check(cylinder_dyad_family(data, kind).build())


@SETTINGS
@given(st.data())
def test_rigid_points(data):
    """(d) Rigid points on a moving link: P by length and angle, T+ and T− by the
    three sides of their triangles (branch +1 and −1), and an RRR dyad driven
    through one of them. Four-bar → on the coupler A–C, the dyad hangs from P with
    branch +1; cylinder–lever → on the lever 03–23, it hangs from T− with branch −1."""
    kind = data.draw(st.sampled_from(["four-bar", "cylinder-lever"]), label="input")
    coord = "th" if kind == "four-bar" else "S"
    b = Builder(data, f"{kind} + rigid points", (coord,))
    if kind == "four-bar":
        b.fourbar(coord)
        o, t = "A", "C"
    else:
        o, t = b.input(kind, coord)
    b.rigid_angle("P", o, t, "P")
    b.rigid_triangle("T+", t, o, "T+", 1)
    b.rigid_triangle("T-", o, t, "T-", -1)
    hang, sigma = ("P", 1) if kind == "four-bar" else ("T-", -1)
    b.frame_near("F", hang, 0.4, 1.2)
    b.dyad("III", hang, "F", "D", sigma)
    b.link("body", o, t)
    b.link("P", o, "P")
    b.link("T+", t, "T+")
    b.link("T-", o, "T-")
    b.link("4", hang, "D")
    b.link("5", "F", "D")
    check(b.build())


@SETTINGS
@given(st.data())
def test_slider_input_and_rrr_dyad(data):
    """(e) Slider input (prismatic, coordinate s) followed by an RRR dyad whose
    second outer joint is the slider."""
    b = Builder(data, "slider-crank", ("s",))
    b.frame_random("O")
    b.slider_input("O", "B", "s")
    b.frame_near("F", "B", 0.4, 1.2)
    b.dyad("II", "F", "B", "C", b.branch())
    b.link("2", "B", "C")
    b.link("3", "F", "C")
    b.distance("OB", "O", "B")
    check(b.build())


@SETTINGS
@given(st.data())
def test_rrp_slider_dyad(data):
    """(f) RRP slider dyads on a four-bar. ``fixed``: the crank end A on a circle
    meets a fixed line through a frame point L0 (fixed ``direction``), joint X.
    ``link``: the line is carried by the moving rocker B0–C (``line_link``, turned
    ``direction``), the circle is about the moving crank end A, joint Y. The two
    take opposite branches, σ and −σ; the moving line passes through C (its branch
    +1) or B0 (−1)."""
    check(rrp_family(data).build())


@SETTINGS
@given(st.data())
def test_pose_point(data):
    """(g) Pose point: fixed to a moving link by its offset (dx, dy) from ``origin``
    at the reference pose (``at`` = a parameter), with an RRR dyad hanging from it.
    Four-bar → on the coupler (origin C, toward A), branch +1; cylinder–lever → on the
    lever (origin 23, toward 03), branch −1."""
    kind = data.draw(st.sampled_from(["four-bar", "cylinder-lever"]), label="input")
    coord = "th" if kind == "four-bar" else "S"
    b = Builder(data, f"{kind} + pose point", (coord,))
    if kind == "four-bar":
        b.fourbar(coord)
        o, t, sigma = "C", "A", 1
    else:
        t, o = b.input(kind, coord)
        sigma = -1
    b.pose_point("S6", o, t, "S6", coord)
    b.frame_near("F", "S6", 0.4, 1.2)
    b.dyad("IV", "S6", "F", "D", sigma)
    b.link("6", o, "S6")
    b.link("4", "S6", "D")
    b.link("5", "F", "D")
    check(b.build())


@SETTINGS
@given(st.data())
def test_rigid_length_and_slider_radius_as_coordinates(data):
    """Other lengths the builder accepts as coordinates, k = 2: a telescopic link (a
    rigid point whose ``length`` is the coordinate L) and an RRP dyad whose
    ``radius`` is the coordinate L, each on a crank and driving/closing a chain."""
    kind = data.draw(st.sampled_from(["rigid length", "slider radius"]), label="length")
    b = Builder(data, f"crank + {kind}", ("th", "L"))
    b.input("crank", "th")
    if kind == "rigid length":
        b.rigid_angle("boom", "A0", "A", "P", length_coord="L")
        b.frame_near("F", "P", 0.4, 1.2)
        b.dyad("II", "P", "F", "D", 1)
        b.link("4", "P", "D")
        b.link("5", "F", "D")
    else:
        beta = b.draw(-math.pi, math.pi, "line direction")
        b.frame_near("L0", "A", 0.2, 0.8)
        b.slider_dyad("II", "A", "X", "L0", -1, beta, radius_coord="L")
        b.link("rod", "A", "X")
    b.link("1", "A0", "A")
    check(b.build())


@SETTINGS
@given(st.data())
def test_crank_radius_as_coordinate(data):
    """A crank whose ``radius`` is the second coordinate R (polar drive), k = 2,
    followed by an RRR dyad: dA/dR = (cos θ, sin θ), d²A/dθdR = (−sin θ, cos θ).

    Regression: the first generated kernel dropped dR/dq for the crank (found by this
    test); minimal case::

        m = (Mechanism("polar", coordinates=("th", "R")).frame("O", 0.0, 0.0)
             .crank("c", pivot="O", out="A", radius="R", q="th"))
        m.solve(np.array([[0.4, 0.8]])).dx("A")  # [[-0.3115, cos 0.4 = 0.9211]]
    """
    b = Builder(data, "polar crank", ("th", "R"))
    b.frame_random("A0")
    b.crank("A0", "A", "th", radius_coord="R")
    b.frame_near("B0", "A", 0.4, 1.2)
    b.dyad("II", "A", "B0", "C", 1)
    b.link("1", "A0", "A")
    b.link("2", "A", "C")
    b.link("3", "B0", "C")
    check(b.build())


@SETTINGS
@given(st.data())
def test_rpr_dyad(data):
    """(h) RPR dyad (rod through a pivoted sleeve) driven by a crank, both roles of
    the crank end (sleeve pivot, branch +1; rod pin, branch −1)."""
    check(rpr_family(data).build())


@SETTINGS
@given(st.data())
def test_prp_dyad(data):
    """(i) PRP dyad (two sliders joined by a pin): fixed lines through a translating
    slider block and a frame point, driven by a slider input; or a line carried by
    the moving rocker of a four-bar (as line a or line b) and a fixed line."""
    check(prp_family(data).build())
