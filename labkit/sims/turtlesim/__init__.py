"""turtlesim: Humble's turtlesim as ordinary rclpy nodes.

Modules: physics (the world, no ROS), sprites (our turtle pictures), node
(turtlesim_node), teleop (turtle_teleop_key, `press()`), draw_square, mimic.
They are imported on use, so `labkit.sims.turtlesim.physics` works without rclpy.
"""
