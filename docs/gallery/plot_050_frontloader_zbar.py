"""
A wheel loader's self-levelling lift — Фронтальный погрузчик с Z-механизмом
===========================================================================

``frontloader_zbar.toml`` is a compact wheel loader with **illustrative dimensions**
(no seed, not a maker's machine): a boom on two lift cylinders S (one cylinder with
``count = 2``) and a Z-bar tilt linkage — the tilt cylinder S1 from the front frame to
the top of a bell crank on the boom, the crank's lower arm pulling the bucket through
a link. Its ``[range]`` lifts the boom over the lift cylinders' stroke and **holds**
the tilt cylinder: S1 is solved at every position so that the bucket's floor stays
level, ``S1 = { hold = "phibucket", equals = "bucket_level", within = ["S1min",
"S1max"] }`` (docs/model-format.md, "Held coordinates").

Компактный фронтальный погрузчик с иллюстративными размерами: стрела на двух
цилиндрах подъёма, Z-образный механизм поворота ковша; цилиндр ковша S1 следует за
подъёмом так, что днище ковша остаётся горизонтальным (самовыравнивание).
"""

# %%
# The levelled path — траектория с выравниванием
# ----------------------------------------------
import numpy as np

from assur import io

model = io.load(io.bundled("frontloader_zbar"))
m = model.mechanism
path = model.path
print(path.describe())
kin = m.solve(model.range)
print(f"hinge pin H from {kin.y('H')[0] * 1e3:.0f} to {kin.y('H')[-1] * 1e3:.0f} mm, "
      f"the boom turns through {np.degrees(np.ptp(kin.phi('boom'))):.1f}°")
print(f"tilt cylinder S1 from {model.range[0, 1] * 1e3:.1f} to {model.range[-1, 1] * 1e3:.1f} mm "
      f"(dS1/dS from {path.dq[0, 1]:.3f} to {path.dq[-1, 1]:.3f})")
print(f"the bucket's floor within {np.abs(kin.phi('bucket')).max():.1e} rad of level")
assert np.abs(kin.phi("bucket")).max() < 1e-10
assert 2850 < kin.y("H")[-1] * 1e3 < 3000

# %%
from assur.views.report import drawing  # noqa: E402

drawn = drawing.draw(m.analyze(model.range[[0, 6, 12]]))

# %%
# Levelled or locked — выравнивание или запертый цилиндр
# ------------------------------------------------------
# With the tilt cylinder locked at its length at the ground, the Z-bar rolls the
# bucket back as the boom rises; held, the bucket only translates, so the payload's
# centre of gravity G rises exactly as the hinge pin does (dY_G/dS = dY_H/dS along the
# path, while ∂Y_G/∂S with S1 locked is larger):
locked = m.solve(np.column_stack([model.range[:5, 0], np.full(5, model.range[0, 1])]))
print(f"locked: the bucket rolls back {np.degrees(locked.phi('bucket')[-1]):.0f}° by "
      f"S = {model.range[4, 0] * 1e3:.0f} mm (the hinge pin at {kin.y('H')[4] * 1e3:.0f} mm)")
I_path, I_H = path.transmission(kin, "G"), path.transmission(kin, "H")
print(f"dY_G/dS along the path {I_path.min():.3f} … {I_path.max():.3f}; "
      f"∂Y_G/∂S with S1 locked {kin.transmission('G', wrt='S').min():.3f} … "
      f"{kin.transmission('G', wrt='S').max():.3f}")
assert np.allclose(I_path, I_H, rtol=1e-10)

# %%
# Cylinders and lift capacity — усилия и грузоподъёмность
# -------------------------------------------------------
# The cylinders' forces are those of both cylinders locked at each position (a force
# balance does not depend on the path); the lift cylinders' capacity at G carries the
# boom's and the crank's own weights (``[tables] dead_loads``):
a = m.analyze(model.range)
lift, tilt = a.cylinder("lift"), a.cylinder("tilt")
print(f"lift cylinders: {lift.pressure.min() / 1e6:.1f} … {lift.pressure.max() / 1e6:.1f} MPa "
      f"with the payload; capacity at G {lift.capacity('G').min() / 1e3:.1f} kN at least")
print(f"tilt cylinder: {tilt.pressure.min() / 1e6:.1f} … {tilt.pressure.max() / 1e6:.1f} MPa")
assert lift.capacity("G").min() > float(m.params["P_load"])
assert lift.pressure.max() < float(m.params["p_relief"])

# %%
# Ratings — номинальные показатели (docs/ratings.md)
# --------------------------------------------------
# The file declares three ``[[rating]]`` tables: the static tipping load at the
# farthest reach of G and the rated operating capacity, half of it (ISO 14397-1), the
# breakout forces 100 mm behind the cutting edge (ISO 14397-2) and the lift capacity
# over the hinge pin's height:
tipping, breakout, lift_chart = model.analyze().ratings
for s in tipping.scalars:
    print(f"{s.label}: {s.values[0] / 1e3:.1f} kN" if s.quantity == "force"
          else f"{s.label}: {s.values[0] * 1e3:.0f} mm")
print(f"lift breakout force {np.min(breakout['F_lift']) / 1e3:.1f} … "
      f"{np.max(breakout['F_lift']) / 1e3:.1f} kN along the lift")
roc = {s.symbol: s.values[0] for s in tipping.scalars}["ROC_rated"]
assert roc >= float(m.params["P_load"])

# %%
# The file's notes — примечания модели
for note in m.notes:
    print("-", note["en"] if isinstance(note, dict) else note)
