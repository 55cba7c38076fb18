"""What is kept with a mechanism: the contract of :meth:`Mechanism.memo`.

A :class:`~assur.core.mechanism.Mechanism` is immutable, so a value computed from it
alone — a compiled program, a prepared parameter table, the plan of a fused kernel,
the chains of its links — may be made once and kept with it. ``mech.memo(key,
make)`` returns the kept value of ``key``, making it with ``make()`` the first time.

Keys
----
A key is a tuple ``(owner, *items)``. ``owner`` is the name of the concern that
fills the entry, registered in :data:`OWNERS` (:func:`register_owner`); the items
after it are the owner's to choose (hashable; the outputs asked for, a shape…). Two
modules therefore cannot collide by inventing the same string, and an unknown owner
is an error, not a silent new entry::

    mech.memo(("statics", "fused rows"), make)          # the owner "statics"
    mech.memo(("program", ("56", "6")), make)           # the owner "program"

An owner is *structural* when its values depend on the structure only (groups,
links, loads — not on parameter values): a copy of the mechanism with other
parameter values (:meth:`Mechanism.with_params`) keeps its entries; the others start
afresh.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Hashable, TypeVar

__all__ = ["Owner", "OWNERS", "register_owner", "Memo", "check_key"]

T = TypeVar("T")


@dataclass(frozen=True)
class Owner:
    """A concern that keeps values with a mechanism.

    Attributes
    ----------
    name : str
        The first item of its keys.
    module : str
        The module that fills its entries.
    doc : str
        What it keeps (one line).
    structural : bool
        True if its values depend only on the structure, not on parameter values:
        a copy with other parameter values keeps them.

    Examples
    --------
    >>> from assur.core.memo import OWNERS
    >>> o = OWNERS["program"]
    >>> o.module, o.structural
    ('assur.core._solving', True)
    """

    name: str
    module: str
    doc: str
    structural: bool = False


#: the registered owners by name (:func:`register_owner`)
OWNERS: dict[str, Owner] = {}


def register_owner(name: str, module: str, doc: str, *, structural: bool = False) -> Owner:
    """Register the owner ``name`` of memo entries (a name already registered by the
    same module is returned as it is; by another module it is refused).

    Examples
    --------
    >>> from assur.core.memo import register_owner
    >>> register_owner("chains", "assur.core.chains", "the coordinates of each point").name
    'chains'
    >>> register_owner("chains", "mypackage.gears", "gear chains")
    Traceback (most recent call last):
    ...
    ValueError: memo owner 'chains' is registered by assur.core.chains already
    """
    old = OWNERS.get(name)
    if old is not None:
        if old.module != module:
            raise ValueError(f"memo owner {name!r} is registered by {old.module} already")
        return old
    OWNERS[name] = owner = Owner(name, module, doc, structural)
    return owner


for _name, _module, _doc, _structural in (
        ("program", "assur.core._solving", "compiled programs by their outputs", True),
        ("prepared", "assur.core._solving",
         "parameter and cos/sin tables of a program, failures of its pre-passes", False),
        ("roles", "assur.core.inputs", "what each parameter is used as (its checks)", True),
        ("chains", "assur.core.chains", "the coordinates that move each point", False),
        ("statics", "assur.core.statics", "the method of static loads and its row index",
         False),
        ("outputs", "assur.core.outputs", "fused-kernel plans, joints and actuators", False),
        ("capacity", "assur.machines.capacity", "the dead loads' mechanism", False),
        ("stability", "assur.machines.stability", "the machine's values per design", False),
        ("cylinders", "assur.machines.cylinders", "a cylinder's constants", False)):
    register_owner(_name, _module, _doc, structural=_structural)


def check_key(key) -> Owner:
    """The owner of a memo key, or a ``TypeError``/``KeyError`` naming what is wrong.

    Examples
    --------
    >>> from assur.core.memo import check_key
    >>> check_key(("statics", "fused rows")).module
    'assur.core.statics'
    >>> check_key("fused rows")
    Traceback (most recent call last):
    ...
    TypeError: a memo key is a tuple (owner, ...) whose owner is registered in assur.core.memo.OWNERS, got 'fused rows'
    >>> check_key(("fused rows",))
    Traceback (most recent call last):
    ...
    KeyError: "memo owner 'fused rows' is not registered (assur.core.memo.register_owner); owners: ['capacity', 'chains', 'cylinders', 'outputs', 'prepared', 'program', 'roles', 'stability', 'statics']"
    """
    if not (isinstance(key, tuple) and key and isinstance(key[0], str)):
        raise TypeError(f"a memo key is a tuple (owner, ...) whose owner is registered in "
                        f"assur.core.memo.OWNERS, got {key!r}")
    owner = OWNERS.get(key[0])
    if owner is None:
        raise KeyError(f"memo owner {key[0]!r} is not registered "
                       f"(assur.core.memo.register_owner); owners: {sorted(OWNERS)}")
    return owner


_ABSENT = object()


class Memo:
    """The values kept with one mechanism, by key (module notes).

    Examples
    --------
    >>> from assur.core.memo import Memo
    >>> memo = Memo()
    >>> memo.get(("chains",), lambda: {"A": {"j1"}})
    {'A': {'j1'}}
    >>> memo.get(("chains",), lambda: 1 / 0)      # kept: make is not called again
    {'A': {'j1'}}
    >>> len(memo)
    1
    """

    __slots__ = ("_values",)

    def __init__(self, values: dict | None = None):
        self._values: dict[Hashable, object] = dict(values or {})

    def get(self, key: tuple, make: Callable[[], T]) -> T:
        """The value kept under ``key``, made by ``make()`` the first time (a value of
        None is kept as well).

        Examples
        --------
        >>> from assur.core.memo import Memo
        >>> calls = []
        >>> memo = Memo()
        >>> [memo.get(("statics", "small calls"), lambda: calls.append(1)) for _ in "ab"]
        [None, None]
        >>> len(calls)
        1
        """
        v = self._values.get(key, _ABSENT)
        if v is _ABSENT:
            check_key(key)
            v = self._values[key] = make()
        return v

    def structural(self) -> "Memo":
        """A new memo holding the entries of the structural owners only (for a copy of
        the mechanism with other parameter values).

        Examples
        --------
        >>> from assur.core.memo import Memo
        >>> memo = Memo()
        >>> _ = memo.get(("program", None), lambda: "a program")
        >>> _ = memo.get(("prepared", 1), lambda: "its tables")
        >>> len(memo), len(memo.structural())
        (2, 1)
        """
        return Memo({k: v for k, v in self._values.items() if OWNERS[k[0]].structural})

    def __len__(self) -> int:
        return len(self._values)
