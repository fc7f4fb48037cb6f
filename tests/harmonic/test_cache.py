"""The disk cache of arrays: hits, and entries that must not be trusted are computed again."""

import os

import numpy as np
import pytest

from eigendance.harmonic.cache import DiskCache, checksum


@pytest.fixture
def cache(tmp_path):
    return DiskCache(folder=str(tmp_path / "cache"))


def counted(arrays):
    calls = []

    def fetch():
        calls.append(1)
        return arrays
    return fetch, calls


def test_a_second_get_reads_the_stored_arrays(cache):
    fetch, calls = counted({"values": np.arange(5.0), "matrix": np.eye(3)})
    first = cache.get("key one", fetch)
    second = cache.get("key one", fetch)
    assert calls == [1]
    np.testing.assert_array_equal(second["matrix"], np.eye(3))
    assert set(first) == set(second) == {"values", "matrix"}


def test_the_checksum_covers_names_shapes_and_bytes():
    arrays = {"a": np.arange(6.0)}
    assert checksum(arrays) == checksum({"a": np.arange(6.0)})
    assert checksum(arrays) != checksum({"b": np.arange(6.0)})
    assert checksum(arrays) != checksum({"a": np.arange(6.0).reshape(2, 3)})
    assert checksum(arrays) != checksum({"a": np.arange(6.0) * 2})


def test_an_entry_stored_under_another_key_is_computed_again(cache):
    fetch, calls = counted({"values": np.ones(3)})
    cache.get("k=10", fetch)
    os.replace(cache.path("k=10"), cache.path("k=20"))  # the right file under the wrong name
    cache.get("k=20", fetch)
    assert calls == [1, 1]


def test_arrays_changed_after_storing_are_computed_again(cache):
    fetch, calls = counted({"values": np.ones(3)})
    cache.get("key", fetch)
    with np.load(cache.path("key")) as data:
        stored = {name: data[name] for name in data.files}
    stored["values"] = stored["values"] * 2  # consistent shapes, wrong numbers
    np.savez(cache.path("key"), **stored)
    again = cache.get("key", fetch)
    assert calls == [1, 1] and np.all(again["values"] == 1)


@pytest.mark.parametrize("damage", ["truncate", "folder", "garbage"])
def test_unreadable_entries_are_replaced(cache, damage):
    fetch, calls = counted({"values": np.ones(3)})
    cache.get("key", fetch)
    path = cache.path("key")
    if damage == "truncate":
        with open(path, "r+b") as file:
            file.truncate(100)
    elif damage == "folder":
        os.unlink(path)
        os.makedirs(path)
    else:
        with open(path, "wb") as file:
            file.write(b"garbage")
    assert np.all(cache.get("key", fetch)["values"] == 1) and calls == [1, 1]
    assert os.path.isfile(path)


def test_an_unwritable_folder_only_costs_the_speed_up(tmp_path):
    blocked = tmp_path / "file"
    blocked.write_text("in the way")
    cache = DiskCache(folder=str(blocked / "cache"))
    fetch, calls = counted({"values": np.ones(2)})
    cache.get("key", fetch)
    cache.get("key", fetch)
    assert calls == [1, 1]


def test_temporary_files_of_killed_writers_are_swept(cache):
    """A writer holds a lock on its temporary file; one nobody holds is debris (tests/test_files.py
    covers the rule, this the cache's use of it)."""
    os.makedirs(cache.folder)
    left = os.path.join(cache.folder, ".eigendance-abc.part")
    with open(left, "w") as file:
        file.write("half an entry")
    cache.get("key", lambda: {"values": np.ones(1)})
    assert not os.path.exists(left)
    assert [name for name in os.listdir(cache.folder) if name.endswith(".part")] == []


def test_the_clients_check_of_the_content_rebuilds_a_refused_entry(cache):
    fetch, calls = counted({"values": np.arange(3.0)})
    cache.get("key", fetch)
    assert cache.get("key", fetch, valid=lambda found: True)["values"].tolist() == [0, 1, 2]
    assert calls == [1]
    cache.get("key", fetch, valid=lambda found: False)
    assert calls == [1, 1] and os.path.exists(cache.path("key"))
