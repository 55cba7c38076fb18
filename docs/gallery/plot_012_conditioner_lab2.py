"""
Seed 001, lab 2: the conditioner's pressing device — Прижимное устройство плющилки
==================================================================================

Lab 2 of the practicum: the rollers of a mower-conditioner are pressed together by
springs; the specific pressure p_c(Y) on the crop layer (eq. 4) follows from the
spring force and the transmission number I = dY/dλ along the spring's stroke
(eq. 5). The lab prints no dimensions: ``conditioner_lab2.toml`` (a four-bar) and
``conditioner_lab2_sixbar.toml`` (the six-bar of the lab's fig. 2.2) are
illustrative. Their springs are the ones :func:`assur.machines.conditioner.flattest_spring`
finds: the rate and preload that keep p_c closest to 20 kN/m.

Лабораторная работа 2: удельное давление вальцов p_c(Y), передаточное число вдоль
хода пружины, пружина с наиболее постоянным давлением, четырёх- и шестизвенник.
"""

# %%
# The four-bar — четырёхзвенник
# -----------------------------
import numpy as np

from assur import io
from assur.machines.conditioner import flattest_spring, specific_pressure
from assur.views.report import seed_tables

L_ROLLER, TARGET = 1.6, 20e3  # roller length [m] and the wanted p_c [N/m] (the files')

four = io.load(io.bundled("conditioner_lab2"))
a4 = four.mechanism.analyze(four.range)
Y = four.range
I, p4 = specific_pressure(a4.kinematics, "sp", L_ROLLER)
print(f"gap Y {Y.min() * 1e3:.0f} … {Y.max() * 1e3:.0f} mm; I = dY/dλ {I.min():.3f} … "
      f"{I.max():.3f}; p_c {p4.min() / 1e3:.2f} … {p4.max() / 1e3:.2f} kN/m")

# %%
# The force of the layer found by virtual work and from the joint reactions is the
# same p_c (eq. 4 as the engine writes it):
st = a4.statics
assert np.allclose(p4, st.actuator_force("Y") / L_ROLLER, rtol=1e-10)
assert np.allclose(p4, st.actuator_force_from_reactions("Y") / L_ROLLER, rtol=1e-9)

# %%
# The lab's slip in eq. (5): it needs the analogs along the spring's stroke; read
# along the gap Y, as the lab's text suggests, the ratio comes out ≈ 1 and says
# nothing. The report's table 3.1 shows both readings and flags the second:
t31 = {t.id: t for t in seed_tables(a4)}["3.1"]
print(f"I along the spring: {np.min(t31['I']):.3f} … {np.max(t31['I']):.3f}; "
      f"eq. (5) read along Y: {np.min(t31['I_Y']):.4f} … {np.max(t31['I_Y']):.4f}")
assert np.allclose(t31["I_Y"], 1.0, atol=0.01)

# %%
# The flattest spring — наиболее подходящая пружина
# -------------------------------------------------
# The file's spring is the least-squares optimum (rate ≥ 20 kN/m):
d4 = flattest_spring(four.mechanism, Y, "sp", TARGET, L_ROLLER, min_rate=20e3)
prm = four.mechanism.params
print(f"optimum: rate {d4.rate / 1e3:.2f} kN/m, preload {d4.preload / 1e3:.2f} kN; "
      f"the file: {prm['c'] / 1e3:.2f} kN/m, {prm['F0'] / 1e3:.2f} kN; spread {d4.spread:.1%}")
assert np.isclose(d4.rate, prm["c"], rtol=1e-3) and np.isclose(d4.preload, prm["F0"], rtol=1e-3)

# %%
# Four-bar against six-bar — сравнение (fig. 2.3)
# -----------------------------------------------
# The six-bar's lever lets the spring act through a transmission number that falls
# as the gap opens, so p_c stays far flatter:
six = io.load(io.bundled("conditioner_lab2_sixbar"))
d6 = flattest_spring(six.mechanism, six.range, "sp", TARGET, L_ROLLER, min_rate=20e3)
print(f"spread of p_c: four-bar {d4.spread:.2%}, six-bar {d6.spread:.2%}")
assert d6.spread < 0.2 * d4.spread

import matplotlib.pyplot as plt  # noqa: E402

from assur.views.report import drawing  # noqa: E402

fig, ax = plt.subplots(figsize=(6.4, 4.0))
ax.plot(Y * 1e3, d4.pressure / 1e3, label="four-bar / четырёхзвенник")
ax.plot(six.range * 1e3, d6.pressure / 1e3, label="six-bar / шестизвенник")
ax.axhline(TARGET / 1e3, color="grey", lw=0.8, ls="--")
ax.set_xlabel("gap between the rollers Y [mm]")
ax.set_ylabel("p_c [kN/m]")
ax.set_title("Specific pressure of the rollers — удельное давление вальцов")
ax.legend()
ax.grid(alpha=0.3)
plt.show()

# %%
drawn = drawing.draw(six.mechanism.analyze(six.range))

# %%
# Synthesis — the flattest pressure (``conditioner_lab2_design.toml``)
# ----------------------------------------------------------------------
# The spring's pins, rate and preload chosen so that p_c (the model's formula, a
# fused-kernel output by its name) varies least over the gap range, within ±5 % of
# p_target (``assur optimize``; a small budget here):
from assur.io import load_problem  # noqa: E402
from assur.synthesis.search.search import optimize  # noqa: E402

pb = load_problem(io.bundled("conditioner_lab2_design"))
res = optimize(pb, popsize=8, maxiter=40, seed=1)
print(f"span of p_c: {res.original.objectives[0, 0]:.0f} N/m → {res.value:.0f} N/m")
assert res.feasible and res.value < 0.5 * res.original.objectives[0, 0]

# %%
# The file's notes:
for note in four.mechanism.notes:
    print("-", note["en"] if isinstance(note, dict) else note)
