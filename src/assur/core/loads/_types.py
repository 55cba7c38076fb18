"""The load types of assur: weights, forces, moments, resisting moments, springs and
masses, each registered with its fields declared once (:mod:`assur.core.loads`)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ._registry import Load, Ref, param, register

__all__ = ["Weight", "PointForce", "Couple", "ResistingMoment", "Spring", "Mass"]


def _along_gravity(c, P):
    """The force of magnitude P along the context's direction of gravity: (fx, fy),
    an exact zero for a zero component (so the default weight is (0, −P))."""
    ux, uy = c.gravity_unit
    return (0.0 if ux == 0 else P * ux), (0.0 if uy == 0 else P * uy)


@register
@dataclass(frozen=True)
class Weight(Load):
    """Weight ``P`` [N] acting along gravity at ``point`` — downward unless the model
    turns gravity (``[model] gravity``, :func:`assur.core.statics.gravity_unit`) —, carried
    by ``link`` (by default the link that owns the point).

    Examples
    --------
    1000 N at the implement's centre of mass S6 of the seed-003 hitch: the cylinder
    pushes P·IS6.

    >>> from assur import examples
    >>> from assur.core.loads import Weight
    >>> m = examples.hitch_003().with_loads([Weight("S6", 1000.0)])
    >>> [round(float(f), 1) for f in m.analyze([0.42, 0.67]).statics.actuator_force()]  # [N]
    [4713.2, 4932.8]

    The builder ``Mechanism.weight`` adds one: the seed's P6 = 27.5 kN at S6 asks
    P6·IS6 of the cylinder (seed 003 table 4.1):

    >>> m = examples.hitch_003().with_loads().weight("S6", 27500.0)
    >>> round(float(m.analyze([0.42]).statics.actuator_force("S")[0]))  # [N]
    129614
    """

    point: str = param("point", doc="the point it acts at")
    P: Ref = param("value", "force", "nonneg", doc="its magnitude, along gravity [N]")
    link: str | None = param("link", default=None,
                             doc="the link that carries it (default: the point's owner)")
    name: str | None = param("name", default=None, doc="its name in reports")

    type_name: ClassVar = "weight"
    summary: ClassVar = "a weight P along gravity (downward by default) at a point"

    def apply(self, c):
        """Apply the weight to the load context ``c``: the force P·u at the point, u
        the direction of gravity (module notes).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import Weight
        >>> from assur.core.statics import applied_loads   # calls apply with its context
        >>> m = examples.hitch_003().with_loads([Weight("S6", "P6")])
        >>> forces, _, _ = applied_loads(m.solve([0.42]))
        >>> [(link, pt, float(fx), float(fy)) for link, pt, fx, fy in forces]  # [N]
        [('6', 'S6', 0.0, -27500.0)]
        """
        P = c.value(self.P)
        c.force(self.link or c.owner(self.point), self.point, *_along_gravity(c, P))


@register
@dataclass(frozen=True)
class PointForce(Load):
    """Force ``(fx, fy)`` [N] at ``point``, carried by ``link`` (default: owner).

    Examples
    --------
    A downward 1000 N at the hitch's suspension axis 56 asks P·I56 of the cylinder:

    >>> from assur import examples
    >>> from assur.core.loads import PointForce
    >>> m = examples.hitch_003().with_loads([PointForce("56", fy=-1000.0)])
    >>> [round(float(f), 1) for f in m.analyze([0.42, 0.67]).statics.actuator_force()]  # [N]
    [4459.4, 2621.3]

    The builder ``Mechanism.force``: a downward 27.5 kN at S6 asks of the cylinder
    what the seed's weight P6 does:

    >>> m = examples.hitch_003().with_loads().force("S6", fy=-27500.0)
    >>> round(float(m.analyze([0.42]).statics.actuator_force("S")[0]))  # P6·IS6 [N]
    129614
    """

    point: str = param("point", doc="the point it acts at")
    fx: Ref = param("value", "force", default=0.0, doc="its x component [N]")
    fy: Ref = param("value", "force", default=0.0, doc="its y component [N]")
    link: str | None = param("link", default=None,
                             doc="the link that carries it (default: the point's owner)")
    name: str | None = param("name", default=None, doc="its name in reports")

    type_name: ClassVar = "force"
    summary: ClassVar = "a force (fx, fy) at a point"

    def apply(self, c):
        """Apply the force to the load context ``c`` at its point.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import PointForce
        >>> from assur.core.statics import applied_loads
        >>> m = examples.hitch_003().with_loads([PointForce("56", fx=1000.0)])
        >>> forces, _, _ = applied_loads(m.solve([0.42]))
        >>> [(link, pt, float(fx), float(fy)) for link, pt, fx, fy in forces]  # [N]
        [('5', '56', 1000.0, 0.0)]
        """
        c.force(self.link or c.owner(self.point), self.point, c.value(self.fx),
                c.value(self.fy))


@register
@dataclass(frozen=True)
class Couple(Load):
    """Moment ``M`` [N·m], counter-clockwise positive, acting on ``link``.

    Examples
    --------
    100 N·m counter-clockwise on the hitch's lever 3: the cylinder holds −M·∂φ3/∂S.

    >>> from assur import examples
    >>> from assur.core.loads import Couple
    >>> m = examples.hitch_003().with_loads([Couple("3", 100.0)])
    >>> [round(float(f), 1) for f in m.analyze([0.42, 0.67]).statics.actuator_force()]  # [N]
    [-671.9, -623.9]

    The builder ``Mechanism.moment``: by virtual work the rod force is F = −M·φ6'
    (φ6' [rad/m], seed 003 table 3.1):

    >>> a = examples.hitch_003().with_loads().moment("6", 1000.0).analyze([0.42, 0.67])
    >>> [round(float(v), 1) for v in a.statics.actuator_force("S")]   # [N]
    [-294.9, -3084.9]
    >>> [round(float(v), 3) for v in a.kinematics.dphi("6")]          # [rad/m]
    [0.295, 3.085]
    """

    link: str = param("link", doc="the link it acts on")
    M: Ref = param("value", "moment", doc="counter-clockwise positive [N·m]")
    name: str | None = param("name", default=None, doc="its name in reports")

    type_name: ClassVar = "moment"
    summary: ClassVar = "a moment M on a link, counter-clockwise positive"

    def apply(self, c):
        """Apply the moment to the load context ``c``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import Couple
        >>> from assur.core.statics import applied_loads
        >>> m = examples.hitch_003().with_loads([Couple("3", 100.0)])
        >>> _, couples, _ = applied_loads(m.solve([0.42]))
        >>> [(link, float(M)) for link, M in couples]   # [N·m]
        [('3', 100.0)]
        """
        c.couple(self.link, c.value(self.M))


@register
@dataclass(frozen=True)
class ResistingMoment(Load):
    """A moment of magnitude ``M`` [N·m] on ``link`` that opposes the link's turn
    while the coordinate ``coordinate`` travels in the direction ``travel`` — the
    resisting moment of a steered wheel (seed 001 lab 4 eq. 17: M_c turns against
    the wheel whichever way it is steered)::

        travel = +1 (q grows):  φ' > 0  →  moment −M  (clockwise)
                                φ' < 0  →  moment +M  (counter-clockwise)

    that is ``moment = −M·sign(travel·∂φ_link/∂q)``; its virtual work along the
    travel, −M·|∂φ/∂q|, is never positive. ``travel = −1`` (q shrinks: the other
    turn) flips it. Where the link stands still (∂φ/∂q = 0) its work is zero either way.

    Parameters
    ----------
    link : str
    M : float or str
        Magnitude of the resisting moment [N·m] (≥ 0).
    travel : {1, -1}
        Direction of travel of the coordinate: +1 while it grows, −1 while it shrinks.
    coordinate : str, optional
        The coordinate whose travel is meant (default: the only one).
    name : str, optional

    Examples
    --------
    The hitch's lever 3 turns counter-clockwise while S grows (∂φ3/∂S > 0), so 100 N·m
    resisting it is −100 N·m, and the cylinder must push more to overcome it:

    >>> from assur import examples
    >>> from assur.core.loads import ResistingMoment
    >>> m = examples.hitch_003().with_loads([ResistingMoment("3", 100.0)])
    >>> [round(float(f), 1) for f in m.analyze([0.42, 0.67]).statics.actuator_force()]  # [N]
    [671.9, 623.9]

    The builder ``Mechanism.resisting_moment``: link 6 turns counter-clockwise as S
    grows (φ6' > 0), so 1000 N·m resisting that travel acts clockwise and the rod must
    push (compare ``Mechanism.moment``):

    >>> m = examples.hitch_003().with_loads().resisting_moment("6", 1000.0, travel=1)
    >>> [round(float(v), 1) for v in m.analyze([0.42, 0.67]).statics.actuator_force("S")]
    [294.9, 3084.9]
    """

    link: str = param("link", doc="the link it acts on")
    M: Ref = param("value", "moment", "nonneg", doc="its magnitude [N·m]")
    travel: int = param("sign", default=1,
                        doc="1: while the coordinate grows, -1: while it shrinks")
    coordinate: str | None = param("coordinate", default=None,
                                   doc="the coordinate whose travel it resists (default: "
                                       "the only one)")
    name: str | None = param("name", default=None, doc="its name in reports")

    type_name: ClassVar = "resisting_moment"
    summary: ClassVar = ("a moment that opposes the link's turn while the coordinate "
                         "travels that way: −M·sign(travel·∂φ/∂q) (seed 001 lab 4: the "
                         "wheel's M_c, eq. 17)")

    def check(self, mech):
        """A problem with this load in ``mech`` (a message), or None.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import ResistingMoment
        >>> m = examples.hitch_003()
        >>> print(ResistingMoment("3", 100.0).check(m))
        None
        >>> ResistingMoment("3", 100.0, travel=2).check(m)
        'travel must be 1 (the coordinate grows) or -1, got 2'
        >>> ResistingMoment("3", 100.0, coordinate="L3").check(m)
        "coordinate 'L3' is not a generalized coordinate ['S']"
        """
        if self.travel not in (1, -1):
            return f"travel must be 1 (the coordinate grows) or -1, got {self.travel!r}"
        if self.coordinate is None and len(mech.coordinates) > 1:
            return (f"name the coordinate whose travel it resists, one of "
                    f"{list(mech.coordinates)}")
        if self.coordinate is not None and self.coordinate not in mech.coordinates:
            return (f"coordinate {self.coordinate!r} is not a generalized coordinate "
                    f"{list(mech.coordinates)}")
        return None

    def apply(self, c):
        """Apply the moment ``−M·sign(travel·∂φ_link/∂q)`` to the load context ``c``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import ResistingMoment
        >>> from assur.core.statics import applied_loads
        >>> for travel in (1, -1):     # S grows, then S shrinks
        ...     m = examples.hitch_003().with_loads([ResistingMoment("3", 100.0, travel)])
        ...     _, couples, _ = applied_loads(m.solve([0.42]))
        ...     print([(link, float(M.ravel()[0])) for link, M in couples])   # [N·m]
        [('3', -100.0)]
        [('3', 100.0)]
        """
        w = c.rate(self.link, self.coordinate)
        c.couple(self.link, -np.copysign(c.value(self.M), self.travel * w))


@register
@dataclass(frozen=True)
class Spring(Load):
    """Linear spring(s) between points ``a`` and ``b`` (links ``links`` or the owners).

    Tension of one spring ``T = preload + rate·(|ab| − free_length)`` [N]; ``rate``
    [N/m], ``free_length`` [m], ``preload`` [N]. ``count`` identical springs act in
    parallel (seed 001 lab 2 eq. 4: k springs): the points are pulled together by
    ``count·T``.

    Examples
    --------
    A spring along the hitch's cylinder, from 01 to 23 (its length is S): the
    cylinder must push with its tension.

    >>> from assur import examples
    >>> from assur.core.loads import Spring
    >>> s = Spring("s", "01", "23", rate=1000.0, free_length=0.5, preload=50.0)
    >>> m = examples.hitch_003().with_loads([s])
    >>> [round(float(f), 1) for f in m.analyze([0.42, 0.67]).statics.actuator_force()]  # [N]
    [-30.0, 220.0]

    The builder ``Mechanism.spring``:

    >>> from assur.core.statics import spring_states
    >>> m = examples.hitch_003().with_loads().spring("k", "07", "S6", rate=1e4,
    ...                                              free_length=1.0)  # [N/m], [m]
    >>> L, T, F = spring_states(m.solve([0.42, 0.67]))["k"]
    >>> [round(float(v), 3) for v in L], [round(float(v)) for v in T]  # [m], [N]
    ([1.674, 1.463], [6745, 4630])
    """

    name: str = param("name", doc="its name (table 5.1's columns ``L_<name>``, ``T_<name>``, "
                                  "``F_<name>``)")
    a: str = param("point", doc="one end")
    b: str = param("point", doc="the other end")
    rate: Ref = param("value", "stiffness", "nonneg", doc="of one spring [N/m]")
    free_length: Ref = param("value", "length", "nonneg", doc="[m]")
    preload: Ref = param("value", "force", default=0.0,
                         doc="tension of one spring at its free length [N]")
    links: tuple[str, str] | None = param("links", default=None,
                                          doc="[link of a, link of b] (default: the owners)")
    count: Ref = param("value", "number", "count", default=1,
                       doc="identical springs in parallel")

    type_name: ClassVar = "spring"
    summary: ClassVar = ("count identical linear springs between points a and b: the "
                         "tension of one, preload + rate·(|ab| − free_length), pulls a and "
                         "b together; the force on the points is count × tension. Table 5.1 "
                         "shows each spring's length ``L_<name>``, the tension of one spring "
                         "``T_<name>`` and the force of all ``F_<name>``")

    def tension(self, c, L):
        """Tension of one spring [N] at the length ``L`` [m] (context values).

        Examples
        --------
        ``c`` needs only ``value`` here (a parameter's value, a number as it is):

        >>> from types import SimpleNamespace
        >>> from assur.core.loads import Spring
        >>> c = SimpleNamespace(value=lambda ref: {"k": 2000.0}.get(ref, ref))
        >>> s = Spring("s", "01", "23", rate="k", free_length=0.5, preload=100.0)
        >>> round(float(s.tension(c, 0.6)), 6)    # 100 + 2000·(0.6 − 0.5) [N]
        300.0
        """
        return c.value(self.preload) + c.value(self.rate) * (L - c.value(self.free_length))

    def apply(self, c):
        """Apply the spring to the load context ``c``: ``count·T`` along a→b at ``a``,
        the opposite at ``b``, and report its tension and length (``c.spring``).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import Spring
        >>> from assur.core.statics import applied_loads
        >>> s = Spring("s", "01", "23", rate=1000.0, free_length=0.5, preload=50.0, count=2)
        >>> m = examples.hitch_003().with_loads([s])
        >>> forces, _, springs = applied_loads(m.solve([0.67]))
        >>> [(link, pt) for link, pt, _, _ in forces]      # the two ends' links
        [('0', '01'), ('3', '23')]
        >>> _, T, L = springs[0]
        >>> round(float(T.ravel()[0]), 1), round(float(L.ravel()[0]), 3)   # one spring [N], [m]
        (220.0, 0.67)
        """
        (ax, ay), (bx, by) = c.point(self.a), c.point(self.b)
        dx, dy = bx - ax, by - ay
        L = np.hypot(dx, dy)
        c.nonzero(L, f"spring {self.name!r}: its ends {self.a!r} and {self.b!r} coincide")
        T = self.tension(c, L)
        n = c.value(self.count)
        F = T if _is_one(n) else n * T
        ux, uy = dx / L, dy / L
        la, lb = self.links or (c.owner(self.a), c.owner(self.b))
        c.force(la, self.a, F * ux, F * uy)
        c.force(lb, self.b, -F * ux, -F * uy)
        c.spring(self, T, L)


def _is_one(v) -> bool:
    """True for the plain number 1 (a count that changes nothing)."""
    return isinstance(v, (int, float, np.floating, np.integer)) and float(v) == 1.0


@register
@dataclass(frozen=True)
class Mass(Load):
    """Mass ``m`` [kg] of a link with its centre of mass at ``point`` and moment of
    inertia ``J`` [kg·m²] about it: its weight m·g, and for a motion in time its
    inertia force −m·a and moment −J·ε (d'Alembert).

    Examples
    --------
    1000 kg at S6 of the hitch weighs 9810 N (g = 9.81 m/s²):

    >>> from assur import examples
    >>> from assur.core.loads import Mass
    >>> m = examples.hitch_003().with_loads([Mass("6", 1000.0, "S6")])
    >>> [round(float(f), 1) for f in m.analyze([0.42, 0.67]).statics.actuator_force()]  # [N]
    [46236.8, 48390.7]

    The builder ``Mechanism.mass``: a mass weighing the seed's P6 = 27.5 kN at rest:

    >>> m = examples.hitch_003().with_loads().mass("6", 27500.0 / 9.81, "S6")  # [kg]
    >>> round(float(m.analyze([0.42]).statics.actuator_force("S")[0]))  # [N]
    129614
    """

    link: str = param("link", doc="the link whose mass it is")
    m: Ref = param("value", "mass", "positive", doc="[kg]")
    point: str = param("point", doc="its centre of mass")
    J: Ref = param("value", "inertia", "nonneg", default=0.0,
                   doc="moment of inertia about the centre of mass [kg·m²]")

    type_name: ClassVar = "mass"
    summary: ClassVar = ("the mass of a link at its centre of mass: its weight m·g and, for "
                         "a motion in time, its inertia force −m·a and moment −J·ε")

    def apply(self, c):
        """Apply the weight m·g to the load context ``c`` and, when it is moving, the
        inertia force −m·a and moment −J·ε.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.loads import Mass
        >>> from assur.core.statics import applied_loads
        >>> m = examples.hitch_003().with_loads([Mass("6", 1000.0, "S6", J=50.0)])
        >>> forces, couples, _ = applied_loads(m.solve([0.42]))    # static: weight only
        >>> [(link, pt, float(fx), round(float(fy), 1)) for link, pt, fx, fy in forces]  # [N]
        [('6', 'S6', 0.0, -9810.0)]
        >>> forces, couples, _ = applied_loads(m.solve([0.42]), qdot=0.1)   # S moving [m/s]
        >>> len(forces), len(couples)       # + the inertia force and moment
        (2, 1)
        """
        m = c.value(self.m)
        c.force(self.link, self.point, *_along_gravity(c, m * c.g))
        if c.moving:
            acc_x, acc_y = c.acceleration(self.point)
            c.force(self.link, self.point, -m * acc_x, -m * acc_y)
            c.couple(self.link, -c.value(self.J) * c.angular_acceleration(self.link))


#: the registry of load types by model-file ``type``, read-only (:func:`registry`)
