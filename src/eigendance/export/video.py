"""Video of a dance with its song: H.264 (yuv420p) and AAC in MP4 (docs/design.md#exports).

Frame i shows the dance at time i/fps exactly, i < ⌈duration·fps⌉ (`dance.video_times`): the
video starts with the song and lasts as long, to within one frame. Frames are drawn offscreen
(`renderer.Renderer`, the player's look) and piped as raw RGBA into the ffmpeg that the
imageio-ffmpeg wheel ships, which encodes them while the next ones are drawn and muxes the song's
audio re-encoded as AAC. The encoder runs bit-exact (no timestamps or version strings in the
file), so the same inputs give the same bytes. ffmpeg writes to a temporary file beside the
destination, renamed over it only when everything succeeded (`output.Outputs`): Ctrl-C, a crash
or an encoder failure leaves nothing behind.
"""

from __future__ import annotations

import contextlib
import math
import os
import re
import subprocess
import tempfile
from fractions import Fraction

import imageio_ffmpeg
import numpy as np

from eigendance import processes
from eigendance.checks import shown
from eigendance.errors import InputError, InternalError, one_line
from eigendance.export.dance import Dance, video_times
from eigendance.export.output import Outputs, check_space
from eigendance.export.renderer import POSES, Camera, Look, Renderer, gallery_cells, gl_started, rim
from eigendance.export.song import seek_options
from eigendance.inputs.defaults import DEFAULT_FPS
from eigendance.limits import check_disk
from eigendance.music.decode import open_audio

MAX_SIDE = 7680  # pixels (8K)
MIN_FPS = 0.01  # frames per second: one frame every 100 s (a rate of 1/100)
# Processes drawing frames in turn. llvmpipe transforms and sets up triangles on one thread, which
# bounds a fine mesh (the bunny: 25 of its 60 ms of CPU per frame); two single-threaded renderers
# keep both cores busy (measured in benchmarks/bench_render.py).
WORKERS = 2
PRESET, CRF, AUDIO_BITRATE = "veryfast", 18, "192k"  # x264 speed/quality, AAC bit rate


SIZE = re.compile(r"\s*([0-9]{1,5})\s*[xX×]\s*([0-9]{1,5})\s*")  # WIDTHxHEIGHT (`parse_size`)


def parse_size(text) -> tuple[int, int]:
    """'1280x720' (or '1280×720', any case, spaces around) → (1280, 720); both even (yuv420p
    halves the chroma), 16 … MAX_SIDE: the one grammar of a video's size (`render --size`,
    a batch plan's `size`, the page's export).

    Parameters
    ----------
    text : WIDTHxHEIGHT.

    Returns
    -------
    (width, height).

    Raises
    ------
    InputError
        For anything else: not two whole numbers around "x", an odd side, a side out of range.

    Example
    -------
    >>> parse_size("1280x720"), parse_size(" 640 × 360 ")
    ((1280, 720), (640, 360))
    """
    found = SIZE.fullmatch(text) if isinstance(text, str) else None
    if found is None:
        raise InputError(f"size {shown(text)}: expected WIDTHxHEIGHT in pixels, e.g. 1280x720")
    width, height = int(found[1]), int(found[2])
    check_size(width, height)
    return width, height


def check_size(width: int, height: int) -> None:
    """InputError unless both sides are even and 16 … MAX_SIDE pixels.

    Parameters
    ----------
    width, height : pixels.
    """
    for side in (width, height):
        if not 16 <= side <= MAX_SIDE:
            raise InputError(f"size {width}x{height}: each side must be 16 to {MAX_SIDE} pixels")
        if side % 2:
            raise InputError(f"size {width}x{height}: H.264 in yuv420p needs even sides")


def ffmpeg_command(width: int, height: int, fps: float, audio: str, output: str,
                   start: float = 0.0, duration: float | None = None) -> list[str]:
    """The encoder: raw RGBA frames (bottom row first) on stdin + the song → MP4.

    Parameters
    ----------
    width, height : pixels.
    fps : frames per second.
    audio : the song's file.
    output : the MP4 to write.
    start, duration : the part of the song to mux, s (`export.song.seek_options`; None: to
        the end).

    Returns
    -------
    list of the command's arguments.
    """
    rate = Fraction(fps).limit_denominator(1001)
    return [imageio_ffmpeg.get_ffmpeg_exe(), "-hide_banner", "-loglevel", "error", "-y",
            "-f", "rawvideo", "-pix_fmt", "rgba", "-s", f"{width}x{height}",
            "-framerate", f"{rate.numerator}/{rate.denominator}", "-i", "pipe:0",
            *seek_options(start, duration), "-i", audio, "-map", "0:v:0", "-map", "1:a:0",
            "-vf", "vflip", "-c:v", "libx264", "-preset", PRESET, "-crf", str(CRF),
            "-pix_fmt", "yuv420p", "-c:a", "aac", "-b:a", AUDIO_BITRATE,
            "-map_metadata", "-1", "-fflags", "+bitexact", "-flags:v", "+bitexact",
            "-flags:a", "+bitexact", "-movflags", "+faststart", "-f", "mp4", output]


def check_song(path) -> str:
    """The song's path; InputError (one line) unless it decodes (its first chunk is read).

    Parameters
    ----------
    path : the song's file.

    Returns
    -------
    str.
    """
    _, chunks = open_audio(path)
    next(iter(chunks), None)
    if hasattr(chunks, "close"):
        chunks.close()
    return os.fspath(path)


def _one_by_one(chunks):
    """(positions, normals) per frame from a dance's chunks."""
    for _, positions, normals in chunks:
        for index in range(len(positions)):
            yield positions[index], None if normals is None else normals[index]


def render_frames(dances: list[Dance], looks: list[Look], times, width: int, height: int):
    """Draw each frame at `times`: yields the RGBA bytes (bottom row first) of each.

    One dance fills the frame as the player shows it; several (a gallery of the same mesh)
    share it in the page's grid. Each view's camera frames its dance as the page does: the rest
    shape and the rim in the loudest poses.

    Parameters
    ----------
    dances : one dance, or several of the same mesh.
    looks : one `Look` per dance.
    times : (T,) s of the dances.
    width, height : pixels.

    Yields
    ------
    bytes, 4·width·height per frame.
    """
    first = dances[0]
    if any(dance.n != first.n or len(dance.faces) != len(first.faces) for dance in dances):
        raise InputError("a gallery's dances must share one mesh")
    cells = [(0, 0, width, height)] if len(dances) == 1 else \
        gallery_cells(len(dances), width, height)
    cameras = view_cameras(dances, cells)
    renderer = Renderer(width, height, first.faces, first.rest_normals(), first.rest,
                        first.scale, first.appearance)
    try:
        streams = [_one_by_one(dance.frames(times)) for dance in dances]
        for frame in zip(*streams, strict=True):
            renderer.begin(cells)
            for (positions, normals), camera, look, cell in zip(frame, cameras, looks, cells,
                                                                strict=True):
                renderer.draw(positions, camera, look, cell, normals)
            yield renderer.read()
    finally:
        renderer.release()


def view_cameras(dances: list[Dance], cells) -> list[Camera]:
    """The camera of each dance's view (x, y, w, h): framed as the page frames it, on the rest
    shape and the rim in the dance's loudest poses (`renderer.Camera.framing`).

    Parameters
    ----------
    dances : the dances.
    cells : their views (x, y, w, h).

    Returns
    -------
    list of Camera.
    """
    first = dances[0]
    framed = rim(first.rest)
    return [Camera.framing(first.rest, dance.positions(dance.loudest_times(POSES))[:, framed],
                           first.scale, w / h)
            for dance, (_, _, w, h) in zip(dances, cells, strict=True)]


def frames_in_turn(dances: list[Dance], looks: list[Look], times, width: int, height: int,
                   workers: int = WORKERS):
    """`render_frames`, drawn by `workers` forked processes in turn (frame i by worker i mod
    workers, each with its own single-threaded llvmpipe context): yields the frames in order.

    Forking is safe here: a worker only draws (numpy, its own GL context) and writes to its pipe;
    it imports nothing and takes no lock another thread of the caller may hold. A caller that has
    drawn before (`renderer.gl_started`) draws itself instead: a fork would inherit llvmpipe's
    state without its threads. Workers ignore Ctrl-C (the caller handles it and kills them) and
    die with the caller.

    Parameters
    ----------
    dances, looks, times, width, height : as for `render_frames`.
    workers : processes drawing in turn.

    Yields
    ------
    bytes, each frame in order.
    """
    times = np.asarray(times, dtype=np.float64)
    if workers <= 1 or len(times) < 2 * workers or gl_started() or not processes.can_fork():
        yield from render_frames(dances, looks, times, width, height)
        return
    context = processes.context("fork")
    pipes, started = [], []
    try:
        for worker in range(workers):
            receive, send = context.Pipe(duplex=False)
            process = context.Process(target=_draw_in_turn, daemon=True, args=(
                send, dances, looks, times[worker::workers], width, height))
            process.start()
            send.close()
            pipes.append(receive)
            started.append(process)
        size = width * height * 4
        for index in range(len(times)):
            try:
                frame = pipes[index % workers].recv_bytes()
            except EOFError:
                raise InternalError("a render worker stopped without a word") from None
            if len(frame) != size:  # a worker's error: "kind<TAB>message"
                kind, _, message = frame.decode(errors="replace").partition("\t")
                raise (InputError if kind == "InputError" else InternalError)(message)
            yield frame
    finally:
        for process in started:
            processes.kill(process)
            process.join()
        for pipe in pipes:
            pipe.close()


def _draw_in_turn(send, dances, looks, times, width, height) -> None:
    """In a render worker: draw `times` and send each frame (or one error line) to the caller."""
    processes.start_worker()  # Ctrl-C is the caller's; the kernel kills us when the caller dies
    os.environ["LP_NUM_THREADS"] = "1"  # read when llvmpipe starts: one thread per worker
    try:
        for frame in render_frames(dances, looks, times, width, height):
            send.send_bytes(frame)
    except BrokenPipeError:
        pass  # the caller stopped reading
    except BaseException as error:  # noqa: BLE001 - everything goes back to the caller
        send.send_bytes(f"{type(error).__name__}\t{one_line(error)}".encode())
    finally:
        send.close()


def encode(command: list[str], frames, count: int, progress=None, path: str = "") -> None:
    """Run the encoder and feed it the frames; the encoder's last error line on failure.

    The encoder dies with this process (`processes.die_with_parent`).

    Parameters
    ----------
    command : the encoder's command (`ffmpeg_command`).
    frames : iterable of raw RGBA frames (bytes).
    count : how many frames (for `progress`).
    progress : optional callable(frames done, frames in all).
    path : the video, for messages (a full disk is an InputError naming it).
    """
    log = tempfile.TemporaryFile()  # a file, not a pipe: the encoder never blocks on it
    encoder = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                               stderr=log, preexec_fn=processes.die_with_parent)
    try:
        try:
            for index, frame in enumerate(frames):
                encoder.stdin.write(frame)
                if progress is not None:
                    progress(index + 1, count)
            encoder.stdin.close()
        except BrokenPipeError:
            pass  # the encoder stopped: its own message follows
        encoder.wait()
        log.seek(0)
        errors = log.read().decode(errors="replace")
        if encoder.returncode != 0:
            last = one_line(errors.strip().splitlines()[-1] if errors.strip() else
                            f"exit status {encoder.returncode}")
            check_space(errors, path or command[-1])
            raise InternalError(f"ffmpeg failed: {last}")
    finally:
        if encoder.poll() is None:
            encoder.kill()
            encoder.wait()
        try:
            encoder.stdin.close()
        except BrokenPipeError:
            pass  # the encoder is gone; nothing more to flush
        log.close()


# The least bytes of H.264 a pixel of a frame took at CRF 18 (measured: 0.0005 for the knight at
# 640x360, 0.002 for the teapot at 1280x720) and of AAC a second (3,000 for a mono 8 kHz song,
# 9,400 for a stereo one): the planned size of a video is a floor, refusing what cannot fit,
# not what might (a disk that fills anyway is one line too).
VIDEO_BYTES_PER_PIXEL, AUDIO_BYTES_PER_SECOND = 0.0005, 3000


def video_bytes(width: int, height: int, frames: int, duration: float) -> float:
    """About how many bytes a video takes (checked against the free disk before rendering).

    Parameters
    ----------
    width, height : pixels.
    frames : how many.
    duration : s.

    Returns
    -------
    float, bytes.
    """
    return VIDEO_BYTES_PER_PIXEL * width * height * frames + AUDIO_BYTES_PER_SECOND * duration


def render_video(path: str | os.PathLike, dances: list[Dance], looks: list[Look],
                 audio: str | os.PathLike, fps: float = DEFAULT_FPS, size=(1280, 720),
                 force: bool = False, progress=None, workers: int = WORKERS,
                 inputs=()) -> dict:
    """Render dances (one, or a gallery of the same mesh) with their song into an MP4.

    Parameters
    ----------
    path : the .mp4 to write (atomically; never overwritten unless `force`).
    dances : one dance, or several of the same mesh drawn as the page's gallery grid; windows
        of their song (`Dance.window`, the same for all) cut the song to the same part.
    looks : one `Look` per dance.
    audio : the song's file (any format ffmpeg reads), muxed as AAC.
    fps : frames per second; size : (width, height) in pixels, both even.
    progress : optional callable(frames done, frames in all).
    workers : processes drawing frames in turn (1: this process draws; a batch, whose workers
        each have a core, draws so).
    inputs : the files the render reads besides the song: never written over.

    Returns
    -------
    {"path", "frames", "fps", "size", "duration"}.
    """
    if not dances or len(looks) != len(dances):
        raise InputError("render needs at least one dance and one look per dance")
    width, height = (int(side) for side in size)
    check_size(width, height)
    if not (math.isfinite(fps) and MIN_FPS <= fps <= 240):
        raise InputError(f"video: frames per second must be from {MIN_FPS:g} to 240 (the "
                         f"encoder's frame rate is a fraction of denominator ≤ 1001), got {fps:g}")
    audio = check_song(audio)
    duration = max(dance.duration for dance in dances)
    start = dances[0].start
    if any(dance.start != start for dance in dances):
        raise InputError("a gallery's dances must start at the same time of the song")
    clipped = any(dance.clipped for dance in dances)
    times = video_times(duration, fps)
    path = os.fspath(path)
    outputs = Outputs([path], force, [*inputs, audio])
    check_disk(path, video_bytes(width, height, len(times), duration),
               f"{os.path.basename(path)}: {len(times)} frames of {width}x{height}")
    with outputs:
        command = ffmpeg_command(width, height, fps, audio, outputs.temporary(path), start,
                                 duration if clipped else None)
        # closing: an interruption stops the drawing workers here, before `outputs` cleans up
        # (a generator left to the garbage collector keeps them, and the pipes they inherited).
        with contextlib.closing(frames_in_turn(dances, looks, times, width, height,
                                               workers)) as frames:
            encode(command, frames, len(times), progress, path)
    return {"path": path, "frames": len(times), "fps": fps, "size": (width, height),
            "duration": duration}
