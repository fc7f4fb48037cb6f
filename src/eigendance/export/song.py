"""The song beside an export: copied, or cut to the dance's window (docs/design.md#window).

A whole song is copied byte for byte. A clip's song is cut with the ffmpeg of the
imageio-ffmpeg wheel: decoded from `start` for `duration` seconds (input seeking, exact to the
sample when transcoding) and encoded again in the format its file's suffix names (ffmpeg's
default encoder for it: WAV as 16-bit PCM, MP3, Ogg Vorbis, FLAC, AAC, Opus …), its first
audio stream only, bit-exact and without metadata, so the same song and window give the same
bytes.
"""

from __future__ import annotations

import os
import subprocess

import imageio_ffmpeg

from eigendance.errors import InputError, one_line
from eigendance.export.output import check_space
from eigendance.processes import die_with_parent


def seek_options(start: float, duration: float | None) -> list[str]:
    """ffmpeg's input options reading a song from `start` for `duration` seconds.

    Parameters
    ----------
    start : s (0: no seek).
    duration : s, or None (to the end).

    Returns
    -------
    list of arguments to put before ``-i SONG`` (empty for the whole song).

    Example
    -------
    >>> seek_options(12.5, 15.0), seek_options(0.0, None)
    (['-ss', '12.500000', '-t', '15.000000'], [])
    """
    options = ["-ss", f"{start:.6f}"] if start > 0 else []
    return options + (["-t", f"{duration:.6f}"] if duration is not None else [])


def cut_song(source: str | os.PathLike, destination: str | os.PathLike, start: float,
             duration: float) -> None:
    """Write the part of a song from `start` for `duration` seconds into `destination`, in
    the format its suffix names.

    Parameters
    ----------
    source : the song (any format ffmpeg reads).
    destination : the file to write (a temporary of `output.Outputs`: its suffix is the
        format's).
    start, duration : the window, s.
    """
    command = [imageio_ffmpeg.get_ffmpeg_exe(), "-hide_banner", "-loglevel", "error", "-y",
               *seek_options(start, duration), "-i", os.fspath(source), "-map", "0:a:0", "-vn",
               "-map_metadata", "-1", "-fflags", "+bitexact", "-flags:a", "+bitexact",
               os.fspath(destination)]
    done = subprocess.run(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, check=False, preexec_fn=die_with_parent)
    if done.returncode != 0:
        lines = done.stderr.decode(errors="replace").strip().splitlines()
        check_space(done.stderr.decode(errors="replace"), os.fspath(destination))
        raise InputError(f"{os.path.basename(os.fspath(source))}: cannot cut the song "
                         f"({one_line(lines[-1] if lines else done.returncode)})")
