"""eigendance: make 3D models dance to music.

Manifold harmonics (Laplacian eigenvectors of a mesh) filtered by the spectrum of a song, and
modal analysis of articulated skeletons; see DESIGN.md for the math every module shares.
"""

from eigendance.errors import EigendanceError
from eigendance.harmonics import HarmonicBasis
from eigendance.mesh import Mesh, load_mesh

__all__ = ["EigendanceError", "HarmonicBasis", "Mesh", "load_mesh"]
__version__ = "0.1.0"
