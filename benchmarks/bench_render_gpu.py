"""The video renderer's drawing on a real GPU against Mesa's llvmpipe: frames per second.

`render` draws with the page's own GLSL (`eigendance.shaders`) through moderngl on an EGL
context: llvmpipe on a machine without a GPU (this project's), the GPU's driver where there is
one. This benchmark times what the GPU changes, the drawing and the read-back of each frame
(begin + draw + read), without the encoder and without the dance's positions (precomputed), in
two steps so that the GPU machine needs only moderngl and a few small packages:

1. ``prepare OUT.npz`` (here): the bunny (34,834 vertices, k = 300, the strongest item of its
   initial gallery on 20 s of the demo music) and the demo cat (k = 150): 30 frames of their
   positions each, their faces, rest normals and the page's cameras for one view and for a
   3 × 3 gallery.
2. ``draw IN.npz`` (anywhere with an EGL context): 300 frames of each case, one view at
   1280×720 and 1920×1080 and the 9-tile gallery at 1920×1080, in clay; prints frames per
   second and the EGL renderer's name (``GL_RENDERER``), so the figure says which device drew.

Run ``draw`` on the GPU machine and on this one: the ratio of the two is the result (the
figures come from two machines, so each prints the renderer it ran on).

    python benchmarks/bench_render_gpu.py prepare /tmp/frames.npz
    python benchmarks/bench_render_gpu.py draw /tmp/frames.npz [--frames 300]
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np

from shared_data import shared_path

FRAMES = 30  # distinct poses per model, drawn in turn
SIZES = {"1280x720": (1280, 720), "1920x1080": (1920, 1080)}


def prepare(out: str) -> None:
    """Positions, faces, normals and cameras of the cat and the bunny into `out` (npz)."""
    from importlib.resources import files

    from eigendance.export.dance import HarmonicDance
    from eigendance.export.renderer import gallery_cells
    from eigendance.export.video import view_cameras
    from eigendance.harmonic.basis import HarmonicBasis
    from eigendance.music.demo_music import demo_track
    from eigendance.music.gallery import strongest_item
    from eigendance.music.spectrogram import Spectrogram

    song = Spectrogram.from_samples(*demo_track(20.0))
    models = {"cat": (files("eigendance") / "data" / "cat_lowres.obj", 150),
              "bunny": (shared_path("meshes", "bunny_stanford.obj"), 300)}
    arrays = {}
    for name, (path, k) in models.items():
        basis = HarmonicBasis.from_mesh(os.fspath(path), k=k)
        dance = HarmonicDance(basis, song, strongest_item(basis, song))
        times = np.linspace(0.5, 19.5, FRAMES)
        arrays[f"{name}_positions"] = dance.positions(times).astype(np.float32)
        arrays[f"{name}_faces"] = np.asarray(dance.faces, dtype=np.uint32)
        arrays[f"{name}_normals"] = np.asarray(dance.rest_normals(), dtype=np.float32)
        arrays[f"{name}_rest"] = np.asarray(dance.rest, dtype=np.float64)
        arrays[f"{name}_scale"] = np.float64(dance.scale)
        for size, (width, height) in SIZES.items():
            one = view_cameras([dance], [(0, 0, width, height)])[0]
            arrays[f"{name}_{size}_view"], arrays[f"{name}_{size}_projection"] = \
                one.view, one.projection
        cells = gallery_cells(9, 1920, 1080)
        cameras = view_cameras([dance] * 9, cells)
        arrays[f"{name}_gallery_cells"] = np.array(cells)
        arrays[f"{name}_gallery_view"] = np.stack([c.view for c in cameras])
        arrays[f"{name}_gallery_projection"] = np.stack([c.projection for c in cameras])
    np.savez_compressed(out, **arrays)
    print(f"wrote {out} ({os.path.getsize(out) / 1e6:.1f} MB)")


def _time(renderer, frames: int, draws) -> float:
    """Frames per second of `frames` frames of begin + draws + read (3 warm-up frames)."""
    for index in range(frames + 3):
        if index == 3:
            start = time.perf_counter()
        draws(index)
        renderer.read()
    return frames / (time.perf_counter() - start)


def draw(path: str, frames: int) -> None:
    """Time the renderer on the poses in `path` (module docstring) and print a table."""
    from eigendance.export.renderer import Camera, Look, Renderer

    data = np.load(path)
    look = Look(materials=False)
    renderer_name = None
    print(f"{'case':<34} {'frames/s':>9} {'ms/frame':>9}")
    for name in ("cat", "bunny"):
        positions = data[f"{name}_positions"]
        n = positions.shape[1]
        for size, (width, height) in [*SIZES.items(), ("gallery 9 × 1920x1080", (1920, 1080))]:
            renderer = Renderer(width, height, data[f"{name}_faces"], data[f"{name}_normals"],
                                data[f"{name}_rest"], float(data[f"{name}_scale"]))
            renderer_name = renderer.context.info["GL_RENDERER"]
            if size in SIZES:
                cells = [(0, 0, width, height)]
                cameras = [Camera(data[f"{name}_{size}_view"], data[f"{name}_{size}_projection"])]
            else:
                cells = [tuple(int(v) for v in cell) for cell in data[f"{name}_gallery_cells"]]
                cameras = [Camera(view, projection) for view, projection in
                           zip(data[f"{name}_gallery_view"], data[f"{name}_gallery_projection"],
                               strict=True)]

            def one(index, renderer=renderer, cells=cells, cameras=cameras,
                    positions=positions):
                renderer.begin(cells)
                for tile, (cell, camera) in enumerate(zip(cells, cameras, strict=True)):
                    renderer.draw(positions[(index + tile) % len(positions)], camera, look, cell)

            rate = _time(renderer, frames, one)
            renderer.release()
            print(f"{name + f' ({n:,} v) ' + size:<34} {rate:9.1f} {1000 / rate:9.2f}")
    print(f"GL_RENDERER: {renderer_name}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="step", required=True)
    sub.add_parser("prepare").add_argument("out")
    drawing = sub.add_parser("draw")
    drawing.add_argument("path")
    drawing.add_argument("--frames", type=int, default=300)
    args = parser.parse_args()
    if args.step == "prepare":
        prepare(args.out)
    else:
        draw(args.path, args.frames)


if __name__ == "__main__":
    main()
