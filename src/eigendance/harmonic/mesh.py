"""Load, check, clean and normalise triangle meshes (docs/design.md#mesh).

Every mesh entering eigendance goes through `load_mesh` (from a file) or `Mesh.from_arrays`
(from arrays): exact duplicate vertices are merged, degenerate and repeated triangles and
unreferenced vertices are dropped, and the result is centred and scaled into [-1, 1]^3 so that
eigenvalues and amplitudes mean the same thing on every model. Any defect that cannot be
repaired raises `InputError` with a one-line message.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp

from eigendance.errors import InputError, one_line
from eigendance.files import check_readable, check_suffix
from eigendance.geometry import (
    MAX_COORDINATE,
    bounding_box_diagonal,
    face_normals,
    unique_rows,
    weld,
)

# A triangle whose area is below this fraction of the squared bounding-box diagonal is degenerate.
ZERO_AREA = 1e-14
# Smallest extent (largest side of the bounding box) of a model, in its own unit: positions are
# written as float32, whose normal numbers end near 1e-38.
MIN_EXTENT = 1e-30
# An OBJ face corner whose vertex index is 0 (OBJ counts from 1; trimesh would read 0 as −1, the
# last vertex). Only the vertex index, the first number of a corner v/vt/vn, is looked at.
OBJ_ZERO_INDEX = re.compile(rb"^[ \t]*f[ \t](?:[^\n]*?[ \t])?[+-]?0+(?=[/ \t\r\n]|$)", re.M)


@dataclass
class Mesh:
    """A cleaned triangle mesh normalised into [-1, 1]^3.

    vertices: (n, 3) float64, normalised; original coordinates are ``vertices * scale + center``.
    faces: (m, 3) int64 triangles, every vertex referenced, no zero-area or repeated triangle.
    vertex_map: (n_input,) int64, the cleaned index of each input vertex, -1 for dropped ones.
    report: what the clean-up changed, e.g. {"duplicate_vertices": 3, "zero_area_faces": 1}.

    Example
    -------
    >>> square = Mesh.from_arrays([[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0], [0, 0, 0]],
    ...                           [[0, 1, 2], [0, 2, 3], [4, 1, 2]])
    >>> square.n, len(square.faces), square.report["duplicate_vertices"]
    (4, 2, 1)
    >>> square.vertices.min(axis=0).tolist(), square.scale
    ([-1.0, -1.0, 0.0], 1.0)
    """

    vertices: np.ndarray
    faces: np.ndarray
    center: np.ndarray
    scale: float
    vertex_map: np.ndarray
    report: dict = field(default_factory=dict)
    name: str = "mesh"

    @property
    def n(self) -> int:
        return len(self.vertices)

    @property
    def original_vertices(self) -> np.ndarray:
        """Vertices in the file's coordinates (after clean-up), (n, 3)."""
        return self.vertices * self.scale + self.center

    @classmethod
    def from_arrays(cls, vertices, faces, name: str = "mesh") -> Mesh:
        """Check, clean and normalise raw arrays (see the module docstring).

        Parameters
        ----------
        vertices : (n, 3) finite coordinates, any unit.
        faces : (m, 3) vertex indices of triangles (integers in 0 … n − 1).
        name : how messages call this mesh (a file name).

        Returns
        -------
        Mesh, normalised into [-1, 1]³; InputError for anything that cannot be repaired.
        """
        vertices, faces = _validated(vertices, faces, name)
        vertices, faces, vertex_map, report = _cleaned(vertices, faces, name)
        lower, upper = vertices.min(axis=0), vertices.max(axis=0)
        center = (lower + upper) / 2
        scale = float((upper - lower).max() / 2)
        if not scale > 0:
            raise InputError(f"{name}: all vertices coincide; the mesh has no extent")
        return cls((vertices - center) / scale, faces, center, scale, vertex_map, report, name)

    def adjacency(self):
        """Sparse (n, n) vertex adjacency through triangle edges."""
        edges = self.faces[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)
        n = len(self.vertices)
        return sp.coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), (n, n)).tocsr()

    def non_manifold_edge_count(self) -> int:
        """Number of undirected edges shared by more than two triangles."""
        edges = np.sort(self.faces[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
        _, counts = np.unique(edges[:, 0] * np.int64(self.n) + edges[:, 1], return_counts=True)
        return int((counts > 2).sum())

    def describe_cleanup(self) -> str:
        """A short phrase listing what the clean-up removed, '' if nothing."""
        return ", ".join(f"{count} {what.replace('_', ' ')}" for what, count in
                         self.report.items() if count)


def load_mesh(path: str | os.PathLike) -> Mesh:
    """Read a mesh file (OBJ, PLY, OFF, STL, glTF/GLB) with trimesh and clean it.

    All triangle primitives of a glTF scene are merged with their node transforms applied.

    Parameters
    ----------
    path : an OBJ, PLY, OFF, STL, glTF or GLB file.

    Returns
    -------
    Mesh, cleaned and normalised (see `Mesh.from_arrays`).

    Example
    -------
    >>> from importlib.resources import files
    >>> cat = load_mesh(files("eigendance") / "data" / "cat_lowres.obj")
    >>> cat.n, len(cat.faces), float(np.abs(cat.vertices).max())
    (7949, 15894, 1.0)
    """
    import trimesh  # heavy (≈0.8 s): imported when a mesh file is read

    check_suffix(path, "mesh")
    path = check_readable(path)
    name = os.path.basename(path)
    if path.lower().endswith(".obj"):
        _check_obj_indices(path, name)
    try:
        loaded = trimesh.load(path, force="mesh", process=False)
    except Exception as error:  # trimesh raises many types for malformed files
        raise InputError(f"{name}: cannot read the mesh ({one_line(error, 200)})") from None
    faces = getattr(loaded, "faces", None)
    if faces is None or len(faces) == 0:
        if path.lower().endswith(".stl"):
            _check_stl_length(path, name)
        raise InputError(f"{name}: the file holds no triangles (a point cloud or empty mesh)")
    return Mesh.from_arrays(loaded.vertices, faces, name=name)


def _check_obj_indices(path: str, name: str) -> None:
    """InputError for a face corner with vertex index 0, which OBJ does not have."""
    try:
        with open(path, "rb") as file:
            found = OBJ_ZERO_INDEX.search(file.read())
    except OSError as error:
        raise InputError(f"{name}: cannot read ({error.strerror})") from None
    if found:
        line = found.string.count(b"\n", 0, found.start()) + 1
        raise InputError(f"{name}: line {line}: a face uses vertex index 0 (OBJ counts vertices "
                         "from 1)")


def _check_stl_length(path: str, name: str) -> None:
    """InputError for a binary STL shorter than the triangle count of its header says."""
    size = os.path.getsize(path)
    with open(path, "rb") as file:
        head = file.read(84)
    if len(head) < 84 or head.lstrip().startswith(b"solid") and b"facet" in head:
        return
    count = int.from_bytes(head[80:84], "little")
    if 84 + 50 * count > size:
        raise InputError(f"{name}: truncated binary STL: the header announces {count} "
                         f"triangles, the file holds {(size - 84) // 50}")


def _validated(vertices, faces, name: str) -> tuple[np.ndarray, np.ndarray]:
    vertices = np.asarray(vertices, dtype=np.float64)
    faces = np.asarray(faces)
    if vertices.ndim != 2 or vertices.shape[1] != 3 or len(vertices) == 0:
        raise InputError(f"{name}: vertices must be an (n, 3) array, got {vertices.shape}")
    if faces.ndim != 2 or faces.shape[1] != 3 or len(faces) == 0:
        raise InputError(f"{name}: faces must be an (m, 3) array of triangles, "
                              f"got {faces.shape}")
    if not np.issubdtype(faces.dtype, np.integer):
        if not np.all(np.isfinite(faces)) or np.any(faces != np.round(faces)):
            raise InputError(f"{name}: face indices must be integers")
    faces = faces.astype(np.int64)
    bad = np.flatnonzero(~np.isfinite(vertices).all(axis=1))
    if len(bad):
        raise InputError(f"{name}: {len(bad)} vertices have NaN or infinite coordinates "
                              f"(first: vertex {bad[0]})")
    largest = float(np.abs(vertices).max())
    if largest > MAX_COORDINATE:
        raise InputError(f"{name}: coordinates reach {largest:.3g}; models must lie within "
                         f"±{MAX_COORDINATE:.0e} (rescale it)")
    out = np.flatnonzero(((faces < 0) | (faces >= len(vertices))).any(axis=1))
    if len(out):
        raise InputError(f"{name}: {len(out)} triangles use vertex indices outside "
                              f"0..{len(vertices) - 1} (first: triangle {out[0]})")
    return vertices, faces


def _cleaned(vertices, faces, name):
    """Merge exact duplicates, drop degenerate/repeated triangles and unused vertices."""
    n_input = len(vertices)
    first, first_to_unique = weld(vertices)  # merged vertices keep their first input order
    unique = vertices[first]
    faces = first_to_unique[faces]
    duplicate_vertices = n_input - len(unique)

    lower = unique.min(axis=0)
    extent = float((unique.max(axis=0) - lower).max())
    if not extent >= MIN_EXTENT:
        raise InputError(f"{name}: the model spans {extent:.3g}, less than {MIN_EXTENT:.0e} "
                         "(all vertices (nearly) coincide)")
    scaled = (unique - lower) / extent  # areas relative to the diagonal do not depend on units
    doubled_area = np.linalg.norm(face_normals(scaled, faces), axis=1)
    diagonal = bounding_box_diagonal(scaled)
    repeated_index = (faces[:, 0] == faces[:, 1]) | (faces[:, 1] == faces[:, 2]) | (
        faces[:, 2] == faces[:, 0])
    degenerate = repeated_index | (doubled_area <= 2 * ZERO_AREA * diagonal**2)
    faces = faces[~degenerate]
    if len(faces) == 0:
        raise InputError(f"{name}: every triangle has zero area")

    first, _ = unique_rows(np.sort(faces, axis=1))
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
