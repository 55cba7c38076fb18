"""
The Python API in ten minutes
=============================

From a bundled model to positions, analogs, forces and a report, then a mechanism
of your own built group by group, and a batch of designs. Units are SI and angles
radians inside; the model files and the reports use the units you give them.
"""

# %%
# A bundled machine
# -----------------
# Every seed machine is one model file in ``src/assur/models/`` (``examples/`` in a
# checkout). :mod:`assur.examples` returns its :class:`~assur.Mechanism`;
# :func:`assur.io.load` returns the whole model (range, solved conditions, notes).
import numpy as np

from assur import examples, io

m = examples.hitch_003()                  # seed 003, the mini-tractor hitch
S = np.linspace(0.42, 0.67, 10)           # cylinder length S [m]
r = m.solve(S)                            # positions and exact analogs
print(np.round(r.phi("6", degrees=True), 2))   # implement angle φ6 [°]
print(np.round(r.dphi("3"), 3))                # dφ3/dS [rad/m]
print(np.round(r.ratio("6", "5"), 3))          # transfer ratio U65 = φ6'/φ5'
print(np.round(r.transmission("S6"), 3))       # IS6 = dY_S6/dS [m/m]

# %%
# ``to_frame`` gives a pandas table with the seed's symbols:
print(r.to_frame().iloc[:3, :8].round(4).to_string())

# %%
# Forces, cylinders, stability
# ----------------------------
# :meth:`~assur.Mechanism.analyze` adds the loads of the model: the cylinder force
# by virtual work, the joint reactions by Assur groups in reverse order, the
# pressure, the lift capacity and the machine's stability.
a = m.analyze(S)
cyl = a.cylinder("ГЦ")
print(f"force {cyl.force[0]:.0f} N, pressure {cyl.pressure[0] / 1e6:.2f} MPa, "
      f"capacity at 56 {cyl.capacity('56')[0]:.0f} N at S = {S[0]} m")
print("reaction of the frame on link 5 at 05 [N]:", np.round(a.statics.reaction("0", "5")[0]))
print("share of the weight on the steered axle [%]:", np.round(a.stability.share("A"), 1))

# %%
# A mechanism of your own
# -----------------------
# The builder has one method per group type (:doc:`../_generated/groups`); lengths
# are numbers [m] or parameter names, angles numbers [rad]. ``branch`` picks the
# assembly: +1 puts the new joint left of the directed line between the group's
# outer joints.
from assur import Mechanism  # noqa: E402

lift = (Mechanism("lift", coordinates=("S",), params={"L3": 0.2, "L4": 0.66, "L5": 0.48})
        .frame("01", 0.415, 0.563).frame("03", 0.25, 1.112).frame("05", 0.135, 0.48)
        .cylinder_lever("I", base="01", pivot="03", out="23", lever="L3", s="S", branch=-1,
                        links=("2", "3"))
        .rigid_point("arm", origin="03", toward="23", out="34", length=0.325, angle=0.384)
        .dyad("II", a="34", b="05", out="45", ra="L4", rb="L5", branch=+1, links=("4", "5"))
        .link("3", "03", "23").link("5", "05", "45"))
k = lift.solve(S)
print(np.round(k.phi("5", degrees=True), 2))

# %%
# A batch of designs
# ------------------
# Every parameter may be an array over designs; results then have the shape
# ``(designs, positions)``. Here 1000 values of L4 at once:
batch = lift.solve(S, params={"L4": np.linspace(0.62, 0.70, 1000)})
print(batch.phi("5").shape)

# %%
# A report
# --------
# :func:`assur.views.report.write_report` writes what ``assur analyze`` writes: the seed's
# tables (CSV, XLSX), figures, the drawing, an animation and one HTML file. The
# figures are also available one by one:
from assur.views.report import drawing, figures  # noqa: E402

drawn = drawing.draw(a, lang="ru")
transmission_figure = figures.transmission(a)
