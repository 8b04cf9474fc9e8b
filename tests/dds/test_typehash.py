"""RIHS01 type hashes (labkit/dds/typehash.py) against the ones the real Jazzy
packages ship (share/<pkg>/msg/<Type>.json of the reference venv's wheels)."""
import json

import pytest

from labkit.dds import typehash
from tests.dds.test_real_peers import ROSREF

SHARE = ROSREF.parent.parent / "share"
# types whose Humble definition (labkit's) differs from Jazzy's, so their hash does too
HUMBLE_DIFFERS = {
    "rmw_dds_common/msg/Gid",                       # char[24] in Humble, char[16] in Jazzy
    "rmw_dds_common/msg/NodeEntitiesInfo", "rmw_dds_common/msg/ParticipantEntitiesInfo",
    "sensor_msgs/msg/Range",                        # Jazzy added 'variance'
}


def _real_hashes():
    for path in sorted(SHARE.glob("*/msg/*.json")):
        for entry in json.loads(path.read_text())["type_hashes"]:
            yield entry["type_name"], entry["hash_string"]


@pytest.mark.skipif(not SHARE.is_dir(), reason="no real-ROS reference venv .venv-rosref (real rclpy wheels: Linux x86_64, CPython 3.11/3.12 only; make setup builds it there)")
def test_every_message_labkit_knows_hashes_as_the_real_packages_say():
    compared, differ = 0, set()
    for name, real_hash in _real_hashes():
        try:
            ours = typehash.type_hash(name)
        except LookupError:            # a package labkit does not bundle (test_msgs, ...)
            continue
        compared += 1
        if ours != real_hash:
            differ.add(name)
    assert compared > 300
    assert differ == HUMBLE_DIFFERS


def test_known_hashes_empty_structure_and_user_data():
    # the values real Jazzy prints in `ros2 topic info -v`
    assert typehash.type_hash("std_msgs/msg/String") == \
        "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18"
    # an empty message is hashed with rosidl's one uint8 member
    assert typehash.type_hash("std_msgs/msg/Empty") == \
        "RIHS01_20b625256f32d5dbc0d04fee44f43c41e51c70d3502f84b4a08e7a9c26a96312"
    assert typehash.user_data("geometry_msgs/msg/Twist") == \
        b"typehash=" + typehash.type_hash("geometry_msgs/msg/Twist").encode() + b";"
    assert typehash.user_data("no_such_pkg/msg/Nothing") == b""
    ft = typehash.field_type
    from labkit.interfaces import definition as d
    assert ft(d.BoundedSequence(d.BoundedString(5), 3)) == {
        "type_id": 117, "capacity": 3, "string_capacity": 5, "nested_type_name": ""}
    assert ft(d.Array(d.NamespacedType(["geometry_msgs", "msg"], "Point"), 2)) == {
        "type_id": 49, "capacity": 2, "string_capacity": 0,
        "nested_type_name": "geometry_msgs/msg/Point"}
