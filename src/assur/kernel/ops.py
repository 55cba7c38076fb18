"""Element operations: the table the generated kernels look up, one op per program row.

A compiled program is a list of rows, each starting with an op code
(:mod:`assur.core.program`). The op of a code is an object with

* ``type_name`` — its name (a comment in the generated source);
* ``continuity`` — whether its position is checked for continuity between samples;
* ``emit(E, index, row)`` — writes its straight-line code into the emitter ``E``.

The structural group types register themselves here when they are registered as
groups (:func:`assur.groups.base.register`): the kernel knows this contract, not the
groups, so it imports nothing above itself (docs/architecture.md).
"""

from __future__ import annotations

import sys

__all__ = ["add", "discard", "op", "source_modules"]

_OPS: list = []


def add(operation) -> int:
    """Add an operation to the table (once) and return its op code.

    Examples
    --------
    >>> from assur.groups import Crank
    >>> from assur.kernel import ops
    >>> ops.add(Crank) == Crank.op          # a group type is there already
    True
    """
    for code, o in enumerate(_OPS):
        if o is operation:
            return code
    _OPS.append(operation)
    return len(_OPS) - 1


def discard(operation) -> None:
    """Remove the operation added last (a test's or a plugin's own type, unregistered):
    the codes of the others must not shift, so only the last one can go.

    Examples
    --------
    >>> from assur.kernel import ops
    >>> class Toy:
    ...     type_name, continuity = "toy", False
    >>> code = ops.add(Toy)
    >>> ops.discard(Toy)
    >>> ops.discard(Toy)
    Traceback (most recent call last):
    ...
    ValueError: only the operation added last can be removed (the others keep their codes)
    """
    if not _OPS or _OPS[-1] is not operation:
        raise ValueError("only the operation added last can be removed (the others keep "
                         "their codes)")
    _OPS.pop()


def op(code):
    """The operation of an op code.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.kernel.ops import op
    >>> rows = examples.combine_002().program().rows    # each row starts with its op code
    >>> [op(row[0]).type_name for row in rows][:4]
    ['frame', 'frame', 'frame', 'crank']
    """
    return _OPS[int(code)]


def source_modules() -> set:
    """The modules that define the registered operations and their base classes: the
    code the emitted kernels come from (hashed into the kernels' cache keys).

    Examples
    --------
    >>> from assur.kernel.ops import source_modules
    >>> sorted(m.__name__ for m in source_modules())[:2]
    ['assur.groups.base', 'assur.groups.crank']
    """
    return {sys.modules[k.__module__] for o in _OPS for k in getattr(o, "__mro__", (type(o),))
            if k.__module__.startswith("assur.")}
