"""The parameter half of rclpy.node.Node (Humble semantics), as a mixin.

Node (labkit/rclpy/node.py) inherits ParameterMixin and calls
``self._init_parameters(...)`` once its ``/parameter_events`` publisher exists.
Attribute names (``_parameters``, ``_descriptors``, ``_parameter_overrides``,
``_parameters_callbacks``) are rclpy's: tools and user code peek at them.
"""
import math
import sys
import warnings

from labkit.rclpy._parameter_exceptions import (
    InvalidParameterException, InvalidParameterTypeException, InvalidParameterValueException,
    ParameterAlreadyDeclaredException, ParameterImmutableException,
    ParameterNotDeclaredException, ParameterUninitializedException)
from labkit.rclpy.parameter import _rcl, Parameter, PARAMETER_SEPARATOR_STRING


def _result(successful, reason=''):
    return _rcl('msg/SetParametersResult')(successful=successful, reason=reason)


def _validate_parameter_name(name):
    # rclpy only rejects the empty name (rcl has no parameter name rule).
    if not name:
        raise InvalidParameterException(name)
    return True


class ParameterMixin:
    """declare/get/set/describe parameters; callbacks; /parameter_events.

    A node that is written in C++ in real ROS 2 (turtlesim, demo_nodes_cpp...)
    sets the class attribute ``_labkit_parameter_dialect = 'rclcpp'``: its
    refusals then carry rclcpp's texts, which is what `ros2 param set/load`
    print for such nodes.
    """

    PARAM_REL_TOL = 1e-6
    _labkit_parameter_dialect = 'rclpy'

    def _speaks_rclcpp(self):
        return self._labkit_parameter_dialect == 'rclcpp'

    # ----------------------------------------------------------------- setup
    def _init_parameters(self, parameter_overrides=None, allow_undeclared_parameters=False,
                         automatically_declare_parameters_from_overrides=False):
        self._parameters = {}
        self._descriptors = {}
        self._parameters_callbacks = []
        self._allow_undeclared_parameters = allow_undeclared_parameters
        self._parameter_overrides = {}
        from_args = getattr(self, '_parameter_overrides_from_args', None)
        for name, value in (from_args() if from_args else {}).items():
            try:
                self._parameter_overrides[name] = Parameter(name, value=value)
            except (TypeError, ValueError):
                # rcl would have refused such a value while parsing; ignore it here.
                self.get_logger().warn(f"Ignoring parameter override '{name}': bad value")
        # Explicit parameter_overrides= win over --ros-args ones, as in rclpy.
        if parameter_overrides is not None:
            self._parameter_overrides.update({p.name: p for p in parameter_overrides})
        if automatically_declare_parameters_from_overrides:
            descriptor = _rcl('msg/ParameterDescriptor')
            self.declare_parameters(
                '', [(name, p.value, descriptor())
                     for name, p in self._parameter_overrides.items()],
                ignore_override=True)

    # --------------------------------------------------------------- declare
    def declare_parameter(self, name, value=None, descriptor=None, ignore_override=False):
        """Declare and initialize a parameter; return it with its effective value."""
        if value is None and descriptor is None:
            args = (name,)  # deprecated form: gives the warning below
        else:
            if descriptor is None:
                descriptor = _rcl('msg/ParameterDescriptor')()
            args = (name, value, descriptor)
        return self.declare_parameters('', [args], ignore_override)[0]

    def declare_parameters(self, namespace, parameters, ignore_override=False):
        """Declare several ``(name[, value or Parameter.Type[, descriptor]])`` at once."""
        ParameterDescriptor = _rcl('msg/ParameterDescriptor')
        ParameterValue = _rcl('msg/ParameterValue')
        parameter_list = []
        descriptors = {}
        for index, parameter_tuple in enumerate(parameters):
            if len(parameter_tuple) < 1 or len(parameter_tuple) > 3:
                raise TypeError(
                    f'Invalid parameter tuple length at index {index} in parameters list: '
                    f'{parameter_tuple}; expecting length between 1 and 3')
            name = parameter_tuple[0]
            second = parameter_tuple[1] if len(parameter_tuple) > 1 else None
            descriptor = (parameter_tuple[2] if len(parameter_tuple) > 2
                          else ParameterDescriptor())
            if not isinstance(name, str):
                raise TypeError(
                    f'First element {name} at index {index} in parameters list is not a str.')
            if not isinstance(descriptor, ParameterDescriptor):
                raise TypeError(
                    f'Third element {descriptor} at index {index} in parameters list '
                    'is not a ParameterDescriptor.')
            if len(parameter_tuple) == 1:
                warnings.warn(
                    f"when declaring parameter named '{name}', "
                    'declaring a parameter only providing its name is deprecated. '
                    'You have to either:\n'
                    '\t- Pass a name and a default value different to "PARAMETER NOT SET"'
                    ' (and optionally a descriptor).\n'
                    '\t- Pass a name and a parameter type.\n'
                    '\t- Pass a name and a descriptor with `dynamic_typing=True')
                descriptor.dynamic_typing = True
            value = None
            if isinstance(second, Parameter.Type):
                if second == Parameter.Type.NOT_SET:
                    raise ValueError(
                        f'Cannot declare parameter {{{name}}} as statically typed of type NOT_SET')
                if descriptor.dynamic_typing is True:
                    raise ValueError(
                        f'When declaring parameter {{{name}}} passing a descriptor with'
                        '`dynamic_typing=True` is not allowed when the parameter type is provided')
                descriptor.type = second.value
            else:
                value = second
                if not descriptor.dynamic_typing and value is not None:
                    # A static type is inferred from the default value.
                    if isinstance(value, ParameterValue):
                        if value.type == Parameter.Type.NOT_SET.value:
                            raise ValueError(
                                'Cannot declare a statically typed parameter with default value '
                                'of type PARAMETER_NOT_SET')
                        descriptor.type = value.type
                    else:
                        descriptor.type = Parameter.Type.from_parameter_value(value).value
            if not ignore_override and name in self._parameter_overrides:
                value = self._parameter_overrides[name].value
            if namespace:
                name = f'{namespace}.{name}'
            _validate_parameter_name(name)
            parameter_list.append(Parameter(name, value=value))
            descriptors[name] = descriptor

        already = [p.name for p in parameter_list if p.name in self._parameters]
        if any(already):
            raise ParameterAlreadyDeclaredException(already)
        # One callback round per parameter; declared ones stay if a later one fails.
        self._set_parameters(parameter_list, descriptors, raise_on_failure=True,
                             allow_undeclared_parameters=True)
        return [self._parameters[p.name] for p in parameter_list]

    def undeclare_parameter(self, name):
        """Forget a declared parameter (no callback and, as in rclpy Humble, no event)."""
        if not self.has_parameter(name):
            raise ParameterNotDeclaredException(name)
        if self._descriptors[name].read_only:
            raise ParameterImmutableException(name)
        del self._parameters[name]
        del self._descriptors[name]

    def has_parameter(self, name):
        """Return True if parameter is declared; False otherwise."""
        return name in self._parameters

    # ------------------------------------------------------------------- get
    def get_parameter_types(self, names):
        if not all(isinstance(name, str) for name in names):
            raise TypeError('All names must be instances of type str')
        return [self.get_parameter_type(name) for name in names]

    def get_parameter_type(self, name):
        # Humble returns the int for declared names but the enum for undeclared ones.
        if self.has_parameter(name):
            return self._parameters[name].type_.value
        if self._allow_undeclared_parameters:
            return Parameter.Type.NOT_SET
        raise ParameterNotDeclaredException(name)

    def get_parameters(self, names):
        return [self.get_parameter(name) for name in names]

    def get_parameter(self, name):
        if self.has_parameter(name):
            parameter = self._parameters[name]
            if (parameter.type_ != Parameter.Type.NOT_SET or
                    self._descriptors[name].dynamic_typing):
                return parameter
            raise ParameterUninitializedException(name)
        if self._allow_undeclared_parameters:
            return Parameter(name, Parameter.Type.NOT_SET, None)
        raise ParameterNotDeclaredException(name)

    def get_parameter_or(self, name, alternative_value=None):
        if alternative_value is None:
            alternative_value = Parameter(name, Parameter.Type.NOT_SET)
        parameter = self._parameters.get(name)
        if parameter is None or parameter.type_ == Parameter.Type.NOT_SET:
            return alternative_value
        return parameter

    def get_parameters_by_prefix(self, prefix):
        """Dict of the Parameters under ``prefix.``, keyed by the rest of their names."""
        if prefix:
            prefix = prefix + PARAMETER_SEPARATOR_STRING
        n = len(prefix)
        return {name[n:]: p for name, p in self._parameters.items() if name.startswith(prefix)}

    def list_parameters(self, prefixes, depth):
        """ListParametersResult for ``prefixes`` and ``depth`` (0 = recursive)."""
        # Same answer the list_parameters service gives.
        from labkit.rclpy import parameter_service as service
        lister = (service.rclcpp_list_parameters_result if self._speaks_rclcpp()
                  else service.list_parameters_result)
        return lister(list(self._parameters.keys()), list(prefixes), depth)

    # ------------------------------------------------------------------- set
    def set_parameters(self, parameter_list):
        """Set one by one; return a SetParametersResult per parameter."""
        return self._set_parameters(parameter_list)

    def _set_parameters(self, parameter_list, descriptors=None, raise_on_failure=False,
                        allow_undeclared_parameters=False):
        if descriptors is not None:
            assert all(p.name in descriptors for p in parameter_list)
        results = []
        for param in parameter_list:
            if not allow_undeclared_parameters:
                self._check_undeclared_parameters([param])
            result = self._set_parameters_atomically(
                [param], descriptors, allow_not_set_type=allow_undeclared_parameters)
            if raise_on_failure and not result.successful:
                if result.reason.startswith('Wrong parameter type'):
                    raise InvalidParameterTypeException(
                        param, Parameter.Type(descriptors[param.name].type).name)
                raise InvalidParameterValueException(param.name, param.value, result.reason)
            results.append(result)
        return results

    def set_parameters_atomically(self, parameter_list):
        """Set all or none; one callback round; one SetParametersResult."""
        self._check_undeclared_parameters(parameter_list)
        return self._set_parameters_atomically(parameter_list)

    def _check_undeclared_parameters(self, parameter_list):
        if not all(isinstance(p, Parameter) for p in parameter_list):
            raise TypeError("parameter must be instance of type '{}'".format(repr(Parameter)))
        undeclared = (p.name for p in parameter_list if p.name not in self._parameters)
        # Faithful to Humble: any() consumes the first undeclared name from the
        # generator, so the exception lists only the others (often `[]`).
        if not self._allow_undeclared_parameters and any(undeclared):
            raise ParameterNotDeclaredException(list(undeclared))

    def _set_parameters_atomically(self, parameter_list, descriptors=None,
                                   allow_not_set_type=False):
        if descriptors is not None:
            # New descriptors (declaration): no read-only check.
            result = self._apply_descriptors(parameter_list, descriptors, False)
        else:
            result = self._apply_descriptors(parameter_list, self._descriptors, True)
        if not result.successful:
            return result
        for callback in self._parameters_callbacks:
            result = callback(parameter_list)
            if not result.successful:
                return result

        event = _rcl('msg/ParameterEvent')()
        ns = self.get_namespace()
        event.node = ns + self.get_name() if ns == '/' else ns + '/' + self.get_name()
        for param in parameter_list:
            if not allow_not_set_type and param.type_ == Parameter.Type.NOT_SET:
                # Setting NOT_SET undeclares the parameter.
                event.deleted_parameters.append(param.to_parameter_msg())
                self._parameters.pop(param.name, None)
                self._descriptors.pop(param.name, None)
                continue
            if descriptors is not None:
                self._descriptors[param.name] = descriptors[param.name]
            elif param.name not in self._descriptors:
                descriptor = _rcl('msg/ParameterDescriptor')()
                descriptor.dynamic_typing = True
                self._descriptors[param.name] = descriptor
            if self.get_parameter_or(param.name).type_ == Parameter.Type.NOT_SET:
                event.new_parameters.append(param.to_parameter_msg())
            else:
                event.changed_parameters.append(param.to_parameter_msg())
            self._parameters[param.name] = param
        event.stamp = self._parameter_event_stamp()
        self._parameter_event_publisher.publish(event)
        return _result(True)

    def _parameter_event_stamp(self):
        try:
            clock = self.get_clock()
        except AttributeError:  # the core has not made the clock yet
            clock = None
        if clock is None:
            return _builtin_time()
        return clock.now().to_msg()

    def add_on_set_parameters_callback(self, callback):
        """Add a callback in front of the list; it gets [Parameter], returns SetParametersResult."""
        self._parameters_callbacks.insert(0, callback)

    def remove_on_set_parameters_callback(self, callback):
        """Remove a callback; ValueError if it was not added."""
        self._parameters_callbacks.remove(callback)

    # ----------------------------------------------------------- descriptors
    def _apply_descriptors(self, parameter_list, descriptors, check_read_only=True):
        for param in parameter_list:
            if param.name in descriptors:
                result = self._apply_descriptor(param, descriptors[param.name], check_read_only)
                if not result.successful:
                    return result
        return _result(True)

    def _apply_descriptor(self, parameter, descriptor=None, check_read_only=True):
        if descriptor is None:
            descriptor = self.describe_parameter(parameter.name)
        else:
            descriptor.name = parameter.name
        rclcpp = self._speaks_rclcpp()
        if check_read_only and descriptor.read_only:
            if rclcpp:
                return _result(False, f"parameter '{parameter.name}' cannot be set because "
                                      'it is read-only')
            return _result(False, f'Trying to set a read-only parameter: {parameter.name}.')
        if descriptor.dynamic_typing:
            descriptor.type = parameter.type_.value
        elif self.has_parameter(parameter.name) and parameter.type_ == Parameter.Type.NOT_SET:
            if rclcpp:
                return _result(False, _rclcpp_type_reason(parameter, descriptor))
            return _result(False, 'Static parameter cannot be undeclared')
        elif (parameter.type_ != Parameter.Type.NOT_SET and
              parameter.type_.value != descriptor.type):
            if rclcpp:
                return _result(False, _rclcpp_type_reason(parameter, descriptor))
            return _result(False, 'Wrong parameter type, expected '
                                  f"'{Parameter.Type(descriptor.type)}' got '{parameter.type_}'")
        if rclcpp:
            return _rclcpp_range_check(parameter, descriptor)
        if parameter.type_ == Parameter.Type.INTEGER and descriptor.integer_range:
            return self._apply_integer_range(parameter, descriptor.integer_range[0])
        if parameter.type_ == Parameter.Type.DOUBLE and descriptor.floating_point_range:
            return self._apply_floating_point_range(parameter,
                                                    descriptor.floating_point_range[0])
        return _result(True)

    def _apply_integer_range(self, parameter, integer_range):
        lo = min(integer_range.from_value, integer_range.to_value)
        hi = max(integer_range.from_value, integer_range.to_value)
        v = parameter.value
        if v == lo or v == hi:  # the edges are always valid
            return _result(True)
        if not lo < v < hi:
            return _result(False, f'Parameter {parameter.name} out of range. '
                                  f'Min: {lo}, Max: {hi}, value: {v}')
        if integer_range.step != 0 and (v - lo) % integer_range.step != 0:
            return _result(False, f'The parameter value for {parameter.name} is not a valid '
                                  f'step. Min: {lo}, max: {hi}, value: {v}, '
                                  f'step: {integer_range.step}')
        return _result(True)

    def _apply_floating_point_range(self, parameter, floating_point_range):
        lo = min(floating_point_range.from_value, floating_point_range.to_value)
        hi = max(floating_point_range.from_value, floating_point_range.to_value)
        v = parameter.value
        tol = self.PARAM_REL_TOL
        if math.isclose(v, lo, rel_tol=tol) or math.isclose(v, hi, rel_tol=tol):
            return _result(True)
        if not lo < v < hi:
            # (Humble's text has no '.' after "range" here, unlike the integer one.)
            return _result(False, f'Parameter {parameter.name} out of range '
                                  f'Min: {lo}, Max: {hi}, value: {v}')
        step = floating_point_range.step
        if step != 0.0:
            steps = round((v - lo) / step)
            if not math.isclose(lo + steps * step, v, rel_tol=tol):
                return _result(False, f'The parameter value for {parameter.name} is not close '
                                      f'enough to a valid step. Min: {lo}, max: {hi}, '
                                      f'value: {v}, step: {step}')
        return _result(True)

    def _apply_descriptor_and_set(self, parameter, descriptor=None, check_read_only=True):
        result = self._apply_descriptor(parameter, descriptor, check_read_only)
        if result.successful:
            self._parameters[parameter.name] = parameter
        return result

    def describe_parameter(self, name):
        try:
            return self._descriptors[name]
        except KeyError:
            if self._allow_undeclared_parameters:
                return _rcl('msg/ParameterDescriptor')()
            raise ParameterNotDeclaredException(name)

    def describe_parameters(self, names):
        return [self.describe_parameter(name) for name in names]

    def set_descriptor(self, name, descriptor, alternative_value=None):
        """Replace a parameter's descriptor; return its (possibly new) ParameterValue."""
        if not self.has_parameter(name):
            if not self._allow_undeclared_parameters:
                raise ParameterNotDeclaredException(name)
            return self.get_parameter(name).get_parameter_value()
        if self.describe_parameter(name).read_only:
            raise ParameterImmutableException(name)
        current = self.get_parameter(name)
        if alternative_value is None:
            alternative = current
        else:
            alternative = Parameter.from_parameter_msg(
                _rcl('msg/Parameter')(name=name, value=alternative_value))
        # Keep the current value if it fits the new descriptor, else try the alternative.
        if not self._apply_descriptor_and_set(current, descriptor, False).successful:
            result = self._apply_descriptor_and_set(alternative, descriptor, False)
            if not result.successful:
                raise InvalidParameterValueException(name, alternative.value, result.reason)
        self._descriptors[name] = descriptor
        return self.get_parameter(name).get_parameter_value()


# rclcpp::to_string(ParameterType), indexed by ParameterType.
_RCLCPP_TYPE_NAMES = ('not set', 'bool', 'integer', 'double', 'string', 'byte_array',
                      'bool_array', 'integer_array', 'double_array', 'string_array')


def _rclcpp_type_reason(parameter, descriptor):
    return (f'Wrong parameter type, parameter {{{parameter.name}}} is of type '
            f'{{{_RCLCPP_TYPE_NAMES[descriptor.type]}}}, setting it to '
            f'{{{_RCLCPP_TYPE_NAMES[parameter.type_.value]}}} is not allowed.')


def _doubles_equal(x, y, ulp=100):
    # rclcpp's __are_doubles_equal
    return abs(x - y) <= sys.float_info.epsilon * abs(x + y) * ulp


def _rclcpp_range_check(parameter, descriptor):
    """rclcpp's range rules: from/to taken as given, one reason text per kind."""
    name, v = parameter.name, parameter.value
    if parameter.type_ == Parameter.Type.INTEGER and descriptor.integer_range:
        r = descriptor.integer_range[0]
        if v in (r.from_value, r.to_value) or (
                r.from_value <= v <= r.to_value and
                (r.step == 0 or (v - r.from_value) % r.step == 0)):
            return _result(True)
        return _result(False, f"Parameter {{{name}}} doesn't comply with integer range.")
    if parameter.type_ == Parameter.Type.DOUBLE and descriptor.floating_point_range:
        r = descriptor.floating_point_range[0]
        if _doubles_equal(v, r.from_value) or _doubles_equal(v, r.to_value):
            return _result(True)
        if r.from_value <= v <= r.to_value:
            if r.step == 0.0 or _doubles_equal(
                    v, r.from_value + math.floor((v - r.from_value) / r.step + 0.5) * r.step):
                return _result(True)
        return _result(False, f"Parameter {{{name}}} doesn't comply with floating point range.")
    return _result(True)


def _builtin_time():
    from labkit.interfaces import get_type
    return get_type('builtin_interfaces/msg/Time')()
