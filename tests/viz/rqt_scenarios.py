"""Graphs (as GraphSnapshot.from_dict specs) on which labkit's view is compared with
rqt_graph's own filtering code. Plain data: also imported by make_rqt_reference.py,
which runs under a real rclpy, not labkit."""

LOG = {"/rosout": "rcl_interfaces/msg/Log",
       "/parameter_events": "rcl_interfaces/msg/ParameterEvent"}
S = "std_msgs/msg/String"
ACTION = "/turtle1/rotate_absolute"


def node(**kinds):
    spec = {"publishers": dict(LOG)}
    for kind, entities in kinds.items():
        spec.setdefault(kind, {}).update(entities)
    return spec


SCENARIOS = {
    "turtlesim_teleop_echo": {
        "/turtlesim": node(
            publishers={"/turtle1/pose": "turtlesim/msg/Pose", "/turtle1/color_sensor": "turtlesim/msg/Color",
                        f"{ACTION}/_action/feedback": "turtlesim/action/RotateAbsolute_FeedbackMessage",
                        f"{ACTION}/_action/status": "action_msgs/msg/GoalStatusArray"},
            subscribers={"/turtle1/cmd_vel": "geometry_msgs/msg/Twist"}),
        "/teleop_turtle": node(
            publishers={"/turtle1/cmd_vel": "geometry_msgs/msg/Twist"},
            subscribers={f"{ACTION}/_action/feedback": "turtlesim/action/RotateAbsolute_FeedbackMessage",
                         f"{ACTION}/_action/status": "action_msgs/msg/GoalStatusArray"}),
        "/_ros2cli_26646": node(subscribers={"/turtle1/cmd_vel": "geometry_msgs/msg/Twist",
                                             "/turtle1/color_sensor": "turtlesim/msg/Color"}),
    },
    "namespaces_and_debug_names": {
        "/talker": node(publishers={"/chatter": S, "/robot/arm/state": S, "/clock": "rosgraph_msgs/msg/Clock",
                                    "/_hidden": S, "/a/_b/c": S}),
        "/robot/arm/listener": node(subscribers={"/chatter": S, "/robot/arm/state": S,
                                                 "/clock": "rosgraph_msgs/msg/Clock", "/_hidden": S,
                                                 "/a/_b/c": S}),
        "/robot/driver": node(publishers={"/robot/odom": S}, subscribers={"/robot/cmd": S}),
        "/rqt_gui_py_node_1234": node(subscribers={"/chatter": S}),
        "/rviz2": node(subscribers={"/robot/odom": S}),
        "/monitor_node": node(),
        "/_private": node(publishers={"/chatter": S}),
    },
    "sinks_leaves_self_loops": {
        "/a": node(publishers={"/only_pub": S, "/shared": S, "/loop": S},
                   subscribers={"/only_sub": S, "/loop": S}),
        "/b": node(publishers={"/only_pub": S}, subscribers={"/shared": S}),
        "/c": node(publishers={"/shared": S}, subscribers={"/robot/parameter_events": S}),
    },
    "tf": {
        "/broadcaster": node(publishers={"/tf": "tf2_msgs/msg/TFMessage", "/tf_static": "tf2_msgs/msg/TFMessage"}),
        "/static_broadcaster": node(publishers={"/tf_static": "tf2_msgs/msg/TFMessage"}),
        "/listener": node(subscribers={"/tf": "tf2_msgs/msg/TFMessage", "/tf_static": "tf2_msgs/msg/TFMessage"}),
        "/other": node(publishers={"/cmd": S}, subscribers={"/tf": "tf2_msgs/msg/TFMessage"}),
        "/driver": node(subscribers={"/cmd": S}),
    },
}

# rqt_graph check boxes -> labkit GraphView options
OPTION_SETS = {
    "defaults": ({}, {}),
    "all_shown": ({"quiet": False, "hide_dead_end_topics": False, "hide_single_connection_topics": False,
                   "hide_dynamic_reconfigure": False},
                  {"hide_debug": False, "hide_dead_sinks": False, "hide_leaf_topics": False}),
    "dead_sinks_shown": ({"hide_dead_end_topics": False}, {"hide_dead_sinks": False}),
    "leaf_topics_shown": ({"hide_single_connection_topics": False}, {"hide_leaf_topics": False}),
    "hide_tf": ({"hide_tf_nodes": True}, {"hide_tf": True}),
    "tf_ungrouped": ({"group_tf_nodes": False}, {"group_tf": False}),
    "cluster_level_1": ({"cluster_namespaces_level": 1}, {"cluster_level": 1}),
    "nodes_only": ({"graph_mode": "node_node"}, {"nodes_only": True}),
}
