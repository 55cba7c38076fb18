"""Checks of the documents a user reads (reports, tables, workbooks): every value in
the unit system chosen, Russian without English words, no NaN or infinity."""

from __future__ import annotations

import html as _html
import re

from assur.core.display import KINDS, SYSTEMS
from assur.core.units import COMMON_UNITS
from assur.views.report.labels import unit


def visible(page: str) -> str:
    """The visible text of an HTML page (no styles, scripts or image data)."""
    page = re.sub(r"<(style|script).*?</\1>", "", page, flags=re.S)
    page = re.sub(r"<img[^>]*>", "", page)
    page = re.sub(r"<svg.*?</svg>", "", page, flags=re.S)
    return _html.unescape(re.sub(r"<[^>]+>", "\n", page))


def allowed_units(du, lang) -> set[str]:
    """The unit labels a document in the display units ``du`` may show."""
    return {unit(du[k].text, lang) for k in KINDS} | {"%", "-"}


def _all_units(lang) -> set[str]:
    """Every unit label of every kind in every system, and of the common units."""
    out = {unit(getattr(k, s), lang) for k in KINDS.values()
           for s in ("si", "engineering", "imperial")}
    out |= {unit(u.replace("**2", "²").replace("**3", "³").replace("*", "·"), lang)
            for u in COMMON_UNITS}
    out |= {unit("deg", lang), "°"}
    return {u for u in out if u not in ("-", "%")}


_NUMBER = r"(?<![\w.,])-?\d+(?:[.,]\d+)?(?:e[-+]?\d+)?"


def unit_violations(text: str, du, lang: str) -> list[str]:
    """Each ``<number> <unit>`` (or ``<number>°``) of ``text`` whose unit is a unit of
    some kind other than the one ``du`` shows that kind in (a value in Pa in a
    report in MPa)."""
    allowed = allowed_units(du, lang)
    degrees = unit("deg", lang) in allowed or "deg" in allowed
    known = sorted(_all_units(lang) - {"°"}, key=len, reverse=True)
    alt = "|".join(re.escape(u) for u in known)
    pattern = re.compile(rf"({_NUMBER})(?:(°)|\s({alt})(?![\w²³/·]))")
    out = []
    for m in pattern.finditer(text):
        if m.group(2):
            if not degrees:
                out.append(m.group(0))
        elif m.group(3) not in allowed:
            out.append(m.group(0))
    return out


def model_texts(mech, lang) -> list[str]:
    """The model file's own texts in ``lang`` (title, notes, flags, sign notes): printed
    literally, so not held to the report's units."""
    from assur.core.columns import formulas_of, signs_of
    from assur.texts import localize

    texts = [mech.title, *mech.notes, *(m.note for m in signs_of(mech) if m.note)]
    for f in formulas_of(mech):
        texts += [*f.flags] + ([f.label] if f.label else [])
    return [localize(t, lang) for t in texts if t]


def without(text: str, parts) -> str:
    """``text`` with every one of ``parts`` taken out (longest first)."""
    for p in sorted(parts, key=len, reverse=True):
        text = text.replace(p, " ")
    return text


def model_symbols(mech, tables=()) -> set[str]:
    """The names a model's documents show as symbols: its parameters, coordinates,
    points, links, groups, cylinders, the tables' column symbols, the model's name."""
    out = set(mech.params) | set(mech.coordinates) | set(mech.points) | set(mech.bodies)
    out |= {str(g.name) for g in mech.groups} | {str(c.name) for c in mech.cylinders}
    out |= {c.symbol for t in tables for c in t.columns} | {mech.name, "assur"}
    out |= {str(getattr(ld, "name", "") or "") for ld in mech.loads}
    return {s for s in out if s}


#: functions a formula in a note may name, and the standards a report cites
_FORMULA_WORDS = {"acos", "asin", "atan", "atan2", "sin", "cos", "tan", "sqrt", "hypot",
                  "abs", "exp", "log", "max", "min", "sign", "ctg", "tg", "arcctg", "arctg",
                  "ISO", "SAE", "DIN", "GOST"}


def _symbol_like(word: str) -> bool:
    """A symbol rather than a word: a letter or two (x, BD), an abbreviation or a Roman
    numeral in capitals (IC, III), anything with a digit (X23s, J283), a subscripted
    symbol whose parts are short (R_ij, p_max, F_S), a file name (hitch_003.toml)."""
    if len(word) <= 2 or re.fullmatch(r"[A-Z]{1,5}", word) or re.search(r"\d", word):
        return True
    if word.endswith(".toml") or re.fullmatch(r"[a-z_]+\.[\w.\[\]]+", word):
        return True  # a file, or a key of a model file (params.XN, groups[3].length)
    parts = word.split("_")
    return len(parts) > 1 and all(len(p) <= 4 for p in parts)


def latin_words(text: str, allowed=frozenset()) -> list[str]:
    """Words with Latin letters in ``text`` (a Russian document) that are neither in
    ``allowed`` (the model's symbols and names) nor symbol-like (:func:`_symbol_like`),
    nor a number's exponent (3,1e-16): the English words left in a Russian text."""
    out = []
    text = re.sub(r"\[\[?[a-z_]+\]?\]", " ", text)  # a model file's section: [motion]
    for w in re.findall(r"[A-Za-z][A-Za-z0-9_\-.]*", text):
        w = w.strip(".-_")
        if not w or w in allowed or w in _FORMULA_WORDS or _symbol_like(w):
            continue
        if re.fullmatch(r"e[-+]?\d+", w):
            continue
        out.append(w)
    return sorted(set(out))


def systems():
    """The unit systems, in order."""
    return SYSTEMS


def axis_units(fig) -> list[str]:
    """The units the axes of ``fig`` name: ``[unit]`` of each axis label, and a colour
    bar's label (its unit alone)."""
    out = []
    for ax in fig.axes:
        for label in (ax.get_xlabel(), ax.get_ylabel()):
            out += re.findall(r"\[([^\]]+)\]", label)
        if getattr(ax, "_colorbar", None) is not None or ax.get_label() == "<colorbar>":
            out += [u for u in (ax.get_ylabel(),) if u and "[" not in u]
    return out
