"""Record how the real rosidl_adapter parses every bundled interface file (run by hand).

    <venv with rosidl_adapter>/bin/python make_parser_reference.py SHARE_ROOT OUT.json

For each 'pkg/kind/Name' the fixture keeps a digest of the parse (field and constant
names, types, defaults, values, comments, units, per message part), so the test can
check labkit's parser file by file without storing the whole dump.
"""
import hashlib
import json
import os
import sys


def canonical(specs):
    return hashlib.sha256(json.dumps(specs, sort_keys=True).encode()).hexdigest()[:16]


def element(name, type_, value, comment, unit):
    return [name, type_, repr(value), comment, unit]


def dump_real(spec):
    def el(e, is_field):
        value = e.default_value if is_field else e.value
        return element(e.name, str(e.type), value, e.annotations.get('comment'),
                       e.annotations.get('unit'))
    return [spec.annotations.get('comment'), spec.annotations.get('unit'),
            [el(f, True) for f in spec.fields], [el(c, False) for c in spec.constants]]


def dump_labkit(spec):
    def el(e, is_field):
        if is_field:
            return element(e.name, str(e.msg_type), e.default, e.comments, e.unit)
        value = e.value[0] if e.type == 'byte' else e.value   # rosidl keeps byte constants as int
        return element(e.name, e.type, value, e.comments, e.unit)
    return [spec.comments, spec.unit,
            [el(f, True) for f in spec.fields], [el(c, False) for c in spec.constants]]


def parse_all(root, parser, dump):
    out = {}
    for pkg in sorted(os.listdir(root)):
        for kind in ('msg', 'srv', 'action'):
            folder = os.path.join(root, pkg, kind)
            if not os.path.isdir(folder):
                continue
            for f in sorted(os.listdir(folder)):
                name = f.rsplit('.', 1)[0]
                with open(os.path.join(folder, f), encoding='utf-8') as fh:
                    text = fh.read()
                if kind == 'msg':
                    specs = [parser.parse_message_string(pkg, name, text)]
                elif kind == 'srv':
                    s = parser.parse_service_string(pkg, name, text)
                    specs = [s.request, s.response]
                else:
                    s = parser.parse_action_string(pkg, name, text)
                    specs = [s.goal, s.result, s.feedback]
                out['%s/%s/%s' % (pkg, kind, name)] = canonical([dump(s) for s in specs])
    return out


if __name__ == '__main__':
    from rosidl_adapter import parser as real_parser
    digests = {}
    for root in sys.argv[1:-1]:
        digests.update(parse_all(root, real_parser, dump_real))
    with open(sys.argv[-1], 'w') as f:
        json.dump(digests, f, indent=0, sort_keys=True)
