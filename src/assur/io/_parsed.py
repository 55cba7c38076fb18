"""A model file's text read but not yet built (:class:`ParsedText`, made by
:func:`assur.io.parse_text`): the interactive page builds each parameter change from
it without reading the text again (:mod:`assur.views.page.session`)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import Mapping

from ._build import Builder
from ._errors import key_path

__all__ = ["ParsedText"]


@dataclass(frozen=True)
class ParsedText:
    """A model file's text read as :func:`loads` reads it — TOML parsed, ``extends``
    resolved, its line index — before the model is built: :meth:`build` is the rest of
    :func:`loads`. :meth:`with_values` gives the same text with other values (of
    ``[params]``, a ``[motion]`` speed) without reading the text again (the
    interactive page's parameter changes, :mod:`assur.views.page.session`).

    Attributes
    ----------
    data : dict
        The file's tables, ``extends`` merged (not to be modified: builds share it).
    index : mapping
        Key path → line (:mod:`assur.io._lines`; with ``extends``, the line in the
        file the key came from).
    name : str
        How errors name the file.
    source : Path or None
        The file the text was read from.

    Examples
    --------
    >>> from assur import io
    >>> text = io.bundled("hitch_003").read_text(encoding="utf-8")
    >>> parsed = io.parse_text(text, "hitch_003.toml")
    >>> parsed.data["params"]["L5"]
    '0.480 m'
    >>> parsed.with_values({("params", "L5"): "0.5 m"}).build().mechanism.params["L5"]  # [m]
    0.5
    """

    data: dict
    index: Mapping
    name: str = "<string>"
    source: Path | None = None

    def with_values(self, values: Mapping[tuple, object]) -> "ParsedText":
        """The text with the values at the key paths ``values`` replaced (``("params",
        "L5")``, ``("motion", "j1", "speed")``), each as the TOML parser gives it
        (``"0.5 m"`` for ``L5 = "0.5 m"``, ``2`` for ``n = 2``): what :func:`parse_text`
        gives for the text with those values written where the old ones stood, each on
        its line (the line index is kept), when the text itself gives each replaced
        value as one value (a number or a string; an ``extends``' base's value at the
        same key is then overridden whole). Every key path must be there already.

        Raises
        ------
        KeyError
            A key path that is not in the data (nothing to replace).

        Examples
        --------
        >>> from assur import io
        >>> parsed = io.parse_text('[params]\\nL = "1 m"\\n', "x.toml")
        >>> parsed.with_values({("params", "L"): "2 m"}).data, parsed.data
        ({'params': {'L': '2 m'}}, {'params': {'L': '1 m'}})
        >>> parsed.with_values({("params", "M"): 1})
        Traceback (most recent call last):
        ...
        KeyError: 'params.M: not in the data'
        """
        data = dict(self.data)
        for path, v in values.items():
            table = data
            for k in path[:-1]:  # copied along the path: the parsed data stay as they are
                inner = table.get(k)
                if not isinstance(inner, dict):
                    raise KeyError(f"{key_path(path)}: not in the data")
                table[k] = inner = dict(inner)
                table = inner
            if path[-1] not in table:
                raise KeyError(f"{key_path(path)}: not in the data")
            table[path[-1]] = v
        return ParsedText(data, self.index, self.name, self.source)

    def build(self) -> "Model":
        """The :class:`Model` (:func:`loads` of the text).

        Raises
        ------
        ModelFileError
            See :func:`loads`.

        Examples
        --------
        >>> from assur import io
        >>> text = io.bundled("hitch_003").read_text(encoding="utf-8")
        >>> io.parse_text(text, "hitch_003.toml").build().range.shape
        (10,)
        """
        from . import Model  # the package's (this module is imported by it)
        data, name, source = self.data, self.name, self.source
        builder = Builder(name, data, self.index)
        mech, grid, axes, solved = builder.build()
        design = None
        if "design" in data:  # [design]: io/_design.py (imported only for files that have one)
            from ._design import build_design
            design = build_design(builder, mech)
        return Model(mech, grid, MappingProxyType(axes), tuple(solved), source,
                     builder.dynamics,
                     tuple(builder.warnings), builder.lift_test, builder.paired, builder.drive,
                     builder.simulation, design, tuple(builder.tolerances), builder.path,
                     tuple(builder.ratings))
