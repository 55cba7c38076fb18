"""One sample mechanism per registered group type (:data:`SAMPLES`), drawn by the
builder of :mod:`tests.helpers.analogs`: the group contract
(:mod:`tests.groups.test_base`) and the numpy kernel (:mod:`tests.kernel.test_vector`)
run on every type through it. A new group type adds its :class:`Sample` here
(docs/adding-a-group.md)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from tests.helpers.analogs import Builder, _dir, _norm


@dataclass(frozen=True)
class Sample:
    """A sample mechanism for one group type.

    ``build(data)`` returns the :class:`Builder` (one structure per type);
    ``group`` is the name of the group under test; ``loaded`` the links to load
    (None: the group's own links, ``topology.group_links``, moving ones);
    ``breaks(b)`` the parameter values {name: value} that make the group unable to
    assemble at the reference pose, or None when the type cannot fail."""

    build: Callable
    group: str
    breaks: Callable | None
    loaded: tuple[str, ...] | None = None



def _crank(data):
    b = Builder(data, "contract: crank", ("th",))
    b.input("crank", "th")  # frame A0, crank "crank" (link 1) A0 → A
    b.link("1", "A0", "A")
    return b



def _cylinder_lever(data):
    b = Builder(data, "contract: cylinder-lever", ("S",))
    b.input("cylinder-lever", "S", sigma=1)  # frames 01, 03; cylinder 2, lever 3
    b.link("3", "03", "23")
    return b



def _break_cylinder_lever(b):
    # lever longer than |01–03| + S: the triangle 01, 03, 23 cannot close
    base = _norm(b.pos["03"] - b.pos["01"])
    return {"L23": base + 2.0 * b.q0["S"] + 0.1}



def _dyad(data):
    b = Builder(data, "contract: dyad", ("th",))
    b.fourbar("th")  # crank A0–A, dyad II (A, B0) → C
    b.link("2", "A", "C")
    return b



def _break_dyad(b):
    # ra > |A–B0| + rb: C cannot reach both
    return {"raC": _norm(b.pos["B0"] - b.pos["A"]) + np.asarray(b.params["rbC"]) + 0.1}



def _slider_input(data):
    b = Builder(data, "contract: slider input", ("s",))
    b.frame_random("O")
    b.slider_input("O", "B", "s")
    b.frame_near("F", "B", 0.4, 1.2)
    b.dyad("II", "F", "B", "C", 1)
    return b



def _slider_dyad(data):
    b = Builder(data, "contract: slider dyad", ("th",))
    b.input("crank", "th")
    beta = b.draw(-math.pi, math.pi, "line direction")
    b.frame_near("L0", "A", 0.2, 0.8)
    b.slider_dyad("III", "A", "X", "L0", 1, beta)
    return b



def _break_slider_dyad(b):
    # move the line's point L0 across the line to r + 0.1 from A: out of reach
    u = _dir(np.broadcast_to(b.params["betaX"], (b.M,)))
    n = np.stack([-u[:, 1], u[:, 0]], -1)
    L0 = b.pos["A"] + (np.asarray(b.params["rX"]) + 0.1)[..., None] * n
    return {"XL0": L0[:, 0], "YL0": L0[:, 1]}



def _rigid_point(data):
    b = Builder(data, "contract: rigid point", ("th",))
    b.input("crank", "th")
    b.rigid_angle("P", "A0", "A", "P")
    b.rigid_triangle("T", "A", "A0", "T", 1)
    b.link("T", "A", "T")
    return b



def _break_rigid_point(b):
    # the opposite side longer than the other two: no triangle
    return {"oppT": np.asarray(b.params["baseT"]) + np.asarray(b.params["lT"]) + 0.1}



def _pose_point(data):
    b = Builder(data, "contract: pose point", ("th",))
    b.fourbar("th")
    b.pose_point("S6", "C", "A", "S6", "th")
    b.link("6", "C", "S6")
    return b



def _rpr_dyad(data):
    b = Builder(data, "contract: RPR dyad", ("th",))
    b.input("crank", "th")
    b.frame_near("B0", "A", 0.3, 1.0)
    b.rpr_dyad("III", "B0", "A", "D", 1)
    b.link("rod", "B0", "D")
    return b



def _break_rpr_dyad(b):
    # the sleeve's offset larger than |B0–A|: the rod cannot reach the sleeve
    return {"eD": _norm(b.pos["A"] - b.pos["B0"]) + 0.1}



def _prp_dyad(data):
    b = Builder(data, "contract: PRP dyad", ("s",))
    b.frame_random("O")
    b.slider_input("O", "B", "s")
    b.prp_dyad("III", "B", "D", "F")
    return b



def _break_prp_dyad(b):
    # both lines at the same fixed direction: parallel, no intersection
    return {"dirbD": b.params["diraD"]}



SAMPLES = {
    "frame": Sample(_crank, "A0", None, loaded=("1",)),
    "crank": Sample(_crank, "crank", None),
    "cylinder_lever": Sample(_cylinder_lever, "cylinder-lever", _break_cylinder_lever),
    "dyad": Sample(_dyad, "II", _break_dyad),
    "slider_input": Sample(_slider_input, "slider", None),
    "slider_dyad": Sample(_slider_dyad, "III", _break_slider_dyad),
    "rigid_point": Sample(_rigid_point, "T", _break_rigid_point),
    "pose_point": Sample(_pose_point, "S6", None),
    "rpr_dyad": Sample(_rpr_dyad, "III", _break_rpr_dyad),
    "prp_dyad": Sample(_prp_dyad, "III", _break_prp_dyad),
}

