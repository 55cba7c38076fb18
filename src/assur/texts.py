"""User text in more than one language: titles, notes, flags and labels of a model.

A model file may give any of its free texts (``[model] title`` and ``notes``, a
formula's ``label`` and ``flags``, a sign map's ``note``) either as a string or as a
table of languages::

    title = { en = "Mini-tractor hitch (seed 003)", ru = "Механизм навески мини-трактора" }

Inside, such a text is a :class:`Text`: a ``str`` (its English, or its only, text —
so every place that treats notes as strings keeps working) that also carries its
translations. Views pick a language with :func:`localize`; a text with no
translation for a language is shown as it is.
"""

from __future__ import annotations

from typing import Mapping

__all__ = ["Text", "text", "localize", "LANGS"]

#: the report languages
LANGS = ("en", "ru")


class Text(str):
    """A string (its English text) with translations.

    Parameters
    ----------
    en : str
        The English text (or the only text of the model).
    **translations : str
        The same text in other languages, by language code (``ru="…"``).

    Examples
    --------
    >>> t = Text("closure", ru="замыкание")
    >>> str(t), localize(t, "ru"), localize("plain", "ru")
    ('closure', 'замыкание', 'plain')
    """

    __slots__ = ("translations",)

    def __new__(cls, en: str, **translations: str):
        self = super().__new__(cls, en)
        self.translations = {k: str(v) for k, v in translations.items() if v is not None}
        return self

    def __reduce__(self):  # pickling (Dask, process pools) keeps the translations
        return (_rebuild, (str(self), self.translations))

    def __repr__(self):
        # the text as a name is written in messages ("rigid point 'arm 34' …") and in a
        # group's repr: its identifying (English) string; the translations are data
        return str.__repr__(self)


def _rebuild(en, translations):
    return Text(en, **translations)


def text(value) -> str:
    """A text from a string or a ``{lang: text}`` mapping (``en`` is the default text;
    a mapping without ``en`` takes its first language as the default).

    Examples
    --------
    >>> from assur.texts import text
    >>> t = text({"ru": "Навеска", "en": "Hitch"})
    >>> str(t), t.translations
    ('Hitch', {'ru': 'Навеска'})
    >>> str(text({"ru": "Навеска"}))         # no English: the first language
    'Навеска'
    >>> text("plain")                        # a string stays as it is
    'plain'
    >>> text({})
    Traceback (most recent call last):
    ...
    ValueError: a text needs at least one language
    """
    if isinstance(value, Mapping):
        items = {str(k): str(v) for k, v in value.items() if v is not None}
        if not items:
            raise ValueError("a text needs at least one language")
        en = items.pop("en", None)
        if en is None:
            en = next(iter(items.values()))
        return Text(en, **items)
    return value


def localize(value, lang: str) -> str:
    """``value`` in ``lang`` (its default text where it has no such translation).

    Examples
    --------
    >>> from assur.texts import localize, text
    >>> t = text({"en": "Hitch", "ru": "Навеска"})
    >>> localize(t, "ru"), localize(t, "en"), localize(t, "de")
    ('Навеска', 'Hitch', 'Hitch')
    >>> localize("plain", "ru"), localize(None, "ru")
    ('plain', None)
    """
    if value is None:
        return value
    if lang != "en":
        tr = getattr(value, "translations", None)
        if tr and lang in tr:
            return tr[lang]
    return str(value)
