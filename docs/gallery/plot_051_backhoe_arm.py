"""
An excavator's boom, arm and bucket — Рабочее оборудование экскаватора
======================================================================

``backhoe_arm.toml`` is the front of a 5–8 t crawler excavator with **illustrative
dimensions** (no seed, not a maker's machine): the boom on its cylinder S1, the arm
(dipper) on the arm cylinder S2, and the bucket through the usual four-bar — the bucket
cylinder S3 drives the joint J of the side link (pivoted on the arm at N) and the guide
link (pinned to the bucket at K); the bucket turns about the bucket pivot Q at the
arm's tip. **Three generalized coordinates** on a full grid, 5 × 5 × 5 positions.

Экскаватор (обратная лопата) с иллюстративными размерами: стрела, рукоять и ковш с
рычажным механизмом на трёх гидроцилиндрах; три обобщённые координаты.
"""

# %%
# Three coordinates — три координаты
# ----------------------------------
import numpy as np

from assur import io

model = io.load(io.bundled("backhoe_arm"))
m = model.mechanism
print("coordinates:", m.coordinates, "grid", model.shape, "=", len(model.range), "positions")
a = m.analyze(model.range)
kin = a.kinematics
print(f"closure residual at most {kin.closure_residual().max():.1e} m")
assert model.shape == (5, 5, 5) and kin.closure_residual().max() < 1e-9

# %%
# The working range — рабочая зона
# --------------------------------
# Over a finer grid of the three strokes the tooth tip sweeps the digging envelope:
s = [np.linspace(float(m.params[f"{c}min"]), float(m.params[f"{c}max"]), 9)
     for c in ("S1", "S2", "S3")]
fine = m.solve(np.stack(np.meshgrid(*s, indexing="ij"), axis=-1).reshape(-1, 3))
depth, height = fine.y("tip").min(), fine.y("tip").max()
reach = np.hypot(fine.x("tip"), fine.y("tip")).max()
print(f"digging depth {-depth * 1e3:.0f} mm, reach {reach * 1e3:.0f} mm, "
      f"height {height * 1e3:.0f} mm (the tooth tip)")
assert 2500 < -depth * 1e3 < 3000 and 5800 < reach * 1e3 < 6500

import matplotlib.pyplot as plt  # noqa: E402

fig, ax = plt.subplots(figsize=(6, 5))
ax.plot(fine.x("tip"), fine.y("tip"), ".", ms=2, alpha=0.4, label="tooth tip")
ax.plot(fine.x("Q"), fine.y("Q"), ".", ms=2, alpha=0.4, label="bucket pivot Q")
ax.axhline(0, color="0.5", lw=0.8)
ax.set_aspect("equal")
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
ax.legend()
plt.show()

# %%
from assur.views.report import drawing  # noqa: E402

drawn = drawing.draw(m.analyze(np.array([[1.5, 1.5, 0.74], [1.5, 1.5, 1.24]])))

# %%
# Each cylinder moves its own part — каждый цилиндр движет своё звено
# -------------------------------------------------------------------
# The boom's angle depends on S1 alone, and the bucket's turn relative to the arm on
# S3 alone; the exact analogs say so (∂φ_boom/∂S3 = 0):
print(f"|∂φ_boom/∂S3| at most {np.abs(kin.dphi('boom', wrt='S3')).max()}, "
      f"∂φ_bucket/∂S3 from {kin.dphi('bucket', wrt='S3').min():.2f} to "
      f"{kin.dphi('bucket', wrt='S3').max():.2f} rad/m")
assert np.abs(kin.dphi("boom", wrt="S3")).max() == 0.0

# %%
# Cylinder forces: virtual work and reactions — усилия в цилиндрах
# ----------------------------------------------------------------
# The weights of the boom, the arm and the bucket with its soil; each cylinder's force
# by virtual work equals the one from the joint reactions:
for name, c in (("boom", "S1"), ("arm", "S2"), ("bucket", "S3")):
    vw, rx = a.statics.actuator_force(c), a.statics.actuator_force_from_reactions(c)
    p = a.cylinder(name).pressure
    print(f"{name:6s} F from {vw.min() / 1e3:6.1f} to {vw.max() / 1e3:5.1f} kN, "
          f"p from {p.min() / 1e6:5.1f} to {p.max() / 1e6:4.1f} MPa; "
          f"|virtual work − reactions| ≤ {np.abs(vw - rx).max():.1e} N")
    assert np.abs(vw - rx).max() < 1e-6 * np.abs(vw).max()

# %%
# Digging forces and the lift chart — усилия копания (ISO 6015)
# -------------------------------------------------------------
# The file's ``[[rating]]`` tables (docs/ratings.md): the bucket- and arm-cylinder
# digging forces at the tooth tip, each limited by the other cylinders' holding, and
# the hydraulic lift capacity at the bucket pivot Q over the reach from the swing axis:
digging, chart = model.analyze().ratings
print(f"bucket-cylinder digging force up to {np.max(digging['F_B']) / 1e3:.1f} kN "
      f"(the bucket cylinder alone up to {np.max(digging['F_B_bucket']) / 1e3:.1f} kN)")
print(f"arm-cylinder digging force up to {np.max(digging['F_A']) / 1e3:.1f} kN "
      f"(the arm cylinder alone up to {np.max(digging['F_A_arm']) / 1e3:.1f} kN)")
print(f"lift capacity at Q from {np.min(chart['G']) / 1e3:.1f} to "
      f"{np.max(chart['G']) / 1e3:.1f} kN")
assert 30e3 < np.max(digging["F_B_bucket"]) < 50e3
