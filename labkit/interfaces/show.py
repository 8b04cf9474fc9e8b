"""The text `ros2 interface show` prints (Humble's ros2interface/verb/show.py behaviour).

Each line of the file is parsed on its own, as ros2interface does; nested types
are expanded below their field, indented with tabs. Comments are dropped with
`no_comments`, and shown for nested types only with `all_comments`, with the
same quirks as the real verb (it strips trailing comments by text search).
"""
from labkit.interfaces import parser as p
from labkit.interfaces import registry

INSTALL_PREFIX = '/opt/ros/humble'


class _Line:
    def __init__(self, pkg, name, text):
        self.text = text
        self.spec = None
        if text != p.SEPARATOR:
            self.spec = p.parse_message_string(pkg, name, text)
            if len(self.spec.fields) > 1:
                raise ValueError("'line_text' must be only one line")

    def field(self):
        return self.spec.fields[0] if self.spec and self.spec.fields else None

    def constant(self):
        return self.spec.constants[0] if self.spec and self.spec.constants else None

    def is_comment(self):
        return bool(self.spec and self.spec.comments)

    def trailing_comment(self):
        for element in (self.field(), self.constant()):
            if element is not None and element.comments:
                return element.comments[0]
        return None

    def nested_type(self):
        f = self.field()
        if f is None or f.msg_type.is_primitive_type():
            return None
        return f.msg_type.base_str().replace('/', '/msg/')


def interface_path(name):
    """Where the file would be (ValueError / LookupError with rosidl_runtime_py's texts)."""
    parts = name.split('/')
    if len(parts) < 2:
        raise ValueError("Invalid name '%s'. Expected at least two parts separated by '/'" % name)
    if not all(parts):
        raise ValueError("Invalid name '%s'. Must not contain empty parts" % name)
    if '..' in parts:
        raise ValueError("Invalid name '%s'. Must not contain '..'" % name)
    if parts[0] not in registry.index():
        raise LookupError("Unknown package '%s'" % parts[0])
    path = None
    if len(parts) == 3:
        path = registry.find_file(parts[0], parts[1], parts[2])
    if path is None:
        suffix = '' if '.' in parts[-1] else '.idl'
        raise LookupError("Could not find the interface '%s/share/%s%s'"
                          % (INSTALL_PREFIX, name, suffix))
    return path


def _lines(name):
    parts = name.split('/')
    if len(parts) != 3:
        raise ValueError("Invalid name '%s'. Expected three parts separated by '/'" % name)
    path = interface_path(name)
    for raw in registry.read_text(path).splitlines():
        yield _Line(parts[0], parts[2], raw.rstrip())


def _show(name, show_comments, show_nested_comments, indent, out):
    for line in _lines(name):
        text = line.text
        printed = True
        if not show_comments:
            if not text or line.is_comment():
                printed = False
            else:
                trailing = line.trailing_comment()
                if trailing:
                    text = text[:text.find(trailing) - 1].strip()
        if printed:
            out.append(indent * '\t' + text if text else '')
        nested = line.nested_type()
        if nested:
            _show(nested, show_nested_comments, show_nested_comments, indent + 1, out)


def interface_show(name, all_comments=False, no_comments=False):
    """Printed lines of `ros2 interface show NAME [--all-comments|--no-comments]`, as one str."""
    out = []
    _show(name, not no_comments, all_comments, 0, out)
    return ''.join(line + '\n' for line in out)
