"""Sequence diagrams are drawn from the traffic that really flowed while recording."""
import re

import pytest

import labkit
from labkit.interfaces import get_type
from labkit.viz._graph_render import MIN_LABEL_PX, label_px_in_column
from labkit.viz.sequence import record

rclpy = pytest.importorskip("labkit.rclpy")

AddTwoInts = get_type("example_interfaces/srv/AddTwoInts")
String = get_type("std_msgs/msg/String")


@pytest.fixture
def nodes():
    rclpy.init()
    made = []

    def make(name):
        node = rclpy.create_node(name)
        made.append(node)
        return node
    yield make
    for node in made:
        node.destroy_node()
    rclpy.try_shutdown()


def adder(nodes):
    server = nodes("adder")

    def add(request, response):
        response.sum = request.a + request.b
        return response
    server.create_service(AddTwoInts, "add_two_ints", add)
    return server


def call(client_node, client, server, a, b):
    from labkit.rclpy.executors import SingleThreadedExecutor
    executor = SingleThreadedExecutor()
    executor.add_node(client_node)
    executor.add_node(server)
    future = client.call_async(AddTwoInts.Request(a=a, b=b))
    executor.spin_until_future_complete(future, timeout_sec=5.0)
    return future.result()


def test_a_service_call_is_one_request_and_its_response(nodes):
    server = adder(nodes)
    asker = nodes("asker")
    client = asker.create_client(AddTwoInts, "add_two_ints")
    with record("/add_two_ints") as trace:
        assert call(asker, client, server, 2, 3).sum == 5
    kinds = [(e.kind, e.src, e.dst, e.label) for e in trace.events]
    assert kinds == [("request", "/asker", ("/adder",), "{a: 2, b: 3}"),
                     ("response", "/adder", ("/asker",), "{sum: 5}")]
    assert trace.participants() == ["/asker", "/adder"]


def test_recording_ends_with_the_block(nodes):
    server = adder(nodes)
    asker = nodes("asker")
    client = asker.create_client(AddTwoInts, "add_two_ints")
    with record("/add_two_ints") as trace:
        pass
    call(asker, client, server, 1, 1)
    assert trace.events == []
    assert trace.text() == "(没有记录到消息)"


def test_only_the_named_channels_and_only_real_readers(nodes):
    talker, listener = nodes("talker"), nodes("listener")
    pub = talker.create_publisher(String, "chatter", 10)
    other = talker.create_publisher(String, "elsewhere", 10)
    listener.create_subscription(String, "chatter", lambda msg: None, 10)
    with record("/chatter") as trace:
        for i in range(3):
            pub.publish(String(data=f"hi {i}"))
        other.publish(String(data="not recorded"))
    # three messages of one stream in a row become one arrow "×3"
    assert len(trace.events) == 1
    event = trace.events[0]
    assert (event.kind, event.src, event.dst, event.count) == ("message", "/talker", ("/listener",), 3)
    assert "hi 0" in trace.text() and "hi 2" in trace.text() and "(×3)" in trace.text()
    with record("/chatter", merge=False) as each:
        for i in range(3):
            pub.publish(String(data=f"hi {i}"))
    assert [e.label for e in each.events] == ["{data: 'hi 0'}", "{data: 'hi 1'}", "{data: 'hi 2'}"]


def test_an_action_goal_with_feedback_and_a_cancel():
    from labkit.rclpy.action import ActionClient
    turtle = labkit.ros2("run turtlesim turtlesim_node")
    labkit.sleep(0.2)
    Rotate = get_type("turtlesim/action/RotateAbsolute")
    rclpy.init()
    node = rclpy.create_node("rotate_client")
    client = ActionClient(node, Rotate, "/turtle1/rotate_absolute")
    assert client.wait_for_server(timeout_sec=5.0)
    with record("/turtle1/rotate_absolute") as trace:
        sent = client.send_goal_async(Rotate.Goal(theta=-2.0), feedback_callback=lambda m: None)
        rclpy.spin_until_future_complete(node, sent)
        labkit.sleep(0.5)
        goal = sent.result()
        canceled = goal.cancel_goal_async()
        rclpy.spin_until_future_complete(node, canceled)
        result = goal.get_result_async()
        rclpy.spin_until_future_complete(node, result)
    lines = trace.text().splitlines()
    channels = [re.search(r"\[(\w+) (\w+)\]", line).groups() for line in lines]
    assert channels[:2] == [("request", "send_goal"), ("response", "send_goal")]
    assert ("request", "cancel_goal") in channels and ("response", "cancel_goal") in channels
    assert channels[-1] == ("response", "get_result")
    assert "CANCELED" in lines[-1]
    feedback = [e for e in trace.events if e.channel.endswith("/feedback")]
    assert feedback and feedback[0].count > 10
    assert trace.participants() == ["/rotate_client", "/turtlesim"]
    node.destroy_node()
    rclpy.try_shutdown()
    turtle.stop()


def test_the_figure_is_the_column_wide_and_its_labels_legible(nodes):
    server = adder(nodes)
    asker = nodes("asker")
    client = asker.create_client(AddTwoInts, "add_two_ints")
    with record("/add_two_ints") as trace:
        call(asker, client, server, 40, 2)
    svg = trace.svg("一次服务调用")
    width_pt = float(re.search(r'width="([\d.]+)pt"', svg).group(1))
    fonts = [float(x) for x in re.findall(r'font-size="([\d.]+)"', svg)]
    assert label_px_in_column(width_pt, min(fonts)) >= MIN_LABEL_PX
    assert "{a: 40, b: 2}" in svg and "{sum: 42}" in svg and "/asker" in svg


def test_a_message_to_two_subscribers_draws_an_arrow_to_each(nodes):
    talker, left, right = nodes("talker"), nodes("left"), nodes("right")
    pub = talker.create_publisher(String, "chatter", 10)
    for n in (left, right):
        n.create_subscription(String, "chatter", lambda msg: None, 10)
    with record("/chatter") as trace:
        pub.publish(String(data="hello"))
    assert trace.events[0].dst == ("/left", "/right")
    svg = trace.svg()
    assert svg.count('marker-end="url(#seq-open)"') == 2
    assert svg.count("hello") == 1
