"""What a model's look costs (issue 23 item 9): per shared textured model and rig, with its
materials against the clay studio look, measured in the same run:

1. the page in headless Chromium (SwiftShader): frames per second of the gallery (8 tiles, or
   the rig's gallery of modes) and of the player while the music plays, materials on and off
   (`?test`, `window.eigendance.setMaterials`);
2. `render_video` (moderngl on llvmpipe, two workers, H.264): seconds of video per second, and
   CPU time per frame, at 1280×720, 30 fps;
3. the glb export: bytes with the look (materials, UVs, embedded images) against without.

Not run by CI. The machine is shared: the load (`uptime`) is printed beside the figures.

    python benchmarks/bench_look.py [--seconds 6] [--no-browser] [--models NAME ...]
"""

from __future__ import annotations

import argparse
import os
import resource
import sys
import tempfile
import time

from shared_data import shared_path

WIDTH, HEIGHT, FPS = 1280, 720, 30.0
MODELS = {  # name: (path, rig?)
    "cake (glb, 7 materials)": (shared_path("textured", "kenney_cakeBirthday.glb"), False),
    "speeder (.gltf + .bin)": (shared_path("textured", "craft_speederD.gltf"), False),
    "MorphStressTest (3 textures)": (shared_path("textured", "MorphStressTest.gltf"), False),
    "robot (OBJ + MTL)": (shared_path("textured", "robot.obj"), False),
    "Character_Gun (rig, gun)": (shared_path("rigged", "quaternius_Character_Gun.glb"), True),
    "Astronaut (rig, Draco, texture)": (
        shared_path("rigged", "quaternius_Astronaut_FinnTheFrog.glb"), True),
    "Fox (rig, texture)": (shared_path("rigged", "Fox.glb"), True),
    "CesiumMan (rig, texture)": (shared_path("rigged", "CesiumMan.glb"), True),
}
K = 60


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=6.0, help="song length")
    parser.add_argument("--no-browser", action="store_true")
    parser.add_argument("--models", nargs="*", help="names (first words) to run")
    args = parser.parse_args()

    from eigendance.music.demo_music import write_demo_wav

    folder = tempfile.mkdtemp(prefix="bench-look-")
    song = os.path.join(folder, "demo.wav")
    write_demo_wav(song, duration=args.seconds)
    chosen = {name: value for name, value in MODELS.items()
              if not args.models or name.split()[0] in args.models}
    print(f"load: {os.getloadavg()[0]:.1f} {os.getloadavg()[1]:.1f} (cpu count "
          f"{os.cpu_count()}); video {WIDTH}x{HEIGHT} at {FPS:g} fps, {args.seconds:g} s song")
    for name, (path, rig) in chosen.items():
        if not os.path.exists(path):
            print(f"{name}: {path} missing, skipped")
            continue
        dance = rig_dance_of(path, song) if rig else harmonic_dance_of(path, song)
        print(f"{name}: {dance.appearance.describe() if dance.appearance else 'no look'}")
        if not args.no_browser:
            page = page_fps(path, song, rig)
            print(f"  page fps (materials / clay): gallery {page['gallery'][0]:.1f} / "
                  f"{page['gallery'][1]:.1f}, player {page['player'][0]:.1f} / "
                  f"{page['player'][1]:.1f}")
        for look in (True, False):
            speed, cpu = video_speed(dance, look, song, folder)
            print(f"  render {'materials' if look else 'clay':<9}: {speed:.2f}× real time, "
                  f"CPU {cpu:.0f} ms per frame")
        with_look, without = glb_sizes(dance, folder)
        print(f"  glb: {with_look / 1e3:.0f} kB with the look, {without / 1e3:.0f} kB without "
              f"({with_look / without:.2f}×)")
    print(f"load after: {os.getloadavg()[0]:.1f}")


def harmonic_dance_of(path: str, song: str):
    from eigendance.export.dance import HarmonicDance
    from eigendance.harmonic.basis import HarmonicBasis
    from eigendance.harmonic.mesh import load_mesh
    from eigendance.music.gallery import strongest_item
    from eigendance.music.spectrogram import Spectrogram

    mesh = load_mesh(path)  # the server's rule: the robust Laplacian for a non-manifold mesh
    laplacian = "robust" if mesh.non_manifold_edge_count() else "cotan"
    basis = HarmonicBasis.from_mesh(mesh, K, laplacian=laplacian)
    spectrogram = Spectrogram.from_file(song)
    return HarmonicDance(basis, spectrogram, strongest_item(basis, spectrogram), song, "bench")


def rig_dance_of(path: str, song: str):
    import numpy as np

    from eigendance.export.rig_dance import rig_dance
    from eigendance.modal.rig import Rig
    from eigendance.modal.sample_rigs import load_rig
    from eigendance.music.spectrogram import Spectrogram

    rig = Rig(load_rig(path), np.float64)  # as the command line builds it
    spectrogram = Spectrogram.from_file(song)
    return rig_dance(rig, spectrogram, rig.mapping(spectrogram, None), "modal", song, "bench")


def cpu_seconds() -> float:
    own, children = (resource.getrusage(who) for who in (resource.RUSAGE_SELF,
                                                          resource.RUSAGE_CHILDREN))
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def video_speed(dance, materials: bool, song: str, folder: str) -> tuple[float, float]:
    """(seconds of video per second, CPU ms per frame) of `render_video`."""
    from eigendance.export.renderer import Look
    from eigendance.export.video import render_video

    before, start = cpu_seconds(), time.perf_counter()
    report = render_video(os.path.join(folder, "video.mp4"), [dance],
                          [Look(materials=materials)], song, FPS, (WIDTH, HEIGHT), force=True)
    seconds = time.perf_counter() - start
    return report["duration"] / seconds, (cpu_seconds() - before) / report["frames"] * 1000


def glb_sizes(dance, folder: str) -> tuple[int, int]:
    """Bytes of the glb with the dance's look, and of the same dance without it."""
    import copy

    from eigendance.export.files import export_dance

    bare = copy.copy(dance)
    bare.appearance = None
    sizes = []
    for each in (dance, bare):
        report = export_dance(each, os.path.join(folder, "dance.glb"), force=True)
        sizes.append(report["bytes"])
    return sizes[0], sizes[1]


def page_fps(path: str, song: str, rig: bool) -> dict:
    """{"gallery": (materials, clay), "player": (materials, clay)} frames per second of the
    page playing the song (browser_look.py)."""
    sys.path.insert(0, os.path.dirname(__file__))
    from browser_look import look_fps

    return look_fps(path, song, rig, K)


if __name__ == "__main__":
    main()
