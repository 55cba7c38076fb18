"""Checks of the memory guard (:func:`assur.core.inputs.check_memory`): a refusal
names what to reduce, the estimate and the limit, and nothing big was allocated
before it."""

from __future__ import annotations

import contextlib
import re
import tracemalloc

#: the most a refused request may allocate before its refusal [bytes]
SMALL = 4 * 1024**2


@contextlib.contextmanager
def allocates_little(limit=SMALL):
    """Fail when the block's peak of Python-traced allocations (numpy's included)
    exceeds ``limit`` bytes.

    Examples
    --------
    >>> with allocates_little():
    ...     _ = [0] * 10
    """
    tracemalloc.start()
    try:
        yield
    finally:
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        assert peak <= limit, f"allocated {peak} B before the refusal (at most {limit})"


def assert_refusal(message, names, limit="1 MiB"):
    """The refusal ``message`` names ``names`` (what to reduce), an estimate and the
    ``limit``.

    Examples
    --------
    >>> assert_refusal("x: 1e+06 designs would need about 1 GiB of memory (limit 1 MiB; "
    ...                "set ASSUR_MAX_MEMORY to change it, or reduce --samples)", "--samples")
    """
    assert names in message, message
    assert re.search(r"would need about \d[\d.]* [KMGTP]iB of memory", message), message
    assert f"(limit {limit};" in message and "ASSUR_MAX_MEMORY" in message, message
