"""Allocation bombs and files that are not files (issue 21, docs/design.md#errors): sizes a file
declares are checked against what it holds and the memory available before anything is
allocated; rigs beyond the size limit are refused before they are analysed; only regular files
are read; the server's budget is charged before an analysis and released after a failure.

Each bomb is refused with one line naming the file and the field, measured with tracemalloc
(numpy reports its arrays there): a refused bomb allocates almost nothing.
"""

from __future__ import annotations

import io
import json
import os
import struct
import threading
import tracemalloc
import zipfile
import zlib

import numpy as np
import pytest

from bombs import accessor_bomb, chain_gltf, chain_skeleton
from eigendance.assets.materials import _check_decodes
from eigendance.assets.reader import read_model
from eigendance.cli import main
from eigendance.errors import InputError
from eigendance.files import load_npz
from eigendance.harmonic.cache import DiskCache
from eigendance.modal.bodies import MAX_BODIES
from eigendance.modal.sample_rigs import load_rig
from eigendance.server.library import Library

SMALL = 64 << 20  # bytes a refused bomb may allocate on its way to the refusal


def refused_within(call, fragment: str, most: int = SMALL) -> str:
    """call() raises InputError containing `fragment`, having allocated less than `most`."""
    tracemalloc.start()
    try:
        with pytest.raises(InputError) as caught:
            call()
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert fragment in str(caught.value) and "\n" not in str(caught.value)
    assert peak < most, f"{peak / 1e6:.0f} MB allocated before the refusal"
    return str(caught.value)


def test_a_gltf_declaring_a_hundred_million_vertices_is_refused_before_allocating(tmp_path):
    path = accessor_bomb(tmp_path / "bomb.gltf", 10**8)  # 5.8 KB in the probe; 8 GB then
    message = refused_within(lambda: read_model(path), "accessor 0 declares 300000000 values")
    assert message.startswith("bomb.gltf: ")


def test_the_command_line_refuses_the_bomb_in_one_line(tmp_path, capfd):
    path = accessor_bomb(tmp_path / "bomb.gltf", 10**8)
    status = main(["basis", str(path), "-o", str(tmp_path / "basis.npz")])
    err = capfd.readouterr().err.strip().splitlines()
    assert status == 1 and len(err) == 1 and "declares 300000000 values" in err[0]
    assert not os.path.exists(tmp_path / "basis.npz")


def test_zeros_a_file_can_describe_are_read(tmp_path):
    """A sparse-style zero accessor within what the file can describe is read as zeros."""
    model = read_model(accessor_bomb(tmp_path / "few.gltf", 3), warn=False)
    assert len(model.positions) == 3 and not model.positions.any()


@pytest.mark.parametrize("maker, size", [(chain_skeleton, 500), (chain_skeleton, MAX_BODIES + 1),
                                         (chain_gltf, 300)])
def test_rigs_beyond_the_size_limit_are_refused_before_their_analysis(tmp_path, maker, size):
    path = maker(tmp_path / f"rig{'.json' if maker is chain_skeleton else '.glb'}", size)
    message = refused_within(lambda: load_rig(path), f"at most {MAX_BODIES} bodies")
    assert message.startswith(os.path.basename(path))


def test_a_skin_of_thousands_of_joints_is_refused_before_its_weights(tmp_path):
    path = chain_gltf(tmp_path / "snake.glb", 1100)  # 3,000 joints ran past 300 s at 7.8 GB
    refused_within(lambda: load_rig(path), "its skins have 1100 joints; at most 1024")


def test_a_document_of_too_many_nodes_is_refused_before_pygltflib_reads_them(tmp_path):
    path = chain_gltf(tmp_path / "snake.glb", 10_001)  # pygltflib: 3 ms a node, 5 min for 10⁵
    refused_within(lambda: load_rig(path), "lists 10002 nodes; at most 10000")


def test_a_rig_within_the_limit_is_analysed(tmp_path):
    rig = load_rig(chain_skeleton(tmp_path / "snake.json", 40))
    assert rig.n_bodies == 40


def png_declaring(width: int, height: int) -> bytes:
    """A 1×1 PNG whose header (CRC fixed) declares width × height."""
    from PIL import Image

    data = io.BytesIO()
    Image.new("RGB", (1, 1)).save(data, "PNG")
    data = bytearray(data.getvalue())
    body = b"IHDR" + struct.pack(">II", width, height) + bytes(data[24:29])
    data[12:29] = body
    data[29:33] = struct.pack(">I", zlib.crc32(body))
    return bytes(data)


def test_images_declaring_more_than_a_texture_holds_are_refused_before_decoding():
    _check_decodes(png_declaring(1, 1))
    refused_within(lambda: _check_decodes(png_declaring(20_000, 1_000)),
                   "an image of 20000 × 1000 pixels")
    refused_within(lambda: _check_decodes(png_declaring(100_000, 100_000)), "image")


def npz_declaring(path, shape) -> str:
    """An .npz whose one member's header declares `shape` float64 but holds 8 bytes."""
    header = io.BytesIO()
    np.lib.format.write_array_header_1_0(header, {"descr": "<f8", "fortran_order": False,
                                                  "shape": shape})
    with zipfile.ZipFile(path, "w") as archive:
        archive.writestr("values.npy", header.getvalue() + b"\0" * 8)
    return str(path)


def test_an_npz_member_declaring_more_than_it_holds_is_refused(tmp_path):
    path = npz_declaring(tmp_path / "spectrum.npz", (10**10,))
    refused_within(lambda: load_npz(path, ("values",)), "values declares (10000000000,)")
    assert load_npz(npz_declaring(tmp_path / "one.npz", (1,)), ("values",))["values"].shape == (1,)


def finishes(call, seconds: float = 20.0):
    """call()'s result (or exception) if it returns within `seconds`; the test fails if it
    blocks (the thread is a daemon: a blocked reader does not keep pytest alive)."""
    outcome = {}

    def target():
        try:
            outcome["value"] = call()
        except Exception as error:  # noqa: BLE001 - handed to the test
            outcome["error"] = error

    thread = threading.Thread(target=target, daemon=True)
    thread.start()
    thread.join(seconds)
    assert not thread.is_alive(), "the reader blocked"
    return outcome


def gltf_with_buffer(folder, uri: str) -> str:
    path = os.path.join(folder, "model.gltf")
    accessor_bomb(path, 3)
    with open(path, encoding="utf-8") as file:
        document = json.load(file)
    document["buffers"][0]["uri"] = uri
    with open(path, "w", encoding="utf-8") as file:
        json.dump(document, file)
    return path


def test_a_fifo_named_by_a_gltf_buffer_is_refused_not_waited_for(tmp_path):
    os.mkfifo(tmp_path / "data.bin")
    outcome = finishes(lambda: read_model(gltf_with_buffer(tmp_path, "data.bin")))
    assert isinstance(outcome.get("error"), InputError), outcome
    assert "not a regular file (a FIFO)" in str(outcome["error"])


def test_a_buffer_through_a_linked_folder_outside_the_model_is_refused(tmp_path):
    os.symlink("/proc/self", tmp_path / "inside")
    with pytest.raises(InputError, match="leads outside the model's folder"):
        read_model(gltf_with_buffer(tmp_path, "inside/environ"))


def test_a_fifo_in_place_of_a_cache_entry_is_replaced_not_waited_for(tmp_path):
    cache = DiskCache(folder=str(tmp_path))
    os.mkfifo(cache.path("key"))
    outcome = finishes(lambda: cache.get("key", lambda: {"a": np.arange(3.0)}))
    assert outcome["value"]["a"].tolist() == [0.0, 1.0, 2.0]
    assert os.path.isfile(cache.path("key"))  # computed again and stored as a file


def test_the_server_charges_an_analysis_before_it_and_releases_it_after_a_failure(tmp_path,
                                                                                  monkeypatch):
    library = Library(str(tmp_path / "library"), k=8, memory_budget=64 << 20)
    try:
        snake = chain_skeleton(tmp_path / "snake.json", 60)  # plans more than 64 MB
        with pytest.raises(InputError, match="would take") as caught:
            library.add_path(snake)
        assert caught.value.status == 413 and library.budget.used == 0 and not library.rigs.keys()\
            - {key for key, item in library.rigs.items() if item.origin == "built-in"}
        seen = []

        def failing(item, skeleton, run, original=None, dtype=None):
            seen.append(library.budget.used)  # charged while the analysis runs
            raise InputError("analysis failed")

        monkeypatch.setattr("eigendance.server.rigs.analyse", failing)
        with pytest.raises(InputError, match="analysis failed"):
            library.add_path(chain_skeleton(tmp_path / "small.json", 4))
        assert seen and seen[0] > 0 and library.budget.used == 0
    finally:
        library.close()
