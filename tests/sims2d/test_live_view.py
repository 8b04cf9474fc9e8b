"""ch24's 2D world live: a view that follows the robot and a key pad for
teleop_twist_keyboard, as the turtlesim window and its key pad are."""
import time

import pytest

import labkit
from labkit.graph import world
from labkit.sims import world2d
from labkit.sims.world2d import render, teleop


@pytest.fixture
def live_gazebo():
    labkit.reset()
    world.set_mode("live")
    world2d.ign("gazebo -v 4 -r visualize_lidar.sdf")
    labkit.ros2("run ros_gz_bridge parameter_bridge "
                "/model/vehicle_blue/cmd_vel@geometry_msgs/msg/Twist]ignition.msgs.Twist")
    labkit.ros2("run teleop_twist_keyboard teleop_twist_keyboard "
                "--ros-args -r /cmd_vel:=/model/vehicle_blue/cmd_vel")
    yield world2d.current()
    labkit.reset()
    world.set_mode("virtual")


def _until(predicate, seconds=10.0):
    end = time.monotonic() + seconds
    while time.monotonic() < end and not predicate():
        time.sleep(0.02)
    return predicate()


def test_live_view_follows_the_robot_and_rests_when_it_stops(live_gazebo):
    view = render.LiveView(live_gazebo, pixels=160)
    first = view.widget.value
    view.start()
    time.sleep(0.5)
    assert view.frames_drawn == 1                  # standing still: nothing redrawn
    from labkit.viz.teleop_widget import KeyPad
    pad = KeyPad(teleop.press, "teleop_twist_keyboard", teleop.KEYPAD)
    pad.press("i")                                 # as the button or the key would
    assert _until(lambda: view.frames_drawn >= 3)
    assert view.widget.value != first and view.widget.value[:4] == b"\x89PNG"
    pad.press("k")
    labkit.reset()                                 # the world ends: the view stops following
    assert _until(lambda: not view._thread.is_alive())
    pad.close()


def test_key_pad_sends_single_characters_only():
    from labkit.viz.teleop_widget import KeyPad
    got = []
    pad = KeyPad(got.append, "teleop_twist_keyboard", teleop.KEYPAD)
    for key in ("i", "Shift", ",", "ArrowUp", "Q"):
        pad.press(key)
    assert got == ["i", ",", "Q"]
    html = pad.static_html()
    assert all(f">{ch}<" in html for ch in "uiojklm,.qwezxctb")
    pad.close()


def test_picture_stays_a_still_png_in_virtual_time():
    labkit.reset()
    world2d.ign("gazebo -v 4 -r visualize_lidar.sdf")
    pic = world2d.picture(pixels=100)
    assert type(pic).__name__ == "Image" and pic.data[:4] == b"\x89PNG"
