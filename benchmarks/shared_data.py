"""Where the benchmarks find the shared test data (meshes, rigs, music), which the repository
does not carry: too large. `shared/data` in a folder above the checkout, or
$EIGENDANCE_SHARED_DATA."""

import os


def _beside_the_checkout() -> str:
    """The first `shared/data` in a folder above the checkout (a worktree sits deeper)."""
    folder = os.path.dirname(os.path.abspath(__file__))
    while os.path.dirname(folder) != folder:
        folder = os.path.dirname(folder)
        if os.path.isdir(os.path.join(folder, "shared", "data")):
            return os.path.join(folder, "shared", "data")
    return os.path.normpath(os.path.join(os.path.dirname(__file__), "..", "..", "shared", "data"))


FOLDER = os.environ.get("EIGENDANCE_SHARED_DATA") or _beside_the_checkout()


def shared_path(*parts: str) -> str:
    """The path of a shared data file, e.g. shared_path("meshes", "bunny_stanford.obj")."""
    return os.path.join(FOLDER, *parts)
