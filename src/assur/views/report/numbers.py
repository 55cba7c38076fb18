"""Numbers and quantities as a document prints them, in the user's units and language.

One place for the digits every view shows (HTML tables, the terminal, the
workbook's display formats, the texts of notes and figures):

* a column of numbers gets one count of decimals, chosen so that its largest
  magnitude shows :data:`SIGNIFICANT` significant digits (:func:`decimals`) — not
  17-digit floats, not −2, −1, −0.149 in one column;
* a number that rounds to zero is printed without a minus ("0.000", never "-0.000");
* Russian uses the decimal comma (:func:`number`);
* a quantity is a value [SI] of a kind shown in the display unit of that kind
  (:class:`assur.core.display.DisplayUnits`), spelt for the language
  (:func:`quantity`: ``27.5 kN``, ``27,5 кН``).
"""

from __future__ import annotations

import math

import numpy as np

from .labels import unit as unit_text

__all__ = ["SIGNIFICANT", "decimals", "number", "numbers", "quantity", "value_text",
           "unit_label"]

#: significant digits of a column's largest magnitude, and of a single value
SIGNIFICANT = 4
#: at most this many decimals (a column of values below 1e-6 is printed in e-notation)
MAX_DECIMALS = 8


def decimals(values, significant: int = SIGNIFICANT) -> int | None:
    """The decimals of a column: its largest finite magnitude gets ``significant``
    significant digits; None when the column needs e-notation (values below 1e-6
    or above 1e15), 0 for integers and a column of zeros.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.views.report.numbers import decimals
    >>> decimals([0.42, 0.67]), decimals([129614.2, 3.1]), decimals([-40.2, 150.3])
    (4, 0, 1)
    >>> decimals([np.nan, 0.0]), decimals([1e-16, 3e-16]), decimals(np.arange(3))
    (0, None, 0)
    """
    a = np.asarray(values)
    if a.dtype.kind in "biu":
        return 0
    a = np.abs(a[np.isfinite(a)].astype(float))
    big = float(a.max()) if a.size else 0.0
    if big == 0.0:
        return 0
    if big < 1e-6 or big >= 1e15:
        return None
    return int(min(MAX_DECIMALS, max(0, significant - 1 - math.floor(math.log10(big)))))


def number(x, digits: int | None = None, lang: str = "en",
           significant: int = SIGNIFICANT) -> str:
    """``x`` printed with ``digits`` decimals (a column's :func:`decimals`), or alone
    with ``significant`` significant digits and no trailing zeros (``digits``
    None); never "-0"; the decimal comma in Russian; "—" for NaN, "∞" for infinity.

    Examples
    --------
    >>> from assur.views.report.numbers import number
    >>> number(0.42, 4), number(-0.00001, 3), number(27.5), number(27.5, lang="ru")
    ('0.4200', '0.000', '27.5', '27,5')
    >>> number(129614.2), number(3.1e-16), number(float("nan")), number(True)
    ('129614', '3.1e-16', '—', 'yes')
    """
    if isinstance(x, (bool, np.bool_)):
        return ("да" if x else "нет") if lang == "ru" else ("yes" if x else "no")
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    x = float(x)
    if not math.isfinite(x):
        return _NOT_FINITE[repr(x)]
    if digits is None:
        digits = decimals([x], significant)
        if digits is None:
            s = f"{x:.{max(significant - 2, 1)}e}"
            mant, exp = s.split("e")
            mant = mant.rstrip("0").rstrip(".") if "." in mant else mant
            s = f"{mant}e{int(exp)}"
        else:
            s = f"{x:.{digits}f}"
            if "." in s:
                s = s.rstrip("0").rstrip(".")
    else:
        s = f"{x:.{digits}f}"
    s = _unsigned_zero(s)
    return s.replace(".", ",") if lang == "ru" else s


#: a value that is not a number, as a document prints it (by Python's text of it)
_NOT_FINITE = {"nan": "—", "inf": "∞", "-inf": "−∞"}


def _unsigned_zero(s: str) -> str:
    """A number's text without the minus of a value that rounds to zero ("-0.000")."""
    return s[1:] if s.startswith("-") and float(s) == 0.0 else s


def numbers(values, digits: int | None = None, lang: str = "en") -> list:
    """A column of numbers printed as :func:`number` prints each (the same strings),
    at once: a table of a crank turn holds tens of thousands of them.

    Examples
    --------
    >>> import numpy as np
    >>> from assur.views.report.numbers import numbers
    >>> numbers([0.42, -0.00001, np.nan, -np.inf, 3.0], 4, "ru")
    ['0,4200', '0,0000', '—', '−∞', '3,0000']
    >>> numbers(np.array([2, 3])), numbers([27.5, 1e-9])    # integers; digits None: each alone
    (['2', '3'], ['27.5', '1e-9'])
    """
    a = np.asarray(values)
    if digits is None or a.dtype.kind not in "f" or a.ndim != 1:
        return [number(x, digits, lang) for x in (a.tolist() if a.ndim else [a.item()])]
    out = [f"{x:.{digits}f}" for x in a.tolist()]
    # only a value that is not finite or has a minus may print otherwise than above
    for i in np.flatnonzero(~np.isfinite(a) | np.signbit(a)).tolist():
        x = float(a[i])
        out[i] = _NOT_FINITE[repr(x)] if not math.isfinite(x) else _unsigned_zero(out[i])
    return [s.replace(".", ",") for s in out] if lang == "ru" else out


def unit_label(text: str, lang: str) -> str:
    """A unit as the documents write it: ``°`` for degrees, Russian symbols in Russian
    (``kN·m`` → ``кН·м``).

    Examples
    --------
    >>> from assur.views.report.numbers import unit_label
    >>> unit_label("deg", "en"), unit_label("deg", "ru"), unit_label("kN·m", "ru")
    ('deg', '°', 'кН·м')
    """
    return unit_text(text, lang)


def quantity(si, kind: str, units, lang: str = "en", significant: int = SIGNIFICANT) -> str:
    """A value [SI] of ``kind`` in its display unit (``units``: a
    :class:`assur.core.display.DisplayUnits`), with its unit, for ``lang``.

    Examples
    --------
    >>> from assur.core.display import unit_system
    >>> from assur.views.report.numbers import quantity
    >>> eng = unit_system(None, "engineering")
    >>> quantity(27500.0, "force", eng), quantity(27500.0, "force", eng, "ru")
    ('27.5 kN', '27,5 кН')
    >>> quantity(0.42, "length", unit_system(None, "imperial"))   # 0.42 m [in]
    '16.54 in'
    >>> import math; quantity(math.pi / 6, "angle", eng, "ru")
    '30°'
    """
    u = units[kind]
    return _with_unit(number(u.of(si), None, lang, significant), u.text, lang)


def value_text(value, unit: str, units, lang: str = "en",
               significant: int = SIGNIFICANT) -> str:
    """A value given in ``unit`` (a table column's: ``"m"``, ``"deg"``, ``"N"``),
    shown in ``units`` with its unit, for ``lang``.

    Examples
    --------
    >>> from assur.core.display import unit_system
    >>> from assur.views.report.numbers import value_text
    >>> value_text(0.42, "m", unit_system(None, "engineering")), value_text(14.679, "deg",
    ...     unit_system(None, "si"), "ru")
    ('420 mm', '0,2562 рад')
    """
    v, text = units.convert(value, unit)
    return _with_unit(number(float(v), None, lang, significant), text, lang)


def _with_unit(number_text: str, unit: str, lang: str) -> str:
    """A number with its unit: degrees as ``30°`` in every language, a plain number
    alone, otherwise ``27.5 kN``."""
    if unit in ("deg", "°"):
        return f"{number_text}°"
    label = unit_label(unit, lang)
    return number_text if label == "-" else f"{number_text} {label}"
