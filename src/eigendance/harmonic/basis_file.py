"""The fields of a basis file, read and checked (docs/design.md#basis-file).

`HarmonicBasis.load` builds the basis from them and checks that its coefficients and remainder
follow from its vertices and eigenvectors.
"""

from __future__ import annotations

import numpy as np

from eigendance.errors import InputError
from eigendance.files import checked_array, load_npz
from eigendance.harmonic.laplacian import LAPLACIANS
from eigendance.harmonic.reduced import (
    ASKED_KEY,
    REDUCED_KEYS,
    check_reduced,
    reduced_from_arrays,
)

FORMAT_KEYS = ("vertices", "faces", "center", "scale", "mass", "eigenvalues", "eigenvectors",
               "coefficients", "residual", "laplacian")
# A reduced basis file holds REDUCED_KEYS instead of the eigenvectors.
COMMON_KEYS = tuple(name for name in FORMAT_KEYS if name != "eigenvectors")


def read_fields(path: str) -> dict:
    """The fields of a basis file, each checked: a missing field, a wrong type or shape, NaN,
    faces past the vertices, a Laplacian of another name, a scale or mass that is not positive.

    Parameters
    ----------
    path : a basis file (.npz).

    Returns
    -------
    dict: `HarmonicBasis`'s fields (eigenvectors None and `reduced` set for a reduced basis).

    Raises
    ------
    InputError
        Naming the file and the field.
    """
    data = load_npz(path, COMMON_KEYS)
    fields = {"vertices": checked_array(data, "vertices", path, shape=(None, 3)),
              "eigenvalues": checked_array(data, "eigenvalues", path, shape=(None,))}
    n, k = len(fields["vertices"]), len(fields["eigenvalues"])
    if n < 3 or k < 1:
        raise InputError(f"{path}: a basis needs at least 3 vertices and 1 harmonic, "
                         f"has {n} and {k}")
    for name, shape in (("center", (3,)), ("scale", ()), ("mass", (n,)),
                        ("coefficients", (k, 3)), ("residual", (n, 3))):
        fields[name] = checked_array(data, name, path, shape=shape)
    fields["faces"] = faces = checked_array(data, "faces", path, "int", (None, 3))
    fields["laplacian"] = checked_array(data, "laplacian", path, "str")
    fields["scale"] = float(fields["scale"])
    if len(faces) == 0 or faces.min() < 0 or faces.max() >= n:
        raise InputError(f"{path}: faces must be triangles of vertex indices 0 … {n - 1}")
    if fields["laplacian"] not in LAPLACIANS:
        raise InputError(f"{path}: laplacian must be one of {', '.join(LAPLACIANS)}")
    if not fields["scale"] > 0 or not np.all(fields["mass"] > 0):
        raise InputError(f"{path}: scale and mass must be positive")
    fields["eigenvectors"], fields["reduced"] = _load_vectors(data, path, n, k)
    return fields


def _load_vectors(data: dict, path: str, n: int, k: int):
    """(eigenvectors, None) of an exact basis file or (None, ReducedHarmonics) of a reduced
    one, checked."""
    if "eigenvectors" in data:
        return checked_array(data, "eigenvectors", path, shape=(n, k)), None
    missing = [name for name in REDUCED_KEYS if name not in data]
    if missing:
        raise InputError(f"{path}: missing eigenvectors (or {', '.join(missing)} of a reduced "
                         "basis); not an eigendance basis file")
    arrays = {"samples": checked_array(data, "samples", path, "int", (None,)),
              "interpolation_indices": checked_array(data, "interpolation_indices", path,
                                                     "int", (n, None)),
              "interpolation_weights": checked_array(data, "interpolation_weights", path,
                                                     shape=(n, None)),
              "coarse_eigenvectors": checked_array(data, "coarse_eigenvectors", path,
                                                   shape=(None, k))}
    if ASKED_KEY in data:  # files written before it was kept lack it
        arrays[ASKED_KEY] = asked = checked_array(data, ASKED_KEY, path, "int", ())
        if not asked > k:
            raise InputError(f"{path}: {ASKED_KEY} must be above k = {k}, not {int(asked)}")
    problem = check_reduced(arrays, n, k)
    if problem:
        raise InputError(f"{path}: reduced basis: {problem}")
    return None, reduced_from_arrays(arrays)
