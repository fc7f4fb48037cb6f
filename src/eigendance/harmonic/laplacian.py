"""Stiffness L and mass M of a triangle mesh (docs/design.md#laplacian).

L is symmetric positive semi-definite with L_ij = -(cot α + cot β)/2 on edges and zero row sums;
M = diag(A_i) with A_i the mixed Voronoi area of vertex i (Meyer et al. 2003). Units: on a mesh
normalised into [-1, 1]^3, eigenvalues of L u = λ M u are in (length)^-2, so a unit sphere gives
λ ≈ l(l+1). "robust" uses the intrinsic-Delaunay Laplacian of Sharp & Crane 2020, which also
handles non-manifold meshes (its mass is the barycentric lumped area).

A mesh of several pieces is coupled where its pieces touch (`harmonic.contacts`): each contact
of vertex i with the point p = Σ_k β_k x_k of another piece adds the spring w (u_i − Σ_k β_k
u_k)² to the energy uᵀLu, w = CONTACT_STIFFNESS times the median edge weight of the mesh (a
penalty: the contact acts as a weld), so touching pieces move as one surface and L's kernel is
one constant per *coupled* component. The mass stays the surface's.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from eigendance.errors import InputError
from eigendance.harmonic.contacts import Contacts, contacts

LAPLACIANS = ("cotan", "robust")
# Stiffness of a contact spring, in units of the mesh's median edge weight |L_ij|: a penalty
# that makes a contact act as a weld. Measured (benchmarks/bench_parts.py, k = 150, the 8 items
# of the initial gallery): at 1 touching pieces still drift by up to 0.95 of the motion (the
# highest harmonics stretch the springs), at 10 up to 0.86, at 10⁴ at most 0.18; the springs'
# own modes then lie far above the harmonics a gallery drives.
CONTACT_STIFFNESS = 1e4


def laplacian_for(mesh) -> str:
    """The Laplacian a mesh dances with when none is asked for: "robust" when it has
    non-manifold edges (the cotangent Laplacian refuses them), else "cotan" (the thesis's).

    Parameters
    ----------
    mesh : a `Mesh`.

    Returns
    -------
    str, one of LAPLACIANS.
    """
    return "robust" if mesh.non_manifold_edge_count() else "cotan"


def laplacian(vertices: np.ndarray, faces: np.ndarray, kind: str = "cotan",
              found: Contacts | None = None) -> tuple[sp.csc_matrix, np.ndarray]:
    """The operator of the harmonics: (L, mass), L sparse (n, n) PSD stiffness with the
    pieces coupled where they touch, mass (n,) vertex areas.

    Parameters
    ----------
    vertices : (n, 3) normalised positions; faces : (m, 3) triangles.
    kind : "cotan" or "robust".
    found : where the pieces touch (default: `contacts.contacts` of the mesh).

    Returns
    -------
    L (n, n) csc, symmetric, zero row sums; mass (n,) positive.
    """
    if kind == "cotan":
        import igl  # heavy (≈0.4 s): imported when a Laplacian is built

        stiffness = -igl.cotmatrix(vertices, faces)
        mass = igl.massmatrix(vertices, faces, igl.MASSMATRIX_TYPE_VORONOI).diagonal()
    elif kind == "robust":
        import robust_laplacian  # optional path: imported only when asked for

        stiffness, mass_matrix = robust_laplacian.mesh_laplacian(
            np.ascontiguousarray(vertices), np.ascontiguousarray(faces))
        mass = mass_matrix.diagonal()
    else:
        raise InputError(f"unknown Laplacian '{kind}' (expected one of {', '.join(LAPLACIANS)})")
    stiffness = sp.csc_matrix(stiffness, dtype=np.float64)
    stiffness = (stiffness + stiffness.T) / 2  # exact symmetry for the symmetric solvers
    mass = np.asarray(mass, dtype=np.float64)
    if not (np.all(np.isfinite(mass)) and np.all(mass > 0) and np.all(np.isfinite(stiffness.data))):
        raise InputError("the Laplacian has non-finite entries or vertices without area",
                         remedy={"laplacian": "robust"})
    if found is None:
        found = contacts(vertices, faces)
    if len(found):
        stiffness = stiffness + coupling(found, len(vertices), _edge_weight(stiffness))
    return stiffness.tocsc(), mass


def coupling(found: Contacts, n: int, weight: float) -> sp.csc_matrix:
    """Σ over contacts of weight·CONTACT_STIFFNESS·g gᵀ, g = e_i − Σ_k β_k e_(face k): the
    springs between touching pieces (n, n), symmetric PSD, zero row sums.

    Parameters
    ----------
    found : the contacts.
    n : vertices.
    weight : the typical edge weight the springs scale.

    Returns
    -------
    (n, n) csc.
    """
    terms = np.column_stack([np.ones(len(found)), -found.weights])  # (c, 4)
    nodes = np.column_stack([found.vertices, found.faces])
    values = weight * CONTACT_STIFFNESS * terms[:, :, None] * terms[:, None, :]
    rows = np.repeat(nodes[:, :, None], 4, axis=2)
    return sp.coo_matrix((values.ravel(), (rows.ravel(), rows.transpose(0, 2, 1).ravel())),
                         shape=(n, n)).tocsc()


def _edge_weight(stiffness: sp.spmatrix) -> float:
    """The median |L_ij| over the mesh's edges (i ≠ j)."""
    off = sp.triu(stiffness, k=1).tocoo()
    weights = np.abs(off.data[off.data != 0])
    return float(np.median(weights)) if len(weights) else 1.0
