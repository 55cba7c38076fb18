"""The kernel of a structure evaluated by numpy, for the first small calls of a process.

A compiled kernel (:mod:`assur.kernel.source`) needs numba, and numba's first use in a
process costs about half a second whatever the work: its import, and the set-up of
its target (every implementation registry, scipy's BLAS) before even a cached kernel
can be loaded. A command that solves a few positions (``assur check``: the design
conditions, then the model's range) or a page's first slider move would spend
nearly all its time there.

So the calls of a process run the *same* emitted code — each group type's
:meth:`~assur.groups.base.Group.emit` lines, conditional expressions as selects — as
numpy expressions over all elements at once (``np.where`` for the selects,
``np.minimum``/``np.maximum`` for ``min``/``max``), a straight-line evaluation of
arrays with no loop over positions, when (:func:`wanted`):

* the structure's compiled kernel is not *ready* — never compiled on this machine
  (a new structure, a new group, a new point) — and the call has at most
  :data:`LARGE` elements: a check, a report's positions, a page's answers never wait
  for the compiler. A process that keeps evaluating such kernels (a simulation, an
  optimization: :data:`RENT` seconds of numpy evaluation) compiles each in a
  background thread (:func:`rent`) and uses it once it is ready;
* or, for a ready kernel, while numba is not in the process and the call is one of
  its first :data:`CALLS` small ones (at most :data:`SMALL` elements): numba's
  start-up (about half a second) would cost more than the calls.

A call of more than :data:`LARGE` elements pays for a compilation: it is compiled
(on the calling thread, if it is not ready). A compiled kernel is *ready* once it
ran here or has a mark on disk (:func:`is_ready`, :func:`mark_ready`): numba's own disk cache
then loads it without compiling.

The results are those of the compiled kernel to rounding: the same operations in the
same order (``tests/kernel/test_vector.py`` compares the two on random mechanisms
of every group type, and the one-position path with the array path); the status
codes and the continuity check (:func:`assur.kernel.source.continuity_check`) are
the same.

Like the compiled kernels (``error_model="numpy"``), the evaluation computes both
operands of every select: 1/0 and sqrt(−1) at an element that does not assemble
give inf and NaN there, which the select discards and the status code reports
(an :class:`~assur.errors.AssemblyError` naming the group, its links and values);
numpy's floating-point warnings are therefore off inside the kernel only, exactly
as they are in the compiled code.
"""

from __future__ import annotations

import builtins
import os
import re
import sys
import threading

from .emit import CODES_PER_OP, CONTINUITY_TOL, FAIL_CONTINUITY
from .select import branchless
from .source import CHUNK, FORMAT, emit_program, quantities

__all__ = ["SMALL", "LARGE", "RENT", "CALLS", "ready_key", "is_ready", "mark_ready", "rent",
           "settle",
           "compiling", "serving", "BACKENDS", "ELEMENTS_START", "backend", "set_backend", "wanted", "is_vector",
           "vector_lines", "reduce_chunks", "generate_vector", "load_vector", "calls_left",
           "set_calls"]

#: elements (designs × positions) of a call that the numpy evaluation takes at most
#: (while numba is not in the process, :data:`CALLS` of them): 1–5 ms each for the
#: bundled structures of 11–20 groups (a crank turn of 361 positions: 1.5 ms), so the
#: calls cost less than numba's start-up even before :data:`CALLS` stops them
SMALL = 1024

#: calls evaluated by numpy in a process before the compiled kernels take over; each
#: costs about 1–3 ms for a ten-group structure, the compiled kernels' first use in a
#: process about 0.5 s. A check of a bundled model makes at most a dozen; a process
#: that makes more (a simulation, a sweep of single positions) loses at most ~0.1 s
#: before it runs compiled
CALLS = 50

#: elements of a call that the numpy evaluation takes while the structure's compiled
#: kernel is not ready: about 10–40 ms for a ten-group structure (a crank turn of 361
#: positions, a grid of 13 × 8), where its compilation costs 5–30 s
LARGE = 4096

#: seconds of numpy evaluation of a not-yet-compiled kernel, in a process, after which
#: it is compiled in a background thread (the rent-or-buy rule): a process that keeps
#: evaluating (a simulation, an optimization) then runs compiled, a short one (a
#: check, a report) never starts the compiler
RENT = 1.0

_state = {"calls": 0, "limit": None, "backend": None, "rent": None}
_READY: set = set()
_RENT = {"spent": {}, "started": set(), "threads": []}
_VECTORS: dict = {}

#: how a kernel call is evaluated: ``"auto"`` (the rule above: the first small calls
#: of a process by numpy, then compiled), ``"numpy"`` (always the numpy evaluation,
#: any size: nothing is compiled — e.g. short scripts on many new structures, or
#: where numba's compiler is slow or missing), ``"numba"`` (always compiled)
BACKENDS = ("auto", "numpy", "numba")


def backend() -> str:
    """The evaluation of kernel calls in this process: :func:`set_backend`'s, else
    ``$ASSUR_KERNELS``, else ``"auto"`` (see :data:`BACKENDS`).

    Examples
    --------
    >>> from assur.kernel.vector import backend, set_backend
    >>> set_backend("numpy")
    >>> backend()
    'numpy'
    >>> set_backend(None)                     # back to $ASSUR_KERNELS or "auto"
    """
    name = _state["backend"] or os.environ.get("ASSUR_KERNELS") or "auto"
    if name not in BACKENDS:
        raise ValueError(f"ASSUR_KERNELS={name!r}: the kernels' evaluation is one of "
                         f"{list(BACKENDS)}")
    return name


def set_backend(name: str | None) -> None:
    """Evaluate the kernel calls of this process by ``name`` (one of :data:`BACKENDS`;
    None: back to ``$ASSUR_KERNELS`` or ``"auto"``). The results are the same to
    rounding (the same emitted operations in the same order).

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.kernel.vector import set_backend
    >>> set_backend("numpy")                  # no kernel is compiled from here on
    >>> try:
    ...     kin = examples.hitch_003().solve(np.linspace(0.42, 0.67, 1000))  # S [m]
    ... finally:
    ...     set_backend(None)
    >>> round(float(kin.y("56")[-1]), 4)      # Y56 at Smax [m], seed 003 table 2.1
    1.0432
    >>> set_backend("jit")
    Traceback (most recent call last):
    ...
    ValueError: the kernels' evaluation is one of ['auto', 'numpy', 'numba'], got 'jit'
    """
    if name is not None and name not in BACKENDS:
        raise ValueError(f"the kernels' evaluation is one of {list(BACKENDS)}, got {name!r}")
    _state["backend"] = name


def set_calls(n: int | None) -> None:
    """Evaluate at most ``n`` more small calls of this process with numpy (0: always
    compiled; None: back to :data:`CALLS` in all).

    Examples
    --------
    >>> import sys
    >>> from assur.kernel.vector import calls_left, set_backend, set_calls, wanted
    >>> set_backend("auto")                   # the rule (whatever $ASSUR_KERNELS says)
    >>> set_calls(0)                          # always compiled from now on
    >>> int(calls_left()), wanted(10)
    (0, False)
    >>> set_calls(3)
    >>> bool(calls_left() == (0 if "numba" in sys.modules else 3))   # with numba: compiled
    True
    >>> set_calls(None)                       # back to CALLS
    >>> set_backend(None)
    >>> set_calls(-1)
    Traceback (most recent call last):
    ...
    ValueError: calls must be ≥ 0, got -1
    """
    if n is None:
        _state["calls"], _state["limit"] = 0, None
    else:
        if int(n) < 0:
            raise ValueError(f"calls must be ≥ 0, got {n!r}")
        _state["calls"], _state["limit"] = 0, int(n)


def calls_left() -> int:
    """Small calls this process may still evaluate with numpy.

    Examples
    --------
    >>> import sys
    >>> from assur.kernel.vector import CALLS, calls_left, set_backend, set_calls, wanted
    >>> set_backend("auto")                   # the rule (whatever $ASSUR_KERNELS says)
    >>> set_calls(None)
    >>> bool(calls_left() == (0 if "numba" in sys.modules else CALLS))   # 50 without numba
    True
    >>> set_calls(2)
    >>> _ = wanted(10)                        # a small call counts (if it is evaluated)
    >>> bool(calls_left() == (0 if "numba" in sys.modules else 1))
    True
    >>> set_calls(None)
    >>> set_backend(None)
    """
    if "numba" in sys.modules:  # its import is paid: the compiled kernels are cheap now
        return 0
    limit = CALLS if _state["limit"] is None else _state["limit"]
    return builtins.max(0, limit - _state["calls"])  # the module's max is numpy's


def wanted(elements: int, ready=None) -> bool:
    """True if a call over ``elements`` elements is to be evaluated by numpy (and
    counts it). ``ready``: a callable telling whether the call's compiled kernel is
    ready (:func:`is_ready`); without it, the kernel is taken as ready.

    Examples
    --------
    >>> import sys
    >>> from assur.kernel.vector import LARGE, SMALL, set_backend, set_calls, wanted
    >>> set_backend("auto")                   # the rule (whatever $ASSUR_KERNELS says)
    >>> wanted(SMALL + 1)                     # 1025 elements of a ready kernel: compiled
    False
    >>> wanted(LARGE, ready=lambda: False), wanted(LARGE + 1, ready=lambda: False)
    (True, False)
    >>> set_calls(1)
    >>> wanted(10) == ("numba" not in sys.modules), wanted(10)   # the one call left, then none
    (True, False)
    >>> set_calls(None)
    >>> set_backend("numpy")
    >>> wanted(10 ** 6)                       # any size
    True
    >>> set_backend(None)
    """
    name = backend()
    if name != "auto":
        return name == "numpy"
    if elements > LARGE:
        return False  # a call that pays for a compilation
    if ready is not None and not ready():
        return True   # not compiled on this machine: never wait for the compiler
    if elements > SMALL or calls_left() <= 0:
        return False
    _state["calls"] += 1
    return True


def ready_key(*parts) -> str:
    """The key of a compiled kernel among the ready marks: a hash of ``parts`` (what its
    source is made of), of the code that emits it and of numba's version (a new
    version compiles again).

    Examples
    --------
    >>> from assur.kernel.vector import ready_key
    >>> k = ready_key("fused", (1, 2), 3)
    >>> len(k), k == ready_key("fused", (1, 2), 3), k == ready_key("fused", (1, 2), 4)
    (20, True, False)
    """
    import hashlib
    from importlib.metadata import PackageNotFoundError, version

    from . import compose
    from .cache import helpers_tag
    try:
        numba = version("numba")
    except PackageNotFoundError:  # pragma: no cover - numba is a dependency
        numba = "none"
    what = f"{FORMAT} {_code_version()} {helpers_tag()} {compose.THRESHOLD} {numba} {parts!r}"
    return hashlib.sha1(what.encode()).hexdigest()[:20]


def _mark(key):
    from .cache import cache_dir
    return cache_dir() / f"c_{key}.ready"


def is_ready(key: str) -> bool:
    """True if the compiled kernel ``key`` (:func:`ready_key`) ran in this process or
    has run on this machine (its mark on disk: numba's disk cache holds it, so it is
    loaded, not compiled).

    Examples
    --------
    >>> import tempfile
    >>> from assur.kernel import set_cache_dir
    >>> from assur.kernel.vector import is_ready, mark_ready, ready_key
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     set_cache_dir(tmp)
    ...     try:
    ...         k = ready_key("doc example", 1)
    ...         before = is_ready(k)
    ...         mark_ready(k)
    ...         after = is_ready(k)
    ...     finally:
    ...         set_cache_dir(None)
    >>> before, after
    (False, True)
    """
    if key in _READY:
        return True
    if _mark(key).exists():
        _READY.add(key)
        return True
    return False


def mark_ready(key: str) -> None:
    """Mark the compiled kernel ``key`` ready, in this process and on disk (after it
    ran: numba has written it to its cache).

    Examples
    --------
    >>> import tempfile
    >>> from assur.kernel import cache_dir, set_cache_dir
    >>> from assur.kernel.vector import mark_ready, ready_key
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     set_cache_dir(tmp)
    ...     try:
    ...         mark_ready(ready_key("doc example", 2))
    ...         marks = [p.suffix for p in cache_dir().iterdir()]
    ...     finally:
    ...         set_cache_dir(None)
    >>> marks                                  # c_<key>.ready, an empty file
    ['.ready']
    """
    _READY.add(key)
    path = _mark(key)
    if not path.exists():
        tmp = path.with_suffix(f".{os.getpid()}.{threading.get_ident()}.tmp")
        tmp.write_bytes(b"")
        os.replace(tmp, path)


def rent(seconds: float, key: str, compile_) -> None:
    """Count ``seconds`` of numpy evaluation of the not-yet-compiled kernel ``key``;
    once the process has spent :data:`RENT` seconds on it, run ``compile_()`` (which
    compiles the kernel, runs it and marks it ready) in a background thread, once per
    kernel: the calls go on by numpy meanwhile and take the compiled kernel when it is
    ready. A failure of the background compilation is logged, never raised: the
    numpy evaluation stays.

    Examples
    --------
    >>> from assur.kernel.vector import RENT, compiling, rent, set_backend
    >>> set_backend("auto")
    >>> made = []
    >>> rent(RENT / 2, "doc-example", lambda: made.append(1))   # not yet
    >>> rent(RENT, "doc-example", lambda: made.append(1))       # past the rent: compiled
    >>> rent(RENT, "doc-example", lambda: made.append(1))       # once per kernel
    >>> compiling(wait=True), made
    (False, [1])
    >>> set_backend(None)
    """
    if backend() != "auto" or key in _RENT["started"]:
        return
    spent = _RENT["spent"][key] = _RENT["spent"].get(key, 0.0) + float(seconds)
    if spent < (RENT if _state["rent"] is None else _state["rent"]):
        return
    _RENT["started"].add(key)
    t = threading.Thread(target=_background, args=(key, compile_), daemon=True,
                         name=f"assur-compile-{key[:8]}")
    _RENT["threads"].append(t)
    t.start()


def settle(key: str, vector: bool, seconds: float, compile_) -> None:
    """After a call of the kernel ``key``: a compiled run marks it ready
    (:func:`mark_ready`); a numpy run of a kernel not ready pays its ``seconds`` of rent
    (:func:`rent`; ``compile_`` is called only if the rent makes it compile, so it
    copies what it needs then, not at every call).

    Examples
    --------
    >>> import tempfile
    >>> from assur.kernel import set_cache_dir
    >>> from assur.kernel.vector import is_ready, ready_key, settle
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     set_cache_dir(tmp)
    ...     try:
    ...         k = ready_key("doc example", 3)
    ...         settle(k, True, 0.0, None)     # by numpy, no rent yet: not ready
    ...         before = is_ready(k)
    ...         settle(k, False, 0.0, None)    # it ran compiled: ready
    ...         after = is_ready(k)
    ...     finally:
    ...         set_cache_dir(None)
    >>> before, after
    (False, True)
    """
    if not vector:
        if not is_ready(key):
            mark_ready(key)  # it ran: numba's cache holds it
    elif not is_ready(key):
        rent(seconds, key, compile_)


def serving() -> None:
    """Make this process one that runs for long (a page's server, ``assur serve``): every
    kernel not yet compiled on this machine is compiled in a background thread from its
    first call (no :data:`RENT` to pay first), and numba is imported now, so that the
    compiled kernels — ready ones loaded from numba's disk cache — take over from the
    numpy evaluation as soon as each is there. A page's answer then costs the compiled
    kernel's microseconds per call instead of the numpy evaluation's milliseconds
    (``benchmarks/page.py``); the calls made meanwhile go on by numpy. Only for processes
    that live long: a short command would pay numba's start-up (about half a second)
    and compilations it never uses.

    Examples
    --------
    >>> import subprocess, sys
    >>> code = ("from assur.kernel import vector; vector.set_backend('auto'); "
    ...         "vector.serving(); print(vector.calls_left(), vector.wanted(10))")
    >>> subprocess.run([sys.executable, "-c", code], capture_output=True,
    ...                text=True).stdout.split()   # no numpy calls left: compiled
    ['0', 'False']
    """
    _state["rent"] = 0.0
    import numba  # noqa: F401 - its start-up paid here, in the caller's thread


def _background(key, compile_):
    try:
        compile_()
    except Exception:  # noqa: BLE001 — the numpy evaluation stays; say why
        import logging
        logging.getLogger("assur.kernel").exception(
            "compiling a kernel in the background failed (its numpy evaluation stays)")


def compiling(wait: bool = False) -> bool:
    """True while a kernel is being compiled in the background (:func:`rent`); with
    ``wait``, wait for them all first (a process that wants its compiled kernels).

    Examples
    --------
    >>> from assur.kernel.vector import compiling
    >>> compiling(wait=True)                  # none left (none started here)
    False
    """
    threads = _RENT["threads"]
    if wait:
        for t in list(threads):
            t.join()
    threads[:] = [t for t in threads if t.is_alive()]
    return bool(threads)


def is_vector(kernel) -> bool:
    """True for a kernel evaluated by numpy (it takes all elements in one call).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.kernel.vector import is_vector
    >>> prog = examples.hitch_003().program()
    >>> is_vector(prog.kernel(vector=True)), is_vector(lambda *args: 0)
    (True, False)
    """
    return bool(getattr(kernel, "__globals__", {}).get("VECTOR", False))


def vector_lines(lines):
    """The emitted element code as numpy statements: per-design reads and the
    coordinates become whole-row locals, conditional expressions selects;
    ``(head, body)`` lines, indented for the body of a generated ``kernel``.

    Examples
    --------
    >>> from assur.kernel.vector import vector_lines
    >>> head, body = vector_lines(["x3 = params[4, d] * q[0, e] if st < 0 else 0.0"])
    >>> [ln.strip() for ln in head], [ln.strip() for ln in body]
    (['P4 = params[4, D]', 'Q0 = q[0]'], ['x3 = _sel(st < 0, P4 * Q0, 0.0)'])
    """
    prows, trows, qrows = set(), set(), set()
    out = []
    for line in lines:
        prows.update(int(m) for m in re.findall(r"params\[(\d+), d\]", line))
        trows.update(int(m) for m in re.findall(r"trig\[(\d+), d\]", line))
        qrows.update(int(m) for m in re.findall(r"q\[(\d+), e\]", line))
        line = re.sub(r"params\[(\d+), d\]", r"P\1", line)
        line = re.sub(r"trig\[(\d+), d\]", r"T\1", line)
        line = re.sub(r"q\[(\d+), e\]", r"Q\1", line)
        out.append("        " + branchless(line).strip())
    head = [f"        P{r} = params[{r}, D]" for r in sorted(prows)]
    head += [f"        T{r} = trig[{r}, D]" for r in sorted(trows)]
    head += [f"        Q{r} = q[{r}]" for r in sorted(qrows)]
    return head, out


#: the start of a numpy-evaluated kernel's element code (after ``E``, the number of
#: elements; the kernels of :func:`generate_vector` and of :mod:`assur.core.outputs`):
#: the design of each element, and — as the compiled kernels' ``error_model="numpy"``
#: — no floating-point warnings: a select discards the inf/NaN of an element that does
#: not assemble, and its status code reports it
ELEMENTS_START = '''    D = 0 if params.shape[1] == 1 else np.arange(E) // npd
    with np.errstate(all="ignore"):
        st = -1
'''


def generate_vector(rows, measures, K, out_pts, out_sca) -> str:
    """Python source of the numpy evaluation of a structure (the arguments of
    :func:`assur.kernel.source.generate`); its ``kernel`` has the compiled kernel's
    signature and results.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.kernel.vector import generate_vector
    >>> prog = examples.hitch_003().program()
    >>> src = generate_vector(prog.rows, prog.measures, prog.k, (prog.slot["56"],), ())
    >>> "def kernel(params, trig, q, npd, check, out, amount, status, c_start, c_end):" in src
    True
    >>> [ln.strip() for ln in src.splitlines() if ln.strip().startswith("out[")]   # x, y and jets of 56
    ['out[0] = _sel(ok_, x7, 0.0)', 'out[1] = _sel(ok_, y7, 0.0)', 'out[2] = _sel(ok_, x7_0, 0.0)', 'out[3] = _sel(ok_, y7_0, 0.0)', 'out[4] = _sel(ok_, x7_00, 0.0)', 'out[5] = _sel(ok_, y7_00, 0.0)']
    """
    E, cont = emit_program(rows, measures, K)
    head, body = vector_lines(E.lines)
    qs = quantities(K, out_pts, out_sca)
    ind = "        "
    outs = [ind + "ok_ = st < 0"]
    outs += [ind + f"out[{qi}] = _sel(ok_, {v}, 0.0)" for qi, v in enumerate(qs)]
    outs.append(ind + "status[:] = st")
    groups = ", ".join(f"({i * CODES_PER_OP + FAIL_CONTINUITY}, g{i}, gd{i})" for i in cont)
    check = (f"{ind}if check:\n{ind}    nfail = _continuity(q[0], npd, status, amount, ok_, "
             f"[{groups}])\n") if cont else ""
    return f'''"""Generated by assur.kernel.vector (format {FORMAT}); do not edit."""
import numpy as np
from assur.kernel.vector import _continuity, _sel, math, max, min

CHECKS_CONTINUITY = True  # see assur.kernel.compose.checks_continuity
VECTOR = True


def kernel(params, trig, q, npd, check, out, amount, status, c_start, c_end):
    """All elements at once, as numpy arrays (c_start, c_end: the whole range; the
    compiled kernel's signature). out: (NQ, E) outputs in the order of
    assur.kernel.source.quantities; with ``check`` the continuity of every dyad
    between consecutive positions: failures get the group's code in ``status`` and
    the depth in ``amount``; returns their number."""
    E = q.shape[1]
    if out.shape[0] != {len(qs)} or out.shape[1] != E or (check and amount.shape[0] != E):
        raise ValueError("assur kernel: output arrays do not match the program")
    nfail = 0
{ELEMENTS_START}''' + "\n".join(head + body + outs) + "\n" + check + "    return nfail\n"


def load_vector(rows, measures, K, out_pts, out_sca):
    """The numpy-evaluated kernel of a structure (cached per process, and on disk by
    the structure and the code that emits it: a later process imports it — bytecode
    cached — without generating it again).

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.kernel.vector import load_vector
    >>> m = examples.hitch_003()
    >>> prog = m.program()
    >>> kernel = load_vector(prog.rows, prog.measures, prog.k, (prog.slot["56"],), ())
    >>> ptab, trig, _ = m.prepared(prog)
    >>> q = np.array([[0.42, 0.67]])                  # S [m]
    >>> out, amount, status = np.empty((6, 2)), np.empty(2), np.empty(2, dtype=np.int64)
    >>> kernel(ptab, trig, q, 2, True, out, amount, status, 0, 1), status.tolist()
    (0, [-1, -1])
    >>> [round(float(v), 3) for v in out[1]], [round(float(v), 3) for v in out[3]]  # Y56 [m], I56 [-]
    ([0.2, 1.043], [4.459, 2.621])
    """
    key = (rows, measures, K, out_pts, out_sca)
    fn = _VECTORS.get(key)
    if fn is None:
        from .cache import load_keyed
        fn = _VECTORS[key] = load_keyed(
            f"vector {FORMAT} {_code_version()} {key!r}",
            lambda: generate_vector(rows, measures, K, out_pts, out_sca))
    return fn


_version: list = []


def _code_version() -> str:
    """Hash of the source of every module that shapes the emitted code (the group
    types, :mod:`assur.kernel.emit`, ``source``, ``fold``, ``select`` and this one): a
    change to any of them is a new cache entry."""
    if not _version:
        import hashlib
        from pathlib import Path

        from . import emit, fold, ops, select, source
        mods = ops.source_modules() | {sys.modules[__name__], emit, fold, select, source}
        h = hashlib.sha1()
        for f in sorted(str(m.__file__) for m in mods):
            h.update(Path(f).read_bytes())
        _version.append(h.hexdigest()[:16])
    return _version[0]


# ---- the namespace of the generated code -------------------------------------------

def _np():
    import numpy as np
    return np


class _Math:
    """``math`` of the emitted code, elementwise (numpy's ufuncs)."""

    def __getattr__(self, name):
        np = _np()
        fn = {"sqrt": np.sqrt, "copysign": np.copysign, "sin": np.sin, "cos": np.cos,
              "tan": np.tan, "atan2": np.arctan2, "acos": np.arccos, "asin": np.arcsin,
              "atan": np.arctan, "hypot": np.hypot, "exp": np.exp, "log": np.log,
              "fabs": np.fabs, "pi": np.pi, "inf": np.inf}.get(name)
        if fn is None:
            raise AttributeError(f"assur.kernel.vector: math.{name} has no elementwise form")
        setattr(self, name, fn)
        return fn


math = _Math()


def _sel(cond, a, b):
    """``a if cond else b`` elementwise."""
    return _np().where(cond, a, b)


def min(a, b):  # noqa: A001 — the emitted code's min, elementwise
    """Elementwise minimum."""
    return _np().minimum(a, b)


def max(a, b):  # noqa: A001
    """Elementwise maximum."""
    return _np().maximum(a, b)


def _continuity(q0, npd, status, amount, ok, groups):
    """The continuity check of :func:`assur.kernel.source.continuity_check` over all
    elements: every interval between consecutive assembled positions of a design and
    every group ``(code, g, gd)`` in order; the interval's right-hand element gets the
    first failing group's code and the depth [m²] in ``amount``. An element so marked
    is not the left end of a checked interval — unless the interval starts a work item
    of the compiled kernel (a run of :data:`~assur.kernel.source.CHUNK` positions),
    which computes its left end again, unmarked. Returns the number of failures."""
    np = _np()
    E = status.shape[0]
    if E < 2 or not groups:
        return 0
    e = np.arange(1, E)
    both = (e % npd != 0) & (status[1:] < 0) & (status[:-1] < 0)
    hs = q0[1:] - q0[:-1]
    h = np.abs(hs)
    first = np.full(E - 1, -1, dtype=np.int64)
    depth = np.zeros(E - 1)
    for code, g, gd in groups:
        g = np.where(ok, g, 0.0) * np.ones(E)  # staged as the compiled kernel stages them
        gd = np.where(ok, gd, 0.0) * np.ones(E)
        g0, g1, d0, d1 = g[:-1], g[1:], gd[:-1], gd[1:]
        mn = np.minimum(g0, g1)
        quick = mn - (4.0 / 27.0) * h * (np.abs(d0) + np.abs(d1)) > 0.0
        for ii in range(1, 16):
            t = ii / 16.0
            t2 = t * t
            t3 = t2 * t
            v = ((2.0 * t3 - 3.0 * t2 + 1.0) * g0
                 + (t3 - 2.0 * t2 + t) * hs * d0
                 + (-2.0 * t3 + 3.0 * t2) * g1 + (t3 - t2) * hs * d1)
            mn = np.where(v < mn, v, mn)
        bad = both & ~quick & (mn < -CONTINUITY_TOL * np.maximum(g0, g1)) & (first < 0)
        first[bad] = code
        depth[bad] = mn[bad]
    nfail = 0
    for j in np.flatnonzero(first >= 0):  # the few failing intervals, in order
        # its left end failed in this pass (within a work item of the compiled kernel)
        if status[j] >= 0 and ((j + 1) % npd) % CHUNK != 0:
            continue
        status[j + 1] = first[j]
        amount[j + 1] = depth[j]
        nfail += 1
    return nfail


def reduce_chunks(values, ok, npd, E, red):
    """The fused kernel's reductions, all elements at once: for each output row ``r``
    (``values[r]``, shape (E,) or a scalar; E elements, ``npd`` per design) and each work item ``c`` of the compiled
    kernel (runs of ≤ :data:`~assur.kernel.source.CHUNK` positions of one design),
    ``red[4r : 4r + 4, c]`` = minimum, maximum and where they are (position in the
    design; −1 when none) over the elements where ``ok`` — the compiled kernel's
    scalar pass (:mod:`assur.core.outputs`): the first of equal values, NaN skipped.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.kernel.vector import reduce_chunks
    >>> v = np.array([3.0, 1.0, 2.0, 5.0, 4.0, 6.0])          # 2 designs × 3 positions
    >>> ok = np.array([True, True, True, False, True, False])
    >>> red = np.empty((4, 2))
    >>> reduce_chunks([v], ok, 3, 6, red)
    >>> red.tolist()                                           # min, max, argmin, argmax
    [[1.0, 4.0], [3.0, 4.0], [1.0, 1.0], [0.0, 1.0]]
    """
    np = _np()
    m = E // npd
    cpd = (npd + CHUNK - 1) // CHUNK
    W = npd if cpd == 1 else CHUNK
    pad = cpd * W - npd
    base = (np.arange(m * cpd) % cpd) * W
    for r, v in enumerate(values):
        v = np.broadcast_to(np.asarray(v, dtype=float), (E,))
        good = np.broadcast_to(ok, (E,)) & (v == v)
        for k, (fill, arg) in enumerate(((np.inf, np.argmin), (-np.inf, np.argmax))):
            a = np.where(good, v, fill).reshape(m, npd)
            if pad:
                a = np.concatenate([a, np.full((m, pad), fill)], axis=1)
            a = a.reshape(m * cpd, W)
            i = arg(a, axis=1)
            best = a[np.arange(m * cpd), i]
            red[4 * r + k] = best
            red[4 * r + 2 + k] = np.where(best == fill, -1.0, base + i)

