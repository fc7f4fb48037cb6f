"""Songs: an audio file decoded into its spectrogram, or a spectrogram file
(docs/design.md#inputs).

`read_song` is how the command line, the server and the batch read a song: a .npz is a
spectrogram written by `eigendance spectrum`; anything else is audio, decoded and analysed
(`Spectrogram.from_file`), a decoder's failure one line naming the file.
"""

from __future__ import annotations

import os

from eigendance.errors import EigendanceError, InputError, one_line
from eigendance.files import SPECTROGRAM_SUFFIXES, suffix_of
from eigendance.music.spectrogram import Spectrogram


def is_spectrogram_file(path: str | os.PathLike) -> bool:
    """Whether a song is given as its spectrogram file (.npz) rather than as audio.

    Parameters
    ----------
    path : the song's file.

    Returns
    -------
    bool.
    """
    return suffix_of(path) in SPECTROGRAM_SUFFIXES


def read_song(path: str | os.PathLike, bands: int = 64, name: str | None = None,
              **options) -> Spectrogram:
    """A song's spectrogram: a spectrogram file as it is, or an audio file analysed into
    `bands` bands.

    Parameters
    ----------
    path : a spectrogram file (.npz) or an audio file (`files.AUDIO_SUFFIXES`).
    bands : bands of an audio file's spectrogram.
    name : how messages call it (default: the file's name).
    **options : the other options of `Spectrogram.from_file` (rate …).

    Returns
    -------
    Spectrogram.

    Raises
    ------
    InputError
        For a missing or unreadable file, an unknown audio format, audio that cannot be
        decoded (one line naming the file), a spectrogram file at fault (the field named).
    """
    if is_spectrogram_file(path):
        return Spectrogram.load(path)
    name = name or os.path.basename(os.fspath(path))
    try:
        return Spectrogram.from_file(path, bands=bands, **options)
    except EigendanceError:
        raise
    except Exception as error:  # noqa: BLE001 - decoders raise many types
        raise InputError(f"{name}: cannot decode the audio ({one_line(error)})") from None
