"""Small mechanisms and model texts that several test files use."""

from __future__ import annotations

import re

from assur import Mechanism
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
