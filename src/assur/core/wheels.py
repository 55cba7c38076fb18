"""Wheels drawn on a mechanism: the one home of the concept.

A :class:`Wheel` is drawing data, not a body of the linkage: a wheel of a given
diameter and width, centred on a point of the mechanism and heading along a link —
a steered wheel on its kingpin turns with its steering lever (seed 001 lab 4), the
wheel of a tractor drawn under a hitch sits on a frame point with a fixed heading.
It takes no part in the kinematics or the forces. Its heading at every position is

    heading = φ_link + offset   [rad, from +x, counter-clockwise]

(``offset`` alone without a link): the wheel's rolling direction, along which its
diameter is drawn; its width is drawn across it. The drawings (the page, the inline
SVG, the report's figure and animation, the DXF) read the wheels through
:func:`assur.views.geometry.geometry` (key ``"wheels"``) and draw each as the
rectangle :func:`assur.views.geometry.wheel_outline`.

A model file declares them in ``[[wheels]]`` (docs/model-format.md); Python adds one
with :meth:`assur.Mechanism.wheel` and replaces them with
:meth:`assur.Mechanism.with_wheels`; they are kept in :attr:`assur.Mechanism.wheels`.

Examples
--------
>>> from assur import examples
>>> [(str(w.name), w.link, w.at) for w in examples.steering_lab4().wheels]
[('left wheel', 'w3', '03'), ('right wheel', 'w5', '05')]
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Union

__all__ = ["Wheel"]

Ref = Union[str, float, int]


@dataclass(frozen=True)
class Wheel:
    """A wheel drawn centred on point ``at``, heading along ``link`` turned by
    ``heading``.

    Parameters
    ----------
    name : str
        Its name (a :class:`assur.texts.Text` may carry translations).
    at : str
        The point it is centred on (a steered wheel: its kingpin).
    diameter : float or str
        Its drawn length along the heading, the tyre's diameter [m] (a number or a
        parameter name).
    width : float or str
        Its drawn width across the heading [m].
    link : str, optional
        A link whose direction φ the heading follows (a link of
        :meth:`~assur.Mechanism.link`, a distance's angle, or a link of the groups);
        None: a wheel that does not turn (on the frame), its heading is ``heading``
        from +x.
    heading : float or str
        The rolling direction relative to the link's direction (from +x without a
        link), counter-clockwise [rad].

    Examples
    --------
    >>> import math
    >>> from assur.core.wheels import Wheel
    >>> w = Wheel("left wheel", at="03", diameter=1.1, width=0.5, link="w3")   # [m]
    >>> w.heading, w.quantities["diameter"], w.quantities["heading"]
    (0.0, 'length', 'angle')
    >>> Wheel("rear", at="O", diameter=1.2, width=0.4, heading=math.pi / 2).link is None
    True
    """

    name: str
    at: str
    diameter: Ref
    width: Ref
    link: str | None = None
    heading: Ref = 0.0

    #: the kind of each value field (the model file's units)
    quantities: ClassVar = {"diameter": "length", "width": "length", "heading": "angle"}
    #: constraints on the values beyond their kind
    flags: ClassVar = {"diameter": "positive", "width": "positive"}
