"""What the page may send: bounded pydantic models of the API's requests.

Every request body is JSON of at most :data:`MAX_BODY` bytes (the server refuses
a longer one with 413 before parsing it). A request names parameters of the
model file and gives finite numbers in the unit the file writes each one; names
are short identifiers, at most :data:`~assur.views.page.session.MAX_PARAMS` of them;
the number of positions is bounded by
:data:`~assur.views.page.session.MAX_POSITIONS`. Nothing is executed: the values are
written into the model's TOML text and read back by :func:`assur.io.loads`,
whose pydantic schema (:mod:`assur.io._schema`) and builder validate the result
as they validate a file on disk.

Examples
--------
>>> AnalyzeRequest(params={"L5": 0.48}, positions=51).positions
51
>>> AnalyzeRequest(params={"L5": float("nan")})
Traceback (most recent call last):
...
pydantic_core._pydantic_core.ValidationError: 1 validation error for AnalyzeRequest
...
"""

from __future__ import annotations

from typing import Annotated, Literal, Optional

from pydantic import BaseModel, ConfigDict, Field, StringConstraints

from .session import MAX_PARAMS, MAX_POSITIONS

__all__ = ["AnalyzeRequest", "ExportRequest", "DxfRequest", "MAX_BODY"]

#: largest request body [bytes]
MAX_BODY = 64 * 1024

#: a parameter's name as a model file writes it (a TOML bare key, at most 64 characters)
Name = Annotated[str, StringConstraints(pattern=r"^[A-Za-z_][A-Za-z0-9_\-]{0,63}$")]
#: a finite number of a sane magnitude (a model's value in its file's unit)
Number = Annotated[float, Field(allow_inf_nan=False, ge=-1e12, le=1e12)]


class _Request(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    params: dict[Name, Number] = Field(default_factory=dict, max_length=MAX_PARAMS)
    lang: Literal["en", "ru"] = "en"
    #: the units results are shown in (:data:`assur.core.display.SYSTEMS`); None: the
    #: model file's choice
    units: Optional[Literal["file", "engineering", "si", "imperial"]] = None


class AnalyzeRequest(_Request):
    """``POST /api/analyze``: the parameters changed, the positions to draw.

    Examples
    --------
    >>> from pydantic import ValidationError
    >>> from assur.views.page.api import AnalyzeRequest
    >>> req = AnalyzeRequest.model_validate_json('{"params": {"L5": 0.48}, "lang": "ru"}')
    >>> req.params, req.positions, req.lang      # L5 in the file's unit [m]
    ({'L5': 0.48}, 101, 'ru')
    >>> try:
    ...     AnalyzeRequest(positions=1)
    ... except ValidationError as e:
    ...     print(e.errors()[0]["loc"], e.errors()[0]["msg"])
    ('positions',) Input should be greater than or equal to 2
    """

    positions: int = Field(101, ge=2, le=MAX_POSITIONS)
    #: the tables' columns as ``{"f64": base64}`` — their values as little-endian
    #: float64 bytes, NaN where undefined — instead of JSON lists of numbers (null where
    #: undefined): what the page asks for, whose answers then cost a fraction to encode
    #: and to parse (``benchmarks/page.py``)
    packed: bool = False


class ExportRequest(_Request):
    """``POST /api/export/{csv,xlsx,toml}``: the tables of the edited model over its
    file's range (``csv``: the table ``table``, default the first), or its file.

    Examples
    --------
    >>> from pydantic import ValidationError
    >>> from assur.views.page.api import ExportRequest
    >>> ExportRequest().table is None, ExportRequest(table="4.1").table   # None: the first
    (True, '4.1')
    >>> try:
    ...     ExportRequest(table="4.1", sheet="all")
    ... except ValidationError as e:
    ...     print(e.errors()[0]["loc"], e.errors()[0]["msg"])
    ('sheet',) Extra inputs are not permitted
    """

    table: Optional[Annotated[str, StringConstraints(max_length=16)]] = None
    #: the page's positions (one coordinate: evenly over its range, a crank's whole
    #: turn); None: the file's own range
    positions: Optional[int] = Field(None, ge=2, le=MAX_POSITIONS)


class DxfRequest(_Request):
    """``POST /api/export/dxf``: the drawing at the coordinate values ``at`` (in the
    coordinate's unit: m, or degrees for a crank; one coordinate: a position per
    value; more: one value per coordinate, one position), one layer per link.

    Examples
    --------
    >>> from pydantic import ValidationError
    >>> from assur.views.page.api import DxfRequest
    >>> DxfRequest(at=[0.42, 0.67]).at             # S [m]
    [0.42, 0.67]
    >>> try:
    ...     DxfRequest(at=[0.5] * 65)
    ... except ValidationError as e:
    ...     print(e.errors()[0]["loc"], e.errors()[0]["msg"])
    ('at',) List should have at most 64 items after validation, not 65
    """

    at: list[Number] = Field(default_factory=list, max_length=64)
    positions: int = Field(101, ge=2, le=MAX_POSITIONS)
