"""The initial gallery: S mappings to choose from before any breeding (docs/design.md#gallery).

Every item drives its own *part* of the model's spectrum, from the lowest harmonic to the
highest, and is calibrated on the song that will play so that it moves the model visibly:
m = the 95th percentile over the song's frames of (RMS vertex displacement / bounding-box
diagonal) is MOTION_LOWEST for the first item, falling geometrically to MOTION_HIGHEST for the
last, unless that would stretch an edge of the surface more than PEAK_STRAIN (a coarse model's
top harmonics) or fold more than FOLD_SHARE of its area over (a crumpled tile): the item then
moves less. Harmonics of eigenvalue 0 (translations) and
harmonics that carry none of the shape (their coefficient is rounding noise) are never driven.

A gallery works on any *dancer* — the harmonics of a mesh, the vibration modes of a rig —
through the `Dancer` protocol (`music.dancer`, with the measures of motion on a song). Sizes
follow one rule, shared by the library, the command line, the server and the page:
`check_gallery_size`.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

from eigendance.errors import InputError
from eigendance.music.dancer import (
    Dancer,
    frame_motion,
    full_scale_motion,
    gallery_motion,
    motion_gram,
    song_times,
    surface_caps,
)
from eigendance.music.envelope import Envelope, Pulse
from eigendance.music.mapping import Mapping

MIN_GALLERY, MAX_GALLERY, DEFAULT_GALLERY = 2, 16, 8
# Target m of the lowest and the highest item (fractions of the bounding-box diagonal); items in
# between fall geometrically. High harmonics are fine ripples: at the same RMS they read as noise.
MOTION_LOWEST, MOTION_HIGHEST = 0.04, 0.015
# What every initial item's m is promised to lie in (its lower end gives way to PEAK_STRAIN and
# FOLD_SHARE: an item capped by either moves less, at least a fifth of it in the tests).
MOTION_BOUNDS = (0.01, 0.08)
PEAK_MOTION = 0.15  # no frame of the song moves an item more (a song loud only for a moment)
# Nor changes any edge's length by more than this many times its rest length (`edge_strain`),
# measured on the STRAIN_FRAMES frames that move it most: on a coarse model (the low-poly cake
# of 552 vertices, the speeder of 163, k = 150) the top harmonics are a vertex or two zig-zagging,
# and an item calibrated on RMS motion alone flung them out to 16 and 14 times their edges (tiles
# that tore into spikes and facets). The top items of the smooth shared meshes reach 2 to 4.3.
PEAK_STRAIN, STRAIN_FRAMES = 3.0, 16
# Nor, in those frames, fold over (turn a face past edge-on: `fold_scale`) more than this share
# of the surface's area. The strain cap alone let triangles invert (a change of one rest length
# collapses an edge): on vibe ace the items 6–8 folded 1–5% of the area of the cake, speeder,
# teapot and cat past 90° (tiles that crumpled into facets); a share, not every face, because
# slivers of a fan-triangulated low-poly model turn under any motion.
FOLD_SHARE = 1e-3
# ω_ν ≤ this · ω_max (λ_ν ≤ 10⁻⁸ λ_max): eigenvalue 0, a translation of a component. At 10⁻⁶
# the kernel of an operator stiffened by its contacts passed for a harmonic (the textured speeder:
# λ₀ = 4.5·10⁻⁹, 3·10⁻¹² λ_max; its tile #1 slid the whole model); the smallest true ω₁ of the
# shared models is above 10⁻² ω_max.
ZERO_FREQUENCY = 1e-4
# A harmonic moving the model less than this · the largest carries only rounding: of the
# arithmetic (1e-15) or of the file's coordinates (6 to 7 significant digits in OBJ, PLY, STL).
CONTENT_FLOOR = 1e-6
GRAM_CHUNK = 64  # harmonics per block when only the diagonal of the Gram matrix is needed
# Items that pulse on the beat (`beat_shaping`): the loudness's attack and release (s), the
# kick's decay (s) and its size against the loud frames' band sum.
PULSE_ATTACK, PULSE_RELEASE, PULSE_DECAY, PULSE_SHARE = 0.1, 0.5, 0.18, 1.0
# Every fourth item (s ≡ 3 mod 4) of a song with sections changes its dance at each: its
# section gene (`Mapping.sections`) alternates a quieter and a bigger part, as a music video's
# verse and chorus; the calibration then holds the whole song's motion to the item's target.
SECTION_GENE, SECTION_EVERY = (0.6, 1.4), 4


def check_gallery_size(size) -> int:
    """The gallery size as an int; InputError unless it is an integer in [MIN, MAX].

    Parameters
    ----------
    size : the size asked for (anything).

    Returns
    -------
    int.
    """
    if isinstance(size, bool) or not isinstance(size, int | np.integer) or \
            not MIN_GALLERY <= size <= MAX_GALLERY:
        raise InputError(f"a gallery has {MIN_GALLERY} to {MAX_GALLERY} items; got {size!r}")
    return int(size)


# ---------------------------------------------------------------------------------------------
# Which harmonics can move the model, and how the gallery splits them


def motion_content(dancer: Dancer) -> np.ndarray:
    """c_ν = RMS over the vertices of D_ν, the motion of target ν per unit of φ_ν − 1 (k,).

    Parameters
    ----------
    dancer : the model.

    Returns
    -------
    (k,).
    """
    k = len(dancer.frequencies)
    blocks = [np.diag(motion_gram(dancer, np.arange(start, min(k, start + GRAM_CHUNK))))
              for start in range(0, k, GRAM_CHUNK)]
    return np.sqrt(np.maximum(np.concatenate(blocks), 0.0))


def drivable_harmonics(dancer: Dancer, content: np.ndarray | None = None) -> np.ndarray:
    """The targets a gallery may drive, ascending (int64): eigenvalue > 0 (ω_ν above
    ZERO_FREQUENCY·ω_max) and a motion c_ν above CONTENT_FLOOR times the largest one.

    Parameters
    ----------
    dancer : the model.
    content : `motion_content(dancer)`, or None.

    Returns
    -------
    (N,) int64; InputError (remedy more harmonics) when none is.
    """
    frequencies = np.maximum(np.asarray(dancer.frequencies, dtype=np.float64), 0.0)
    if not len(frequencies) or not frequencies.max() > 0:
        raise InputError("the model has no harmonic of non-zero frequency: nothing can make it "
                         "dance", remedy={"k": max(2 * len(frequencies), 8)})
    content = motion_content(dancer) if content is None else content
    moving = frequencies > ZERO_FREQUENCY * frequencies.max()
    largest = content[moving].max() if moving.any() else 0.0
    drivable = moving & (content > CONTENT_FLOOR * largest) & (largest > 0)
    if not drivable.any():
        raise InputError("no harmonic of the model moves it (its shape has no component on "
                         "them)", remedy={"k": 2 * len(frequencies)})
    return np.flatnonzero(drivable)


@dataclass
class Part:
    """The part of the spectrum one initial item drives.

    harmonics: the targets its transfer reaches, ascending; unit: its amplification on them
    before calibration (signed); home: the targets whose amplification it calibrates for every
    item (its own range); profile: the unit magnitude on `home`; order: how its transfer spreads
    the bands over `harmonics` ("direct": low bands to low harmonics, "reversed", or
    "interleaved": band ξ to harmonic ξ mod w).

    Parameters
    ----------
    harmonics, unit, home, profile, order : as above.
    """

    harmonics: np.ndarray
    unit: np.ndarray
    home: np.ndarray
    profile: np.ndarray
    order: str


def geometric_starts(count: int, parts: int) -> np.ndarray:
    """Start positions of `parts` consecutive groups of `count` ≥ `parts` items, each at least
    one long, lengths growing geometrically: start_i ≈ (count + 1)^(i/parts) − 1.

    Parameters
    ----------
    count : items.
    parts : groups.

    Returns
    -------
    (parts,) int64 ascending, the first 0.
    """
    starts = np.round((count + 1.0) ** (np.arange(parts) / parts) - 1).astype(np.int64)
    for i in range(1, parts):  # at least one item per group, room left for the later ones
        starts[i] = min(max(starts[i], starts[i - 1] + 1), count - (parts - i))
    return starts


def ranged_parts(drivable: np.ndarray, size: int) -> list[Part]:
    """Parts over contiguous ranges of the drivable list P (N ≥ S of them).

    Item 0 sends every band to P[0] and item S−1 to P[N−1] (thesis ε = 0: constant maps to the
    lowest and the highest frequency, so crossings reach any transfer); items 1…S−2 split
    P[1:N−1] into geometrically growing ranges, their bands spread over them, direct and reversed
    in turn. Item s's sign is (−1)^s; its amplification is flat on its range (a band-pass).

    Parameters
    ----------
    drivable : (N,) the drivable targets.
    size : S.

    Returns
    -------
    list of S parts.
    """
    count = len(drivable)
    bounds = [0, count - 1]
    if size > 2:
        bounds = [0, *(1 + geometric_starts(count - 2, size - 2)), count - 1]
    bounds.append(count)
    parts = []
    for s in range(size):
        home = drivable[bounds[s]:bounds[s + 1]]
        reached = home[:1] if s == 0 else home[-1:] if s == size - 1 else home
        sign = 1.0 if s % 2 == 0 else -1.0
        parts.append(Part(reached, np.full(len(reached), sign), home, np.ones(len(home)),
                          "direct" if s % 2 else "reversed"))
    return parts


def combined_parts(drivable: np.ndarray, content: np.ndarray, size: int) -> list[Part]:
    """Parts for a model with fewer drivable harmonics N than items S (a sphere, a small k).

    The items are the single harmonics, then signed pairs, then signed triples … (first sign the
    item's (−1)^s), each harmonic equalised to the same motion per unit (amplification 1/c_ν), its
    bands interleaved: two such items correlate at most √(2/3) when their loudness is alike.

    Parameters
    ----------
    drivable : (N,) the drivable targets.
    content : (k,) `motion_content`.
    size : S.

    Returns
    -------
    list of S parts; InputError when fewer than S combinations exist.
    """
    count = len(drivable)
    combos = list(itertools.islice(signed_combinations(count), size))
    if len(combos) < size:
        raise InputError(f"the model has only {count} harmonic{'s' * (count > 1)} that move "
                         f"it: too few for {size} different gallery items",
                         remedy={"k": 4 * len(content)})  # symmetric shapes: moving ones are rare
    parts = []
    for s, (members, signs) in enumerate(combos):
        harmonics = drivable[list(members)]
        sign = 1.0 if s % 2 == 0 else -1.0
        equaliser = 1.0 / content[harmonics]
        home = harmonics if len(members) == 1 else harmonics[:0]
        parts.append(Part(harmonics, sign * signs * equaliser, home, equaliser[:len(home)],
                          "interleaved"))
    return parts


def signed_combinations(count: int):
    """(members, signs) of 1, 2, … of `count` items, first sign +: the singles, then the pairs
    (+ +, + −), then the triples …; (3^count − 1)/2 in all.

    Parameters
    ----------
    count : items.

    Yields
    ------
    (members (tuple of indices), signs (tuple of ±1)).
    """
    for width in range(1, count + 1):
        for members in itertools.combinations(range(count), width):
            for signs in itertools.product((1.0, -1.0), repeat=width - 1):
                yield members, np.array([1.0, *signs])


def part_transfer(part: Part, bands: int, k: int) -> np.ndarray:
    """The transfer (B,) sending every band into `part.harmonics`: cell centres (ν + ½)/k.

    Parameters
    ----------
    part : the part.
    bands : B.
    k : the targets.

    Returns
    -------
    (B,) in [0, 1].
    """
    width = len(part.harmonics)
    xi = np.arange(bands)
    if part.order == "interleaved":
        index = xi % width
    else:
        index = np.minimum(width - 1, ((xi + 0.5) * width / bands).astype(np.int64))
        if part.order == "reversed":
            index = width - 1 - index
    return (part.harmonics[index] + 0.5) / k


# ---------------------------------------------------------------------------------------------
# The gallery


def motion_targets(size: int) -> np.ndarray:
    """Target m of each item: MOTION_LOWEST falling geometrically to MOTION_HIGHEST.

    Parameters
    ----------
    size : S.

    Returns
    -------
    (S,) fractions of the diagonal.
    """
    return MOTION_LOWEST * (MOTION_HIGHEST / MOTION_LOWEST) ** (np.arange(size) /
                                                                max(1, size - 1))


def calibrate(dancer: Dancer, spectrogram, times: np.ndarray, mapping: Mapping,
              target: float, diagonal: float) -> float:
    """α such that α·(the mapping's amplification) moves the model by m = target on the song
    at these times (F,) (its envelope and pulse included).

    m is linear in α: α = target·diagonal / (95th percentile of the unit motion), lowered so
    that no frame moves more than PEAK_MOTION and none of the STRAIN_FRAMES frames that move
    it most strains an edge more than PEAK_STRAIN (`edge_strain`) or folds more than FOLD_SHARE
    of the surface's area over (`fold_scale`); a silent song is calibrated
    at full-scale input (g̃ ≡ 1, the loudest it could be).

    Parameters
    ----------
    dancer : the model.
    spectrogram : the song.
    times : (F,) s, the song's frames measured (`song_times`).
    mapping : the item with its unit amplification (its transfer, envelope and pulse).
    target : m, a fraction of the diagonal.
    diagonal : the model's diagonal.

    Returns
    -------
    float α.
    """
    k = len(dancer.frequencies)
    targets = np.flatnonzero(mapping.amplification)
    gram = motion_gram(dancer, targets)
    phi = mapping.play(spectrogram, times, k)
    rms = frame_motion(phi[:, targets] - 1.0, gram)
    typical, peak = np.percentile(rms, 95), rms.max()
    if not typical > 1e-12 * max(peak, 1e-300) or not peak > 0:
        return target * diagonal / full_scale_motion(dancer, [mapping])[0]
    # fold measured on the frames as they are: scaled by α, their φ − 1 scales by α
    strains, fold = surface_caps(dancer, phi[np.argsort(rms)[-STRAIN_FRAMES:]], FOLD_SHARE)
    strain = strains.max()
    return min(target * diagonal / typical, PEAK_MOTION * diagonal / peak,
               PEAK_STRAIN / strain if strain > 0 else np.inf, fold)


def initial_gallery(dancer: Dancer, spectrogram, size: int = DEFAULT_GALLERY,
                    amplitude: float | None = None) -> list[Mapping]:
    """The S items of the initial gallery (docs/design.md#gallery; departs from thesis §6.2.2).

    Parameters
    ----------
    dancer : a `HarmonicBasis` (or any `Dancer`).
    spectrogram : the `Spectrogram` of the song that will play: each item is calibrated on it.
    size : S, checked by `check_gallery_size` (odd sizes too).
    amplitude : None (the default: the construction below); a number M_a gives the thesis's own
        gallery with that amplification, uncalibrated (`thesis_gallery`: a rig calibrates its
        items itself).

    Returns
    -------
    S mappings, lowest part of the spectrum first, each recording the basis it was made on (a
    `HarmonicBasis`'s `record`: docs/design.md#mapping-file). With N ≥ S drivable harmonics P
    (eigenvalue > 0, some shape on them): item 0 sends every band to P[0], item S−1 to P[N−1], items
    1…S−2 spread the bands over geometrically growing ranges of P in between (`ranged_parts`); with
    N < S, signed combinations of the few harmonics (`combined_parts`). Item s's amplification is
    (−1)^s·α_r on the range of every item r (α_r calibrated so that item r alone moves the model by
    its target m on the song, `motion_targets`), 0 on harmonics that are never driven: each item
    moves only its own range, while crossing any initial transfer with any initial amplification
    still moves the model, with either sign.

    Example
    -------
    >>> import trimesh
    >>> from eigendance.harmonic.basis import HarmonicBasis
    >>> from eigendance.harmonic.mesh import Mesh
    >>> from eigendance.music.spectrogram import Spectrogram
    >>> sphere = trimesh.creation.icosphere(2)
    >>> basis = HarmonicBasis.from_mesh(Mesh.from_arrays(sphere.vertices * [1.4, 1, 0.8],
    ...                                                  sphere.faces), 30, cache=False)
    >>> song = Spectrogram.from_samples(np.sin(np.arange(44100) / 5.0), 44100)
    >>> gallery = initial_gallery(basis, song, size=5)
    >>> len(gallery), gallery[0].bands, len(gallery[0].amplification)
    (5, 64, 30)
    >>> [round(item.motion, 3) for item in gallery_motion(basis, song, gallery)]
    [0.04, 0.031, 0.024, 0.019, 0.015]
    """
    if amplitude is not None:
        return thesis_gallery(dancer, spectrogram, size, amplitude)
    size = check_gallery_size(size)
    k = len(dancer.frequencies)
    bands = spectrogram.bands
    content = motion_content(dancer)
    drivable = drivable_harmonics(dancer, content)
    parts = ranged_parts(drivable, size) if len(drivable) >= size else \
        combined_parts(drivable, content, size)
    times = song_times(spectrogram)
    diagonal = dancer.diagonal
    transfers = [part_transfer(part, bands, k) for part in parts]
    shapings = [beat_shaping(part, spectrogram, k) if s % 2 else (Envelope(), Pulse())
                for s, part in enumerate(parts)]
    parted = len(getattr(getattr(spectrogram, "rhythm", None), "sections", ()))
    genes = [SECTION_GENE if parted and s % SECTION_EVERY == SECTION_EVERY - 1 else None
             for s in range(len(parts))]
    scales = []
    for part, transfer, target, (envelope, pulse), gene in zip(
            parts, transfers, motion_targets(size), shapings, genes, strict=True):
        unit = np.zeros(k)
        unit[part.harmonics] = part.unit
        mapping = Mapping(transfer, unit, envelope=envelope, pulse=pulse, sections=gene)
        scales.append(calibrate(dancer, spectrogram, times, mapping, target, diagonal))
    dormant = np.zeros(k)  # |amplification| every item has on each harmonic outside its part
    for part, scale in zip(parts, scales, strict=True):
        dormant[part.home] = scale * part.profile
    items = []
    for s, (part, transfer, scale) in enumerate(zip(parts, transfers, scales, strict=True)):
        amplification = (1.0 if s % 2 == 0 else -1.0) * dormant
        amplification[part.harmonics] = scale * part.unit
        envelope, pulse = shapings[s]
        items.append(Mapping(transfer, amplification, None, f"gallery item {s + 1}",
                             envelope=envelope, pulse=pulse, sections=genes[s],
                             basis=getattr(dancer, "record", None)))  # a basis's (k …)
    return items


def beat_shaping(part: Part, spectrogram, k: int) -> tuple[Envelope, Pulse]:
    """The envelope and pulse of an item that pulses on the beat (the odd items).

    The loudness swells slowly (attack PULSE_ATTACK, release PULSE_RELEASE: its own peaks are
    few and broad) and each beat kicks the item's own harmonics, decaying in PULSE_DECAY, by
    PULSE_SHARE times what the song's loud frames give them (the band sum of the B/w bands
    each of its w harmonics receives at the 95th percentile of the mean loudness): the peaks of
    the motion land on the beats. A song without beats plays the swell alone.

    Parameters
    ----------
    part : the item's part of the harmonics.
    spectrogram : the song.
    k : the model's harmonics.

    Returns
    -------
    (Envelope, Pulse).
    """
    bands = spectrogram.bands
    width = len(part.harmonics)
    level = float(np.percentile(np.asarray(spectrogram.values, dtype=np.float64).mean(axis=1),
                                95)) if len(spectrogram.values) else 0.0
    amount = PULSE_SHARE * bands / width * max(level, 0.05)
    low = float(part.harmonics.min()) / k
    high = float(part.harmonics.max() + 1) / k
    return (Envelope([PULSE_ATTACK], [PULSE_RELEASE], [0.0]),
            Pulse(amount, PULSE_DECAY, low, high, "beats"))


def strongest_item(dancer: Dancer, spectrogram, size: int = DEFAULT_GALLERY) -> Mapping:
    """The initial-gallery item that moves the model most on this song (a default mapping).

    Parameters
    ----------
    dancer : the model.
    spectrogram : the song.
    size : the gallery measured.

    Returns
    -------
    Mapping.
    """
    gallery = initial_gallery(dancer, spectrogram, size)
    motion = [item.motion for item in gallery_motion(dancer, spectrogram, gallery)]
    return gallery[int(np.argmax(motion))]


# ---------------------------------------------------------------------------------------------
# The thesis's initial gallery (§6.2.2), as written: for dancers that calibrate themselves (a
# rig's ranked modes, `eigendance.modal.rig.rig_gallery`) and for comparison


def initial_indices(frequencies, band_edges, positions=None) -> np.ndarray:
    """ν_ini at (possibly fractional) band positions x (default 0 … B−1), int64.

    ν_ini(x) = the smallest ν with f_x / f_{B−1} ≤ ω_ν / ω_{k−1} (thesis 6-4 with ω = √λ),
    where f_x is the geometric centre of band x. Band edges are geometric, so
    f_x / f_{B−1} = (e_B / e_0)^((x − B + 1)/B) exactly, which also defines f_x between bands
    (the gallery's t(εξ)).

    Parameters
    ----------
    frequencies : (k,) ascending.
    band_edges : (B+1,) Hz.
    positions : band positions, or None.

    Returns
    -------
    int64 of the positions' shape.
    """
    frequencies = np.maximum(np.asarray(frequencies, dtype=np.float64), 0.0)
    band_edges = np.asarray(band_edges, dtype=np.float64)
    bands = len(band_edges) - 1
    if positions is None:
        positions = np.arange(bands, dtype=np.float64)
    if not frequencies[-1] > 0:
        raise InputError("the model has no positive frequency; cannot build transfers")
    ratio = (band_edges[-1] / band_edges[0]) ** ((np.asarray(positions) - bands + 1) / bands)
    levels = frequencies / frequencies[-1]  # non-decreasing, ends at 1
    index = np.searchsorted(levels, ratio, side="left")
    return np.minimum(index, len(frequencies) - 1).astype(np.int64)


def direct_transfer(frequencies, band_edges, positions=None) -> np.ndarray:
    """t_ini = (ν_ini + ½)/k: low sounds drive low harmonics (thesis 6-4).

    Parameters
    ----------
    frequencies, band_edges, positions : as for `initial_indices`.

    Returns
    -------
    transfer values in [0, 1].
    """
    k = len(frequencies)
    return (initial_indices(frequencies, band_edges, positions) + 0.5) / k


def reversed_transfer(frequencies, band_edges, positions=None) -> np.ndarray:
    """t_rev = (k − 1 − ν_ini + ½)/k: low sounds drive high harmonics.

    Parameters
    ----------
    frequencies, band_edges, positions : as for `initial_indices`.

    Returns
    -------
    transfer values in [0, 1].
    """
    k = len(frequencies)
    return (k - 1 - initial_indices(frequencies, band_edges, positions) + 0.5) / k


def gallery_epsilons(size: int) -> np.ndarray:
    """The ⌈S/2⌉ compressions ε of the transfers: 0, 1, 2/S, 4/S, …

    Parameters
    ----------
    size : S.

    Returns
    -------
    (⌈S/2⌉,).
    """
    count = (size + 1) // 2
    return np.array([0.0, 1.0, *[2 * i / size for i in range(1, count - 1)]])[:count]


def gallery_intervals(size: int) -> np.ndarray:
    """The ⌈S/2⌉ normalised amplification intervals I_ε = [ε², (ε + 2/S)²], ε = 0, 2/S, …

    Parameters
    ----------
    size : S.

    Returns
    -------
    (⌈S/2⌉, 2) [lower, upper].
    """
    eps = 2 * np.arange((size + 1) // 2) / size
    return np.stack([eps ** 2, (eps + 2 / size) ** 2], axis=1)


def thesis_gallery(dancer: Dancer, spectrogram, size: int, amplitude: float) -> list[Mapping]:
    """The thesis's initial gallery (§6.2.2) with M_a = amplitude, uncalibrated.

    Item i < ⌈S/2⌉: transfer t_ini(ε_i·ξ), amplification +M_a on interval I_i, 0 elsewhere; the
    other ⌊S/2⌋ items: t_rev(ε_i·ξ) and −M_a on I_i. ε_i = 0, 1, 2/S, 4/S, …;
    I_i = [(2i/S)², ((2i+2)/S)²] of the normalised target range: target ν is in I_i when its
    cell centre (ν + ½)/k lies in [lower, upper) (the last one closed). On a mesh's harmonics
    most items never move (docs/design.md#gallery): `initial_gallery` is the one to use.

    Parameters
    ----------
    dancer : the model.
    spectrogram : the song (its band edges), or the band edges.
    size : S.
    amplitude : M_a.

    Returns
    -------
    list of S mappings.
    """
    size = check_gallery_size(size)
    edges = np.asarray(getattr(spectrogram, "band_edges", spectrogram), dtype=np.float64)
    bands = len(edges) - 1
    frequencies = dancer.frequencies
    k = len(frequencies)
    xi = np.arange(bands, dtype=np.float64)
    centres = (np.arange(k) + 0.5) / k
    intervals = gallery_intervals(size)
    epsilons = gallery_epsilons(size)
    items = []
    for sign, transfer, count in ((1.0, direct_transfer, (size + 1) // 2),
                                  (-1.0, reversed_transfer, size // 2)):
        for i, eps in enumerate(epsilons[:count]):
            lower, upper = intervals[i]
            last = i == len(intervals) - 1
            inside = (centres >= lower) & ((centres <= upper) if last else (centres < upper))
            items.append((transfer(frequencies, edges, eps * xi), sign * inside * amplitude))
    return [Mapping(t, a, None, f"gallery item {i + 1}") for i, (t, a) in enumerate(items)]
