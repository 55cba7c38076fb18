"""
Seed 001, lab 6: the adapter lift in time — Динамика подъёма адаптера
=====================================================================

Lab 6 of the practicum: a gear pump lifts a header section through a cylinder and a
lever. The hydraulic drive (pump, compressible oil, line losses, relief valve) and
the mechanism (its reduced mass m(S) and m'(S) from the exact analogs) are
integrated in time. From the lab: one cylinder (piston 0.125 m, rod 0.05 m), the
НШ-32 pump at 1800 rpm with η0 = 0.9, E = 2.0e8 Pa, a 16 MPa relief valve.
Illustrative (the lab gives none): the lever, the section, the hose and the valve
of ``adapter_lab6.toml``.

Лабораторная работа 6: насос, сжимаемость масла, потери в линии,
предохранительный клапан и механизм с переменной приведённой массой — во времени.
"""

# %%
# The lab's steady speed — установившаяся скорость
# ------------------------------------------------
# Task 1 of the lab: Q = q·n·η0 and the rod speed Q/A = 0.0704 m/s.
import math

import numpy as np

from assur import io
from assur.dynamics import simulate_model

model = io.load(io.bundled("adapter_lab6"))
Q_lab = 32e-6 * 1800 / 60 * 0.9          # НШ-32 at 1800 rpm, η0 = 0.9 [m³/s]
v_lab = Q_lab / (math.pi * 0.125**2 / 4)  # [m/s]
print(f"pump flow {model.drive.pump_flow() * 6e4:.2f} l/min; steady rod speed "
      f"{v_lab:.4f} m/s (the lab: 0.0704 m/s)")
assert round(v_lab, 4) == 0.0704 and math.isclose(model.drive.pump_flow(), Q_lab, rel_tol=1e-12)

# %%
# The lift — подъём
# -----------------
r = simulate_model(model)
t_off, t_end = r.events["lift-off"][0], r.events["end of stroke"][0]
print(r.message)
print(f"lift-off at {t_off:.3f} s, end of the stroke at {t_end:.2f} s; "
      f"mean rod speed {0.25 / (t_end - t_off):.4f} m/s")
assert abs(0.25 / (t_end - t_off) / v_lab - 1) < 1e-2

# %%
# The start-up overshoots and the speed oscillates through the lift (the lab: "most
# of the lift at a variable speed"); at the top stop the pressure rises to the
# relief valve's setting plus its regulation range:
moving = r.phase == "moving"
p_hold = np.median(r.load[moving]) / model.drive.area
print(f"pressure that holds the load {p_hold / 1e6:.1f} MPa, peak {r.p1[moving].max() / 1e6:.1f} MPa; "
      f"final {r.p1[-1] / 1e6:.1f} MPa")
assert r.p1[moving].max() > 1.3 * p_hold

# %%
# The energy balance, integrated with the states — pump work against losses, the
# mechanism and the oil:
e = r.energy
print(f"pump {e['pump']:.0f} J = relief {e['relief']:.0f} + line {e['line']:.0f} + "
      f"impact {e['impact']:.0f} + loads {e['loads']:.0f} + … ; residual {e['residual']:.1e} J")
assert abs(e["residual"]) <= 1e-3 * e["pump"]

# %%
# The report's figures (lab 6 figs. 6.3–6.7), in English and the first in Russian:
from assur.views.report import simulation  # noqa: E402

simulation_figures = simulation.figures(r, "en")
print(sorted(simulation_figures))
p_ru = simulation.figures(r, "ru")
p_ru = {k: v for k, v in p_ru.items() if k == sorted(p_ru)[0]}

# %%
# The file's notes (the lab's slip: the line-loss term a3·S² must be a3·Ṡ|Ṡ|):
for note in model.mechanism.notes:
    print("-", note["en"] if isinstance(note, dict) else note)
