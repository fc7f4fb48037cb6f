"""Multi-instrument pieces with exactly known beats, written as General MIDI files (mido) and
rendered through fluidsynth with a GM SoundFont (Debian packages `fluidsynth`,
`fluid-soundfont-gm`). For benchmarks/bench_rhythm.py only; not a test dependency.

Each piece has a metre (beats per bar), a tempo curve (beats per minute at every beat: steady
or drifting) and instruments playing patterns placed in beats. The tempo map holds one
set_tempo event per beat, so beat i sounds exactly at t_i = Σ_{j<i} 60/bpm_j (with the tempo
rounded to whole microseconds per beat, as MIDI stores it). The onsets are every note-on time
(drums included), merged when closer than 30 ms.
"""

from __future__ import annotations

import os
import subprocess
from dataclasses import dataclass

import numpy as np

SOUNDFONT = "/usr/share/sounds/sf2/FluidR3_GM.sf2"
TICKS = 480  # per beat
DRUMS = 9  # the GM percussion channel
KICK, SNARE, CLOSED_HAT, RIDE, BRUSH, CLAVE, CONGA_LOW, CONGA_HIGH, SIDE_STICK = \
    36, 38, 42, 51, 40, 75, 64, 63, 37


@dataclass
class Piece:
    name: str
    genre: str
    metre: int  # beats per bar
    bpm: np.ndarray  # (beats,) tempo of each beat
    notes: list  # (channel, program, note, start beat, length in beats, velocity)

    @property
    def beats(self) -> np.ndarray:
        """Exact beat times (s) as the MIDI file stores the tempo."""
        micro = np.round(60e6 / self.bpm)
        return np.concatenate([[0.0], np.cumsum(micro / 1e6)])[:len(self.bpm)]

    def time_of(self, beat: float) -> float:
        """Seconds at a (fractional) beat position."""
        beats = self.beats
        i = min(int(beat), len(beats) - 1)
        return float(beats[i] + (beat - i) * np.round(60e6 / self.bpm[i]) / 1e6)

    @property
    def onsets(self) -> np.ndarray:
        times = np.unique(np.round([self.time_of(n[3]) for n in self.notes], 6))
        merged = [times[0]]
        for t in times[1:]:
            if t - merged[-1] >= 0.03:
                merged.append(t)
        return np.array(merged)

    def write_midi(self, path: str) -> None:
        import mido

        midi = mido.MidiFile(ticks_per_beat=TICKS)
        track = mido.MidiTrack()
        midi.tracks.append(track)
        events = [(int(round(i * TICKS)), 0, mido.MetaMessage(
            "set_tempo", tempo=int(round(60e6 / bpm)))) for i, bpm in enumerate(self.bpm)]
        events.append((0, 0, mido.MetaMessage("time_signature", numerator=self.metre,
                                              denominator=4)))
        programs = {}
        for channel, program, note, start, length, velocity in self.notes:
            if channel != DRUMS and programs.get(channel) != program:
                programs[channel] = program
                events.append((0, 1, mido.Message("program_change", channel=channel,
                                                  program=program)))
            on = int(round(start * TICKS))
            off = on + max(1, int(round(length * TICKS)))
            events.append((on, 3, mido.Message("note_on", channel=channel, note=note,
                                               velocity=velocity)))
            events.append((off, 2, mido.Message("note_off", channel=channel, note=note)))
        events.sort(key=lambda e: (e[0], e[1]))
        now = 0
        for tick, _, message in events:
            track.append(message.copy(time=tick - now))
            now = tick
        midi.save(path)

    def render(self, folder: str, sample_rate: int = 44100) -> str:
        """The piece as a WAV file in `folder` (rendered once, then reused)."""
        wav = os.path.join(folder, f"{self.name}.wav")
        if not os.path.exists(wav):
            mid = os.path.join(folder, f"{self.name}.mid")
            self.write_midi(mid)
            subprocess.run(["fluidsynth", "-ni", "-q", "-g", "0.6", "-r", str(sample_rate),
                            "-F", wav, SOUNDFONT, mid], check=True, capture_output=True)
        return wav


def scale_notes(root: int, minor: bool = False) -> list[int]:
    steps = [0, 2, 3, 5, 7, 8, 10] if minor else [0, 2, 4, 5, 7, 9, 11]
    return [root + s + 12 * o for o in range(2) for s in steps]


def melody(random, channel, program, bars, metre, scale, rhythm, velocity=80):
    """A random line on `rhythm` (offsets within a bar, beats), notes from `scale`."""
    notes, index = [], 4
    for bar in range(bars):
        for i, offset in enumerate(rhythm):
            index = int(np.clip(index + random.integers(-2, 3), 0, len(scale) - 1))
            end = rhythm[i + 1] if i + 1 < len(rhythm) else metre
            notes.append((channel, program, scale[index], bar * metre + offset,
                          0.9 * (end - offset), velocity))
    return notes


def tempo_curve(beats: int, start: float, end: float | None = None,
                wobble: float = 0.0) -> np.ndarray:
    """bpm of each beat: from start to end (linear), with a slow ±wobble fraction."""
    end = start if end is None else end
    x = np.arange(beats) / max(1, beats - 1)
    return (start + (end - start) * x) * (1 + wobble * np.sin(2 * np.pi * 1.5 * x))


def pop(bars=16) -> Piece:
    random, metre = np.random.default_rng(1), 4
    notes = []
    chords = [[60, 64, 67], [57, 60, 64], [53, 57, 60], [55, 59, 62]]
    for bar in range(bars):
        b = bar * metre
        for beat in range(metre):
            notes.append((DRUMS, 0, KICK if beat in (0, 2) else SNARE, b + beat, 0.2, 110))
            for half in (0, 0.5):
                notes.append((DRUMS, 0, CLOSED_HAT, b + beat + half, 0.1, 70))
            notes.append((1, 33, chords[bar % 4][0] - 24, b + beat, 0.9, 95))
        for beat in (0, 2):
            notes += [(2, 0, n, b + beat, 1.9, 70) for n in chords[bar % 4]]
    notes += melody(random, 3, 73, bars, metre, scale_notes(72), [0, 1, 1.5, 2, 3])
    return Piece("pop_4-4_118bpm", "pop", metre, tempo_curve(bars * metre, 118), notes)


def waltz(bars=20) -> Piece:
    random, metre = np.random.default_rng(2), 3
    notes = []
    chords = [[55, 60, 64], [55, 59, 62], [53, 57, 60], [55, 59, 62]]
    for bar in range(bars):
        b, chord = bar * metre, chords[bar % 4]
        notes.append((1, 0, chord[0] - 12, b, 0.9, 100))  # oom
        for beat in (1, 2):  # pah pah
            notes += [(1, 0, n, b + beat, 0.5, 70) for n in chord]
    notes += melody(random, 2, 48, bars, metre, scale_notes(72), [0, 2], velocity=75)
    return Piece("waltz_3-4_drifting", "waltz", metre,
                 tempo_curve(bars * metre, 150, 138, wobble=0.03), notes)


def country(bars=20) -> Piece:
    random, metre = np.random.default_rng(3), 2
    notes = []
    chords = [[55, 59, 62, 67], [60, 64, 67, 72], [62, 66, 69, 74], [55, 59, 62, 67]]
    for bar in range(bars):
        b, chord = bar * metre, chords[(bar // 2) % 4]
        notes.append((1, 32, chord[0] - 24, b, 0.8, 100))  # bass on 1
        notes.append((1, 32, chord[0] - 17, b + 1, 0.8, 90))  # the fifth on 2
        for beat in (0, 1):
            notes += [(2, 25, n, b + beat + 0.5 + 0.01 * i, 0.4, 70)
                      for i, n in enumerate(chord)]  # off-beat strums
        notes.append((DRUMS, 0, BRUSH, b + 1, 0.2, 70))
    notes += melody(random, 3, 40, bars, metre, scale_notes(67), [0, 0.5, 1, 1.5], velocity=80)
    return Piece("country_2-4_accelerating", "country", metre,
                 tempo_curve(bars * metre, 100, 122), notes)


def swing(bars=12) -> Piece:
    random, metre = np.random.default_rng(4), 4
    notes = []
    walk = scale_notes(36)
    for bar in range(bars):
        b = bar * metre
        for beat in range(metre):
            notes.append((1, 32, walk[(bar * 4 + beat * 2) % 9], b + beat, 0.9, 95))
            notes.append((DRUMS, 0, RIDE, b + beat, 0.2, 85))
            if beat in (1, 3):
                notes.append((DRUMS, 0, RIDE, b + beat + 2 / 3, 0.1, 60))
                notes.append((DRUMS, 0, 44, b + beat, 0.1, 70))  # pedal hi-hat
        for offset in (1.667, 3.667) if bar % 2 else (0, 2.667):  # comping, syncopated
            notes += [(2, 0, n, b + offset, 0.3, 65) for n in (60, 64, 67, 70)]
    notes += melody(random, 3, 66, bars, metre, scale_notes(62, True),
                    [0, 0.667, 1, 1.667, 2.667, 3.333], velocity=80)
    return Piece("swing_4-4_150bpm", "jazz", metre, tempo_curve(bars * metre, 150,
                                                               wobble=0.02), notes)


def latin(bars=14) -> Piece:
    random, metre = np.random.default_rng(5), 4
    notes = []
    for bar in range(bars):
        b = bar * metre
        clave = (0, 1.5, 3) if bar % 2 == 0 else (1, 2)  # son clave 3-2, syncopated
        notes += [(DRUMS, 0, CLAVE, b + o, 0.1, 90) for o in clave]
        notes += [(DRUMS, 0, CONGA_LOW if o in (1.5, 3.5) else CONGA_HIGH, b + o, 0.1, 80)
                  for o in (0.5, 1.5, 2.5, 3.5)]
        notes += [(1, 33, 41 if bar % 2 else 43, b + o, 0.4, 100) for o in (1.5, 3)]  # tumbao
        notes += [(2, 0, n, b + o, 0.2, 70) for o in (0.5, 1.5, 2, 3, 3.5)
                  for n in ((65, 69, 72) if bar % 2 else (67, 71, 74))]  # montuno
    notes += melody(random, 3, 56, bars, metre, scale_notes(67), [0, 1.5, 2.5, 3], velocity=85)
    return Piece("latin_4-4_syncopated", "latin", metre, tempo_curve(bars * metre, 104), notes)


PIECES = (pop, waltz, country, swing, latin)
