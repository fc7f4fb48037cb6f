"""eigendance: make 3D models dance to music.

Manifold harmonics (Laplacian eigenvectors of a mesh) filtered by the spectrum of a song, and
modal analysis of articulated skeletons driven by the same spectrum; docs/design.md states the
math every module shares. The entry points below are the public API (the README shows them).
"""

from eigendance.errors import EigendanceError, InputError, InternalError
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.mesh import Mesh, load_mesh
from eigendance.harmonic.motion import positions_at
from eigendance.modal.model import ModalModel
from eigendance.modal.motion import rig_coefficients
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import load_rig
from eigendance.modal.skeleton import Skeleton
from eigendance.modal.skinning import ModalSkin, linear_blend_skinning
from eigendance.music.breeding import breed
from eigendance.music.gallery import initial_gallery
from eigendance.music.mapping import Mapping
from eigendance.music.spectrogram import Spectrogram

__all__ = [
    "EigendanceError", "HarmonicBasis", "InputError", "InternalError", "Mapping", "Mesh",
    "ModalModel", "ModalSkin", "Rig", "Skeleton", "Spectrogram", "breed", "initial_gallery",
    "linear_blend_skinning", "load_mesh", "load_rig", "positions_at", "rig_coefficients",
]
__version__ = "0.2.0"
