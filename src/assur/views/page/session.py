"""One model file being edited on the page: its parameters, the edited text, the payload.

A :class:`PageModel` holds the file's text as a :mod:`tomlkit` document (comments,
order and layout kept). The page sends new values of parameters of ``[params]``
in the unit the file gives each one (``L5 = 0.48`` for ``L5 = "0.480 m"``,
``phiBD = 22`` for ``"22 deg"``); :meth:`PageModel.edited_text` writes them into
the text (``L5 = "0.5 m"``) and :meth:`PageModel.load` gives the model of that text
as :func:`assur.io.loads` reads it — the same TOML values, pydantic schema
(:mod:`assur.io._schema`) and builder as a file on disk; the file's TOML (and its
``extends`` files) is parsed once, and a change puts its values into that data
(:meth:`assur.io.ParsedText.with_values`). Nothing the page sends is
executed: values are finite numbers, names must be parameters of the file.

:meth:`PageModel.compute` analyzes the edited model over ``positions`` evenly
spaced values of its coordinate (one coordinate; the file's own positions for
more) and returns the page's payload: the drawing (:mod:`assur.views.geometry`),
the seed-like tables (:func:`assur.views.report.tables.seed_tables`) and the solved
design conditions; a model that cannot be built or assembled gives
``{"ok": False, "error": {...}}`` with the message of its :class:`ModelError`
or :class:`AssemblyError` (never a traceback).

Examples
--------
>>> from assur.io import bundled
>>> pm = PageModel.from_path(bundled("hitch_003"))
>>> [p["name"] for p in pm.parameters()[:3]], pm.parameters()[0]["unit"]
(['X01', 'Y01', 'X03'], 'm')
>>> 'L5 = "0.5 m"' in pm.edited_text({"L5": 0.5})
True
>>> out = pm.compute({"L5": 0.3}, positions=11)
>>> out["ok"], out["error"]["kind"]
(False, 'assembly')
"""

from __future__ import annotations

import dataclasses
import math
import re
import threading
import time
from collections import OrderedDict
from pathlib import Path

import numpy as np

__all__ = ["PageModel", "MAX_POSITIONS", "MAX_PARAMS", "default_plots", "packed_values"]

#: most positions a page may ask for (the drawing, the plots and the live table)
MAX_POSITIONS = 1001
#: most parameters one request may set
MAX_PARAMS = 512
#: loaded models kept, by their edited text (least recently used dropped)
MODELS_KEPT = 16

#: a value with an optional unit as a model file writes it: "0.48 m", "22 deg", "17.5 MPa"
_QUANTITY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([^\d\s].*)?$")


def _number_and_unit(value):
    """``(number, unit text)`` of a TOML value that is a plain number or a number with a
    unit; None for anything else (a parameter name, an expression, a table)."""
    if isinstance(value, bool):
        return None
    if isinstance(value, (int, float)):
        return float(value), ""
    if isinstance(value, str):
        m = _QUANTITY.match(value)
        if m:
            return float(m.group(1)), (m.group(2) or "").strip()
    return None


def _toml_number(raw: str):
    """A bare TOML number's text (``2``, ``0.84``, ``1_000``) as a Python number."""
    raw = raw.replace("_", "")
    try:
        return int(raw)
    except ValueError:
        try:
            return float(raw)
        except ValueError:
            return None


#: kinds of quantity that are never negative (a mass, an inertia, a pressure, an area…)
_NON_NEGATIVE = {"mass", "inertia", "pressure", "area", "volume", "time", "flow", "stiffness"}


def _limits(name, unit, raw) -> dict:
    """The physical span of a parameter's value, in the unit the file writes it:
    ``{"min", "max", "integer"}`` (None: unbounded) — a count (a TOML integer without
    a unit) is whole and not negative, an efficiency (``eta…``, ``η…``) lies in
    0…1, a mass, an inertia, a pressure, an area, a volume, a time or a flow is
    not negative; lengths (coordinates of points too), angles and forces may be
    of either sign.

    Examples
    --------
    >>> _limits("n_boom", "-", 2), _limits("eta_v", "-", 0.9)
    ({'min': 0, 'max': None, 'integer': True}, {'min': 0, 'max': 1, 'integer': False})
    >>> _limits("m", "kg", "1047 kg"), _limits("X01", "m", "-0.1 m")
    ({'min': 0, 'max': None, 'integer': False}, {'min': None, 'max': None, 'integer': False})
    """
    from ...core.display import kind_of
    if unit == "-":
        if isinstance(raw, int) and not isinstance(raw, bool):
            return {"min": 0, "max": None, "integer": True}
        if re.match(r"(?i)^(eta|η)", name):
            return {"min": 0, "max": 1, "integer": False}
        return {"min": None, "max": None, "integer": False}
    kind = kind_of(unit)
    return {"min": 0 if kind in _NON_NEGATIVE else None, "max": None, "integer": False}


def _plain(value):
    """A tomlkit item as a plain Python value."""
    unwrap = getattr(value, "unwrap", None)
    return unwrap() if unwrap is not None else value


class PageModel:
    """A model file's text, editable by parameter.

    Parameters
    ----------
    text : str
        The model file's content (TOML).
    name : str
        How messages name the file (its path as given).
    source : Path, optional
        The file it came from (``extends`` paths are relative to its directory).

    Raises
    ------
    ModelError
        When the text itself is not a valid model (the page needs a valid start).

    Examples
    --------
    >>> from assur.io import bundled
    >>> from assur.views.page.session import PageModel
    >>> text = bundled("hitch_003").read_text(encoding="utf-8")
    >>> pm = PageModel(text, name="hitch.toml")
    >>> pm.name, pm.model.mechanism.name, len(pm.editable)   # editable parameters
    ('hitch.toml', 'hitch_003', 28)
    >>> PageModel("[model]", name="bad.toml")
    Traceback (most recent call last):
    ...
    assur.io.ModelFileError: bad.toml:1: model.name: missing required key "name"
    """

    def __init__(self, text: str, name: str = "<model>", source: Path | None = None):
        from ..._extras import require
        require("page", "the interactive page (assur serve)")
        import tomlkit

        from ...io import parse_text
        self.text = _inherited(text.removeprefix("\ufeff"), source)
        self.name = name
        self.source = source
        # the text read once (TOML, extends): a change of values builds from it
        # (:meth:`load`); the model as io.loads gives it, which refuses a bad start
        self._parsed = parse_text(self.text, name, source=source)
        self.model = self._parsed.build()
        #: where each editable value stands in the file's data: ("params", name), or
        #: ("motion", coordinate, "speed")
        self._paths = {}
        # the models of the texts loaded last (a model is immutable, loading is pure):
        # a slider moved back, the language switched or a download after a change
        # reads its file once
        self._models = OrderedDict()
        self._lock = threading.Lock()
        self.doc = tomlkit.parse(self.text)
        self._params = self._read_params()
        self._spans = self._value_spans()
        self._read_speeds()
        for p in self._params:  # a value the text does not show plainly is not edited
            p["editable"] = p["editable"] and p["name"] in self._spans
        self.editable = {p["name"]: p for p in self._params if p["editable"]}

    @classmethod
    def from_path(cls, path) -> "PageModel":
        """The model file at ``path`` (read as :func:`assur.io.load` reads it).

        Examples
        --------
        >>> from assur.io import bundled
        >>> from assur.views.page.session import PageModel
        >>> pm = PageModel.from_path(bundled("adapter_lab6"))    # seed 001 lab 6
        >>> pm.name, pm.model.mechanism.coordinates
        ('adapter_lab6.toml', ('S',))
        >>> PageModel.from_path("no-such-model.toml")
        Traceback (most recent call last):
        ...
        FileNotFoundError: [Errno 2] No such file or directory: 'no-such-model.toml'
        """
        from ...io import read_model_bytes
        p = Path(path)
        data = read_model_bytes(p, str(path))
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError:
            from ...io import load
            load(p)  # raises the file error with its line
            raise
        return cls(text, name=p.name, source=p)

    # ---- parameters ---------------------------------------------------------------
    def _read_params(self) -> list:
        """The ``[params]`` entries in file order, grouped by the comment lines that
        precede them (``# §1.1 frame pivots``)."""
        from tomlkit.items import Comment

        from ..report.labels import unit as unit_text
        params = self.doc.get("params")
        mech = self.model.mechanism
        solved = {s.condition.unknown: s for s in self.model.solved}
        out, group, after_key = [], "", True
        if params is None:
            return out
        for key, item in params.value.body:
            if key is None:
                if isinstance(item, Comment):  # consecutive comment lines: one heading
                    line = str(item.as_string()).strip().lstrip("#").strip()
                    group = line if after_key else f"{group} {line}".strip()
                    after_key = False
                continue
            after_key = True
            name = key.key
            nu = _number_and_unit(_plain(item))
            unit = nu[1] if nu else ""
            scale = mech.units[name].scale if name in mech.units else 1.0
            value = mech.params.get(name)
            shown = float(np.asarray(value, dtype=float).ravel()[0]) / scale \
                if value is not None and np.size(value) == 1 else None
            raw = _plain(item)
            shown_unit = mech.units[name].text if name in mech.units else (unit or "-")
            out.append({
                "name": name,
                "group": group,
                "unit": unit or "-",
                "value": shown,
                "file_value": nu[0] if nu else None,
                "editable": nu is not None and name not in solved,
                "solved": name in solved,
                "comment": str(getattr(item.trivia, "comment", "") or "").lstrip("# ").strip(),
                # the unit as the tables write it (kg·m² for "kg*m^2"), in each language
                "unit_text": {lg: unit_text(shown_unit, lg) for lg in ("en", "ru")},
                **_limits(name, unit or "-", raw),
            })
        return out

    def _read_speeds(self):
        """A crank's speed of ``[motion]`` (``j1 = { direction = "cw", speed = "30 rad/s" }``)
        as one more editable value, in rpm, named ``speed-<coordinate>`` (a name no
        parameter has: a parameter's is a TOML bare key without a hyphen… or with one,
        then the speed is not offered); written back into the file as ``"<n> rpm"``.
        A speed given by a parameter's name is edited as that parameter."""
        header = re.search(r"(?m)^\[motion\][ \t]*(#.*)?$", self.text)
        if header is None:
            return
        end = re.search(r"(?m)^[ \t]*\[", self.text[header.end():])
        stop = header.end() + end.start() if end else len(self.text)
        mech = self.model.mechanism
        names = {p["name"] for p in self._params}
        for c in mech.coordinates:
            if mech.coordinate_kind(c) != "angle":
                continue
            motion = mech.motion(c)  # None: the file gives this coordinate no motion
            speed = motion.speed if motion is not None else None
            key = re.escape(c)
            pat = re.compile(rf'(?m)^[ \t]*(?:{key}|"{key}")[ \t]*=[ \t]*\{{[^\n}}]*?'
                             rf'speed[ \t]*=[ \t]*("[^"\n]*")')
            hits = list(pat.finditer(self.text, header.end(), stop))
            name = f"speed-{c}"
            if len(hits) != 1 or speed is None or name in names:
                continue
            nu = _number_and_unit(hits[0].group(1)[1:-1])
            if nu is None or not nu[1]:
                continue  # a parameter's name: edited as the parameter
            rpm = round(abs(float(speed)) * 60.0 / (2.0 * np.pi), 4)
            self._spans[name] = hits[0].span(1)
            self._paths[name] = ("motion", c, "speed")
            self._params.append({
                "name": name, "group": "[motion]", "unit": "rpm", "value": rpm,
                "file_value": nu[0], "editable": True, "solved": False,
                "comment": f"{c}: the crank's speed", "unit_text": {"en": "rpm", "ru": "об/мин"},
                "min": 0, "max": None, "integer": False})

    def _value_spans(self) -> dict:
        """``{name: (start, end)}``: where the value of each number-valued parameter of
        ``[params]`` stands in the text (one line ``name = value``, found once), so an
        edit replaces those characters and leaves the rest of the text as it is."""
        header = re.search(r"(?m)^\[params\][ \t]*(#.*)?$", self.text)
        if header is None:
            return {}
        end = re.search(r"(?m)^[ \t]*\[", self.text[header.end():])
        stop = header.end() + end.start() if end else len(self.text)
        spans = {}
        for p in self._params:
            if p["file_value"] is None:
                continue
            key = re.escape(p["name"])
            pat = re.compile(rf'(?m)^[ \t]*(?:{key}|"{key}"|\'{key}\')[ \t]*=[ \t]*'
                             rf'("[^"\n]*"|\'[^\'\n]*\'|[-+0-9.eE_]+)')
            hits = list(pat.finditer(self.text, header.end(), stop))
            if len(hits) == 1:
                raw = hits[0].group(1)
                text = raw[1:-1] if raw[:1] in "\"'" else raw
                nu = _number_and_unit(text if raw[:1] in "\"'" else _toml_number(raw))
                if nu is not None and nu[0] == p["file_value"]:
                    spans[p["name"]] = hits[0].span(1)
                    self._paths[p["name"]] = ("params", p["name"])
        return spans

    def parameters(self) -> list:
        """The parameters of ``[params]``: name, group (the comment above), unit as the
        file writes it (``-`` for a plain number), current value in that unit, whether
        the page may edit it (a number, not an unknown of ``[[solve]]``), and the
        comment at the end of its line.

        Examples
        --------
        >>> from assur.io import bundled
        >>> from assur.views.page.session import PageModel
        >>> pm = PageModel.from_path(bundled("hitch_003"))          # seed 003
        >>> p = {q["name"]: q for q in pm.parameters()}
        >>> p["L5"]["group"], p["L5"]["unit"], p["L5"]["value"], p["L5"]["editable"]  # [m]
        ('§1.2 links', 'm', 0.48, True)
        >>> round(p["L4"]["value"], 4), p["L4"]["solved"], p["L4"]["editable"]  # seed: 0.6613 m
        (0.6613, True, False)
        """
        return [dict(p) for p in self._params]

    def check_params(self, values: dict) -> None:
        """Refuse names that are not editable parameters of the file and values that
        are not finite numbers.

        Raises
        ------
        ModelError
            Naming the parameter (with a did-you-mean) or the value.

        Examples
        --------
        >>> from assur.io import bundled
        >>> from assur.views.page.session import PageModel
        >>> pm = PageModel.from_path(bundled("hitch_003"))          # seed 003
        >>> pm.check_params({"L5": 0.5, "X01": 0.4})    # [m]: valid, returns None
        >>> pm.check_params({"L55": 0.5})
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: params.L55: not an editable parameter of hitch_003.toml; did you mean "L5"?
        >>> pm.check_params({"L4": 0.66})
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: params.L4: is an unknown of [[solve]] (Given/Find): its value is solved, not set
        """
        import difflib

        from ...errors import ModelError
        if len(values) > MAX_PARAMS:
            raise ModelError(f"at most {MAX_PARAMS} parameters per request, got {len(values)}")
        solved = {p["name"] for p in self._params if p["solved"]}
        for k, v in values.items():
            if k not in self.editable:
                if k in solved:
                    raise ModelError(f"params.{k}: is an unknown of [[solve]] (Given/Find): "
                                     f"its value is solved, not set")
                close = difflib.get_close_matches(k, list(self.editable), n=1)
                hint = f'; did you mean "{close[0]}"?' if close else ""
                raise ModelError(f"params.{k}: not an editable parameter of {self.name}{hint}")
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                raise ModelError(f"params.{k}: expected a finite number, got {v!r}")

    def edited_text(self, values: dict) -> str:
        """The model file's text with the parameters ``values`` set (each in the unit
        the file gives it); comments and layout are kept.

        Raises
        ------
        ModelError
            See :meth:`check_params`.

        Examples
        --------
        >>> from assur.io import bundled
        >>> from assur.views.page.session import PageModel
        >>> pm = PageModel.from_path(bundled("hitch_003"))          # seed 003
        >>> old, new = pm.text.splitlines(), pm.edited_text({"L5": 0.5}).splitlines()
        >>> [(a, b) for a, b in zip(old, new) if a != b]    # one line changed [m]
        [('L5 = "0.480 m"', 'L5 = "0.5 m"')]
        """
        self.check_params(values)
        if not values:
            return self.text
        edits = [(*self._spans[k], new) for k, new in self._written(values).items()]
        text = self.text
        for start, end, new in sorted(edits, reverse=True):
            text = text[:start] + new + text[end:]
        return text

    def _written(self, values: dict) -> dict:
        """``{name: TOML text}``: each value as :meth:`edited_text` writes it (in the
        unit the file gives it)."""
        out = {}
        for k, v in values.items():
            unit = self.editable[k]["unit"]
            num = repr(float(v))
            num = num[:-2] if num.endswith(".0") else num
            if unit == "-":
                out[k] = num  # 2.0 is written 2 (a TOML integer), 0.84 as it is
            else:
                out[k] = f'"{num} {unit}"'
        return out

    def load(self, values: dict):
        """The :class:`assur.io.Model` of the edited text.

        Raises
        ------
        ModelError
            Bad names or values; any problem of the edited file (a condition without
            a root, a group that cannot be built) with its key and line.

        Examples
        --------
        >>> from assur.io import bundled
        >>> from assur.views.page.session import PageModel
        >>> pm = PageModel.from_path(bundled("hitch_003"))          # seed 003
        >>> model = pm.load({"L5": 0.5})                   # [m]
        >>> model.mechanism.params["L5"], model.range.shape   # [m]; positions of S
        (0.5, (10,))
        >>> pm.load({"L5": 0.5}) is model                   # kept by its text
        True
        """
        text = self.edited_text(values)
        with self._lock:
            model = self._models.get(text)
            if model is not None:
                self._models.move_to_end(text)
                return model
        model = self._build(values, text)  # raises: not kept
        with self._lock:
            self._models[text] = model
            while len(self._models) > MODELS_KEPT:
                self._models.popitem(last=False)
        return model

    def _build(self, values: dict, text: str):
        """The model of ``text`` (the edited text of ``values``) as :func:`assur.io.loads`
        gives it, built from the file's data read once with the new values put where the
        text writes them (:meth:`assur.io.ParsedText.with_values`): the same data,
        line index and builder as a fresh read of ``text``, without reading its TOML
        (and its ``extends`` files) again; ``text`` is read afresh when a value is not
        in the data as the text writes it."""
        import tomllib

        from ...io import loads
        try:
            new = {self._paths[k]: tomllib.loads(f"v = {w}")["v"]
                   for k, w in self._written(values).items()}
            parsed = self._parsed.with_values(new)
        except (KeyError, tomllib.TOMLDecodeError):
            return loads(text, name=self.name, source=self.source)
        return parsed.build()

    # ---- the page's payload -------------------------------------------------------
    def model_on(self, model, positions: int):
        """``model`` with its range resampled on ``positions`` values of its coordinate
        (one coordinate); the model as it is for more coordinates.

        A crank whose file's angles go round (span a turn, counting the step of the
        list: 0 … 360°, or 14.7°, −15.3° … −315.3° and a position added) is resampled
        over one whole turn from the file's first angle in the file's direction,
        ``positions`` evenly spaced angles with the end (the start again) left out, so
        a slider over them turns continuously through 360°; any other range evenly
        between its two ends (the file's first and last when they are its extremes).

        Examples
        --------
        >>> import numpy as np
        >>> from assur.io import bundled
        >>> from assur.views.page.session import PageModel
        >>> pm = PageModel.from_path(bundled("hitch_003"))          # seed 003
        >>> pm.model_on(pm.model, 5).range.tolist()       # S [m]
        [0.42, 0.4825, 0.545, 0.6075, 0.67]
        >>> pm = PageModel.from_path(bundled("combine_002"))        # 13 angles, one extra
        >>> q = np.degrees(pm.model_on(pm.model, 4).range)            # j1 [deg]
        >>> np.round(q, 3).tolist()                        # clockwise from 14.679°
        [14.679, -75.321, -165.321, -255.321]
        """
        if len(model.mechanism.coordinates) != 1 or positions is None:
            return model
        r = np.asarray(model.range, dtype=float)
        n = int(positions)
        lo, hi = float(np.min(r)), float(np.max(r))
        if model.mechanism.coordinate_kind(model.mechanism.coordinates[0]) == "angle" \
                and r.size > 1 and _goes_round(r):
            way = -1.0 if r[1] < r[0] else 1.0
            q = r[0] + way * 2.0 * np.pi * np.arange(n) / n
        elif r[0] in (lo, hi) and r[-1] in (lo, hi):
            q = np.linspace(r[0], r[-1], n)
        else:
            q = np.linspace(lo, hi, n)
        return dataclasses.replace(model, range=q)

    def turns(self, model) -> bool:
        """True when the page shows ``model`` over a whole turn of its crank
        (:meth:`model_on`).

        Examples
        --------
        >>> from assur.io import bundled
        >>> from assur.views.page.session import PageModel
        >>> pm = PageModel.from_path(bundled("cleaning_lab3"))      # 0 … 360°
        >>> hitch = PageModel.from_path(bundled("hitch_003"))       # S = 0.42 … 0.67 m
        >>> pm.turns(pm.model), hitch.turns(hitch.model)
        (True, False)
        """
        mech = model.mechanism
        r = np.asarray(model.range, dtype=float)
        return bool(len(mech.coordinates) == 1 and mech.coordinate_kind(mech.coordinates[0])
                    == "angle" and r.size > 1 and _goes_round(r))

    def compute(self, values: dict, positions: int = 101, lang: str = "en",
                units: str | None = None, packed: bool = False) -> dict:
        """The page's payload for the parameters ``values``.

        Returns
        -------
        dict
            ``{"ok": True, "geometry", "tables", "solved", "warnings", "units", "ms"}``
            (the tables in the display units ``units``: a system of
            :data:`assur.core.display.SYSTEMS`, default the model file's; ``units``:
            the system and the units of length and angle the position is shown in) or
            ``{"ok": False, "error": {"kind", "message"}, "ms"}``; ``kind`` is
            ``"model"`` (the file or a value), ``"assembly"`` (the mechanism cannot
            assemble) or ``"singular"``. With ``packed``, each column's ``values``
            is ``{"f64": base64}`` (:func:`packed_values`) instead of a list, and so
            are the drawing's points (x, y by position), coordinates and wheels'
            headings (:func:`_packed_geometry`).

        Examples
        --------
        >>> from assur.io import bundled
        >>> from assur.views.page.session import PageModel
        >>> pm = PageModel.from_path(bundled("hitch_003"))          # seed 003
        >>> out = pm.compute({}, positions=11)             # the file's values
        >>> out["ok"], [t["id"] for t in out["tables"]]
        (True, ['2.1', '2.2', '3.1', '4.1', '5.1', '6.1', 'IC', 'L'])
        >>> [(s["name"], round(s["value"], 4), s["unit"]) for s in out["solved"]][:1]
        [('L4', 0.6613, 'm')]
        >>> out = pm.compute({"L5": 0.5}, positions=11)    # [m]
        >>> round(out["solved"][0]["value"], 4)            # L4 solved again [m]
        0.6681
        >>> out = pm.compute({"L5": 1e6})                  # [m]
        >>> out["ok"], out["error"]["kind"]
        (False, 'model')
        >>> out = pm.compute({}, positions=11, units="imperial")
        >>> out["units"]["length"], out["tables"][3]["columns"][1]["unit"]   # S; Fgc
        ('in', 'lbf')
        """
        from ...errors import AssemblyError, ModelError, SingularPositionError
        from ..report.labels import unit
        from ..report.tables import seed_tables
        from ...texts import localize
        from ..geometry import geometry

        t0 = time.perf_counter()
        if positions is not None and not 2 <= positions <= MAX_POSITIONS:
            raise ValueError(f"positions must be in 2…{MAX_POSITIONS}, got {positions}")
        try:
            from ...core.display import unit_system
            model = self.load(values)
            analysis = self.model_on(model, positions).analyze(balancing=False)
            du = unit_system(analysis.mechanism, units)
            tables = seed_tables(analysis, lang=lang, units=du)
            geo = geometry(analysis.kinematics)
        except AssemblyError as e:
            return _error("assembly", e, t0)
        except SingularPositionError as e:
            return _error("singular", e, t0)
        except ModelError as e:
            return _error("model", e, t0)
        mech = model.mechanism
        # the columns' values as arrays for the grid and the default plots, then as the
        # page reads them: bytes (packed) or JSON lists
        tabs = [_table_json(t, lang, _column) for t in tables]
        page_warnings = []
        solved = [{"name": s.condition.unknown,
                   "value": float(s.value) / (mech.units[s.condition.unknown].scale
                                              if s.condition.unknown in mech.units else 1.0),
                   "unit": self._unit_of(s.condition.unknown)} for s in model.solved]
        grid = _grid(tabs, len(mech.coordinates))
        defaults = default_plots(tabs, len(mech.coordinates),
                                 declared=mech.display.get("plots", ()),
                                 warnings=page_warnings)
        encode = packed_values if packed else _finite
        for tj in tabs:
            for cj in tj["columns"]:
                cj["values"] = encode(cj["values"])
        if packed:
            geo = _packed_geometry(geo)
        return {
            "ok": True,
            "title": localize(mech.title, lang),
            "coordinates": [{"name": c, "kind": mech.coordinate_kind(c)}
                            for c in mech.coordinates],
            "geometry": geo,
            "tables": tabs,
            "turn": self.turns(model),
            "grid": grid,
            "defaults": defaults,
            "units": {"system": du.system, "length": unit(du["length"].text, lang),
                      "length_scale": du["length"].scale,
                      "angle": unit(du["angle"].text, lang),
                      "angle_scale": du["angle"].scale},
            "fields": self.fields(du, lang),
            "solved": solved,
            "warnings": [str(w) for w in model.warnings] + page_warnings,
            "ms": round(1e3 * (time.perf_counter() - t0), 2),
        }

    def fields(self, du, lang="en") -> dict:
        """How the page shows each editable parameter in the display units ``du`` (a
        :class:`~assur.core.display.DisplayUnits`): ``{name: {"unit", "factor"}}``, the
        shown value being the file's value × ``factor`` (the page sends the file's
        value back: shown / factor). In the ``file`` system, and for a parameter of no
        known kind, the file's own unit (factor 1).

        Examples
        --------
        >>> from assur.io import bundled
        >>> from assur.core.display import unit_system
        >>> from assur.views.page.session import PageModel
        >>> pm = PageModel.from_path(bundled("hitch_003"))          # L5 = "0.480 m"
        >>> pm.fields(unit_system(pm.model.mechanism, "engineering"))["L5"]
        {'unit': 'mm', 'factor': 1000.0}
        >>> pm.fields(unit_system(pm.model.mechanism, "imperial"), "ru")["P6"]["unit"]
        'фунт-сила'
        >>> pm.fields(unit_system(pm.model.mechanism, None))["L5"]
        {'unit': 'm', 'factor': 1.0}
        """
        from ...core.display import KINDS, kind_of
        from ..report.labels import unit
        mech = self.model.mechanism
        out = {}
        for name, p in self.editable.items():
            mu = mech.units.get(name)
            kind = kind_of(mu.text) if mu is not None else None
            if mu is None or du.system == "file" or kind not in KINDS:
                out[name] = {"unit": p["unit_text"][lang], "factor": 1.0}
                continue
            shown = du[kind]
            out[name] = {"unit": unit(shown.text, lang),
                         "factor": float(mu.scale / shown.scale)}
        return out

    def _unit_of(self, name):
        for p in self._params:
            if p["name"] == name:
                return p["unit"]
        return "-"

    def export_tables(self, values: dict, fmt: str, table: str | None = None,
                      lang: str = "en", units: str | None = None,
                      positions: int | None = None) -> tuple[bytes, str, str]:
        """The tables of the edited model over the file's own range (or, given
        ``positions``, over the page's: :meth:`model_on`), in the display units
        ``units`` (default: the model file's) and ``lang`` (Russian CSV: ``;`` and the
        decimal comma).

        Parameters
        ----------
        fmt : {"csv", "xlsx"}
            ``csv``: one table (``table``, default the first); ``xlsx``: all.

        Returns
        -------
        (bytes, media type, file name)

        Examples
        --------
        >>> from assur.io import bundled
        >>> from assur.views.page.session import PageModel
        >>> pm = PageModel.from_path(bundled("hitch_003"))          # seed 003
        >>> data, media, name = pm.export_tables({}, "csv", table="2.1")
        >>> media, name
        ('text/csv; charset=utf-8', 'hitch_003_table_2_1.csv')
        >>> data.decode("utf-8").splitlines()[0]
        'S [m],phi2 [deg],phi3 [deg],phi34 [deg],phi4 [deg],phi5 [deg],phi6 [deg],phi7 [deg]'
        >>> data, _, _ = pm.export_tables({}, "csv", table="2.1", lang="ru", units="si")
        >>> data.decode("utf-8-sig").splitlines()[1].split(";")[:2]     # S [m], φ2 [rad]
        ['0,42', '1,6001246213093063']
        >>> pm.export_tables({}, "pdf")
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: format must be csv or xlsx, got 'pdf'
        """
        import tempfile

        from ...errors import ModelError
        from ..report.html import model_inputs
        from ..report.tables import seed_tables, table_filename, write_csv, write_xlsx
        from ...core.display import unit_system
        model = self.load(values)
        analysis = (model if positions is None else
                    self.model_on(model, positions)).analyze(balancing=False)
        du = unit_system(analysis.mechanism, units)
        tabs = seed_tables(analysis, lang=lang, units=du)
        stem = Path(self.name).stem or "model"
        with tempfile.TemporaryDirectory() as d:
            if fmt == "xlsx":
                p = write_xlsx(tabs, Path(d) / "tables.xlsx", lang=lang,
                               inputs=model_inputs(analysis, lang, du))
                return (p.read_bytes(), "application/vnd.openxmlformats-officedocument."
                        "spreadsheetml.sheet", f"{stem}_tables.xlsx")
            if fmt != "csv":
                raise ModelError(f"format must be csv or xlsx, got {fmt!r}")
            ids = [t.id for t in tabs]
            tab = tabs[0] if not table else next((t for t in tabs if t.id == table), None)
            if tab is None:
                raise ModelError(f"table {table!r}: this model has tables {ids}")
            p = write_csv(tab, Path(d) / table_filename(tab), lang)
            return p.read_bytes(), "text/csv; charset=utf-8", f"{stem}_{p.name}"


def _goes_round(r) -> bool:
    """True when the angles ``r`` [rad] cover a turn: their span and the largest step
    between neighbours in order make 360° (to 0.1°)."""
    u = np.unique(np.asarray(r, dtype=float))
    step = float(np.max(np.diff(u))) if u.size > 1 else 0.0
    return bool(float(u[-1] - u[0]) >= 2.0 * np.pi - 1e-6 or
                (u.size > 2 and float(u[-1] - u[0]) + step >= 2.0 * np.pi - np.radians(0.1)))


def _grid(tables, k):
    """The full grid of a model of two coordinates, as its tables show them:
    ``{"x": [first coordinate's values], "y": [second's], "i": [per position],
    "j": [per position]}`` (display units), or None (one coordinate, more than two,
    or paired paths)."""
    from ..report.tables import grid_of
    if k != 2 or not tables or len(tables[0]["columns"]) < 2:
        return None
    c1, c2 = tables[0]["columns"][:2]
    g = grid_of(c1["values"], c2["values"])
    if g is None:
        return None
    u1, u2, i1, i2 = g
    return {"x": u1.tolist(), "y": u2.tolist(), "i": i1.tolist(), "j": i2.tolist()}


def default_plots(tables, k, declared=(), warnings=None) -> list:
    """The plots the page shows first: those the model file declares (``[display]
    plots``: ``[{"y": (columns…), "x": column or None}]``, each found in the one table
    that holds its columns: ``{"table", "symbol", "x", "with"}``; one whose columns no
    table holds is named in ``warnings``), then those chosen from what the model's
    tables hold: ``[{"table": id, "symbol": column}]`` — each cylinder's pressure and the
    capacities (``G…`` forces) of its table, the joint reaction (a magnitude
    ``R…``) with the largest peak, the centre of mass ``Xc``, ``Yc`` and the speed
    ``omega`` of a crank's dynamics; the first link angle when none of these is
    there. Among the reactions, those on the frame (link 0: ``R0…``) come first.

    Examples
    --------
    >>> from assur.io import bundled
    >>> from assur.views.page.session import PageModel, default_plots
    >>> out = PageModel.from_path(bundled("hitch_003")).compute({}, positions=11)
    >>> [(p["table"], p["symbol"]) for p in default_plots(out["tables"], 1)]
    [('4.1', 'Pgc'), ('4.1', 'G56'), ('4.1', 'GS6'), ('5.1', 'R01')]
    """
    from ...core.display import kind_of
    out = []
    for spec in declared:
        want = [*spec["y"], *([spec["x"]] if spec.get("x") else [])]
        t = next((t for t in tables if {c["symbol"] for c in t["columns"]} >= set(want)), None)
        if t is None:
            if warnings is not None:
                warnings.append(f"[display] plots: no table holds the columns {want} together")
            continue
        out.append({"table": t["id"], "symbol": spec["y"][0], "x": spec.get("x"),
                    "with": list(spec["y"][1:])})

    def add(t, c):
        if len(out) < 6 and not any(p["symbol"] == c["symbol"] and p["table"] == t["id"]
                                    for p in out):
            out.append({"table": t["id"], "symbol": c["symbol"]})

    for t in tables:
        cols = t["columns"][k:]
        pressures = [c for c in cols if kind_of(c["unit"]) == "pressure"]
        for c in pressures[:2]:
            add(t, c)
        if pressures:
            for c in [c for c in cols if c["symbol"].startswith("G")
                      and kind_of(c["unit"]) == "force"][:2]:
                add(t, c)
    peak = None
    for t in tables:
        for c in t["columns"][k:]:
            s = c["symbol"]
            if s.startswith("R") and s[-1:] not in ("x", "y") and kind_of(c["unit"]) == "force":
                v = np.asarray(c["values"], dtype=float)   # a list (None: undefined) or array
                vals = np.abs(v[np.isfinite(v)])
                rank = (s.startswith("R0"), float(vals.max())) if vals.size else None  # frame first
                if vals.size and (peak is None or rank > peak[0]):
                    peak = (rank, t, c)
        if peak is not None:
            break  # the statics' table (without inertia loads), not the kinetostatics'
    if peak is not None:
        add(peak[1], peak[2])
    for t in tables:
        for c in t["columns"][k:]:
            if c["symbol"] in ("Xc", "Yc", "omega"):
                add(t, c)
    if not out:
        for t in tables:
            for c in t["columns"][k:]:
                if kind_of(c["unit"]) == "angle":
                    add(t, c)
                    return out
    return out


def _inherited(text: str, source, depth: int = 0) -> str:
    """The model file's ``text`` with the parameters it inherits through ``extends``
    written into its own ``[params]`` (with the base's comments, as the base writes
    them), so that the page shows and edits them; the model is the same (a file's
    ``[params]`` overrides its base's with the same values). A text without
    ``extends`` (or without a ``source`` to find the base from, or whose base cannot be
    read: its load then says why) is returned as it is.

    Examples
    --------
    >>> from assur.io import bundled, loads
    >>> from assur.views.page.session import _inherited
    >>> child = bundled("hitch_003_design")                # extends hitch_003.toml
    >>> text = _inherited(child.read_text(encoding="utf-8"), child)
    >>> 'L5 = "0.480 m"' in text, "# §1.2 links" in text   # the base's, with its comments
    (True, True)
    >>> m = loads(text, name=child.name, source=child)
    >>> m.mechanism.params == loads(child.read_text(encoding="utf-8"), name=child.name,
    ...                             source=child).mechanism.params
    True
    """
    import tomlkit
    from tomlkit.exceptions import TOMLKitError

    from ...errors import ModelError
    from ...io import read_model_bytes
    try:
        doc = tomlkit.parse(text)
    except TOMLKitError:  # not TOML: the model's load says where
        return text
    ext = doc.get("extends")
    if not isinstance(ext, str) or source is None or depth > 16:
        return text
    try:
        base = (Path(source).resolve().parent / ext).resolve()
        base_text = read_model_bytes(base, str(base)).decode("utf-8").removeprefix("\ufeff")
        base_params = tomlkit.parse(_inherited(base_text, base, depth + 1)).get("params")
    except (OSError, RuntimeError, ValueError, ModelError, TOMLKitError):
        return text  # a base that cannot be read or parsed: the model's own load says why
    own = doc.get("params")
    if not base_params or not hasattr(base_params, "items"):
        return text
    missing = [k for k in base_params if own is None or k not in own]
    if not missing:
        return text
    if own is None:
        block = tomlkit.dumps({"params": base_params})
        return (text.rstrip("\n") + f"\n\n# the parameters of {ext} (this file extends it), "
                f"written here by the page\n" + block)
    for k in missing:
        own.add(k, base_params[k])
    return tomlkit.dumps(doc)


def _error(kind, e, t0):
    return {"ok": False, "error": {"kind": kind, "message": str(e)},
            "ms": round(1e3 * (time.perf_counter() - t0), 2)}


def _finite(values):
    """The values as a JSON list, None where a value is not finite (undefined)."""
    a = np.asarray(values, dtype=float).ravel()
    out = a.tolist()  # one C loop; then None where needed
    for i in np.flatnonzero(~np.isfinite(a)).tolist():
        out[i] = None
    return out


def packed_values(values) -> dict:
    """The values as ``{"f64": base64}``: their little-endian float64 bytes in base64,
    NaN where a value is undefined (the page's encoding of a table's column: a tenth of
    the time of a JSON list to write, and to read in the browser).

    Examples
    --------
    >>> import base64
    >>> import numpy as np
    >>> from assur.views.page.session import packed_values
    >>> p = packed_values([0.42, float("nan")])
    >>> np.frombuffer(base64.b64decode(p["f64"]), "<f8").tolist()
    [0.42, nan]
    """
    import base64
    a = np.ascontiguousarray(np.asarray(values, dtype="<f8").ravel())
    return {"f64": base64.b64encode(a.tobytes()).decode("ascii")}


def _column(values):
    """A column's values as one flat float array."""
    return np.asarray(values, dtype=float).ravel()


def _packed_geometry(geo) -> dict:
    """The drawing's data (:func:`assur.views.geometry.geometry`) with its arrays per
    position — each point's ``[x, y]`` (as ``(n, 2)`` values, row by row), each
    coordinate's values and each wheel's heading — as :func:`packed_values` (a JSON
    list of numbers costs ten times as much to write and to read).

    Examples
    --------
    >>> import base64
    >>> import numpy as np
    >>> g = _packed_geometry({"points": {"A": [[0.0, 1.0], [0.5, 1.5]]}, "q": {"S": [0.4, 0.6]},
    ...                       "wheels": [{"heading": [0.0, 0.1]}], "n": 2})
    >>> np.frombuffer(base64.b64decode(g["points"]["A"]["f64"]), "<f8").tolist()
    [0.0, 1.0, 0.5, 1.5]
    >>> g["q"]["S"]["f64"] == packed_values([0.4, 0.6])["f64"], g["n"]
    (True, 2)
    """
    out = dict(geo)
    out["points"] = {p: packed_values(v) for p, v in geo["points"].items()}
    out["q"] = {c: packed_values(v) for c, v in geo["q"].items()}
    if "wheels" in geo:
        out["wheels"] = [dict(w, heading=packed_values(w["heading"])) for w in geo["wheels"]]
    return out


def _table_json(t, lang, values=_finite):
    """A table as the page's JSON; ``values`` makes each column's values (default: a JSON
    list, None where undefined)."""
    from ..report.labels import unit
    return {
        "id": t.id,
        "label": t.label,
        "title": t.title(lang),
        "columns": [{"symbol": c.symbol, "unit": unit(c.unit, lang),
                     "label": c.label.get(lang, ""),
                     "values": values(c.values)} for c in t.columns],
        "notes": [n.get(lang, "") for n in t.notes],
    }
