"""Keyframes, the song's strip and the scene's timing, the same in Blender 4.2 and 5.0.

Blender 5.0 keeps keyframes in layered actions (`action.layers[…].strips[…].channelbag(slot)
.fcurves`; `Action.fcurves` is gone), 4.2 in `action.fcurves`: a curve is made by
`keyframe_insert` (which makes the action, its slot and its layer in either) and then found
where that version keeps it; its samples are written at once (`foreach_set`).
"""

import os

import numpy as np

SONG_STRIP = "eigendance song"


def fcurves_of(owner):
    """The F-curves of an ID's action, wherever this Blender keeps them.

    Parameters
    ----------
    owner : an ID with animation data (an object, a shape-key block).

    Returns
    -------
    a collection of F-curves (find, remove), or () without an action.
    """
    animation = owner.animation_data
    action = animation.action if animation else None
    if action is None:
        return ()
    if getattr(action, "layers", None):  # a layered action (Blender 4.4 and later)
        slot = getattr(animation, "action_slot", None)
        for layer in action.layers:
            for strip in layer.strips:
                bag = strip.channelbag(slot) if slot is not None else None
                if bag is not None:
                    return bag.fcurves
        return ()
    return action.fcurves


def fresh_action(owner, name: str) -> None:
    """Detach the ID's current action (kept in the file) so that the keys go into a new one.

    Parameters
    ----------
    owner : an ID.
    name : the new action's name (set by `name_action` once it exists).
    """
    if owner.animation_data is not None:
        owner.animation_data.action = None
    owner["eigendance_action"] = name


def name_action(owner) -> None:
    """Name the ID's new action as `fresh_action` asked.

    Parameters
    ----------
    owner : an ID.
    """
    animation = owner.animation_data
    if animation is not None and animation.action is not None and "eigendance_action" in owner:
        animation.action.name = owner["eigendance_action"]
        del owner["eigendance_action"]


def key_samples(owner, target, prop: str, index: int, frames, values) -> None:
    """Keyframe `target.prop[index]` at every frame, linear between them.

    Parameters
    ----------
    owner : the ID that holds the action (an object, a shape-key block).
    target : the struct keyed (the ID, a pose bone, a shape key).
    prop : the property's name.
    index : its component (-1 for a number).
    frames : (T,) frame numbers, increasing.
    values : (T,) the values.
    """
    target.keyframe_insert(prop, index=index, frame=float(frames[0]))
    path = target.path_from_id(prop)
    curve = fcurves_of(owner).find(path, index=max(index, 0))
    points = curve.keyframe_points
    points.add(len(frames) - len(points))
    samples = np.empty(2 * len(frames), dtype=np.float32)
    samples[0::2], samples[1::2] = frames, values
    points.foreach_set("co", samples)
    for point in points:
        point.interpolation = "LINEAR"
    curve.update()


def set_timing(scene, fps: int, count: int) -> tuple[int, int]:
    """The scene plays `count` samples at `fps` from its start frame.

    Parameters
    ----------
    scene : the scene.
    fps : frames per second.
    count : samples.

    Returns
    -------
    (first, last) frame.
    """
    scene.render.fps, scene.render.fps_base = int(fps), 1.0
    first = scene.frame_start
    scene.frame_end = first + max(count, 1) - 1
    scene.sync_mode = "AUDIO_SYNC"  # play keeps to the song
    return first, scene.frame_end


def strips_of(editor):
    """The sequencer's strips: `strips_all`/`strips` in 5.0, `sequences_all`/`sequences` in 4.2.

    Parameters
    ----------
    editor : scene.sequence_editor.

    Returns
    -------
    (every strip, the top level collection).
    """
    if hasattr(editor, "strips_all"):
        return editor.strips_all, editor.strips
    return editor.sequences_all, editor.sequences


def add_song(scene, song: str, start: float, fps: int):
    """The song as a sound strip from the scene's start frame, playing from `start` s.

    Parameters
    ----------
    scene : the scene.
    song : the audio file.
    start : where in the song the dance starts, s (a whole number of frames).
    fps : frames per second.

    Returns
    -------
    the strip, or None when Blender cannot read the file (the dance is baked anyway).
    """
    editor = scene.sequence_editor or scene.sequence_editor_create()
    every, top = strips_of(editor)
    for strip in list(every):
        if strip.name.startswith(SONG_STRIP):
            top.remove(strip)
    skip = int(round(start * fps))
    first = scene.frame_start
    try:
        strip = top.new_sound(SONG_STRIP, os.path.abspath(song), 1, first - skip)
    except (RuntimeError, TypeError):
        return None
    if skip:
        strip.frame_offset_start = skip
    return strip
