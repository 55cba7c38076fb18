"""
Seed 002: the combine six-bar — Шестизвенный механизм комбайна
==============================================================

Seed ``002_e16fe39845bb7e76.txt``: the structural and kinematic analysis of a
crank-driven six-bar of a combine — two vector loops, 13 crank positions, velocity
analogs along the clockwise rotation. The bundled file ``combine_002.toml`` places
the frame pivots by length and angle (O3 = O1 + l10∠j10, O6 = O3 + l8∠j8) as the
seed's vectors do. The seed's numeric tables are withheld as a reference case; what
its text states is checked here.

Структурный и кинематический анализ шестизвенного механизма комбайна с кривошипом:
два векторных контура, 13 положений кривошипа, аналоги скоростей.
"""

# %%
# The seed's l2 as printed — l2, как напечатано
# ---------------------------------------------
# Table 2.2 prints l2 = 0,1 m. With it the first dyad cannot close; the message
# says by how much and where (``combine_002_printed.toml``):
import numpy as np

from assur import AssemblyError, io

printed = io.load(io.bundled("combine_002_printed"))
try:
    printed.mechanism.solve(printed.range)
except AssemblyError as e:
    print(e)
    gap_mm = e.amount * 1e3
assert round(gap_mm) == 521

# %%
# With l2 = 1.0 m — the value of the seed's withheld tables — it assembles:
model = io.load(io.bundled("combine_002"))
m = model.mechanism
print(f"l2 = {m.params['l2']} m; crank positions j1 [°]:", np.round(np.degrees(model.range), 3))
a = m.analyze(model.range)
kin = a.kinematics
print(f"closure residual {kin.closure_residual().max():.1e} m")

# %%
# The working stroke — рабочий ход
# --------------------------------
# The seed starts and ends the rocker's working stroke at j1 = 14.679° and
# 188.229° (positions 1 and 13), where the rocker l3 stands still: dφ3 = 0. The
# engine's exact analog is zero there at the printed precision:
d3 = kin.dphi("3")
print(f"dφ3/dφ1 at 14.679°: {d3[0]:+.5f}, at 188.229°: {d3[12]:+.5f}; "
      f"elsewhere |dφ3/dφ1| ≥ {np.abs(d3[1:12]).min():.3f}")
assert abs(d3[0]) < 5e-4 and abs(d3[12]) < 5e-4 and np.all(np.abs(d3[1:12]) > 0.04)

# %%
# The drawing at the two extremes of the rocker (``--draw-at 14.679,188.229`` on the
# command line):
from assur.views.report import drawing, figures  # noqa: E402

drawn = drawing.draw(a, positions=[0, 12])

# %%
# A full turn — полный оборот
# ---------------------------
# ``combine_002_turn.toml`` turns the crank clockwise through 360° (one position per
# degree); the branches stay continuous, and φ3 has its minimum and maximum at the
# seed's two angles:
turn = io.load(io.bundled("combine_002_turn"))
t = turn.mechanism.analyze(turn.range)
phi3 = t.kinematics.phi("3", degrees=True)
q = np.mod(np.degrees(t.kinematics.q()), 360)
print(f"φ3 least at j1 = {q[phi3.argmin()]:.1f}°, largest at j1 = {q[phi3.argmax()]:.1f}° "
      f"(the seed: 14.679°, 188.229°); swing {phi3.max() - phi3.min():.2f}°")
assert abs(q[phi3.argmin()] - 14.679) <= 1 and abs(q[phi3.argmax()] - 188.229) <= 1

angles_figure = figures.angles(t)

# %%
# Velocities at 300 rpm — скорости при 300 об/мин
# -----------------------------------------------
# The seed gives only analogs (φ1' = −1 along the clockwise rotation). A crank speed
# turns them into real velocities:
mm = turn.mechanism.with_motion("j1", "cw", speed=300 * np.pi / 30)
k = mm.solve(turn.range)
qdot, qddot = mm.motion().rates(k.q())
v = k.velocity("D", qdot)
print(f"crank speed {qdot[0]:.1f} rad/s; the rocker's point D reaches "
      f"{np.hypot(*v.T).max():.2f} m/s")

# %%
# The seed's slips (the file's notes): l2 printed 0,1 m for 1.0 m, and the fixed
# angles of l10 and l8 lost from its text (restored from the withheld tables).
for note in m.notes:
    print("-", note["en"] if isinstance(note, dict) else note)
