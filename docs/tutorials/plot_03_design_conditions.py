"""
Design conditions (Given/Find)
==============================

A Mathcad worksheet fixes unknown lengths with Given/Find blocks. A model file
writes each as a ``[[solve]]`` condition: choose the parameter ``unknown`` inside
``bracket`` so that ``quantity`` equals ``equals`` at the position ``at``.
Conditions are solved in dependency order by a scan of the bracket and Brent's
method (:mod:`assur.synthesis.conditions`); no root, or more than one, in the bracket is an
error that names the condition and its line.
"""

# %%
# Seed 003's three conditions
# ---------------------------
# ``hitch_003.toml`` (§2.2–2.3 of the seed): L4 such that Y56(Smin) = 0.2 m, the
# working stroke Sp such that Y56(Sp) = 0.4 m, L7 such that φ6(Sp) = 90°:
from assur import io
from assur.views.report.values import solved_line

model = io.load(io.bundled("hitch_003"))
text = io.bundled("hitch_003").read_text(encoding="utf-8")
blocks = text.split("\n[[solve]]")[1:]
print("\n\n".join("[[solve]]" + b.split("\n\n")[0] for b in blocks))
for s in model.solved:
    print(solved_line(s, model.mechanism, "en"))

# %%
# A condition without a root
# --------------------------
# Asking for Y56(Smin) = 2 m — out of reach — is refused with the file, the line of
# the ``[[solve]]`` entry and the bracket searched:
bad = text.replace('equals = "0.2 m"', 'equals = "2 m"', 1)
try:
    io.loads(bad, name="hitch_003.toml")
except io.ModelFileError as e:
    print(e)
