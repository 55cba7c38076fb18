"""What is kept with a mechanism (:mod:`assur.core.memo`): a value is made once per key
and mechanism, a key names a registered owner (else an error says what is wrong), a
copy with other parameter values keeps only the structural owners' values."""

import pytest

from assur import examples
from assur.core.memo import OWNERS, Memo, check_key, register_owner


def test_made_once_per_key():
    m = examples.hitch_003().with_params(L4=0.65)
    made = []
    key = ("program", ("test_memo",))
    a = m.memo(key, lambda: made.append(1) or object())
    assert m.memo(key, lambda: made.append(1) or object()) is a and made == [1]
    assert check_key(key) is OWNERS["program"]
    with pytest.raises((KeyError, TypeError)):
        check_key(("no such owner",))
    with pytest.raises(TypeError):
        check_key("program")


def test_owners_register_once_and_a_memo_makes_once():
    again = register_owner("program", OWNERS["program"].module, OWNERS["program"].doc,
                           structural=OWNERS["program"].structural)
    assert again is OWNERS["program"] or again == OWNERS["program"]
    memo, calls = Memo(), []
    first = memo.get(("chains",), lambda: calls.append(1) or {"A": {"j1"}})
    assert memo.get(("chains",), lambda: 1 / 0) is first and calls == [1] and len(memo) == 1
