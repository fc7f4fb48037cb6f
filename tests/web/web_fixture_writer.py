"""Reference numbers for the browser's unit tests (web/test), written by the Python reference.

`python tests/web/web_fixture_writer.py` rewrites web/test/fixtures/; test_web_fixtures.py checks
that the committed files (the JSON numbers and the binary bundles) equal what the current Python
code writes, so the Vitest tests always compare the TypeScript ports — the filter, the bundle
parser, rig motion, the palette's default rule, the gallery's grid, the rhythm (envelopes, the
pulse, the tempo lock) — with today's reference implementation.
"""

from __future__ import annotations

import json
import os
import sys
from dataclasses import replace

import numpy as np
import trimesh

from eigendance.export.renderer import gallery_columns
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.harmonic.mesh import Mesh
from eigendance.modal.motion import body_poses, default_mapping, rig_coefficients, rig_mapping
from eigendance.modal.palette import resolve_palette
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import open_chain
from eigendance.music.demo_music import demo_track
from eigendance.music.envelope import Envelope, Pulse
from eigendance.music.gallery import initial_gallery
from eigendance.music.mapping import Mapping
from eigendance.music.mode_settings import ModeSettings
from eigendance.music.onset import BeatFeatures
from eigendance.music.spectrogram import Spectrogram
from eigendance.server.binary import basis_bundle, rig_bundle, spectrogram_bundle

FOLDER = os.path.join(os.path.dirname(__file__), "..", "..", "web", "test", "fixtures")
TIMES = [0.0, 0.137, 0.5, 1.2345, 1.99]


def build():
    """Every fixture: name → bytes."""
    return {**build_harmonics(), **live_reference()}


def build_harmonics():
    sphere = trimesh.creation.icosphere(1)
    vertices = sphere.vertices * [1.0, 0.8, 0.6]  # an ellipsoid: distinct eigenvalues
    mesh = Mesh.from_arrays(vertices, sphere.faces, name="ellipsoid")
    basis = HarmonicBasis.from_mesh(mesh, 14, cache=False)  # k = 14: a padded last texel
    samples, rate = demo_track(2.0)
    spectrogram = Spectrogram.from_samples(samples, rate, bands=16)
    mappings = initial_gallery(basis, spectrogram, size=4)
    odd = Mapping(mappings[1].transfer, np.linspace(-0.3, 0.5, 9), 5)  # K = 9 ≠ k: resampled
    mappings.append(odd)
    values = spectrogram.at(np.array(TIMES))
    cases = []
    for mapping in mappings:
        phi = mapping.filter(values, basis.k)
        cases.append({"mapping": mapping.to_json(), "phi": phi.tolist(),
                      "positions": basis.filter_positions(phi).reshape(len(TIMES), -1).tolist()})
    reference = {"times": TIMES, "values": values.tolist(), "n": basis.n, "k": basis.k,
                 "bands": spectrogram.values.shape[1], "frames": len(spectrogram.times),
                 "vertices": basis.vertices.ravel().tolist(),
                 "eigenvectors": basis.eigenvectors.ravel().tolist(),
                 "coefficients": basis.coefficients.ravel().tolist(), "cases": cases}
    rig_files = rig_reference(spectrogram, values)
    grid = {"columns": {str(count): gallery_columns(count) for count in range(1, 17)}}
    return {**rig_files, **rhythm_reference(basis),
            "reference.json": json.dumps(reference, indent=0).encode(),
            "grid.json": json.dumps(grid, indent=0).encode(),
            "basis.bin": basis_bundle(basis, "ellipsoid"),
            "basis16.bin": basis_bundle(basis, "ellipsoid", half=True),
            "spectrogram.bin": spectrogram_bundle(spectrogram, "demo-2s")}


def rig_reference(spectrogram, values):
    """A 3-body spherical chain (6 modes, G = 2) and the page's rig motion from Python: mode
    coefficients (`rig_coefficients`), modal-skinned positions and body poses for a default
    mapping (offset 0.25, gain 1.5) and one with an explicit palette given out of order."""
    rig = Rig.from_skeleton(open_chain(3, "spherical"))
    default = default_mapping(spectrogram, len(rig.palette.selected))
    default.offset, default.gain = 0.25, 1.5
    chosen = default_mapping(spectrogram, 2)
    chosen.modes = ModeSettings(np.array([4, 1]), np.array([0.3, 0.2]), np.array([1.0, 2.5]),
                                0.7)
    cases = []
    for mapping in (default, chosen):
        c = rig_coefficients(rig.model, spectrogram, mapping, np.array(TIMES))
        rotations, centres = body_poses(rig.model, c)
        positions = rig.skin.positions(c).reshape(len(TIMES), -1)
        cases.append({"mapping": mapping.to_json(), "coefficients": c.tolist(),
                      "positions": np.round(positions, 8).tolist(),
                      "rotations": rotations.reshape(len(TIMES), -1).tolist(),
                      "centres": centres.reshape(len(TIMES), -1).tolist()})
    reference = {"times": TIMES, "values": values.tolist(), "cases": cases}
    return {"rig.json": json.dumps(reference, indent=0).encode(),
            "palette.json": json.dumps(palette_reference(rig), indent=0).encode(),
            "rig.bin": rig_bundle(rig, "chain3")}


# Palettes with fields missing: the default rule fills them (`resolve_palette`); the 40° cap
# binds for every mode of the chain, the time scale follows the selected modes; the floor caps
# the amplitudes (a mode alone: 3 rad; together: the others).
PALETTES = [None, {"selected": [1, 4]}, {"selected": [0, 1, 2, 3, 4, 5]}, {"selected": [5]},
            {"selected": [3, 0]}, {"selected": [3, 0], "phases": [0.5, 1.5]},
            {"selected": [2, 4], "amplitudes": [0.1, 0.2]}, {"time_scale": 0.7},
            {"selected": [4, 1], "time_scale": 2.0},
            {"selected": [0, 3], "amplitudes": [3.0, 0.01]}]


def palette_reference(rig):
    """Each partial palette of PALETTES and the palette Python resolves for the rig."""
    cases = []
    for fields in PALETTES:
        settings = None if fields is None else ModeSettings.from_json(
            {"selected": None, "amplitudes": None, "phases": None, "time_scale": None,
             **fields}, "palette")
        palette = resolve_palette(rig.model, settings)
        cases.append({"modes": fields, "resolved": palette.to_settings().to_json()})
    return {"cases": cases}


RHYTHM_TIMES = [0.0, 0.137, 0.5, 0.51, 0.63, 1.2345, 2.0, 2.004, 3.3, 5.1, 5.99]


def click_song(seconds: float = 6.0, rate: int = 22050) -> np.ndarray:
    """Clicks at 120 BPM (from 0.25 s) over a quiet 220 Hz tone: a song with known beats."""
    t = np.arange(int(seconds * rate)) / rate
    samples = 0.05 * np.sin(2 * np.pi * 220 * t)
    for start in np.arange(0.25, seconds, 0.5):
        i = int(start * rate)
        burst = np.random.default_rng(int(start * 100)).normal(0, 0.5, 300) * np.exp(
            -np.arange(300) / 60)
        samples[i:i + 300] += burst
    return samples


def rhythm_reference(basis):
    """A click song's rhythm and the version-3 mapping fields played by Python: shaped values
    (envelopes, auto-range), φ with the pulse on beats and on onsets, and a rig's coefficients
    locked to the beats and free-running (docs/design.md#rhythm, #mapping, #tempo-lock)."""
    rate = 22050
    song = Spectrogram.from_samples(click_song(6.0, rate), rate, bands=16)
    bands = song.bands
    envelope = Envelope(np.linspace(0.0, 0.2, bands), np.linspace(0.3, 0.0, bands),
                        np.linspace(0.0, 0.4, bands), True)
    gallery = initial_gallery(basis, song, size=4)
    times = np.array(RHYTHM_TIMES)
    mappings = [replace(gallery[1], envelope=envelope, smoothing=0.05,
                        pulse=Pulse(3.0, 0.2, 0.2, 0.6, "beats")),
                replace(gallery[2], pulse=Pulse(1.5, 0.1, 0.0, 1.0, "onsets"),
                        envelope=Envelope([0.05], [0.25], [0.1], False)),
                gallery[3]]
    cases = [{"mapping": m.to_json(), "phi": m.play(song, times, basis.k).tolist(),
              "shaped": m.shaped(song).values[::37].tolist()} for m in mappings]
    rig = Rig.from_skeleton(open_chain(3, "spherical"))
    rig_cases = []
    for tempo in (None, "free"):
        mapping = rig_mapping(rig.model, song)
        mapping = replace(mapping, pulse=Pulse(0.5, 0.15, 0.0, 1.0, "beats"),
                          modes=replace(mapping.modes, tempo=tempo))
        rig_cases.append({"mapping": mapping.to_json(), "coefficients": rig_coefficients(
            rig.model, song, mapping, times).tolist()})
    # The beat pulse's kick 10 ms after every beat: a bar's first beat kicks harder.
    kick_times = song.rhythm.beats + 0.01
    reference = {"times": RHYTHM_TIMES, "frames_step": 37, "beats": song.rhythm.beats.tolist(),
                 "phase": song.rhythm.beat_phase(times).tolist(), "tempo": song.rhythm.tempo,
                 "accent": song.rhythm.downbeat_accent(times).tolist(),
                 "cases": cases, "rig_cases": rig_cases, "kick_times": kick_times.tolist(),
                 "kicks": mappings[0].kicks(song, kick_times).tolist()}
    return {"rhythm.json": json.dumps(reference, indent=0).encode(),
            "rhythm.bin": spectrogram_bundle(song, "clicks-6s")}


LIVE_RATES = (44100, 48000, 96000)
LIVE_EVERY = 7  # frames kept in live.json


def live_signal(sample_rate: int, seconds: float = 1.0) -> np.ndarray:
    """The live analysis's test signal (web/test/live.test.ts computes the same formula): a
    220 Hz tone, a chirp from 300 Hz entering at 0.3 s and a 6 kHz tone at 0.6 s."""
    t = np.arange(int(seconds * sample_rate)) / sample_rate
    return (0.4 * np.sin(2 * np.pi * 220 * t)
            + 0.2 * np.sin(2 * np.pi * (300 * t + 2000 * t * t)) * (t >= 0.3)
            + 0.1 * np.sin(2 * np.pi * 6000 * t) * (t >= 0.6))


def live_reference():
    """What the live analysis (web/src/live-analysis.ts) must compute: the offline spectrogram
    and onset envelope of `live_signal` at 44.1, 48 and 96 kHz (every LIVE_EVERY-th frame)."""
    cases = []
    for rate in LIVE_RATES:
        spectrogram = Spectrogram.from_samples(live_signal(rate), rate)
        stream = BeatFeatures(rate)  # librosa's onset strength: the live tempo's envelope
        stream.feed(live_signal(rate))
        beat = stream.finish()[0]
        frames = list(range(0, len(spectrogram.values), LIVE_EVERY))
        cases.append({"sample_rate": rate, "frames": frames,
                      "values": np.round(spectrogram.values[frames], 6).tolist(),
                      "onset": np.round(spectrogram.rhythm.onset_strength[frames], 5).tolist(),
                      "beat": np.round(beat, 5).tolist(),
                      "edges": spectrogram.band_edges.tolist()})
    return {"live.json": json.dumps({"cases": cases}, indent=0).encode()}


def write(folder=FOLDER):
    os.makedirs(folder, exist_ok=True)
    for name, data in build().items():
        with open(os.path.join(folder, name), "wb") as file:
            file.write(data)


if __name__ == "__main__":
    write(sys.argv[1] if len(sys.argv) > 1 else FOLDER)
