"""Stiffness L and mass M of a triangle mesh (docs/design.md#laplacian).

L is symmetric positive semi-definite with L_ij = -(cot α + cot β)/2 on edges and zero row sums;
M = diag(A_i) with A_i the mixed Voronoi area of vertex i (Meyer et al. 2003). Units: on a mesh
normalised into [-1, 1]^3, eigenvalues of L u = λ M u are in (length)^-2, so a unit sphere gives
λ ≈ l(l+1). "robust" uses the intrinsic-Delaunay Laplacian of Sharp & Crane 2020, which also
handles non-manifold meshes (its mass is the barycentric lumped area).
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from eigendance.errors import InputError

LAPLACIANS = ("cotan", "robust")


def laplacian(vertices: np.ndarray, faces: np.ndarray,
              kind: str = "cotan") -> tuple[sp.csc_matrix, np.ndarray]:
    """Return (L, mass): L sparse (n, n) PSD stiffness, mass (n,) vertex areas.

    Parameters
    ----------
    vertices : (n, 3).
    faces : (m, 3).
    kind : "cotan" or "robust".

    Returns
    -------
    (L, mass).
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
    return stiffness.tocsc(), mass
