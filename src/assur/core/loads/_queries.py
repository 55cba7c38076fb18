"""What the rest of the engine asks of a mechanism's loads: the links they act on,
the masses, the dead loads of a capacity, the common centre of mass."""

from __future__ import annotations

from ._types import Mass

__all__ = ["names_in", "load_link", "masses_of", "dead_load_links", "is_dead", "centre_of_mass"]

def names_in(value) -> tuple:
    """The names a point or link field holds: none (None), one (a str) or a tuple.

    Examples
    --------
    >>> from assur.core.loads import names_in
    >>> names_in(None), names_in("3"), names_in(["0", "3"])
    ((), ('3',), ('0', '3'))
    """
    if value is None:
        return ()
    return (value,) if isinstance(value, str) else tuple(value)


def load_link(mech, load):
    """The link a load acts on: its ``link``, else the owner of its ``point``; None for
    a load between two links (a spring).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.loads import load_link
    >>> m = examples.hitch_003()
    >>> m.loads[0], load_link(m, m.loads[0])        # P6 at S6, on the implement 6
    (Weight(point='S6', P='P6', link=None, name='P6'), '6')
    """
    link = getattr(load, "link", None)
    if link is not None:
        return link
    point = getattr(load, "point", None)
    return mech.owner(point) if point is not None else None


def masses_of(mech) -> tuple:
    """The :class:`Mass` loads of a mechanism on moving links.

    Examples
    --------
    >>> from assur import examples, io
    >>> from assur.core.loads import masses_of
    >>> masses_of(examples.hitch_003())      # a weight P6, no masses
    ()
    >>> ms = masses_of(io.load(io.bundled("cleaning_lab3")).mechanism)   # seed 001 lab 3
    >>> len(ms), ms[1]                       # m2, J2 are model parameters
    (9, Mass(link='2', m='m2', point='S2', J='J2'))
    """
    return tuple(ld for ld in mech.loads if type(ld) is Mass and ld.link != "0")


def dead_load_links(mech) -> tuple:
    """The links whose loads every capacity carries besides the load it lifts
    (``[tables] dead_loads``; seed 001 lab 1 eq. 14: the boom's own weight).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.loads import dead_load_links
    >>> dead_load_links(examples.loader_lab1())   # the boom 3 (seed 001 lab 1 eq. 14)
    ('3',)
    >>> dead_load_links(examples.hitch_003())     # none declared
    ()
    """
    return tuple(mech.tables.get("dead_loads", ()) or ())


def is_dead(mech, load, links=None) -> bool:
    """Whether ``load`` is a dead load: it acts on one of ``links`` (default: the
    model's :func:`dead_load_links`).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.loads import is_dead
    >>> m = examples.loader_lab1()
    >>> [(ld.point, is_dead(m, ld)) for ld in m.loads]   # the boom's mass at S3 [-]
    [('S3', True), ('S9', False)]
    """
    links = dead_load_links(mech) if links is None else tuple(links)
    return bool(links) and load_link(mech, load) in links


def centre_of_mass(masses, value, point):
    """The common centre of mass Σ m_i·r_i / Σ m_i of ``masses`` and their total mass,
    ``(x, y, M)`` [m, m, kg] in the numbers of a context — arrays, dual numbers or the
    symbols of a kernel (seed 001 lab 3; the outputs ``Xc``, ``Yc`` and
    :func:`assur.dynamics.balancing.common_centre` both call it).

    Parameters
    ----------
    masses : sequence of Mass
    value : callable
        A mass's ``m`` (a number or parameter name) → its value [kg].
    point : callable
        A point's name → its ``(x, y)`` [m].

    Examples
    --------
    >>> from assur.core.loads import Mass, centre_of_mass
    >>> ms = [Mass("1", 2.0, "A"), Mass("2", 6.0, "B")]
    >>> pts = {"A": (0.0, 0.0), "B": (1.0, 2.0)}
    >>> centre_of_mass(ms, float, pts.get)        # [m], [m], [kg]
    (0.75, 1.5, 8.0)
    """
    sx = sy = tot = 0.0
    for ld in masses:
        m = value(ld.m)
        x, y = point(ld.point)
        sx, sy, tot = sx + m * x, sy + m * y, tot + m
    return sx / tot, sy / tot, tot
