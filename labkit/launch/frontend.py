"""The XML and YAML launch front-ends (launch_xml, launch_yaml): a declarative launch file
becomes the same launch description a Python launch file builds.

The tags and attributes are the real ones (launch's and launch_ros's `parse` methods):
`launch` (root), `arg` (+ `choice`), `let`, `group` (`scoped`, `forwarding`, `keep`),
`include` (`file`, + `arg`), `log`, `set_env`, `unset_env`, `append_env`, `reset_env`,
`timer`, `shutdown`, `reset` (+ `keep`), `executable` (`cmd`, `cwd`, `name`, `launch-prefix`,
`output`, `respawn`, `respawn_delay`, `shell`, + `env`), `node` (the same but `cmd`, and
`pkg`, `exec`, `name`, `namespace`, `exec_name`, `args`, `ros_args`, + `param`, `remap`),
`push-ros-namespace` (also `push_ros_namespace`), `set_parameter`, `set_remap`; every action takes `if` / `unless`.
As in Humble, an attribute, nested tag or YAML key that the tag's parser did not read is an
error ("Unexpected attribute(s) found in `node`: {'nmae'}").
Substitutions are written `$(name arg ...)`: var, env, eval, anon, not, and, or, command,
find-exec, dirname, filename, find-pkg-share, find-pkg-prefix, exec-in-pkg.

XML attributes are text, coerced to the type an attribute needs (YAML rules, as
launch_xml does); `name-sep` splits a list. YAML values keep their own types.
"""
import os
import xml.etree.ElementTree as ET

import yaml

from labkit import oslayer
from labkit.launch.launch_description import LaunchDescription
from labkit.launch.launch_description_sources import InvalidLaunchFileError, _load_errors

XML_EXTENSIONS = ('launch.xml', 'xml', 'launch')          # launch_xml's Parser
YAML_EXTENSIONS = ('launch.yaml', 'launch.yml', 'yaml', 'yml', 'launch')   # launch_yaml's

ENTITIES = 'entities'       # get_attr(data_type=ENTITIES): nested entities of that name


def is_frontend_file(path):
    return _ends_with(path, XML_EXTENSIONS + YAML_EXTENSIONS)


# ------------------------------------------------------------------ substitutions

class _Reader:
    """`$(name arg ...)` inside text, by launch's grammar (grammar.lark), read by hand."""

    def __init__(self, text):
        self.text = text
        self.i = 0

    def peek(self, n=1):
        return self.text[self.i:self.i + n]

    def at_substitution(self):
        return self.peek(2) == '$('

    def template(self):
        """Top level: text and substitutions, up to the end (spaces and quotes are text)."""
        out = _Parts()
        while self.i < len(self.text):
            if self.at_substitution():
                out.add(self.substitution())
            else:
                out.text(self.char())
        return out.items

    def char(self):
        c = self.text[self.i]
        if c == '\\' and self.i + 1 < len(self.text):   # an escaped character is itself
            self.i += 2
            return self.text[self.i - 1]
        self.i += 1
        return c

    def substitution(self):
        start = self.i
        self.i += 2
        name_start = self.i
        while self.i < len(self.text) and (self.text[self.i].isalnum() or
                                            self.text[self.i] in '_-'):
            self.i += 1
        name = self.text[name_start:self.i]
        if not name or not name[0].isalpha():
            raise ValueError(f"Invalid substitution at column {start}: '{self.text}'")
        args = []
        while self.peek() == ' ':
            self.i += 1
            args.append(self.argument())
        if self.peek() != ')':
            raise ValueError(f"Unterminated substitution '$({name}' in '{self.text}'")
        self.i += 1
        return instantiate_substitution(name, args)

    def argument(self):
        quote = self.peek()
        out = _Parts()
        if quote in ("'", '"'):
            self.i += 1
            while self.i < len(self.text) and self.peek() != quote:
                if self.at_substitution():
                    out.add(self.substitution())
                else:
                    out.text(self.char())
            if self.peek() != quote:
                raise ValueError(f"Unterminated quote in '{self.text}'")
            self.i += 1
            return out.items
        while self.i < len(self.text) and self.peek() not in (' ', ')', "'", '"'):
            if self.at_substitution():
                out.add(self.substitution())
            else:
                out.text(self.char())
        return out.items


class _Parts:
    def __init__(self):
        self.items = []

    def text(self, chars):
        from labkit.launch.substitutions import TextSubstitution
        if self.items and isinstance(self.items[-1], TextSubstitution):
            self.items[-1] = TextSubstitution(text=self.items[-1].text + chars)
        else:
            self.items.append(TextSubstitution(text=chars))

    def add(self, substitution):
        self.items.append(substitution)


def _arity(name, args, low, high=None):
    high = low if high is None else high
    if not low <= len(args) <= high:
        counts = {0: "doesn't expect arguments", 1: 'expects 1 argument'}
        wanted = counts.get(high, f'expects {low} or {high} arguments' if low != high
                            else f'expects {high} arguments')
        if high == 0:
            wanted = "doesn't expect arguments"
        raise TypeError(f'{name} substitution {wanted}')


def instantiate_substitution(name, args):
    from labkit.launch import substitutions as s
    from labkit.launch_ros import substitutions as rs
    if name == 'var':
        _arity(name, args, 1, 2)
        return s.LaunchConfiguration(args[0], default=args[1] if len(args) > 1 else None)
    if name == 'env':
        _arity(name, args, 1, 2)
        return s.EnvironmentVariable(args[0],
                                     default_value=args[1] if len(args) > 1 else None)
    if name == 'eval':
        _arity(name, args, 1)
        return s.PythonExpression(args[0])
    if name == 'anon':
        _arity(name, args, 1)
        return s.AnonName(args[0])
    if name == 'not':
        _arity(name, args, 1)
        return s.NotSubstitution(args[0])
    if name in ('and', 'or'):
        if len(args) != 2:         # Humble's `or` says 'and' here too
            raise TypeError('and substitution expects 2 arguments')
        cls = s.AndSubstitution if name == 'and' else s.OrSubstitution
        return cls(args[0], args[1])
    if name == 'command':
        if not 1 <= len(args) <= 2:
            raise ValueError('command substitution expects 1 or 2 arguments')
        return s.Command(args[0], **({'on_stderr': args[1]} if len(args) > 1 else {}))
    if name == 'find-exec':
        if len(args) != 1:
            raise AttributeError('find-exec substitution expects 1 argument')
        return s.FindExecutable(name=args[0])
    if name in ('dirname', 'filename'):
        _arity(name, args, 0)
        return s.ThisLaunchFileDir() if name == 'dirname' else s.ThisLaunchFile()
    if name in ('find-pkg-share', 'find-pkg-prefix'):
        if len(args) != 1:
            raise AttributeError('find package substitutions expect 1 argument')
        cls = rs.FindPackageShare if name == 'find-pkg-share' else rs.FindPackagePrefix
        return cls(args[0])
    if name == 'exec-in-pkg':
        if len(args) != 2:
            raise AttributeError('exec-in-package substitution expects 2 arguments')
        return rs.ExecutableInPackage(executable=args[0], package=args[1])
    raise RuntimeError('Unknown substitution: {}'.format(name))


def parse_substitution(text):
    """Text with `$(...)` -> a list of substitutions (launch.frontend.parse_substitution)."""
    from labkit.launch.substitutions import TextSubstitution
    if not text:
        return [TextSubstitution(text=text)]
    return _Reader(text).template()


def parse_if_substitutions(value):
    """A plain value stays as it is; text with substitutions becomes substitutions."""
    from labkit.launch.substitutions import TextSubstitution
    if isinstance(value, str):
        parsed = parse_substitution(value)
        if len(parsed) == 1 and isinstance(parsed[0], TextSubstitution):
            return parsed[0].text
        return parsed
    if isinstance(value, list):
        return [parse_if_substitutions(v) for v in value]
    return value


def escape_characters(value):
    out, i = [], 0
    while i < len(value):
        if value[i] == '\\' and i + 1 < len(value):
            i += 1
        out.append(value[i])
        i += 1
    return ''.join(out)


# ------------------------------------------------------------------ entities

def list_of(scalar):
    """The type of a list attribute (launch's List[int] etc.): ('list', int)."""
    return ('list', scalar)


def _is_list_type(data_type):
    return isinstance(data_type, tuple)


def _type_text(data_type):
    """How launch's errors name a type: "<class 'str'>", "typing.List[int]"."""
    if isinstance(data_type, tuple):
        return 'typing.List[{}]'.format(data_type[1].__name__)
    return str(data_type)


def _yaml_value(text, can_be_str, error):
    """One attribute text read by YAML rules (an empty text stays empty). Text YAML cannot
    read stays text when it may; a mapping, a date, a mixed list... is an error."""
    if not text:
        return text
    try:
        value = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        if can_be_str:
            return text
        raise ValueError(f'{error}: yaml.safe_load() failed\n{exc}') from None
    if not _yaml_is_instance(value, None, can_be_str):
        raise ValueError(f'{error}: output type is not allowed, got {type(value)}')
    return value


def _coerce(text, data_type, can_be_str=True):
    """XML text -> the attribute's type (launch.utilities.type_utils rules): no type means
    "the best YAML reading"; int/float by their constructors; bool and lists by YAML."""
    if data_type is None:
        return _yaml_value(text, can_be_str, f"Failed to convert '{text}' using yaml rules")
    if _is_list_type(data_type):
        valid = (str, data_type[1]) if can_be_str else data_type[1]
        wanted = f"Cannot convert value '{text}' to a list of '{valid}'"
        value = _yaml_value(text, can_be_str, wanted)
        if not isinstance(value, list) or not all(isinstance(v, valid) for v in value):
            raise ValueError(wanted)
        return value
    if data_type is str:
        return text
    if data_type in (int, float):
        try:
            return data_type(text)
        except ValueError:
            if can_be_str:
                return text
            raise
    if data_type is bool:
        value = _yaml_value(text, can_be_str, f"Failed to convert '{text}' to '{bool}'")
        if isinstance(value, (bool, str) if can_be_str else bool):
            return value
        raise ValueError(f"Cannot convert value '{text}' to '{bool}'")
    return text


class XmlEntity:
    """One XML element (launch_xml's Entity): attributes are read through get_attr, which
    remembers what was read so that anything left over is reported as unexpected."""

    def __init__(self, element):
        self._element = element
        self._read_attributes = set()
        self._read_children = set()

    @property
    def type_name(self):
        return self._element.tag

    @property
    def children(self):
        self._read_children = {child.tag for child in self._element}
        return [XmlEntity(child) for child in self._element]

    def assert_entity_completely_parsed(self):
        tag = self._element.tag
        nested = {child.tag for child in self._element} - self._read_children
        if nested:
            raise ValueError(f'Unexpected nested tag(s) found in `{tag}`: {nested}')
        attributes = set(self._element.attrib) - self._read_attributes
        if attributes:
            raise ValueError(f'Unexpected attribute(s) found in `{tag}`: {attributes}')

    def get_attr(self, name, *, data_type=str, optional=False, can_be_str=True):
        missing = AttributeError("Attribute '{}' of type '{}' not found in Entity '{}'".format(
            name, 'typing.List[launch.frontend.entity.Entity]' if data_type == ENTITIES
            else _type_text(data_type), self.type_name))
        if data_type == ENTITIES:
            found = [XmlEntity(child) for child in self._element if child.tag == name]
            if not found:
                if optional:
                    return None
                raise missing
            self._read_children.add(name)
            return found
        attrib = self._element.attrib
        if name not in attrib:
            if optional:
                return None
            raise missing
        self._read_attributes.add(name)
        value = attrib[name]
        separator = attrib.get(name + '-sep')
        try:
            if separator is None:
                return _coerce(value, data_type, can_be_str)
            self._read_attributes.add(name + '-sep')
            if data_type is not None and not _is_list_type(data_type):
                raise TypeError(f"Cannot convert input '{value.split(separator)}' of type "
                                f"'{list}' to '{data_type}'")
            scalar = data_type[1] if data_type is not None else None
            return [_coerce(item, scalar, can_be_str) for item in value.split(separator)]
        except ValueError:
            raise TypeError("Attribute '{}' of Entity '{}' expected to be of type '{}'."
                            "'{}' can not be converted to one of those types".format(
                                name, self.type_name, _type_text(data_type), value)) from None


class YamlEntity:
    """One YAML mapping (launch_yaml's Entity): values keep their YAML types, which must
    be the ones asked for; keys not read are reported as unexpected."""

    def __init__(self, element, type_name):
        self._element = element
        self._type_name = type_name
        self._read_keys = set()
        self._children_read = False

    @property
    def type_name(self):
        return self._type_name

    @property
    def children(self):
        self._children_read = True
        element = self._element
        if not isinstance(element, (dict, list)):
            raise TypeError(f'Expected a dict or list, got {type(element)}:'
                            f'\n---\n{element}\n---')
        if isinstance(element, dict):
            if 'children' not in element:
                raise ValueError(
                    f'Expected entity `{self._type_name}` to have children entities.'
                    f'That can be a list of subentities or a dictionary with a `children` '
                    'list element')
            self._read_keys.add('children')
            element = element['children']
        out = []
        for child in element:
            if not isinstance(child, dict) or len(child) != 1:
                raise RuntimeError('Subentities must be a dictionary with only one key'
                                   ', which is the entity type')
            (type_name, body), = child.items()
            out.append(YamlEntity(body, type_name))
        return out

    def assert_entity_completely_parsed(self):
        if isinstance(self._element, list):
            if not self._children_read:
                raise ValueError(f'Unexpected nested entity(ies) found in '
                                 f'`{self._type_name}`: {self._element}')
            return
        keys = set(self._element or {}) - self._read_keys
        if keys:
            raise ValueError(f'Unexpected key(s) found in `{self._type_name}`: {keys}')

    def get_attr(self, name, *, data_type=str, optional=False, can_be_str=True):
        element = self._element if isinstance(self._element, dict) else {}
        if name not in element:
            if optional:
                return None
            raise AttributeError("Can not find attribute '{}' in Entity '{}'".format(
                name, self._type_name))
        self._read_keys.add(name)
        data = element[name]
        if data_type == ENTITIES:
            if isinstance(data, list) and data and isinstance(data[0], dict):
                return [YamlEntity(child, name) for child in data]
            raise TypeError("Attribute '{}' of Entity '{}' expected to be a list of "
                            "dictionaries.".format(name, self._type_name))
        if not _yaml_is_instance(data, data_type, can_be_str):
            raise TypeError("Attribute '{}' of Entity '{}' expected to be of type '{}', got "
                            "'{}'".format(name, self._type_name, _type_text(data_type),
                                          type(data)))
        return data


def _yaml_is_instance(data, data_type, can_be_str):
    """launch's is_instance_of, exactly as strict: a YAML value of the asked type (`5` is
    an int, not a float; True is an int, as in Python); a text passes when it can be a
    string (it may hold substitutions). No type: any scalar, or a list of one scalar type."""
    scalars = (bool, int, float, str)
    if data_type is None:
        if not isinstance(data, list):
            return isinstance(data, scalars)
        member = next((type(v) for v in data if type(v) is not str), str)
        if member not in scalars:
            return False
        return all(isinstance(v, (member, str) if can_be_str else member) for v in data)
    if _is_list_type(data_type):
        wanted = (str, data_type[1]) if can_be_str else data_type[1]
        return isinstance(data, list) and all(isinstance(v, wanted) for v in data)
    return isinstance(data, (str, data_type) if can_be_str else data_type)


# ------------------------------------------------------------------ actions

def _condition(entity):
    from labkit.launch.conditions import IfCondition, UnlessCondition
    given = {key: entity.get_attr(key, optional=True) for key in ('if', 'unless')}
    given = {key: value for key, value in given.items() if value is not None}
    if len(given) == 2:
        raise RuntimeError("if and unless conditions can't be used simultaneously")
    for key, kind in (('if', IfCondition), ('unless', UnlessCondition)):
        if key in given:
            return {'condition': kind(parse_substitution(str(given[key])))}
    return {}


def _text(entity, name, optional=False):
    value = entity.get_attr(name, optional=optional)
    return None if value is None else parse_substitution(str(value))


def _pairs(entities, first, second):
    """Nested (name, value) entities: `<arg>` of include, `<keep>`, `<env>`, `<remap>`;
    each must have nothing else."""
    pairs = [(_text(e, first), _text(e, second)) for e in entities or []]
    for e in entities or []:
        e.assert_entity_completely_parsed()
    return pairs


def _cmdline(text):
    """launch's ExecuteProcess._parse_cmdline: a command line -> arguments, each a list
    of substitutions (text around substitutions split on spaces, shell-like)."""
    from labkit.launch.substitutions import TextSubstitution
    args, arg = [], []
    for sub in parse_substitution(text):
        if not isinstance(sub, TextSubstitution):
            arg.append(sub)
            continue
        tokens = oslayer.split_args(sub.text)
        if not tokens:
            if arg:
                args.append(arg)
                arg = []
            continue
        if sub.text[0].isspace() and arg:
            args.append(arg)
            arg = []
        arg.append(TextSubstitution(text=tokens[0]))
        if len(tokens) > 1:
            args.append(arg)
            args.extend([TextSubstitution(text=t)] for t in tokens[1:-1])
            arg = [TextSubstitution(text=tokens[-1])]
        if sub.text[-1].isspace():
            args.append(arg)
            arg = []
    if arg:
        args.append(arg)
    return args


def _arg(entity):
    from labkit.launch.actions import DeclareLaunchArgument
    kwargs = _condition(entity)
    default = entity.get_attr('default', optional=True)
    if default is not None:
        kwargs['default_value'] = parse_substitution(str(default))
    description = entity.get_attr('description', optional=True)
    if description is not None:
        kwargs['description'] = escape_characters(description)
    choices = entity.get_attr('choice', data_type=ENTITIES, optional=True)
    if choices is not None:
        kwargs['choices'] = [escape_characters(str(c.get_attr('value'))) for c in choices]
    return DeclareLaunchArgument(escape_characters(entity.get_attr('name')), **kwargs)


def _let(entity):
    from labkit.launch.actions import SetLaunchConfiguration
    return SetLaunchConfiguration(_text(entity, 'name'), _text(entity, 'value'),
                                  **_condition(entity))


def _keeps(entity):
    """`<keep name= value=/>` children: the launch configurations a group or a reset sets."""
    keeps = entity.get_attr('keep', data_type=ENTITIES, optional=True)
    if keeps is None:
        return {}
    return {'launch_configurations': {tuple(k): v for k, v in _pairs(keeps, 'name', 'value')}}


def _group(entity):
    from labkit.launch.actions import GroupAction
    kwargs = _condition(entity)
    for flag in ('scoped', 'forwarding'):
        value = entity.get_attr(flag, data_type=bool, optional=True, can_be_str=False)
        if value is not None:
            kwargs[flag] = value
    kwargs.update(_keeps(entity))
    actions = [parse_action(child) for child in entity.children if child.type_name != 'keep']
    return GroupAction(actions, **kwargs)


def _include(entity):
    from labkit.launch.actions import IncludeLaunchDescription
    kwargs = _condition(entity)
    args = entity.get_attr('arg', data_type=ENTITIES, optional=True)
    if args is not None:
        kwargs['launch_arguments'] = _pairs(args, 'name', 'value')
    return IncludeLaunchDescription(_text(entity, 'file'), **kwargs)


def _log(entity):
    from labkit.launch.actions import LogInfo
    return LogInfo(msg=_text(entity, 'message'), **_condition(entity))


def _set_env(entity):
    from labkit.launch.actions import SetEnvironmentVariable
    return SetEnvironmentVariable(_text(entity, 'name'), _text(entity, 'value'),
                                  **_condition(entity))


def _unset_env(entity):
    from labkit.launch.actions import UnsetEnvironmentVariable
    return UnsetEnvironmentVariable(_text(entity, 'name'), **_condition(entity))


def _append_env(entity):
    from labkit.launch.actions import AppendEnvironmentVariable
    kwargs = _condition(entity)
    prepend = entity.get_attr('prepend', data_type=bool, optional=True)
    if prepend is not None:
        kwargs['prepend'] = parse_if_substitutions(prepend)
    separator = entity.get_attr('separator', optional=True)
    if separator is not None:
        kwargs['separator'] = str(separator)
    return AppendEnvironmentVariable(_text(entity, 'name'), _text(entity, 'value'), **kwargs)


def _timer(entity):
    from labkit.launch.actions import TimerAction
    kwargs = _condition(entity)
    kwargs['period'] = parse_if_substitutions(entity.get_attr('period', data_type=float))
    kwargs['actions'] = [parse_action(c) for c in entity.children]
    cancel = entity.get_attr('cancel_on_shutdown', data_type=bool, optional=True)
    if cancel is not None:
        kwargs['cancel_on_shutdown'] = parse_if_substitutions(cancel)
    return TimerAction(**kwargs)


def _shutdown(entity):
    from labkit.launch.actions import Shutdown
    kwargs = _condition(entity)
    reason = entity.get_attr('reason', optional=True)
    if reason:
        kwargs['reason'] = parse_substitution(str(reason))
    return Shutdown(**kwargs)


def _process_kwargs(entity, with_cmd=True):
    """What `<executable>` and `<node>` share (launch's ExecuteProcess.parse)."""
    kwargs = _condition(entity)
    if with_cmd:
        kwargs['cmd'] = _cmdline(str(entity.get_attr('cmd')))
    for attr, key in (('cwd', 'cwd'), ('name', 'name'), ('launch-prefix', 'prefix'),
                      ('output', 'output'), ('respawn', 'respawn')):
        value = entity.get_attr(attr, optional=True)
        if value is not None:
            kwargs[key] = parse_substitution(str(value))
    delay = entity.get_attr('respawn_delay', data_type=float, optional=True)
    if delay is not None:
        if isinstance(delay, float) and delay < 0.0:
            raise ValueError('Attribute respawn_delay of Entity node expected to be '
                             'a non-negative value but got `{}`'.format(delay))
        kwargs['respawn_delay'] = delay
    shell = entity.get_attr('shell', data_type=bool, optional=True)
    if shell is not None:
        kwargs['shell'] = shell
    env = entity.get_attr('env', data_type=ENTITIES, optional=True)
    if env is not None:
        kwargs['additional_env'] = {tuple(k): v for k, v in _pairs(env, 'name', 'value')}
    return kwargs


def _executable(entity):
    from labkit.launch.actions import ExecuteProcess
    return ExecuteProcess(**_process_kwargs(entity))


_PARAM_TYPES = {'str': str, 'int': int, 'float': float, 'bool': bool,
                'list_of_str': list_of(str), 'list_of_int': list_of(int),
                'list_of_float': list_of(float), 'list_of_bool': list_of(bool), 'yaml': None}


def _parameters(entities):
    """<param name= value= type=/>, nested <param name=><param .../></param>, and
    <param from= allow_substs=/> (launch_ros's Node.parse_nested_parameters rules)."""
    from labkit.launch_ros.parameter_descriptions import ParameterFile, ParameterValue

    def nested(params):
        out = {}
        for param in params:
            name = tuple(_text(param, 'name'))
            type_id = param.get_attr('type', data_type=None, optional=True)
            data_type = None
            if type_id is not None:
                if type_id not in _PARAM_TYPES:
                    raise ValueError(f"Got invalid type identifier '{type_id}'")
                data_type = _PARAM_TYPES[type_id]
            value = param.get_attr('value', data_type=data_type, optional=True)
            children = param.get_attr('param', data_type=ENTITIES, optional=True)
            param.assert_entity_completely_parsed()
            if value is not None and children:
                raise RuntimeError('nested parameters and value attributes are mutually '
                                   'exclusive')
            if data_type is not None and children:
                raise RuntimeError('nested parameters and type attributes are mutually '
                                   'exclusive')
            if value is not None:
                value_type = list if _is_list_type(data_type) else data_type
                out[name] = ParameterValue(parse_if_substitutions(value),
                                           value_type=value_type)
            elif children:
                out[name] = nested(children)
            else:
                raise RuntimeError('either a value attribute or nested params are needed')
        return out

    normalized = []
    for param in entities:
        source = param.get_attr('from', optional=True)
        allow = param.get_attr('allow_substs', data_type=bool, optional=True)
        name = param.get_attr('name', optional=True)
        if source is not None and name is not None:
            raise RuntimeError('name and from attributes are mutually exclusive')
        if source is not None:
            allow = parse_substitution(allow) if isinstance(allow, str) else bool(allow)
            param.assert_entity_completely_parsed()
            normalized.append(ParameterFile(parse_substitution(str(source)),
                                            allow_substs=allow))
        elif name is not None:
            if allow is not None:
                raise RuntimeError("'allow_substs' can only be used together with 'from' "
                                   'attribute')
            normalized.append(nested([param]))
        else:
            raise ValueError('param Entity should have name or from attribute')
    return normalized


def _node(entity):
    """launch_ros's `node`: every `executable` attribute but `cmd`, and its own."""
    from labkit.launch_ros.actions import Node
    kwargs = _process_kwargs(entity, with_cmd=False)
    args = entity.get_attr('args', optional=True)
    if args is not None:
        kwargs['arguments'] = _cmdline(str(args))
    ros_args = entity.get_attr('ros_args', optional=True)
    if ros_args is not None:
        kwargs['ros_arguments'] = _cmdline(str(ros_args))
    for attr, key in (('node-name', 'node_name'), ('name', 'name'),
                      ('exec_name', 'exec_name'), ('pkg', 'package')):
        value = entity.get_attr(attr, optional=True)
        if value is not None:
            kwargs[key] = parse_substitution(str(value))
    kwargs['executable'] = _text(entity, 'exec')
    namespace = entity.get_attr('namespace', optional=True)
    if namespace is not None:
        kwargs['namespace'] = parse_substitution(str(namespace))
    remaps = entity.get_attr('remap', data_type=ENTITIES, optional=True)
    if remaps is not None:
        kwargs['remappings'] = _pairs(remaps, 'from', 'to')
    params = entity.get_attr('param', data_type=ENTITIES, optional=True)
    if params is not None:
        kwargs['parameters'] = _parameters(params)
    return Node(**kwargs)


def _push_ros_namespace(entity):
    from labkit.launch_ros.actions import PushRosNamespace
    return PushRosNamespace(_text(entity, 'namespace'), **_condition(entity))


def _set_parameter(entity):
    from labkit.launch_ros.actions import SetParameter
    return SetParameter(_text(entity, 'name'), _text(entity, 'value'), **_condition(entity))


def _set_remap(entity):
    from labkit.launch_ros.actions import SetRemap
    return SetRemap(_text(entity, 'from'), _text(entity, 'to'), **_condition(entity))


def _reset(entity):
    from labkit.launch.actions import ResetLaunchConfigurations
    kwargs = _condition(entity)
    kwargs.update(_keeps(entity))
    return ResetLaunchConfigurations(**kwargs)


def _reset_env(entity):
    from labkit.launch.actions import ResetEnvironment
    return ResetEnvironment(**_condition(entity))


ACTIONS = {
    'arg': _arg, 'let': _let, 'group': _group, 'include': _include, 'log': _log,
    'set_env': _set_env, 'unset_env': _unset_env, 'append_env': _append_env,
    'reset_env': _reset_env, 'reset': _reset,
    'timer': _timer, 'shutdown': _shutdown, 'executable': _executable, 'node': _node,
    'push-ros-namespace': _push_ros_namespace, 'push_ros_namespace': _push_ros_namespace,
    'set_parameter': _set_parameter, 'set_remap': _set_remap,
}


def parse_action(entity):
    """One tag -> its action; then whatever the tag has that its action did not read
    (an attribute, a nested tag) is an error, as launch's expose_action wrapper says."""
    parse = ACTIONS.get(entity.type_name)
    if parse is None:
        raise RuntimeError('Unrecognized entity of the type: {}'.format(entity.type_name))
    action = parse(entity)
    entity.assert_entity_completely_parsed()
    return action


def parse_description(entity):
    if entity.type_name != 'launch':
        raise RuntimeError("Expected 'launch' as root tag")
    deprecated = entity.get_attr('deprecated', optional=True)
    return LaunchDescription([parse_action(child) for child in entity.children],
                             deprecated_reason=deprecated)


# ------------------------------------------------------------------ files

class InvalidFrontendLaunchFileError(InvalidLaunchFileError):
    """launch.frontend.InvalidFrontendLaunchFileError: no parser could read the file."""


def _parsers():
    """launch's parser extensions, by entry-point name (xml, then yaml), each with the
    file endings it claims."""
    return [(_load_xml, XML_EXTENSIONS), (_load_yaml, YAML_EXTENSIONS)]


def load(path):
    """The root entity of an XML or YAML launch file, as launch.frontend.Parser.load: the
    parsers that claim the file's ending first, then every other one; when none can read
    it, one error that lists what each said."""
    with open(path, encoding='utf-8'):   # a missing file is that error alone, not a parser's
        pass
    claimed = [load for load, endings in _parsers() if _ends_with(path, endings)]
    order = claimed + [load for load, _ in _parsers() if load not in claimed]
    errors = []
    for load_file in order:
        try:
            return load_file(path)
        except Exception as exc:        # noqa: BLE001 - every parser's error is reported
            errors.append(exc)
    extension = frontend_format(path) if is_frontend_file(path) else ''
    raise InvalidFrontendLaunchFileError(_load_errors(extension, errors))


def _ends_with(path, endings):
    return path.endswith(tuple('.' + e for e in endings))


def _load_xml(path):
    return XmlEntity(ET.parse(path).getroot())


def _load_yaml(path):
    with open(path, encoding='utf-8') as f:
        tree = yaml.safe_load(f)
    if len(tree) != 1:         # None has no len() (an empty file): launch's TypeError too
        raise RuntimeError('Expected only one root')
    type_name, = tree.keys()        # a list: AttributeError, as launch_yaml's
    return YamlEntity(tree[type_name], type_name)


def get_launch_description_from_frontend_launch_file(path):
    return parse_description(load(path))


def xml_launch_description(path):
    """launch_xml's parser alone (XMLLaunchDescriptionSource): its error is its own."""
    return parse_description(_load_xml(path))


def yaml_launch_description(path):
    """launch_yaml's parser alone (YAMLLaunchDescriptionSource)."""
    return parse_description(_load_yaml(path))


def frontend_format(path):
    """'xml' / 'yaml' (the extension launch names in its errors)."""
    name = os.path.basename(path)
    return os.path.splitext(name)[1].lstrip('.')
