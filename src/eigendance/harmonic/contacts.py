"""Where the separate pieces of a mesh meet (docs/design.md#laplacian).

A model made of pieces (candles on a cake, eyes in a head, straps on a body) has several
connected components. `contacts` finds, for vertices of one piece, the closest point on another
piece's surface: every vertex closer to another piece than its own mean edge length (the pieces
touch there), and, for each group of pieces that touches no other, the vertices where it comes
closest to the nearest group (so that every piece is joined). `part_drift` measures how far
touching pieces drift apart in a dance. libigl's AABB trees answer the distance queries.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import connected_components

from eigendance.geometry import bounding_box_diagonal, face_edges

# A vertex touches another piece when its closest point there lies within this many of its own
# mean edge lengths,
CONTACT_REACH = 2.0
# each length at most this fraction of the bounding-box diagonal: a coarse piece's long edges
# (a base of two triangles, a block's two-triangle faces) would otherwise reach pieces it does
# not touch, up to the whole model, and pin it to them, so that the harmonics tore the outer
# blocks of MorphStressTest into spikes. 2 × 0.005 = 1% of the diagonal, `part_drift`'s reach.
TOUCH_LENGTH = 0.005
# A group of pieces that touches none is joined where it comes within its gap to the nearest
# group plus this many of each vertex's mean edge lengths.
JOIN_BAND = 1.0


@dataclass
class Contacts:
    """Vertex i ↔ a point of another piece: vertices (c,), faces (c, 3) the triangle the
    point lies on, weights (c, 3) its barycentric coordinates, distances (c,).

    Parameters
    ----------
    vertices, faces, weights, distances : as above.
    """

    vertices: np.ndarray
    faces: np.ndarray
    weights: np.ndarray
    distances: np.ndarray

    def __len__(self) -> int:
        return len(self.vertices)

    def gather(self, values: np.ndarray) -> np.ndarray:
        """(…, c, d) values at the contact points from per-vertex values (…, n, d).

        Parameters
        ----------
        values : (…, n, d).

        Returns
        -------
        (…, c, d).
        """
        corners = values[..., self.faces, :]  # (…, c, 3, d)
        return np.einsum("...cjd,cj->...cd", corners, self.weights)


def components(n: int, faces: np.ndarray) -> tuple[int, np.ndarray]:
    """(count, labels (n,)) of the connected components of the triangles' vertex graph.

    Parameters
    ----------
    n : vertices.
    faces : (m, 3).

    Returns
    -------
    (count, labels).
    """
    edges = face_edges(faces)
    graph = sp.coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), (n, n))
    return connected_components(graph, directed=False)


def edge_lengths(vertices: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """(n,) the mean length of the edges at each vertex (0 for an unreferenced one).

    Parameters
    ----------
    vertices : (n, 3).
    faces : (m, 3).

    Returns
    -------
    (n,).
    """
    edges = face_edges(faces)
    length = np.linalg.norm(vertices[edges[:, 0]] - vertices[edges[:, 1]], axis=1)
    total = np.bincount(edges.ravel(), np.repeat(length, 2), minlength=len(vertices))
    count = np.bincount(edges.ravel(), minlength=len(vertices))
    return total / np.maximum(count, 1)


def closest_on_others(vertices, faces, labels, queries, reach) -> Contacts:
    """For each query vertex, the closest point on a piece other than its own, if one lies
    within reach[q]; pieces whose bounding box (grown by the largest reach) misses a vertex
    are not asked about it.

    Parameters
    ----------
    vertices : (n, 3).
    faces : (m, 3).
    labels : (n,) the piece of each vertex.
    queries : the vertices asked about.
    reach : (n,) the distance each may look.

    Returns
    -------
    Contacts.
    """
    face_labels = labels[faces[:, 0]]
    best = np.full(len(queries), np.inf)
    found_face = np.zeros(len(queries), dtype=np.int64)
    found_point = np.zeros((len(queries), 3))
    margin = float(reach.max(initial=0.0))
    points = vertices[queries]
    for label in np.unique(face_labels):
        piece = faces[face_labels == label]
        corners = vertices[piece].reshape(-1, 3)
        lower, upper = corners.min(axis=0) - margin, corners.max(axis=0) + margin
        asked = np.flatnonzero((labels[queries] != label)
                               & np.all((points >= lower) & (points <= upper), axis=1))
        if len(asked):
            _closest(vertices, piece, points, asked, best, found_face, found_point,
                     np.flatnonzero(face_labels == label))
    near = np.flatnonzero(np.sqrt(best) <= reach)
    return _contacts(vertices, faces, queries[near], found_face[near], found_point[near],
                     np.sqrt(best[near]))


def _closest(vertices, piece, points, asked, best, found_face, found_point, face_ids):
    import igl  # heavy (≈0.4 s): imported when a Laplacian is built

    distance, face, point = igl.point_mesh_squared_distance(
        np.ascontiguousarray(points[asked]), np.ascontiguousarray(vertices),
        np.ascontiguousarray(piece))
    better = distance < best[asked]
    chosen = asked[better]
    best[chosen] = distance[better]
    found_face[chosen] = face_ids[face[better]]
    found_point[chosen] = point[better]


def _contacts(vertices, faces, queries, face_index, points, distances) -> Contacts:
    corners = faces[face_index]
    weights = _barycentric(points, *(vertices[corners[:, k]] for k in range(3)))
    return Contacts(queries.astype(np.int64), corners, weights, distances)


def _barycentric(p, a, b, c) -> np.ndarray:
    """(c, 3) barycentric coordinates of points p on triangles abc (clipped, summing to 1)."""
    v0, v1, v2 = b - a, c - a, p - a
    d00, d01, d11 = (v0 * v0).sum(1), (v0 * v1).sum(1), (v1 * v1).sum(1)
    d20, d21 = (v2 * v0).sum(1), (v2 * v1).sum(1)
    denominator = d00 * d11 - d01 * d01
    safe = np.where(np.abs(denominator) > 0, denominator, 1.0)
    v = (d11 * d20 - d01 * d21) / safe
    w = (d00 * d21 - d01 * d20) / safe
    weights = np.clip(np.column_stack([1 - v - w, v, w]), 0.0, 1.0)
    weights[np.abs(denominator) <= 0] = (1.0, 0.0, 0.0)
    return weights / weights.sum(axis=1, keepdims=True)


def contacts(vertices: np.ndarray, faces: np.ndarray) -> Contacts:
    """Where the pieces of a mesh touch, and where each group of pieces that touches none
    comes closest to the nearest other group (see the module docstring).

    Parameters
    ----------
    vertices : (n, 3); faces : (m, 3).

    Returns
    -------
    Contacts (empty for a mesh of one piece): every vertex with another piece's surface
    within CONTACT_REACH of its mean edge lengths (each at most TOUCH_LENGTH of the bounding-box
    diagonal), then the joins.

    Example
    -------
    >>> import trimesh
    >>> box = trimesh.creation.box()
    >>> lid = box.copy().apply_translation([0, 0, 1])               # sitting on the box
    >>> both = trimesh.util.concatenate([box, lid])
    >>> found = contacts(both.vertices, both.faces)
    >>> int((found.distances == 0).sum()), len(found)    # the 8 corners that meet, all in reach
    (8, 8)
    """
    vertices = np.asarray(vertices, dtype=np.float64)
    faces = np.asarray(faces, dtype=np.int64)
    count, labels = components(len(vertices), faces)
    if count < 2:
        return Contacts(np.zeros(0, np.int64), np.zeros((0, 3), np.int64), np.zeros((0, 3)),
                        np.zeros(0))
    lengths = np.minimum(edge_lengths(vertices, faces),
                         TOUCH_LENGTH * bounding_box_diagonal(vertices))
    everyone = np.flatnonzero(np.bincount(faces.ravel(), minlength=len(vertices)) > 0)
    found = closest_on_others(vertices, faces, labels, everyone,
                              CONTACT_REACH * lengths[everyone])
    joins = [found]
    while True:
        groups, group = _groups(len(vertices), faces, labels, joins)
        more = _joins(vertices, faces, group, groups, lengths, everyone)
        if groups < 2 or not sum(len(c) for c in more):
            break
        joins.extend(more)
    return Contacts(*(np.concatenate([getattr(c, name) for c in joins]) for name in
                      ("vertices", "faces", "weights", "distances")))


def _groups(n, faces, labels, joins) -> tuple[int, np.ndarray]:
    """Groups of pieces connected by the contacts so far: (count, group of each vertex)."""
    edges = [faces[:, [0, 1]], faces[:, [1, 2]]]
    for found in joins:
        edges.append(np.column_stack([found.vertices, found.faces[:, 0]]))
    edges = np.concatenate(edges)
    graph = sp.coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), (n, n))
    return connected_components(graph, directed=False)


def _joins(vertices, faces, group, groups, lengths, everyone) -> list[Contacts]:
    """Each group of pieces joined to its nearest other group (one round of Borůvka's
    algorithm): the vertices of the group within the gap plus JOIN_BAND edge lengths."""
    face_group = group[faces[:, 0]]
    found = []
    for label in range(groups):
        own = everyone[group[everyone] == label]
        others = faces[face_group != label]
        if not len(own) or not len(others):
            continue
        gap = closest_on_others(vertices, np.concatenate([faces[face_group == label], others]),
                                np.where(group == label, 0, 1), own, np.full(len(own), np.inf))
        reach = gap.distances.min() + JOIN_BAND * lengths[gap.vertices]
        keep = gap.distances <= reach
        found.append(Contacts(gap.vertices[keep], gap.faces[keep], gap.weights[keep],
                              gap.distances[keep]))
    return found


def part_drift(vertices, faces, displacements, reach: float = 0.01) -> float:
    """How far touching pieces drift apart in a motion, relative to the motion itself.

    For every vertex whose closest point on another piece lies within `reach` of the
    bounding-box diagonal (the pieces touch there), the change of its offset to that point,
    d_i(t) − d_p(t); the result is its RMS over those vertices and the frames, divided by the
    RMS displacement of all vertices over the frames.

    Parameters
    ----------
    vertices : (n, 3) rest positions; faces : (m, 3).
    displacements : (T, n, 3) the motion's displacements from rest.
    reach : the distance that counts as touching, a fraction of the diagonal.

    Returns
    -------
    The ratio (0 when pieces move together; NaN for a mesh whose pieces nowhere touch or a
    still motion).
    """
    vertices = np.asarray(vertices, dtype=np.float64)
    faces = np.asarray(faces, dtype=np.int64)
    count, labels = components(len(vertices), faces)
    if count < 2:
        return float("nan")
    diagonal = bounding_box_diagonal(vertices)
    used = np.flatnonzero(np.bincount(faces.ravel(), minlength=len(vertices)) > 0)
    touching = closest_on_others(vertices, faces, labels, used,
                                 np.full(len(used), reach * diagonal))
    motion = np.sqrt(np.mean(np.sum(np.asarray(displacements)[:, used] ** 2, axis=-1)))
    if not len(touching) or not motion > 0:
        return float("nan")
    change = displacements[:, touching.vertices] - touching.gather(displacements)
    return float(np.sqrt(np.mean(np.sum(change ** 2, axis=-1))) / motion)
