"""Skeleton JSON (docs/design.md#skeleton-file): reading, one-line errors naming the bad item."""

import json

import numpy as np
import pytest

from eigendance.errors import EigendanceError
from eigendance.modal.sample_rigs import load_rig
from eigendance.modal.skeleton import Skeleton


def document(**changes):
    base = {"format": "eigendance.skeleton", "version": 1,
            "bodies": [{"name": "upper", "start": [0, 0, 0], "end": [0, 0, 1], "radius": 0.1,
                        "density": 1000},
                       {"name": "lower", "start": [0, 0, 1], "end": [0, 1, 1], "radius": 0.1}],
            "joints": [{"name": "knee", "type": "revolute", "bodies": ["upper", "lower"],
                        "stiffness": 10.0, "damping": 0.1}]}
    base.update(changes)
    return base


def write(tmp_path, content):
    path = tmp_path / "rig.json"
    path.write_text(content if isinstance(content, str) else json.dumps(content))
    return path


def test_reads_a_valid_skeleton(tmp_path):
    skeleton = Skeleton.from_json(write(tmp_path, document()))
    assert skeleton.body_names == ["upper", "lower"]
    joint = skeleton.joints[0]
    np.testing.assert_allclose(joint.position, [0, 0, 1])  # the shared end
    assert joint.type == "revolute" and joint.stiffness.tolist() == [10.0]
    body = skeleton.bodies[0]
    assert body.mass == pytest.approx(1000 * np.pi * 0.01)
    assert body.inertia[0] == pytest.approx(body.mass * 0.01 / 2)
    assert body.inertia[1] == pytest.approx(body.mass * (0.03 + 1) / 12)
    again = Skeleton.from_dict(skeleton.to_dict())
    np.testing.assert_allclose(again.joints[0].position, joint.position)


@pytest.mark.parametrize("changes, message", [
    ({"joints": [{"name": "knee", "type": "revolute", "bodies": ["upper", "shin"],
                  "stiffness": 1}]}, "joint 'knee' names unknown body 'shin'"),
    ({"bodies": [{"name": "upper", "start": [0, 0, 0], "end": [0, 0, 0], "radius": 0.1}],
      "joints": []}, "body 'upper' has zero length"),
    ({"bodies": [{"name": "a", "start": [0, 0, 0], "end": [0, 0, 1], "radius": 0.1},
                 {"name": "a", "start": [0, 0, 1], "end": [0, 0, 2], "radius": 0.1}],
      "joints": []}, "duplicate body name 'a'"),
    ({"bodies": [{"name": "a", "start": [0, float("nan"), 0], "end": [0, 0, 1],
                  "radius": 0.1}], "joints": []}, "body 'a': \"start\" is not finite"),
    ({"joints": [{"name": "knee", "type": "hinge", "bodies": ["upper", "lower"],
                  "stiffness": 1}]}, "joint 'knee' has unknown type 'hinge'"),
    ({"joints": [{"name": "knee", "type": "revolute", "bodies": ["upper", "lower"]}]},
     "joint 'knee' needs a \"stiffness\""),
    ({"joints": [{"name": "knee", "type": "spherical", "bodies": ["upper", "lower"],
                  "stiffness": [1, 2]}]}, "list of 3 numbers"),
    ({"bodies": [{"name": "a", "start": [0, 0, 0], "end": [0, 0, 1], "radius": -1}],
      "joints": []}, "body 'a': \"radius\" must be positive"),
    ({"format": "something.else"}, "not an eigendance skeleton"),
    ({"version": 7}, "unsupported skeleton version 7"),
])
def test_validation_errors_are_one_line_and_name_the_item(tmp_path, changes, message):
    with pytest.raises(EigendanceError) as caught:
        Skeleton.from_json(write(tmp_path, document(**changes)))
    assert message in str(caught.value)
    assert "\n" not in str(caught.value)


def test_malformed_json_and_missing_file(tmp_path):
    with pytest.raises(EigendanceError, match=r"malformed JSON at line 1"):
        Skeleton.from_json(write(tmp_path, '{"format": "eigendance.skeleton", '))
    with pytest.raises(EigendanceError, match="no such file"):
        Skeleton.from_json(tmp_path / "nothing.json")
    with pytest.raises(EigendanceError, match="unknown rig format"):
        load_rig(tmp_path / "rig.obj")


def test_a_loop_written_as_json_keeps_the_thesis_dimensions(tmp_path):
    from eigendance.modal.model import ModalModel
    from eigendance.modal.sample_rigs import planar_loop

    document = planar_loop(4, skin=False).to_dict()
    for joint in document["joints"]:
        del joint["position"]  # found again where the bodies meet
    skeleton = Skeleton.from_json(write(tmp_path, document))
    model = ModalModel.from_skeleton(skeleton)
    assert (model.constraint_rows, model.nullspace_dim, model.rigid_modes) == (20, 7, 6)
