#!/usr/bin/env python3
"""The web build's freshness stamp: proof that the committed build matches its sources.

The built front end is committed in `src/eigendance/static/` so that a pip install needs no
Node; this stamp makes a stale build detectable without Node. `scripts/web.sh build` runs
`python3 scripts/web_stamp.py write` after `vite build` (whose `emptyOutDir` wipes the folder),
and `tests/web/test_web_build_fresh.py` (or `python3 scripts/web_stamp.py check`) recomputes it.

`src/eigendance/static/build-stamp.json` holds two SHA-256 digests, each over the sorted list of
(path relative to the repository, bytes) of a set of files, every file hashed as
`path (UTF-8) · NUL · length (8 bytes, little-endian) · bytes`:

- `sources`: every file under `web/src/`, the GLSL the page shares with the video
  (`src/eigendance/shaders/*.glsl`), plus `web/index.html`, `web/package-lock.json`,
  `web/package.json`, `web/vite.config.ts` and `web/tsconfig.json`;
- `build`: every file under `src/eigendance/static/` except the stamp itself (catches a build
  edited by hand or committed in part).

Each also lists its files' own SHA-256, so a failed check can say which files changed.
Standard library only.
"""

from __future__ import annotations

import hashlib
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SOURCE_FOLDERS = ("web/src",)
SHADERS = ("src/eigendance/shaders", ".glsl")  # imported by web/src/shaders.ts (`?raw`)
SOURCE_FILES = ("web/index.html", "web/package-lock.json", "web/package.json",
                "web/vite.config.ts", "web/tsconfig.json", "src/eigendance/music/analysis.json")
BUILD_FOLDER = "src/eigendance/static"
STAMP = f"{BUILD_FOLDER}/build-stamp.json"
FORMAT = "eigendance.web-build-stamp"
REMEDY = "run `make web` (or `bash scripts/web.sh build`) and commit src/eigendance/static"


def files_under(root: Path, folder: str) -> list[str]:
    """Relative POSIX paths of every file below `root/folder`, sorted."""
    base = root / folder
    if not base.is_dir():
        return []
    return sorted(path.relative_to(root).as_posix() for path in base.rglob("*") if path.is_file())


def source_paths(root: Path = ROOT) -> list[str]:
    """The files a build is made from (a missing listed file counts as changed, not skipped)."""
    paths = [path for folder in SOURCE_FOLDERS for path in files_under(root, folder)]
    shaders = [path for path in files_under(root, SHADERS[0]) if path.endswith(SHADERS[1])]
    return sorted({*paths, *shaders, *SOURCE_FILES})


def build_paths(root: Path = ROOT) -> list[str]:
    return [path for path in files_under(root, BUILD_FOLDER) if path != STAMP]


def digest(root: Path, paths: list[str]) -> dict:
    """SHA-256 over the sorted (path, bytes) pairs, and each file's own SHA-256."""
    total = hashlib.sha256()
    files = {}
    for path in sorted(paths):
        file = root / path
        data = file.read_bytes() if file.is_file() else b""
        files[path] = hashlib.sha256(data).hexdigest() if file.is_file() else "missing"
        encoded = path.encode("utf-8")
        total.update(encoded + b"\0" + len(data).to_bytes(8, "little") + data)
    return {"sha256": total.hexdigest(), "files": files}


def stamp(root: Path = ROOT) -> dict:
    return {"format": FORMAT, "version": 1,
            "sources": digest(root, source_paths(root)),
            "build": digest(root, build_paths(root))}


def write(root: Path = ROOT) -> Path:
    """Write the stamp of the build now in `src/eigendance/static` (call after `vite build`)."""
    target = root / STAMP
    target.write_text(json.dumps(stamp(root), indent=1, sort_keys=True) + "\n")
    return target


def changed(old: dict, new: dict) -> list[str]:
    """Files added, removed or changed between two digests."""
    before, after = old.get("files", {}), new.get("files", {})
    return sorted(path for path in before.keys() | after.keys()
                  if before.get(path) != after.get(path))


def problems(root: Path = ROOT) -> list[str]:
    """Why the committed build is not the build of the sources here (empty: it is)."""
    target = root / STAMP
    if not target.is_file():
        return [f"{STAMP} is missing: {REMEDY}"]
    try:
        recorded = json.loads(target.read_text())
    except ValueError as problem:
        return [f"{STAMP} is not valid JSON ({problem}): {REMEDY}"]
    if recorded.get("format") != FORMAT:
        return [f"{STAMP} is not a {FORMAT} file: {REMEDY}"]
    now = stamp(root)
    found = []
    for part, what in (("sources", "the web sources changed since the build"),
                       ("build", "the committed build differs from the one stamped")):
        old = recorded.get(part, {})
        if old.get("sha256") != now[part]["sha256"]:
            files = changed(old, now[part]) or ["(file order or names)"]
            shown = ", ".join(files[:8]) + (f" and {len(files) - 8} more" if len(files) > 8 else "")
            found.append(f"{what} ({shown}): {REMEDY}")
    return found


def main(argv: list[str]) -> int:
    if argv[1:] == ["write"]:
        print(f"web: stamped {write().relative_to(ROOT)}")
        return 0
    if argv[1:] == ["check"]:
        found = problems()
        for line in found:
            print(f"web build is stale: {line}", file=sys.stderr)
        return 1 if found else 0
    print("usage: scripts/web_stamp.py write|check", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
