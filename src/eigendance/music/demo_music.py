"""Built-in demo music: a short procedural track made by code, so nothing has to be downloaded.

`demo_track()` returns 30 s of mono float64 PCM at 44.1 kHz: 120 beats per minute in 4/4, a
kick drum on every beat (low bands), a snare on beats 2 and 4 and closed hi-hats on eighth notes
(high bands), a bass line following the chords (A minor – F – C – G), sustained chord pads (mid
bands) and a melody climbing from C4 to C7 and back (low to high bands). Deterministic: the noise
comes from a fixed seed, so every call returns the same samples.
"""

from __future__ import annotations

import io
import os

import numpy as np
import soundfile

from eigendance.writes import atomic_write

SAMPLE_RATE = 44100
TEMPO = 120.0  # beats per minute

# Chord roots (MIDI) and chord tones, one chord per bar of four beats.
CHORDS = [(45, (57, 60, 64)), (41, (53, 57, 60)), (48, (55, 60, 64)), (43, (55, 59, 62))]
# Melody: scale degrees of A minor pentatonic over three octaves, eighth notes.
PENTATONIC = [57, 60, 62, 64, 67, 69, 72, 74, 76, 79, 81, 84, 86, 88, 91, 93, 96]


def _hz(midi):
    return 440.0 * 2.0 ** ((np.asarray(midi, dtype=np.float64) - 69) / 12)


def _place(track, start, sound):
    """Add `sound` into `track` from sample `start`, clipped at the end."""
    stop = min(len(track), start + len(sound))
    if stop > start:
        track[start:stop] += sound[:stop - start]


def demo_track(duration: float = 30.0, sample_rate: int = SAMPLE_RATE) -> tuple[np.ndarray, int]:
    """The demo music: (mono float64 samples with peak 0.9, sample rate).

    Parameters
    ----------
    duration : s.
    sample_rate : Hz.

    Returns
    -------
    (samples (duration·sample_rate,) float64, sample rate Hz).
    """
    random = np.random.default_rng(20121)
    count = int(round(duration * sample_rate))
    track = np.zeros(count)
    beat = 60.0 / TEMPO
    beat_samples = int(round(beat * sample_rate))
    beats = int(np.ceil(duration / beat))

    # Drums.
    t = np.arange(int(0.35 * sample_rate)) / sample_rate
    kick = np.sin(2 * np.pi * (45 * t + (110 / 30) * (1 - np.exp(-30 * t)))) * np.exp(-9 * t)
    t = np.arange(int(0.2 * sample_rate)) / sample_rate
    snare = (0.6 * random.standard_normal(len(t)) * np.exp(-22 * t)
             + 0.4 * np.sin(2 * np.pi * 190 * t) * np.exp(-30 * t))
    t = np.arange(int(0.05 * sample_rate)) / sample_rate
    hat_noise = random.standard_normal(len(t))
    hat = np.diff(np.concatenate([[0.0], hat_noise])) * np.exp(-60 * t) * 0.6  # high-passed
    for b in range(beats):
        start = b * beat_samples
        _place(track, start, 0.9 * kick)
        if b % 2 == 1:
            _place(track, start, 0.5 * snare)
        _place(track, start, hat)
        _place(track, start + beat_samples // 2, 0.6 * hat)

    # Bass, pads and melody, one chord per bar.
    bar_samples = 4 * beat_samples
    t_bar = np.arange(bar_samples) / sample_rate
    note_samples = beat_samples // 2
    t_note = np.arange(note_samples) / sample_rate
    envelope_note = np.minimum(1, t_note * 200) * np.exp(-5 * t_note)
    step = 0
    for bar in range(int(np.ceil(beats / 4))):
        root, tones = CHORDS[bar % len(CHORDS)]
        start = bar * bar_samples
        for b in range(4):  # bass: root on beats, octave on off-beats
            f = _hz(root - 12 + (12 if b % 2 else 0))
            t = t_bar[:beat_samples]
            wave = sum(np.sin(2 * np.pi * h * f * t) / h for h in range(1, 5))
            _place(track, start + b * beat_samples,
                   0.35 * wave * np.minimum(1, t * 300) * np.exp(-3 * t))
        pad = sum(np.sin(2 * np.pi * _hz(n) * t_bar) + 0.3 * np.sin(4 * np.pi * _hz(n) * t_bar)
                  for n in tones)
        swell = np.minimum(1, t_bar / 0.2) * np.minimum(1, (t_bar[-1] - t_bar) / 0.2)
        _place(track, start, 0.08 * pad * swell)
        for eighth in range(8):  # melody: up and down the pentatonic ladder
            position = step % (2 * len(PENTATONIC) - 2)
            index = position if position < len(PENTATONIC) else 2 * len(PENTATONIC) - 2 - position
            step += 1
            f = _hz(PENTATONIC[index])
            wave = (np.sin(2 * np.pi * f * t_note) + 0.4 * np.sin(4 * np.pi * f * t_note)
                    + 0.2 * np.sin(6 * np.pi * f * t_note))
            _place(track, start + eighth * note_samples, 0.18 * wave * envelope_note)

    track *= 0.9 / np.abs(track).max()
    return track, sample_rate


def write_demo_wav(path: str | os.PathLike, duration: float = 30.0) -> None:
    """Write the demo track as a 16-bit mono WAV file (atomically).

    Parameters
    ----------
    path : the .wav to write.
    duration : s.
    """
    samples, sample_rate = demo_track(duration)
    wav = io.BytesIO()  # encoded first: a full disk is then an OSError, not libsndfile's own
    soundfile.write(wav, samples, sample_rate, format="WAV", subtype="PCM_16")
    atomic_write(path, lambda file: file.write(wav.getvalue()), alone=True)
