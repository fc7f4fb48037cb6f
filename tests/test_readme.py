"""README.md is the front door: every Python block in it runs as written, each on its own, in
an empty folder (the blocks use the built-in data: the demo cat, the demo music, the rigs)."""

import os
import re

import pytest

README = os.path.join(os.path.dirname(__file__), "..", "README.md")


def python_blocks() -> list[str]:
    with open(README, encoding="utf-8") as file:
        return re.findall(r"^```python\n(.*?)^```", file.read(), flags=re.M | re.S)


def test_the_readme_shows_python():
    assert len(python_blocks()) >= 3


@pytest.fixture(scope="module")
def cache(tmp_path_factory):
    """One basis cache for the blocks, as a reader's machine has: the cat is solved once."""
    return str(tmp_path_factory.mktemp("readme-cache"))


@pytest.mark.parametrize("index", range(len(python_blocks())))
def test_each_python_block_of_the_readme_runs(index, tmp_path, monkeypatch, cache):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("EIGENDANCE_CACHE_DIR", cache)
    block = python_blocks()[index]
    namespace = {"__name__": f"readme_block_{index}"}
    exec(compile(block, f"README.md python block {index + 1}", "exec"), namespace)  # noqa: S102
