"""
Seed 004: the forestry crane's work cycles — Манипулятор лесной машины
======================================================================

Seed ``004_4ff0af19c30e8a3a.txt``, a journal paper: the boom and stick of a
forestry manipulator on two cylinders, their Lagrange equations (37–38), and the
cylinder forces over a work cycle when the two move together or one after the other.
``crane_lv184a.toml`` is the ЛВ-184А of the paper's table 1 on the two cylinder
lengths (S1, S2); ``crane_lv185.toml`` and ``crane_lv215.toml`` extend it.
:mod:`assur.dynamics.cycles` moves the rods at constant speeds — the paper's
assumption — and gives F = h(q, q̇) − Q(q) from the engine's equations of motion.

Статья о динамике манипулятора: совмещённое и раздельное движение стрелы и рукояти,
циклы от 4 до 20 с, три крана.
"""

# %%
# The crane — кран ЛВ-184А
# ------------------------
import numpy as np

from assur import io
from assur.dynamics.drive import FlowDivider
from assur.dynamics.cycles import cycle, cycle_forces, sweep

model = io.load(io.bundled("crane_lv184a"))
m = model.mechanism
p = m.params
start = (float(p["S01"]), float(p["S2_53"]))   # boom down, stick at the table's 53°
end = (float(p["Smax1"]), float(p["S2_146"]))  # boom up, stick at 146°
print(f"boom S1 {start[0]:.3f} → {end[0]:.3f} m, stick S2 {start[1]:.3f} → {end[1]:.3f} m")

from assur.views.report import drawing  # noqa: E402

drawn = drawing.draw(m.analyze(np.array([start, end])))

# %%
# The flow divider's speeds — скорости (eqs. 63–68)
# -------------------------------------------------
# 80 l/min, written 1.33e-3 m³/s in the paper; a divider gives both cylinders equal
# flows (V1 = Q/2f1, V2 = Q/2f2); alone, one cylinder takes the whole flow (V = Q/f).
Q = 1.33e-3
f1, f2 = 7.85e-3, 5.024e-3  # piston areas of ЛВ-184А [m²], table 1
V1, V2 = FlowDivider((0.5, 0.5)).speeds(Q, (f1, f2))
print(f"combined: V1 = {V1:.3f}, V2 = {V2:.2f} m/s (printed 0.085, 0.13); "
      f"separate: {Q / f1:.2f}, {Q / f2:.2f} m/s (printed 0.17, 0.26)")
assert (round(V1, 3), round(V2, 2), round(Q / f1, 2), round(Q / f2, 2)) == (0.085, 0.13, 0.17, 0.26)

# %%
# A 6 s cycle, combined and separate — совмещённое и раздельное движение
# ----------------------------------------------------------------------
combined = cycle(start, end, 6.0, "combined_equal")   # eq. (60): V1 = V2
separate = cycle(start, end, 6.0, "separate_second")  # eq. (62): the stick first
(Fc, Fsc), (Fs, Fss) = cycle_forces(m, [combined, separate], g=9.81)

import matplotlib.pyplot as plt  # noqa: E402

fig, axes = plt.subplots(1, 2, figsize=(9, 3.6), sharex=True)
for ax, j, name in zip(axes, (0, 1), ("boom F1 — стрела", "stick F2 — рукоять")):
    ax.plot(combined.t, Fc[:, j] / 1e3, label="combined (60)")
    ax.plot(separate.t, Fs[:, j] / 1e3, label="separate, stick first (62a)")
    ax.set_title(name)
    ax.set_xlabel("t [s]")
    ax.grid(alpha=0.3)
axes[0].set_ylabel("cylinder force [kN]")
axes[0].legend(fontsize=8)
plt.show()

# %%
# The paper's conclusions against the model — выводы статьи
# ---------------------------------------------------------
# The paper: "at a 6 s cycle separate motion gives max forces ≈ 90 % (boom) and 30 %
# (stick) higher" and "dynamic components fall 3–8 times with combined motion". The
# forces compared are those in the fed direction (``F1_fed``, ``F2_fed``: the chamber
# the valve feeds for the stroke — the boom extends, the stick's rod retracts), against
# ideal combined motion (eq. 61: both rods end at T_c); max abs(F) against V1 = V2
# (eq. 60, whose "6 s" cycle lasts 7.8 s) beside them.
d = sweep(m, start, end, periods=[6, 11]).set_index(["scenario", "T"])
for T in (6, 11):
    ideal, equal = d.loc[("combined_ideal", T)], d.loc[("combined_equal", T)]
    sep = d.loc[("separate_second", T)]
    print(f"T = {T} s: separate ÷ ideal combined, fed direction — F1 "
          f"{sep.F1_fed / ideal.F1_fed:.2f}, F2 {sep.F2_fed / ideal.F2_fed:.2f}, dynamic "
          f"F_d1 {sep.Fd1_max / ideal.Fd1_max:.1f}, F_d2 {sep.Fd2_max / ideal.Fd2_max:.1f}; "
          f"max |F| ÷ V1 = V2 — F1 {sep.F1_max / equal.F1_max:.2f}, "
          f"F2 {sep.F2_max / equal.F2_max:.2f}")
ideal6, sep6 = d.loc[("combined_ideal", 6)], d.loc[("separate_second", 6)]
assert 1.8 < sep6.F1_fed / ideal6.F1_fed < 2.0 and 1.2 < sep6.F2_fed / ideal6.F2_fed < 1.3
assert 3 < sep6.Fd1_max / ideal6.Fd1_max < 8

# %%
# The other two cranes — ЛВ-185 и ЛВ-215
# --------------------------------------
# ``crane_lv185.toml`` and ``crane_lv215.toml`` extend the first file with their
# table-1 columns (f2 = 12.266e-3 m², not the printed 12.666e-3: a digit swap that
# the paper's own V2 = 0.054 m/s confirms):
for other in (io.load(io.bundled("crane_lv185")), io.load(io.bundled("crane_lv215"))):
    name = other.name
    q = other.mechanism.params
    s0 = (float(q["S01"]), float(q["S2_53"]))
    s1 = (float(q["Smax1"]), float(q["S2_146"]))
    o = sweep(other.mechanism, s0, s1, periods=[6]).set_index("scenario")
    c, s_ = o.loc["combined_ideal"], o.loc["separate_second"]
    print(f"{name}, T = 6 s: separate ÷ ideal combined, fed direction — F1 "
          f"{s_.F1_fed / c.F1_fed:.2f}, F2 {s_.F2_fed / c.F2_fed:.2f}")

# %%
# Both agree: the boom +89 % against ≈ 90 %, the stick +25 % against ≈ 30 % (max abs(F)
# against V1 = V2 gives +79 % and +13 %: the stick's largest abs(F) is the push against
# its motion at the start, held by the drained side). The paper does not say which
# order, crane or speeds its figure is for, and its own S_max2 does not give the
# stroke's start angle Φ1p0. With constant rod speeds every
# dynamic term scales as 1/T_c², so the ratio of dynamic parts cannot depend on T_c —
# the sweep shows it unchanged between 6 and 11 s, while the gain in the total force
# shrinks as the static part takes over.
#
# The paper's slips, resolved in the file (BRIEF.md): in eq. (37) the term
# (2φ̈1 + φ̈2)φ̈2·sin(αp − φ2) must be (2φ̇1 + φ̇2)φ̇2·sin(αp − φ2), and in eq. (38)
# −C·φ̈1²·sin must be −C·φ̇1²·sin (an independent sympy Lagrange derivation agrees);
# eq. (16) puts φe in the wrong quadrant below 77.7°; for ЛВ-185/215 the printed
# f2 = 12.666e-3 m² is a digit swap of 12.266e-3 m². The file's notes:
for note in m.notes:
    print("-", note["en"] if isinstance(note, dict) else note)
