"""Action: the unit a launch description is made of (visit -> maybe more entities)."""


class LaunchDescriptionEntity:
    def visit(self, context):
        return None

    def describe_sub_entities(self):
        return []

    def describe_conditional_sub_entities(self):
        return []


class Action(LaunchDescriptionEntity):
    def __init__(self, *, condition=None):
        self.__condition = condition

    @property
    def condition(self):
        return self.__condition

    def visit(self, context):
        if self.__condition is not None and not self.__condition.evaluate(context):
            return None
        return self.execute(context)

    def execute(self, context):
        return None

    def describe(self):
        return '{}()'.format(type(self).__name__)
