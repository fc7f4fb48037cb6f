"""Modal analysis and skinning speed, each beside a baseline measured in the same run.

    python benchmarks/bench_modal.py

1. Modal model of 100-body skeletons (target ≤ 1 s): `ModalModel.from_skeleton` against a
   straightforward version — joints assembled one by one in Python, scipy.linalg.null_space,
   scipy.linalg.eigh, default BLAS threads.
2. Skinning a 50k-vertex mesh with 30 modes: frames per second of `ModalSkin.positions`
   (float32) against a bare numpy product of the same shapes, (T, 30) @ (30, 150k) + x; linear
   blend skinning of the exact body transforms for scale.
3. Equilibrium pose editing of 100-body skeletons with a tube skin (target ≤ 1 s, thesis
   §4.5.6): turn a joint (`Skeleton.rotate_joint`), recompute the modes and the modal skin
   (`Rig.from_skeleton`) and pack the rig bundle the server answers, against the same edit with
   the baseline modal analysis of 1.
"""

from __future__ import annotations

import math
import time

import numpy as np
import scipy.linalg
from threadpoolctl import threadpool_limits

from eigendance.modal.model import ModalModel
from eigendance.modal.motion import body_transforms, mode_coefficients
from eigendance.modal.rig import Rig
from eigendance.modal.rotations import skew
from eigendance.modal.sample_rigs import add_tube_skin, open_chain, planar_loop
from eigendance.modal.skinning import ModalSkin, linear_blend_skinning
from eigendance.server.binary import rig_bundle


def best_of(function, repeats=3):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def baseline_modal(skeleton):
    """Per-joint Python assembly, scipy null_space and eigh (the obvious implementation)."""
    n = skeleton.n_bodies
    g_rows, r_rows, k = [], [], []
    for joint in skeleton.joints:
        frame = skeleton.joint_rotation(joint)
        blocks = []
        for b in joint.bodies:
            body = skeleton.bodies[b]
            rotation = frame.T @ skeleton.rotations[b]
            offset = frame.T @ (body.center - joint.position)
            adjoint = np.zeros((6, 6))
            adjoint[:3, :3] = rotation
            adjoint[3:, 3:] = rotation
            adjoint[3:, :3] = skew(offset) @ rotation
            blocks.append(adjoint)
        for row in range(6):
            line = np.zeros(6 * n)
            i, l = joint.bodies
            line[6 * i:6 * i + 6] = blocks[0][row]
            line[6 * l:6 * l + 6] -= blocks[1][row]
            (g_rows if row in joint.constrained_rows else r_rows).append(line)
        k.extend(joint.stiffness)
    G, R, K = np.array(g_rows), np.array(r_rows), np.diag(k)
    N = scipy.linalg.null_space(G, rcond=1e-9)
    M = np.diag(skeleton.spatial_inertia)
    eigenvalues, vectors = scipy.linalg.eigh(N.T @ R.T @ K @ R @ N, N.T @ M @ N)
    return np.sqrt(np.clip(eigenvalues, 0, None)) / (2 * math.pi), N @ vectors


def bench_modal():
    print("1. modal model of a 100-body skeleton (target <= 1 s)")
    for label, skeleton in (("chain of 100, spherical joints", open_chain(100, skin=False)),
                            ("planar loop of 100, revolute", planar_loop(100, skin=False))):
        ours = best_of(lambda s=skeleton: ModalModel.from_skeleton(s))
        base = best_of(lambda s=skeleton: baseline_modal(s))
        with threadpool_limits(1):
            base_single = best_of(lambda s=skeleton: baseline_modal(s))
        model = ModalModel.from_skeleton(skeleton)
        frequencies, _ = baseline_modal(skeleton)
        agree = np.allclose(frequencies[model.rigid_modes:], model.frequencies, rtol=1e-6)
        print(f"   {label}: eigendance {ours:.3f} s, baseline {base:.3f} s, "
              f"ratio {base / ours:.1f}x; baseline on 1 BLAS thread {base_single:.3f} s, ratio "
              f"{base_single / ours:.1f}x  ({model.n_modes} modes, same frequencies: {agree})")


def bench_skinning(frames=60):
    print("2. skinning 50k vertices with 30 modes")
    skeleton = open_chain(11, skin=False)  # 10 spherical joints: 30 vibration modes
    add_tube_skin(skeleton, rings=142, around=32)
    model = ModalModel.from_skeleton(skeleton)
    n, nm = len(skeleton.vertices), model.n_modes
    coefficients = mode_coefficients(model, np.arange(frames) / 30.0)
    skin = ModalSkin(model, skeleton.vertices, skeleton.weights, dtype=np.float32)
    c32 = coefficients.astype(np.float32)
    matrix = np.random.default_rng(0).normal(size=(nm, 3 * n)).astype(np.float32)
    flat = skeleton.vertices.reshape(-1).astype(np.float32)
    def bare_product():
        out = np.matmul(c32, matrix)
        out += flat
        return out.reshape(frames, n, 3)

    ours = best_of(lambda: skin.positions(c32), repeats=5)
    bare = best_of(bare_product, repeats=5)
    transforms = body_transforms(model, coefficients)
    blend = best_of(lambda: linear_blend_skinning(skeleton.vertices, skeleton.weights,
                                                  transforms), repeats=1)
    print(f"   {n} vertices, {nm} modes, {frames} frames per call")
    print(f"   modal skinning {frames / ours:.0f} frames/s, bare numpy product "
          f"{frames / bare:.0f} frames/s, eigendance/bare = {bare / ours:.2f} (1 = no overhead)")
    print(f"   linear blend skinning (exact transforms, float64) {frames / blend:.0f} frames/s")


TURN = [0.0, 0.0, 0.4]  # the pose edit: a rotation vector, radians


def bench_pose_edit():
    print("3. equilibrium pose edit of a 100-body skeleton with its skin (target <= 1 s)")
    for label, skeleton, joint in (("chain of 100, spherical", open_chain(100), "j49"),
                                   ("chain of 100, revolute", open_chain(100, "revolute"),
                                    "j10")):
        def modes(s=skeleton, j=joint):
            ModalModel.from_skeleton(s.rotate_joint(j, TURN))

        def answer(s=skeleton, j=joint):
            rig_bundle(Rig.from_skeleton(s.rotate_joint(j, TURN)))

        def baseline(s=skeleton, j=joint):
            baseline_modal(s.rotate_joint(j, TURN))

        edit, full, base = best_of(modes), best_of(answer), best_of(baseline)
        size = len(rig_bundle(Rig.from_skeleton(skeleton))) / 2**20
        print(f"   {label}: edit + modes {edit:.3f} s (baseline modal analysis {base:.3f} s, "
              f"ratio {base / edit:.1f}x); the server's whole answer (+ modal skin of "
              f"{len(skeleton.vertices)} vertices + {size:.0f} MiB bundle) {full:.3f} s")


if __name__ == "__main__":
    bench_modal()
    bench_skinning()
    bench_pose_edit()
