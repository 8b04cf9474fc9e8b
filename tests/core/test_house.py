"""The house (labkit/ARCHITECTURE.md): arrows point down. The CLI (labkit/cli) is the top
floor: it may import every room, and no room imports it. Checked statically over the source."""
import ast
import pathlib

import labkit

ROOT = pathlib.Path(labkit.__file__).parent

# The front doors stand above the CLI: `labkit.ros2(...)` / `%load_ext labkit` (the package
# facade) and `python -m labkit` hand the reader to the CLI; they are not rooms.
DOORS = {'__init__.py', '__main__.py'}

# labkit/commands.py is layer 3: it may use the layers below it and nothing above.
LOW_ROOMS = ('labkit.commands', 'labkit.rclpy', 'labkit.graph', 'labkit.interfaces')


def _module_name(path):
    parts = list(path.relative_to(ROOT.parent).with_suffix('').parts)
    if parts[-1] == '__init__':
        parts.pop()
    return '.'.join(parts)


def imported_modules(path):
    """Every module `path` imports, anywhere in it (top level or inside functions)."""
    tree = ast.parse(path.read_text(encoding='utf-8'), str(path))
    here = _module_name(path)
    package = here if path.name == '__init__.py' else here.rpartition('.')[0]
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [(node.lineno, alias.name) for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ''
            if node.level:
                anchor = package.split('.')
                anchor = anchor[:len(anchor) - (node.level - 1)]
                base = '.'.join(anchor + ([base] if base else []))
            found.append((node.lineno, base))
            # `from labkit import cli` names the module in the alias
            found += [(node.lineno, f'{base}.{alias.name}') for alias in node.names]
        elif (isinstance(node, ast.Call) and node.args
              and isinstance(node.args[0], ast.Constant) and isinstance(node.args[0].value, str)
              and getattr(node.func, 'attr', getattr(node.func, 'id', None))
              in ('import_module', '__import__')):
            found.append((node.lineno, node.args[0].value))
    return found


def _is_cli(name):
    return name == 'labkit.cli' or name.startswith('labkit.cli.')


def test_no_room_imports_the_cli():
    offenders = []
    for path in sorted(ROOT.rglob('*.py')):
        relative = path.relative_to(ROOT)
        if relative.parts[0] == 'cli' or str(relative) in DOORS:
            continue
        offenders += [f'{relative}:{line}: imports {name}'
                      for line, name in imported_modules(path) if _is_cli(name)]
    assert offenders == []


def test_the_checker_sees_every_kind_of_import(tmp_path):
    """The check above can fail: each spelling of an upward import is caught."""
    room = ROOT / 'bag'
    spellings = ['import labkit.cli.ros2\n',
                 'def f():\n    from labkit.cli.ros2._base import CliNode\n',
                 'from labkit import cli\n',
                 'import importlib\nimportlib.import_module("labkit.cli.magics")\n']
    for text in spellings:
        probe = room / '_house_probe.py'
        try:
            probe.write_text(text)
            assert any(_is_cli(name) for _, name in imported_modules(probe)), text
        finally:
            probe.unlink()
    relative = room / '_house_probe_rel.py'
    try:  # a relative import that climbs into the CLI
        relative.write_text('from ..cli import magics\n')
        assert any(_is_cli(name) for _, name in imported_modules(relative))
    finally:
        relative.unlink()


def test_command_plumbing_stays_low():
    """labkit/commands.py (layer 3) imports only what lies below it."""
    upward = [f'commands.py:{line}: imports {name}'
              for line, name in imported_modules(ROOT / 'commands.py')
              if name.startswith('labkit') and name != 'labkit'
              and not name.startswith(LOW_ROOMS)]
    assert upward == []


def test_rooms_register_through_plugins_and_the_cli_sees_them():
    """A room's noun and magic reach the CLI without the room importing it."""
    from labkit import plugins
    plugins.register_all()
    assert plugins.NOUNS['bag'][0] == 'labkit.bag.cli'
    assert 'colcon' in plugins.MAGICS
    from labkit.cli import magics
    from labkit.cli.ros2 import run_command
    assert magics.MAGICS['colcon'] is plugins.MAGICS['colcon']
    result = run_command('bag -h')
    assert result.returncode == 0 and 'record' in result.stdout
