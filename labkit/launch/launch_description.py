"""LaunchDescription: the list of actions a launch file returns."""
from labkit.launch.action import LaunchDescriptionEntity


class LaunchDescription(LaunchDescriptionEntity):
    def __init__(self, initial_entities=None, *, deprecated_reason=None):
        self.__entities = list(initial_entities) if initial_entities is not None else []
        self.deprecated_reason = deprecated_reason

    def visit(self, context):
        return list(self.__entities)

    def describe_sub_entities(self):
        return list(self.__entities)

    @property
    def entities(self):
        return list(self.__entities)

    def add_entity(self, entity):
        self.__entities.append(entity)

    def add_action(self, action):
        self.add_entity(action)

    def get_launch_arguments(self, conditional_inclusion=False):
        """DeclareLaunchArgument actions, also inside groups (in order, no duplicates)."""
        from labkit.launch.actions import DeclareLaunchArgument, GroupAction
        found, names = [], set()

        def walk(entities, conditional):
            for e in entities:
                if isinstance(e, DeclareLaunchArgument):
                    if e.name not in names:
                        names.add(e.name)
                        e._conditionally_included = conditional
                        found.append(e)
                elif isinstance(e, GroupAction):
                    walk(e.get_sub_entities(), conditional or e.condition is not None)
                elif isinstance(e, LaunchDescription):
                    walk(e.entities, conditional)
        walk(self.__entities, conditional_inclusion)
        return found
