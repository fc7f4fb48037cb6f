"""The floor under a rig and how far its modes may move the skin (docs/design.md#the-floor).

The floor is the horizontal plane (y up, as glTF) of the skin's lowest point in the rest pose,
where the page draws the model's contact shadow. Modal skinning is linear, x′ = x + Σ_κ c_κ τ_κ,
so a vertex i sinks at most Σ_κ |c_κ|·|τ_iκ,y| below where it rests: the palette keeps that
within the vertex's *room* y_i − floor + FLOOR_SLACK·diagonal for every vertex, whatever the
phases (`modal.palette.resolve_palette`: each mode alone, then all together at φ = 1). The page
applies the same rule to the same numbers (web/src/floor.ts).

The mode gallery's tiles play each mode alone at an amplitude made to be seen
(`tile_amplitudes`): its largest skin displacement TILE_MOTION of the diagonal, within
TILE_REACH (the largest body rotation of the linearised skin: beyond it a limb visibly
stretches) and the floor.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from eigendance.geometry import bounding_box_diagonal
from eigendance.modal.palette import mode_reach

FLOOR_SLACK = 0.02  # how far (fraction of the skin's diagonal) a limb may sink below the floor
TILE_MOTION = 0.05  # a mode tile's largest skin displacement, fraction of the diagonal
TILE_REACH = math.radians(90)  # …within this largest body rotation (reach), radians


@dataclass
class SkinFloor:
    """What the floor asks of a skin's modes.

    room (n,): how far each vertex may sink, y_i − min y + FLOOR_SLACK·diagonal; sink (n, nm):
    |τ_iκ,y|, how far it sinks per unit coefficient of each mode.

    Parameters
    ----------
    room, sink : as above.

    Example
    -------
    >>> from eigendance.modal.rig import Rig
    >>> from eigendance.modal.sample_rigs import load_rig
    >>> floor = Rig(load_rig("hand")).model.floor
    >>> bool(floor.caps().min() > 0), floor.scale([0], [0.0])
    (True, 1.0)
    """

    room: np.ndarray
    sink: np.ndarray
    _caps: np.ndarray | None = field(default=None, repr=False, compare=False)

    @classmethod
    def of_skin(cls, vertices, displacement) -> SkinFloor:
        """The floor of a skin.

        Parameters
        ----------
        vertices : (n, 3) rest positions, y up.
        displacement : (nm, 3n) τ per mode (`ModalSkin.displacement`).

        Returns
        -------
        SkinFloor.
        """
        vertices = np.asarray(vertices, dtype=float)
        n = len(vertices)
        slack = FLOOR_SLACK * bounding_box_diagonal(vertices)
        room = vertices[:, 1] - vertices[:, 1].min() + slack
        sink = np.abs(np.asarray(displacement).reshape(-1, n, 3)[:, :, 1]).T
        return cls(room, np.ascontiguousarray(sink))

    def caps(self) -> np.ndarray:
        """(nm,) the largest |coefficient| of each mode alone: min_i room_i / |τ_iκ,y|.

        Returns
        -------
        (nm,) coefficient units (inf for a mode that moves nothing up or down).
        """
        if self._caps is None:
            with np.errstate(divide="ignore"):
                self._caps = np.min(np.where(self.sink > 0, self.room[:, None] / self.sink,
                                             np.inf), axis=0, initial=np.inf)
        return self._caps

    def scale(self, selected, coefficients) -> float:
        """The factor (≤ 1) that keeps modes `selected` at |coefficients| above the floor
        together, whatever their phases: min(1, min_i room_i / Σ_κ |μ_κ|·|τ_iκ,y|).

        Parameters
        ----------
        selected : (k,) mode indices.
        coefficients : (k,) μ.

        Returns
        -------
        float in (0, 1].
        """
        selected = np.asarray(selected, dtype=np.int64)
        if not len(selected):
            return 1.0
        sunk = self.sink[:, selected] @ np.abs(np.asarray(coefficients, dtype=float))
        worst = np.max(sunk / self.room, initial=0.0)
        return float(1.0 / worst) if worst > 1 else 1.0


def tile_amplitudes(model, skin, natural) -> np.ndarray:
    """(nm,) the reach each mode tile of the page's gallery plays at (module docstring): its
    largest skin displacement TILE_MOTION·diagonal (never less than `natural`), at most
    TILE_REACH and the floor's cap.

    Parameters
    ----------
    model : the rig's modes (`ModalModel`, its `floor`).
    skin : its `ModalSkin`.
    natural : (nm,) the default rule's amplitude of each mode alone (reach, radians).

    Returns
    -------
    (nm,) radians of reach.
    """
    reach = mode_reach(model)
    n = len(skin.vertices)
    largest = np.linalg.norm(skin.displacement.reshape(-1, n, 3), axis=2).max(axis=1,
                                                                             initial=0.0)
    diagonal = bounding_box_diagonal(skin.vertices)
    with np.errstate(divide="ignore"):
        seen = np.where(largest > 0, TILE_MOTION * diagonal / largest, 0.0) * reach
    amplitudes = np.minimum(np.maximum(np.asarray(natural, dtype=float), seen), TILE_REACH)
    if model.floor is not None:
        amplitudes = np.minimum(amplitudes, model.floor.caps() * reach)
    return amplitudes
