"""The page's model (:mod:`assur.views.page.session`): the edited model file keeps its
comments and loads as the same model; parameters that are not finite numbers are
refused; the bounds of a session."""

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

