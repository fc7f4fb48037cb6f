"""Rig items: analysed when first asked for, edited, reset (docs/design.md#server).

The built-in rigs are listed from the start and analysed on first use; a skeleton JSON, or a
glTF file with a skin (which is also a mesh), is analysed when added. Each rig item keeps its
original skeleton and the current `Rig` (stiffness and rest-pose edits); every edit asks the
current `Rig` for a new one (`Rig.with_stiffness`, `Rig.rotate_joint`), makes its bundle and
bumps the revision. A failed edit leaves the item as it was.
"""

from __future__ import annotations

from collections.abc import Callable

from eigendance.errors import EigendanceError, InputError
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import load_rig, sample_rig
from eigendance.modal.skeleton import Skeleton
from eigendance.modal.skinning import skin_bytes
from eigendance.server.binary import rig_bundle
from eigendance.server.items import RigItem


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


def analyse(item: RigItem, rig: Rig, original: Skeleton | None = None) -> None:
    """Give the item a rig and its bundle; set them (and the revision) only when the bundle is
    made.

    Parameters
    ----------
    item : the rig item.
    rig : the rig (loaded, or edited).
    original : the skeleton as loaded (None: the rig's own).
    """
    edited = original is not None and rig.skeleton is not original  # a reset is not an edit
    bundle = rig_bundle(rig, item.name, item.revision + (item.rig is not None), edited)
    item.original = original or rig.skeleton
    item.revision += item.rig is not None
    item.rig, item.bundle, item.edited = rig, bundle, edited


def ready(item: RigItem, public: Callable[[str], str]) -> RigItem:
    """The item analysed (a built-in rig is analysed on first use, a file again after its
    analysis was forgotten).

    Parameters
    ----------
    item : the rig item.
    public : a message → the message as the page may see it (`Library.public`).

    Returns
    -------
    The item; InputError (409) when it could not be analysed, with the reason.
    """
    with item.lock:
        if item.rig is None and not item.error:
            try:
                analyse(item, Rig(sample_rig(item.source) if item.origin == "built-in"
                                  else load_rig(item.source, item.name)))
            except EigendanceError as error:
                item.error = public(str(error))
        if item.error:
            raise InputError(item.error, status=409)
    return item


def edit(item: RigItem, change: Callable[[Rig], Rig]) -> bytes:
    """Apply `change` to the item's current rig.

    Parameters
    ----------
    item : an analysed rig item (`ready`).
    change : rig → edited rig (`Rig.with_stiffness`, `Rig.rotate_joint`, …).

    Returns
    -------
    bytes: the new rig bundle; the item is unchanged when `change` raises.
    """
    with item.lock:
        analyse(item, change(item.rig), original=item.original)
        return item.bundle


def forget(item: RigItem) -> None:
    """Forget a built-in rig's analysis and edits (it stays listed; the memory is freed).

    Parameters
    ----------
    item : a built-in rig item.
    """
    item.original = item.rig = item.bundle = item.look_bundle = None
    item.revision, item.error, item.edited = 0, "", False
