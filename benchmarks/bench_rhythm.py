"""Rhythm, measured (docs/design.md#rhythm): how well the analysis finds beats and onsets, and
how well the dances land on them, on clips whose beats are known exactly.

Clips: General MIDI pieces in several genres and metres (pop 4/4, a waltz in 3/4 with a
drifting tempo, country 2/4 accelerating, swing 4/4, a syncopated latin 4/4; see
benchmarks/rhythm_pieces.py), rendered through fluidsynth with the FluidR3 GM SoundFont (Debian
packages `fluidsynth`, `fluid-soundfont-gm`); and a real recording, the shared
beatnet_808kick120bpm.mp3 (808 kicks at exactly 120 BPM, from the BeatNet 1.1.3 wheel on PyPI,
CC BY 4.0). No annotated real song could be reached from PyPI, npm or Debian.

1. Analysis: beat F (mir_eval, ±70 ms, first 5 s trimmed) and onset F (±50 ms) per clip,
   ours beside librosa's default call (beat_track and onset_detect on the audio resampled to
   22050 Hz) on the same clips, and the analysis time per minute of audio.
2. Harmonics (the demo cat, k = 150, the initial gallery of 8): the peaks of each item's motion
   magnitude (RMS vertex displacement at 100 frames/s; local maxima with a prominence of at
   least 10% of its 5–95th percentile range) against the beats, F at ±70 ms. "before": the
   items as the loudness alone moves them (no envelope, no pulse: today's gallery), best item;
   "after": the items that pulse on the beat, worst and mean.
3. Rigs (the default dance of loop8, hand, Fox): the turning points of the main sway (the
   projection of the skin's displacement on its first principal direction; local extrema with
   the same prominence rule) against the beats or the half-beat grid (the better of the two),
   F at ±70 ms; "free" is the thesis's free-running palette, "beat" the tempo lock.
2 and 3 also run on five shared real recordings (45 s each; country, jazz, lo-fi, pop,
classical), scored against the beats of librosa's default call: no annotations.
4. Agreement on the eleven shared real recordings (whole files, no annotations): our tempo and
   librosa's default call's, beat F of ours against its beats (±70 ms, first 5 s trimmed; not
   trimmed for a file shorter than 10 s), the meter and the number of sections we find, and
   the rhythm's CPU seconds per minute of audio, and the bars' consistency: each
   WINDOW-second window of the song analysed alone (the whole analysis, beats included), its
   downbeats scored against the whole song's downbeats in that window (F at ±70 ms, mean over
   the windows; 1.00: every part of the song alone chose the same bar phase as the whole), and
   how many windows chose the whole song's meter. Downbeat F (1.) is ours against the pieces'
   bars; librosa's default call has no downbeats: beside it, every 4th of its beats from the
   first (a naive bar).

Run: EIGENDANCE_SHARED_DATA=/path/to/shared/data .venv/bin/python benchmarks/bench_rhythm.py
(`--real` runs 4. alone; `--bars` runs 4. and 1., not the dances).
"""

from __future__ import annotations

import os
import sys
import tempfile
import time
from dataclasses import replace

import mir_eval
import numpy as np
from scipy.signal import find_peaks

sys.path.insert(0, os.path.dirname(__file__))
from eigendance.music.decode import open_audio  # noqa: E402
from eigendance.music.envelope import Envelope, Pulse  # noqa: E402
from eigendance.music.spectrogram import Spectrogram  # noqa: E402
from rhythm_pieces import PIECES  # noqa: E402
from shared_data import shared_path  # noqa: E402

TOLERANCE = 0.07
WINDOW = 30.0  # s: the windows of the bars' consistency (4.)


def beat_f(reference, estimate) -> float:
    return mir_eval.beat.f_measure(mir_eval.beat.trim_beats(np.asarray(reference)),
                                   mir_eval.beat.trim_beats(np.asarray(estimate)))


def events_f(reference, estimate) -> float:
    """F of events against beats at ±70 ms, first 5 s trimmed (as beat F)."""
    return beat_f(reference, estimate)


def turning_points(signal: np.ndarray, rate: float, extrema: bool) -> np.ndarray:
    """Times of the local maxima (and minima when `extrema`) of a signal at `rate`, with a
    prominence of at least 10% of its 5–95th percentile range."""
    low, high = np.percentile(signal, [5, 95])
    prominence = 0.1 * max(high - low, 1e-12)
    peaks = list(find_peaks(signal, prominence=prominence)[0])
    if extrema:
        peaks += list(find_peaks(-signal, prominence=prominence)[0])
    return np.sort(np.array(peaks, dtype=float)) / rate


def clips(folder: str) -> list[tuple[str, str, np.ndarray, np.ndarray | None]]:
    """(name, audio path, beats, onsets or None) of every clip."""
    found = []
    for make in PIECES:
        piece = make()
        found.append((piece.name, piece.render(folder), piece.beats, piece.onsets, piece.metre))
    kick = shared_path("audio", "beatnet_808kick120bpm.mp3")
    if os.path.exists(kick):
        found.append(("808kick_120bpm (real)", kick, np.arange(0, 10.0, 0.5), None, 0))
    return found


def analysis(clips_) -> dict:
    import librosa

    Spectrogram.from_samples(np.random.default_rng(0).normal(0, 0.1, 44100), 44100)  # JIT
    print(f"{'clip':28s} {'beat F ours':>11s} {'librosa':>8s} {'onset F ours':>12s} "
          f"{'librosa':>8s} {'tempo':>6s} {'CPU s/min: ours':>15s} {'all':>5s} {'librosa':>8s} "
          f"{'downbeat F':>10s} {'naive':>6s}")
    songs, ours_f, theirs_f = {}, [], []
    for name, path, beats, onsets, metre in clips_:
        rate, chunks = open_audio(path)
        samples = np.concatenate(list(chunks))
        minutes = len(samples) / rate / 60
        start = time.process_time()  # CPU time: the host is shared, wall time is noise
        song = Spectrogram.from_samples(samples, rate)
        ours_time = (time.process_time() - start) / minutes
        start = time.process_time()
        Spectrogram.from_samples(samples, rate, rhythm=False)
        plain_time = (time.process_time() - start) / minutes
        start = time.process_time()
        resampled = librosa.resample(samples, orig_sr=rate, target_sr=22050)
        _, their_beats = librosa.beat.beat_track(y=resampled, sr=22050, units="time")
        their_onsets = librosa.onset.onset_detect(y=resampled, sr=22050, units="time")
        their_time = (time.process_time() - start) / minutes
        rhythm = song.rhythm
        ours, theirs = beat_f(beats, rhythm.beats), beat_f(beats, their_beats)
        ours_f.append(ours)
        theirs_f.append(theirs)
        onset = "–" if onsets is None else \
            f"{mir_eval.onset.f_measure(onsets, rhythm.onsets, window=0.05)[0]:.2f}"
        their_onset = "–" if onsets is None else \
            f"{mir_eval.onset.f_measure(onsets, their_onsets, window=0.05)[0]:.2f}"
        bars = naive = "–"
        if metre:
            bars = f"{beat_f(beats[::metre], rhythm.downbeats):.2f}"
            naive = f"{beat_f(beats[::metre], their_beats[::4]):.2f}"
        print(f"{name:28s} {ours:11.2f} {theirs:8.2f} {onset:>12s} {their_onset:>8s} "
              f"{rhythm.tempo:6.1f} {ours_time - plain_time:15.2f} {ours_time:5.2f} "
              f"{their_time:8.2f} {bars:>10s} {naive:>6s}")
        songs[name] = (song, beats)
    print(f"{'mean':28s} {np.mean(ours_f):11.2f} {np.mean(theirs_f):8.2f}   (CPU seconds per "
          "minute of audio after the JIT warm-up; ours: the rhythm's share, all: the whole "
          "spectrogram with it; librosa: resampling, beats and onsets)")
    return songs


def item_f(basis, song, beats, item) -> float:
    """F of the peaks of one gallery item's motion magnitude against the beats."""
    from eigendance.music.dancer import frame_motion, motion_gram

    w = item.play(song, song.times, basis.k) - 1.0
    targets = np.flatnonzero(np.abs(w).max(axis=0) > 0)
    magnitude = frame_motion(w[:, targets], motion_gram(basis, targets))
    return events_f(beats, turning_points(magnitude, song.rate, extrema=False))


def harmonics(songs: dict) -> None:
    from eigendance.harmonic.basis import HarmonicBasis
    from eigendance.music.gallery import initial_gallery

    mesh = os.path.join(os.path.dirname(__file__), "..", "src", "eigendance", "data",
                        "cat_lowres.obj")
    basis = HarmonicBasis.from_mesh(mesh, 150)
    print(f"\nharmonics (cat, k = {basis.k}): peaks of the motion magnitude vs beats, F")
    print(f"{'clip':28s} {'before: best':>12s} {'after: worst':>12s} {'mean':>6s} "
          f"{'pulse items':>11s}")
    for name, (song, beats) in songs.items():
        gallery = initial_gallery(basis, song, 8)
        before = [item_f(basis, song, beats, replace(item, envelope=Envelope(), pulse=Pulse()))
                  for item in gallery]
        pulsing = [item_f(basis, song, beats, item) for item in gallery if item.pulse.amount > 0]
        print(f"{name:28s} {max(before):12.2f} {min(pulsing):12.2f} {np.mean(pulsing):6.2f} "
              f"{len(pulsing):11d}")


def rigs(songs: dict) -> None:
    from eigendance.modal.rig import Rig
    from eigendance.modal.sample_rigs import load_rig

    fixtures = os.path.join(os.path.dirname(__file__), "..", "tests", "fixtures", "rigged")
    print("\nrigs (default dance): turning points of the main sway vs beats or half-beats, F")
    names = ["loop8", "hand", os.path.join(fixtures, "Fox.glb")]
    print(f"{'clip':28s} " + " ".join(f"{os.path.basename(n)[:8] + ' free':>13s} "
                                     f"{'beat':>5s}" for n in names))
    loaded = [Rig(load_rig(name)) for name in names]
    for clip, (song, beats) in songs.items():
        halves = np.sort(np.concatenate([beats, (beats[:-1] + beats[1:]) / 2]))
        row = []
        for rig in loaded:
            for tempo in ("free", "beat"):
                mapping = rig.mapping(song)
                mapping = replace(mapping, modes=replace(mapping.modes, tempo=tempo))
                c = rig.coefficients(song, mapping, song.times)
                moved = rig.positions(c).reshape(len(c), -1)
                moved = moved - moved.mean(axis=0)
                direction = np.linalg.svd(moved[::4], full_matrices=False)[2][0]
                points = turning_points(moved @ direction, song.rate, extrema=True)
                row.append(max(events_f(beats, points), events_f(halves, points)))
        print(f"{clip:28s} " + " ".join(f"{row[i]:13.2f} {row[i + 1]:5.2f}"
                                         for i in range(0, len(row), 2)))


REAL_SONGS = ("emegeme_country.mp3", "kevin_macleod_vibe_ace.ogg", "tad_florist_lofi.mp3",
              "kevin_macleod_monkeys_spinning_monkeys.ogg",
              "brahms_hungarian_dance_5_us_army_strings.ogg")


def real_songs(seconds: float = 45.0) -> dict:
    """Shared real recordings (no annotations): the first `seconds`, with librosa's default
    call's beats as the reference the dances are scored against (an independent tracker)."""
    import librosa

    songs = {}
    for name in REAL_SONGS:
        path = shared_path("audio", name)
        if not os.path.exists(path):
            continue
        rate, chunks = open_audio(path)
        samples = np.concatenate(list(chunks))[:int(seconds * rate)]
        resampled = librosa.resample(samples, orig_sr=rate, target_sr=22050)
        _, beats = librosa.beat.beat_track(y=resampled, sr=22050, units="time")
        songs[f"{name[:22]} (ref: librosa)"] = (Spectrogram.from_samples(samples, rate), beats)
    return songs


def agreement() -> None:
    """4.: ours against librosa's default call on every shared real recording."""
    import librosa

    folder = shared_path("audio")
    names = sorted(n for n in os.listdir(folder) if n.endswith((".ogg", ".mp3")))
    print("\nshared real recordings (no annotations): ours vs librosa's default call")
    print(f"{'recording':34s} {'s':>6s} {'tempo ours':>10s} {'librosa':>8s} {'beat F':>7s} "
          f"{'meter':>5s} {'sections':>8s} {'rhythm CPU s/min':>16s} {'bar consistency':>15s} "
          f"{'same meter':>10s}")
    for name in names:
        rate, chunks = open_audio(os.path.join(folder, name))
        samples = np.concatenate(list(chunks))
        minutes = len(samples) / rate / 60
        start = time.process_time()
        song = Spectrogram.from_samples(samples, rate)
        ours_time = time.process_time() - start
        start = time.process_time()
        Spectrogram.from_samples(samples, rate, rhythm=False)
        rhythm_time = (ours_time - (time.process_time() - start)) / minutes
        resampled = librosa.resample(samples, orig_sr=rate, target_sr=22050)
        tempo, beats = librosa.beat.beat_track(y=resampled, sr=22050, units="time")
        rhythm = song.rhythm
        short = song.duration < 10
        f = mir_eval.beat.f_measure(np.asarray(beats), rhythm.beats) if short else \
            beat_f(beats, rhythm.beats)
        consistency, meters = bar_consistency(samples, rate, rhythm)
        print(f"{name[:34]:34s} {song.duration:6.1f} {rhythm.tempo:10.1f} "
              f"{float(np.ravel(tempo)[0]):8.1f} {f:7.2f} {rhythm.meter:5d} "
              f"{len(rhythm.sections):8d} {rhythm_time:16.2f} {consistency:>15s} {meters:>10s}")


def bar_consistency(samples, rate, rhythm) -> tuple[str, str]:
    """Each WINDOW-s window analysed alone: mean downbeat F against the whole song's
    downbeats within it (a second at either end left out), and windows of the same meter /
    windows."""
    size = int(WINDOW * rate)
    if not len(rhythm.downbeats) or len(samples) < size:
        return "–", "–"
    scores, same = [], 0
    for start in range(0, len(samples) - size + 1, size):
        part = Spectrogram.from_samples(samples[start:start + size], rate).rhythm
        offset = start / rate
        whole = rhythm.downbeats[(rhythm.downbeats >= offset + 1.0)
                                 & (rhythm.downbeats <= offset + WINDOW - 1.0)] - offset
        alone = part.downbeats[(part.downbeats >= 1.0) & (part.downbeats <= WINDOW - 1.0)]
        scores.append(mir_eval.beat.f_measure(whole, alone))
        same += part.meter == rhythm.meter
    return f"{np.mean(scores):.2f}", f"{same}/{len(scores)}"



def main() -> None:
    print(f"load: {os.getloadavg()[0]:.1f} (1-minute average, 2 cores)")
    Spectrogram.from_samples(np.random.default_rng(0).normal(0, 0.1, 44100), 44100)  # JIT
    agreement()
    if "--real" in sys.argv:
        return
    with tempfile.TemporaryDirectory() as folder:
        songs = analysis(clips(folder))
    if "--bars" in sys.argv:
        return
    songs.update(real_songs())
    harmonics(songs)
    rigs(songs)


if __name__ == "__main__":
    main()
