"""launch_ros.parameter_descriptions: a parameter value with an explicit type, a params file."""


class ParameterValue:
    """`ParameterValue(Command([...]), value_type=str)`: evaluated at launch, kept as that type."""

    def __init__(self, value, *, value_type=None):
        self.value = value
        self.value_type = value_type

    def evaluate(self, context):
        from labkit.launch.utilities import is_a_substitution, perform
        if not is_a_substitution(self.value) and not isinstance(self.value, str):
            return self.value
        text = perform(context, self.value)
        if self.value_type is str:
            return text
        import yaml
        value = yaml.safe_load(text)
        if self.value_type is not None and not isinstance(value, self.value_type):
            raise TypeError("Expected '{}' to be of type {}".format(text, self.value_type))
        return value


class ParameterFile:
    """A YAML parameters file given to a Node (`allow_substs` is accepted, not applied)."""

    def __init__(self, param_file, *, allow_substs=False):
        self.param_file = param_file
        self.allow_substs = allow_substs

    def evaluate(self, context):
        from labkit.launch.utilities import perform
        return perform(context, self.param_file)
