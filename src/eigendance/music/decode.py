"""Decode music to mono PCM in bounded memory (docs/design.md#decoding).

WAV, FLAC, OGG (Vorbis/Opus) and AIFF go through soundfile (libsndfile) first; anything else
(MP3, M4A/AAC, Opus in WebM/MKV, …), and any file libsndfile refuses, through PyAV (FFmpeg).
MP3 skips libsndfile, and so does a file whose first bytes are not those of the containers
libsndfile is used for (an MP3 named .wav): libsndfile's MP3 decoder (libmpg123) prints notes
about damaged streams straight onto the terminal, where PyAV decodes the same samples silently.
Channels are mixed to mono by their mean (PyAV's mono resampler would sum them at −3 dB
instead); the file's sample rate is kept. Files are read in chunks, so a one-hour track needs
no more memory than a short one.
"""

from __future__ import annotations

import os
from collections.abc import Iterator

import numpy as np
import soundfile

from eigendance.errors import InputError, one_line
from eigendance.files import check_readable, suffix_of

# Read by libsndfile first; the rest go straight to PyAV.
SOUNDFILE_SUFFIXES = (".wav", ".wave", ".flac", ".ogg", ".oga", ".aif", ".aiff")
# The first four bytes of those containers: RIFF/RIFX/RF64/BW64 WAV, FLAC, Ogg, AIFF.
SOUNDFILE_MAGIC = (b"RIFF", b"RIFX", b"RF64", b"BW64", b"fLaC", b"OggS", b"FORM")
CHUNK_SAMPLES = 1 << 18  # samples per decoded chunk (per channel): ≈ 6 s at 44.1 kHz
_INTEGER_SCALE = {"u8": 128.0, "s16": 32768.0, "s32": 2147483648.0, "s64": 9223372036854775808.0}


def open_audio(path: str | os.PathLike) -> tuple[int, Iterator[np.ndarray]]:
    """Open an audio file.

    Parameters
    ----------
    path : the file (any format libsndfile or FFmpeg reads).

    Returns
    -------
    (sample rate in Hz, iterator over mono float64 chunks in [-1, 1]).

    Raises InputError with one line for a missing, empty, unreadable or corrupt file.
    """
    path = check_readable(path)  # any suffix: FFmpeg reads more than any table lists
    if suffix_of(path) in SOUNDFILE_SUFFIXES:
        opened = _open_soundfile(path)
        if opened is not None:
            return opened
    return _open_pyav(path)


def read_audio(path: str | os.PathLike) -> tuple[np.ndarray, int]:
    """The whole file as mono float64 samples (for short files and tests) and its sample rate.

    Parameters
    ----------
    path : the file.

    Returns
    -------
    (samples (n,) float64 in [-1, 1], sample rate Hz).
    """
    sample_rate, chunks = open_audio(path)
    parts = list(chunks)
    samples = np.concatenate(parts) if parts else np.zeros(0)
    return samples, sample_rate


def mono(samples) -> np.ndarray:
    """(n,) or (n, channels) samples → mono float64 by the mean of the channels.

    Float samples are taken as they are (full scale ±1); integer PCM is scaled by 2^(bits−1).

    Parameters
    ----------
    samples : (n,) or (n, channels), float or integer PCM.

    Returns
    -------
    (n,) float64.
    """
    samples = np.asarray(samples)
    if np.issubdtype(samples.dtype, np.integer):
        samples = samples / float(2 ** (8 * samples.dtype.itemsize - 1))
    if samples.ndim == 1:
        return samples.astype(np.float64)
    if samples.ndim == 2 and samples.shape[1] >= 1:
        return samples.mean(axis=1, dtype=np.float64)
    raise InputError(f"samples must be (n,) or (n, channels), got {samples.shape}")


def _open_soundfile(path: str):
    try:
        with open(path, "rb") as head:
            if head.read(4) not in SOUNDFILE_MAGIC:
                return None  # not a container libsndfile is used for: PyAV decides
        file = soundfile.SoundFile(path)
    except Exception:  # libsndfile refuses it: let FFmpeg try
        return None
    if file.channels < 1 or file.samplerate < 1:
        file.close()
        return None
    name = os.path.basename(path)

    def chunks():
        with file:
            while True:
                try:
                    block = file.read(CHUNK_SAMPLES, dtype="float32", always_2d=True)
                except Exception as error:
                    raise InputError(f"{name}: corrupt audio data ({one_line(error)})") from None
                if len(block) == 0:
                    return
                yield block.mean(axis=1, dtype=np.float64)

    return int(file.samplerate), chunks()


def _open_pyav(path: str):
    import av  # heavy (FFmpeg's libraries): imported only for what libsndfile cannot read

    name = os.path.basename(path)
    try:
        container = av.open(path)
    except Exception as error:
        # FFmpeg's own words, without its error number and the file's path
        why = getattr(error, "strerror", None) or one_line(error)
        raise InputError(f"{name}: not a readable audio file ({why})") from None
    streams = [stream for stream in container.streams if stream.type == "audio"]
    if not streams:
        container.close()
        raise InputError(f"{name}: the file holds no audio stream")
    stream = streams[0]
    frames = container.decode(stream)
    try:  # the first frame's rate is the truth (HE-AAC streams may announce half of it)
        first = next(frames, None)
    except Exception as error:
        container.close()
        raise InputError(f"{name}: corrupt audio data ({one_line(error)})") from None
    sample_rate = int(first.sample_rate if first is not None
                      else stream.codec_context.sample_rate or 0)
    if sample_rate < 1:
        container.close()
        raise InputError(f"{name}: the audio stream has no sample rate")

    def chunks():
        with container:
            if first is None:
                return
            yield _mono(first)
            try:
                for frame in frames:
                    if frame.sample_rate != sample_rate:
                        raise InputError(f"{name}: the sample rate changes inside the stream "
                                         f"({sample_rate} → {frame.sample_rate} Hz)")
                    yield _mono(frame)
            except InputError:
                raise
            except Exception as error:
                raise InputError(f"{name}: corrupt audio data ({one_line(error)})") from None

    return sample_rate, chunks()


def _mono(frame) -> np.ndarray:
    """One PyAV audio frame → mono float64: the mean of its channels, in [-1, 1]."""
    array = frame.to_ndarray()
    channels = len(frame.layout.channels)
    if not frame.format.is_planar:
        array = array.reshape(-1, channels).T
    kind = frame.format.name.rstrip("p")
    if kind in _INTEGER_SCALE:
        offset = 128.0 if kind == "u8" else 0.0
        return (array.mean(axis=0, dtype=np.float64) - offset) / _INTEGER_SCALE[kind]
    return array.mean(axis=0, dtype=np.float64)
