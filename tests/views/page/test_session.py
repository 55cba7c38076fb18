"""The page's model (:mod:`assur.views.page.session`): the edited model file keeps its
comments and loads as the same model but for the edited values; parameters that are
not finite numbers are refused; the bounds of a request."""

import pytest

from assur.io import bundled
from assur.views.page.session import PageModel


def test_page_model_rejects_non_numbers():
    from assur.errors import ModelError
    pm = PageModel.from_path(bundled("hitch_003"))
    with pytest.raises(ModelError, match="finite number"):
        pm.edited_text({"L5": float("inf")})
    with pytest.raises(ModelError, match="finite number"):
        pm.edited_text({"L5": True})



def test_the_edited_file_keeps_comments_and_loads_as_the_same_model():
    from assur import io
    pm = PageModel.from_path(bundled("hitch_003"))
    text = pm.edited_text({"L5": 0.49})
    original = bundled("hitch_003").read_text(encoding="utf-8")
    comments = [ln for ln in original.splitlines() if ln.lstrip().startswith("#")]
    assert all(c in text for c in comments)
    edited = io.loads(text, name="edited.toml").mechanism
    base = io.load(bundled("hitch_003")).mechanism
    assert edited.params["L5"] == 0.49
    solved = {"L4", "Sp", "L7"}  # solved again from the file's conditions with the new L5
    assert {k: v for k, v in edited.params.items() if k not in solved | {"L5"}} == \
        {k: v for k, v in base.params.items() if k not in solved | {"L5"}}
    assert edited.params["L4"] != base.params["L4"]
    assert pm.load({"L5": 0.49}).mechanism.params["L5"] == 0.49


def test_the_bounds_of_a_request():
    from assur.errors import ModelError
    from assur.views.page.session import MAX_PARAMS, MAX_POSITIONS
    pm = PageModel.from_path(bundled("hitch_003"))
    with pytest.raises(ModelError, match=f"at most {MAX_PARAMS} parameters"):
        pm.check_params({f"p{i}": 1.0 for i in range(MAX_PARAMS + 1)})
    with pytest.raises(ValueError, match=f"positions must be in 2…{MAX_POSITIONS}"):
        pm.compute({}, positions=MAX_POSITIONS + 1)
