"""
Seed 001, lab 1: the mini-loader lift device — Подъёмно-навесное устройство
===========================================================================

Lab 1 of Popov's practicum (seed ``001_4447446e88a18ffc.txt``): the lift device of a
mini power unit with **two generalized coordinates** — the boom cylinder S (МПС) and
the traverse cylinder S1 (МПТ) — its lift capacity with the boom's own weight
(eqs. 10, 14) and the steerability limits (eqs. 16, 18). The lab gives the
structure, the formulas and two results, not the dimensions: ``loader_lab1.toml``
has illustrative dimensions chosen so that those two results come out as the lab
reports them (≈ 11.5 kN at the suspension axis, ≈ 800 kg).

Лабораторная работа 1: ПНУ мини-УЭС с двумя обобщёнными координатами (цилиндры
стрелы S и траверсы S1), грузоподъёмность с учётом веса стрелы, управляемость.
"""

# %%
# Two coordinates on a grid — две координаты на сетке
# ---------------------------------------------------
import numpy as np

from assur import ModelError, io
from assur.machines.capacity import farthest_reach

model = io.load(io.bundled("loader_lab1"))
m = model.mechanism
print("coordinates:", m.coordinates, "grid", model.shape, "=", len(model.range), "positions")
for s in model.solved:  # the stroke, from φ3(Smin) = −2° and φ3(Smax) = 75° (Given/Find)
    print(f"{s.condition.unknown} = {s.value:.4f} m")
a = m.analyze(model.range)
kin = a.kinematics
phi3 = kin.phi("3", degrees=True)
print(f"the boom turns through {np.ptp(phi3):.1f}° (the lab: 75–80°)")
assert 75 <= np.ptp(phi3) <= 80

# %%
from assur.views.report import drawing, figures  # noqa: E402

drawn = drawing.draw(a)

# %%
# Transmission numbers, exactly — передаточные числа
# --------------------------------------------------
# The lab's eq. 13 adds an analog along S1 to one along S. The traverse turns with
# the boom, so the transmission number of the tool's centre of mass S9 is two
# quantities, one per coordinate; assur gives both exactly:
IS9_S, IS9_S1 = kin.transmission("S9", wrt="S"), kin.transmission("S9", wrt="S1")
print(f"∂Y_S9/∂S  from {IS9_S.min():.3f} to {IS9_S.max():.3f}")
print(f"∂Y_S9/∂S1 from {IS9_S1.min():.3f} to {IS9_S1.max():.3f}")

# %%
# Lift capacity with the boom's weight — грузоподъёмность (eqs. 10, 14)
# ---------------------------------------------------------------------
# The boom cylinder's capacity carries the boom's own weight (a dead load); the
# traverse cylinder S1 does not move the suspension axis 09, so it has no capacity
# there — an error that says so, not a column of infinities:
mps, mpt = a.cylinder("MPS"), a.cylinder("MPT")
G09 = mps.capacity("09")
print(f"capacity at the suspension axis 09: least {G09.min() / 1e3:.2f} kN "
      f"(the lab: about 11.5 kN)")
assert abs(G09.min() - 11.5e3) <= 0.02 * 11.5e3
print(f"without the boom's weight it would be {mps.capacity('09', dead_loads=()).min() / 1e3:.2f} kN")
try:
    mpt.capacity("09")
except ModelError as e:
    print("MPT at 09:", e)

capacity_figure = figures.capacity(a)

# %%
# Steerability — управляемость (eqs. 16, 18)
# ------------------------------------------
# The largest implement mass keeping 20 % of the weight on the steered axle, at the
# farthest reach of the suspension axis, without and with the fuel tank as a
# counterweight:
g = 9.81
i = farthest_reach(kin, "09")
st = a.stability
m16 = st.max_implement_weight_without_counterweights[i] / g
m18 = st.max_implement_weight[i] / g
print(f"at X09 = {kin.x('09')[i]:.3f} m: {m16:.0f} kg (eq. 16; the lab: about 800 kg), "
      f"{m18:.0f} kg with the counterweight (eq. 18)")
assert abs(m16 - 800) <= 0.02 * 800 and m18 > m16

# %%
# The lab's slips and the model's choices (the file's notes):
for note in m.notes:
    print("-", note["en"] if isinstance(note, dict) else note)

# %%
# A self-levelling lift: S1 held — самовыравнивание траверсы
# ----------------------------------------------------------
# ``loader_lab1_level.toml`` extends this file with one ``[range]`` line: the traverse
# cylinder S1 is solved at every position of S so that the traverse 9 (which carries
# the tool) keeps φ9 = 75°, ``S1 = { hold = "phi9", equals = "phi9_level", within =
# ["S1_short", "S1max"] }``. The path's analogs follow by the implicit-function rule
# (dS1/dS = −(∂φ9/∂S)/(∂φ9/∂S1)); the transmission number of S9 along the path is
# dY_S9/dS with S1 following:
level = io.load(io.bundled("loader_lab1_level"))
path = level.path
print(path.describe())
lk = level.mechanism.solve(level.range)
print(f"φ9 stays within {np.abs(lk.phi('9') - np.radians(75)).max():.1e} rad of 75°")
print(f"S1 from {level.range[0, 1]:.4f} to {level.range[-1, 1]:.4f} m, "
      f"dS1/dS from {path.dq[0, 1]:.3f} to {path.dq[-1, 1]:.3f}")
I_path = path.transmission(lk, "S9")
print(f"dY_S9/dS along the path from {I_path.min():.3f} to {I_path.max():.3f} "
      f"(∂Y_S9/∂S alone: {lk.transmission('S9', wrt='S').min():.3f} …)")
assert np.abs(lk.phi("9") - np.radians(75)).max() < 1e-10
