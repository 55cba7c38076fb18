"""Streaming (non-temporal) stores for the generated kernels' output copy.

A kernel stages one work item's outputs in a buffer that stays in cache, then
copies each output row to the caller's array: dozens of rows, each a run of a few
kB. With ordinary stores every cache line written is first read from memory (a
read for ownership) and the hardware's stream detection is spread over all rows
at once: on a 2-core EPYC the copy of the seed-003 hitch's 63 rows ran at 6–9 GB/s
and took two thirds of the kernel's time. Non-temporal stores write whole lines
without reading them and bypass the caches: the same copy runs at 26 GB/s, the
memory's bandwidth. They pay only when the output is far larger than the caches,
which the generated kernels decide (:data:`STREAM_MIN`); their results are then
read from memory either way.

numba has no non-temporal store, so :func:`stream_copy` is a numba intrinsic (the
supported way to emit LLVM IR from numba code) that writes the copy loop with
LLVM's ``!nontemporal`` store metadata; :func:`store_fence` orders the streamed
stores before the kernel returns (x86's weakly ordered streaming stores; a plain
fence elsewhere). Both are made on first use, so importing assur does not import
numba.

Examples
--------
>>> import numpy as np
>>> from numba import njit
>>> from assur.kernel.stream import store_fence, stream_copy
>>> @njit
... def copy_rows(out, buf, e0, n):          # what a kernel does after a work item
...     for r in range(out.shape[0]):
...         stream_copy(out, r, e0, buf, r, 0, n)
...     store_fence()
>>> out, buf = np.zeros((2, 40)), np.arange(60.0).reshape(2, 30)
>>> copy_rows(out, buf, 5, 30)               # out[:, 5:35] = buf[:, :30]
>>> bool((out[:, 5:35] == buf).all()), float(out[:, :5].sum() + out[:, 35:].sum())
(True, 0.0)
"""

from __future__ import annotations

__all__ = ["stream_copy", "store_fence", "STREAM_MIN"]

#: output elements (rows × positions) from which a kernel copies its outputs with
#: streaming stores: 1 Mi doubles = 8 MiB, beyond a core's share of the caches
#: (below, the outputs are likely read again while in cache). Measured on the
#: cylinder–lever of seed 003 (3 rows × 1e6 positions = 24 MiB, reused output):
#: 6.7–8.0 ms streamed against 8.3–9.6 ms with ordinary stores (from 1 << 22), on
#: a 2-core EPYC with a 32 MiB L3.
STREAM_MIN = 1 << 20


def _make():
    from llvmlite import ir
    from numba import types
    from numba.core import cgutils
    from numba.extending import intrinsic

    @intrinsic
    def stream_copy(typingctx, dst, dr, dc, src, sr, sc, n):
        """``dst[dr, dc:dc + n] = src[sr, sc:sc + n]`` for 2-D C-contiguous float64
        arrays, the aligned part with 64-byte non-temporal stores."""
        for a in (dst, src):
            if not (isinstance(a, types.Array) and a.ndim == 2 and a.layout == "C"
                    and a.dtype == types.float64):
                return None
        sig = types.void(dst, dr, dc, src, sr, sc, n)

        def codegen(context, builder, signature, args):
            i64 = ir.IntType(64)
            f64 = ir.DoubleType()
            v8 = ir.VectorType(f64, 8)
            d_arr = context.make_array(signature.args[0])(context, builder, args[0])
            s_arr = context.make_array(signature.args[3])(context, builder, args[3])
            idx = [context.cast(builder, v, t, types.intp)
                   for v, t in zip(args[1:], signature.args[1:]) if not isinstance(t, types.Array)]
            dr_, dc_, sr_, sc_, n_ = idx
            dshape = cgutils.unpack_tuple(builder, d_arr.shape, 2)
            sshape = cgutils.unpack_tuple(builder, s_arr.shape, 2)
            dptr = builder.gep(d_arr.data, [builder.add(builder.mul(dr_, dshape[1]), dc_)])
            sptr = builder.gep(s_arr.data, [builder.add(builder.mul(sr_, sshape[1]), sc_)])
            zero, c8, c63 = ir.Constant(i64, 0), ir.Constant(i64, 8), ir.Constant(i64, 63)
            n_ = builder.select(builder.icmp_signed(">", n_, zero), n_, zero)
            # head: element stores until dst is 64-byte aligned (a whole cache line)
            mis = builder.and_(builder.ptrtoint(dptr, i64), c63)
            head = builder.udiv(builder.and_(builder.sub(ir.Constant(i64, 64), mis), c63), c8)
            head = builder.select(builder.icmp_unsigned("<", head, n_), head, n_)
            with cgutils.for_range(builder, head) as loop:
                i = loop.index
                builder.store(builder.load(builder.gep(sptr, [i])), builder.gep(dptr, [i]))
            nvec = builder.udiv(builder.sub(n_, head), c8)
            nt = builder.module.add_metadata([ir.Constant(ir.IntType(32), 1)])
            with cgutils.for_range(builder, nvec) as loop:
                i = builder.add(head, builder.mul(loop.index, c8))
                v = builder.load(builder.bitcast(builder.gep(sptr, [i]), v8.as_pointer()),
                                 align=8)
                st = builder.store(v, builder.bitcast(builder.gep(dptr, [i]), v8.as_pointer()),
                                   align=64)
                st.set_metadata("nontemporal", nt)
            start = builder.add(head, builder.mul(nvec, c8))
            with cgutils.for_range(builder, builder.sub(n_, start)) as loop:
                i = builder.add(start, loop.index)
                builder.store(builder.load(builder.gep(sptr, [i])), builder.gep(dptr, [i]))
            return context.get_dummy_value()

        return sig, codegen

    @intrinsic
    def store_fence(typingctx):
        """A sequentially consistent fence: the streamed stores before it are
        visible to other threads after it."""
        def codegen(context, builder, signature, args):
            builder.fence("seq_cst")
            return context.get_dummy_value()

        return types.void(), codegen

    return {"stream_copy": stream_copy, "store_fence": store_fence}


_made: dict = {}


def __getattr__(name):
    if name in ("stream_copy", "store_fence"):
        if not _made:
            _made.update(_make())
        return _made[name]
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
