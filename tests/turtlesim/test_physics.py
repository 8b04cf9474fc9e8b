"""The turtlesim world without ROS: numbers checked against Humble's turtle.cpp."""
import math

import pytest

from labkit.sims.turtlesim import physics as P

TICK = 16_000_000


def make_world():
    w = P.TurtleWorld()
    assert w.spawn("", P.CENTER, P.CENTER, 0.0) == "turtle1"
    w.step(0)                     # the first tick only starts the clock
    return w


def run(w, t, steps):
    results = []
    for _ in range(steps):
        t += TICK
        results.append(w.step(t))
    return t, results


def test_world_size_and_centre():
    assert P.WIDTH_IN_METERS == pytest.approx(11.088889, abs=1e-6)
    assert P.CENTER == 5.544444561004639   # what `ros2 topic echo /turtle1/pose` shows


def test_first_tick_only_starts_clock():
    w = P.TurtleWorld()
    w.spawn("", 1, 1, 0)
    assert w.step(0) == []
    assert len(w.step(TICK)) == 1


def test_one_second_at_two_metres_per_second_then_stop():
    w = make_world()
    w.turtles["turtle1"].command_velocity(2.0, 0.0, 0.0, 0)
    t, results = run(w, 0, 100)
    moving = [r[0] for r in results if r[0].pose[3] > 0]
    # the command applies while now - last_command <= 1 s: ticks 16 ms .. 992 ms
    assert len(moving) == 62
    x, y, theta, lin, ang = results[-1][0].pose
    assert x == pytest.approx(P.CENTER + 62 * 0.032)
    assert y == pytest.approx(P.CENTER)
    assert lin == 0.0 and ang == 0.0


def test_holonomic_linear_y():
    w = make_world()
    w.turtles["turtle1"].command_velocity(0.0, 1.0, 0.0, 0)
    _, results = run(w, 0, 10)
    x, y, *_ = results[-1][0].pose
    assert x == pytest.approx(P.CENTER)
    assert y == pytest.approx(P.CENTER + 10 * 0.016)


def test_wall_clamps_and_warns():
    w = make_world()
    w.turtles["turtle1"].command_velocity(0.0, 0.0, 0.0, 0)
    w.turtles["turtle1"].teleport_absolute(11.0, 3.0, 0.0)
    w.turtles["turtle1"].command_velocity(2.0, 0.0, 0.0, 0)
    _, results = run(w, 0, 5)
    warnings = [r[0].warning for r in results if r[0].warning]
    assert warnings[0].startswith("Oh no! I hit the wall! (Clamping from [x=11.")
    assert warnings[0].endswith(", y=%f])" % (P.HEIGHT_IN_METERS - P.f32(3.0)))
    assert results[-1][0].pose[0] == P.WIDTH_IN_METERS


def test_spawn_names_and_errors():
    w = make_world()
    assert w.spawn("", 2, 2, 0) == "turtle2"
    assert w.spawn("", 3, 3, 0) == "turtle3"
    assert w.spawn("turtle2", 4, 4, 0) == ""
    assert w.spawn("leo", 4, 4, 0) == "leo"
    assert w.spawn("turtle4", 1, 1, 0) == "turtle4"
    assert w.spawn("", 1, 1, 0) == "turtle5"          # the counter skips taken names
    assert w.kill("turtle3") and not w.kill("turtle3")


def test_reset_leaves_only_turtle1_and_clears():
    w = make_world()
    w.spawn("", 2, 2, 0)
    w.turtles["turtle1"].command_velocity(1.0, 0, 0, 0)
    run(w, 0, 10)
    assert (w.path.pixels[..., 3] > 0).any()
    w.reset()
    assert list(w.turtles) == ["turtle1"]
    assert w.turtles["turtle1"].pose() == (P.CENTER, P.CENTER, 0.0)
    assert not (w.path.pixels[..., 3] > 0).any()
    assert w.spawn("", 1, 1, 0) == "turtle2"


def test_pen_and_colour_sensor():
    w = make_world()
    turtle = w.turtles["turtle1"]
    _, results = run(w, 0, 1)
    assert results[0][0].color == (255, 255, 255)      # Humble's transparent path image reads white
    turtle.command_velocity(1.0, 0, 0, 0)
    _, results = run(w, 0, 3)
    assert results[-1][0].color == P.DEFAULT_PEN
    turtle.set_pen(255, 0, 0, 5, 0)
    _, results = run(w, 0, 3)
    assert results[-1][0].color == (255, 0, 0)
    assert turtle.pen_width == 5
    turtle.set_pen(0, 255, 0, 0, 1)                    # off: lifted, colour kept
    assert not turtle.pen_on and turtle.pen_rgb == (255, 0, 0)
    drawn = int((w.path.pixels[..., 3] > 0).sum())
    run(w, 0, 3)
    assert int((w.path.pixels[..., 3] > 0).sum()) == drawn
    turtle.set_pen(0, 0, 255, 0, 0)                    # width 0 means the default 3
    assert turtle.pen_width == 3


def test_teleport_absolute_and_relative():
    w = make_world()
    t = w.turtles["turtle1"]
    t.teleport_absolute(1.0, 2.0, 1.0)
    _, results = run(w, 0, 1)
    x, y, theta, *_ = results[0][0].pose
    assert (x, y, theta) == pytest.approx((1.0, 2.0, 1.0))
    t.teleport_relative(1.0, math.pi / 2 - 1.0)
    _, results = run(w, 0, 1)
    x, y, theta, *_ = results[0][0].pose
    assert (x, y) == pytest.approx((1.0, 3.0), abs=1e-6)
    assert (w.path.pixels[..., 3] > 0).any()           # the pen draws teleports too


class Goal(P.RotationGoal):
    def __init__(self, theta):
        self.theta = P.f32(theta)
        self.feedback, self.outcome, self.cancel = [], None, False

    def is_canceling(self):
        return self.cancel

    def publish_feedback(self, remaining):
        self.feedback.append(P.f32(remaining))

    def succeed(self, delta):
        self.outcome = ("succeed", P.f32(delta))

    def canceled(self, delta):
        self.outcome = ("canceled", P.f32(delta))


def test_rotate_absolute_matches_real_feedback():
    w = make_world()
    goal = Goal(-1.57)
    w.turtles["turtle1"].accept_goal(goal)
    run(w, 0, 200)
    # the numbers `ros2 action send_goal ... "{theta: -1.57}" --feedback` prints on Humble
    assert goal.feedback[:2] == [-1.5700000524520874, -1.5540000200271606]
    assert goal.feedback[-2:] == [-0.03400003910064697, -0.018000006675720215]
    assert goal.outcome == ("succeed", 1.5520000457763672)


def test_rotate_absolute_cancel_and_preempt():
    w = make_world()
    turtle = w.turtles["turtle1"]
    goal = Goal(1.0)
    turtle.accept_goal(goal)
    t, _ = run(w, 0, 10)
    goal.cancel = True
    t, results = run(w, t, 2)
    assert goal.outcome[0] == "canceled"
    assert results[-1][0].pose[4] == 0.0               # stopped
    first, second = Goal(2.0), Goal(-2.0)
    turtle.accept_goal(first)
    assert turtle.accept_goal(second) is first         # the node aborts what comes back
    assert turtle.command_velocity(1, 0, 0, t) is second


def test_history_rebuilds_pen_layer():
    w = make_world()
    w.turtles["turtle1"].command_velocity(1.0, 0, 1.0, 0)
    run(w, 0, 40)
    seq_mid = w.history[20][1]
    pixels = w.pixels_at(seq_mid)
    assert 0 < int((pixels[..., 3] > 0).sum()) < int((w.path.pixels[..., 3] > 0).sum())
    assert (w.pixels_at(w.path.seq) == w.path.pixels).all()


def test_history_stays_bounded_and_replayable():
    w = make_world()
    t = 0
    for k in range(int(70 / 0.016)):              # 70 s of continuous drawing
        t += TICK
        if k % 50 == 0:
            w.turtles["turtle1"].command_velocity(1.0, 0, 0.9, t)
        w.step(t)
    assert len(w.history) <= P.HISTORY_SECONDS / 0.016 + 2
    assert len(w.keyframes) <= P.HISTORY_SECONDS / 2 + 2
    assert len(w.path.ops) <= P.HISTORY_SECONDS / 0.016 + P._LIVE_OPS_KEPT + 200
    oldest_seq = w.history[0][1]
    assert w.keyframes[0][1] <= oldest_seq      # the oldest remembered moment can be rebuilt
    assert (w.pixels_at(w.path.seq) == w.path.pixels).all()
