"""The types of the command line's numeric options, defined once: every count, seed,
duration and list of positions is checked by typer before a command runs (the ``parser`` of each option), and a
value outside its range is a usage error (exit status 2) that names the option and
the range (:mod:`assur.views.cli`).

* :data:`COUNT` (samples, population, starts, generations, positions, designs per
  task): a whole number ≥ 1, also written as ``2e7`` or ``10_000``;
* :data:`SEED`: a whole number 0 … 2**32 − 1, the range of numpy's legacy seeding
  that SciPy's differential evolution and pymoo use (``np.random.default_rng``, of
  ``sweep`` and ``tolerance``, takes it too);
* :data:`DURATION`: a finite number of seconds > 0 (``nan``, ``inf``, 0 and negative
  values refused, never silently replaced);
* :class:`Numbers`: comma-separated finite numbers (``dxf --at``, ``analyze
  --draw-at``);
* :class:`Address`: a Dask scheduler's address, ``tcp://host:port``.
"""

from __future__ import annotations

import math
import re

import typer

def _fail(message: str):
    """Refuse an option's value: typer names the option and exits with status 2."""
    raise typer.BadParameter(message)


__all__ = ["Count", "Positive", "Numbers", "Address", "COUNT", "SEED", "DURATION"]


class Count:
    """A whole number in ``minimum … maximum``, given as an integer (``20000``,
    ``20_000``) or as a number whose value is whole (``2e7``, ``2.0e4``).

    Parameters
    ----------
    minimum : int
        The smallest value accepted.
    maximum : int or None
        The largest value accepted (None: no bound).
    note : str
        Shown after the range in messages, e.g. ``"2**32 − 1"``.

    Examples
    --------
    >>> from assur.views.cli._types import COUNT, SEED
    >>> import typer
    >>> COUNT("2e7"), COUNT("10_000"), SEED("4294967295")
    (20000000, 10000, 4294967295)
    >>> for bad in (COUNT, "0"), (COUNT, "2.5"), (SEED, "-1"):
    ...     try:
    ...         bad[0](bad[1])
    ...     except typer.BadParameter as e:
    ...         print(e)
    0 is out of range: expected a whole number ≥ 1
    '2.5' is not a whole number: expected a whole number ≥ 1 (2e7 is accepted)
    -1 is out of range: expected a whole number in 0 … 4294967295 (2**32 − 1)
    """

    def __init__(self, minimum: int = 1, maximum: int | None = None, note: str = ""):
        self.minimum, self.maximum, self.note = int(minimum), maximum, note

    def describe(self) -> str:
        """The accepted values in words.

        Examples
        --------
        >>> from assur.views.cli._types import Count
        >>> Count(0, 65535).describe(), Count(2).describe()
        ('a whole number in 0 … 65535', 'a whole number ≥ 2')
        """
        if self.maximum is None:
            return f"a whole number ≥ {self.minimum}"
        note = f" ({self.note})" if self.note else ""
        return f"a whole number in {self.minimum} … {self.maximum}{note}"

    def __call__(self, value):
        if isinstance(value, bool):
            _fail(f"{value!r} is not a number: expected {self.describe()}")
        if isinstance(value, int):
            n = value
        else:
            text = str(value).strip()
            try:
                n = int(text)
            except ValueError:
                try:
                    f = float(text)
                except ValueError:
                    _fail(f"{value!r} is not a number: expected {self.describe()}")
                if not math.isfinite(f) or not f.is_integer():
                    _fail(f"{value!r} is not a whole number: expected "
                          f"{self.describe()} (2e7 is accepted)")
                n = int(f)
        if n < self.minimum or (self.maximum is not None and n > self.maximum):
            _fail(f"{value} is out of range: expected {self.describe()}")
        return n

    def __repr__(self):
        return f"Count({self.minimum}, {self.maximum})"


class Positive:
    """A finite number > 0 (NaN, ±inf, 0 and negative values are refused).

    Parameters
    ----------
    unit : str
        The unit written after the range in messages, e.g. ``"s"``.

    Examples
    --------
    >>> from assur.views.cli._types import DURATION
    >>> import typer
    >>> DURATION("2.5"), DURATION("1e-3")
    (2.5, 0.001)
    >>> try:
    ...     DURATION("nan")
    ... except typer.BadParameter as e:
    ...     print(e)
    'nan' is not allowed: expected a finite number > 0 s
    """

    def __init__(self, unit: str = ""):
        self.unit = unit

    def describe(self) -> str:
        """The accepted values in words.

        Examples
        --------
        >>> from assur.views.cli._types import Positive
        >>> Positive("s").describe()
        'a finite number > 0 s'
        """
        return "a finite number > 0" + (f" {self.unit}" if self.unit else "")

    def __call__(self, value):
        if isinstance(value, bool):
            _fail(f"{value!r} is not a number: expected {self.describe()}")
        try:
            f = float(value)
        except (TypeError, ValueError):
            _fail(f"{value!r} is not a number: expected {self.describe()}")
        if not math.isfinite(f) or f <= 0:
            _fail(f"{value!r} is not allowed: expected {self.describe()}")
        return f

    def __repr__(self):
        return f"Positive({self.unit!r})"


class Numbers:
    """Comma-separated finite numbers, each optionally followed by ``°`` or ``deg``
    (crank angles); the empty string is no value (the command's default positions).
    Converted to a tuple of floats; NaN, ±inf and text are refused.

    Examples
    --------
    >>> from assur.views.cli._types import Numbers
    >>> import typer
    >>> Numbers()("0.42, 0.67"), Numbers()("14.7°,90deg"), Numbers()("")
    ((0.42, 0.67), (14.7, 90.0), ())
    >>> try:
    ...     Numbers()("0.5,nan")
    ... except typer.BadParameter as e:
    ...     print(e)
    'nan' is not a finite number: expected comma-separated finite numbers, e.g. 0.42,0.67
    """

    def __call__(self, value):
        if isinstance(value, tuple):
            return value
        out = []
        for part in str(value).split(","):
            text = part.strip().removesuffix("°").removesuffix("deg").strip()
            if not text:
                continue
            try:
                f = float(text)
            except ValueError:
                _fail(f"{part.strip()!r} is not a number: expected comma-separated "
                          f"numbers, e.g. 0.42,0.67")
            if not math.isfinite(f):
                _fail(f"{part.strip()!r} is not a finite number: expected comma-separated "
                          f"finite numbers, e.g. 0.42,0.67")
            out.append(f)
        if not out and str(value).strip():
            _fail(f"{value!r} names no position: expected comma-separated numbers, "
                      f"e.g. 0.42,0.67")
        return tuple(out)

    def __repr__(self):
        return "Numbers()"


class Address:
    """The address of a Dask scheduler: ``[scheme://]host:port`` with the scheme
    ``tcp`` (the default), ``tls``, ``ws``, ``wss`` or ``ucx``, a host name or an IP
    address (IPv6 in brackets) and a port 1 … 65535. Converted to the address with its
    scheme; whether anything listens there is checked when the command connects.

    Examples
    --------
    >>> from assur.views.cli._types import Address
    >>> import typer
    >>> Address()("10.0.0.5:8786"), Address().split("tls://[::1]:8786")
    ('tcp://10.0.0.5:8786', ('tls', '::1', 8786))
    >>> try:
    ...     Address()("not a url")
    ... except typer.BadParameter as e:
    ...     print(e)
    'not a url' is not a scheduler address: expected [tcp://]host:port, e.g. tcp://192.168.1.10:8786
    """

    SCHEMES = ("tcp", "tls", "ws", "wss", "ucx")
    _RE = re.compile(r"^(?:(?P<scheme>[A-Za-z][A-Za-z0-9+.-]*)://)?"
                     r"(?P<host>\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9](?:[A-Za-z0-9._-]*[A-Za-z0-9])?)"
                     r":(?P<port>[0-9]{1,5})/?$")

    def split(self, value: str):
        """``(scheme, host, port)`` of an address, or None when it is not one.

        Examples
        --------
        >>> from assur.views.cli._types import Address
        >>> Address().split("host:8786"), Address().split("host")
        (('tcp', 'host', 8786), None)
        """
        m = self._RE.match(str(value).strip())
        if m is None:
            return None
        scheme = (m["scheme"] or "tcp").lower()
        port = int(m["port"])
        if scheme not in self.SCHEMES or not 1 <= port <= 65535:
            return None
        return scheme, m["host"].strip("[]"), port

    def __call__(self, value):
        parts = self.split(value)
        if parts is None:
            _fail(f"{value!r} is not a scheduler address: expected [tcp://]host:port, "
                      f"e.g. tcp://192.168.1.10:8786")
        scheme, host, port = parts
        return f"{scheme}://{f'[{host}]' if ':' in host else host}:{port}"

    def __repr__(self):
        return "Address()"


#: counts: samples, population per variable, starts, generations, designs per task
COUNT = Count(1)
#: seeds of the random generators: numpy's legacy range, which SciPy and pymoo use
SEED = Count(0, 2**32 - 1, "2**32 − 1")
#: durations [s]
DURATION = Positive("s")
