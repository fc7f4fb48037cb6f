"""Table 7.2 of the thesis, reproduced: articulated models in a gallery of NM tiles.

    python benchmarks/bench_rigs.py [--frames 30] [--browser fps.json]

For every built-in rig and every shared rig (benchmarks/shared_data.py, rigged/*.glb) it prints
bodies, vertices, vibration modes, the time to load the file, the preprocessing time (the modal
analysis alone, then with the modal-skin precomputation: `Rig.from_skeleton`) and the Python time
per frame of a mode gallery of NM tiles (tile i plays mode i alone at its default amplitude:
coefficients, then modal skinning of every tile in one float32 product, on one BLAS thread as a
page has), for NM = 1, 9 (the thesis's "9 to 15 modes") and every mode. Baselines measured in
the same run: the naive modal analysis of bench_modal.py (per-joint Python assembly, scipy
null_space and eigh) for the preprocessing, and linear blend skinning of the exact body
transforms (the obvious per-frame path) for the frames. Beside them, the thesis's figures
(3.06 GHz CPU, GeForce GT 130, 1024×768 window): zebra 572 v, 23 modes, 0.021 s; laço 576 v,
13 modes, 0.055 s; mão 762 v, 19 modes, 0.024 s; smurf 32168 v, 36 modes, 0.029 s; CPU NM = 1
≈ 3.7 fps, GPU NM = 1 ≈ 13.6 fps (smurf 4.7). Our counterparts: laço = loop16 (the thesis's 13
modes), mão = hand, zebra ≈ quaternius_Horse (a quadruped), smurf ≈ quaternius_men_Casual (a
humanoid).

Browser frames per second (the page's modal skinning on the GPU with NM tiles, drawn) are
measured in headless Chromium with --measure-browser (browser_rigs.py: WebGL without a GPU here,
SwiftShader), or given with --browser, a JSON file {"rig name": {"1": fps, "9": fps}} (rig names
as printed); they fill the last columns ("—" otherwise).
"""

from __future__ import annotations

import argparse
import glob
import json
import os
import time

import numpy as np
from threadpoolctl import threadpool_limits

from bench_modal import baseline_modal, best_of
from browser_rigs import browser_fps
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import body_transforms, mode_coefficients
from eigendance.modal.palette import default_phases, mode_reach, single_mode_amplitudes
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import SAMPLE_RIGS, load_rig
from eigendance.modal.skinning import ModalSkin, linear_blend_skinning
from shared_data import shared_path

# Thesis Table 7.2: vertices, modes, preprocessing (s), CPU fps NM = 1, GPU fps NM = 1.
THESIS = {"zebra": (572, 23, 0.021, 3.718, 13.727), "laço": (576, 13, 0.055, 3.717, 13.59),
          "mão": (762, 19, 0.024, 3.707, 14.1), "smurf": (32168, 36, 0.029, 3.826, 4.74)}
COUNTERPART = {"loop16": "laço", "hand": "mão", "quaternius_Horse.glb": "zebra",
               "quaternius_men_Casual.glb": "smurf"}
GALLERIES = (1, 9)


def rigs():
    """(name, loader) of the built-in rigs and the shared rigged files."""
    found = [(name, lambda n=name: load_rig(n)) for name in SAMPLE_RIGS]
    for path in sorted(glob.glob(shared_path("rigged", "*.glb"))):
        found.append((os.path.basename(path), lambda p=path: load_rig(p)))
    return found


class ModeGallery:
    """Tiles 0 … NM−1 of the mode gallery: tile i plays mode i alone at its default amplitude
    and phase and the default time scale; `coefficients(t)` is (NM, nm), one row per tile."""

    def __init__(self, rig: Rig, tiles: int):
        model = rig.model
        self.model, self.time_scale = model, rig.palette.time_scale
        self.amplitudes = single_mode_amplitudes(model) / mode_reach(model)
        self.phases = default_phases(np.arange(model.n_modes))
        count = min(tiles, model.n_modes)
        self.mask = np.zeros((count, model.n_modes))
        self.mask[np.arange(count), np.arange(count)] = 1.0

    def coefficients(self, t: float) -> np.ndarray:
        wave = mode_coefficients(self.model, [t], self.amplitudes, self.phases,
                                 self.time_scale)[0]
        return self.mask * wave


def per_frame(function, frames: int) -> float:
    """Seconds per call of function(t) over `frames` frames at 30 fps, best of 3 rounds."""
    def run():
        for frame in range(frames):
            function(frame / 30.0)
    return best_of(run) / frames


def measure(name, loader, frames):
    start = time.perf_counter()
    skeleton = loader()
    loaded = time.perf_counter() - start
    modes = best_of(lambda: ModalModel.from_skeleton(skeleton))
    preprocess = best_of(lambda: Rig.from_skeleton(skeleton))
    naive = best_of(lambda: baseline_modal(skeleton), repeats=1)
    rig = Rig.from_skeleton(skeleton)
    skin32 = ModalSkin(rig.model, skeleton.vertices, skeleton.weights, dtype=np.float32)
    row = {"rig": name, "bodies": skeleton.n_bodies, "vertices": len(skeleton.vertices),
           "modes": rig.model.n_modes, "load": loaded, "analysis": modes,
           "preprocess": preprocess, "naive": naive}
    if rig.model.n_modes == 0:
        return row
    with threadpool_limits(1):  # products this small only lose time to more threads
        for key, tiles in (("1", 1), ("9", 9), ("all", rig.model.n_modes)):
            gallery = ModeGallery(rig, tiles)
            row[f"modal {key}"] = per_frame(
                lambda t, g=gallery: skin32.positions(g.coefficients(t)), frames)
        single = ModeGallery(rig, 1)
        row["lbs 1"] = per_frame(lambda t: linear_blend_skinning(
            skeleton.vertices, skeleton.weights,
            body_transforms(rig.model, single.coefficients(t))), frames)
    return row


def milliseconds(value) -> str:
    return "—" if value is None else f"{1000 * value:8.2f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=30, help="frames timed per figure")
    parser.add_argument("--browser", help="JSON {rig: {\"1\": fps, \"9\": fps}} measured in "
                                          "the page")
    parser.add_argument("--measure-browser", action="store_true",
                        help="measure the page's frames per second in headless Chromium")
    args = parser.parse_args()
    browser = {}
    if args.measure_browser:
        browser = browser_fps(sorted(glob.glob(shared_path("rigged", "*.glb"))))
        print(f"browser: headless Chromium, {browser.pop('renderer')}, 1024×768")
    elif args.browser:
        with open(args.browser, encoding="utf-8") as file:
            browser = json.load(file)
    print("Table 7.2 — thesis: 3.06 GHz CPU + GeForce GT 130, rendered 1024×768; ours: this "
          "machine, Python/numpy float32, no rendering")
    print("preprocessing: modes = modal analysis, +skin = with the modal-skin precomputation; "
          "naive = bench_modal's baseline modal analysis")
    print(f"{'rig':28} {'thesis':6} {'bodies':>6} {'verts':>6} {'modes':>5} {'load s':>7} "
          f"{'modes s':>8} {'+skin s':>8} {'naive s':>8} {'thesis s':>8} | ms/frame: "
          f"{'NM=1':>8} {'NM=9':>8} {'NM=all':>8} {'LBS NM=1':>8} | browser fps NM=1, NM=9")
    for name, loader in rigs():
        row = measure(name, loader, args.frames)
        thesis = COUNTERPART.get(name, "")
        reference = f"{THESIS[thesis][2]:8.3f}" if thesis else f"{'':8}"
        fps = browser.get(name, {})
        print(f"{name:28} {thesis:6} {row['bodies']:6d} {row['vertices']:6d} {row['modes']:5d} "
              f"{row['load']:7.3f} {row['analysis']:8.3f} {row['preprocess']:8.3f} "
              f"{row['naive']:8.3f} {reference} | "
              f"{'':10}{milliseconds(row.get('modal 1'))} {milliseconds(row.get('modal 9'))} "
              f"{milliseconds(row.get('modal all'))} {milliseconds(row.get('lbs 1'))} | "
              f"{fps.get('1', '—')}, {fps.get('9', '—')}")
    print("thesis, per model: " + "; ".join(
        f"{key} {v} v, {m} modes, {p} s, CPU NM=1 {c} fps, GPU NM=1 {g} fps"
        for key, (v, m, p, c, g) in THESIS.items()))


if __name__ == "__main__":
    main()
