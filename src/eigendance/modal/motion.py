"""Modal motion: music-driven mode coefficients, body poses, skinned vertices
(docs/design.md#modal-motion).

The coefficient of vibration mode κ at time t (thesis 6-2 with a time scale s and an offset b):

    c_κ(t) = φ_κ(t) · μ_κ · sin(2π ν_κ s t + γ_κ),   φ_κ(t) = gain·a(κ) · Σ_{ξ: κ(ξ)=κ} g̃(ξ, t) + b,

where φ is the same filter as the harmonics' (`Mapping.filter`, from the same `Spectrogram`)
over the palette's selected modes instead of harmonics, and μ, γ, s come from the palette
(`eigendance.modal.palette`). b = 0 (the default) makes silence the rest pose. Modes outside
the palette have c = 0. `rig_coefficients` is the one definition that the command line, the
web page and the exports reproduce. Body b's twist p̂_b = Σ_κ c_κ η_κ^b = [θ; x] in its body
frame moves it exactly: rotation exp([θ]×) about its centre of mass, then translation x.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from eigendance.errors import InputError
from eigendance.modal.model import ModalModel
from eigendance.modal.palette import (
    Palette,
    lock_ratios,
    locked_phases,
    mode_reach,
    resolve_palette,
    single_mode_amplitudes,
)
from eigendance.modal.rotations import rotation_exp
from eigendance.music.envelope import Envelope
from eigendance.music.mapping import Mapping
from eigendance.music.mode_settings import ModeSettings
from eigendance.music.spectrogram import Spectrogram
from eigendance.writes import atomic_save_npz

DRIVE_ATTACK, DRIVE_RELEASE = 0.15, 0.8  # s: the default mapping's envelope (a slow swell)


def mode_coefficients(model: ModalModel, times, amplitudes=None, phases=None,
                      time_scale: float = 1.0, drive=None, modes=None,
                      beat=None) -> np.ndarray:
    """c_κ(t) = φ_κ(t)·μ_κ·sin(2πν_κ s t + γ_κ): the kernel of the motion.

    Parameters
    ----------
    model : the rig's modes.
    times : (T,) s.
    amplitudes : μ per mode (nm,) in coefficient units; default each mode alone at its default
        bend (`palette.single_mode_amplitudes`).
    phases : γ (nm,) radians; default 0.
    time_scale : s.
    drive : φ, (T, nm) (or (T, len(modes)) when `modes` is given); default 1.
    modes : indices of the modes that move (others get c = 0); default all.
    beat : None (free-running), or (B(t) (T,) in beats, tempo in BPM[, accent (T,)]): the
        tempo lock (docs/design.md#tempo-lock): the angle is 2π r_κ B(t) + γ′_κ, r_κ =
        `lock_ratios`, γ′ = `locked_phases`, c times the accent (`Rhythm.downbeat_accent`).

    Returns
    -------
    (T, nm) coefficients.
    """
    times = np.asarray(times, dtype=float).reshape(-1)
    count = model.n_modes
    selected = np.arange(count) if modes is None else np.asarray(modes, dtype=int)
    if selected.size and (selected.min() < 0 or selected.max() >= count):
        raise InputError(f"mode index out of range: the model has {count} vibration modes "
                         f"(0 … {count - 1})")
    amplitudes = single_mode_amplitudes(model) / mode_reach(model) if amplitudes is None else \
        np.broadcast_to(np.asarray(amplitudes, dtype=float), (count,))
    phases = np.zeros(count) if phases is None else \
        np.broadcast_to(np.asarray(phases, dtype=float), (count,))
    result, accent = np.zeros((times.size, count)), ()
    if beat is None:
        argument = 2 * math.pi * model.frequencies[selected] * time_scale * times[:, None] \
            + phases[selected]
    else:
        phase, tempo, *accent = beat
        ratios = lock_ratios(model.frequencies[selected], time_scale, tempo)
        argument = 2 * math.pi * ratios * np.asarray(phase, dtype=float).reshape(-1, 1) \
            + locked_phases(phases[selected])
    values = amplitudes[selected] * np.sin(argument)
    if accent:
        values = values * np.asarray(accent[0], dtype=float).reshape(-1, 1)
    if drive is not None:
        drive = np.asarray(drive, dtype=float)
        if drive.shape == (times.size, count) and modes is not None:
            drive = drive[:, selected]
        if drive.shape != values.shape:
            raise InputError(f"the drive has shape {drive.shape}; expected {values.shape} "
                             "(frames, modes)")
        values = values * drive
    result[:, selected] = values
    return result


def mapping_palette(model: ModalModel, mapping: Mapping | None) -> Palette:
    """The palette a mapping plays on this model: its `modes`, completed by the default rule.

    Parameters
    ----------
    model : the rig's modes.
    mapping : a mapping, or None.

    Returns
    -------
    Palette.
    """
    return resolve_palette(model, mapping.modes if mapping is not None else None)


def rig_coefficients(model: ModalModel, spectrogram: Spectrogram | None,
                     mapping: Mapping | None, times) -> np.ndarray:
    """Mode coefficients (T, nm) of a rig dancing to a song (docs/design.md#modal-motion).

    Parameters
    ----------
    model : the rig's modes.
    spectrogram : the song's g̃, or None for steady motion (φ ≡ 1: music off).
    mapping : transfer, amplification, gain, smoothing, offset b and palette (`modes`); None
        is `default_mapping(spectrogram, k)` with the default palette.
    times : (T,) seconds.

    Returns
    -------
    c (T, nm): for the palette's selected modes κ_0 < κ_1 < … < κ_{k−1} (the mapping's k
    targets), c_{κ_ν}(t) = φ_ν(t)·μ_ν·sin(2π ν_{κ_ν} s t + γ_ν) with φ = `mode_drive`; 0 for
    the other modes.

    Example
    -------
    >>> from eigendance.modal.sample_rigs import sample_rig
    >>> model = ModalModel.from_skeleton(sample_rig("loop8"))
    >>> c = rig_coefficients(model, None, None, np.linspace(0, 1, 5))
    >>> c.shape, bool(np.all(c[0] == 0))          # sin(γ) with γ_0 = 0 … and the others not 0
    ((5, 5), False)

    With a song whose spectrogram holds beats, the default palette (or `modes.tempo` "beat")
    locks to them (`tempo_lock`); `modes.tempo` "free" keeps the free-running sinusoids.
    """
    times = np.asarray(times, dtype=float).reshape(-1)
    palette = mapping_palette(model, mapping)
    k = len(palette.selected)
    if spectrogram is None:
        drive = np.ones((times.size, k))
    else:
        mapping = mapping if mapping is not None else default_mapping(spectrogram, k)
        drive = mode_drive(mapping, spectrogram, times, k)
    amplitudes = np.zeros(model.n_modes)
    phases = np.zeros(model.n_modes)
    amplitudes[palette.selected] = palette.coefficient_amplitudes(model)
    phases[palette.selected] = palette.phases
    return mode_coefficients(model, times, amplitudes, phases, palette.time_scale, drive,
                             palette.selected, tempo_lock(spectrogram, mapping, times))


def tempo_lock(spectrogram: Spectrogram | None, mapping: Mapping | None, times):
    """The tempo lock of a dance (docs/design.md#tempo-lock), or None (free-running).

    It locks when the palette's `tempo` is "beat" or unset and the song has beats (4 or more).

    Parameters
    ----------
    spectrogram : the song, or None (no song: free-running).
    mapping : the mapping played (its `modes.tempo`), or None.
    times : (T,) s of the song.

    Returns
    -------
    (B(t) (T,) in beats, tempo in BPM, the accent (T,) `Rhythm.downbeat_accent`), or None.
    """
    rhythm = getattr(spectrogram, "rhythm", None)
    settings = mapping.modes if mapping is not None else None
    if settings is not None and settings.tempo == "free":
        return None
    if rhythm is None or not rhythm.has_beats:
        return None
    return rhythm.beat_phase(times), rhythm.tempo, rhythm.downbeat_accent(times)


def twists(model: ModalModel, coefficients) -> np.ndarray:
    """Body twists [θ; x] in body frames, (T, n_b, 6), for coefficients (T, nm).

    Parameters
    ----------
    model : the rig's modes.
    coefficients : (T, nm).

    Returns
    -------
    (T, n_b, 6).
    """
    coefficients = np.atleast_2d(np.asarray(coefficients, dtype=float))
    return (coefficients @ model.modes.T).reshape(len(coefficients), model.n_bodies, 6)


def body_poses(model: ModalModel, coefficients) -> tuple[np.ndarray, np.ndarray]:
    """World rotations (T, n_b, 3, 3) and centres (T, n_b, 3) of every body: rotation
    exp([θ]×) about the centre of mass, then translation x, both in the body frame.

    Parameters
    ----------
    model : the rig's modes.
    coefficients : (T, nm).

    Returns
    -------
    rotations (T, n_b, 3, 3), centres (T, n_b, 3).
    """
    twist = twists(model, coefficients)
    rotations = model.body_rotations[None] @ rotation_exp(twist[..., :3])
    centers = model.body_centers[None] + np.einsum("bij,tbj->tbi", model.body_rotations,
                                                   twist[..., 3:])
    return rotations, centers


def body_transforms(model: ModalModel, coefficients=None, poses=None) -> np.ndarray:
    """World transforms (T, n_b, 4, 4) taking rest-pose points to posed points.

    From the coefficients, or from `poses` = body_poses(model, coefficients) already computed.

    Parameters
    ----------
    model : the rig's modes.
    coefficients : (T, nm), or None when `poses` is given.
    poses : (rotations, centres) of `body_poses`, or None.

    Returns
    -------
    (T, n_b, 4, 4).
    """
    rotations, centers = poses if poses is not None else body_poses(model, coefficients)
    linear = rotations @ np.swapaxes(model.body_rotations, -1, -2)[None]
    transforms = np.zeros(linear.shape[:2] + (4, 4))
    transforms[..., :3, :3] = linear
    transforms[..., :3, 3] = centers - np.einsum("tbij,bj->tbi", linear, model.body_centers)
    transforms[..., 3, 3] = 1
    return transforms


def band_mapping(bands: int, n_modes: int) -> Mapping:
    """The default mapping of bands onto modes: in order, in contiguous groups.

    Band ξ drives the mode ⌊(ξ + ½)·nm/B⌋ (low sounds drive low modes), each with the
    amplification nm/B, so that a full-scale spectrum gives φ ≈ 1 on every mode that a band
    reaches. The loudness swells (attack DRIVE_ATTACK, release DRIVE_RELEASE): the sway's
    amplitude follows the music while its turning points stay the sinusoids' (on the beats,
    docs/design.md#tempo-lock), not every drum hit's.

    Parameters
    ----------
    bands : B.
    n_modes : nm, the targets.

    Returns
    -------
    Mapping named "bands in order".
    """
    transfer = (np.arange(bands) + 0.5) / bands
    return Mapping(transfer, np.array([n_modes / bands]), name="bands in order",
                   envelope=Envelope([DRIVE_ATTACK], [DRIVE_RELEASE], [0.0]))


def song_calibrated(mapping: Mapping, spectrogram: Spectrogram, n_modes: int) -> Mapping:
    """The mapping with its amplification scaled so that the song's loudest frame drives the
    most driven of n_modes targets at |φ − b| = 1 (docs/design.md#modal-motion).

    Unchanged when the song never reaches any target (silence, or a transfer and an
    amplification that never meet).

    Parameters
    ----------
    mapping : the mapping.
    spectrogram : the song.
    n_modes : the mapping's targets.

    Returns
    -------
    Mapping, a new one (or `mapping` itself when unchanged).
    """
    music = mode_drive(mapping, spectrogram, spectrogram.times, n_modes, offset=0.0)
    loudest = float(np.abs(music).max(initial=0.0))
    if not loudest > 1e-12:
        return mapping
    return mapping.with_genes(mapping.transfer, mapping.amplification / loudest, mapping.seed,
                              mapping.name)


def default_mapping(spectrogram: Spectrogram, n_modes: int) -> Mapping:
    """`band_mapping` calibrated to the song (`song_calibrated`): what plays when no mapping
    is given.

    Parameters
    ----------
    spectrogram : the song.
    n_modes : the palette's selected modes.

    Returns
    -------
    Mapping.
    """
    return song_calibrated(band_mapping(spectrogram.bands, n_modes), spectrogram, n_modes)


def rig_mapping(model: ModalModel, spectrogram: Spectrogram | None,
                mapping: Mapping | None = None, selected=None, amplitude: float | None = None,
                time_scale: float | None = None, offset: float | None = None,
                bands: int = 64, tempo: str | None = None) -> Mapping:
    """The complete mapping a rig plays, its palette resolved, with a person's overrides.

    Parameters
    ----------
    model : the rig's modes.
    spectrogram : the song (None: no song; then the mapping's filter has `bands` bands).
    mapping : what to play; None is the default mapping for the song (`default_mapping`).
    selected : mode indices that move instead of the mapping's (their amplitudes and phases
        then follow the default rule).
    amplitude : every selected mode's largest body rotation at φ = 1, radians.
    time_scale : s.
    offset : b.
    bands : the filter's bands when there is neither a song nor a mapping.
    tempo : "beat" (locked to the song's beats, docs/design.md#tempo-lock) or "free" (the
        thesis's free-running sinusoids) instead of the mapping's, or None (the mapping's).

    Returns
    -------
    Mapping whose `modes` holds the resolved palette (`resolve_palette`), ready for
    `rig_coefficients`; the command line, the exports and the page play the same.
    """
    settings = mapping.modes if mapping is not None and mapping.modes is not None \
        else ModeSettings()
    if selected is not None:
        settings = ModeSettings(np.asarray(selected, dtype=np.int64), None, None,
                                settings.time_scale, settings.tempo)
    if amplitude is not None:
        count = len(resolve_palette(model, settings).selected)
        settings = replace(settings, amplitudes=np.full(count, float(amplitude)))
    if time_scale is not None:
        settings = replace(settings, time_scale=float(time_scale))
    if tempo is not None:
        if tempo not in ("beat", "free"):
            raise InputError(f"tempo must be \"beat\" or \"free\", not {tempo!r}")
        settings = replace(settings, tempo=tempo)
    palette = resolve_palette(model, settings)
    if mapping is None:
        mapping = band_mapping(bands, len(palette.selected)) if spectrogram is None else \
            default_mapping(spectrogram, len(palette.selected))
    return replace(mapping, modes=replace(palette.to_settings(), tempo=settings.tempo),
                   offset=mapping.offset if offset is None else float(offset))


def mode_drive(mapping: Mapping, spectrogram: Spectrogram, times, n_modes: int,
               offset: float | None = None) -> np.ndarray:
    """φ (T, n_modes) = gain·a·Σ g̃ + b: the mapping's filter over the modes at `times`.

    b = `offset`, else the mapping's own offset; the song goes through `Mapping.play`
    (smoothing, envelope, pulse).

    Parameters
    ----------
    mapping : the mapping.
    spectrogram : the song.
    times : (T,) s.
    n_modes : the targets.
    offset : b, or None (the mapping's).

    Returns
    -------
    (T, n_modes).
    """
    if mapping.bands != spectrogram.bands:
        raise InputError(f"{mapping.name}: the mapping has {mapping.bands} bands, the song's "
                         f"spectrogram {spectrogram.bands}; analyse the song into "
                         f"{mapping.bands} bands")
    return mapping.play(spectrogram, times, n_modes, mapping.offset if offset is None else offset)


def parse_modes(text: str | None, n_modes: int) -> np.ndarray | None:
    """'0,2,5-8' → sorted indices; None → None (the palette's default selection).

    Parameters
    ----------
    text : the --modes value, or None.
    n_modes : the rig's vibration modes.

    Returns
    -------
    (k,) int64 or None; InputError naming a mode that does not exist.
    """
    if text is None:
        return None
    indices = []
    try:
        for part in text.split(","):
            part = part.strip()
            if "-" in part:
                low, high = (int(v) for v in part.split("-", 1))
                if high >= n_modes or low < 0:
                    raise InputError(f"modes {part}: the rig has {n_modes} vibration modes "
                                     f"(0 … {n_modes - 1})")
                indices.extend(range(low, high + 1))
            elif part:
                indices.append(int(part))
    except InputError:
        raise
    except ValueError:
        raise InputError(f"modes {text!r}: expected indices like 0,2,5-8") from None
    bad = [i for i in indices if not 0 <= i < n_modes]
    if bad:
        raise InputError(f"mode {bad[0]} does not exist (the rig has {n_modes} vibration "
                         f"modes, 0 … {n_modes - 1})")
    if not indices:
        raise InputError("the mode list selects no mode")
    return np.array(sorted(set(indices)))


def save_animation(path, arrays: dict) -> None:
    """Write a rig animation file atomically.

    Parameters
    ----------
    path : the .npz to write.
    arrays : the arrays (`Rig.animation`).
    """
    atomic_save_npz(path, **arrays)
