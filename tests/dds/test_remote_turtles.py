"""A notebook that called labkit.connect() draws the turtlesim of another terminal:
the canvas's model follows /turtle1/pose over DDS (the model is tested, not pixels)."""
import textwrap

from tests.dds.test_real_peers import domain, labkit_ros2, notebook  # noqa: F401


def test_canvas_model_follows_a_turtlesim_in_another_process(domain):
    sim = labkit_ros2(domain, "run", "turtlesim", "turtlesim_node", background=True)
    code = textwrap.dedent("""
        import time
        import labkit
        from labkit.viz import remote_turtles
        from labkit.viz.canvas import TurtleCanvas
        from labkit.interfaces import get_type

        def until(cond, timeout):
            end = time.monotonic() + timeout
            while not cond() and time.monotonic() < end:
                time.sleep(0.05)
            return cond()

        labkit.connect()
        canvas = TurtleCanvas.remote()
        world = canvas.world
        turtles = [t for t in remote_turtles._running if t.world is world][0]
        print('turtle1 drawn', until(lambda: 'turtle1' in world.turtles, 20))
        x0, y0, _ = world.turtles['turtle1'].pose()
        print('at the centre', round(x0, 3), round(y0, 3), world.path.seq)
        import labkit.rclpy as rclpy
        rclpy.init()
        node = rclpy.create_node('driver')
        Twist = get_type('geometry_msgs/msg/Twist')
        pub = node.create_publisher(Twist, '/turtle1/cmd_vel', 10)
        print('matched', until(lambda: pub.get_subscription_count() > 0, 10))
        cmd = Twist()
        cmd.linear.x = 2.0
        end = time.monotonic() + 15
        while world.turtles['turtle1'].pose()[0] < x0 + 1.0 and time.monotonic() < end:
            pub.publish(cmd)
            time.sleep(0.1)
        x1, y1, _ = world.turtles['turtle1'].pose()
        print('moved right', x1 > x0 + 1.0, 'same height', abs(y1 - y0) < 1e-3)
        print('pen lines drawn', world.path.seq > 0, 'poses', turtles.poses_seen > 10)
        background, drawn, _ = world.snapshot()
        print('canvas draws', [t[0] for t in drawn], canvas.image().size)
        labkit.reset()
        print('following after reset', turtles._thread.is_alive())
    """)
    nb = notebook(domain, code, sim)
    assert nb.stdout == ("turtle1 drawn True\nat the centre 5.544 5.544 0\nmatched True\n"
                         "moved right True same height True\npen lines drawn True poses True\n"
                         "canvas draws ['turtle1'] (500, 500)\nfollowing after reset False\n"
                         ), nb.stdout + nb.stderr
