"""Mechanisms of a given number of structural groups, for compile-time measurements
and tests: the seed-003 hitch plus extra rigid points, and a chain of RRR dyads."""

from __future__ import annotations

import math

import numpy as np

from assur import Dyad, Frame, RigidPoint, examples

__all__ = ["hitch_plus_rigid", "dyad_chain", "with_groups"]


def hitch_plus_rigid(n_extra: int):
    """``examples.hitch_003()`` (4 groups) plus ``n_extra`` rigid points on links 3, 5
    and 6 in turn, each with parameters of its own (length, angle)."""
    m = examples.hitch_003()
    carriers = (("03", "23"), ("05", "56"), ("56", "67"))
    params, groups = {}, []
    for i in range(n_extra):
        o, t = carriers[i % 3]
        params[f"lr{i}"] = 0.05 + 0.3 * ((i * 0.618) % 1.0)
        params[f"br{i}"] = -math.pi + 2 * math.pi * ((i * 0.382) % 1.0)
        groups.append(RigidPoint(name=f"R{i}", origin=o, toward=t, out=f"R{i}",
                                 length=f"lr{i}", angle=f"br{i}"))
    return m.extended(groups, params)


def dyad_chain(n_dyads: int, q_ref: float = 0.545):
    """The hitch's frame and cylinder–lever group (point 23) followed by a chain of
    ``n_dyads`` RRR dyads, each with a frame point of its own (2 groups per dyad):
    dyad i joins the previous joint (23 for the first) and frame point F{i} at a
    right angle, so each dyad passes on at most the motion it receives."""
    base = examples.hitch_003()
    pts = base.evaluate_positions({"S": np.array([q_ref])})
    px, py = (float(v[0]) for v in pts["23"])
    params = dict(base.params)
    groups = list(base.groups[:5])  # frames 01…07 and the cylinder–lever group
    prev = "23"
    for i in range(n_dyads):
        th = 2.399963 * i  # golden angle: directions spread over the circle
        ra, rb = 0.2 + 0.1 * ((i * 0.618) % 1.0), 0.25
        cx, cy = px + ra * math.cos(th), py + ra * math.sin(th)
        fx, fy = cx - rb * math.sin(th), cy + rb * math.cos(th)
        params.update({f"XF{i}": fx, f"YF{i}": fy, f"ra{i}": ra, f"rb{i}": rb})
        groups.append(Frame(name=f"F{i}", x=f"XF{i}", y=f"YF{i}"))
        # branch: C on the left (+1) or right of A → B
        cr = (fx - px) * (cy - py) - (fy - py) * (cx - px)
        groups.append(Dyad(name=f"D{i}", a=prev, b=f"F{i}", out=f"C{i}", ra=f"ra{i}",
                           rb=f"rb{i}", branch=1 if cr > 0 else -1,
                           links=(f"a{i}", f"b{i}")))
        prev, px, py = f"C{i}", cx, cy
    from assur import Mechanism
    return Mechanism("dyad_chain", coordinates=base.coordinates, params=params,
                     groups=groups, links=())


def with_groups(kind: str, n: int):
    """A mechanism of about ``n`` kernel groups (rows) of the given kind."""
    if kind == "rigid":
        return hitch_plus_rigid(max(n - 10, 0))
    return dyad_chain(max((n - 5) // 2, 0))
