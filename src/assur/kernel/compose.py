"""Composed kernels for large structures: one small compiled function per distinct
group *shape*, called in order by a generated driver.

The fused kernel of :mod:`assur.kernel.source` is fastest at run time, but numba
and LLVM compile it in time that grows faster than the number of groups. Above
:data:`THRESHOLD` groups (and measures) a structure gets a composed kernel instead,
with the same signature, outputs, status codes and continuity staging:

* each group's code (and each measure's) is emitted as for the fused kernel, with
  group index 0, and made *canonical*: the values it shares with other groups (the
  jets of its points ``x5_0``…, its measures ``s2``…, its continuity staging
  ``g0``/``gd0``) are renamed ``v0, v1, …`` in order of appearance, its parameter and
  trig rows ``P0, P1, …`` and ``T0, …``, its status codes offset by an argument
  ``sb`` (``CODES_PER_OP·i``). Groups of one type that differ only in which points
  and parameters they use have the same canonical source;
* each distinct canonical source is one ``@njit(cache=True)`` function over a block
  of elements of one design: it reads its inputs from rows of a state array
  ``S[row, j]``, runs the straight-line code (vectorizable loop), writes its
  outputs back. It is stored in the kernel cache by its hash, so it is compiled
  once per machine and shared by every structure that uses it;
* the driver (generated per structure, small) loops over the blocks and calls, for
  each group, its function through an if-chain over function numbers with the
  group's rows (tables of integers, constants of the driver), then copies the
  requested quantities to ``out`` (0 at failed elements) and the staging to ``gout``.

Compile time is that of the distinct functions (a few per group type, once) plus a
driver whose size grows with the number of distinct functions, not of groups. The
values are those of the fused kernel bit for bit: the same expressions in the same
order, passed between groups through memory in float64.
"""

from __future__ import annotations

import ast
import hashlib
import re

from .ops import op
from .cache import helpers_tag, load_source
from .emit import CODES_PER_OP, Emitter
from .fold import fold
from .source import CHUNK, FORMAT, emit_measure, generate, quantities

__all__ = ["THRESHOLD", "BLOCK", "canonical", "generate_composed", "is_fused",
           "checks_continuity", "load_kernel"]

#: structures with more groups + measures than this get a composed kernel (set to
#: 0 to compose every structure, to a large number to fuse every one)
THRESHOLD = 20

#: elements per call of a group function (the state array is (names, BLOCK))
BLOCK = 256

_EXPORTED = re.compile(r"^(?:[xys]\d+(?:_\w+)?|gd?\d+)$")


class _Canon(ast.NodeTransformer):
    """Renames exported names to v{k}, makes conditional expressions selects and
    status codes relative to ``sb``."""

    def __init__(self):
        self.names: dict[str, int] = {}
        self.loaded: set = set()
        self.stored: set = set()

    def visit_Name(self, node):
        if _EXPORTED.match(node.id):
            k = self.names.setdefault(node.id, len(self.names))
            if isinstance(node.ctx, ast.Store):
                self.stored.add(node.id)
            elif node.id not in self.stored:
                self.loaded.add(node.id)
            return ast.copy_location(ast.Name(f"v{k}", node.ctx), node)
        return node

    def visit_Assign(self, node):
        # st = code if (...) else st  ->  st = _sel(..., sb + code, st)
        v = node.value
        if (len(node.targets) == 1 and isinstance(node.targets[0], ast.Name)
                and node.targets[0].id == "st" and isinstance(v, ast.IfExp)
                and isinstance(v.body, ast.Constant) and isinstance(v.body.value, int)):
            v.body = ast.BinOp(ast.Name("sb", ast.Load()), ast.Add(), ast.Constant(v.body.value))
        node.value = self.visit(node.value)  # loads before the store
        node.targets = [self.visit(t) for t in node.targets]
        return node

    def visit_IfExp(self, node):
        self.generic_visit(node)
        return ast.copy_location(
            ast.Call(func=ast.Name("_sel", ast.Load()),
                     args=[node.test, node.body, node.orelse], keywords=[]), node)


def canonical(lines):
    """Canonical form of one group's emitted lines.

    Returns ``(body, names, inputs, outputs, prows, trows)``: the body's lines,
    the exported names in the order of their ``v{k}``, which of them are read
    before written (inputs) and which are written (outputs), and the parameter
    and trig rows of ``P{k}`` and ``T{k}``.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.groups import group_type
    >>> from assur.kernel.compose import canonical
    >>> from assur.kernel.emit import Emitter
    >>> row = examples.hitch_003().program().rows[6]   # dyad II (4,5): 34 and 05 → 45
    >>> E = Emitter(1)
    >>> group_type(row[0]).emit(E, 0, row[1:])
    >>> body, names, inputs, outputs, prows, trows = canonical(E.lines)
    >>> inputs[:4], outputs[:4]     # jets of the points in slots 5, 2 read; of slot 6 written
    (['x2', 'x5', 'y2', 'y5'], ['x6', 'y6', 'x6_0', 'y6_0'])
    >>> prows, body[0]              # parameter rows of L4, L5 become P0, P1
    ([28, 9], 't0ra = P0')
    """
    prows: dict[int, int] = {}
    trows: dict[int, int] = {}

    def sub_p(m):
        return f"P{prows.setdefault(int(m.group(1)), len(prows))}"

    def sub_t(m):
        return f"T{trows.setdefault(int(m.group(1)), len(trows))}"

    tr = _Canon()
    body = []
    for line in lines:
        s = line.strip()
        if not s or s.startswith("#"):
            continue
        s = re.sub(r"trig\[(\d+), d\]", sub_t, re.sub(r"params\[(\d+), d\]", sub_p, s))
        tree = tr.visit(ast.parse(s))
        body.append(ast.unparse(ast.fix_missing_locations(tree)))
    names = sorted(tr.names, key=tr.names.get)
    outputs = [n for n in names if n in tr.stored]
    inputs = [n for n in names if n in tr.loaded]
    return body, names, inputs, outputs, list(prows), list(trows)


def _group_source(body, names, inputs, outputs, n_p, n_t):
    """Source of the compiled function of one canonical group."""
    k = {n: i for i, n in enumerate(names)}
    ind = "        "
    head = [f"    P{i} = params[prm[{i}], d]" for i in range(n_p)]
    head += [f"    T{i} = trig[trg[{i}], d]" for i in range(n_t)]
    head += [f"    r{i} = loc[{i}]" for i in range(len(names))]
    loads = [ind + f"v{k[n]} = S[r{k[n]}, j]" for n in inputs]
    stores = [ind + f"S[r{k[n]}, j] = v{k[n]}" for n in outputs]
    return (f'"""Generated by assur.kernel.compose (format {FORMAT}, helpers {helpers_tag()}); '
            f'do not edit."""\n'
            "import math\nfrom numba import njit\n"
            "from assur.kernel.select import sel as _sel\n\n\n"
            '@njit(cache=True, error_model="numpy", nogil=True)\n'
            "def grp(S, stv, params, trig, q, d, e0, n, loc, prm, trg, sb):\n"
            + "\n".join(head + ["    for j in range(n):", ind + "e = e0 + j",
                                ind + "st = stv[j]"] + loads
                        + [ind + b for b in body] + stores + [ind + "stv[j] = st"]) + "\n")


def _int_array(name, values):
    vals = ", ".join(str(int(v)) for v in values) or ""
    return f"{name} = np.array([{vals}], dtype=np.int64)\n"


def _emitted(rows, measures, K):
    """Each group's and measure's emitted lines with its status base, and the groups
    checked for continuity (k = 1), whose staging ``g0``/``gd0`` is renamed by group."""
    items = []  # (emitted lines, status base)
    cont = []
    for i, row in enumerate(rows):
        gt = op(row[0])
        E = Emitter(K)
        gt.emit(E, 0, tuple(int(v) for v in row[1:]))
        lines = E.lines
        if gt.continuity and K == 1:
            cont.append(i)
            lines = [re.sub(r"\bg(d?)0\b", rf"g\g<1>{i}", ln) for ln in lines]
        items.append((lines, i * CODES_PER_OP))
    n = len(rows)
    for j, (kind, s_, P, Q) in enumerate(measures):
        E = Emitter(K)
        emit_measure(E, 0, kind, s_, P, Q)
        items.append((E.lines, (n + j) * CODES_PER_OP))
    return items, cont


def _calls(items):
    """The distinct group sources, the rows of the state array (``{name: row}``) and
    the calls: ``(function number, loc rows, param rows, trig rows, status base)``."""
    srcs, keys = [], {}
    state: dict[str, int] = {}
    calls = []
    for lines, sb in items:
        body, names, inputs, outputs, prows, trows = canonical(fold(lines))
        src = _group_source(body, names, inputs, outputs, len(prows), len(trows))
        if src not in keys:
            keys[src] = len(srcs)
            srcs.append(src)
        for nm in inputs:
            if nm not in state:
                raise ValueError(f"assur compose: {nm} is read before it is computed")
        loc = [state.setdefault(nm, len(state)) for nm in names]
        calls.append((keys[src], loc, prows, trows, sb))
    return srcs, state, calls


def _tables(calls, qrow, grow):
    """The driver's constant tables: the calls' function numbers, their rows as flat
    arrays with offsets, the rows of the requested quantities and of the staging."""
    def off(lists):
        return [0] + [sum(len(x) for x in lists[:i + 1]) for i in range(len(lists))]

    tab = _int_array("_FN", [c[0] for c in calls])
    tab += _int_array("_LOC", [v for c in calls for v in c[1]])
    tab += _int_array("_LOFF", off([c[1] for c in calls]))
    tab += _int_array("_PRM", [v for c in calls for v in c[2]])
    tab += _int_array("_POFF", off([c[2] for c in calls]))
    tab += _int_array("_TRG", [v for c in calls for v in c[3]])
    tab += _int_array("_TOFF", off([c[3] for c in calls]))
    tab += _int_array("_SB", [c[4] for c in calls])
    tab += _int_array("_QROW", qrow) + _int_array("_GROW", grow)
    return tab


def _driver_source(srcs, ncalls, nstate, tab, nq, ng):
    """Source of the driver: imports of the group functions by the hashes of their
    sources, the tables, and the loop over blocks calling them through an if-chain."""
    hashes = [hashlib.sha1(s.encode()).hexdigest()[:20] for s in srcs]
    imports = "".join(f'_f{k} = _group("{h}")\n' for k, h in enumerate(hashes))
    ind = "                "
    chain = []
    for k in range(len(srcs)):
        chain.append(ind + ("if" if k == 0 else "elif") + f" fn == {k}:")
        chain.append(ind + f"    _f{k}(S, stv, params, trig, q, d, b0, nb, loc, prm, trg, sb)")
    return f'''"""Generated by assur.kernel.compose (format {FORMAT}, helpers {helpers_tag()}); do not edit."""
import math
import numpy as np
from numba import njit
from assur.kernel.compose import _group

{imports}
{tab}

@njit(cache=True, error_model="numpy", nogil=True)
def kernel(params, trig, q, npd, check, out, gout, status, c_start, c_end):
    """Chunks c_start…c_end−1 of the elements (see assur.kernel.source), by
    {len(srcs)} group functions called {ncalls} times per block of elements."""
    E = q.shape[1]
    NQ = {nq}
    NG = {ng}
    if out.shape[0] != NQ or gout.shape[0] != NG or out.shape[1] != E:
        raise ValueError("assur kernel: output arrays do not match the program")
    S = np.zeros(({max(nstate, 1)}, {BLOCK}))
    stv = np.empty({BLOCK}, dtype=np.int64)
    cpd = (npd + {CHUNK} - 1) // {CHUNK}
    for c in range(c_start, c_end):
        d = c // cpd
        e0 = d * npd + (c % cpd) * {CHUNK}
        e1 = min(d * npd + npd, e0 + {CHUNK})
        for b0 in range(e0, e1, {BLOCK}):
            nb = min({BLOCK}, e1 - b0)
            for j in range(nb):
                stv[j] = -1
            for g in range({ncalls}):
                fn = _FN[g]
                loc = _LOC[_LOFF[g]:_LOFF[g + 1]]
                prm = _PRM[_POFF[g]:_POFF[g + 1]]
                trg = _TRG[_TOFF[g]:_TOFF[g + 1]]
                sb = _SB[g]
''' + "\n".join(chain) + '''
            for j in range(nb):
                status[b0 + j] = stv[j]
            for r in range(NQ):
                src = _QROW[r]
                for j in range(nb):
                    out[r, b0 + j] = S[src, j] if stv[j] < 0 else 0.0
            if check:
                for r in range(NG):
                    src = _GROW[r]
                    for j in range(nb):
                        gout[r, b0 + j] = S[src, j] if stv[j] < 0 else 0.0
'''


def generate_composed(rows, measures, K, out_pts, out_sca):
    """Sources of the composed kernel: ``(group_sources, driver)`` where the driver
    imports the group functions by the cache keys of their sources.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.kernel.compose import generate_composed
    >>> prog = examples.hitch_003().program()
    >>> srcs, driver = generate_composed(prog.rows, prog.measures, prog.k,
    ...                                  tuple(prog.slot[p] for p in prog.out_pts),
    ...                                  tuple(prog.scal[s] for s in prog.out_sca))
    >>> len(prog.rows) + len(prog.measures), len(srcs)   # 18 calls of 6 distinct functions
    (18, 6)
    >>> driver.count('_group("'), "def kernel(params, trig, q, npd, check, out, gout," in driver
    (6, True)
    """
    items, cont = _emitted(rows, measures, K)
    srcs, state, calls = _calls(items)
    qs = quantities(K, out_pts, out_sca)
    qrow = [state[v] for v in qs]
    grow = [state[f"g{s}{i}"] for i in cont for s in ("", "d")]
    driver = _driver_source(srcs, len(calls), len(state), _tables(calls, qrow, grow),
                            len(qs), len(grow))
    return srcs, driver


def _group(key):
    """The compiled function of a group source written to the cache (a driver's
    import calls this; :func:`load_kernel` has loaded them before)."""
    from .cache import _loaded, cache_dir
    mod = _loaded.get(key)
    if mod is None:
        return load_source((cache_dir() / f"k_{key}.py").read_text(), "grp")
    return mod.grp


def is_fused(rows, measures) -> bool:
    """True if the structure gets the fused kernel of :mod:`assur.kernel.source`, False
    for a composed one.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.kernel.compose import THRESHOLD, is_fused
    >>> prog = examples.hitch_003().program()       # 11 groups and 7 link angles
    >>> THRESHOLD, is_fused(prog.rows, prog.measures), is_fused(prog.rows * 2, prog.measures)
    (20, True, False)
    """
    return len(rows) + len(measures) <= THRESHOLD


def checks_continuity(kernel) -> bool:
    """True for a kernel that checks continuity itself (a fused kernel: its 7th
    argument is the depth array ``amount``), False for one that stages the squared
    heights in ``gout`` for :func:`assur.kernel.run.check_continuity` (composed).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.kernel.compose import checks_continuity
    >>> prog = examples.hitch_003().program()
    >>> fused = prog.kernel()                       # the hitch's fused kernel
    >>> checks_continuity(fused), checks_continuity(lambda *args: 0)
    (True, False)
    """
    return bool(getattr(kernel, "py_func", kernel).__globals__.get("CHECKS_CONTINUITY", False))


def load_kernel(rows, measures, K, out_pts, out_sca):
    """The compiled kernel of a structure: fused up to :data:`THRESHOLD` groups and
    measures, composed above (:func:`is_fused`).

    Examples
    --------
    >>> import numpy as np
    >>> from assur import examples
    >>> from assur.kernel.compose import load_kernel
    >>> from assur.kernel.source import quantities
    >>> m = examples.hitch_003()
    >>> prog = m.program()
    >>> pts = tuple(prog.slot[p] for p in prog.out_pts)
    >>> sca = tuple(prog.scal[s] for s in prog.out_sca)
    >>> kernel = load_kernel(prog.rows, prog.measures, prog.k, pts, sca)   # compiled once per machine
    >>> ptab, trig, _ = m.prepared(prog)            # parameter and fixed-angle tables
    >>> q = np.array([[0.42, 0.67]])                # S [m]
    >>> rows = quantities(prog.k, pts, sca)
    >>> out, amount = np.empty((len(rows), 2)), np.empty(2)
    >>> status = np.empty(2, dtype=np.int64)
    >>> kernel(ptab, trig, q, 2, True, out, amount, status, 0, 1), status.tolist()   # no failures
    (0, [-1, -1])
    >>> y56 = f"y{prog.slot['56']}"
    >>> [round(float(v), 3) for v in out[rows.index(y56)]]           # Y56 [m]
    [0.2, 1.043]
    >>> [round(float(v), 3) for v in out[rows.index(y56 + "_0")]]    # I56, the pole check [-]
    [4.459, 2.621]
    """
    if is_fused(rows, measures):
        return load_source(generate(rows, measures, K, out_pts, out_sca))
    srcs, driver = generate_composed(rows, measures, K, out_pts, out_sca)
    for s in srcs:
        load_source(s, "grp")
    return load_source(driver)
