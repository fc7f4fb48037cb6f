import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "web"))

from chromium import CHROMIUM, launch  # noqa: E402 - after its folder is on the path

from helpers import required  # noqa: E402


@pytest.fixture(autouse=True)
def isolated_cache(tmp_path, monkeypatch):
    """Every test gets its own empty basis cache."""
    monkeypatch.setenv("EIGENDANCE_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setenv("EIGENDANCE_PRESETS_DIR", str(tmp_path / "presets"))


@pytest.fixture
def rng():
    return np.random.default_rng(7)


@pytest.fixture(scope="session")
def browser():
    """Headless Chromium (/usr/bin/chromium), one per session: Playwright's sync API allows one
    instance per thread, so tests/web and tests/export share it."""
    required("Chromium", os.path.exists(CHROMIUM), f"at {CHROMIUM}: make system")
    from playwright.sync_api import sync_playwright  # heavy: only for the browser tests

    with sync_playwright() as playwright:
        launched = launch(playwright.chromium)
        yield launched
        launched.close()
