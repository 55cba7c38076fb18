"""
Seed 001, lab 3: the grain-cleaning ten-bar — Механизм очистки зерна
====================================================================

Lab 3 of the practicum: the crank mechanism that shakes the sieves of a combine's
cleaning. Over one turn: the common centre of mass and its amplitudes, the inertia
loads, the joint reactions with inertia and their hodographs, the reduced moment
and moment of inertia, the flywheel for a speed irregularity δ = 0.05 and the
counter-masses that balance it. The lab gives the structure (fig. 3.2) and its
results, not the dimensions: ``cleaning_lab3.toml`` is illustrative, chosen so that
the common centre of mass swings by a few millimetres like the lab's
(A_x = 3.97 mm, A_y = 3.85 mm for the lab's own machine).

Лабораторная работа 3: центр масс, силы инерции, реакции с учётом инерции,
приведённый момент, маховик и уравновешивание.
"""

# %%
# One turn at 30 rad/s — один оборот
# ----------------------------------
import numpy as np

from assur import io
from assur.dynamics.balancing import balance
from assur.dynamics.crank import crank_dynamics

model = io.load(io.bundled("cleaning_lab3"))
kin = model.mechanism.solve(model.range)  # one clockwise turn, 1° steps
dyn = crank_dynamics(kin, qdot=-30.0)     # ω = −30 rad/s (clockwise), ε = 0
Ax, Ay = dyn.centre.amplitude_x, dyn.centre.amplitude_y
print(f"common centre of mass: A_x = {Ax * 1e3:.2f} mm, A_y = {Ay * 1e3:.2f} mm "
      f"(the lab's machine: 3.97 mm, 3.85 mm)")
assert 3e-3 < Ax < 5e-3 and 3e-3 < Ay < 5e-3

# %%
# The reduced moment of every load, inertia included, balances the driving power at
# every position — a check of the whole kinetostatics:
print(f"power residual {np.abs(dyn.power_residual()).max():.1e} W; "
      f"reduced moment of inertia {dyn.reduced_inertia.min():.3f} … "
      f"{dyn.reduced_inertia.max():.3f} kg·m²")
assert np.abs(dyn.power_residual()).max() < 1e-6

# %%
# Flywheel — маховик (energy–mass method)
# ---------------------------------------
fw = dyn.flywheel(delta=model.dynamics.delta)
print(f"flywheel for δ = {model.dynamics.delta}: J_f = {fw.J_flywheel:.2f} kg·m², |ω| {fw.omega_min:.2f} … {fw.omega_max:.2f} rad/s")
assert abs((fw.omega_max - fw.omega_min) / fw.omega_mean - model.dynamics.delta) < 1e-3

# %%
# Balancing — уравновешивание
# ---------------------------
b = balance(kin, model.dynamics.counter_masses, model.dynamics.objective)
print(f"after balancing: A_x = {b.after.amplitude_x * 1e3:.2f} mm, "
      f"A_y = {b.after.amplitude_y * 1e3:.2f} mm")
assert b.after.amplitude_x < Ax and b.after.amplitude_y < Ay

# %%
# The figures of the report (lab 3 figs. 3.3, 3.4), in Russian as the lab draws them:
from assur.views.report.dynamics import figures  # noqa: E402

dynamics_figures = figures(dyn, "ru", flywheel=fw, balancing=b)
print(sorted(dynamics_figures))

# %%
# Synthesis — the linkage that shakes least (``cleaning_lab3_design.toml``)
# -------------------------------------------------------------------------
# Instead of counter-masses, change the linkage: the rocker's arms and the hangers'
# pivots move (±30…50 mm) to make the horizontal excursion of the common centre of
# mass over a turn (the span of the fused output ``Xc``, 2·A_x) least, with the
# vertical one no larger and every sieve's stroke at least the original's
# (``assur optimize``; a small budget here).
from assur.dynamics.balancing import common_centre  # noqa: E402
from assur.io import load_problem  # noqa: E402
from assur.synthesis.search.search import optimize  # noqa: E402

pb = load_problem(io.bundled("cleaning_lab3_design"))
res = optimize(pb, popsize=6, maxiter=30, seed=1)
c1 = common_centre(pb.with_design(res.x).solve(pb.positions))
print(f"span of Xc: {res.original.objectives[0, 0] * 1e3:.2f} mm → {res.value * 1e3:.2f} mm; "
      f"A_x = {c1.amplitude_x * 1e3:.2f} mm, A_y = {c1.amplitude_y * 1e3:.2f} mm")
assert res.feasible and res.value < 0.25 * res.original.objectives[0, 0]

# %%
# The file's notes:
for note in model.mechanism.notes:
    print("-", note["en"] if isinstance(note, dict) else note)
