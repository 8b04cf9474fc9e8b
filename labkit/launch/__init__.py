"""launch (the ROS 2 launch system) on labkit: the core of it.

Launch files run unchanged: `LaunchDescription`, `launch.actions`,
`launch.substitutions`, `launch.conditions`, `launch.launch_description_sources`,
and `launch_ros.actions.Node` (labkit.launch_ros). `LaunchService` (service.py)
visits the description and starts each node as a labkit process with the
console lines of `ros2 launch`; `launch.events` and `launch.event_handlers`
react to processes starting, writing and exiting, and to shutdown. XML and YAML
launch files go through the front-ends in frontend.py (`launch_xml`, `launch_yaml`).
Composable nodes are not there yet.
"""
from labkit.launch import actions, conditions, launch_description_sources, substitutions  # noqa
from labkit.launch import event_handlers, events  # noqa: F401
from labkit.launch.event_handlers import EventHandler  # noqa: F401
from labkit.launch.events import Event  # noqa: F401
from labkit.launch.action import Action, LaunchDescriptionEntity  # noqa: F401
from labkit.launch.launch_context import LaunchContext  # noqa: F401
from labkit.launch.launch_description import LaunchDescription  # noqa: F401
from labkit.launch.service import LaunchService  # noqa: F401
from labkit.launch.substitution import Substitution  # noqa: F401
from labkit.launch.utilities import perform_substitutions  # noqa: F401



def register():
    """labkit.plugins hook: `import launch` / `import launch_ros`, and `ros2 launch`."""
    from labkit import compat
    from labkit.plugins import register_noun
    compat.register_alias('launch', 'labkit.launch')
    compat.register_alias('launch_ros', 'labkit.launch_ros')
    compat.register_alias('launch_xml', 'labkit.launch.launch_xml')
    compat.register_alias('launch_yaml', 'labkit.launch.launch_yaml')
    register_noun('launch', 'labkit.launch.cli', 'Run a launch file')


SomeSubstitutionsType = object  # typing aliases used in annotations only

__all__ = ['Action', 'Event', 'EventHandler', 'event_handlers', 'events', 'LaunchContext',
           'LaunchDescription', 'LaunchDescriptionEntity',
           'LaunchService', 'Substitution', 'actions', 'conditions',
           'launch_description_sources', 'register', 'substitutions']
