"""`--ros-args` parsing like rcl_parse_arguments, remapping and parameter overrides.

parse(argv) -> Arguments, or raises ArgumentError (bad rule) whose text is rcl's.
Unknown ROS arguments are kept in `unparsed_ros_args` (rclpy turns them into
UnknownROSArgsError).
"""
import fnmatch
import re

from labkit.graph import names

ROS_ARGS = "--ros-args"
END = "--"
TOPIC, SERVICE, NODENAME, NAMESPACE = 1, 2, 4, 8
LEVELS = {"DEBUG": 10, "INFO": 20, "WARN": 30, "WARNING": 30, "ERROR": 40, "FATAL": 50,
          "UNSET": 0}


class ArgumentError(RuntimeError):
    """A malformed --ros-args rule (rcl's RCL_RET_INVALID_ROS_ARGS)."""


class RemapRule:
    __slots__ = ("node", "kind", "match", "replacement")

    def __init__(self, node, kind, match, replacement):
        self.node, self.kind, self.match, self.replacement = node, kind, match, replacement

    def __repr__(self):
        return f"RemapRule({self.node!r}, {self.kind}, {self.match!r}, {self.replacement!r})"


class Arguments:
    def __init__(self):
        self.remaps = []
        self.param_files = []        # paths
        self.file_params = []        # (node pattern, name, value) from files, in order
        self.cli_params = []         # (node pattern, name, value) from -p, in order
        self.log_levels = {}         # logger name -> level; '' is the default level
        self.enclave = None
        self.log_config_file = None
        self.stdout_logs = True
        self.rosout_logs = True
        self.external_lib_logs = True
        self.unparsed_ros_args = []  # indices
        self.non_ros_args = []       # the arguments that are not ROS arguments

    def __repr__(self):
        return (f"Arguments(remaps={self.remaps}, params={self.cli_params}, "
                f"files={self.param_files}, log_levels={self.log_levels})")


_TOKEN = r"[A-Za-z_][A-Za-z0-9_]*"
_NODE_PREFIX = re.compile(rf"^({_TOKEN}):(?!=)")


def _parse_remap(rule):
    """[node:][rostopic://|rosservice://]from:=to, __node:=x, __ns:=/x."""
    text = rule
    node = None
    m = _NODE_PREFIX.match(text)
    if m and not text.startswith(("rostopic://", "rosservice://")):
        node = m.group(1)
        text = text[m.end():]
    if ":=" not in text:
        raise ArgumentError("Expected lexeme type (19) not found, search ended at index "
                            f"{len(rule)}")
    match, replacement = text.split(":=", 1)
    if match in ("__node", "__name"):
        err = names.validate_node_name(replacement)
        if err:
            raise ArgumentError(f"Node name not valid: {replacement}")
        return RemapRule(node, NODENAME, None, replacement)
    if match == "__ns":
        err = names.validate_namespace(replacement)
        if err:
            raise ArgumentError(f"Namespace not valid: {replacement}")
        return RemapRule(node, NAMESPACE, None, replacement)
    kind = TOPIC | SERVICE
    if match.startswith("rostopic://"):
        kind, match = TOPIC, match[len("rostopic://"):]
    elif match.startswith("rosservice://"):
        kind, match = SERVICE, match[len("rosservice://"):]
    if not match or "*" in match:
        if "**" in match:
            raise ArgumentError("Wildcard '**' is not implemented")
        if "*" in match:
            raise ArgumentError("Wildcard '*' is not implemented")
        raise ArgumentError("Expecting token or wildcard")
    for side in (match, replacement):
        if not side or names.validate_topic_name(side) is not None:
            raise ArgumentError("Expecting token or wildcard")
    return RemapRule(node, kind, match, replacement)


def parse_value(text):
    """A -p value, typed as YAML like rcl_parse_yaml_value."""
    import yaml             # here: a program without parameters starts without it
    try:
        value = yaml.safe_load(text) if text != "" else ""
    except yaml.YAMLError as exc:
        raise ArgumentError(f"Failed to parse value '{text}': {exc}") from None
    if value is None and text.strip() not in ("null", "~", ""):
        value = text
    if isinstance(value, dict):
        raise ArgumentError("Nested maps are not supported as parameter values")
    return value


def _parse_param_rule(rule):
    node = "/**"
    text = rule
    m = re.match(r"^([A-Za-z0-9_/*]+):(?!=)", text)
    if m and ":=" in text[m.end():]:
        node = m.group(1)
        text = text[m.end():]
    if ":=" not in text:
        raise ArgumentError("Expected lexeme type (22) not found, search ended at index "
                            f"{len(rule)}")
    name, value = text.split(":=", 1)
    if not name:
        raise ArgumentError("Expecting token or wildcard")
    return node, name, parse_value(value)


def _flatten(prefix, data, out):
    for key, value in data.items():
        full = f"{prefix}.{key}" if prefix else str(key)
        if isinstance(value, dict):
            _flatten(full, value, out)
        else:
            out.append((full, value))


def load_params_file(path):
    """[(node pattern, name, value)] from a ROS 2 parameter YAML file."""
    import yaml
    try:
        with open(path, encoding="utf-8") as f:
            data = yaml.safe_load(f)
    except OSError:
        raise ArgumentError(f"Error opening YAML file, at ./src/parser.c:{285}") from None
    except yaml.YAMLError as exc:
        raise ArgumentError(f"Error parsing a event near line {getattr(exc, 'problem_mark', '')}") \
            from None
    out = []

    def walk(node_path, data):
        if not isinstance(data, dict):
            raise ArgumentError("Cannot have a value before ros__parameters at this level")
        for key, value in data.items():
            if key == "ros__parameters":
                if not isinstance(value, dict):
                    raise ArgumentError("ros__parameters must be a map")
                flat = []
                _flatten("", value, flat)
                node = node_path if node_path.startswith("/") else "/" + node_path
                for name, v in flat:
                    out.append((node, name, v))
            else:
                walk(f"{node_path}/{key}" if node_path else str(key), value)

    if data is None:
        return out
    walk("", data)
    return out


def parse(argv):
    """rcl_parse_arguments over the full argv (argv[0] included if given)."""
    args = Arguments()
    argv = list(argv or [])
    ros = False
    i = 0
    n = len(argv)
    while i < n:
        arg = argv[i]
        if not ros:
            if arg == ROS_ARGS:
                ros = True
            else:
                args.non_ros_args.append(arg)
            i += 1
            continue
        if arg == ROS_ARGS:
            i += 1
            continue
        if arg == END:
            ros = False
            i += 1
            continue
        nxt = argv[i + 1] if i + 1 < n else None
        if arg in ("--param", "-p"):
            if nxt is None:
                raise ArgumentError(
                    f"Couldn't parse trailing {arg} flag. No parameter override rule found.")
            try:
                args.cli_params.append(_parse_param_rule(nxt))
            except ArgumentError as exc:
                raise ArgumentError(f"Couldn't parse parameter override rule: '{arg} {nxt}'. "
                                    f"Error: {exc}") from None
            i += 2
        elif arg in ("--remap", "-r"):
            if nxt is None:
                raise ArgumentError(f"Couldn't parse trailing {arg} flag. No remap rule found.")
            try:
                args.remaps.append(_parse_remap(nxt))
            except ArgumentError as exc:
                raise ArgumentError(f"Couldn't parse remap rule: '{arg} {nxt}'. "
                                    f"Error: {exc}") from None
            i += 2
        elif arg == "--params-file":
            if nxt is None:
                raise ArgumentError(f"Couldn't parse trailing {arg} flag. No file path provided.")
            try:
                args.file_params.extend(load_params_file(nxt))
            except ArgumentError as exc:
                raise ArgumentError(f"Couldn't parse params file: '{arg} {nxt}'. "
                                    f"Error: {exc}") from None
            args.param_files.append(nxt)
            i += 2
        elif arg == "--log-level":
            if nxt is None:
                raise ArgumentError(f"Couldn't parse trailing log level flag: '{arg}'. "
                                    "No log level provided.")
            logger, sep, level = nxt.rpartition(":=")
            if sep and not logger:
                raise ArgumentError(f"Couldn't parse log level: '{arg} {nxt}'. Error: "
                                    "Argument has an invalid logger item that name is empty")
            if level.upper() not in LEVELS:
                raise ArgumentError(f"Couldn't parse log level: '{arg} {nxt}'. Error: "
                                    f"Argument does not have a valid log level: {level}")
            args.log_levels[logger] = LEVELS[level.upper()]
            i += 2
        elif arg == "--log-config-file":
            if nxt is None:
                raise ArgumentError(f"Couldn't parse trailing {arg} flag. No file path provided.")
            args.log_config_file = nxt
            i += 2
        elif arg in ("--enclave", "-e"):
            if nxt is None:
                raise ArgumentError(
                    f"Couldn't parse trailing {arg} flag. No enclave path provided.")
            if names.validate_namespace(nxt) is not None:
                raise ArgumentError(f"Couldn't parse enclave name: '{arg} {nxt}'. Error: "
                                    f"enclave name not valid: {nxt}")
            args.enclave = nxt
            i += 2
        elif arg in ("--enable-stdout-logs", "--disable-stdout-logs"):
            args.stdout_logs = arg.startswith("--enable")
            i += 1
        elif arg in ("--enable-rosout-logs", "--disable-rosout-logs"):
            args.rosout_logs = arg.startswith("--enable")
            i += 1
        elif arg in ("--enable-external-lib-logs", "--disable-external-lib-logs"):
            args.external_lib_logs = arg.startswith("--enable")
            i += 1
        else:
            args.unparsed_ros_args.append(i)
            i += 1
    return args


def remove_ros_args(argv):
    """The arguments that are not ROS arguments (rcl_remove_ros_arguments)."""
    return parse(argv).non_ros_args


# ----------------------------------------------------------------- remapping
def _first(rule_sets, kind, name, node_name, namespace):
    for rules in rule_sets:
        for rule in rules:
            if not rule.kind & kind:
                continue
            if rule.node is not None and rule.node != node_name:
                continue
            if kind & (TOPIC | SERVICE):
                try:
                    expanded = names.expand_topic_name(rule.match, node_name, namespace)
                except ValueError:
                    continue
                if expanded != name:
                    continue
            return rule
    return None


def remap_node_name(rule_sets, node_name):
    rule = _first(rule_sets, NODENAME, None, node_name, None)
    return rule.replacement if rule else node_name


def remap_namespace(rule_sets, node_name, namespace):
    rule = _first(rule_sets, NAMESPACE, None, node_name, None)
    return rule.replacement if rule else namespace


def remap_name(rule_sets, kind, fq_name, node_name, namespace):
    """Apply the first matching topic/service rule (local rules first) to an expanded name."""
    rule = _first(rule_sets, kind, fq_name, node_name, namespace)
    if rule is None:
        return fq_name
    return names.expand_topic_name(rule.replacement, node_name, namespace)


# ----------------------------------------------------------------- parameters
def _node_matches(pattern, fqn):
    if pattern == fqn or pattern == "/**":
        return True
    if "*" not in pattern:
        return False
    rx = "^"
    parts = pattern.split("/")
    tokens = []
    for part in parts[1:]:
        if part == "**":
            tokens.append("(/[^/]+)*")
        else:
            tokens.append("/" + fnmatch.translate(part)[4:-3].replace(".*", "[^/]*"))
    rx += "".join(tokens) + "$"
    return re.match(rx, fqn) is not None


def parameter_overrides(args_list, node_fqn):
    """{name: value} for a node from a chain of Arguments (global first, then local)."""
    out = {}
    for args in args_list:
        if args is None:
            continue
        for pattern, name, value in list(args.file_params) + list(args.cli_params):
            if _node_matches(pattern if pattern.startswith("/") else "/" + pattern, node_fqn):
                out[name] = value
    return out
