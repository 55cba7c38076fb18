"""Checks of what a caller hands the engine: coordinates, parameters, memory.

The model-file loader (:mod:`assur.io`) and the Python API
(:meth:`assur.Mechanism.solve`) both call these plain functions, so a value
refused in a file is refused in the same words through ``params=``:

* :func:`coordinates_array` — the generalized coordinates ``q`` as a finite
  float array (not ``None``, not empty, not ragged, not text);
* :func:`check_params` — parameter overrides and the mechanism's own values:
  numbers, finite, 1-D over designs, and within the physical span of their role
  (:data:`SPANS`: a length is at most 10 km and, where it must be positive, at
  least 1 µm; an efficiency is in [0.01, 1]; a cylinder count is a whole number
  1 … 1000; forces, pressures … are at most 1e12 in SI);
* :func:`check_memory` — the memory a request needs, estimated *before* anything
  is allocated, against the limit :func:`max_memory` (default half the physical memory, at least
  2 GiB per request,
  settable with the environment variable ``ASSUR_MAX_MEMORY``, e.g. ``"8 GiB"``,
  ``"500 MiB"`` or a number of bytes);
* :func:`check_finite` — the results of an analysis hold no NaN or infinity
  (a last guard: the spans above keep every supported input finite);
* :func:`check_table` — a table a command writes holds no NaN or infinity (the
  one check every command makes before it writes, naming table, column and row).

Every refusal is a :class:`~assur.errors.ModelError` naming the key, the value
and its unit.
"""

from __future__ import annotations

import math
import os
import re
import weakref
from typing import Mapping

import numpy as np

from ..errors import ModelError
from ..groups.base import signed_name

__all__ = ["params_problem", "mark_checked", "max_memory", "fmt_bytes",
           "bytes_per_position", "check_memory", "coordinates_array",
           "span_problem", "check_params", "check_finite", "check_table", "all_finite", "SPANS",
           "MAX_MEMORY_ENV"]

#: environment variable holding the memory limit of one request
MAX_MEMORY_ENV = "ASSUR_MAX_MEMORY"
#: smallest default memory limit of one request [bytes] (2 GiB)
DEFAULT_MAX_MEMORY = 2 * 1024**3


def _physical_memory() -> int:
    """Physical memory of the machine [bytes], 0 when unknown."""
    try:
        return int(os.sysconf("SC_PAGE_SIZE")) * int(os.sysconf("SC_PHYS_PAGES"))
    except (AttributeError, ValueError, OSError):  # not a POSIX system
        return 0

_UNITS = {"": 1, "b": 1, "k": 1000, "kb": 1000, "m": 1000**2, "mb": 1000**2, "g": 1000**3,
          "gb": 1000**3, "t": 1000**4, "tb": 1000**4, "kib": 1024, "mib": 1024**2,
          "gib": 1024**3, "tib": 1024**4}
_SIZE = re.compile(r"^\s*(\d+(?:\.\d*)?(?:[eE][-+]?\d+)?)\s*([A-Za-z]*)\s*$")

#: physical spans by kind: (largest |value|, smallest positive value where the role
#: must be positive), SI units
SPANS = {
    "length": (1e4, 1e-6),            # 10 km, 1 µm
    "angle": (1e6, 0.0),              # rad
    "force": (1e12, 0.0),             # N
    "moment": (1e12, 0.0),            # N·m
    "pressure": (1e12, 0.0),          # Pa
    "mass": (1e9, 1e-9),              # kg
    "stiffness": (1e12, 0.0),         # N/m
    "inertia": (1e12, 0.0),           # kg·m²
    # the hydraulic drive's kinds (its components: assur.dynamics.drive): wide enough for
    # any machine's drive, narrow enough that a slip of a unit or an exponent (a
    # displacement of 1e308 cm³, a flow of 1e-300 l/min) is refused at its key
    "volume": (10.0, 1e-9),           # m³: 10 m³, 1 mm³
    "flow": (10.0, 1e-9),             # m³/s: 600 000 l/min, 0.06 ml/min
    "angular velocity": (1e4, 1e-2),  # rad/s: 95 000 rpm, 0.1 rpm
    "density": (1e5, 1.0),            # kg/m³
    "kinematic viscosity": (1e-1, 1e-8),  # m²/s: 100 000 mm²/s, 0.01 mm²/s
    "inertance": (1e15, 0.0),         # Pa·s²/m³
    "resistance": (1e15, 0.0),        # Pa·s/m³
    "turbulent resistance": (1e18, 0.0),  # Pa·s²/m⁶
}
_SI = {"length": "m", "angle": "rad", "force": "N", "moment": "N·m", "pressure": "Pa",
       "mass": "kg", "stiffness": "N/m", "inertia": "kg·m²", "volume": "m³",
       "flow": "m³/s", "angular velocity": "rad/s", "density": "kg/m³",
       "kinematic viscosity": "m²/s", "inertance": "Pa·s²/m³", "resistance": "Pa·s/m³",
       "turbulent resistance": "Pa·s²/m⁶"}
#: smallest efficiency accepted [-]
MIN_EFFICIENCY = 0.01
#: largest number of cylinders of one group [-]
MAX_COUNT = 1000


def max_memory() -> int:
    """The memory limit of one request [bytes]: ``$ASSUR_MAX_MEMORY``, else half the
    machine's physical memory (at least 2 GiB).

    Raises
    ------
    ModelError
        When the variable is set but is not a size such as ``"8 GiB"``.

    Examples
    --------
    >>> import os
    >>> from unittest import mock
    >>> from assur.core.inputs import max_memory
    >>> with mock.patch.dict(os.environ, {"ASSUR_MAX_MEMORY": "500 MiB"}):
    ...     max_memory()                                          # [bytes]
    524288000
    >>> with mock.patch.dict(os.environ, {"ASSUR_MAX_MEMORY": "lots"}):
    ...     max_memory()
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: ASSUR_MAX_MEMORY='lots': expected a size such as "2 GiB", "500 MiB" or a number of bytes
    """
    text = os.environ.get(MAX_MEMORY_ENV, "").strip()
    if not text:
        return max(DEFAULT_MAX_MEMORY, _physical_memory() // 2)
    m = _SIZE.match(text)
    unit = m.group(2).lower() if m else None
    if not m or unit not in _UNITS or not math.isfinite(float(m.group(1))):
        raise ModelError(f"{MAX_MEMORY_ENV}={text!r}: expected a size such as \"2 GiB\", "
                         f"\"500 MiB\" or a number of bytes")
    return int(float(m.group(1)) * _UNITS[unit])


def fmt_bytes(n: float) -> str:
    """``3.2e9`` → ``"3 GiB"``-style text (KiB, MiB, GiB, TiB, PiB) [bytes].

    Examples
    --------
    >>> from assur.core.inputs import fmt_bytes
    >>> fmt_bytes(3.2e9), fmt_bytes(2 * 1024**3), fmt_bytes(512)     # [bytes]
    ('2.98 GiB', '2 GiB', '512 B')
    """
    for unit, size in (("PiB", 1024**5), ("TiB", 1024**4), ("GiB", 1024**3),
                       ("MiB", 1024**2), ("KiB", 1024)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{int(n)} B"


def bytes_per_position(mech) -> int:
    """Estimated memory one position of one design takes in a full analysis [bytes].

    The kernel writes every point's position, first and second analogs (2·(1 + k +
    k²) numbers) and every link's angle or distance with its analogs (1 + k + k²);
    statics, cylinders, stability and the report's tables hold about as much again,
    plus the coordinates and per-position flags. Measured peaks (seed
    003 at 10⁵ positions) stay below this estimate.

    Examples
    --------
    Seed 003's hitch: k = 1, 11 points and 7 links, 8·((2·11 + 7)·3·2 + 8 + 128):

    >>> from assur import examples
    >>> from assur.core.inputs import bytes_per_position
    >>> bytes_per_position(examples.hitch_003())                     # [bytes]
    2480
    """
    hit = _PER_POSITION.get(mech)
    if hit is None:
        k = len(mech.coordinates)
        jet = 1 + k + k * k
        points = sum(len(g.outputs()) for g in mech.groups)
        scalars = len(mech.links) + len(mech.distances)
        hit = _PER_POSITION[mech] = int(8 * ((2 * points + scalars) * jet * 2 + 8 * k + 128))
    return hit


#: bytes per position of each mechanism (immutable objects)
_PER_POSITION: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def check_memory(positions: float, per_position: float, what: str, *,
                 unit: str = "positions", reduce: str | None = None) -> None:
    """Refuse a request of ``positions`` elements of ``per_position`` bytes each when
    it exceeds :func:`max_memory`; nothing is allocated here.

    Parameters
    ----------
    positions : float
        Number of elements: positions × designs, designs, machines, output times,
        frames … (may be huge: it is never allocated).
    per_position : float
        Bytes one element takes (:func:`bytes_per_position` for a position).
    what : str
        What the request is, for the message (e.g. ``"range.S (count = 1e9)"``).
    unit : str
        What one element is, in the plural (``"positions"``, ``"designs"``,
        ``"machines"``, ``"frames"`` …).
    reduce : str, optional
        What the user should make smaller: an option or a file key, e.g.
        ``"--samples"`` or ``"[simulation] outputs"`` (default: "use fewer ``unit``").

    Raises
    ------
    ModelError
        With the estimate and the limit, e.g. ``… would need about 2.5 TiB of memory
        (limit 2 GiB, set ASSUR_MAX_MEMORY to change it)``.

    Examples
    --------
    >>> import os
    >>> from unittest import mock
    >>> from assur.core.inputs import check_memory
    >>> with mock.patch.dict(os.environ, {"ASSUR_MAX_MEMORY": "2 GiB"}):
    ...     check_memory(1e5, 2480, "range.S (count = 1e5)")     # 248 MB [bytes]: fine
    ...     check_memory(1e9, 2480, "range.S (count = 1e9)")
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: range.S (count = 1e9): 1e+09 positions would need about 2.26 TiB of memory (limit 2 GiB; set ASSUR_MAX_MEMORY to change it, or use fewer positions)
    >>> with mock.patch.dict(os.environ, {"ASSUR_MAX_MEMORY": "2 GiB"}):
    ...     check_memory(1e9, 800, "sweep: samples = 1e+09", unit="designs",
    ...                  reduce="the samples (--samples)")
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: sweep: samples = 1e+09: 1e+09 designs would need about 745 GiB of memory (limit 2 GiB; set ASSUR_MAX_MEMORY to change it, or reduce the samples (--samples))
    """
    need = float(positions) * float(per_position)
    limit = max_memory()
    if not need <= limit:
        hint = f"use fewer {unit}" if reduce is None else f"reduce {reduce}"
        raise ModelError(f"{what}: {float(positions):.4g} {unit} would need about "
                         f"{fmt_bytes(need)} of memory (limit {fmt_bytes(limit)}; set "
                         f"{MAX_MEMORY_ENV} to change it, or {hint})")


# ---- coordinates ---------------------------------------------------------------------
def coordinates_array(q, mech, designs: int = 1, per_position: float | None = None) -> np.ndarray:
    """The generalized coordinates ``q`` of :meth:`Mechanism.solve` as a finite float
    array, checked before the engine allocates anything.

    Parameters
    ----------
    q : array_like
        Shape (n,) or (m, n) for one coordinate, (..., k) for k [m or rad].
    mech : Mechanism
    designs : int
        Number of designs of the parameters (the coordinates broadcast over them).
    per_position : float, optional
        Bytes one position of one design takes in this request (default: a full
        analysis, :func:`bytes_per_position`).

    Returns
    -------
    numpy.ndarray of float

    Raises
    ------
    ModelError
        For ``None``, text, complex or ragged input, no positions, a value that is
        not finite, or more positions than the memory limit allows.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.inputs import coordinates_array
    >>> m = examples.hitch_003()
    >>> a = coordinates_array([0.42, 0.67], m)                       # S [m]
    >>> a.dtype.name, a.tolist()
    ('float64', [0.42, 0.67])
    >>> coordinates_array([[0.42], [0.5, 0.6]], m)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': the generalized coordinates must be numbers [m or rad] in a regular array; got a ragged list (rows of different lengths): [[0.42], [0.5, 0.6]]
    >>> coordinates_array("0.42", m)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': the generalized coordinates must be numbers [m or rad], got the text '0.42'
    """
    if type(q) is np.ndarray and q.dtype == np.float64 and 0 < q.size <= 4096 and designs <= 1:
        # the common small case (one or a few positions): the checks below, cheaper
        if not np.isfinite(q).all():
            bad = tuple(int(i) for i in np.argwhere(~np.isfinite(q))[0])
            raise ModelError(f"mechanism {mech.name!r}: the generalized coordinate value at "
                             f"index {bad} is not finite ({float(q[bad])!r})")
        return q
    name = f"mechanism {mech.name!r}"
    if q is None:
        raise ModelError(f"{name}: the generalized coordinates are None; expected numbers "
                         f"[m or rad], e.g. numpy.linspace(0.42, 0.67, 10)")
    if isinstance(q, (str, bytes)):
        raise ModelError(f"{name}: the generalized coordinates must be numbers [m or rad], "
                         f"got the text {_short(q)}")
    try:
        complex_ = np.iscomplexobj(q)
    except (TypeError, ValueError):  # ragged: asarray below says so
        complex_ = False
    if complex_:
        raise ModelError(f"{name}: the generalized coordinates must be real numbers "
                         f"[m or rad], got complex ones")
    try:
        a = np.asarray(q, dtype=float)
    except (TypeError, ValueError, OverflowError) as e:
        # numpy's words for ragged lists and text; re-raised as one user error
        what = ("a ragged list (rows of different lengths)" if "inhomogeneous" in str(e)
                else "not numbers")
        raise ModelError(f"{name}: the generalized coordinates must be numbers [m or rad] in "
                         f"a regular array; got {what}: {_short(q)}") from None
    if a.size == 0:
        raise ModelError(f"{name}: no positions: the generalized coordinates are empty "
                         f"(shape {a.shape})")
    k = len(mech.coordinates)
    n = a.size // (k if k > 1 and a.ndim >= 1 and a.shape[-1] == k else 1)
    if a.ndim <= (1 if k == 1 else 2):
        n *= max(int(designs), 1)
    check_memory(n, bytes_per_position(mech) if per_position is None else per_position,
                 f"{name}: solving")
    if not np.isfinite(a).all():
        bad = tuple(int(i) for i in np.argwhere(~np.isfinite(a))[0])
        raise ModelError(f"{name}: the generalized coordinate value at index {bad} is not "
                         f"finite ({float(a[bad])!r})")
    return a


def _short(v) -> str:
    text = repr(v)
    return text if len(text) <= 80 else text[:77] + "…"


# ---- parameters ----------------------------------------------------------------------
_LOAD_ROLES = {  # load attribute -> (kind, must be positive)
    "P": ("force", False), "fx": ("force", False), "fy": ("force", False),
    "M": ("moment", False), "rate": ("stiffness", False), "free_length": ("length", False),
    "preload": ("force", False), "m": ("mass", False), "J": ("inertia", False),
    "bore": ("length", True), "rod": ("length", False), "rod2": ("length", False),
    "p_relief": ("pressure", False),
    "dp_throttle": ("pressure", False), "dp_line": ("pressure", False),
    "count": ("count", True), "eta_mech": ("efficiency", True),
    "eta_hyd": ("efficiency", True),
}


def span_problem(kind: str, value: float, positive: bool = False) -> str | None:
    """What is wrong with the SI ``value`` of a ``kind`` (``"length"``, ``"force"``, …,
    ``"efficiency"``, ``"count"``), or None when it is within :data:`SPANS`.

    Examples
    --------
    >>> from assur.core.inputs import span_problem
    >>> span_problem("length", 2e4)                                  # [m]
    'expected a length of at most 10000 m in magnitude'
    >>> span_problem("length", 0.0, positive=True)                   # [m]
    'expected a length of at least 1e-06 m'
    >>> span_problem("count", 2.5)                                   # [-]
    'expected a whole number (a count) from 1 to 1000'
    >>> print(span_problem("efficiency", 0.84))                      # [-]
    None
    """
    if not math.isfinite(value):
        return "expected a finite number"
    if kind == "efficiency":
        if not MIN_EFFICIENCY <= value <= 1:
            return f"expected an efficiency in [{MIN_EFFICIENCY}, 1]"
        return None
    if kind == "count":
        if value != int(value) or not 1 <= value <= MAX_COUNT:
            return f"expected a whole number (a count) from 1 to {MAX_COUNT}"
        return None
    if kind not in SPANS:
        return None
    big, small = SPANS[kind]
    unit = _SI[kind]
    a = "an" if kind[0] in "aeiou" else "a"
    if abs(value) > big:
        return f"expected {a} {kind} of at most {big:g} {unit} in magnitude"
    if positive and value < small:
        return f"expected {a} {kind} of at least {small:g} {unit}"
    return None


def _roles(mech):
    """``{reference: [(kind, positive, where), …]}`` of every value the mechanism's
    groups, loads and cylinders use (parameter names and literal numbers)."""
    out: dict = {}

    def add(ref, kind, positive, where):
        if ref is None or isinstance(ref, bool):
            return
        if isinstance(ref, str) and ref in mech.coordinates:
            return
        key = ref if isinstance(ref, str) else ("literal", where)
        out.setdefault(key, []).append((kind, positive, where, ref))

    for g in mech.groups:
        # the group type's own fields say what each value is (assur.groups.base.Field)
        for f in g.fields:
            if f.role == "value" and f.quantity:
                add(getattr(g, f.name), f.quantity, f.flag == "positive",
                    f"{g.kind} {g.name!r}.{f.name}")
    for ld in tuple(getattr(mech, "loads", ())) + tuple(getattr(mech, "cylinders", ())):
        for attr, (kind, pos) in _LOAD_ROLES.items():
            if hasattr(ld, attr):
                label = getattr(ld, "name", None) or type(ld).__name__.lower()
                add(getattr(ld, attr), kind, pos, f"{type(ld).__name__.lower()} "
                                                  f"{label!r}.{attr}")
    return out


#: mechanisms whose own parameter values passed :func:`check_params` (immutable objects)
_CHECKED: "weakref.WeakSet" = weakref.WeakSet()


def check_params(mech, params: Mapping | None = None) -> None:
    """Validate parameter overrides ``params`` (and the mechanism's own values) as a
    model file's values are validated.

    Each value must be a number or a 1-D array of numbers over designs, finite, and
    within the span of every role it is used in (:func:`span_problem`): e.g. a dyad
    radius is a positive length of at most 10 km.

    Raises
    ------
    ModelError
        Naming the parameter, the value, the role and the expected span.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.inputs import check_params
    >>> m = examples.hitch_003()
    >>> check_params(m, {"L4": 0.7})                                 # [m]: fine
    >>> check_params(m, {"L4": -0.7})
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': parameter 'L4' (used as RRR dyad 'II (4,5)'.ra): expected a length of at least 1e-06 m, found -0.7 [m]
    >>> check_params(m, {"eta": [0.84, 1.2]})                        # two designs [-]
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': parameter 'eta' (used as cylinder 'ГЦ'.eta_hyd): expected an efficiency in [0.01, 1], found 1.2 [-] (design 1)
    """
    _problem(mech, params)
    if not params:
        _CHECKED.add(mech)


def params_problem(mech, params: Mapping | None = None):
    """The message :func:`check_params` would raise for ``params`` (None: no problem).

    Once a mechanism's own values have passed, only the overrides ``params`` are
    checked again (a search or a fit evaluates thousands of them one by one).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.inputs import params_problem
    >>> m = examples.hitch_003()
    >>> params_problem(m, {"L4": 0.7}) is None                       # [m]
    True
    >>> params_problem(m, {"L4": 0.0})
    "mechanism 'hitch_003': parameter 'L4' (used as RRR dyad 'II (4,5)'.ra): expected a length of at least 1e-06 m, found 0.0 [m]"
    """
    try:
        _problem(mech, params)
    except ModelError as e:
        return str(e)
    return None


def mark_checked(parent, child, changed: Mapping) -> None:
    """Record ``child`` (``parent`` with the values ``changed``, same structure) as
    checked when ``parent`` is and the changed values pass; otherwise
    :func:`check_params` checks the child's values on its first use, as for any
    mechanism.

    Examples
    --------
    ``Mechanism.with_params`` calls it: a copy with a value that fails is made, and
    refused on its first use.

    >>> from assur import examples
    >>> m = examples.hitch_003()
    >>> good, bad = m.with_params(L4=0.7), m.with_params(L4=-0.7)   # [m]
    >>> round(float(good.solve([0.42]).phi("6", degrees=True)[0]), 1)   # [°]
    88.3
    >>> bad.solve([0.42])
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': parameter 'L4' (used as RRR dyad 'II (4,5)'.ra): expected a length of at least 1e-06 m, found -0.7 [m]
    """
    if parent not in _CHECKED and params_problem(parent) is None:
        _CHECKED.add(parent)   # once per parent: then only the changed values are checked
    if parent in _CHECKED and (not changed or params_problem(parent, changed) is None):
        _CHECKED.add(child)


def _problem(mech, params):
    if not params and mech in _CHECKED:
        return  # the mechanism's own values, checked on an earlier call
    name = f"mechanism {mech.name!r}"
    merged = dict(mech.params)
    if params:
        if not isinstance(params, Mapping):
            raise ModelError(f"{name}: params must be a mapping of parameter names to values, "
                             f"got {type(params).__name__}")
        unknown = sorted(set(params) - set(mech.params), key=str)
        if unknown:
            raise ModelError(f"{name}: unknown parameter(s) {unknown}; known: "
                             f"{sorted(mech.params)}")
        merged.update(params)
    roles = mech.memo(("roles",), lambda: _roles(mech))
    own_checked = bool(params) and mech in _CHECKED
    arrays = {}
    for p, v in merged.items():
        if own_checked and p not in params:
            continue  # the mechanism's own value, checked before
        if p not in roles and not (params and p in params):
            continue  # checked finite by Mechanism itself; no role to check it against
        if isinstance(v, (str, bytes, bool)) or v is None:
            raise ModelError(f"{name}: parameter {p!r} must be a number [SI] or a 1-D array "
                             f"of numbers over designs, got {v!r}")
        try:
            a = np.asarray(v, dtype=float)
        except (TypeError, ValueError, OverflowError):
            # numpy's words for text or ragged input; re-raised as one user error
            raise ModelError(f"{name}: parameter {p!r} must be a number [SI] or a 1-D array "
                             f"of numbers over designs, got {_short(v)}") from None
        if a.ndim > 1 or a.size == 0:
            raise ModelError(f"{name}: parameter {p!r} must be a number or a non-empty 1-D "
                             f"array over designs, got shape {a.shape}")
        if not np.isfinite(a).all():
            raise ModelError(f"{name}: parameter {p!r} must be finite, got {_short(v)}")
        arrays[p] = np.atleast_1d(a)
    for ref, uses in roles.items():
        for kind, pos, where, raw in uses:
            if isinstance(ref, str):
                base = signed_name(ref)  # "-a": the span holds for −a
                if (base or ref) not in arrays:
                    continue
                a = -arrays[base] if base else arrays[ref]
                label = f"parameter {ref!r} (used as {where})"
            else:
                if own_checked:
                    continue  # a literal of the mechanism's own, checked before
                try:
                    a = np.atleast_1d(np.asarray(raw, dtype=float))
                except (TypeError, ValueError):
                    continue  # not a number: the mechanism reports it itself
                label = where
            bad = _first_outside(kind, a, pos)
            if bad is not None:
                x = float(a[bad])
                raise ModelError(f"{name}: {label}: {span_problem(kind, x, pos)}, found "
                                 f"{x!r} [{_SI.get(kind, '-')}]"
                                 + (f" (design {bad})" if a.size > 1 else ""))


def _first_outside(kind, a, positive):
    """Index of the first element of ``a`` outside the span of ``kind``, or None
    (vectorized: batches of millions of designs)."""
    if kind == "efficiency":
        ok = (a >= MIN_EFFICIENCY) & (a <= 1)
    elif kind == "count":
        ok = (a >= 1) & (a <= MAX_COUNT) & (a == np.round(a))
    elif kind in SPANS:
        big, small = SPANS[kind]
        ok = np.abs(a) <= big
        if positive:
            ok &= a >= small
    else:
        return None
    if ok.all():
        return None
    return int(np.flatnonzero(~ok)[0])


# ---- results ------------------------------------------------------------------------
def all_finite(v) -> bool:
    """True if every value of ``v`` (a number or an array) is finite: a few values
    (one position) by ``math.isfinite``, a fifth of numpy's per-call cost.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.core.inputs import all_finite
    >>> all_finite(np.array([0.5])), all_finite(np.array([0.5, np.nan])), all_finite(np.inf)
    (True, False, False)
    >>> all_finite(np.linspace(0.42, 0.67, 1000))               # numpy for many values
    True
    """
    if isinstance(v, np.ndarray) and v.size <= 4:
        return all(map(math.isfinite, v.ravel().tolist()))
    if isinstance(v, float):
        return math.isfinite(v)
    return bool(np.isfinite(v).all())


def check_table(table: str, columns, key=None) -> None:
    """Raise before a table is written when one of its values is NaN or infinite,
    naming the table, the column, the row and the row's ``key`` value (default: the
    first column's, e.g. the time or the position). Every command that writes
    results (CSV, XLSX, HTML, Parquet, DXF) checks what it writes with this one
    function: exit 0 never leaves a NaN or an infinity in a file.

    Parameters
    ----------
    table : str
        The table's name, as the file or the report calls it.
    columns : mapping of str to array_like
        The columns by name (a :class:`pandas.DataFrame` is such a mapping), each
        of one value per row, or of shape (rows, …). Columns of text, integers or
        booleans are finite; a column of objects is checked value by value (None, a
        value left undefined and shown as such, is not a number and passes).
    key : str, optional
        The column whose value names a row in the message.

    Raises
    ------
    ModelError

    Examples
    --------
    >>> import numpy as np
    >>> from assur.core.inputs import check_table
    >>> check_table("simulation", {"t [s]": [0.0, 0.1], "p1 [MPa]": [0.0, 3.1]})
    >>> check_table("simulation", {"t [s]": [0.0, 0.1], "p1 [MPa]": [0.0, np.inf]})
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: table 'simulation': column 'p1 [MPa]' is inf at row 1 (t [s] = 0.1): not a finite number, so nothing is written; the inputs are outside the range where it can be computed
    """
    names = list(columns.keys())
    for name in names:
        a = np.asarray(columns[name])
        if a.dtype.kind in "fc":
            if all_finite(a):
                continue
            bad = ~np.isfinite(a)
        elif a.dtype.kind == "O":
            bad = np.array([isinstance(x, (float, complex, np.floating, np.complexfloating))
                            and not np.isfinite(x) for x in a.ravel()],
                           dtype=bool).reshape(a.shape)
            if not bad.any():
                continue
        else:
            continue
        at = tuple(int(i) for i in np.argwhere(bad)[0]) if a.ndim else ()
        value = a[at].item() if hasattr(a[at], "item") else a[at]
        where = ""
        if at:
            where = f" at row {at[0]}" + (f", element {at[1:]}" if len(at) > 1 else "")
            k = names[0] if key is None else key
            if k != name and k in names:
                kv = np.asarray(columns[k])
                if kv.ndim == 1 and kv.size == a.shape[0]:
                    kx = kv[at[0]]
                    kx = kx.item() if hasattr(kx, "item") else kx
                    where += f" ({k} = {kx!r})"
        raise ModelError(f"table {table!r}: column {name!r} is {value!r}{where}: not a "
                         f"finite number, so nothing is written; the inputs are outside "
                         f"the range where it can be computed")


def check_finite(analysis) -> None:
    """Raise when any result of an analysis is NaN or infinite, naming the quantity
    and the first position (a guard: inputs within :data:`SPANS` never get here).

    Raises
    ------
    ModelError

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.inputs import check_finite
    >>> a = examples.hitch_003().analyze([0.42, 0.67])                # S [m]
    >>> check_finite(a)                                              # all finite
    >>> a.kinematics.output_buffer[0, 1] = float("inf")  # spoil X23 at S = 0.67 m
    >>> check_finite(a)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: mechanism 'hitch_003': the position of point '23' is not finite (element 1): the inputs are outside the range where it can be computed; check the sizes of lengths, loads, bores and efficiencies
    """
    kin = analysis.kinematics
    for bad in (kin.first_nonfinite(), analysis.statics.first_nonfinite()):
        if bad is not None:
            name = f"mechanism {kin.mechanism.name!r}"
            raise ModelError(f"{name}: the {bad[0]} is not finite (element {bad[1]}): the "
                             f"inputs are outside the range where it can be computed; check "
                             f"the sizes of lengths, loads, bores and efficiencies")
    items = []   # (what, value or tuple of values)
    dyn = getattr(analysis, "dynamics", None)
    if dyn is not None:
        bad = dyn.statics.first_nonfinite()
        if bad is not None:
            name = f"mechanism {kin.mechanism.name!r}"
            raise ModelError(f"{name}: the {bad[0]} with inertia is not finite (element "
                             f"{bad[1]}): check the masses, speeds and lengths")
        items.append(("reduced moment of inertia", dyn.reduced_inertia))
        items.append(("reduced moment", dyn.reduced_moment))
    for name_, cyl in analysis.cylinders.items():
        # the force F_req = ±p·k·A·η_h is finite where the pressure is (k, A, η_h are
        # finite and positive within SPANS): its own check would repeat this one
        items.append(("pressure of cylinder", name_, cyl.pressure))
        items.append(("largest force of cylinder", name_, cyl.force_max))
    for what, *whose, vals in items:
        for v in (vals if isinstance(vals, tuple) else (vals,)):
            if all_finite(v):
                continue
            a = np.asarray(v, dtype=float).ravel()
            i = int(np.flatnonzero(~np.isfinite(a))[0])
            what = f"{what} {whose[0]!r}" if whose else what
            raise ModelError(f"mechanism {kin.mechanism.name!r}: the {what} is "
                             f"{float(a[i])!r} (element {i}): the inputs are outside "
                             f"the range where it can be computed; check the sizes of "
                             f"lengths, loads, bores and efficiencies")
