"""
Seed 000: the combine header lift and its diagnosis — Подъём жатки: диагноз
===========================================================================

Seed ``000_04e80bfff5466283.txt`` is a Mathcad worksheet of a combine header lift
whose tables are full of complex numbers (``…i``). Its input cannot assemble: the
bell-crank triangle L3, L34, L4 cannot close. This example shows what assur says
about it, where the seed's real numbers still agree, and the corrected header.

Таблицы источника 000 полны комплексных чисел: треугольник L3, L34, L4 качалки не
замыкается. Здесь — что об этом говорит assur, где числа источника действительны и
совпадают, и исправленный механизм.
"""

# %%
# The seed as printed — источник как напечатан
# --------------------------------------------
# ``header_000.toml`` loads (the file is well-formed); solving the mechanism over
# its range raises :class:`assur.AssemblyError`, which names the group, its links,
# the three sides, the violated inequality with its numbers and the first failing
# position:
import numpy as np

from assur import AssemblyError, io

model = io.load(io.bundled("header_000"))
S = model.range  # S = 0.65 … 0.80 m, 16 positions
try:
    model.mechanism.solve(S)
except AssemblyError as e:
    error = e
print(error)

# %%
# The error is data too: the group, its links, the first failing position and by
# how much the inequality is violated [m]:
print(error.group, error.links, {k: float(v) for k, v in error.coordinate.items()},
      f"{error.amount * 1e3:.2f} mm")
assert error.group == "arm 46" and "L4 exceeds L3 + L34 = 0.65234 m by 4.66 mm" in str(error)

# %%
# The seed computes DELFI = acos((L3² + L4² − L34²)/(2·L3·L4)); its argument is
# 1.0199 > 1, so DELFI is complex, and so is everything after it:
p = model.mechanism.params
arg = (p["L3"] ** 2 + p["L4"] ** 2 - p["L34"] ** 2) / (2 * p["L3"] * p["L4"])
print(f"argument of the seed's acos: {arg:.4f}")
assert round(arg, 4) == 1.0199

# %%
# A batch asks for the failures as data instead (``on_failure="report"``): no NaN and
# no complex number anywhere, an ``ok`` mask and one message per failure:
r = model.mechanism.solve(S, on_failure="report")
print(f"{(~r.ok).sum()} of {r.ok.size} positions fail; first message:\n{r.failures[0]}")

# %%
# What the seed gets right — где источник прав
# --------------------------------------------
# The cylinder–lever group comes before the broken triangle, so the seed's lever
# angle FI3 and its analog DFI3 are real. They agree with the engine on a header
# whose triangle closes (L4 = 0.652 m changes nothing before the triangle):
fixed = io.load(io.bundled("header_000_fixed"))
kin = fixed.mechanism.solve(S)
# seed 000, Табл. 1 (FI3 [°]) and Табл. 4 (DFI3 [rad/m], its first six legible rows)
FI3_PRINTED = np.array([5.188, 8.562, 11.971, 15.428, 18.945, 22.537, 26.219, 30.011,
                        33.935, 38.022, 42.309, 46.845, 51.702, 56.985, 62.866, 69.668])
DFI3_PRINTED = np.array([5.864, 5.916, 5.988, 6.082, 6.199, 6.342])
fi3, dfi3 = kin.phi("3", degrees=True), kin.dphi("3")
tol = 0.5e-3 * (1 + 1e-9)
assert np.all(np.abs(fi3 - FI3_PRINTED) <= tol) and np.all(np.abs(dfi3[:6] - DFI3_PRINTED) <= tol)
print("S [m]  FI3 computed  printed   DFI3 computed  printed")
for i in range(6):
    print(f"{S[i]:.2f}  {fi3[i]:12.3f}  {FI3_PRINTED[i]:7.3f}   {dfi3[i]:13.3f}  "
          f"{DFI3_PRINTED[i]:7.3f}")

# %%
# The corrected header — исправленный механизм
# --------------------------------------------
# ``header_000_fixed.toml`` extends the seed's file with an illustrative
# L4 = 0.652 m. It assembles, and the whole worksheet follows: transmission numbers,
# the force on the two cylinders and the share of their maximum force for the
# seed's candidate bores D = 80, 63, 50 mm (its table 5).
from assur.views.report import drawing, figures  # noqa: E402

a = fixed.mechanism.analyze(S)
drawn = drawing.draw(a)

# %%
cyl = a.cylinder()
for D in (0.080, 0.063, 0.050):
    share = cyl.share(bore=D)
    print(f"D = {D * 1e3:.0f} mm: the lift needs {share.min():.2f} … {share.max():.2f} "
          f"of the two cylinders' maximum force")
transmission_figure = figures.transmission(a)

# %%
# With the seed's P = 1500 kgf the 80 mm pair uses about half its maximum force —
# what the real parts of the seed's complex table 5 suggest (0.34 … 0.52):
share80 = cyl.share(bore=0.080)
assert 0.3 < share80.min() and share80.max() < 0.6

# %%
# The seed's other slips (the file's notes): FIS6 is overwritten by hand, delI lacks
# the factor U54, and P = 1500 is in kgf.
for note in model.mechanism.notes:
    print("-", note["en"] if isinstance(note, dict) else note)
