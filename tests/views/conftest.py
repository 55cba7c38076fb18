"""Fixtures of the views' tests: a real headless Chromium for the page and the reports.

Debian's chromium (``$ASSUR_CHROMIUM``, default /usr/bin/chromium, installed by
``make test`` through .ci/chromium.sh) driven by Playwright for Python; Playwright's own
browser builds are never downloaded.
"""

import os
from pathlib import Path

import pytest

CHROMIUM = os.environ.get("ASSUR_CHROMIUM", "/usr/bin/chromium")


@pytest.fixture(scope="module")
def browser():
    """A headless Chromium (one per test module)."""
    if not Path(CHROMIUM).exists():
        pytest.fail(f"{CHROMIUM} is missing: `make test` installs Debian's chromium "
                    f"(.ci/chromium.sh, as root); install it to run the browser tests")
    from playwright.sync_api import sync_playwright
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, headless=True)
        yield b
        b.close()
