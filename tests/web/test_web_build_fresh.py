"""The committed web build (src/eigendance/static) is the build of the sources in web/: the
stamp written by `scripts/web.sh build` (scripts/web_stamp.py) still matches. Needs no Node."""

from __future__ import annotations

import importlib.util
import json
import shutil
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def load_web_stamp():
    spec = importlib.util.spec_from_file_location("web_stamp", ROOT / "scripts" / "web_stamp.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


web_stamp = load_web_stamp()


def test_committed_web_build_is_fresh():
    problems = web_stamp.problems(ROOT)
    assert not problems, "the committed web build is stale:\n" + "\n".join(problems)


def copy_of_the_inputs(tmp_path: Path) -> Path:
    """The stamped files of the repository, copied to a scratch root."""
    stamp = json.loads((ROOT / web_stamp.STAMP).read_text())
    for part in ("sources", "build"):
        for path in stamp[part]["files"]:
            (tmp_path / path).parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(ROOT / path, tmp_path / path)
    shutil.copyfile(ROOT / web_stamp.STAMP, tmp_path / web_stamp.STAMP)
    return tmp_path


def test_a_changed_source_or_lock_file_or_build_is_reported_with_the_remedy(tmp_path):
    root = copy_of_the_inputs(tmp_path)
    assert web_stamp.problems(root) == []
    (root / "web/src/main.ts").write_text("// edited after the build\n", encoding="utf-8")
    (root / "web/package-lock.json").write_bytes(b"{}")
    (root / "web/src/extra.ts").write_text("export {};\n", encoding="utf-8")
    problems = web_stamp.problems(root)
    assert len(problems) == 1 and "make web" in problems[0]
    for path in ("web/src/main.ts", "web/package-lock.json", "web/src/extra.ts"):
        assert path in problems[0]
    web_stamp.write(root)
    assert web_stamp.problems(root) == []
    (root / "src/eigendance/static/index.html").write_text("edited by hand", encoding="utf-8")
    problems = web_stamp.problems(root)
    assert len(problems) == 1 and "index.html" in problems[0] and "make web" in problems[0]
    (root / web_stamp.STAMP).unlink()
    assert "missing" in web_stamp.problems(root)[0]


def test_the_digest_is_over_sorted_path_and_bytes_pairs(tmp_path):
    (tmp_path / "b").write_bytes(b"1")
    (tmp_path / "a").write_bytes(b"2")
    digest = web_stamp.digest(tmp_path, ["b", "a"])
    assert digest == web_stamp.digest(tmp_path, ["a", "b"])
    (tmp_path / "a").write_bytes(b"2 ")
    assert web_stamp.digest(tmp_path, ["a", "b"])["sha256"] != digest["sha256"]
    # the path and length framing keeps ("a", "bc") apart from ("ab", "c")
    (tmp_path / "a").write_bytes(b"bc")
    (tmp_path / "ab").write_bytes(b"c")
    sha256 = [web_stamp.digest(tmp_path, [path])["sha256"] for path in ("a", "ab")]
    assert sha256[0] != sha256[1]
