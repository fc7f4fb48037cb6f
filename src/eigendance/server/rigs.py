"""Rig items: analysed when first asked for, edited, reset (docs/design.md#server).

The built-in rigs are listed from the start and analysed on first use; a skeleton JSON, or a
glTF file with a skin (which is also a mesh), is analysed when added. Each rig item keeps its
original skeleton and the current `Rig` (stiffness and rest-pose edits); every edit changes the
current rig's skeleton (`Skeleton.with_stiffness`, `Skeleton.rotate_joint`), analyses it anew
and makes its bundle (`analysis.analyse_rig`, in a worker process: `workers.run`), and
bumps the revision. A failed edit leaves the item as it was.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from eigendance.errors import EigendanceError, InputError
from eigendance.modal.skeleton import Skeleton
from eigendance.modal.skinning import skin_bytes
from eigendance.server import analysis
from eigendance.server.items import RigItem

Run = Callable[..., object]


def direct(function, *args, seconds: float | None = None):
    """function(*args) here, in this thread: the `run` of a caller without worker processes.

    Parameters
    ----------
    function : what to call.
    *args : its arguments.
    seconds : the deadline a worker process would have (here there is none to kill).

    Returns
    -------
    Its result.
    """
    return function(*args)


def planned_bytes(skeleton: Skeleton) -> int:
    """The memory analysing a skeleton may take at its peak: its modal skin (`skin_bytes`)
    with at most 6 modes per body; charged to the library's budget before the analysis.

    Parameters
    ----------
    skeleton : a skeleton with its skin.

    Returns
    -------
    int, bytes.
    """
    vertices = 0 if skeleton.vertices is None else len(skeleton.vertices)
    return skin_bytes(vertices, 6 * skeleton.n_bodies)


def analyse(item: RigItem, skeleton: Skeleton, run: Run = direct,
            original: Skeleton | None = None, dtype=np.float32) -> None:
    """Give the item the rig of a skeleton and its bundle (`analysis.analyse_rig`, through
    `run`); set them (and the revision) only when the bundle is made.

    Parameters
    ----------
    item : the rig item.
    skeleton : the skeleton (loaded, or edited).
    run : how to call the analysis: `Library.run` (in a worker process), or `direct`.
    original : the skeleton as loaded (None: this one).
    dtype : the modal skin's precision.
    """
    edited = original is not None and skeleton is not original  # a reset is not an edit
    rig, bundle = run(analysis.analyse_rig, skeleton, np.dtype(dtype).str, item.name,
                      item.revision + (item.rig is not None), edited)
    item.original = original or rig.skeleton
    item.revision += item.rig is not None
    item.rig, item.bundle, item.edited = rig, bundle, edited


def ready(item: RigItem, public: Callable[[str], str], run: Run = direct) -> RigItem:
    """The item analysed (a built-in rig is analysed on first use, a file again after its
    analysis was forgotten).

    Parameters
    ----------
    item : the rig item.
    public : a message → the message as the page may see it (`Library.public`).
    run : how to call the analysis (`analyse`).

    Returns
    -------
    The item; InputError (409) when it could not be analysed, with the reason.
    """
    with item.lock:
        if item.rig is None and not item.error:
            try:
                analyse(item, run(analysis.read_rig, item.source, item.name,
                                  item.origin == "built-in"), run)
            except EigendanceError as error:
                item.error = public(str(error))
        if item.error:
            raise InputError(item.error, status=409)
    return item


def edit(item: RigItem, change: Callable[[Skeleton], Skeleton], run: Run = direct) -> bytes:
    """Apply `change` to the skeleton of the item's current rig and analyse it anew.

    Parameters
    ----------
    item : an analysed rig item (`ready`).
    change : skeleton → edited skeleton (`Skeleton.with_stiffness`, `Skeleton.rotate_joint`,
        or the original: a reset).
    run : how to call the analysis (`analyse`).

    Returns
    -------
    bytes: the new rig bundle; the item is unchanged when `change` or the analysis raises.
    """
    with item.lock:
        analyse(item, change(item.rig.skeleton), run, item.original, item.rig.dtype)
        return item.bundle


def forget(item: RigItem) -> None:
    """Forget a built-in rig's analysis and edits (it stays listed; the memory is freed).

    Parameters
    ----------
    item : a built-in rig item.
    """
    item.original = item.rig = item.bundle = item.look_bundle = None
    item.revision, item.error, item.edited = 0, "", False
