"""librosa's onset strength of a song, computed in bounded memory (docs/design.md#rhythm).

`librosa.beat.beat_track(y=y, sr=22050)` tracks beats on
`librosa.onset.onset_strength(y=y, sr=22050, hop_length=512, aggregate=np.median)`. `BeatFeatures`
computes the same envelope chunk by chunk, as the decoder's chunks come, without holding the
song's samples:

- the mono samples are resampled to SR = 22050 Hz by soxr's streaming resampler at librosa's
  quality ("HQ", `librosa.resample`'s soxr_hq);
- frame t is centred on sample t·HOP (HOP = 512) and covers N_FFT = 2048 samples, zero outside
  the song (librosa's centred STFT with constant padding): 1 + ⌊n/HOP⌋ frames;
- P_t = M·|rfft(w·x_t)|², M librosa's mel filter bank (128 Slaney bands, 0 … SR/2), w the
  periodic Hann window;
- S_t = max(10·log₁₀ max(P_t, 10⁻¹⁰), max_t' S_t' − 80) (`librosa.power_to_db`, its top_db floor
  below the song's loudest mel value);
- e_t = aggregate over mels of max(0, S_t − S_{t−1}), delayed by 1 + N_FFT/(2·HOP) = 3 frames
  (librosa's lag and centring compensation, zeros first) and trimmed to the frame count;
  aggregate = median for the beats (as beat_track), mean for the onsets (as onset_detect).

Beside the envelope it keeps what the bars and the sections need per frame: the mel power in
dB (for MFCCs) and the chroma (librosa.filters.chroma over the same power spectrum, tuning 0).
All three are (T, ·) float32 at 43 frames per second: about a quarter of the samples' size.
"""

from __future__ import annotations

import warnings

import numpy as np
import soxr
from scipy.fft import rfft

from eigendance.music.constants import ANALYSIS

# From analysis.json, which the page's live tempo (web/src/live-rhythm.ts) reads too:
SR = int(ANALYSIS["onset"]["beat_sample_rate"])  # Hz: librosa's default, the tracker's input
HOP = int(ANALYSIS["onset"]["beat_hop"])  # samples between frames (librosa's default hop)
N_FFT = 2048  # samples per frame (librosa's default)
# Frames the onset strength (and so a beat frame) trails the mel frame its rise goes into: e_t
# holds S_{t−3} − S_{t−4}, a rise into mel frame t − 2 (librosa's lag and centring).
ENVELOPE_LAG = N_FFT // (2 * HOP)
MELS = 128  # librosa's default mel bands
TOP_DB = 80.0  # librosa.power_to_db's floor below the maximum
AMIN = 1e-10  # librosa.power_to_db's smallest power
FRAME_RATE = SR / HOP  # frames per second of the envelope (≈ 43.07)


class BeatFeatures:
    """Streaming librosa onset strength, mel dB and chroma (module docstring).

    Parameters
    ----------
    sample_rate : the song's, Hz.
    """

    def __init__(self, sample_rate: int):
        import librosa  # heavy (numba, 1–2 s): only when a song is analysed

        self.resampler = None if sample_rate == SR else \
            soxr.ResampleStream(sample_rate, SR, 1, dtype="float64", quality="HQ")
        with warnings.catch_warnings():  # a low sample rate leaves some bands empty
            warnings.simplefilter("ignore")
            self.mel = np.ascontiguousarray(
                librosa.filters.mel(sr=SR, n_fft=N_FFT, n_mels=MELS).T, dtype=np.float32)
            self.chroma = np.ascontiguousarray(
                librosa.filters.chroma(sr=SR, n_fft=N_FFT, tuning=0.0).T, dtype=np.float32)
        self.window = (0.5 - 0.5 * np.cos(2 * np.pi * np.arange(N_FFT) / N_FFT)).astype(
            np.float32)
        self.buffer = np.zeros(N_FFT // 2, dtype=np.float32)  # the centred STFT's zero padding
        self.start = -(N_FFT // 2)  # sample index (at SR) of buffer[0]
        self.next = 0  # next frame
        self.total = 0  # samples at SR received
        self.decibels: list[np.ndarray] = []
        self.chromas: list[np.ndarray] = []

    def feed(self, chunk: np.ndarray, last: bool = False) -> None:
        """Add the next mono samples (at the song's rate); `last` flushes the resampler.

        Parameters
        ----------
        chunk : (m,) samples.
        last : whether no samples follow.
        """
        chunk = np.asarray(chunk, dtype=np.float64).ravel()
        if self.resampler is not None:
            chunk = self.resampler.resample_chunk(chunk, last=last)
        self.total += len(chunk)
        self.buffer = np.concatenate([self.buffer, chunk.astype(np.float32)])
        stop = 1 + self.total // HOP if last else \
            max(self.next, (self.start + len(self.buffer) - N_FFT // 2) // HOP + 1)
        if last:  # the zeros after the song
            self.buffer = np.concatenate([self.buffer, np.zeros(N_FFT, dtype=np.float32)])
        if stop > self.next:
            windows = np.lib.stride_tricks.sliding_window_view(self.buffer, N_FFT)
            offsets = np.arange(self.next, stop) * HOP - N_FFT // 2 - self.start
            for first in range(0, len(offsets), 1024):
                frames = windows[offsets[first:first + 1024]]
                power = np.square(np.abs(rfft(frames * self.window, axis=1)), dtype=np.float32)
                mel = power @ self.mel
                self.decibels.append((10 * np.log10(np.maximum(mel, AMIN))).astype(np.float32))
                self.chromas.append(power @ self.chroma)
            self.next = stop
        drop = self.next * HOP - N_FFT // 2 - self.start
        if drop > 0:
            self.buffer = self.buffer[drop:]
            self.start += drop

    def finish(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The song's features, once every chunk was fed.

        Returns
        -------
        median (T,) and mean (T,) onset strength (the beats' and the onsets' envelopes),
        mel dB (T, MELS) with librosa's top_db floor, chroma (T, 12) (librosa's max-normalised
        chroma_stft), all float32 at FRAME_RATE.
        """
        self.feed(np.zeros(0), last=True)
        decibels = np.concatenate(self.decibels) if self.decibels else np.zeros((0, MELS),
                                                                               np.float32)
        chroma = np.concatenate(self.chromas) if self.chromas else np.zeros((0, 12), np.float32)
        count = len(decibels)
        if count:
            np.maximum(decibels, decibels.max() - TOP_DB, out=decibels)
        flux = np.maximum(decibels[1:] - decibels[:-1], 0)
        delay = 1 + ENVELOPE_LAG
        median, mean = np.zeros(count, np.float32), np.zeros(count, np.float32)
        if len(flux) and count > delay:
            median[delay:] = np.median(flux, axis=1)[:count - delay]
            mean[delay:] = flux.mean(axis=1)[:count - delay]
        chroma /= np.maximum(chroma.max(axis=1, keepdims=True), np.finfo(np.float32).tiny)
        return median, mean, decibels, chroma
