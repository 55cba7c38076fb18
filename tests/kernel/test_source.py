"""The generated kernel source (:mod:`assur.kernel.source`): the element loop stores
only to kernel-local buffers (LLVM's run-time overlap check against the caller's
arrays sent it to the 4× slower scalar loop, depending on the addresses), and the
branch-free atan2 it emits gives numpy's link angles."""

from __future__ import annotations

import re

import numpy as np

from assur import Mechanism, examples
from assur.core import program as P
from assur.kernel.source import generate
from tests.helpers import by_numpy


def test_element_loop_stores_only_to_local_buffers():
    prog = P.compile_program(by_numpy(examples.hitch_003))
    src = generate(prog.rows, prog.measures, prog.k, tuple(prog.slot[p] for p in prog.out_pts),
                   tuple(prog.scal[s] for s in prog.out_sca))
    lines = src.splitlines()
    start = next(i for i, ln in enumerate(lines) if ln.strip().startswith("for e in range("))
    indent = len(lines[start]) - len(lines[start].lstrip())
    body = []
    for ln in lines[start + 1:]:
        if ln.strip() and len(ln) - len(ln.lstrip()) <= indent:
            break
        body.append(ln)
    stores = {m.group(1) for ln in body for m in [re.match(r"\s*(\w+)\[", ln)] if m}
    assert stores == {"buf", "sbuf"}, stores



def test_link_angles_of_the_kernel_agree_with_numpy_arctan2():
    """The kernel's branch-free atan2 (Cephes atan, assur.kernel.source.emit_atan2)
    against numpy's on every quadrant, the axes and both signs of zero."""
    rng = np.random.default_rng(7)
    q = np.concatenate([np.linspace(-np.pi, np.pi, 4001), rng.uniform(-4, 4, 4000),
                        [0.0, np.pi / 2, np.pi, -np.pi / 2, -np.pi, 1e-300, -1e-300]])
    m = (Mechanism("crank", coordinates=("q",), params={"r": 0.37})
         .frame("O", 0.25, -0.5)
         .crank("crank", pivot="O", out="A", radius="r", q="q", links=("1",))
         .link("1", "O", "A"))
    r = m.solve(q, check_continuity=False)  # principal values, not unwrapped
    ref = np.arctan2(r.y("A") - (-0.5), r.x("A") - 0.25)
    assert np.max(np.abs(r.phi("1") - ref)) <= 1e-15
    assert np.array_equal(np.signbit(r.phi("1")), np.signbit(ref))
    # the angle's analogs are those of the direction: φ' = 1, φ'' = 0 for a crank
    assert np.allclose(r.dphi("1"), 1.0, rtol=0, atol=1e-12)
    assert np.allclose(r.ddphi("1"), 0.0, rtol=0, atol=1e-12)

