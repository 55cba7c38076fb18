"""The compiled program of a mechanism (:mod:`assur.core.program`): one program per
structure, whatever the parameter values; the parameter table holds every value at
its row (designs as columns), the trig table the cosine and sine of every fixed
angle; the kernel treats the designs of a batch independently."""

import numpy as np
import pytest

from assur import examples
from assur.core.program import compile_program, execute, trig_table


def test_one_program_per_structure_and_the_values_at_their_rows():
    m = examples.hitch_003()
    prog = compile_program(m)
    assert compile_program(m.with_params(L3=0.21, L4=0.65)) is prog
    L4 = np.array([0.64, 0.66, 0.68])
    ptab = prog.param_table({**m.params, "L4": L4})
    assert ptab.shape[1] == 3
    for name, value in m.params.items():
        row = ptab[prog.param_row(name)]
        np.testing.assert_array_equal(row, L4 if name == "L4" else np.full(3, value))


def test_the_trig_table_holds_cosine_and_sine_of_the_fixed_angles():
    m = examples.hitch_003()
    prog = compile_program(m)
    phi = np.array([0.3, 0.4])
    ptab = prog.param_table({**m.params, "phiBD": phi})
    trig = trig_table(prog, ptab)
    assert trig.shape == (2 * len(prog.trig), 2)
    for i, (kind, row) in enumerate(prog.trig):
        assert kind == "angle"
        np.testing.assert_allclose(trig[2 * i], np.cos(ptab[row]), rtol=0, atol=1e-15)
        np.testing.assert_allclose(trig[2 * i + 1], np.sin(ptab[row]), rtol=0, atol=1e-15)
    row = prog.param_row("phiBD")
    assert any(r == row for _, r in prog.trig)


def test_designs_of_a_batch_are_independent():
    """Two designs at once give, bit for bit, what each gives alone."""
    m = examples.hitch_003()
    prog = compile_program(m)
    S = np.linspace(0.42, 0.67, 7)
    L3 = [0.2, 0.21]
    both = prog.param_table({**m.params, "L3": np.array(L3)})
    q = np.ascontiguousarray(np.tile(S, 2)[None, :])
    res = execute(prog, both, q, len(S), trig=trig_table(prog, both))
    for d, value in enumerate(L3):
        one = prog.param_table({**m.params, "L3": value})
        alone = execute(prog, one, np.ascontiguousarray(S[None, :]), len(S),
                        trig=trig_table(prog, one))
        # every output row (positions, analogs, angles) and the status, element-wise
        for key in ("out", "pv", "pd", "pdd", "sv", "sd", "sdd", "status"):
            part = res[key][..., d * len(S):(d + 1) * len(S)]
            assert np.array_equal(part, alone[key]), key
    assert (np.asarray(res["status"]) < 0).all()
    with pytest.raises(Exception, match="designs"):
        prog.param_table({**m.params, "L3": np.array(L3), "L4": np.array([0.6, 0.62, 0.64])})
