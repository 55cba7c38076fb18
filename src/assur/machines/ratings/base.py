"""The contract of a rating: what a rating kind declares and what it returns.

A *rating* is a machine's figure of merit in the manner of a standard — the lifting
capacity of a crane over its reach, the digging forces of a backhoe (ISO 6015), the
tipping load of a loader (ISO 14397). A model file declares the ratings it wants as
``[[rating]]`` tables whose ``type`` names a rating kind (docs/ratings.md); each kind
is a frozen dataclass subclassing :class:`Rating`, registered under its ``type``
(:mod:`assur.machines.ratings._registry`, the pattern of the load and group types,
DESIGN.md §9):

==================  ==============================================================
member              what it provides
==================  ==============================================================
``type_name``       registry key = the file's ``type``
``title``           what it is, by language (:class:`assur.texts.Text`)
``standard``        the standard it follows, cited (``"ISO 6015"``)
``fields``          its parameters (:func:`param`: role, quantity, default, doc)
``evaluate``        ``(mech, kin) -> RatingResult``: the rating of the solved
                    mechanism ``kin`` (one design), by the engine's formulas
==================  ==============================================================

A kind's docstring gives the standard's definition in our words, with the standard's
number. Every number of a result comes from the engine: transmission numbers and
analogs (:mod:`assur.core.analogs`), virtual work (:mod:`assur.core.virtual_work`),
a cylinder's capacity (:func:`assur.core.cylinders.capacity`) and the axle reactions
(:func:`assur.machines.stability.axle_reactions`); nothing is tuned by hand.
"""

from __future__ import annotations

from dataclasses import MISSING, dataclass, field as _dataclass_field, fields as _dataclass_fields
from typing import ClassVar

import numpy as np

from ...core.quantities import DEFAULT_UNITS
from ...errors import ModelError
from ...texts import Text

__all__ = ["ROLES", "Param", "param", "declared", "Series", "RatingResult", "Rating", "names_of",
           "carried_loads", "with_loads_of", "number", "check_names", "need_cylinders"]

#: what a parameter of a rating holds, by its role; the file's checks follow the role
ROLES = {
    "point": "the name of a point of the model (moving or of the frame)",
    "cylinder": "the name of a cylinder of the model ([[cylinders]])",
    "cylinders": "a list of cylinder names (default: every cylinder that applies)",
    "value": "a number in the unit of its quantity, or a parameter name",
    "count": "a whole number ≥ 1",
    "flag": "true or false",
    "text": 'a title: a string or { en = "…", ru = "…" }',
}


@dataclass(frozen=True)
class Param:
    """One declared parameter of a rating kind (what :func:`param` records).

    Examples
    --------
    >>> from assur.machines.ratings import Param
    >>> Param("point", "point", None, None, True, "the load point").required
    True
    """

    name: str
    role: str
    quantity: str | None
    default: object
    required: bool
    doc: str


def param(role: str, quantity: str | None = None, *, default=MISSING, doc: str = ""):
    """Declare one parameter of a rating kind in its dataclass body: its role
    (:data:`ROLES`), the quantity of a value (a key of
    :data:`assur.core.quantities.DEFAULT_UNITS`), its default (absent: required) and
    one line for the docs.

    Examples
    --------
    >>> from assur.machines.ratings import param
    >>> f = param("value", "number", default=0.5, doc="share of the tipping load [-]")
    >>> f.metadata["rating"]["quantity"], f.default
    ('number', 0.5)
    """
    if role not in ROLES:
        raise ValueError(f"unknown rating parameter role {role!r} (one of: {', '.join(ROLES)})")
    if (role == "value") != (quantity is not None) or (
            quantity is not None and quantity not in DEFAULT_UNITS):
        raise ValueError(f"a value needs a quantity (one of: {', '.join(DEFAULT_UNITS)}) and "
                         f"only a value has one, got {quantity!r}")
    return _dataclass_field(default=default, metadata={"rating": {
        "role": role, "quantity": quantity, "doc": doc}})


def declared(cls) -> tuple:
    """The :class:`Param` of each dataclass field of the rating kind ``cls`` (what
    :func:`assur.machines.ratings.register` records as its ``fields``).

    Examples
    --------
    >>> from assur.machines.ratings import declared, rating_type
    >>> [(p.name, p.required) for p in declared(rating_type("crane_chart"))][:3]
    [('point', True), ('axis', True), ('cylinders', False)]
    """
    out = []
    for f in _dataclass_fields(cls):
        d = f.metadata.get("rating")
        if d is None:
            raise TypeError(f"rating type {cls.type_name!r}: field {f.name!r} is not declared "
                            f"with assur.machines.ratings.param")
        required = f.default is MISSING
        out.append(Param(f.name, d["role"], d["quantity"], None if required else f.default,
                         required, d["doc"]))
    return tuple(out)


@dataclass(frozen=True)
class Series:
    """One named array of a rating's result, with its quantity and label.

    Attributes
    ----------
    symbol : str
        Its short name (a table's column, ``G_S1``, ``reach``).
    values : ndarray, shape (n,)
        In SI (the quantity's unit of :data:`assur.core.quantities.DEFAULT_UNITS`);
        ``inf`` where a limit does not bind (the cylinder is not loaded there).
    quantity : str
        ``"force"``, ``"length"``, ``"moment"``, ``"angle"``, ``"number"`` …
    label : Text
        What it is, by language.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.machines.ratings import Series
    >>> s = Series("reach", np.array([1.0, 2.0]), "length", "reach of the load point")
    >>> s.unit
    'm'
    """

    symbol: str
    values: np.ndarray
    quantity: str
    label: object

    @property
    def unit(self) -> str:
        """The SI unit of the values (of :data:`assur.core.quantities.DEFAULT_UNITS`).

        Examples
        --------
        >>> import numpy as np
        >>> from assur.machines.ratings import Series
        >>> Series("M", np.zeros(1), "moment", "gross lifting moment").unit
        'N·m'
        """
        return DEFAULT_UNITS[self.quantity].text


@dataclass(frozen=True)
class RatingResult:
    """A rating computed: named arrays over its rows, what its figure plots, notes.

    Attributes
    ----------
    rating : Rating
        The rating it is of (its kind, parameters, title).
    series : tuple of Series
        The rows' values, first the positions' coordinates.
    x : str
        The symbol of the figure's abscissa.
    y : tuple of str
        The symbols of the figure's curves.
    group : str or None
        A symbol whose equal values make one curve each (a load chart's boom angle);
        None: one curve per ``y``.
    notes : tuple of Text
        What the table says under it (the governing limits' key, the definitions).
    scalars : tuple of Series
        Single values of the rating (one-element arrays: a static tipping load at the
        standard position), shown under its table in the user's units.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.machines.ratings import RatingResult, Series
    >>> r = RatingResult(None, (Series("x", np.arange(2.0), "length", "x"),
    ...                         Series("G", np.array([5.0, 4.0]), "force", "G")), "x", ("G",))
    >>> r["G"].tolist(), r.symbols
    ([5.0, 4.0], ('x', 'G'))
    """

    rating: object
    series: tuple
    x: str
    y: tuple
    group: str | None = None
    notes: tuple = ()
    scalars: tuple = ()

    @property
    def symbols(self) -> tuple:
        """The series' symbols in order.

        Examples
        --------
        >>> import numpy as np
        >>> from assur.machines.ratings import RatingResult, Series
        >>> RatingResult(None, (Series("x", np.zeros(1), "length", "x"),), "x", ()).symbols
        ('x',)
        """
        return tuple(s.symbol for s in self.series)

    def __getitem__(self, symbol) -> np.ndarray:
        for s in self.series:
            if s.symbol == symbol:
                return s.values
        raise KeyError(f"no series {symbol!r} in this rating; it has: {', '.join(self.symbols)}")

    def get(self, symbol) -> Series:
        """The :class:`Series` named ``symbol``.

        Examples
        --------
        >>> import numpy as np
        >>> from assur.machines.ratings import RatingResult, Series
        >>> r = RatingResult(None, (Series("x", np.zeros(1), "length", "x"),), "x", ())
        >>> r.get("x").quantity
        'length'
        """
        for s in self.series:
            if s.symbol == symbol:
                return s
        raise KeyError(f"no series {symbol!r} in this rating; it has: {', '.join(self.symbols)}")


class Rating:
    """Base of the rating kinds: the contract each implements (module notes).

    Examples
    --------
    >>> from assur.machines.ratings import Rating, rating_type
    >>> cls = rating_type("crane_chart")
    >>> issubclass(cls, Rating), cls.standard
    (True, 'ISO 4301-1, ISO 10245-1')
    >>> [p.name for p in cls.fields][:2]
    ['point', 'axis']
    """

    type_name: ClassVar[str] = ""
    title: ClassVar[object] = Text("rating")
    standard: ClassVar[str] = ""
    fields: ClassVar[tuple] = ()

    def heading(self, lang="en") -> str:
        """The rating's title in ``lang``: the file's ``title``, else the kind's with the
        standard cited.

        Examples
        --------
        >>> from assur.machines.ratings import rating_type
        >>> rating_type("crane_chart")(point="D", axis="O").heading()
        'Load chart: lifting capacity over the reach (ISO 4301-1, ISO 10245-1)'
        """
        from ...texts import localize
        own = getattr(self, "name", None)
        if own:
            return localize(own, lang)
        return f"{localize(self.title, lang)} ({self.standard})"

    def check(self, mech):
        """A problem with this rating in ``mech`` beyond its names (which
        :func:`check_names` checks): ``(parameter, message)`` or None; a kind overrides
        it.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.machines.ratings import rating_type
        >>> print(rating_type("crane_chart")(point="56", axis="01").check(examples.hitch_003()))
        None
        """
        return None

    def evaluate(self, mech, kin) -> RatingResult:
        """The rating of the solved mechanism ``kin`` (one design) of ``mech``: each
        kind implements it.

        Examples
        --------
        >>> from assur.machines.ratings import Rating
        >>> Rating().evaluate(None, None)
        Traceback (most recent call last):
        ...
        NotImplementedError
        """
        raise NotImplementedError


def names_of(ratings) -> list:
    """The names of a machine's ratings in its files and links: each its kind's
    (``crane_chart``), numbered in the file's order where the machine has two of a
    kind (``loader_lift_1``, ``loader_lift_2``).

    Parameters
    ----------
    ratings : sequence of Rating or RatingResult
        In the model file's order.

    Examples
    --------
    >>> from assur.machines.ratings import names_of, rating_type
    >>> chart, lift = rating_type("crane_chart"), rating_type("loader_lift")
    >>> names_of([chart(point="D", axis="O"), lift("T", "O"), lift("T", "O")])
    ['crane_chart', 'loader_lift_1', 'loader_lift_2']
    """
    kinds = [getattr(r, "rating", r).type_name for r in ratings]
    return [k if kinds.count(k) == 1 else f"{k}_{kinds[:i + 1].count(k)}"
            for i, k in enumerate(kinds)]


def number(mech, ref) -> float:
    """A rating parameter's value [SI]: a number, or a parameter of ``mech``.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.machines.ratings import number
    >>> number(examples.hitch_003(), "L4"), number(None, 0.5)   # [m], [-]
    (0.661..., 0.5)
    """
    if isinstance(ref, str):
        return float(np.asarray(mech.value_of(ref), float).reshape(-1)[0])
    return float(ref)


def carried_loads(mech, point):
    """The mechanism with the loads a rating at ``point`` carries besides the rated load:
    every load of the model but those applied at ``point`` itself (the payload the
    rating replaces); None when there are none.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.machines.ratings import carried_loads
    >>> m = examples.loader_lab1()
    >>> [ld.point for ld in carried_loads(m, "S9").loads]    # the boom's mass only
    ['S3']
    """
    keep = tuple(ld for ld in mech.loads
                 if point not in [getattr(ld, f) for f in getattr(ld, "point_fields", ())])
    return mech.with_loads(keep) if keep else None


def with_loads_of(kin, mech):
    """The kinematics ``kin`` seen with the loads of ``mech`` (the same geometry): what
    the virtual work of a subset of the loads is computed on.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.machines.ratings import carried_loads, with_loads_of
    >>> m = examples.loader_lab1()
    >>> kin = m.solve(examples.loader_lab1_range()[:2])
    >>> with_loads_of(kin, carried_loads(m, "S9")).mechanism.loads[0].point
    'S3'
    """
    import copy
    k2 = copy.copy(kin)
    k2.mechanism = mech
    return k2


def check_names(mech, rating):
    """A problem with the names ``rating`` refers to in ``mech``: ``(parameter,
    message)``, or None.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.machines.ratings import check_names, rating_type
    >>> m = examples.hitch_003()
    >>> print(check_names(m, rating_type("crane_chart")(point="56", axis="01")))
    None
    >>> check_names(m, rating_type("crane_chart")(point="Q", axis="01"))
    ('point', "expected a point of the model, found 'Q'")
    """
    points = set(mech.points) | set(mech.frame_points)
    cyls = [c.name for c in mech.cylinders]
    for p in rating.fields:
        v = getattr(rating, p.name)
        if v is None:
            continue
        if p.role == "point" and v not in points:
            return p.name, f"expected a point of the model, found {v!r}"
        if p.role in ("cylinder", "cylinders"):
            for c in ([v] if p.role == "cylinder" else v):
                if c not in cyls:
                    return p.name, (f"expected a cylinder of the model "
                                    f"({', '.join(cyls) or 'none: add [[cylinders]]'}), "
                                    f"found {c!r}")
    return None


def need_cylinders(mech, names, what):
    """The cylinders named (or, for None, every cylinder driving a coordinate) of
    ``mech``; ModelError if there is none.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.machines.ratings import need_cylinders
    >>> [c.name for c in need_cylinders(examples.hitch_003(), None, "crane_chart")]
    ['ГЦ']
    """
    cyls = [c for c in mech.cylinders if c.coordinate is not None
            and (names is None or c.name in names)]
    if not cyls:
        raise ModelError(f"{mech.name}: the rating {what!r} needs a cylinder driving a "
                         f"coordinate ([[cylinders]] with a coordinate)")
    return cyls
