"""Load, check, clean and normalise triangle meshes (DESIGN §2).

Every mesh entering eigendance goes through `load_mesh` (from a file) or `Mesh.from_arrays`
(from arrays): exact duplicate vertices are merged, degenerate and repeated triangles and
unreferenced vertices are dropped, and the result is centred and scaled into [-1, 1]^3 so that
eigenvalues and amplitudes mean the same thing on every model. Any defect that cannot be
repaired raises `EigendanceError` with a one-line message.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import numpy as np

from eigendance.errors import EigendanceError

MESH_SUFFIXES = (".obj", ".ply", ".off", ".stl", ".gltf", ".glb")

# A triangle whose area is below this fraction of the squared bounding-box diagonal is degenerate.
ZERO_AREA = 1e-14


@dataclass
class Mesh:
    """A cleaned triangle mesh normalised into [-1, 1]^3.

    vertices: (n, 3) float64, normalised; original coordinates are ``vertices * scale + center``.
    faces: (m, 3) int64 triangles, every vertex referenced, no zero-area or repeated triangle.
    vertex_map: (n_input,) int64, the cleaned index of each input vertex, -1 for dropped ones.
    report: what the clean-up changed, e.g. {"duplicate_vertices": 3, "zero_area_faces": 1}.
    """

    vertices: np.ndarray
    faces: np.ndarray
    center: np.ndarray
    scale: float
    vertex_map: np.ndarray
    report: dict = field(default_factory=dict)
    name: str = "mesh"

    @property
    def original_vertices(self) -> np.ndarray:
        """Vertices in the file's coordinates (after clean-up), (n, 3)."""
        return self.vertices * self.scale + self.center

    @classmethod
    def from_arrays(cls, vertices, faces, name: str = "mesh") -> Mesh:
        """Check, clean and normalise raw arrays; see the module docstring."""
        vertices, faces = _validated(vertices, faces, name)
        vertices, faces, vertex_map, report = _cleaned(vertices, faces, name)
        lower, upper = vertices.min(axis=0), vertices.max(axis=0)
        center = (lower + upper) / 2
        scale = float((upper - lower).max() / 2)
        if not scale > 0:
            raise EigendanceError(f"{name}: all vertices coincide; the mesh has no extent")
        return cls((vertices - center) / scale, faces, center, scale, vertex_map, report, name)

    def adjacency(self):
        """Sparse (n, n) vertex adjacency through triangle edges."""
        import scipy.sparse as sp

        edges = self.faces[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)
        n = len(self.vertices)
        return sp.coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), (n, n)).tocsr()

    def non_manifold_edge_count(self) -> int:
        """Number of undirected edges shared by more than two triangles."""
        edges = np.sort(self.faces[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
        _, counts = np.unique(edges, axis=0, return_counts=True)
        return int((counts > 2).sum())

    def describe_cleanup(self) -> str:
        """A short phrase listing what the clean-up removed, '' if nothing."""
        return ", ".join(f"{count} {what.replace('_', ' ')}" for what, count in
                         self.report.items() if count)


def load_mesh(path: str | os.PathLike) -> Mesh:
    """Read a mesh file (OBJ, PLY, OFF, STL, glTF/GLB) with trimesh and clean it.

    All triangle primitives of a glTF scene are merged with their node transforms applied.
    """
    import trimesh

    path = os.fspath(path)
    name = os.path.basename(path)
    if not os.path.isfile(path):
        raise EigendanceError(f"{path}: no such file")
    suffix = os.path.splitext(path)[1].lower()
    if suffix not in MESH_SUFFIXES:
        raise EigendanceError(
            f"{name}: unknown mesh format '{suffix}' (expected one of {', '.join(MESH_SUFFIXES)})")
    if os.path.getsize(path) == 0:
        raise EigendanceError(f"{name}: the file is empty")
    try:
        loaded = trimesh.load(path, force="mesh", process=False)
    except Exception as error:  # trimesh raises many types for malformed files
        raise EigendanceError(f"{name}: cannot read the mesh ({_one_line(error)})") from None
    faces = getattr(loaded, "faces", None)
    if faces is None or len(faces) == 0:
        raise EigendanceError(f"{name}: the file holds no triangles (a point cloud or empty mesh)")
    return Mesh.from_arrays(loaded.vertices, faces, name=name)


def _one_line(error: Exception) -> str:
    text = " ".join(str(error).split()) or type(error).__name__
    return text[:200]


def _validated(vertices, faces, name: str) -> tuple[np.ndarray, np.ndarray]:
    vertices = np.asarray(vertices, dtype=np.float64)
    faces = np.asarray(faces)
    if vertices.ndim != 2 or vertices.shape[1] != 3 or len(vertices) == 0:
        raise EigendanceError(f"{name}: vertices must be an (n, 3) array, got {vertices.shape}")
    if faces.ndim != 2 or faces.shape[1] != 3 or len(faces) == 0:
        raise EigendanceError(f"{name}: faces must be an (m, 3) array of triangles, "
                              f"got {faces.shape}")
    if not np.issubdtype(faces.dtype, np.integer):
        if not np.all(np.isfinite(faces)) or np.any(faces != np.round(faces)):
            raise EigendanceError(f"{name}: face indices must be integers")
    faces = faces.astype(np.int64)
    bad = np.flatnonzero(~np.isfinite(vertices).all(axis=1))
    if len(bad):
        raise EigendanceError(f"{name}: {len(bad)} vertices have NaN or infinite coordinates "
                              f"(first: vertex {bad[0]})")
    out = np.flatnonzero(((faces < 0) | (faces >= len(vertices))).any(axis=1))
    if len(out):
        raise EigendanceError(f"{name}: {len(out)} triangles use vertex indices outside "
                              f"0..{len(vertices) - 1} (first: triangle {out[0]})")
    return vertices, faces


def _cleaned(vertices, faces, name):
    """Merge exact duplicates, drop degenerate/repeated triangles and unused vertices."""
    n_input = len(vertices)
    # Merged vertices keep the order of their first occurrence in the input.
    _, first, inverse = np.unique(vertices, axis=0, return_index=True, return_inverse=True)
    order = np.argsort(first)
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    unique = vertices[first[order]]
    first_to_unique = rank[inverse.reshape(-1)]
    faces = first_to_unique[faces]
    duplicate_vertices = n_input - len(unique)

    corners = unique[faces]
    doubled_area = np.linalg.norm(
        np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
    diagonal = np.linalg.norm(unique.max(axis=0) - unique.min(axis=0))
    repeated_index = (faces[:, 0] == faces[:, 1]) | (faces[:, 1] == faces[:, 2]) | (
        faces[:, 2] == faces[:, 0])
    degenerate = repeated_index | (doubled_area <= 2 * ZERO_AREA * diagonal**2)
    faces = faces[~degenerate]
    if len(faces) == 0:
        raise EigendanceError(f"{name}: every triangle has zero area")

    _, first = np.unique(np.sort(faces, axis=1), axis=0, return_index=True)
    repeated_faces = len(faces) - len(first)
    faces = faces[np.sort(first)]

    used = np.zeros(len(unique), dtype=bool)
    used[faces.ravel()] = True
    renumber = np.full(len(unique), -1, dtype=np.int64)
    renumber[used] = np.arange(used.sum())
    # Unreferenced input vertices: those whose merged vertex is unused.
    unused_vertices = int((~used[first_to_unique]).sum())
    report = {
        "duplicate_vertices": int(duplicate_vertices),
        "unreferenced_vertices": unused_vertices,
        "zero_area_faces": int(degenerate.sum()),
        "repeated_faces": int(repeated_faces),
    }
    return unique[used], renumber[faces], renumber[first_to_unique], report
