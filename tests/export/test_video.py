"""Videos (docs/design.md#exports): H.264 yuv420p + AAC in MP4, frame i at time i/fps, the song's
start and length, the same bytes every time, the gallery grid, and no partial file ever."""

from __future__ import annotations

import math
import os
import signal
import subprocess
import sys
import time

import av
import numpy as np
import pytest
from export_helpers import SONG

from eigendance.errors import InputError
from eigendance.export.dance import HarmonicDance
from eigendance.export.renderer import BACKGROUND, Look, Renderer, gallery_cells
from eigendance.export.video import parse_size, render_frames, render_video, view_cameras
from eigendance.harmonic.motion import positions_at
from helpers import start

FPS, SIZE = 10.0, (192, 108)


def decode(path):
    with av.open(str(path)) as container:
        video, audio = container.streams.video[0], container.streams.audio[0]
        info = {"video": (video.codec_context.name, video.codec_context.pix_fmt,
                          video.codec_context.width, video.codec_context.height),
                "audio": audio.codec_context.name,
                "video_start": float(video.start_time * video.time_base),
                "audio_start": float(audio.start_time * audio.time_base),
                "video_duration": float(video.duration * video.time_base),
                "audio_duration": float(audio.duration * audio.time_base)}
        frames = [frame.to_ndarray(format="rgb24") for frame in container.decode(video=0)]
    return info, np.array(frames)


@pytest.fixture(scope="module")
def video(harmonic, tmp_path_factory):
    path = tmp_path_factory.mktemp("video") / "dance.mp4"
    report = render_video(path, [harmonic], [Look()], SONG, FPS, SIZE)
    return path, report


def test_the_video_is_h264_with_the_song_as_aac_from_the_same_start(video, harmonic):
    path, report = video
    info, frames = decode(path)
    count = math.ceil(harmonic.duration * FPS)
    assert report["frames"] == len(frames) == count
    assert info["video"] == ("h264", "yuv420p", *SIZE) and info["audio"] == "aac"
    assert info["video_start"] == 0 and info["audio_start"] == 0
    assert abs(info["video_duration"] - harmonic.duration) <= 1 / FPS
    assert abs(info["audio_duration"] - harmonic.duration) <= 1 / FPS


def silhouette(positions, faces, camera, width, height) -> np.ndarray:
    """The pixels a mesh covers, by a rasterizer written here (not the renderer's): each
    triangle's interior, through the camera's view and projection, pixel centres tested with
    barycentric coordinates. (height, width) bool, top row first."""
    points = np.c_[positions, np.ones(len(positions))] @ (camera.projection @ camera.view).T
    pixels = (points[:, :2] / points[:, 3:] + 1) / 2 * [width, height]  # x right, y up
    mask = np.zeros((height, width), bool)
    for a, b, c in pixels[faces]:
        low = np.maximum(np.floor(np.min([a, b, c], axis=0)).astype(int), 0)
        high = np.minimum(np.ceil(np.max([a, b, c], axis=0)).astype(int), [width, height])
        ys, xs = np.mgrid[low[1]:high[1], low[0]:high[0]] + 0.5
        area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        if abs(area) < 1e-12:
            continue
        u = ((b[0] - xs) * (c[1] - ys) - (b[1] - ys) * (c[0] - xs)) / area
        v = ((c[0] - xs) * (a[1] - ys) - (c[1] - ys) * (a[0] - xs)) / area
        inside = (u >= 0) & (v >= 0) & (u + v <= 1)
        mask[low[1]:high[1], low[0]:high[0]] |= inside
    return mask[::-1]


def test_frame_i_shows_time_i_over_fps(video, harmonic):
    """Each decoded frame shows the mesh where the reference positions at i/fps put it: its
    clay silhouette (brighter than the dark studio behind it, the shadow only darkens) matches
    the silhouette rasterized here from `positions_at(i/fps)`, and better than the silhouettes
    of the other times checked (the dance moves between them)."""
    path, _ = video
    _, decoded = decode(path)
    assert len(decoded) == math.ceil(harmonic.duration * FPS)
    checked = [0, 7, 15, 22, 30, len(decoded) - 1]
    times = np.array(checked) / FPS  # frame i shows i/fps
    camera = view_cameras([harmonic], [(0, 0, *SIZE)])[0]
    renderer = Renderer(*SIZE, harmonic.faces, harmonic.rest_normals(), harmonic.rest,
                        harmonic.scale)
    try:  # the empty studio under the same camera: the mesh is what differs from it
        renderer.begin([(0, 0, *SIZE)])
        renderer.draw(None, camera, Look())
        studio = np.frombuffer(renderer.read(), np.uint8).reshape(SIZE[1], SIZE[0], 4)
    finally:
        renderer.release()
    studio = studio[::-1, :, :3].astype(int)
    positions = positions_at(harmonic.basis, harmonic.spectrogram, harmonic.mapping, times)
    expected = [silhouette(p, harmonic.faces, camera, *SIZE) for p in positions]
    overlap = np.zeros((len(checked), len(checked)))
    for row, index in enumerate(checked):
        seen = (decoded[index].astype(int) - studio).sum(axis=2) > 60
        for column, mask in enumerate(expected):
            overlap[row, column] = (seen & mask).sum() / (seen | mask).sum()
    assert np.all(np.diag(overlap) > 0.99), np.diag(overlap)
    assert np.all(np.argmax(overlap, axis=1) == np.arange(len(checked))), overlap


def test_the_same_inputs_give_the_same_bytes(video, harmonic, tmp_path):
    path, _ = video
    again = tmp_path / "again.mp4"
    render_video(again, [harmonic], [Look()], SONG, FPS, SIZE)
    assert again.read_bytes() == path.read_bytes()


def test_a_gallery_is_drawn_as_the_page_grid_each_tile_in_its_studio(basis, song, mappings):
    dances = [HarmonicDance(basis, song, mapping) for mapping in mappings]
    looks = [Look() for _ in dances]
    width, height = 320, 180
    frame = next(render_frames(dances, looks, [1.0], width, height))
    image = np.frombuffer(frame, np.uint8).reshape(height, width, 4)[:, :, :3]  # bottom up
    cells = gallery_cells(len(dances), width, height)
    assert len(cells) == 4 and len({(w, h) for _, _, w, h in cells}) == 1
    first = dances[0]
    renderer = Renderer(width, height, first.faces, first.rest_normals(), first.rest,
                        first.scale)
    try:  # the empty studios under the same cameras: the meshes are what differs
        renderer.begin(cells)
        for cell, camera in zip(cells, view_cameras(dances, cells), strict=True):
            renderer.draw(None, camera, Look(), cell)
        studio = np.frombuffer(renderer.read(), np.uint8).reshape(height, width, 4)[:, :, :3]
    finally:
        renderer.release()
    covered = np.zeros((height, width), bool)
    masks = []
    for x, y, w, h in cells:
        tile = image[y:y + h, x:x + w].astype(float)
        drawn = np.any(np.abs(tile - studio[y:y + h, x:x + w]) > 2, axis=2)
        assert 0.05 < drawn.mean() < 0.9  # the mesh is in its cell, framed
        # the studio: the backdrop is darker at the bottom than at the top
        assert studio[y + 1, x + w // 2].sum() < studio[y + h - 2, x + w // 2].sum()
        masks.append(drawn)
        covered[y:y + h, x:x + w] = True
    assert np.all(image[~covered] == BACKGROUND)  # nothing drawn between the tiles
    # every tile dances its own mapping: no two show the same silhouette
    assert min((masks[i] ^ masks[j]).mean() for i in range(4) for j in range(i)) > 0.002


def test_sizes_are_checked():
    assert parse_size("1280x720") == (1280, 720) and parse_size("64×48") == (64, 48)
    for bad, message in (("1281x720", "even"), ("8x8", "16 to"), ("big", "WIDTHxHEIGHT")):
        with pytest.raises(InputError, match=message):
            parse_size(bad)


def test_an_unreadable_song_is_an_input_error_and_leaves_nothing(harmonic, tmp_path):
    song = tmp_path / "song.ogg"
    song.write_text("not audio")
    with pytest.raises(InputError, match="song.ogg: not a readable audio file"):
        render_video(tmp_path / "dance.mp4", [harmonic], [Look()], song, FPS, SIZE)
    assert sorted(os.listdir(tmp_path)) == ["song.ogg"]


def test_an_existing_video_is_kept_without_force(video, harmonic):
    path, _ = video
    before = path.read_bytes()
    with pytest.raises(InputError, match="exists"):
        render_video(path, [harmonic], [Look()], SONG, FPS, SIZE)
    assert path.read_bytes() == before


def test_ctrl_c_while_rendering_leaves_no_file(tmp_path):
    """The command line, interrupted once frames are flowing: exit status 130, nothing left."""
    output = tmp_path / "out" / "dance.mp4"
    env = dict(os.environ, EIGENDANCE_CACHE_DIR=str(tmp_path / "cache"))
    process = start(
        [sys.executable, "-m", "eigendance.cli", "render", "chain", SONG, "--fps", "240",
         "--size", "640x360", "-o", str(output)], env=env, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and process.poll() is None:
        parts = [name for name in os.listdir(output.parent) if name.endswith(".mp4")] \
            if output.parent.exists() else []
        if parts and os.path.getsize(output.parent / parts[0]) > 0:
            break
        time.sleep(0.05)
    assert process.poll() is None, "the render ended before it could be interrupted"
    process.send_signal(signal.SIGINT)
    _, errors = process.communicate(timeout=60)
    assert process.returncode == 130, errors
    assert "interrupted" in errors
    assert os.listdir(output.parent) == []


def test_render_workers_draw_the_same_frames_in_order(tmp_path):
    """Two forked workers drawing frames in turn give the frames one process draws, in order
    (in a fresh interpreter: a process that has drawn never forks renderers)."""
    script = (
        "import numpy as np, sys, trimesh\n"
        "from eigendance.export.dance import HarmonicDance\n"
        "from eigendance.export.renderer import Look\n"
        "from eigendance.export.video import frames_in_turn, render_frames\n"
        "from eigendance.harmonic.basis import HarmonicBasis\n"
        "from eigendance.harmonic.mesh import Mesh\n"
        "from eigendance.music.gallery import strongest_item\n"
        "from eigendance.music.spectrogram import Spectrogram\n"
        "s = trimesh.creation.icosphere(2)\n"
        "basis = HarmonicBasis.from_mesh(Mesh.from_arrays(s.vertices * [1.4, 1, 0.8], s.faces),"
        " 20, cache=False)\n"
        "song = Spectrogram.from_file(sys.argv[1])\n"
        "dance = HarmonicDance(basis, song, strongest_item(basis, song))\n"
        "times = np.arange(12) / 3.0\n"
        "turns = list(frames_in_turn([dance], [Look()], times, 64, 48, workers=2))\n"
        "alone = list(render_frames([dance], [Look()], times, 64, 48))\n"
        "print(len(turns), turns == alone, len(set(alone)))\n")
    run = subprocess.run([sys.executable, "-c", script, SONG], capture_output=True, text=True,
                         timeout=120)
    assert run.returncode == 0, run.stderr
    assert run.stdout.split() == ["12", "True", "12"]


def test_an_error_in_a_render_worker_is_one_line_and_leaves_nothing(tmp_path):
    output = tmp_path / "out" / "tiny.mp4"
    env = dict(os.environ, EIGENDANCE_CACHE_DIR=str(tmp_path / "cache"))
    run = subprocess.run([sys.executable, "-m", "eigendance.cli", "render",
                          os.path.join(os.path.dirname(SONG), "..", "meshes", "teapot.obj"),
                          SONG, "-k", "8", "--gallery", "4", "--size", "32x16", "-o",
                          str(output)], env=env, capture_output=True, text=True, timeout=300)
    assert run.returncode == 1, run.stderr
    assert run.stderr.strip().endswith("32×16 pixels is too small for a gallery of 4 tiles")
    assert run.stderr.count("\n") == 1
    assert not output.parent.exists() or os.listdir(output.parent) == []
