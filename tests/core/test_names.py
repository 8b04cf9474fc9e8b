import pytest

from labkit.graph import names
from labkit.rclpy.exceptions import (InvalidNamespaceException, InvalidNodeNameException,
                                     InvalidServiceNameException, InvalidTopicNameException)
from labkit.rclpy.validate_namespace import validate_namespace
from labkit.rclpy.validate_node_name import validate_node_name
from labkit.rclpy.validate_topic_name import validate_topic_name
from labkit.rclpy.validate_full_topic_name import validate_full_topic_name


@pytest.mark.parametrize('name, text, index', [
    ('', 'node name must not be empty', 0),
    ('my-node', "node name must not contain characters other than alphanumerics or '_'", 2),
    ('1node', 'node name must not start with a number', 0),
    ('a/b', "node name must not contain characters other than alphanumerics or '_'", 1),
])
def test_invalid_node_names(name, text, index):
    assert names.validate_node_name(name) == (text, index)
    with pytest.raises(InvalidNodeNameException) as exc:
        validate_node_name(name)
    assert str(exc.value) == f"Invalid node name: {text}:\n  '{name}'\n   {' ' * index}^"


def test_valid_names():
    assert validate_node_name('talker_2')
    assert validate_namespace('/')
    assert validate_namespace('/a/b_c')
    assert validate_topic_name('~/cmd_vel')
    assert validate_topic_name('{node}/x')
    assert validate_full_topic_name('/turtle1/cmd_vel')


@pytest.mark.parametrize('ns, text, index', [
    ('', 'namespace must not be empty', 0),
    ('ns', "namespace must be absolute, it must lead with a '/'", 0),
    ('/ns/', "namespace must not end with a '/', unless only a '/'", 3),
    ('/a//b', "namespace must not contain repeated '/'", 3),
    ('/a/1b', 'namespace must not have a token that starts with a number', 3),
    ('/a-b', "namespace must not contain characters other than alphanumerics, '_', or '/'", 2),
])
def test_invalid_namespaces(ns, text, index):
    with pytest.raises(InvalidNamespaceException) as exc:
        validate_namespace(ns)
    assert str(exc.value).startswith(f'Invalid namespace: {text}:')
    assert names.validate_namespace(ns) == (text, index)


@pytest.mark.parametrize('topic, text, index', [
    ('', 'topic name must not be empty string', 0),
    ('1abc', 'topic name token must not start with a number', 0),
    ('abc/', 'topic name must not end with a forward slash', 3),
    ('a b', "topic name must not contain characters other than alphanumerics, '_', '~', '{', "
            "or '}'", 1),
    ('a~', "topic name must not have tilde '~' unless it is the first character", 1),
    ('~ab', "topic name must not have a tilde '~' that is not followed by a forward slash '/'",
     1),
    ('{a', "topic name must not have unmatched (unbalanced) curly braces '{}'", 0),
    ('{1a}', 'substitution name must not start with a number', 1),
    ('a/2b', 'topic name token must not start with a number', 2),
])
def test_invalid_topic_names(topic, text, index):
    assert names.validate_topic_name(topic) == (text, index)
    with pytest.raises(InvalidTopicNameException):
        validate_topic_name(topic)
    with pytest.raises(InvalidServiceNameException) as exc:
        validate_topic_name(topic, is_service=True)
    assert str(exc.value).startswith(f'Invalid service name: {text}:')


def test_expansion():
    assert names.expand_topic_name('chatter', 'talker', '/') == '/chatter'
    assert names.expand_topic_name('chatter', 'talker', '/ns') == '/ns/chatter'
    assert names.expand_topic_name('/abs', 'talker', '/ns') == '/abs'
    assert names.expand_topic_name('~', 'talker', '/ns') == '/ns/talker'
    assert names.expand_topic_name('~/x', 'talker', '/') == '/talker/x'
    assert names.expand_topic_name('{node}/y', 'talker', '/ns') == '/ns/talker/y'
    assert names.expand_topic_name('/{ns}/z', 'talker', '/ns') == '/ns/z'
    with pytest.raises(ValueError):
        names.expand_topic_name('{bogus}', 'talker', '/')


def test_hidden_and_fqn():
    assert names.is_hidden('/_private/x')
    assert names.is_hidden('/a/_b')
    assert not names.is_hidden('/a/b_')
    assert names.fully_qualified_node_name('/', 'n') == '/n'
    assert names.fully_qualified_node_name('/a/b', 'n') == '/a/b/n'


def test_node_names_and_topic_errors_through_rclpy(rclpy, msgs):
    from labkit.rclpy.node import Node
    with pytest.raises(InvalidNodeNameException):
        Node('bad name')
    with pytest.raises(InvalidNamespaceException):
        Node('ok', namespace='/bad//ns')
    node = Node('ok', namespace='relative')
    assert node.get_namespace() == '/relative'
    assert node.get_fully_qualified_name() == '/relative/ok'
    with pytest.raises(InvalidTopicNameException) as exc:
        node.create_publisher(msgs.String, 'bad topic', 10)
    assert "Invalid topic name: topic name must not contain characters" in str(exc.value)
    with pytest.raises(InvalidServiceNameException):
        node.create_service(msgs.AddTwoInts, '1add', lambda q, r: r)
    pub = node.create_publisher(msgs.String, '~/status', 10)
    assert pub.topic_name == '/relative/ok/status'
    assert pub.topic == '~/status'
    assert node.resolve_topic_name('{node}/a') == '/relative/ok/a'
