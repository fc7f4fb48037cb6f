import numpy as np
import pytest


@pytest.fixture(autouse=True)
def isolated_cache(tmp_path, monkeypatch):
    """Every test gets its own empty basis cache."""
    monkeypatch.setenv("EIGENDANCE_CACHE_DIR", str(tmp_path / "cache"))


@pytest.fixture
def rng():
    return np.random.default_rng(7)
