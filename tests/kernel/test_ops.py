"""The table of element operations (:mod:`assur.kernel.ops`): every registered group
type has its op code, the code finds the type back, a type is added once, every
program row starts with the code of its group, and the modules that define the
operations are those the kernels' cache keys read."""

from assur import examples
from assur.groups import registry
from assur.kernel import ops
from tests.helpers import by_numpy


def test_every_group_type_has_its_op_code():
    codes = set()
    for name, cls in registry().items():
        assert ops.op(cls.op) is cls and ops.add(cls) == cls.op, name
        codes.add(cls.op)
    assert len(codes) == len(registry())  # one code per type


def test_program_rows_start_with_their_groups_code():
    m = by_numpy(examples.combine_002)
    rows = m.program().rows
    types = [ops.op(row[0]).type_name for row in rows]
    assert types == [type(g).type_name for g in m.groups]
    modules = {mod.__name__ for mod in ops.source_modules()}
    assert {cls.__module__ for cls in registry().values()} <= modules
    assert "assur.groups.base" in modules
