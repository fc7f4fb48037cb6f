"""`Model`: a model file as drawn vertices, parts, materials and, for a glTF with skins, its
joints and weights; `combine` makes one of the pieces a reader found (docs/design.md#appearance).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np

from eigendance.assets.appearance import Appearance, Image, Material, Part
from eigendance.assets.primitives import Piece
from eigendance.assets.scene import SkinTree
from eigendance.errors import InputError, ModelWarning
from eigendance.geometry import vertex_normals


@dataclass
class Model:
    """A model file as drawn (before welding), in the file's coordinates at rest.

    positions (n_d, 3) float64; parts one `Part` per material (triangles into positions);
    materials, images; normals (n_d, 3) (the file's, or computed per piece); uvs one (n_d, 2)
    per UV set; colors (n_d, 4) linear RGBA or None; tangents (n_d, 4) or None; styled: whether
    the file says anything about the look (materials, vertex colours: else the clay look);
    skin: the joints of its skins or None; weights (n_d, n_joints) skin weights (rows of rigid
    pieces and of pieces that hang from a bone: 0, and `bones` says which); bones (n_d,) the
    joint column a rigid piece hangs from, -1 if none; warnings: what was not kept.

    Parameters
    ----------
    name, positions, parts, materials, images, normals, uvs, colors, tangents, styled, skin,
    weights, bones, warnings : as above.
    """

    name: str
    positions: np.ndarray
    parts: list[Part]
    materials: list[Material]
    images: list[Image]
    normals: np.ndarray | None
    uvs: list[np.ndarray]
    colors: np.ndarray | None
    tangents: np.ndarray | None
    styled: bool
    skin: SkinTree | None = None
    weights: np.ndarray | None = None
    bones: np.ndarray | None = None
    warnings: list[str] = field(default_factory=list)

    @property
    def triangles(self) -> np.ndarray:
        """Every part's triangles, one after the other.

        Returns
        -------
        (m, 3) int64 into positions.
        """
        return np.concatenate([part.triangles for part in self.parts]) if self.parts else \
            np.zeros((0, 3), dtype=np.int64)

    def appearance(self, welded: np.ndarray) -> Appearance | None:
        """The look with drawn vertex i on analysis vertex welded[i] (−1: the analysis dropped
        it; such vertices and their triangles leave the drawing); None for a model without a
        look of its own (the clay look).

        Parameters
        ----------
        welded : (n_d,) int64.

        Returns
        -------
        Appearance or None.
        """
        if not self.styled:
            return None
        look = Appearance(np.asarray(welded, dtype=np.int64), self.parts, self.materials,
                          self.images, self.normals, self.uvs, self.colors, self.tangents)
        kept = look.welded >= 0
        return look if kept.all() else look.kept(kept, look.welded)

    def warn(self) -> None:
        """Issue the warnings (once, one line)."""
        if self.warnings:
            warnings.warn(ModelWarning(f"{self.name}: not kept: {'; '.join(self.warnings)}"),
                          stacklevel=3)


def combine(name: str, pieces: list[Piece], materials: list[Material], images: list[Image],
            skin: SkinTree | None = None, problems: list[str] | None = None) -> Model:
    """One `Model` of pieces: their vertices one after the other, one part per material
    (a piece without material takes glTF's default material).

    Parameters
    ----------
    name : the model's name.
    pieces : its pieces.
    materials, images : the file's.
    skin : the joints of its skins, or None.
    problems : what was not kept (warnings), or None.

    Returns
    -------
    Model.
    """
    materials = list(materials)
    offsets = np.cumsum([0] + [len(piece.positions) for piece in pieces])
    by_material: dict[int, list[np.ndarray]] = {}
    for piece, offset in zip(pieces, offsets, strict=False):
        material = piece.material if 0 <= piece.material < len(materials) else -1
        by_material.setdefault(material, []).append(piece.triangles + offset)
    if -1 in by_material:
        materials.append(Material(name="default"))
        by_material[len(materials) - 1] = by_material.pop(-1)
    parts = [Part(material, np.concatenate(triangles).astype(np.int64))
             for material, triangles in sorted(by_material.items())]
    positions = np.concatenate([piece.positions for piece in pieces])
    styled = any(piece.material >= 0 or piece.colors is not None for piece in pieces)
    normals = None
    if styled:  # the clay look needs none: Mesh.from_arrays checks the arrays of the others
        if positions.ndim != 2 or positions.shape[1] != 3 or not np.all(np.isfinite(positions)):
            raise InputError(f"{name}: vertex positions must be finite (n, 3) coordinates")
        normals = np.concatenate([piece.normals if piece.normals is not None else
                                  vertex_normals(piece.positions, piece.triangles)
                                  for piece in pieces])
    model = Model(name, positions, parts, materials, images, normals, _uv_sets(pieces),
                  _colors(pieces), _tangents(pieces), styled, warnings=list(problems or []))
    if skin is not None:
        model.skin = skin
        model.weights = np.concatenate([piece.weights if piece.weights is not None else
                                        np.zeros((len(piece.positions), len(skin.names)))
                                        for piece in pieces])
        model.bones = np.concatenate([np.full(len(piece.positions), piece.bone)
                                      for piece in pieces])
    return model


def _uv_sets(pieces: list[Piece]) -> list[np.ndarray]:
    """Every UV set some piece has; pieces without it read (0, 0)."""
    count = max(len(piece.uvs) for piece in pieces)
    return [np.concatenate([piece.uvs[index] if index < len(piece.uvs) else
                            np.zeros((len(piece.positions), 2)) for piece in pieces])
            for index in range(count)]


def _colors(pieces: list[Piece]) -> np.ndarray | None:
    if all(piece.colors is None for piece in pieces):
        return None
    return np.concatenate([piece.colors if piece.colors is not None else
                           np.ones((len(piece.positions), 4)) for piece in pieces])


def _tangents(pieces: list[Piece]) -> np.ndarray | None:
    if any(piece.tangents is None for piece in pieces):
        return None
    return np.concatenate([piece.tangents for piece in pieces])
