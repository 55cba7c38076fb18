"""Messages of assembly failures: which group, its links, the values, the position.

The kernel reports only *which* group failed at an element and the failure code;
the amount and the words come from the group itself
(:meth:`assur.groups.base.Group.failure`), evaluated on the plain-numpy reference
positions of the groups before it.
"""

from __future__ import annotations

import numpy as np

from ..errors import AssemblyError
from ..groups.base import fmt
from ..kernel.emit import CODES_PER_OP, FAIL_CONTINUITY

__all__ = ["failure_message", "assembly_error", "describe_failures", "coordinate_value",
           "coordinate_text"]


def coordinate_value(mech, c, v) -> str:
    """A coordinate value as messages show it: a crank angle in degrees
    (``"14.679°"``), a length as its number in metres (``"0.42"``).

    Examples
    --------
    >>> import math
    >>> from assur import Mechanism, examples
    >>> from assur.core.diagnostics import coordinate_value
    >>> coordinate_value(examples.hitch_003(), "S", 0.42)             # S [m]
    '0.42'
    >>> crank = (Mechanism("crank", coordinates=("j1",)).frame("O1", 0.0, 0.0)
    ...          .crank("c", pivot="O1", out="A", radius=0.1, q="j1"))  # radius [m]
    >>> coordinate_value(crank, "j1", math.radians(14.679))            # j1 [rad] → [°]
    '14.679°'
    """
    if mech.coordinate_kind(c) == "angle":
        return f"{float(np.degrees(v)):.6g}°"
    return f"{float(v):.6g}"


def coordinate_text(mech, c, v) -> str:
    """``"j1 = 14.679°"``, ``"S = 0.42"`` (see :func:`coordinate_value`).

    Examples
    --------
    >>> import math
    >>> from assur import Mechanism, examples
    >>> from assur.core.diagnostics import coordinate_text
    >>> coordinate_text(examples.hitch_003(), "S", 0.4200000001)      # S [m]
    'S = 0.42'
    >>> crank = (Mechanism("crank", coordinates=("j1",)).frame("O1", 0.0, 0.0)
    ...          .crank("c", pivot="O1", out="A", radius=0.1, q="j1"))  # radius [m]
    >>> coordinate_text(crank, "j1", math.radians(-15.321))            # j1 [rad]
    'j1 = -15.321°'
    """
    return f"{c} = {coordinate_value(mech, c, v)}"


def _where(mech, ptab, qarr, n, e):
    d, pos = divmod(e, n)
    at = ", ".join(coordinate_text(mech, c, qarr[j, e]) for j, c in enumerate(mech.coordinates))
    return f"at position {pos} ({at})" + (f" of design {d}" if ptab.shape[1] > 1 else "")


def group_links(mech, g) -> tuple[str, ...]:
    """The links a group's messages name: the links it adds, by the names the
    topology gives them (the user's, or the defaults "<group>:a", ":b" when
    ``links=`` is omitted); for a group that puts a point on an existing link
    (``link_roles`` None), that link."""
    links = tuple(mech.topology.group_links.get(g.name, ()))
    roles = getattr(g, "link_roles", ())
    return links if roles is None else links[:len(roles)]


def failure_message(mech, prog, ptab, qarr, status, amount, n, e):
    """``(message, amount, group or measure)`` of the failure at element ``e``.

    Examples
    --------
    The kernel's raw status of seed 003's hitch with a brace L4 = 0.95 m too long
    (:meth:`assur.Mechanism.solve` builds its messages so):

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.core.diagnostics import failure_message
    >>> from assur.core.program import execute
    >>> m = examples.hitch_003(L4=0.95)                                 # [m]
    >>> prog = m.program()
    >>> ptab, trig, _ = m.prepared(prog)
    >>> q = np.array([[0.42, 0.67]])                                    # S [m]
    >>> res = execute(prog, ptab, q, 2, trig=trig)
    >>> res["status"].tolist()                       # ≥ 0: a failure's code; -1: ok
    [129, -1]
    >>> msg, amount, group = failure_message(m, prog, ptab, q, res["status"],
    ...                                      res["amount"], 2, 0)
    >>> print(msg)
    RRR dyad 'III (6,7)' (links 6, 7) cannot assemble at position 0 (S = 0.42): the distance |56–07| = 1.31749 m exceeds L6 + L7 = 0.515 + 0.75217 = 1.26717 m by 50.3 mm
    >>> round(amount, 4), group.name                                    # [m]
    (0.0503, 'III (6,7)')
    """
    opi, code = divmod(int(status[e]), CODES_PER_OP)
    d = e // n
    where = _where(mech, ptab, qarr, n, e)
    ngroups = len(mech.groups)
    if opi >= ngroups:
        obj = (mech.links + mech.distances)[opi - ngroups]
        return f"link {obj.name!r}: its two points coincide {where}", 0.0, obj
    g = mech.groups[opi]
    links = group_links(mech, g)
    ltxt = (f" (link{'s' if len(links) > 1 else ''} {', '.join(links)})" if links else "")
    if code == FAIL_CONTINUITY:
        c = mech.coordinates[0]
        amt = float(amount[e])
        head = (f"{g.kind} {g.name!r}{ltxt} cannot move continuously from "
                f"{coordinate_text(mech, c, qarr[0, e - 1])} to "
                f"{coordinate_text(mech, c, qarr[0, e])}"
                f"{f' (design {d})' if ptab.shape[1] > 1 else ''}: ")
        return (head + "its triangle flattens or opens between these positions (the squared "
                f"height, interpolated with its exact slope, dips to {amt:.3g} m²): a dead "
                "point or a loss of assembly between samples; refine the positions, or "
                "check the range and the branch"), amt, g
    params = {name: ptab[i, d] for i, name in enumerate(prog.param_names)}
    qd = {c: qarr[j, e] for j, c in enumerate(mech.coordinates)}
    pts = mech.evaluate_positions(qd, params, upto=opi) if opi else {}
    pts = {k: (float(x), float(y)) for k, (x, y) in pts.items()}

    def v(ref):
        if isinstance(ref, str) and ref in qd:
            return float(qd[ref])
        return float(ptab[prog.param_row(ref), d])

    def nm(ref):
        return ref if isinstance(ref, str) else fmt(ref)

    f = g.failure(code, pts, v, nm)
    return f"{g.kind} {g.name!r}{ltxt} {f.verb} {where}: {f.text}", f.amount, g


def describe_failures(mech, prog, ptab, qarr, status, amount, n, limit=20):
    """Messages of the first ``limit`` failed elements.

    Examples
    --------
    Seed 003's hitch with a brace L4 = 0.95 m too long, at three strokes S:

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.core.diagnostics import describe_failures
    >>> from assur.core.program import execute
    >>> m = examples.hitch_003(L4=0.95)                                 # [m]
    >>> prog = m.program()
    >>> ptab, trig, _ = m.prepared(prog)
    >>> q = np.array([[0.42, 0.43, 0.67]])                              # S [m]
    >>> res = execute(prog, ptab, q, 3, trig=trig)
    >>> for text in describe_failures(m, prog, ptab, q, res["status"], res["amount"], 3):
    ...     print(text.split(": the")[0])
    RRR dyad 'III (6,7)' (links 6, 7) cannot assemble at position 0 (S = 0.42)
    RRR dyad 'III (6,7)' (links 6, 7) cannot assemble at position 1 (S = 0.43)
    """
    idx = np.flatnonzero(status >= 0)
    return [failure_message(mech, prog, ptab, qarr, status, amount, n, e)[0]
            for e in idx[:limit]]


def assembly_error(mech, prog, ptab, qarr, status, amount, n, ok):
    """The :class:`AssemblyError` of the first failed element, with the failing
    spans of its design and the number of failing designs.

    Examples
    --------
    Seed 003's hitch with a brace L4 = 0.95 m too long (what
    :meth:`assur.Mechanism.solve` raises):

    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.core.diagnostics import assembly_error
    >>> from assur.core.program import execute
    >>> m = examples.hitch_003(L4=0.95)                                 # [m]
    >>> prog = m.program()
    >>> ptab, trig, _ = m.prepared(prog)
    >>> q = np.array([[0.42, 0.43, 0.67]])                              # S [m]
    >>> res = execute(prog, ptab, q, 3, trig=trig)
    >>> e = assembly_error(m, prog, ptab, q, res["status"], res["amount"], 3,
    ...                    (res["status"] < 0).reshape(1, 3))
    >>> e.group, e.links, e.position, e.coordinate
    ('III (6,7)', ('6', '7'), 0, {'S': 0.42})
    >>> print(str(e).split("; ")[-1])
    2 of 3 positions fail (S = 0.42…0.43)
    """
    idx = np.flatnonzero(status >= 0)
    e = int(idx[0])
    msg, amt, g = failure_message(mech, prog, ptab, qarr, status, amount, n, e)
    d, pos = divmod(e, n)
    fails_here = idx[(idx >= d * n) & (idx < (d + 1) * n)]
    if len(mech.coordinates) == 1 and n > 1:
        pos_idx = fails_here - d * n
        runs = np.split(pos_idx, np.flatnonzero(np.diff(pos_idx) != 1) + 1)
        qd = qarr[0, d * n:(d + 1) * n]
        c0 = mech.coordinates[0]
        spans = ", ".join(f"{coordinate_value(mech, c0, qd[r[0]])}…"
                          f"{coordinate_value(mech, c0, qd[r[-1]])}" if len(r) > 1 else
                          coordinate_value(mech, c0, qd[r[0]]) for r in runs[:5])
        msg += (f"; {len(fails_here)} of {n} positions fail"
                f" ({mech.coordinates[0]} = {spans}{', …' if len(runs) > 5 else ''})")
    if ptab.shape[1] > 1:
        nd = len(np.unique(idx // n))
        msg += f"; {nd} of {ptab.shape[1]} designs fail, first design {d}"
    links = group_links(mech, g) if hasattr(g, "group_links") else ()
    at = {c: float(v) for c, v in zip(mech.coordinates, qarr[:, e])}   # plain floats
    return AssemblyError(msg, group=g.name, links=links, coordinate=at, design=d,
                         position=pos, amount=amt, failures=ok)
