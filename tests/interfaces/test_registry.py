"""Lookup, listing, raw texts, module objects, extra share roots, `interface show` text."""
import pytest

import labkit.interfaces as li
from labkit.interfaces.show import interface_show

PACKAGES = ['action_msgs', 'action_tutorials_interfaces', 'builtin_interfaces',
            'diagnostic_msgs', 'example_interfaces', 'geometry_msgs', 'lifecycle_msgs',
            'nav_msgs', 'rcl_interfaces', 'rosgraph_msgs', 'sensor_msgs', 'shape_msgs',
            'std_msgs', 'std_srvs', 'tf2_msgs', 'trajectory_msgs', 'turtlesim',
            'unique_identifier_msgs', 'visualization_msgs']


def test_get_type_spellings():
    String = li.get_type('std_msgs/msg/String')
    assert li.get_type('std_msgs/String') is String
    assert li.get_type('turtlesim/srv/Spawn_Request') is li.get_type('turtlesim/srv/Spawn').Request
    rotate = li.get_type('turtlesim/action/RotateAbsolute')
    assert li.get_type('turtlesim/action/RotateAbsolute_FeedbackMessage') is \
        rotate.Impl.FeedbackMessage
    assert li.get_type('turtlesim/action/RotateAbsolute_SendGoal') is rotate.Impl.SendGoalService
    for bad in ['std_msgs/msg/Nope', 'nope_msgs/msg/String', 'std_msgs', 'std_msgs/foo/String',
                'a/b/c/d', '', 'turtlesim/srv/Spawn_Nope']:
        with pytest.raises(LookupError):
            li.get_type(bad)
    with pytest.raises(TypeError):
        li.type_name(3)


def test_bundled_packages_and_lists():
    pkgs = li.list_packages()
    assert set(PACKAGES) <= set(pkgs) and pkgs == sorted(pkgs)
    turtlesim = li.list_interfaces('turtlesim')
    assert turtlesim == ['turtlesim/action/RotateAbsolute', 'turtlesim/msg/Color',
                         'turtlesim/msg/Pose', 'turtlesim/srv/Kill', 'turtlesim/srv/SetPen',
                         'turtlesim/srv/Spawn', 'turtlesim/srv/TeleportAbsolute',
                         'turtlesim/srv/TeleportRelative']
    everything = li.list_interfaces()
    assert everything == sorted(everything) and 'std_srvs/srv/SetBool' in everything
    with pytest.raises(LookupError):
        li.list_interfaces('nope_msgs')


def test_every_bundled_interface_generates():
    for name in li.list_interfaces():
        cls = li.get_type(name)
        assert li.type_name(cls) == name
        if '/msg/' in name:
            assert repr(cls()).startswith(name.replace('/msg/', '.msg.'))


def test_raw_text_keeps_comments():
    text = li.get_interface_text('turtlesim/srv/Spawn')
    assert text == ('float32 x\nfloat32 y\nfloat32 theta\nstring name # Optional.  A unique '
                    'name will be created and returned if this is empty\n---\nstring name')
    assert li.get_interface_text('std_msgs/Header').startswith('# Standard metadata')


def test_module_objects():
    mod = li.module('std_msgs.msg')
    assert mod.String is li.get_type('std_msgs/msg/String')
    assert 'Header' in mod.__all__ and 'Header' in dir(mod)
    with pytest.raises(AttributeError):
        mod.Nope
    assert li.module('std_msgs.msg') is mod
    assert li.module('turtlesim.srv').Spawn is li.get_type('turtlesim/srv/Spawn')
    file_mod = li.module('turtlesim.action._rotate_absolute')
    assert file_mod.RotateAbsolute_Goal is li.get_type('turtlesim/action/RotateAbsolute').Goal
    assert li.module('std_msgs.msg._string').String is mod.String
    pkg = li.module('turtlesim')
    assert pkg.msg is li.module('turtlesim.msg') and pkg.__path__ == []
    assert sorted(pkg.__all__) == ['action', 'msg', 'srv']
    assert li.module('std_msgs').__all__ == ['msg']
    for bad in ['nope_msgs', 'std_msgs.foo', 'nope_msgs.msg', 'std_msgs.msg._nope', 'std_msgs.srv',
                'std_srvs.msg']:
        with pytest.raises(LookupError):
            li.module(bad)


def test_workspace_share_path_overlays(tmp_path):
    (tmp_path / 'my_interfaces' / 'msg').mkdir(parents=True)
    (tmp_path / 'my_interfaces' / 'srv').mkdir(parents=True)
    (tmp_path / 'my_interfaces' / 'msg' / 'Num.msg').write_text('int64 num\n')
    (tmp_path / 'my_interfaces' / 'srv' / 'AddThreeInts.srv').write_text(
        'int64 a\nint64 b\nint64 c\n---\nint64 sum\n')
    li.add_share_path(str(tmp_path))
    try:
        assert 'my_interfaces' in li.list_packages()
        assert li.list_interfaces('my_interfaces') == [
            'my_interfaces/msg/Num', 'my_interfaces/srv/AddThreeInts']
        Num = li.get_type('my_interfaces/msg/Num')
        assert repr(Num(num=3)) == 'my_interfaces.msg.Num(num=3)'
        assert li.module('my_interfaces.srv').AddThreeInts.Request(a=1).a == 1
        # editing and re-adding the root (a rebuild) regenerates the class
        (tmp_path / 'my_interfaces' / 'msg' / 'Num.msg').write_text('int64 num\nstring note\n')
        li.add_share_path(str(tmp_path))
        assert li.get_type('my_interfaces/msg/Num')().note == ''
    finally:
        li.remove_share_path(str(tmp_path))
    assert 'my_interfaces' not in li.list_packages()
    with pytest.raises(LookupError):
        li.get_type('my_interfaces/msg/Num')


def test_unknown_nested_type_is_reported_like_rosidl(tmp_path):
    (tmp_path / 'bad_msgs' / 'msg').mkdir(parents=True)
    (tmp_path / 'bad_msgs' / 'msg' / 'Bad.msg').write_text('Missing m\n')
    li.add_share_path(tmp_path)
    try:
        with pytest.raises(li.parser.UnknownMessageType,
                           match="Message interface 'bad_msgs/Missing' contains an unknown "
                                 'field type: bad_msgs/Missing m'):
            li.get_type('bad_msgs/msg/Bad')
    finally:
        li.remove_share_path(tmp_path)


def test_interface_show_texts():
    assert interface_show('geometry_msgs/msg/Twist') == (
        '# This expresses velocity in free space broken into its linear and angular parts.\n'
        '\n'
        'Vector3  linear\n\tfloat64 x\n\tfloat64 y\n\tfloat64 z\n'
        'Vector3  angular\n\tfloat64 x\n\tfloat64 y\n\tfloat64 z\n')
    # Humble cuts a trailing comment at the character before its text: the '#' stays
    assert interface_show('turtlesim/srv/Spawn', no_comments=True) == (
        'float32 x\nfloat32 y\nfloat32 theta\nstring name #\n---\nstring name\n')
    header = interface_show('std_msgs/msg/Header', all_comments=True)
    assert '\t# The seconds component, valid over all int32 values.\n\tint32 sec\n' in header
    with pytest.raises(LookupError, match="Unknown package 'nope'"):
        interface_show('nope/msg/X')
    with pytest.raises(LookupError, match="Could not find the interface"):
        interface_show('std_msgs/msg/Nope')
    with pytest.raises(ValueError, match='Expected three parts'):
        interface_show('std_msgs/String')


def test_interface_show_matches_the_real_verb_for_every_interface(test_msgs):
    """Digests of the real Humble verb's output (tools/make_show_reference.py)."""
    import hashlib
    import json
    import os

    from ifc_paths import DATA
    with open(os.path.join(DATA, 'interface_show_reference.json')) as f:
        expected = json.load(f)
    modes = {'default': {}, 'all': {'all_comments': True}, 'none': {'no_comments': True}}
    wrong = []
    for key, want in expected.items():
        name, mode = key.split('|')
        text = interface_show(name, **modes[mode])
        if hashlib.sha256(text.encode()).hexdigest()[:16] != want:
            wrong.append(key)
    assert len(expected) > 600 and wrong == []
