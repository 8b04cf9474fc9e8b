"""Read a package's real CMakeLists.txt the way an ament_cmake configure step would.

Only what interface packages (and simple ament_cmake packages) use is
understood: project, set, find_package, rosidl_generate_interfaces, install,
ament_package, if/endif, and the C++ commands that are accepted but produce
nothing here (add_executable, ament_target_dependencies, ...). Errors carry
CMake's texts ("CMake Error at CMakeLists.txt:N (command):").
"""
import re

# commands accepted without effect (a C++ target cannot be built in labkit)
IGNORED = {
    'cmake_minimum_required', 'add_compile_options', 'add_executable', 'add_library',
    'ament_target_dependencies', 'target_link_libraries', 'target_include_directories',
    'target_compile_features', 'target_compile_options', 'include_directories',
    'ament_export_dependencies', 'ament_export_include_directories',
    'ament_export_libraries', 'ament_export_targets', 'ament_lint_auto_find_test_dependencies',
    'rosidl_get_typesupport_target', 'rosidl_target_interfaces', 'message', 'list',
    'ament_add_gtest', 'ament_add_pytest_test',
    'rclcpp_components_register_node', 'rclcpp_components_register_nodes',
    'set_target_properties', 'find_library', 'link_directories', 'option', 'string',
}


class CMakeError(Exception):
    def __init__(self, text):
        super().__init__(text)
        self.text = text


class Command:
    __slots__ = ('name', 'args', 'line')

    def __init__(self, name, args, line):
        self.name, self.args, self.line = name, args, line


_TOKEN = re.compile(r'"((?:[^"\\]|\\.)*)"|([^\s()"#]+)|(#[^\n]*)|(\()|(\))|(\n)')


def parse(text):
    """CMake source -> [Command] (name lower-cased, arguments split, line numbers)."""
    commands = []
    line = 1
    i = 0
    n = len(text)
    name_re = re.compile(r'[ \t]*([A-Za-z_][A-Za-z0-9_]*)[ \t]*\(')
    while i < n:
        if text[i] == '\n':
            line += 1
            i += 1
            continue
        if text[i] in ' \t\r':
            i += 1
            continue
        if text[i] == '#':
            end = text.find('\n', i)
            i = n if end < 0 else end
            continue
        m = name_re.match(text, i)
        if not m:
            raise CMakeError(f'CMake Error at CMakeLists.txt:{line}:\n  Parse error.  '
                             f'Expected a command name, got unquoted argument with text '
                             f'"{text[i:].split()[0]}".\n')
        start_line = line
        i = m.end()
        args, depth = [], 1
        while i < n and depth:
            t = _TOKEN.match(text, i)
            if t is None:
                i += 1
                continue
            quoted, word, comment, lp, rp, nl = t.groups()
            if quoted is not None:
                args.append(quoted)
                line += quoted.count('\n')
            elif word is not None:
                args.append(word)
            elif nl:
                line += 1
            elif lp:
                depth += 1
            elif rp:
                depth -= 1
            i = t.end()
            while i < n and text[i] in ' \t\r':
                i += 1
        if depth:
            raise CMakeError(f'CMake Error at CMakeLists.txt:{start_line}:\n  Parse error.  '
                             'Function missing ending ")".  End of file reached.\n')
        commands.append(Command(m.group(1).lower(), args, start_line))
    return commands


def expand(value, variables):
    return re.sub(r'\$\{([A-Za-z0-9_]+)\}', lambda m: variables.get(m.group(1), ''), value)


ROSIDL_GENERATE_INTERFACES = \
    '/opt/ros/humble/share/rosidl_cmake/cmake/rosidl_generate_interfaces.cmake'


def rosidl_error(line_in_rosidl, text, cmd_line):
    """rosidl_generate_interfaces()'s own FATAL_ERROR, with CMake's call stack."""
    return CMakeError(
        f'CMake Error at {ROSIDL_GENERATE_INTERFACES}:{line_in_rosidl} (message):\n'
        + wrap_message(text)
        + f'\nCall Stack (most recent call first):\n'
          f'  CMakeLists.txt:{cmd_line} (rosidl_generate_interfaces)\n')


def wrap_message(text, width=75):
    """A message(FATAL_ERROR) text as CMake prints it: two-space indent, words
    wrapped when the column plus the next word would pass `width`."""
    lines, line = [], ''
    for word in text.split():
        if line and len(line) + len(word) > width:
            lines.append(line)
            line = word
        else:
            line = f'{line} {word}' if line else word
    lines.append(line)
    return '\n'.join('  ' + line for line in lines)


def error(cmd, body):
    return CMakeError(f'CMake Error at CMakeLists.txt:{cmd.line} ({cmd.name}):\n{body}\n')


def not_found(cmd, pkg):
    return error(cmd, (
        f'  By not providing "Find{pkg}.cmake" in CMAKE_MODULE_PATH this project has\n'
        f'  asked CMake to find a package configuration file provided by "{pkg}", but\n'
        f'  CMake did not find one.\n\n'
        f'  Could not find a package configuration file provided by "{pkg}" with any\n'
        f'  of the following names:\n\n'
        f'    {pkg}Config.cmake\n    {pkg.lower()}-config.cmake\n\n'
        f'  Add the installation prefix of "{pkg}" to CMAKE_PREFIX_PATH or set\n'
        f'  "{pkg}_DIR" to a directory containing one of the above files.  If "{pkg}"\n'
        f'  provides a separate development package or SDK, be sure it has been\n'
        f'  installed.\n'))


class Configure:
    """The result of configuring: interfaces to generate, files to install, flags."""

    def __init__(self):
        self.project = None
        self.found = []             # find_package'd names
        self.interfaces = []        # relative paths, e.g. 'srv/FaceResult.srv'
        self.interface_deps = []    # DEPENDENCIES
        self.interface_line = None
        self.installs = []          # (kind, [sources], destination)
        self.ament_package = False
        self.targets = []           # add_executable names (not built in labkit)
        self.python_packages = []   # ament_python_install_package(<name> [PACKAGE_DIR d])


def configure(text, package_name, is_known_package, member_of_groups):
    """Run the commands; `is_known_package(name)` answers find_package."""
    result = Configure()
    variables = {'CMAKE_CURRENT_SOURCE_DIR': '.', 'PROJECT_SOURCE_DIR': '.',
                 'CMAKE_INSTALL_PREFIX': '${CMAKE_INSTALL_PREFIX}', 'BUILD_TESTING': 'OFF'}
    commands_available = set()
    skip = []   # stack of booleans for if/else blocks
    for cmd in parse(text):
        args = [expand(a, variables) for a in cmd.args]
        if cmd.name == 'if':
            skip.append(_false_condition(args, variables) or any(skip))
            continue
        if cmd.name in ('elseif', 'else'):
            if skip:
                skip[-1] = not skip[-1] if cmd.name == 'else' else True
            continue
        if cmd.name == 'endif':
            if skip:
                skip.pop()
            continue
        if any(skip):
            continue
        if cmd.name == 'project':
            result.project = args[0] if args else None
            variables['PROJECT_NAME'] = result.project or ''
            if result.project != package_name:
                raise error(cmd, f"  ament_package_xml() package name '{package_name}' in "
                                 f"'package.xml' does not match current PROJECT_NAME "
                                 f"'{result.project}'.  You must call project() with the "
                                 f"same package name before.")
        elif cmd.name == 'set' and args:
            variables[args[0]] = ';'.join(args[1:])
        elif cmd.name == 'find_package':
            if not args:
                continue
            pkg = args[0]
            if is_known_package(pkg):
                result.found.append(pkg)
                variables[f'{pkg}_FOUND'] = 'TRUE'
                if pkg == 'rosidl_default_generators':
                    commands_available.add('rosidl_generate_interfaces')
                if pkg in ('ament_cmake', 'ament_cmake_python'):
                    commands_available.add('ament_package')
                if pkg == 'ament_cmake_python':
                    commands_available.add('ament_python_install_package')
            elif 'REQUIRED' in args:
                raise not_found(cmd, pkg)
        elif cmd.name == 'rosidl_generate_interfaces':
            if cmd.name not in commands_available:
                raise error(cmd, '  Unknown CMake command "rosidl_generate_interfaces".')
            _rosidl(cmd, args[1:], result, member_of_groups)
        elif cmd.name == 'install':
            _install(cmd, args, result)
        elif cmd.name == 'ament_package':
            if 'ament_package' not in commands_available:
                raise error(cmd, '  Unknown CMake command "ament_package".')
            result.ament_package = True
        elif cmd.name == 'ament_python_install_package':
            if 'ament_python_install_package' not in commands_available:
                raise error(cmd, '  Unknown CMake command "ament_python_install_package".')
            package_dir = args[args.index('PACKAGE_DIR') + 1] if 'PACKAGE_DIR' in args \
                and args.index('PACKAGE_DIR') + 1 < len(args) else args[0]
            result.python_packages.append((args[0], package_dir))
        elif cmd.name in ('add_executable', 'add_library'):
            result.targets.append(args[0] if args else '')
        elif cmd.name in IGNORED or cmd.name in ('endforeach', 'foreach', 'function',
                                                 'endfunction', 'macro', 'endmacro'):
            continue
        else:
            raise error(cmd, f'  Unknown CMake command "{cmd.name}".')
    return result


def _false_condition(args, variables):
    """`if(BUILD_TESTING)` and `if(NOT ...)`: tests are not built by `colcon build` here."""
    words = [a for a in args]
    negate = words[:1] == ['NOT']
    if negate:
        words = words[1:]
    value = variables.get(words[0], words[0]) if words else ''
    truthy = str(value).upper() not in ('', '0', 'OFF', 'NO', 'FALSE', 'N', 'IGNORE',
                                        'NOTFOUND') and not str(value).endswith('-NOTFOUND')
    return truthy if negate else not truthy


def _rosidl(cmd, args, result, member_of_groups):
    files, deps, mode = [], [], 'files'
    for a in args:
        if a == 'DEPENDENCIES':
            mode = 'deps'
        elif a in ('ADD_LINTER_TESTS', 'SKIP_INSTALL', 'SKIP_GROUP_MEMBERSHIP_CHECK'):
            mode = 'flag'
        elif a == 'LIBRARY_NAME':
            mode = 'libname'
        elif mode == 'files':
            files.extend(x for x in a.split(';') if x)
        elif mode == 'deps':
            deps.extend(x for x in a.split(';') if x)
    if not files:
        raise rosidl_error(59, 'rosidl_generate_interfaces() called without any interface '
                               'files', cmd.line)
    if result.ament_package:
        raise rosidl_error(64, 'rosidl_generate_interfaces() must be called before '
                               'ament_package()', cmd.line)
    if 'rosidl_interface_packages' not in member_of_groups and \
            'SKIP_GROUP_MEMBERSHIP_CHECK' not in args:
        raise rosidl_error(229, "Packages installing interfaces must include "
                                "'<member_of_group>rosidl_interface_packages</member_of_group>' "
                                "in their package.xml", cmd.line)
    for dep in deps:
        if dep not in result.found:   # rosidl_cmake's own FATAL_ERROR, as Humble prints it
            raise CMakeError(
                f'CMake Error at {ROSIDL_GENERATE_INTERFACES}:162 (message):\n'
                + wrap_message(f"rosidl_generate_interfaces() the passed dependency '{dep}' "
                               "has not been found before using find_package()")
                + f'\nCall Stack (most recent call first):\n'
                  f'  CMakeLists.txt:{cmd.line} (rosidl_generate_interfaces)\n')
    result.interfaces.extend(files)
    result.interface_deps.extend(deps)
    result.interface_line = cmd.line


def _install(cmd, args, result):
    if not args:
        return
    kind = args[0]
    if kind not in ('DIRECTORY', 'FILES', 'PROGRAMS'):
        return      # TARGETS: C++ targets are not built in labkit
    sources, destination, i = [], None, 1
    while i < len(args):
        if args[i] == 'DESTINATION' and i + 1 < len(args):
            destination = args[i + 1]
            i += 2
            continue
        if args[i] in ('PATTERN', 'FILES_MATCHING', 'USE_SOURCE_PERMISSIONS', 'OPTIONAL'):
            break
        sources.append(args[i])
        i += 1
    if destination is None:
        raise error(cmd, f'  install {kind} given no DESTINATION!')
    result.installs.append((kind, sources, destination))
