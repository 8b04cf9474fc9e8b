"""Parse .msg / .srv / .action text the way rosidl_adapter (Humble) does.

The result is a small spec (fields with IDL type descriptors, constants,
defaults, comments). Error classes and texts follow rosidl_adapter.parser, so a
reader who writes a bad .msg sees the message colcon would print.
"""
import re
import textwrap

from labkit.interfaces import definition as d

PRIMITIVE_TYPES = (
    'bool', 'byte', 'char', 'float32', 'float64', 'int8', 'uint8', 'int16', 'uint16',
    'int32', 'uint32', 'int64', 'uint64', 'string', 'wstring', 'duration', 'time')

VALID_PACKAGE_NAME_PATTERN = re.compile(r'^(?!.*__)(?!.*_$)[a-z][a-z0-9_]*$')
VALID_FIELD_NAME_PATTERN = VALID_PACKAGE_NAME_PATTERN
VALID_MESSAGE_NAME_PATTERN = re.compile(r'^[A-Z][A-Za-z0-9]*$')
VALID_CONSTANT_NAME_PATTERN = re.compile(r'^[A-Z]([A-Z0-9_]?[A-Z0-9]+)*$')

SEPARATOR = '---'
_NAME_SUFFIXES = ('_Request', '_Response', '_Goal', '_Result', '_Feedback')


class InvalidSpecification(Exception):
    pass


class InvalidActionSpecification(InvalidSpecification):
    pass


class InvalidServiceSpecification(InvalidSpecification):
    pass


class InvalidResourceName(InvalidSpecification):
    pass


class InvalidFieldDefinition(InvalidSpecification):
    pass


class UnknownMessageType(InvalidSpecification):
    pass


class InvalidValue(Exception):
    def __init__(self, type_, value_string, message_suffix=None):
        message = "value '%s' can not be converted to type '%s'" % (value_string, type_)
        if message_suffix is not None:
            message += ': %s' % message_suffix
        super().__init__(message)


def is_valid_package_name(name):
    return VALID_PACKAGE_NAME_PATTERN.fullmatch(name) is not None


def is_valid_field_name(name):
    return VALID_FIELD_NAME_PATTERN.fullmatch(name) is not None


def is_valid_message_name(name):
    if name.startswith('Sample_'):
        name = name[len('Sample_'):]
    for suffix in _NAME_SUFFIXES:
        if name.endswith(suffix):
            name = name[:-len(suffix)]
    return VALID_MESSAGE_NAME_PATTERN.fullmatch(name) is not None


def is_valid_constant_name(name):
    return VALID_CONSTANT_NAME_PATTERN.fullmatch(name) is not None


class MsgType:
    """A field type as written in a .msg file: base, string bound, array shape."""

    __slots__ = ('pkg_name', 'type', 'string_upper_bound', 'is_array', 'array_size',
                 'is_upper_bound')

    def __init__(self, type_string, context_package_name=None):
        self.is_array = type_string.endswith(']')
        self.array_size = None
        self.is_upper_bound = False
        if self.is_array:
            index = type_string.rfind('[')
            if index < 0:
                raise TypeError("the type ends with ']' but does not contain a '['")
            size_string = type_string[index + 1:-1]
            if size_string:
                self.is_upper_bound = size_string.startswith('<=')
                if self.is_upper_bound:
                    size_string = size_string[2:]
                ex = TypeError(
                    "the size of array type '<=' must be a valid integer value > 0 "
                    "optionally prefixed with '%s' if it is only an upper bound" % type_string)
                try:
                    self.array_size = int(size_string)
                except ValueError:
                    raise ex from None
                if self.array_size <= 0:
                    raise ex
            type_string = type_string[:index]
        self._set_base(type_string, context_package_name)

    def _set_base(self, type_string, context_package_name):
        self.string_upper_bound = None
        if type_string in PRIMITIVE_TYPES:
            self.pkg_name, self.type = None, type_string
            return
        if type_string.startswith(('string<=', 'wstring<=')):
            self.pkg_name = None
            self.type, _, bound = type_string.partition('<=')
            ex = TypeError("the upper bound of the string type '%s' must be a valid "
                           'integer value > 0' % type_string)
            try:
                self.string_upper_bound = int(bound)
            except ValueError:
                raise ex from None
            if self.string_upper_bound <= 0:
                raise ex
            return
        parts = type_string.split('/')
        if len(parts) == 3 and parts[1] == 'msg':  # 'pkg/msg/Type' is accepted too
            parts = [parts[0], parts[2]]
        if len(parts) == 1 and type_string == 'Header':  # ROS 1 habit, as the brief wants
            parts = ['std_msgs', 'Header']
        if not (len(parts) == 2 or (len(parts) == 1 and context_package_name is not None)):
            raise InvalidResourceName(type_string)
        if len(parts) == 2:
            self.pkg_name, self.type = parts
        else:
            self.pkg_name, self.type = context_package_name, type_string
        if not is_valid_package_name(self.pkg_name):
            raise InvalidResourceName(
                "'%s' is an invalid package name. It should have the pattern '%s'"
                % (self.pkg_name, VALID_PACKAGE_NAME_PATTERN.pattern))
        if not is_valid_message_name(self.type):
            raise InvalidResourceName(
                "'%s' is an invalid message name. It should have the pattern '%s'"
                % (self.type, VALID_MESSAGE_NAME_PATTERN.pattern))

    def is_primitive_type(self):
        return self.pkg_name is None

    def base_str(self):
        if self.pkg_name is not None:
            return '%s/%s' % (self.pkg_name, self.type)
        if self.string_upper_bound:
            return '%s<=%d' % (self.type, self.string_upper_bound)
        return self.type

    def __str__(self):
        s = self.base_str()
        if self.is_array:
            s += '[%s%s]' % ('<=' if self.is_upper_bound else '',
                             '' if self.array_size is None else self.array_size)
        return s

    def base(self):
        """The element type as a non-array MsgType."""
        t = MsgType.__new__(MsgType)
        t.pkg_name, t.type, t.string_upper_bound = self.pkg_name, self.type, self.string_upper_bound
        t.is_array, t.array_size, t.is_upper_bound = False, None, False
        return t

    def to_idl(self):
        """The rosidl_parser-style descriptor of this type."""
        if self.pkg_name is not None:
            base = d.NamespacedType([self.pkg_name, 'msg'], self.type)
        elif self.type == 'time':
            base = d.NamespacedType(['builtin_interfaces', 'msg'], 'Time')
        elif self.type == 'duration':
            base = d.NamespacedType(['builtin_interfaces', 'msg'], 'Duration')
        elif self.type == 'string':
            base = (d.BoundedString(self.string_upper_bound) if self.string_upper_bound
                    else d.UnboundedString())
        elif self.type == 'wstring':
            base = (d.BoundedWString(self.string_upper_bound) if self.string_upper_bound
                    else d.UnboundedWString())
        else:
            base = d.BasicType(d.MSG_TO_IDL[self.type])
        if not self.is_array:
            return base
        if self.array_size and not self.is_upper_bound:
            return d.Array(base, self.array_size)
        if self.is_upper_bound:
            return d.BoundedSequence(base, self.array_size)
        return d.UnboundedSequence(base)


class Constant:
    __slots__ = ('type', 'name', 'value', 'comments', 'unit')

    def __init__(self, primitive_type, name, value_string):
        if primitive_type not in PRIMITIVE_TYPES:
            raise TypeError("the constant type '%s' must be a primitive type" % primitive_type)
        self.type = primitive_type
        if not is_valid_constant_name(name):
            raise NameError("'%s' is an invalid constant name. It should have the pattern '%s'"
                            % (name, VALID_CONSTANT_NAME_PATTERN.pattern))
        self.name = name
        if value_string is None:
            raise ValueError("the constant value must not be 'None'")
        self.value = parse_primitive_value_string(MsgType(primitive_type), value_string)
        # python value as rosidl_generator_py emits it: byte constants are bytes
        if primitive_type == 'byte':
            self.value = bytes([self.value])
        self.comments = []
        self.unit = None


class Field:
    __slots__ = ('msg_type', 'type', 'name', 'default', 'comments', 'unit')

    def __init__(self, msg_type, name, default_value_string=None):
        self.msg_type = msg_type
        if not is_valid_field_name(name):
            raise NameError("'%s' is an invalid field name. It should have the pattern '%s'"
                            % (name, VALID_FIELD_NAME_PATTERN.pattern))
        self.name = name
        self.default = (None if default_value_string is None
                        else parse_value_string(msg_type, default_value_string))
        self.type = msg_type.to_idl()
        self.comments = []
        self.unit = None


class MessageSpec:
    """One message: `pkg/msg/Name` fields and constants (also a Request, Goal, ...)."""

    def __init__(self, pkg_name, msg_name, fields, constants, comments=()):
        # rosidl_adapter checks the package and message names here (InvalidResourceName)
        MsgType(pkg_name + '/' + msg_name)
        self.pkg_name = pkg_name
        self.msg_name = msg_name
        self.fields = list(fields)
        self.constants = list(constants)
        self.comments = list(comments)
        self.unit = None
        names = [f.name for f in self.fields]
        dup = sorted({n for n in names if names.count(n) > 1})
        if dup:
            raise ValueError('the fields iterable contains duplicate names: %s' % ', '.join(dup))
        names = [c.name for c in self.constants]
        dup = sorted({n for n in names if names.count(n) > 1})
        if dup:
            raise ValueError('the constants iterable contains duplicate names: %s'
                             % ', '.join(dup))


class ServiceSpec:
    def __init__(self, pkg_name, srv_name, request, response):
        self.pkg_name, self.srv_name = pkg_name, srv_name
        self.request, self.response = request, response


class ActionSpec:
    def __init__(self, pkg_name, action_name, goal, result, feedback):
        self.pkg_name, self.action_name = pkg_name, action_name
        self.goal, self.result, self.feedback = goal, result, feedback


def parse_message_string(pkg_name, msg_name, message_string):
    fields, constants = [], []
    last = None
    pending = []
    lines = message_string.replace('\t', ' ').splitlines()
    # leading comment lines are the message's own comments
    first = next((i for i, v in enumerate(lines) if not v.startswith('#')), len(lines))
    file_comments = [line.lstrip('#') for line in lines[:first]]
    for line in lines[first:]:
        line = line.rstrip()
        if not line:
            continue
        index = line.find('#')
        if index >= 0:
            comment = line[index:].lstrip('#')
            line = line[:index]
            if line and not line.strip():
                # an indented comment belongs to the element above
                if last is not None:
                    last.comments.append(comment)
                continue
            pending.append(comment)
            line = line.rstrip()
            if not line:
                continue
        type_string, _, rest = line.partition(' ')
        rest = rest.lstrip()
        if not rest:
            raise InvalidFieldDefinition(line)
        index = rest.find('=')
        if index == -1:
            field_name, _, default_string = rest.partition(' ')
            default_string = default_string.lstrip() or None
            fields.append(Field(MsgType(type_string, context_package_name=pkg_name),
                                field_name, default_string))
            last = fields[-1]
        else:
            name, _, value = rest.partition('=')
            constants.append(Constant(type_string, name.rstrip(), value.lstrip()))
            last = constants[-1]
        last.comments += pending
        pending = []
    spec = MessageSpec(pkg_name, msg_name, fields, constants)
    spec.comments, spec.unit = process_comments(file_comments)
    for element in (*fields, *constants):
        element.comments, element.unit = process_comments(element.comments)
    return spec


def process_comments(lines):
    """rosidl_adapter's comment condensing: (comment lines, unit or None).

    A single bracketed unit ('[m/s]') is taken out as the unit; blank lines at the
    ends go, runs of blank lines become one, common indentation is removed.
    """
    lines = list(lines)
    unit = None
    matches = re.findall(r'(\s*\[([^,\]]+)\])', '\n'.join(lines))
    if len(matches) == 1:
        unit = matches[0][1]
        lines = [line.replace(matches[0][0], '') for line in lines]
    while lines and lines[0] == '':
        del lines[0]
    while lines and lines[-1] == '':
        del lines[-1]
    i = 1
    while i < len(lines):
        if lines[i] == '' and lines[i - 1] == '':
            del lines[i]
            continue
        i += 1
    if lines:
        lines = textwrap.dedent('\n'.join(lines)).split('\n')
    return lines, unit


def parse_service_string(pkg_name, srv_name, text):
    lines = text.splitlines()
    seps = [i for i, line in enumerate(lines) if line == SEPARATOR]
    if not seps:
        raise InvalidServiceSpecification(
            "Could not find separator '%s' between request and response" % SEPARATOR)
    if len(seps) != 1:
        raise InvalidServiceSpecification(
            "Could not find unique separator '%s' between request and response" % SEPARATOR)
    request = parse_message_string(pkg_name, srv_name + '_Request', '\n'.join(lines[:seps[0]]))
    response = parse_message_string(pkg_name, srv_name + '_Response',
                                    '\n'.join(lines[seps[0] + 1:]))
    return ServiceSpec(pkg_name, srv_name, request, response)


def parse_action_string(pkg_name, action_name, text):
    lines = text.splitlines()
    seps = [i for i, line in enumerate(lines) if line == SEPARATOR]
    if len(seps) != 2:
        raise InvalidActionSpecification(
            "Number of '%s' separators nonconformant with action definition" % SEPARATOR)
    goal = parse_message_string(pkg_name, action_name + '_Goal', '\n'.join(lines[:seps[0]]))
    result = parse_message_string(pkg_name, action_name + '_Result',
                                  '\n'.join(lines[seps[0] + 1:seps[1]]))
    feedback = parse_message_string(pkg_name, action_name + '_Feedback',
                                    '\n'.join(lines[seps[1] + 1:]))
    return ActionSpec(pkg_name, action_name, goal, result, feedback)


def parse_value_string(type_, value_string):
    if type_.is_primitive_type() and not type_.is_array:
        return parse_primitive_value_string(type_, value_string)
    if type_.is_primitive_type() and type_.is_array:
        if not value_string.startswith('[') or not value_string.endswith(']'):
            raise InvalidValue(type_, value_string,
                               "array value must start with '[' and end with ']'")
        inner = value_string[1:-1]
        if type_.type in ('string', 'wstring'):
            items = _split_string_array(inner)
        else:
            items = inner.split(',') if inner else []
        if type_.array_size:
            if not type_.is_upper_bound and len(items) != type_.array_size:
                raise InvalidValue(type_, value_string,
                                   'array must have exactly %u elements, not %u'
                                   % (type_.array_size, len(items)))
            if type_.is_upper_bound and len(items) > type_.array_size:
                raise InvalidValue(type_, value_string,
                                   'array must have not more than %u elements, not %u'
                                   % (type_.array_size, len(items)))
        values = []
        base = type_.base()
        for i, item in enumerate(items):
            try:
                values.append(parse_primitive_value_string(base, item.strip()))
            except InvalidValue as e:
                raise InvalidValue(type_, value_string, 'element %u with %s' % (i, e)) from None
        return values
    raise NotImplementedError(
        "parsing string values into type '%s' is not supported" % type_)


def _split_string_array(text):
    """Split the inside of a string-array default; quoted items may hold commas."""
    values = []
    while text:
        text = text.lstrip(' ')
        if not text:
            break
        if text[0] == ',':
            raise ValueError("unxepected ',' at beginning of [%s]" % text)
        quote = text[0] if text[0] in '"\'' else None
        if quote:
            end = _closing_quote(text, quote)
            if end < 0:
                raise ValueError('string [%s] incorrectly quoted\n%s' % (text, values))
            values.append(text[1:end].replace('\\' + quote, quote))
            text = text[end + 1:]
        else:
            comma = text.find(',')
            if comma < 0:
                values.append(text)
                text = ''
            else:
                values.append(text[:comma])
                text = text[comma:]
        text = text.lstrip(' ')
        if text.startswith(','):
            text = text[1:]
    return values


def _closing_quote(text, quote):
    i = 1
    while i < len(text):
        if text[i] == '\\':
            i += 2
            continue
        if text[i] == quote:
            return i
        i += 1
    return -1


def parse_primitive_value_string(type_, value_string):
    if not type_.is_primitive_type() or type_.is_array:
        raise ValueError('the passed type must be a non-array primitive type')
    t = type_.type
    if t == 'bool':
        low = value_string.lower()
        if low not in ('true', '1', 'false', '0'):
            raise InvalidValue(t, value_string, "must be either 'true' / '1' or 'false' / '0'")
        return low in ('true', '1')
    if t in ('byte', 'char'):
        return _parse_int(t, value_string, 0, 255,
                          'must be a valid integer value >= 0 and <= 255')
    if t in ('float32', 'float64'):
        try:
            return float(value_string)
        except ValueError:
            raise InvalidValue(t, value_string,
                               "must be a floating point number using '.' as the separator"
                               ) from None
    if t in ('int8', 'uint8', 'int16', 'uint16', 'int32', 'uint32', 'int64', 'uint64'):
        unsigned = t.startswith('u')
        bits = int(t[4 if unsigned else 3:])
        low = 0 if unsigned else -(2 ** (bits - 1))
        high = 2 ** (bits if unsigned else bits - 1) - 1
        return _parse_int(t, value_string, low, high,
                          'must be a valid integer value >= %d and <= %u' % (low, high))
    if t in ('string', 'wstring'):
        for quote in '"\'':
            if len(value_string) >= 2 and value_string.startswith(quote) \
                    and value_string.endswith(quote):
                value_string = value_string[1:-1]
                if re.search(r'(?<!\\)%s' % quote, value_string):
                    raise InvalidValue(t, value_string,
                                       'string inner quotes not properly escaped')
                value_string = value_string.replace('\\' + quote, quote)
                break
        if type_.string_upper_bound and len(value_string) > type_.string_upper_bound:
            raise InvalidValue(type_.base_str(), value_string,
                               'string must not exceed the maximum length of %u characters'
                               % type_.string_upper_bound)
        return value_string
    raise InvalidValue(t, value_string, 'unsupported type')


def _parse_int(t, value_string, low, high, suffix):
    try:
        value = int(value_string)
    except ValueError:
        try:
            value = int(value_string, 0)
        except ValueError:
            raise InvalidValue(t, value_string, suffix) from None
    if value < low or value > high:
        raise InvalidValue(t, value_string, suffix)
    return value
