"""docs/design.md is the reference: every citation of it points at a section that exists."""

import glob
import os
import re

ROOT = os.path.join(os.path.dirname(__file__), "..")
DESIGN = os.path.join(ROOT, "docs", "design.md")
SOURCES = ["src/eigendance/**/*.py", "tests/**/*.py", "tests/**/*.mjs", "benchmarks/*.py",
           "web/src/**/*.ts", "web/test/**/*.ts", "docs/*.md", "README.md"]


def slug(heading: str) -> str:
    """GitHub's anchor of a Markdown heading."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def anchors() -> set[str]:
    with open(DESIGN, encoding="utf-8") as file:
        return {slug(line.lstrip("#")) for line in file if line.startswith("#")}


def source_files():
    for pattern in SOURCES:
        yield from glob.glob(os.path.join(ROOT, pattern), recursive=True)


def test_every_citation_of_the_design_names_a_section():
    known = anchors()
    cited = {}
    for path in source_files():
        with open(path, encoding="utf-8") as file:
            for anchor in re.findall(r"design\.md#([\w\-]+)", file.read()):
                cited.setdefault(anchor, os.path.relpath(path, ROOT))
    missing = {anchor: where for anchor, where in cited.items() if anchor not in known}
    assert not missing, f"citations of missing sections: {missing}"
    assert len(cited) >= 20


def test_no_code_cites_the_old_brief():
    stale = []
    for path in source_files():
        with open(path, encoding="utf-8") as file:
            if re.search("DESIGN" + r"(\.md)? ?§", file.read()):
                stale.append(os.path.relpath(path, ROOT))
    assert not stale, f"citations of the old brief left in {stale}"


def test_the_design_states_the_departures_from_the_thesis():
    assert "departures-from-the-thesis" in anchors()
    for section in ("mesh", "laplacian", "eigensolver", "basis", "filter", "spectrogram",
                    "mapping", "gallery", "breeding", "modal-model", "modal-motion", "skinning",
                    "basis-file", "mapping-file", "skeleton-file", "modal-file", "cli"):
        assert section in anchors(), section
