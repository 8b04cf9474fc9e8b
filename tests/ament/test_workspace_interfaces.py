"""A package made with `pkg create` in a workspace's src, read as an interface root.

Covers the two interface-layer behaviours chapter 9 relies on: rosidl's check of
the message and package names, and re-reading a package after a new .msg appears.
"""
import sys

import pytest

import labkit.interfaces as ifc
from labkit import compat
from labkit.ament import create, files
from labkit.interfaces.parser import InvalidResourceName, parse_message_string


@pytest.fixture
def src(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    was_active = compat.is_active() if hasattr(compat, 'is_active') else None
    compat.activate()
    yield tmp_path
    ifc.remove_share_path(str(tmp_path))
    for key in [k for k in sys.modules if k.split('.')[0] == 'ws_test_interfaces']:
        del sys.modules[key]
    if was_active is False:
        compat.deactivate()
    files.leave_home(remove=False)


def test_message_and_package_names_are_checked_like_rosidl():
    assert parse_message_string('facer_interfaces', 'DetectResult', 'string r').msg_name == \
        'DetectResult'
    with pytest.raises(InvalidResourceName, match="'detect_result' is an invalid message name"):
        parse_message_string('facer_interfaces', 'detect_result', 'string r')
    with pytest.raises(InvalidResourceName, match="'FacerInterfaces' is an invalid package name"):
        parse_message_string('FacerInterfaces', 'DetectResult', 'string r')
    # service and action parts keep their suffixes, as in rosidl_adapter
    parse_message_string('facer_interfaces', 'FaceResult_Request', 'string r')
    parse_message_string('facer_interfaces', 'CameraState_Feedback', 'string r')


def test_new_msg_file_is_importable_after_registering_again(src, capsys):
    assert create.main(['ws_test_interfaces', '--license', 'MIT']) == 0
    files.mkdir('ws_test_interfaces/msg')
    (src / 'ws_test_interfaces/msg/First.msg').write_text('int32 a 7\n')
    ifc.add_share_path(str(src))
    from ws_test_interfaces.msg import First
    assert First().a == 7
    (src / 'ws_test_interfaces/msg/Second.msg').write_text('uint8 LIMIT=3\nstring b "x"\n')
    ifc.add_share_path(str(src))
    from ws_test_interfaces.msg import Second
    assert (Second.LIMIT, Second().b) == (3, 'x')
