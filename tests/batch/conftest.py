"""Small inputs for batch tests: a 162-vertex sphere, built-in rigs, 2-second songs made here;
one local Ray for the whole session (Ray's testing guide: start+stop costs seconds)."""

import logging
import os

import pytest
import trimesh
from batch_helpers import song

from helpers import required


@pytest.fixture
def inputs(tmp_path):
    """A folder with sphere.obj and two songs, a.wav and b.wav."""
    icosphere = trimesh.creation.icosphere(2)
    icosphere.vertices *= [1.3, 1.0, 0.8]
    icosphere.export(tmp_path / "sphere.obj")
    song(str(tmp_path / "a.wav"), seed=0)
    song(str(tmp_path / "b.wav"), seed=1)
    return tmp_path


@pytest.fixture(scope="session")
def ray_session():
    """One local Ray (2 CPUs) for the session; the batch joins it."""
    try:
        import ray
    except ImportError:
        ray = None
    required("Ray", ray is not None, "pip install 'eigendance[ray]'")
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False,
             logging_level=logging.WARNING)
    yield ray
    ray.shutdown()


def temporaries(folder) -> list[str]:
    """The temporary files of writers in `folder` (none must be left)."""
    return [name for name in os.listdir(folder) if name.startswith(".eigendance-")]
