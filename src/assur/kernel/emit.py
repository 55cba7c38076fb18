"""The toolkit a group type uses to emit its kernel code (DESIGN.md §9).

Each element (design, position) of the generated kernel is straight-line code in
which every point ``P`` is held in local variables: its value ``xP, yP`` [m], its
first analogs ``xP_a`` = ∂x/∂q_a and second analogs ``xP_ab`` = ∂²x/∂q_a∂q_b
(``a ≤ b``) — a second-order forward "jet" over the ``k`` generalized coordinates.
A group's :meth:`~assur.groups.base.Group.emit` writes the lines that compute its
outputs' jets from its inputs' jets with an :class:`Emitter`, using the names built
here. Per-design values are read as ``params[row, d]`` and fixed angles as
``trig[row, d]`` (cos) and ``trig[row + 1, d]`` (sin); the generator hoists both
out of the element loop.

Failures never branch: :func:`fail` records the first failing group in ``st``
with a select, which keeps the element loop vectorizable. A failed element's
outputs are written as 0, never NaN; the caller turns the status into an
:class:`assur.errors.AssemblyError` with the group's own message.
"""

from __future__ import annotations

__all__ = [
    "Emitter", "pt", "d", "dd", "length_ref", "fail", "emit_unit", "emit_zero_jets",
    "FAIL_TOO_FAR", "FAIL_TOO_CLOSE", "FAIL_TRIANGLE", "FAIL_LINE", "FAIL_COINCIDENT",
    "FAIL_DEAD_POINT", "FAIL_CONTINUITY", "FAIL_PARALLEL", "DEAD_POINT_TOL",
    "CONTINUITY_TOL", "CODES_PER_OP",
]

# ---- failure codes (status = CODES_PER_OP·op_index + code) ----------------------------
FAIL_TOO_FAR = 1  #: distance between outer joints exceeds ra + rb
FAIL_TOO_CLOSE = 2  #: distance between outer joints below |ra − rb| (or an offset)
FAIL_TRIANGLE = 3  #: three given sides cannot form a triangle
FAIL_LINE = 4  #: circle does not reach a slider line
FAIL_COINCIDENT = 5  #: two points that must define a direction coincide
FAIL_DEAD_POINT = 6  #: the group assembles but its Jacobian is singular
FAIL_CONTINUITY = 7  #: a dyad opens or flattens between two consecutive positions
FAIL_PARALLEL = 8  #: two slider lines that must intersect are parallel
CODES_PER_OP = 16

#: |sin μ| of a dyad (μ the transmission angle) below which a position is a dead point.
#: At a dead point the squared triangle height h² is ~0 up to rounding (~ε·L²), so the
#: computed h, and with it sin μ, is only known to ~√ε ≈ 1.5e-8: below 1e-7 the analogs
#: (∝ 1/sin μ) are rounding noise and the position is reported as a dead point.
DEAD_POINT_TOL = 1e-7

#: relative depth below zero of the interpolated squared triangle height that fails
#: the continuity check (see :mod:`assur.kernel.run`)
CONTINUITY_TOL = 1e-9


class Emitter:
    """Collects one element's lines; ``E(line)`` appends a line of code.

    Attributes
    ----------
    K : int
        Number of generalized coordinates k.
    order : int
        Highest order of analogs emitted (1 or 2).
    pairs : list of (int, int)
        The index pairs ``a ≤ b`` of the second analogs (empty for order 1).

    Examples
    --------
    >>> from assur.kernel.emit import Emitter
    >>> E = Emitter(2)                        # two generalized coordinates
    >>> E("x9 = 0.5 * (x4 + x5)")
    >>> E.lines                               # indented for the element loop
    ['            x9 = 0.5 * (x4 + x5)']
    >>> E.pairs, Emitter(2, order=1).pairs    # second analogs ∂²/∂q_a∂q_b, a ≤ b
    ([(0, 0), (0, 1), (1, 1)], [])
    """

    def __init__(self, K: int, order: int = 2):
        self.K = K
        self.order = order
        self.lines: list[str] = []
        #: index pairs of the second analogs; empty when only first order is asked
        #: (group code loops over them, so none of its second-order lines is emitted)
        self.pairs = [(a, b) for a in range(K) for b in range(a, K)] if order >= 2 else []

    def __call__(self, line: str) -> None:
        self.lines.append("            " + line)


def pt(slot: int) -> tuple[str, str]:
    """Names of the x and y values of the point in ``slot``.

    Examples
    --------
    >>> from assur.kernel.emit import pt
    >>> pt(7)                                 # point in slot 7 (56 of the hitch)
    ('x7', 'y7')
    """
    return f"x{slot}", f"y{slot}"


def d(v: str, a: int) -> str:
    """Name of the first analog ∂v/∂q_a.

    Examples
    --------
    >>> from assur.kernel.emit import d, pt
    >>> [d(v, 0) for v in pt(7)]              # ∂x/∂q_0, ∂y/∂q_0
    ['x7_0', 'y7_0']
    """
    return f"{v}_{a}"


def dd(v: str, a: int, b: int) -> str:
    """Name of the second analog ∂²v/∂q_a∂q_b (symmetric).

    Examples
    --------
    >>> from assur.kernel.emit import dd
    >>> dd("x7", 1, 0), dd("x7", 0, 1), dd("x7", 0, 0)   # symmetric
    ('x7_01', 'x7_01', 'x7_00')
    """
    a, b = min(a, b), max(a, b)
    return f"{v}_{a}{b}"


def length_ref(ref: int, K: int) -> tuple[str, list[str]]:
    """Expression and first-derivative literals of a compiled length reference.

    ``ref ≥ 0`` is a parameter row (constant over positions); ``ref < 0`` is the
    generalized coordinate ``−ref − 1`` (its derivative is 1 along itself).

    Examples
    --------
    >>> from assur.kernel.emit import length_ref
    >>> length_ref(28, 2)                     # parameter row 28 (L4 of the hitch): constant
    ('params[28, d]', ['0.0', '0.0'])
    >>> length_ref(-2, 2)                     # the second coordinate: ∂/∂q_1 = 1
    ('q[1, e]', ['0.0', '1.0'])
    """
    if ref >= 0:
        return f"params[{ref}, d]", ["0.0"] * K
    j = -ref - 1
    return f"q[{j}, e]", ["1.0" if a == j else "0.0" for a in range(K)]


def fail(E: Emitter, i: int, code: int, cond: str) -> None:
    """Record group ``i``'s failure ``code`` where ``cond`` holds, unless an earlier
    group failed (a select, no branch).

    Examples
    --------
    >>> from assur.kernel.emit import Emitter, fail, FAIL_TOO_FAR
    >>> E = Emitter(1)
    >>> fail(E, 6, FAIL_TOO_FAR, "t6r > P28 + P9")      # group 6: status 16·6 + 1
    >>> E.lines[0].strip()
    'st = 97 if ((st < 0) & (t6r > P28 + P9)) else st'
    >>> ns = {"st": -1, "t6r": 1.5, "P28": 0.66, "P9": 0.48}   # |A–B| > ra + rb [m]
    >>> exec(E.lines[0].strip(), ns)
    >>> ns["st"]
    97
    """
    E(f"st = {i * CODES_PER_OP + code} if ((st < 0) & ({cond})) else st")


def emit_zero_jets(E: Emitter, v: str) -> None:
    """Zero first and second analogs of a value constant over the positions.

    Examples
    --------
    >>> from assur.kernel.emit import Emitter, emit_zero_jets
    >>> E = Emitter(2)
    >>> emit_zero_jets(E, "x0")               # a frame point: constant over the positions
    >>> [line.strip() for line in E.lines]
    ['x0_0 = 0.0', 'x0_1 = 0.0', 'x0_00 = 0.0', 'x0_01 = 0.0', 'x0_11 = 0.0']
    """
    for a in range(E.K):
        E(f"{d(v, a)} = 0.0")
    for a, b in E.pairs:
        E(f"{dd(v, a, b)} = 0.0")


def emit_unit(E: Emitter, i: int, p: int, q: int, cb: str, sb: str, tag=None) -> None:
    """``u = R(β)(Q − P)/|Q − P|`` with its jets, into ``u{tag}x, u{tag}y`` (``tag``
    defaults to the group index ``i``; a group with two lines uses two tags).

    P and Q are points of one rigid link (validated by the topology), so |Q − P| is
    constant and u is a linear map of Q − P: ``u' = R(β)(Q' − P')/|Q − P|``, and
    likewise u''. ``cb``, ``sb`` are the expressions of cos β and sin β.

    Examples
    --------
    >>> import math
    >>> from assur.kernel.emit import Emitter, emit_unit
    >>> E = Emitter(1)
    >>> emit_unit(E, 0, 0, 1, "1.0", "0.0")   # u = R(0)(Q − P)/|Q − P|, P slot 0, Q slot 1
    >>> ns = dict(math=math, st=-1, x0=0.0, y0=0.0, x1=3.0, y1=4.0,        # [m]
    ...           x0_0=0.0, y0_0=0.0, x1_0=1.0, y1_0=0.0,                  # [m/m]
    ...           x0_00=0.0, y0_00=0.0, x1_00=0.0, y1_00=0.0)              # [m/m²]
    >>> exec("\\n".join(line.strip() for line in E.lines), ns)
    >>> [round(ns[v], 6) for v in ("u0x", "u0y", "u0x_0", "u0y_0")], ns["st"]   # u [-], u' [1/m]
    ([0.6, 0.8, 0.2, 0.0], -1)
    """
    K = E.K
    px, py = pt(p)
    qx, qy = pt(q)
    tag = i if tag is None else tag
    t = f"t{tag}"
    E(f"{t}dx = {qx} - {px}")
    E(f"{t}dy = {qy} - {py}")
    E(f"{t}r = math.sqrt({t}dx * {t}dx + {t}dy * {t}dy)")
    fail(E, i, FAIL_COINCIDENT, f"{t}r == 0.0")
    E(f"{t}ir = 1.0 / {t}r if {t}r > 0.0 else 0.0")
    E(f"{t}cb = {cb} * {t}ir")
    E(f"{t}sb = {sb} * {t}ir")
    E(f"u{tag}x = {t}cb * {t}dx - {t}sb * {t}dy")
    E(f"u{tag}y = {t}sb * {t}dx + {t}cb * {t}dy")
    for a in range(K):
        E(f"{t}dx_{a} = {d(qx, a)} - {d(px, a)}")
        E(f"{t}dy_{a} = {d(qy, a)} - {d(py, a)}")
        E(f"u{tag}x_{a} = {t}cb * {t}dx_{a} - {t}sb * {t}dy_{a}")
        E(f"u{tag}y_{a} = {t}sb * {t}dx_{a} + {t}cb * {t}dy_{a}")
    for a, b in E.pairs:
        E(f"{t}d2x = {dd(qx, a, b)} - {dd(px, a, b)}")
        E(f"{t}d2y = {dd(qy, a, b)} - {dd(py, a, b)}")
        E(f"{dd(f'u{tag}x', a, b)} = {t}cb * {t}d2x - {t}sb * {t}d2y")
        E(f"{dd(f'u{tag}y', a, b)} = {t}sb * {t}d2x + {t}cb * {t}d2y")
