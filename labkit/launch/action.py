"""Action: the unit a launch description is made of (visit -> maybe more entities)."""


class LaunchDescriptionEntity:
    def visit(self, context):
        return None

    def describe_sub_entities(self):
        return []

    def describe_conditional_sub_entities(self):
        return []


class Action(LaunchDescriptionEntity):
    _completes_on_exit = False      # a process action is complete when its process exits

    def __init__(self, *, condition=None):
        self.__condition = condition

    @property
    def condition(self):
        return self.__condition

    def visit(self, context):
        if self.__condition is not None and not self.__condition.evaluate(context):
            return None
        try:
            return self.execute(context)
        finally:
            if not self._completes_on_exit and context.launch_service is not None:
                from labkit.launch.events import ExecutionComplete
                event = ExecutionComplete(action=self)
                if context.would_handle_event(event):
                    context.launch_service.emit_event(event)

    def execute(self, context):
        return None

    def get_sub_entities(self):
        return []

    def describe_sub_entities(self):
        return self.get_sub_entities() if self.__condition is None else []

    def describe_conditional_sub_entities(self):
        if self.__condition is None:
            return []
        return [('Conditionally included by {}'.format(self.describe()),
                 self.get_sub_entities())]

    def describe(self):
        return '{}()'.format(type(self).__name__)
