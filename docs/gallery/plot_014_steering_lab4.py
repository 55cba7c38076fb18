"""
Seed 001, lab 4: steering with two cylinders — Рулевое управление
=================================================================

Lab 4 of the practicum: the steering of the steered axle of a power unit
(УЭС-2-250А). The base drive has **two cylinders in one closed chain**: the left
cylinder S1 drives, the right one S2 is passive — its length follows from the
chain, and both share one supply line, whose pressure is found by virtual work.
Resisting moments at the kingpins oppose the turn (eq. 17). ``steering_lab4.toml``
has illustrative dimensions and the lab's loads; ``steering_lab4_modern.toml`` is
the modernised slider-crank drive with one double-rod cylinder.

Лабораторная работа 4: рулевой привод с двумя гидроцилиндрами в одной замкнутой
цепи, соотношение Аккермана, давление и момент сопротивления повороту.
"""

# %%
# The lab's numbers, recomputed — числа работы
# --------------------------------------------
# Eq. 17, the wheel's resisting moment: with the lab's inputs it gives 3453.6 N·m,
# while the lab prints 2932 N·m. The model uses eq. 17's value and flags the print:
import math

import numpy as np

from assur import io
from assur.machines import steering
from assur.machines.cylinders import supply_pressure_from_reactions

mc = steering.resisting_moment(27560.0, 0.070, 0.500, 0.8)
print(f"eq. 17: Mc = {mc:.1f} N·m (the lab prints 2932 N·m)")
assert round(mc, 1) == 3453.6

# %%
# The Ackermann check of §4.5: ctg 34° − ctg 51° = 0.673 against A/L = 0.575, while
# the lab prints "0.538 ≈ 0.574, error 3.6 %":
computed = 1 / math.tan(math.radians(34)) - 1 / math.tan(math.radians(51))
print(f"ctg 34° − ctg 51° = {computed:.3f}; A/L = {1.456 / 2.534:.3f}")
assert round(computed, 3) == 0.673

# %%
# The base drive over the turn — базовый привод
# ---------------------------------------------
model = io.load(io.bundled("steering_lab4"))
a = model.mechanism.analyze(model.range)
kin = a.kinematics
c1, c2 = a.cylinder("ГЦ1"), a.cylinder("ГЦ2")
print(f"S1 {model.range.min():.3f} … {model.range.max():.3f} m; the passive S2 "
      f"{kin.length('S2').min():.3f} … {kin.length('S2').max():.3f} m")
print(f"one line, one pressure: {c1.pressure.min() / 1e6:.2f} … "
      f"{c1.pressure.max() / 1e6:.2f} MPa")
assert np.array_equal(c1.pressure, c2.pressure)

# %%
# The same pressure from the joint reactions (the passive cylinder's push a load on
# the chain) — the two routes to the forces agree:
p_rx = supply_pressure_from_reactions(kin, "P")
print(f"largest difference {np.abs(c1.pressure - p_rx).max():.2e} Pa")
assert np.allclose(c1.pressure, p_rx, rtol=1e-9, atol=1e-3)

# %%
# The Ackermann deviation over the turn: ctg β − ctg α − A/L, zero for a perfect
# linkage (the wheels' angles from the kingpin arms w3, w5):
alpha = kin.phi("w3") - np.pi / 2
beta = kin.phi("w5") - np.pi / 2
dev = steering.ackermann_deviation(alpha, beta, 1.456, 2.534)
print(f"Ackermann deviation {np.nanmin(dev):+.3f} … {np.nanmax(dev):+.3f}")

# %%
from assur.views.report import drawing, figures  # noqa: E402

drawn = drawing.draw(a)
pressure_figure = figures.pressure(a)

# %%
# The modernised drive — модернизированный привод
# -----------------------------------------------
# One double-rod cylinder on a slider-crank. The lab's force of §4.7 prints
# "290/67·10⁻³ + 290/190·10⁻³" with the results 43280 + 15260 N of
# 2900/0.067 + 2900/0.19 — the '290' is a slip; the model's formula columns show both:
modern = io.load(io.bundled("steering_lab4_modern"))
am = modern.mechanism.analyze(modern.range)
F_lab, F_290 = float(np.ravel(am.formula("F_lab"))[0]), float(np.ravel(am.formula("F_290"))[0])
print(f"2900/0.067 + 2900/0.19 = {F_lab:.0f} N; as printed, 290/67e-3 + 290/190e-3 = {F_290:.0f} N")
assert round(2900 / 0.067, -1) == 43280 and abs(F_lab - 58540) < 10
modern_drawn = drawing.draw(am)

# %%
# The file's notes:
for note in model.mechanism.notes:
    print("-", note["en"] if isinstance(note, dict) else note)
