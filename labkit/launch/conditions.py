"""launch.conditions: IfCondition / UnlessCondition on 'true'/'false'-like text."""
from labkit.launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

VALID_TRUE = ('true', '1')
VALID_FALSE = ('false', '0')


def evaluate_condition_expression(context, expression):
    text = perform_substitutions(context, expression).lower()
    if text in VALID_TRUE:
        return True
    if text in VALID_FALSE:
        return False
    raise RuntimeError(
        "Unexpected expression '{}', expected one of {}".format(
            text, ['true', 'false', '1', '0']))


class Condition:
    def __init__(self, *, predicate=None):
        self._predicate = predicate

    def evaluate(self, context):
        return bool(self._predicate(context)) if self._predicate else True


class IfCondition(Condition):
    def __init__(self, predicate_expression):
        self._expr = normalize_to_list_of_substitutions(predicate_expression)
        super().__init__(predicate=lambda ctx: evaluate_condition_expression(ctx, self._expr))


class UnlessCondition(Condition):
    def __init__(self, predicate_expression):
        self._expr = normalize_to_list_of_substitutions(predicate_expression)
        super().__init__(
            predicate=lambda ctx: not evaluate_condition_expression(ctx, self._expr))


class LaunchConfigurationEquals(Condition):
    def __init__(self, launch_configuration_name, expected_value):
        self._name = launch_configuration_name
        self._expected = expected_value

    def evaluate(self, context):
        from labkit.launch.utilities import perform
        value = context.launch_configurations.get(self._name)
        expected = None if self._expected is None else perform(context, self._expected)
        return value == expected


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    def evaluate(self, context):
        return not super().evaluate(context)
