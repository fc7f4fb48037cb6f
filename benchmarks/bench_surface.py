"""The whole body dances (issue 33, docs/design.md#surface-of-a-rig): a rig's skin ripples in its
harmonics while its bones sway. For every shared rig, on a real song:

1. the skin's basis (k = 100; its solve time, from the cache when it is there);
2. the tearing statistic of issue 23 (`harmonic.contacts.part_drift`, ≤ 0.3 must hold) of the
   whole body's motion (linear blend skinning of x + d), for each of the 4 initial-gallery items
   of the skin, beside the bones alone, and of the ripple alone;
3. the surface's share of the motion (`modal.surface.surface_share`) at gains 0.25 … 4 of the
   item that moves the skin most;
4. the cost per frame of the skin's positions (modal skinning, as `render` and `animate-rig` ask
   them; linear blend skinning, as the glb plays) with and without the surface, and of
   `render` (the video, 640×360, frames + encoding), with and without the surface, in the same
   run;
5. with --page: the page's rig player (headless Chromium, `browser_surface.py`): ms per frame
   with the surface off and on, in modal skinning and in the LBS view.

    EIGENDANCE_SHARED_DATA=/work/shared/data python benchmarks/bench_surface.py
        [--song kevin_macleod_vibe_ace.ogg] [--frames 120] [--seconds 8] [--no-render] [--page]
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time

import numpy as np

from shared_data import shared_path

RIGS = ["Fox.glb", "CesiumMan.glb", "quaternius_Character_Gun.glb",
        "quaternius_Astronaut_FinnTheFrog.glb", "quaternius_men_Casual.glb",
        "quaternius_Horse.glb", "quaternius_Wolf.glb", "quaternius_Triceratops.glb"]
GAINS = (0.25, 0.5, 1.0, 2.0, 4.0)


def per_frame(function, frames: int, repeat: int = 3) -> float:
    """The best of `repeat` runs of function(), in ms per frame."""
    best = np.inf
    for _ in range(repeat):
        began = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - began)
    return 1000 * best / frames


def measure(name, song, song_path, frames, seconds, render):
    from eigendance.export.renderer import Look
    from eigendance.export.rig_dance import rig_dance
    from eigendance.export.video import render_video
    from eigendance.harmonic.contacts import part_drift
    from eigendance.modal.rig import Rig
    from eigendance.modal.sample_rigs import load_rig
    from eigendance.modal.surface import SurfaceDance, surface_share
    from eigendance.music.gallery import gallery_motion, initial_gallery

    rig = Rig(load_rig(shared_path("rigged", name)), np.float32)
    rig.skin  # noqa: B018 - the modal skin, made before anything is timed
    rest, faces = rig.skeleton.vertices, rig.skeleton.faces
    began = time.perf_counter()
    harmonics = rig.surface()
    solve = time.perf_counter() - began
    times = np.linspace(0, song.duration - 0.1, frames)
    mapping = rig.mapping(song, None)
    c = rig.coefficients(song, mapping, times)
    bones = rig.positions(c, "lbs")
    items = initial_gallery(harmonics.basis, song, 4)
    drift = [part_drift(rest, faces, bones - rest)]
    ripple_drift = []
    for item in items:
        d = SurfaceDance(harmonics, song, item).displacements(times)
        drift.append(part_drift(rest, faces, rig.positions(c, "lbs", surface=d) - rest))
        ripple_drift.append(part_drift(rest, faces, d))
    strongest = items[int(np.argmax([m.motion for m in gallery_motion(harmonics.basis, song,
                                                                      items)]))]
    shares = []
    for gain in GAINS:
        strongest.gain = gain
        d = SurfaceDance(harmonics, song, strongest).displacements(times)
        shares.append(surface_share(bones, rig.positions(c, "lbs", surface=d), rest))
    strongest.gain = 1.0
    d = SurfaceDance(harmonics, song, strongest).displacements(times)
    cost = {"modal": per_frame(lambda: rig.positions(c, "modal"), frames),
            "modal + surface": per_frame(lambda: rig.positions(
                c, "modal", SurfaceDance(harmonics, song, strongest).displacements(times)),
                frames),
            "lbs": per_frame(lambda: rig.positions(c, "lbs"), frames),
            "lbs + surface": per_frame(lambda: rig.positions(
                c, "lbs", SurfaceDance(harmonics, song, strongest).displacements(times)),
                frames)}
    line = (f"{name}: {len(rest)} vertices, {rig.model.n_bodies} bodies, basis k = "
            f"{harmonics.k} in {solve:.2f} s; drift bones {drift[0]:.3f}, whole body "
            f"{' '.join(f'{x:.3f}' for x in drift[1:])}, ripple alone "
            f"{' '.join(f'{x:.3f}' for x in ripple_drift)}; share at gains "
            f"{', '.join(f'{g:g}: {s:.0%}' for g, s in zip(GAINS, shares, strict=True))}; "
            f"ms/frame {', '.join(f'{k} {v:.3f}' for k, v in cost.items())}")
    if render:
        dance = rig_dance(rig, song, mapping, "modal", song_path, "bench", duration=seconds)
        with_surface = rig_dance(rig, song, mapping, "modal", song_path, "bench",
                                 duration=seconds,
                                 surface=SurfaceDance(harmonics, song, strongest))
        folder = tempfile.mkdtemp(prefix="bench-surface-")
        spent = {}
        for label, each in (("render", dance), ("render + surface", with_surface)):
            began = time.perf_counter()
            result = render_video(os.path.join(folder, f"{label}.mp4"), [each], [Look()],
                                  song_path, 30.0, (640, 360), workers=1)
            spent[label] = 1000 * (time.perf_counter() - began) / result["frames"]
        line += "; " + ", ".join(f"{k} {v:.1f} ms/frame" for k, v in spent.items())
    print(line, flush=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--song", default="kevin_macleod_vibe_ace.ogg")
    parser.add_argument("--frames", type=int, default=120)
    parser.add_argument("--seconds", type=float, default=8.0, help="video length for render")
    parser.add_argument("--no-render", action="store_true")
    parser.add_argument("--rigs", nargs="*", default=RIGS)
    parser.add_argument("--page", action="store_true", help="only the page's player")
    args = parser.parse_args()
    if args.page:
        from browser_surface import player_ms

        for name, value in player_ms([shared_path("rigged", r) for r in args.rigs]).items():
            print(f"page {name}: {value}", flush=True)
        return

    from eigendance.music.spectrogram import Spectrogram

    song_path = shared_path("audio", args.song)
    song = Spectrogram.from_file(song_path)
    for name in args.rigs:
        measure(name, song, song_path, args.frames, args.seconds, not args.no_render)


if __name__ == "__main__":
    main()
