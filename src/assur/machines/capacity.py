"""Lift capacity of several cylinders: which points each can lift, dead loads, the
minimum over the positions and the farthest reach (seed 001 lab 1, eqs. 10, 14, 14a).

A loader's boom cylinder S lifts the suspension axis 09 and everything the boom
carries; its traverse cylinder S1 only turns the traverse about 09. The capacity of
a cylinder at a point, G = (σ_w·F_max,w·η_m − F_dead)/I with I = ∂Y/∂q of the point
along the cylinder's coordinate q and σ_w, F_max,w of the chamber of the stroke's
working direction (positive for a pulling cylinder too; :mod:`assur.core.cylinders`
has the sign diagram) (:meth:`assur.machines.cylinders.CylinderResult.capacity`), has
a meaning only for the points of the chain that cylinder drives
(:mod:`assur.core.chains`); elsewhere I ≡ 0 and the capacity is left out, with a note.

Dead loads (lab 1 eq. 14): the capacity of the boom cylinder carries the boom's own
weight, m_po·g·I_S9 + m_str·g·I_S3 = 2·F_max·η (eq. 10), so

.. math::

    G(S, S_1) = \\frac{2 p_{max} F_n \\eta - m_{str} g I_{S3}(S)}{I_{S9}(S, S_1)},

which is eq. (14) solved for the weight G = m_po·g (eq. 14 writes the same with
m_str/m_po inside the bracket). A model names the links whose loads are dead loads
(``[tables] dead_loads = ["3"]``, :meth:`Mechanism.with_tables`); their weights and
masses are then carried in every capacity, through the virtual work of those loads
along the cylinder's coordinate (zero for a cylinder that does not move them). A
dead load is never the load to lift: the reserve (G − P)/P is against the payload P
alone, since G has already paid for the dead loads.
"""

from __future__ import annotations

import numpy as np

from ..core.chains import point_coordinates
from ..core.loads import dead_load_links, load_link
from ..errors import ModelError

__all__ = ["dead_load_links", "dead_load_mechanism", "check_lifts", "lifts", "farthest_reach"]


def dead_load_mechanism(mech, links=None):
    """The mechanism with only the loads acting on ``links`` (default: the model's
    dead-load links), or None when there are none.

    Raises
    ------
    ModelError
        If a link carries no load (a misspelt link name would silently carry nothing).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.machines.capacity import dead_load_mechanism
    >>> m = examples.loader_lab1()
    >>> dead_load_mechanism(m).loads      # the boom's mass m_str at S3 (seed 001 lab 1)
    (Mass(link='3', m='m_str', point='S3', J=0.0),)
    >>> print(dead_load_mechanism(examples.hitch_003()))
    None
    >>> dead_load_mechanism(m, "4")   # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: loader_lab1: dead loads on links ['4']: no load acts on it ...
    """
    if isinstance(links, str):
        links = (links,)
    links = dead_load_links(mech) if links is None else tuple(links)
    if not links:
        return None

    def make():
        keep = tuple(ld for ld in mech.loads if load_link(mech, ld) in links)
        empty = [l for l in links if not any(load_link(mech, ld) == l for ld in keep)]
        if empty:
            raise ModelError(f"{mech.name}: dead loads on links {empty}: no load acts on "
                             f"{'it' if len(empty) == 1 else 'them'} (add a [[loads]] weight "
                             f"or mass on the link)")
        return mech.with_loads(keep)

    return mech.memo(("capacity", "dead loads", links), make)


def lifts(mech, coordinate, point) -> bool:
    """True if the cylinder on ``coordinate`` moves ``point`` (its capacity there has
    a meaning).

    Examples
    --------
    The loader of seed 001 lab 1: the boom cylinder S lifts the boom's centre S3 and
    the load S9; the traverse cylinder S1 only turns the traverse, moving S9:

    >>> from assur import examples
    >>> from assur.machines.capacity import lifts
    >>> m = examples.loader_lab1()
    >>> lifts(m, "S", "S3"), lifts(m, "S", "S9")
    (True, True)
    >>> lifts(m, "S1", "S3"), lifts(m, "S1", "S9")
    (False, True)
    """
    return coordinate in point_coordinates(mech, point)


def check_lifts(mech, coordinate, point, name=None):
    """Raise :class:`ModelError` if the cylinder on ``coordinate`` does not move
    ``point`` (its transmission number there is identically zero).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.machines.capacity import check_lifts
    >>> m = examples.loader_lab1()
    >>> check_lifts(m, "S", "S3")      # the boom cylinder lifts the boom: no error
    >>> check_lifts(m, "S1", "S3", name="MPT")   # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: loader_lab1: capacity of cylinder 'MPT' on S1 ...(moved by: S)
    """
    if not lifts(mech, coordinate, point):
        who = f"cylinder {name!r}" if name else "the cylinder"
        movers = sorted(point_coordinates(mech, point)) or ["none"]
        raise ModelError(f"{mech.name}: capacity of {who} on {coordinate} at {point!r} is "
                         f"undefined: {coordinate} does not move {point!r} (moved by: "
                         f"{', '.join(movers)})")


def farthest_reach(kin, point, design=None):
    """Index of the position where ``point`` is farthest forward (largest x): the
    position (S*, S1*) of lab 1 eq. 14a. For a batch give ``design``.

    Examples
    --------
    The loader of seed 001 lab 1 over its 13 × 8 grid of (S, S1):

    >>> from assur import examples
    >>> from assur.machines.capacity import farthest_reach
    >>> q = examples.loader_lab1_range()
    >>> kin = examples.loader_lab1().solve(q)
    >>> i = farthest_reach(kin, "S9")
    >>> i, [round(float(v), 3) for v in q[i]]     # (S*, S1*) [m]
    (31, [1.163, 0.92])
    >>> round(float(kin.x("S9")[i]), 3)           # its reach X9 [m]
    3.324
    """
    x = np.asarray(kin.x(point))
    if x.ndim == 2:
        if design is None:
            raise ValueError("a batch of designs: choose one with design=<index>")
        x = x[design]
    return int(np.argmax(x))
