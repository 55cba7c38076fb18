"""The static tipping load of a machine on two axles: the load at a point of its
mechanism at which the axle farther from the load is unloaded (ISO 14397-1 §3, our
words; the crane chart's stability limit).

The machine (``[machine]``, :class:`assur.machines.stability.Machine`) stands on two
axles; its weights and counterweights are fixed, the mechanism's own loads (the
boom's weight, the bucket's) move with it. A vertical load W at the point P at x_P
changes the reaction of each axle linearly, R(W) = R_0 + c·W: R_0 and c are those of
:func:`assur.machines.stability.axle_reactions` (moments about the other axle), with
the mechanism's vertical loads added each at its point's x. The machine tips about
the axle nearer to P when the farther axle's reaction reaches zero:

.. math::

    W_{tip} = -R_{0,far} / c_{far} \\qquad (c_{far} < 0),

``inf`` where the load does not unload the farther axle (P between the axles), 0 where
the machine alone already lifts it.
"""

from __future__ import annotations

import copy

import numpy as np

from ...core.virtual_work import applied_loads
from ...errors import ModelError
from ..stability import axle_reactions
from .base import number

__all__ = ["tipping_load", "machine_of"]


def machine_of(mech):
    """The :class:`assur.machines.stability.Machine` of ``mech``'s ``[machine]`` with its
    numbers from the model's parameters (one design).

    Raises
    ------
    ModelError
        If the model describes no machine.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.machines.ratings.stability import machine_of
    >>> machine_of(examples.hitch_003()).axles    # seed 003 §6 [m]
    {'A': -2.96, 'B': 0.0}
    """
    if mech.machine is None:
        raise ModelError(f"{mech.name}: a tipping load needs the machine's axles and weights "
                         f"([machine])")
    carrying = mech.machine
    return carrying.machine_for({r: number(mech, r) for r in carrying.ref_names()})


def tipping_load(mech, kin, point, carried=None, x=None):
    """The static tipping load at ``point`` over the positions of ``kin`` (one design)
    [N] (module notes).

    Parameters
    ----------
    mech : Mechanism
        With a ``[machine]``.
    kin : Kinematics
        The positions, one design.
    point : str
        Where the load acts (a bucket's centre of gravity, a crane's hook).
    carried : Mechanism, optional
        A mechanism whose loads' vertical forces the machine carries besides the load
        (:func:`assur.machines.ratings.carried_loads`); None: the machine's own weights
        only.
    x : ndarray, optional
        The load's horizontal coordinate over the positions [m], where it acts at no
        named point (a point of a body between two named ones); default: ``point``'s.

    Examples
    --------
    The seed-003 tractor, a load at its hitch point 56 behind the rear axle B: it
    tips about B when the front axle A is unloaded, W·x56 = −ΣP·x (moments about B):

    >>> from assur import examples
    >>> from assur.machines.ratings.stability import tipping_load
    >>> m = examples.hitch_003()
    >>> kin = m.solve([0.42])
    >>> from assur.machines.ratings.stability import machine_of
    >>> W = tipping_load(m, kin, "56")
    >>> x = float(kin.x("56")[0])
    >>> mach = machine_of(m)
    >>> M = sum(P * xi for _, P, xi in mach.weights + mach.counterweights)   # about B [N·m]
    >>> round(float(W[0] * x + M), 6)
    0.0
    """
    machine = machine_of(mech)
    x = np.asarray(kin.x(point) if x is None else x, float).reshape(-1)
    names = list(machine.axles)
    xa = np.array([machine.axles[n] for n in names])
    far = np.argmax(np.abs(x[:, None] - xa[None, :]), axis=1)   # (n,)

    def reaction(W, at):
        r = axle_reactions(machine, W, at).reactions
        a, b = (np.broadcast_to(np.asarray(r[n], float), at.shape) for n in names)
        return np.where(far == 0, a, b)

    R0 = reaction(0.0, x)
    c = reaction(1.0, x) - R0
    if carried is not None:
        k2 = copy.copy(kin)
        k2.mechanism = carried
        forces, _, _ = applied_loads(k2, g=mech.g)
        for _, pt, _, fy in forces:
            xp = np.asarray(kin.x(pt), float).reshape(-1)
            P = -np.broadcast_to(np.asarray(fy, float), (kin.m, kin.n)).reshape(-1)
            R0 = R0 + reaction(P, xp) - reaction(0.0, xp)
    unloads = c < 0.0
    W = np.where(unloads, -R0 / np.where(unloads, c, -1.0), np.inf)
    return np.where(unloads & (R0 <= 0.0), 0.0, W)
