"""
Branches and assembly failures
==============================

A dyad closes a triangle: given its two outer joints and two lengths, its middle
joint is on one side or the other of the line between them. The side is the group's
**branch**, given explicitly (``branch = +1``: on the left of the directed line
from the first outer joint to the second, ``-1``: on the right) and kept between
positions: the engine checks that no dyad flattens or opens between two consecutive
positions. When a triangle cannot close, assur raises an
:class:`~assur.AssemblyError` — never a NaN or a complex number.
"""

# %%
# The two branches of one dyad
# ----------------------------
import numpy as np

from assur import AssemblyError, Mechanism

q = np.radians(np.arange(0.0, 360.0, 30.0))


def four_bar(branch, ra=0.40):
    """A crank A0–A and an RRR dyad (A, B0) → C on the given branch."""
    return (Mechanism("four-bar", coordinates=("j1",), params={"ra": ra})
            .frame("A0", 0.0, 0.0).frame("B0", 0.4, 0.0)
            .crank("crank", pivot="A0", out="A", radius=0.12, q="j1", links=("1",))
            .dyad("II", a="A", b="B0", out="C", ra="ra", rb=0.30, branch=branch,
                  links=("2", "3")))


for branch in (+1, -1):
    k = four_bar(branch).solve(q)
    print(f"branch {branch:+d}: y of C from {k.y('C').min():+.3f} to {k.y('C').max():+.3f} m")

# %%
# A triangle that cannot close
# ----------------------------
# With ra = 0.15 m the dyad cannot reach B0 from A at every crank angle. The message
# names the group, its links, the lengths, the violated inequality with its numbers
# and the first failing position; the exception carries the same as data:
try:
    four_bar(+1, ra=0.15).solve(q)
except AssemblyError as e:
    print(e)
    print("group", e.group, "links", e.links, "position", e.position,
          f"amount {e.amount * 1e3:.1f} mm")

# %%
# How to read it: *"RRR dyad 'II' (links 2, 3)"* is the group and its links;
# *"at position k (j1 = …°)"* the first position where it fails; then the
# inequality that does not hold — the distance between the outer joints against the
# sum (or the difference) of the two lengths — and by how much; last, how many
# positions fail and over which range. Lengthen or shorten one of the named links by
# at least that amount, or restrict the range to the positions that assemble.
#
# Failures as data
# ----------------
# A batch of designs reports instead of raising: an ``ok`` mask over
# ``(designs, positions)`` and a message per failure.
r = four_bar(+1).solve(q, params={"ra": np.array([0.15, 0.40])}, on_failure="report")
print(r.ok.astype(int))
print(r.failures[0])

# %%
# The seed that could not assemble
# --------------------------------
# Seed 000's worksheet has a bell-crank triangle whose third side is longer than the
# other two together; its tables are full of complex numbers. assur says why
# (the :doc:`gallery example <../auto_gallery/plot_000_header>` goes on from here):
from assur import io  # noqa: E402

header = io.load(io.bundled("header_000"))
try:
    header.mechanism.solve(header.range)
except AssemblyError as e:
    print(e)
