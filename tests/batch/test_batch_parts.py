"""The batch's parts on their own: shared values are read-only views of one mapped file, the
record survives a torn line and refuses a second batch, content keys follow content."""

import json
import os

import numpy as np
import pytest

from eigendance.batch import shared
from eigendance.batch.content import model_digest, referenced_files
from eigendance.batch.plan import Model
from eigendance.batch.record import RECORD, Record, file_entry, read_entries
from eigendance.errors import InputError
from helpers import fixture_path


def test_a_shared_value_is_read_only_views_of_the_mapped_file(tmp_path):
    store = shared.Store(str(tmp_path))
    value = {"big": np.arange(100_000, dtype=np.float64).reshape(-1, 4),
             "fortran": np.asfortranarray(np.ones((30, 7))), "strided": np.arange(9)[::3],
             "text": "bunny"}
    path = store.put(value)
    loaded = shared.load(path)
    assert loaded["text"] == "bunny"
    for name in ("big", "fortran", "strided"):
        np.testing.assert_array_equal(loaded[name], value[name])
    big = loaded["big"]
    assert not big.flags.writeable and not big.flags.owndata
    size = os.path.getsize(path)
    assert value["big"].nbytes < size < value["big"].nbytes + 4096  # raw, not pickled twice
    with pytest.raises(ValueError):
        big[0, 0] = 1.0
    store.close()
    assert not os.path.exists(store.folder)


def test_the_record_skips_a_torn_line_and_one_batch_writes_a_folder_at_a_time(tmp_path):
    (tmp_path / "a.glb").write_bytes(b"glb")
    entry = {"a.glb": file_entry(str(tmp_path / "a.glb"))}
    with Record(str(tmp_path)) as record:
        record.add("a.glb", "key1", entry)
        with pytest.raises(InputError, match="another batch is writing there"):
            Record(str(tmp_path)).__enter__()
    with open(tmp_path / RECORD, "a") as file:
        file.write('{"output": "b.glb", "key": "k", "fil')  # killed mid-line
    assert list(read_entries(str(tmp_path / RECORD))) == ["a.glb"]
    with Record(str(tmp_path)) as record:
        assert record.complete("a.glb", "key1") and not record.complete("a.glb", "key2")
        assert record.ours("a.glb") and not record.ours("b.glb")
        (tmp_path / "a.glb").write_bytes(b"GLB")  # same size, other bytes
        assert not record.complete("a.glb", "key1")
    lines = (tmp_path / RECORD).read_text().splitlines()
    assert [json.loads(line)["output"] for line in lines] == ["a.glb"]  # compacted
    # An output claimed before it is made: its files are the batch's, it is not complete.
    with Record(str(tmp_path)) as record:
        record.claim({"c.glb": ["c.glb", "c.wav"]})
    (tmp_path / "c.glb").write_bytes(b"finished, then Ctrl-C before it was recorded")
    with Record(str(tmp_path)) as record:
        assert record.ours("c.glb") and record.ours("c.wav") and not record.ours("d.glb")
        assert not record.complete("c.glb", "key1") and record.complete("a.glb", "key1") is False


def test_a_models_content_covers_the_files_it_names(tmp_path):
    for name in ("robot.obj", "robot.mtl"):
        (tmp_path / name).write_bytes(open(fixture_path("textured", name), "rb").read())
    model = Model("robot", str(tmp_path / "robot.obj"), "mesh")
    assert [os.path.basename(p) for p in referenced_files(model.path)] == ["robot.mtl"]
    before = model_digest(model)
    with open(tmp_path / "robot.mtl", "a") as file:
        file.write("\n# changed\n")
    assert model_digest(model) != before
    gltf = fixture_path("textured", "craft_speederD.gltf")
    assert [os.path.basename(p) for p in referenced_files(gltf)] == ["craft_speederD_data.bin"]
    assert model_digest(Model("loop4", "loop4", "rig")) != model_digest(Model("x", "hand", "rig"))
