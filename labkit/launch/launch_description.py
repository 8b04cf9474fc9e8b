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
        """DeclareLaunchArgument actions found without running anything: in groups, and in
        included files whose path is known before launch (first declaration wins)."""
        from labkit.launch.actions import DeclareLaunchArgument
        found = []

        def walk(entities, conditional):
            for entity in entities:
                if isinstance(entity, DeclareLaunchArgument):
                    if entity.name in (a.name for a in found):
                        continue
                    entity._conditionally_included = conditional or \
                        entity.condition is not None
                    found.append(entity)
                walk(entity.describe_sub_entities(), False)
                for _, entities_ in entity.describe_conditional_sub_entities():
                    walk(entities_, True)
        walk(self.__entities, conditional_inclusion)
        return found
