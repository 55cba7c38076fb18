"""User text in more than one language (:mod:`assur.texts`): a :class:`Text` is the
string of its English (so every place that treats texts as strings keeps working),
carries its translations through copies, pickling (Dask) and model files, and is
shown in the report's language where it has one, as it is elsewhere."""

import copy
import pickle

import pytest

from assur import io
from assur.texts import LANGS, Text, localize, text


def test_a_text_is_its_english_string_with_translations():
    t = Text("Hitch", ru="Навеска")
    assert isinstance(t, str) and t == "Hitch" and t.upper() == "HITCH"
    assert {"Hitch": 1}[t] == 1  # hashes as its string
    assert [localize(t, lang) for lang in LANGS] == ["Hitch", "Навеска"]
    assert localize(t, "de") == "Hitch"
    for again in (pickle.loads(pickle.dumps(t)), copy.deepcopy(t)):
        assert type(again) is Text and again.translations == {"ru": "Навеска"}
    # a name in a message is its identifying string (f"{name!r}": 'Hitch')
    assert repr(t) == "'Hitch'" and t.translations == {"ru": "Навеска"}


def test_text_from_strings_and_mappings():
    assert text("plain") == "plain" and localize(text("plain"), "ru") == "plain"
    t = text({"ru": "Навеска", "en": "Hitch", "de": None})
    assert t == "Hitch" and t.translations == {"ru": "Навеска"}
    assert text({"ru": "Только"}) == "Только"
    with pytest.raises(ValueError, match="at least one language"):
        text({"en": None})


def test_a_model_files_title_in_two_languages_reaches_the_mechanism():
    src = io.bundled("hitch_003").read_text(encoding="utf-8")
    model = io.loads(src, name="hitch.toml")
    title = model.mechanism.title
    assert isinstance(title, Text) and title.translations.get("ru")
    assert localize(title, "ru") != localize(title, "en")
