"""A model made of pieces dances as one (docs/design.md#laplacian): the pieces are coupled where
they touch, the operator is connected (one harmonic of eigenvalue 0), and touching pieces drift
apart by at most 0.3 of the dance's motion for every item of the initial gallery on a real song
(before the coupling: 0.5–2.9, benchmarks/bench_parts.py)."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
import trimesh

from eigendance.harmonic import laplacian as operators
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.contacts import components, contacts, part_drift
from eigendance.harmonic.eigensolver import null_space
from eigendance.harmonic.mesh import load_mesh
from eigendance.harmonic.motion import positions_at
from eigendance.music.gallery import initial_gallery
from eigendance.music.spectrogram import Spectrogram
from helpers import fixture_path, sphere


@pytest.fixture(scope="module")
def robot():
    """robot.obj: 6 pieces (body, eyes, antenna …) with 3 materials."""
    return load_mesh(fixture_path("textured", "robot.obj"))


def test_a_single_piece_keeps_the_cotangent_laplacian():
    import igl  # the reference: libigl's matrix itself

    mesh = sphere(2)
    stiffness, _ = operators.laplacian(mesh.vertices, mesh.faces)
    assert abs(stiffness + igl.cotmatrix(mesh.vertices, mesh.faces)).max() < 1e-12
    assert len(contacts(mesh.vertices, mesh.faces)) == 0


def test_touching_pieces_are_coupled_and_far_ones_joined():
    box = trimesh.creation.box()
    lid = box.copy()
    lid.apply_translation([0, 0, 1])  # sits on the box
    far = box.copy()
    far.apply_translation([5, 0, 0])  # touches nothing
    pieces = trimesh.util.concatenate([box, lid, far])
    count, _ = components(len(pieces.vertices), pieces.faces)
    assert count == 3
    stiffness, mass = operators.laplacian(pieces.vertices, pieces.faces)
    assert abs(stiffness - stiffness.T).max() < 1e-9 * abs(stiffness).max()
    assert np.abs(np.asarray(stiffness.sum(axis=1))).max() < 1e-9 * abs(stiffness).max()
    assert len(null_space(stiffness, mass, 10)) == 1  # one component: one constant
    eigenvalues = np.linalg.eigvalsh(stiffness.toarray())
    assert eigenvalues.min() > -1e-6 * eigenvalues.max()  # still positive semi-definite


def test_the_pieces_of_a_real_model_dance_as_one(robot):
    count, _ = components(robot.n, robot.faces)
    assert count == 6
    song = Spectrogram.from_file(fixture_path("audio", "kevin_macleod_vibe_ace_0s-21s.ogg"))
    basis = HarmonicBasis.from_mesh(robot, 80, cache=False)
    assert np.sum(basis.eigenvalues < 1e-8 * basis.eigenvalues.max()) == 1
    times = np.linspace(0, song.duration, 120)
    rest = basis.to_original(basis.vertices)
    drift = [part_drift(rest, basis.faces, positions_at(basis, song, item, times) - rest)
             for item in initial_gallery(basis, song, 8)]
    assert max(drift) <= 0.3, drift


def test_without_the_coupling_the_pieces_come_apart(robot, monkeypatch):
    """The statistic sees the problem the coupling solves (so the bound above can fail)."""
    monkeypatch.setattr(operators, "CONTACT_STIFFNESS", 0.0)
    song = Spectrogram.from_file(fixture_path("audio", "kevin_macleod_vibe_ace_0s-21s.ogg"))
    basis = HarmonicBasis.from_mesh(robot, 80, solver="eigsh", cache=False)
    stiffness, mass = operators.laplacian(basis.vertices, basis.faces)
    assert len(null_space(sp.csr_matrix(stiffness), mass, 10)) == 6
    rest = basis.to_original(basis.vertices)
    item = initial_gallery(basis, song, 8)[3]
    times = np.linspace(0, song.duration, 120)
    assert part_drift(rest, basis.faces, positions_at(basis, song, item, times) - rest) > 0.3


def blocks_on_a_coarse_base():
    """MorphStressTest's shape: a base of two-triangle faces (2 × 0.3 × 0.5, a trimesh box) and
    eight blocks (0.125 wide, 0.125 apart, subdivided) standing on it, every piece its own."""
    base = trimesh.creation.box([2.0, 0.3, 0.5])
    blocks = []
    for i in range(8):
        block = trimesh.creation.box([0.125, 0.25, 0.25]).subdivide().subdivide()
        x = -0.875 + i * 0.25  # centres 0.25 apart: gaps of 0.125
        blocks.append(block.apply_translation([x, 0.15 + 0.125, 0.0]))
    return trimesh.util.concatenate([base, *blocks])


def test_contacts_reach_only_pieces_that_touch():
    """A coarse piece's long edges must not reach pieces it does not touch: every contact
    spans at most 1% of the diagonal (before the cap, springs spanned up to 0.35 of this
    model's 2.13: the base's corners to the blocks, a block's faces to its neighbours), and every
    block still sits on the base (each block has contacts, and the operator is one piece)."""
    mesh = blocks_on_a_coarse_base()
    diagonal = np.linalg.norm(np.ptp(mesh.vertices, axis=0))
    found = contacts(mesh.vertices, mesh.faces)
    assert found.distances.max() <= 0.01 * diagonal + 1e-12, found.distances.max()
    _, labels = components(len(mesh.vertices), mesh.faces)
    touched = set(labels[found.vertices]) | set(labels[found.faces[:, 0]])
    assert touched == set(range(9))  # the base and all eight blocks
    stiffness, _ = operators.laplacian(mesh.vertices, mesh.faces, "cotan")
    pieces, _ = sp.csgraph.connected_components(abs(stiffness) > 0, directed=False)
    assert pieces == 1
