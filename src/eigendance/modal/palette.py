"""A rig's palette and the default rule that makes any rig dance (docs/design.md#modal-motion).

The palette says which vibration modes move, how much, with which phase and at which time scale
(the mapping file's `modes`, `eigendance.music.mode_settings.ModeSettings`). Every field it leaves
empty is filled by the default rule, chosen so that at a song's loud moments (φ ≈ 1) the bodies
move at 0.5–4 Hz and the most bent joint turns by 5°–45° (less where the floor holds it):

- selection: the lowest modes, at most DEFAULT_MODES, whose frequency is at most MODE_SPREAD
  times the lowest one (they fit into the dancing band together);
- time scale s: the factor closest to 1 that puts the selected natural frequencies inside
  TEMPO_BAND = [0.8, 3.5] Hz; when they spread too wide for that, the factor that centres them
  (geometrically) in it;
- amplitudes: each mode alone at φ = 1 bends its most bent joint by MODE_BEND (25°); then, if the
  selected modes all in phase would bend some joint by more than COMBINED_BEND (40°), all are
  scaled down to that;
- the floor (any amplitudes, given or default): each mode alone, and then all selected modes
  together in their worst phases at φ = 1, sink no skin vertex more than FLOOR_SLACK of the
  diagonal below the floor (`modal.floor`; the page's palette.ts applies the same rule);
- phases: γ_κ = κ·g mod 2π for mode κ, g = π(3 − √5) the golden angle: whatever modes are
  selected, their phases are spread around the circle, so they do not start together.

Units. The coefficient c_κ of mode κ multiplies its M-orthonormal shape η_κ. A joint's *bend*
per unit coefficient is the relative motion of its two bodies, max(|Δθ|, |Δp|/ℓ): Δθ the
difference of their rotation vectors (world frame), Δp the difference of the joint point's
displacement on each (non-zero only for sliding joints), ℓ = REACH_LENGTH·size a limb-sized
length. A palette amplitude A_κ is the *reach* at φ = 1: the largest body rotation, or body
translation over ℓ, in radians; the coefficient amplitude is μ_κ = A_κ / reach_κ.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from eigendance.errors import InputError
from eigendance.modal.model import ModalModel
from eigendance.music.mode_settings import ModeSettings

DEFAULT_MODES = 8  # modes a default palette selects at most
MODE_SPREAD = 4.0  # …whose frequency is at most this times the lowest one
TEMPO_BAND = (0.8, 3.5)  # Hz: where the default time scale puts the selected modes
DANCE_BAND = (0.5, 4.0)  # Hz: the frequencies that read as dancing (the rule's target)
MODE_BEND = math.radians(25)  # largest joint bend of one mode alone at φ = 1
COMBINED_BEND = math.radians(40)  # largest joint bend of the selected modes in phase at φ = 1
REACH_LENGTH = 0.25  # ℓ = REACH_LENGTH · size turns translations into angles
GOLDEN_ANGLE = math.pi * (3 - math.sqrt(5))  # default phase step between modes, radians


@dataclass
class Palette:
    """A resolved palette: every field set (see the module docstring for the units).

    selected (k,) int64 ascending mode indices; amplitudes (k,) reach at φ = 1, radians;
    phases (k,) radians; time_scale s > 0.

    Parameters
    ----------
    selected, amplitudes, phases, time_scale : as above.
    """

    selected: np.ndarray
    amplitudes: np.ndarray
    phases: np.ndarray
    time_scale: float

    def coefficient_amplitudes(self, model: ModalModel) -> np.ndarray:
        """μ (k,) of the selected modes: amplitude / reach.

        Parameters
        ----------
        model : the rig's modes.

        Returns
        -------
        (k,).
        """
        return self.amplitudes / mode_reach(model)[self.selected]

    def to_settings(self) -> ModeSettings:
        """The palette as the mapping file's `modes` field, every value explicit.

        Returns
        -------
        ModeSettings.
        """
        return ModeSettings(self.selected.copy(), self.amplitudes.copy(), self.phases.copy(),
                            float(self.time_scale))


def reach_length(model: ModalModel) -> float:
    """ℓ = REACH_LENGTH · size: the length that turns a translation into an angle.

    Parameters
    ----------
    model : the rig's modes (its size).

    Returns
    -------
    float, the rig's unit.
    """
    return REACH_LENGTH * model.size


def mode_reach(model: ModalModel) -> np.ndarray:
    """(nm,) reach per unit coefficient: max over bodies of max(|θ_b|, |x_b|/ℓ).

    Parameters
    ----------
    model : the rig's modes.

    Returns
    -------
    (nm,) radians per unit coefficient (1 for a mode that moves nothing).
    """
    twists = model.modes.reshape(model.n_bodies, 6, -1)
    rotation = np.linalg.norm(twists[:, :3], axis=1).max(axis=0, initial=0.0)
    translation = np.linalg.norm(twists[:, 3:], axis=1).max(axis=0, initial=0.0)
    reach = np.maximum(rotation, translation / reach_length(model))
    return np.where(reach > 0, reach, 1.0)


def joint_bend(model: ModalModel) -> np.ndarray:
    """(n_j, nm) bend of every joint per unit coefficient of every mode (module docstring).

    Body b's world rotation vector and velocity per unit coefficient: ω_b = R_b θ_b and
    u_b = R_b x_b; the joint point P moves on body b by u_b + ω_b × (P − c_b), so
    Δθ = ω_l − ω_i and Δp = (u_l + ω_l × (P − c_l)) − (u_i + ω_i × (P − c_i)).

    Parameters
    ----------
    model : the rig's modes.

    Returns
    -------
    (n_j, nm) radians per unit coefficient.
    """
    pairs = model.joint_bodies
    if not len(pairs):
        return np.zeros((0, model.n_modes))
    twists = model.modes.reshape(model.n_bodies, 6, -1)
    omega = np.einsum("bij,bjk->bki", model.body_rotations, twists[:, :3])  # (n_b, nm, 3)
    linear = np.einsum("bij,bjk->bki", model.body_rotations, twists[:, 3:])
    first, second = pairs[:, 0], pairs[:, 1]
    point = model.joint_positions

    def moved(body):
        return linear[body] + np.cross(omega[body], (point - model.body_centers[body])[:, None])

    turn = np.linalg.norm(omega[second] - omega[first], axis=-1)
    slide = np.linalg.norm(moved(second) - moved(first), axis=-1) / reach_length(model)
    return np.maximum(turn, slide)


def default_selection(frequencies) -> np.ndarray:
    """The lowest ≤ DEFAULT_MODES modes within MODE_SPREAD times the lowest frequency.

    Parameters
    ----------
    frequencies : (nm,) Hz ascending.

    Returns
    -------
    (k,) int64 mode indices.
    """
    frequencies = np.asarray(frequencies, dtype=float)
    if not len(frequencies):
        return np.zeros(0, dtype=np.int64)
    limit = MODE_SPREAD * frequencies[0]
    count = int(np.sum(frequencies[:DEFAULT_MODES] <= limit))
    return np.arange(max(1, count), dtype=np.int64)


def default_time_scale(frequencies) -> float:
    """s closest to 1 with s·[min ν, max ν] inside TEMPO_BAND, else the geometric centring.

    Parameters
    ----------
    frequencies : the selected modes' natural frequencies, Hz.

    Returns
    -------
    float s.
    """
    frequencies = np.asarray(frequencies, dtype=float)
    positive = frequencies[frequencies > 0]
    if not len(positive):
        return 1.0
    low, high = TEMPO_BAND
    smallest, largest = low / positive.min(), high / positive.max()
    if smallest <= largest:
        return float(np.clip(1.0, smallest, largest))
    return float(math.sqrt(smallest * largest))


def default_phases(selected) -> np.ndarray:
    """γ_κ = κ·g mod 2π for the modes κ, g = π(3 − √5) the golden angle (radians).

    Parameters
    ----------
    selected : (k,) mode indices.

    Returns
    -------
    (k,) radians in [0, 2π).
    """
    return np.mod(np.asarray(selected, dtype=float) * GOLDEN_ANGLE, 2 * math.pi)


def single_mode_amplitudes(model: ModalModel) -> np.ndarray:
    """(nm,) the reach at which each mode alone bends its most bent joint by MODE_BEND.

    Parameters
    ----------
    model : the rig's modes.

    Returns
    -------
    (nm,) radians.
    """
    bend = joint_bend(model).max(axis=0, initial=0.0)
    mu = MODE_BEND / np.where(bend > 0, bend, np.inf)
    mu = np.where(bend > 0, mu, MODE_BEND)  # a mode that bends nothing: reach MODE_BEND
    return mu * mode_reach(model)


def default_amplitudes(model: ModalModel, selected) -> np.ndarray:
    """(k,) reach of the selected modes: MODE_BEND each, capped together at COMBINED_BEND.

    Parameters
    ----------
    model : the rig's modes.
    selected : (k,) mode indices.

    Returns
    -------
    (k,) radians.
    """
    selected = np.asarray(selected, dtype=np.int64)
    amplitudes = single_mode_amplitudes(model)[selected]
    mu = amplitudes / mode_reach(model)[selected]
    together = (joint_bend(model)[:, selected] * mu).sum(axis=1).max(initial=0.0)
    if together > COMBINED_BEND:
        amplitudes = amplitudes * (COMBINED_BEND / together)
    return amplitudes


def default_palette(model: ModalModel) -> Palette:
    """The palette of the default rule (module docstring).

    Parameters
    ----------
    model : the rig's modes (at least one).

    Returns
    -------
    Palette.
    """
    return resolve_palette(model, None)


def resolve_palette(model: ModalModel, settings: ModeSettings | None) -> Palette:
    """The palette of `settings` with every missing field from the default rule.

    The selected modes are taken in ascending order (amplitudes and phases follow them), so
    the mapping's targets ν = 0, 1, … are the selected modes from low to high frequency.
    InputError if a selected mode does not exist in this model.

    Parameters
    ----------
    model : the rig's modes.
    settings : the mapping's `modes`, or None.

    Returns
    -------
    Palette.
    """
    if model.n_modes == 0:
        raise InputError("the rig has no vibration mode (no elastic joint); nothing moves")
    settings = settings or ModeSettings()
    if settings.selected is None:
        selected = default_selection(model.frequencies)
    else:
        selected = np.asarray(settings.selected, dtype=np.int64)
        bad = selected[(selected < 0) | (selected >= model.n_modes)]
        if len(bad):
            raise InputError(f"modes.selected names mode {bad[0]}, but the rig has "
                             f"{model.n_modes} vibration modes (0 … {model.n_modes - 1})")
    order = np.argsort(selected, kind="stable")
    selected = selected[order]
    amplitudes = default_amplitudes(model, selected) if settings.amplitudes is None else \
        _matched(settings.amplitudes, selected, "amplitudes")[order]
    amplitudes = floor_capped(model, selected, amplitudes)
    phases = default_phases(selected) if settings.phases is None else \
        _matched(settings.phases, selected, "phases")[order]
    time_scale = default_time_scale(model.frequencies[selected]) \
        if settings.time_scale is None else float(settings.time_scale)
    return Palette(selected, np.asarray(amplitudes, dtype=float),
                   np.asarray(phases, dtype=float), time_scale)


def floor_capped(model: ModalModel, selected, amplitudes) -> np.ndarray:
    """Amplitudes that keep the skin above the floor (docs/design.md#the-floor): each at most
    its mode's cap alone, then all scaled down together while their worst phases at φ = 1
    would sink a vertex too far (`modal.floor.SkinFloor`; unchanged without a floor).

    Parameters
    ----------
    model : the rig's modes (its `floor`).
    selected : (k,) mode indices.
    amplitudes : (k,) reach, radians.

    Returns
    -------
    (k,) radians.
    """
    amplitudes = np.asarray(amplitudes, dtype=float)
    floor = model.floor
    if floor is None or not len(amplitudes):
        return amplitudes
    reach = mode_reach(model)[selected]
    capped = np.sign(amplitudes) * np.minimum(np.abs(amplitudes), floor.caps()[selected] * reach)
    return capped * floor.scale(selected, capped / reach)


def _matched(values, selected, key: str) -> np.ndarray:
    values = np.asarray(values, dtype=float)
    if values.shape != selected.shape:
        raise InputError(f"modes.{key} has {values.size} values for {len(selected)} selected "
                         "modes")
    return values


# ---------------------------------------------------------------------------------------------
# Tempo lock (docs/design.md#tempo-lock)

LOCK_RATIOS = (0.5, 1.0, 2.0)  # cycles per beat a locked mode may make: half, the beat, double


def lock_ratios(frequencies, time_scale: float, tempo: float) -> np.ndarray:
    """r_κ: the cycles per beat in LOCK_RATIOS nearest (in log frequency) to each mode's
    time-scaled natural frequency s·ν_κ, for a song at `tempo` beats per minute
    (docs/design.md#tempo-lock).

    Parameters
    ----------
    frequencies : (k,) ν_κ, Hz.
    time_scale : s.
    tempo : beats per minute (> 0).

    Returns
    -------
    (k,) cycles per beat, each ½, 1 or 2.

    Example
    -------
    >>> lock_ratios([0.9, 1.8, 5.0], 1.0, 120.0).tolist()    # 2 beats per second
    [0.5, 1.0, 2.0]
    """
    frequencies = np.asarray(frequencies, dtype=float) * time_scale
    ratios = np.asarray(LOCK_RATIOS)
    beat = tempo / 60.0
    distance = np.abs(np.log(np.maximum(frequencies[:, None], 1e-12) / (ratios[None] * beat)))
    return ratios[np.argmin(distance, axis=1)]


def locked_phases(phases) -> np.ndarray:
    """γ snapped to the nearest π/2 + nπ: sin(2π r B + γ) then turns on the beats (r = ½: every
    beat; r = 1: every beat and half-beat; r = 2: every quarter-beat).

    Parameters
    ----------
    phases : (k,) γ, radians.

    Returns
    -------
    (k,) γ′, radians (halves rounded to even, as numpy rounds).
    """
    phases = np.asarray(phases, dtype=float)
    return math.pi / 2 + math.pi * np.round((phases - math.pi / 2) / math.pi)
