"""Small mechanisms and model texts that several test files use."""

from __future__ import annotations

import math
import re

from assur import Mechanism, io
from tests.helpers import DOCS

#: the lift of docs/model-format.md (its first TOML block) without its ``[[solve]]``
#: blocks (no solving: fast), as a model file's text
LIFT = re.sub(r"(?ms)^\[\[solve\]\].*", "", re.search(
    r"```toml\n(.*?)```", (DOCS / "model-format.md").read_text(encoding="utf-8"), re.S).group(1))


def crank_dyad():
    """A crank and a dyad that cannot close for q in (1.3125, 1.829) rad: |AB|² =
    10 − 6 sin q must stay ≥ (ra − rb)² = 2.05² (seed-free)."""
    return (Mechanism("crank-dyad", coordinates=("q",), params=dict(ra=2.65, rb=0.6))
            .frame("O", 0.0, 0.0).frame("B", 0.0, 3.0)
            .crank("crank", pivot="O", out="A", radius=1.0, q="q", links=("1",))
            .dyad("II", a="A", b="B", out="C", ra="ra", rb="rb", branch=1, links=("2", "3")))


#: a four-bar driven by a crank, its fixed pivot placed by length and angle (a model file
#: with the slots {extra_params} and {extra})
FOURBAR = """
[model]
name = "fourbar"
coordinates = ["q"]

[params]
r = "0.1 m"
c = "0.5 m"
k = "0.3 m"
d = "0.45 m"
a = "10 deg"
{extra_params}

[range]
q = {{ from = 0, to = 360, count = 25 }}

[frame]
O = [0, 0]
P = {{ origin = "O", length = "d", angle = "a" }}

[[groups]]
type = "crank"
name = "crank"
pivot = "O"
out = "A"
radius = "r"
q = "q"
links = ["1"]

[[groups]]
type = "dyad"
name = "II"
a = "A"
b = "P"
out = "B"
ra = "c"
rb = "k"
branch = 1
links = ["2", "3"]

[links]
"3" = ["P", "B"]

{extra}
"""



def load_fourbar(extra="", extra_params=""):
    """The four-bar's model file with ``extra`` sections and ``extra_params``."""
    return io.loads(FOURBAR.format(extra=extra, extra_params=extra_params), name="fourbar.toml")



def python_fourbar(**kw):
    """The four-bar built in Python."""
    return (Mechanism("fourbar", coordinates=("q",),
                      params=dict(r=0.1, c=0.5, k=0.3, d=0.45, a=math.radians(10)))
            .frame("O", 0, 0).frame("P", origin="O", length="d", angle="a")
            .crank("crank", pivot="O", out="A", radius="r", q="q", links=("1",))
            .dyad("II", a="A", b="P", out="B", ra="c", rb="k", branch=1, links=("2", "3"))
            .link("3", "P", "B"))

