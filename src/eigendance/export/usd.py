"""USD of a dance (usd-core): a mesh with time-sampled points (docs/design.md#exports).

The stage has timeCodesPerSecond = framesPerSecond = fps, so time code i is frame i, the dance at
i/fps; /Dance (the default prim, an Xform) holds /Dance/Mesh (UsdGeom.Mesh: triangles, the rest
points as the default value, then points and extent at every time code) and, when the song is
known, /Dance/Song (UsdMedia.SpatialAudio, non-spatial, from time code 0) naming the song file
written beside it. Units are the model file's (metersPerUnit 1 is declared, as the source files
carry no unit); upAxis Y, as glTF and the player use. Any dance (harmonics, either skinning of a
rig) is exact here: the points are the reference positions. A dance with a look keeps it
(`usd_look`: UsdPreviewSurface materials per subset, the textures as files beside the stage).
"""

from __future__ import annotations

import numpy as np
from pxr import Gf, Sdf, Usd, UsdGeom, UsdMedia, Vt

from eigendance.export.dance import Dance
from eigendance.export.usd_look import bind_look


def write_usd(path: str, dance: Dance, times, fps: float, song: str | None = None,
              progress=None, textures: list[str] = ()) -> None:
    """Write the USD stage of `dance` at `times` (time code i = times[i]·fps) to `path`.

    Parameters
    ----------
    path : the file to create (.usd or .usdc binary, .usda text; the suffix picks the format).
    dance : the motion.
    times : (T,) sample times i/fps.
    fps : frames per second (timeCodesPerSecond).
    song : the song's file name relative to `path`'s folder, or None.
    progress : optional callable(frames done).
    textures : the image files of the dance's look, written beside `path` (`usd_look`).
    """
    times = np.asarray(times, dtype=np.float64)
    layer = Sdf.Layer.CreateNew(path)
    stage = Usd.Stage.Open(layer)
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.y)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    stage.SetTimeCodesPerSecond(fps)
    stage.SetFramesPerSecond(fps)
    stage.SetStartTimeCode(0)
    stage.SetEndTimeCode(max(0, len(times) - 1))
    root = UsdGeom.Xform.Define(stage, "/Dance")
    stage.SetDefaultPrim(root.GetPrim())
    mesh = UsdGeom.Mesh.Define(stage, "/Dance/Mesh")
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    mesh.CreateDoubleSidedAttr(True)
    look = dance.appearance
    faces = dance.faces if look is None else look.welded[look.triangles]
    mesh.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(
        np.full(len(faces), 3, dtype=np.int32)))
    mesh.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(faces.astype(np.int32).ravel()))
    points = mesh.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(dance.rest.astype(np.float32)))
    extent = mesh.CreateExtentAttr(_extent(dance.rest))
    if look is None:
        mesh.CreateDisplayColorAttr(Vt.Vec3fArray([Gf.Vec3f(0.91, 0.66, 0.49)]))
    else:
        bind_look(stage, mesh, look, list(textures))
    for first, positions, _ in dance.frames(times):
        for offset, frame in enumerate(positions):  # USD sets one time sample per call
            code = Usd.TimeCode(round(times[first + offset] * fps, 6))
            points.Set(Vt.Vec3fArray.FromNumpy(np.ascontiguousarray(frame)), code)
            extent.Set(_extent(frame), code)
        if progress is not None:
            progress(first + len(positions))
    if song is not None:
        audio = UsdMedia.SpatialAudio.Define(stage, "/Dance/Song")
        audio.CreateFilePathAttr(Sdf.AssetPath(song))
        audio.CreateAuralModeAttr(UsdMedia.Tokens.nonSpatial)
        # startTime 0 and endTime before it (the defaults): play the whole song from frame 0.
    layer.documentation = (f"eigendance: {dance.name} dancing, {len(times)} frames at {fps:g} "
                           "fps")
    layer.Save()


def _extent(points: np.ndarray) -> Vt.Vec3fArray:
    return Vt.Vec3fArray.FromNumpy(np.stack([points.min(axis=0), points.max(axis=0)])
                                   .astype(np.float32))

