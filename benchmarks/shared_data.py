"""Where the benchmarks find the shared test data (meshes, rigs, music), which the repository
does not carry: too large. `../shared/data` beside the checkout, or $EIGENDANCE_SHARED_DATA."""

import os

FOLDER = os.environ.get("EIGENDANCE_SHARED_DATA") or os.path.normpath(
    os.path.join(os.path.dirname(__file__), "..", "..", "shared", "data"))


def shared_path(*parts: str) -> str:
    """The path of a shared data file, e.g. shared_path("meshes", "bunny_stanford.obj")."""
    return os.path.join(FOLDER, *parts)
