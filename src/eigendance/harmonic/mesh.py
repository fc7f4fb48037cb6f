"""Load, check, clean and normalise triangle meshes (docs/design.md#mesh).

Every mesh entering eigendance goes through `load_mesh` (from a file) or `Mesh.from_arrays`
(from arrays): exact duplicate vertices are merged, degenerate and repeated triangles and
unreferenced vertices are dropped, and the result is centred and scaled into [-1, 1]^3 so that
eigenvalues and amplitudes mean the same thing on every model. Any defect that cannot be
repaired raises `InputError` with a one-line message.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp

from eigendance.assets.appearance import WELD_TOLERANCE, Appearance
from eigendance.assets.model import Model
from eigendance.assets.reader import read_model
from eigendance.errors import InputError
from eigendance.files import check_suffix
from eigendance.geometry import (
    MAX_COORDINATE,
    bounding_box_diagonal,
    face_edges,
    face_normals,
    unique_rows,
    weld,
)

# A triangle whose area is below this fraction of the squared bounding-box diagonal is degenerate.
ZERO_AREA = 1e-14
# Smallest extent (largest side of the bounding box) of a model, in its own unit: positions are
# written as float32, whose normal numbers end near 1e-38.
MIN_EXTENT = 1e-30


@dataclass
class Mesh:
    """A cleaned triangle mesh normalised into [-1, 1]^3.

    vertices: (n, 3) float64, normalised; original coordinates are ``vertices * scale + center``.
    faces: (m, 3) int64 triangles, every vertex referenced, no zero-area or repeated triangle.
    vertex_map: (n_input,) int64, the cleaned index of each input vertex, -1 for dropped ones.
    report: what the clean-up changed, e.g. {"duplicate_vertices": 3, "zero_area_faces": 1}.
    appearance: how the model is drawn (docs/design.md#appearance), its `welded` map onto
        these vertices; None for a model without a look of its own (drawn in clay).

    Parameters
    ----------
    vertices, faces, center, scale, vertex_map, report, appearance : as above (`from_arrays`
        and `from_model` make them).
    name : how messages call it.

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
    appearance: Appearance | None = None

    @property
    def n(self) -> int:
        """Vertices n."""
        return len(self.vertices)

    @property
    def original_vertices(self) -> np.ndarray:
        """Vertices in the file's coordinates (after clean-up), (n, 3)."""
        return self.vertices * self.scale + self.center

    @classmethod
    def from_arrays(cls, vertices, faces, name: str = "mesh", weld_tolerance: float = 0.0) -> Mesh:
        """Check, clean and normalise raw arrays (see the module docstring).

        Parameters
        ----------
        vertices : (n, 3) finite coordinates, any unit.
        faces : (m, 3) vertex indices of triangles (integers in 0 … n − 1).
        name : how messages call this mesh (a file name).
        weld_tolerance : vertices closer than this fraction of the bounding-box diagonal are
            merged (0: only exact duplicates; `geometry.weld`).

        Returns
        -------
        Mesh, normalised into [-1, 1]³; InputError for anything that cannot be repaired.
        """
        vertices, faces = check_mesh(vertices, faces, name)
        vertices, faces, vertex_map, report = _cleaned(vertices, faces, name, weld_tolerance)
        lower, upper = vertices.min(axis=0), vertices.max(axis=0)
        center = (lower + upper) / 2
        scale = float((upper - lower).max() / 2)
        if not scale > 0:
            raise InputError(f"{name}: all vertices coincide; the mesh has no extent")
        return cls((vertices - center) / scale, faces, center, scale, vertex_map, report, name)

    def adjacency(self):
        """Sparse (n, n) vertex adjacency through triangle edges.

        Returns
        -------
        scipy.sparse csr (n, n).
        """
        edges = face_edges(self.faces)
        n = len(self.vertices)
        return sp.coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), (n, n)).tocsr()

    def non_manifold_edge_count(self) -> int:
        """Number of undirected edges shared by more than two triangles.

        Returns
        -------
        int.
        """
        edges = np.sort(face_edges(self.faces), axis=1)
        _, counts = np.unique(edges[:, 0] * np.int64(self.n) + edges[:, 1], return_counts=True)
        return int((counts > 2).sum())

    def describe_cleanup(self) -> str:
        """A short phrase listing what the clean-up removed, '' if nothing.

        Returns
        -------
        str.
        """
        return ", ".join(f"{count} {what.replace('_', ' ')}" for what, count in
                         self.report.items() if count)


    @classmethod
    def from_model(cls, model: Model) -> Mesh:
        """The analysis mesh of a model as drawn (`assets.read_model`): drawn vertices within
        WELD_TOLERANCE of the diagonal welded, then cleaned as `from_arrays`; `appearance`
        maps every drawn vertex onto its welded vertex (docs/design.md#appearance).

        Parameters
        ----------
        model : the model as read.

        Returns
        -------
        Mesh with its appearance (None without a look).
        """
        mesh = cls.from_arrays(model.positions, model.triangles, model.name,
                               WELD_TOLERANCE if model.styled else 0.0)
        mesh.appearance = model.appearance(mesh.vertex_map)
        return mesh


def load_mesh(path: str | os.PathLike) -> Mesh:
    """Read a mesh file (glTF/GLB, OBJ with its MTL, PLY, OFF, STL) and clean it.

    Every mesh node of a glTF scene comes in with its node transform (`assets.read_model`);
    a model with materials or vertex colours keeps them in `Mesh.appearance`.

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
    >>> cat.n, len(cat.faces), float(np.abs(cat.vertices).max()), cat.appearance
    (7949, 15894, 1.0, None)
    """
    check_suffix(path, "mesh")
    return Mesh.from_model(read_model(path))


def check_mesh(vertices, faces, name: str = "mesh") -> tuple[np.ndarray, np.ndarray]:
    """The one check of a mesh's arrays (as potpourri3d's `validate_mesh`): InputError naming
    the mesh and the first defect that no clean-up can repair.

    Parameters
    ----------
    vertices : (n, 3) coordinates, n ≥ 1, finite, within ±MAX_COORDINATE.
    faces : (m, 3) vertex indices, m ≥ 1, integers in 0 … n − 1.
    name : how messages call the mesh (a file name).

    Returns
    -------
    (vertices float64, faces int64).

    Example
    -------
    >>> vertices, faces = check_mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    >>> vertices.dtype, faces.dtype
    (dtype('float64'), dtype('int64'))
    """
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


def _cleaned(vertices, faces, name, tolerance=0.0):
    """Merge duplicates, drop degenerate/repeated triangles and unused vertices."""
    n_input = len(vertices)
    first, first_to_unique = weld(vertices, tolerance)  # merged: first input order kept
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
