"""rclpy.parameter_service: the six ``<node>/..._parameters`` services (Humble).

`ros2 param` talks to nodes only through these services.
"""
import weakref

from labkit.rclpy._parameter_exceptions import (
    ParameterNotDeclaredException, ParameterUninitializedException)
from labkit.rclpy.parameter import _rcl, Parameter, PARAMETER_SEPARATOR_STRING

DEPTH_RECURSIVE = 0  # rcl_interfaces/srv/ListParameters.Request.DEPTH_RECURSIVE


def list_parameters_result(names, prefixes, depth):
    """rcl_interfaces/msg/ListParametersResult for declared ``names``, as rclpy Humble lists.

    Names without a '.' match a prefix by plain ``startswith``; dotted names must
    start with ``prefix + '.'`` and have fewer than ``depth`` dots (depth 0: any).
    """
    result = _rcl('msg/ListParametersResult')()
    out_names, out_prefixes = [], []
    dotted = []
    for name in names:
        if PARAMETER_SEPARATOR_STRING in name:
            dotted.append(name)
        elif prefixes:
            out_names.extend(name for prefix in prefixes if name.startswith(prefix))
        else:
            out_names.append(name)
    if depth != 1:
        if depth != DEPTH_RECURSIVE:
            dotted = [n for n in dotted if n.count(PARAMETER_SEPARATOR_STRING) < depth]
        for name in dotted:
            parent = name.rsplit(PARAMETER_SEPARATOR_STRING, 1)[0]
            if not prefixes:
                if parent not in out_prefixes:
                    out_prefixes.append(parent)
                out_names.append(name)
                continue
            for prefix in prefixes:
                if name.startswith(prefix + PARAMETER_SEPARATOR_STRING):
                    out_names.append(name)
                    for p in (parent, prefix):
                        if p not in out_prefixes:
                            out_prefixes.append(p)
    result.names = out_names
    result.prefixes = out_prefixes
    return result


def rclcpp_list_parameters_result(names, prefixes, depth):
    """ListParametersResult as rclcpp answers it (C++ nodes): sorted names, a prefix
    matches itself or ``prefix.``, depth counts the dots after the prefix."""
    result = _rcl('msg/ListParametersResult')()
    out_names, out_prefixes = [], []
    sep = PARAMETER_SEPARATOR_STRING

    def shallow(text):
        return depth == DEPTH_RECURSIVE or text.count(sep) < depth

    for name in sorted(names):  # rclcpp keeps parameters in a std::map
        get_all = not prefixes and shallow(name)
        matches = any(name == prefix or (name.startswith(prefix + sep) and
                                         shallow(name[len(prefix):]))
                      for prefix in prefixes)
        if get_all or matches:
            out_names.append(name)
            if sep in name:
                parent = name.rsplit(sep, 1)[0]
                if parent not in out_prefixes:
                    out_prefixes.append(parent)
    result.names = out_names
    result.prefixes = out_prefixes
    return result


def _speaks_rclcpp(node):
    return getattr(node, '_labkit_parameter_dialect', 'rclpy') == 'rclcpp'


class ParameterService:
    """Creates describe/get/get_types/list/set/set_atomically services on a node."""

    def __init__(self, node):
        from labkit.rclpy.qos import qos_profile_parameters
        self._node_weak_ref = weakref.ref(node)
        name = node.get_name()
        for srv, suffix, callback in (
                ('DescribeParameters', 'describe_parameters', self._describe_parameters_callback),
                ('GetParameters', 'get_parameters', self._get_parameters_callback),
                ('GetParameterTypes', 'get_parameter_types',
                 self._get_parameter_types_callback),
                ('ListParameters', 'list_parameters', self._list_parameters_callback),
                ('SetParameters', 'set_parameters', self._set_parameters_callback),
                ('SetParametersAtomically', 'set_parameters_atomically',
                 self._set_parameters_atomically_callback)):
            # Relative '<name>/<suffix>': lands in the node's namespace, like rclpy.
            node.create_service(_rcl('srv/' + srv), f'{name}/{suffix}', callback,
                                qos_profile=qos_profile_parameters)

    def _get_node(self):
        node = self._node_weak_ref()
        if node is None:
            raise ReferenceError('Expected valid node weak reference')
        return node

    # One unknown name empties the whole answer (Humble behaviour).
    def _describe_parameters_callback(self, request, response):
        node = self._get_node()
        try:
            response.descriptors = [node.describe_parameter(n) for n in request.names]
        except ParameterNotDeclaredException:
            response.descriptors = []
        return response

    def _get_parameters_callback(self, request, response):
        node = self._get_node()
        try:
            response.values = [node.get_parameter(n).get_parameter_value()
                                for n in request.names]
        except (ParameterNotDeclaredException, ParameterUninitializedException):
            response.values = []
        return response

    def _get_parameter_types_callback(self, request, response):
        node = self._get_node()
        try:
            types = [node.get_parameter_type(n) for n in request.names]
        except ParameterNotDeclaredException:
            types = []
        response.types = [t.value if isinstance(t, Parameter.Type) else t for t in types]
        return response

    def _list_parameters_callback(self, request, response):
        node = self._get_node()
        lister = rclcpp_list_parameters_result if _speaks_rclcpp(node) else list_parameters_result
        response.result = lister(
            list(node._parameters.keys()), list(request.prefixes), request.depth)
        return response

    def _set_parameters_callback(self, request, response):
        node = self._get_node()
        results = []
        for p in request.parameters:
            try:
                results.append(node.set_parameters_atomically([Parameter.from_parameter_msg(p)]))
            except ParameterNotDeclaredException as e:
                reason = (f"parameter '{p.name}' cannot be set because it was not declared"
                          if _speaks_rclcpp(node) else str(e))
                results.append(_rcl('msg/SetParametersResult')(successful=False, reason=reason))
        response.results = results
        return response

    def _set_parameters_atomically_callback(self, request, response):
        node = self._get_node()
        try:
            response.result = node.set_parameters_atomically(
                [Parameter.from_parameter_msg(p) for p in request.parameters])
        except ParameterNotDeclaredException as e:
            reason = ('One or more parameters were not declared before setting'
                      if _speaks_rclcpp(node) else str(e))
            response.result = _rcl('msg/SetParametersResult')(successful=False, reason=reason)
        return response


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
