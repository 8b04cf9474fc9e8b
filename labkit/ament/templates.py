"""The files `ros2 pkg create` writes, with Humble's exact content.

Each function returns the text of one file. The shapes (blank lines, comments,
indentation) are what ros2pkg's templates produce, so a package made here is
byte-for-byte the package a real Humble install makes.
"""

APACHE_HEADER = """\
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#     http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.
"""


def package_xml(*, package_format, name, description, maintainer_name, maintainer_email,
                license, buildtool_depends, depends, test_depends, build_type):
    lines = [
        '<?xml version="1.0"?>',
        f'<?xml-model href="http://download.ros.org/schema/package_format{package_format}.xsd"'
        ' schematypens="http://www.w3.org/2001/XMLSchema"?>',
        f'<package format="{package_format}">',
        f'  <name>{name}</name>',
        '  <version>0.0.0</version>',
        f'  <description>{description}</description>',
        f'  <maintainer email="{maintainer_email}">{maintainer_name}</maintainer>',
        f'  <license>{license}</license>',
        '',
    ]
    # each non-empty group of dependencies is followed by one blank line
    for tag, names in (('buildtool_depend', buildtool_depends), ('depend', depends),
                       ('test_depend', test_depends)):
        if names:
            lines += [f'  <{tag}>{n}</{tag}>' for n in names] + ['']
    lines += [
        '  <export>',
        f'    <build_type>{build_type}</build_type>',
        '  </export>',
        '</package>',
    ]
    return '\n'.join(lines) + '\n'


# ----------------------------------------------------------------------------- ament_python

def setup_py(*, name, maintainer_name, maintainer_email, description, license, node_name):
    entry = f"            '{node_name} = {name}.{node_name}:main'\n" if node_name else ''
    return (
        "from setuptools import find_packages, setup\n"
        "\n"
        f"package_name = '{name}'\n"
        "\n"
        "setup(\n"
        "    name=package_name,\n"
        "    version='0.0.0',\n"
        "    packages=find_packages(exclude=['test']),\n"
        "    data_files=[\n"
        "        ('share/ament_index/resource_index/packages',\n"
        "            ['resource/' + package_name]),\n"
        "        ('share/' + package_name, ['package.xml']),\n"
        "    ],\n"
        "    install_requires=['setuptools'],\n"
        "    zip_safe=True,\n"
        f"    maintainer='{maintainer_name}',\n"
        f"    maintainer_email='{maintainer_email}',\n"
        f"    description='{description}',\n"
        f"    license='{license}',\n"
        "    tests_require=['pytest'],\n"
        "    entry_points={\n"
        "        'console_scripts': [\n"
        f"{entry}"
        "        ],\n"
        "    },\n"
        ")\n"
    )


def setup_cfg(name):
    return (f'[develop]\nscript_dir=$base/lib/{name}\n'
            f'[install]\ninstall_scripts=$base/lib/{name}\n')


def python_main(name):
    return (f"def main():\n    print('Hi from {name}.')\n\n\n"
            "if __name__ == '__main__':\n    main()\n")


def test_copyright():
    return (
        '# Copyright 2015 Open Source Robotics Foundation, Inc.\n' + APACHE_HEADER +
        '\n'
        'from ament_copyright.main import main\n'
        'import pytest\n'
        '\n'
        '\n'
        '# Remove the `skip` decorator once the source file(s) have a copyright header\n'
        "@pytest.mark.skip(reason='No copyright header has been placed in the generated "
        "source file.')\n"
        '@pytest.mark.copyright\n'
        '@pytest.mark.linter\n'
        'def test_copyright():\n'
        "    rc = main(argv=['.', 'test'])\n"
        "    assert rc == 0, 'Found errors'\n"
    )


def test_flake8():
    return (
        '# Copyright 2017 Open Source Robotics Foundation, Inc.\n' + APACHE_HEADER +
        '\n'
        'from ament_flake8.main import main_with_errors\n'
        'import pytest\n'
        '\n'
        '\n'
        '@pytest.mark.flake8\n'
        '@pytest.mark.linter\n'
        'def test_flake8():\n'
        '    rc, errors = main_with_errors(argv=[])\n'
        '    assert rc == 0, \\\n'
        "        'Found %d code style errors / warnings:\\n' % len(errors) + \\\n"
        "        '\\n'.join(errors)\n"
    )


def test_pep257():
    return (
        '# Copyright 2015 Open Source Robotics Foundation, Inc.\n' + APACHE_HEADER +
        '\n'
        'from ament_pep257.main import main\n'
        'import pytest\n'
        '\n'
        '\n'
        '@pytest.mark.linter\n'
        '@pytest.mark.pep257\n'
        'def test_pep257():\n'
        "    rc = main(argv=['.', 'test'])\n"
        "    assert rc == 0, 'Found code style errors / warnings'\n"
    )


# ----------------------------------------------------------------------------- ament_cmake

_LINT_BLOCK = """\
if(BUILD_TESTING)
  find_package(ament_lint_auto REQUIRED)
  # the following line skips the linter which checks for copyrights
  # comment the line when a copyright and license is added to all source files
  set(ament_cmake_copyright_FOUND TRUE)
  # the following line skips cpplint (only works in a git repo)
  # comment the line when this package is in a git repo and when
  # a copyright and license is added to all source files
  set(ament_cmake_cpplint_FOUND TRUE)
  ament_lint_auto_find_test_dependencies()
endif()
"""

_MANUAL_DEPS = """\
# uncomment the following section in order to fill in
# further dependencies manually.
# find_package(<dependency> REQUIRED)
"""

_COMPILE_OPTIONS = """\
if(CMAKE_COMPILER_IS_GNUCXX OR CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  add_compile_options(-Wall -Wextra -Wpedantic)
endif()
"""

_INCLUDE_DIRS = ('  $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>\n'
                 '  $<INSTALL_INTERFACE:include>')
_CXX17 = 'PUBLIC c_std_99 cxx_std_17)  # Require C99 and C++17\n'


def _target_dependencies(target, deps):
    return ('ament_target_dependencies(\n'
            f'  {target}\n' + ''.join(f'  "{d}"\n' for d in deps) + ')\n')


def ament_cmake_lists(name, deps, node_name=None, library_name=None):
    t = 'cmake_minimum_required(VERSION 3.8)\n'
    t += f'project({name})\n\n' + _COMPILE_OPTIONS + '\n'
    t += '# find dependencies\nfind_package(ament_cmake REQUIRED)\n'
    if library_name:
        t += 'find_package(ament_cmake_ros REQUIRED)\n'
    t += ''.join(f'find_package({d} REQUIRED)\n' for d in deps) if deps else _MANUAL_DEPS
    if library_name:
        lib = library_name
        t += (f'\nadd_library({lib} src/{lib}.cpp)\n'
              f'target_compile_features({lib} ' + _CXX17 +
              f'target_include_directories({lib} PUBLIC\n' + _INCLUDE_DIRS + ')\n')
        if deps:
            t += _target_dependencies(lib, deps)
        t += ('\n# Causes the visibility macros to use dllexport rather than dllimport,\n'
              '# which is appropriate when building the dll but not consuming it.\n'
              f'target_compile_definitions({lib} PRIVATE "{name.upper()}_BUILDING_LIBRARY")\n'
              '\ninstall(\n  DIRECTORY include/\n  DESTINATION include\n)\n'
              f'install(\n  TARGETS {lib}\n  EXPORT export_${{PROJECT_NAME}}\n'
              '  ARCHIVE DESTINATION lib\n  LIBRARY DESTINATION lib\n'
              '  RUNTIME DESTINATION bin\n)\n')
    if node_name:
        t += (f'\nadd_executable({node_name} src/{node_name}.cpp)\n'
              f'target_include_directories({node_name} PUBLIC\n' + _INCLUDE_DIRS + ')\n')
        if library_name:
            t += f'target_link_libraries({node_name} {library_name})\n'
        else:
            t += f'target_compile_features({node_name} ' + _CXX17
            if deps:
                t += _target_dependencies(node_name, deps)
        t += f'\ninstall(TARGETS {node_name}\n  DESTINATION lib/${{PROJECT_NAME}})\n'
    t += '\n' + _LINT_BLOCK
    if library_name:
        t += ('\nament_export_include_directories(\n  include\n)\n'
              f'ament_export_libraries(\n  {library_name}\n)\n'
              'ament_export_targets(\n  export_${PROJECT_NAME}\n)\n')
    return t + '\nament_package()\n'


# ----------------------------------------------------------------------------- plain cmake

def cmake_lists(name, deps, node_name=None, library_name=None):
    t = 'cmake_minimum_required(VERSION 3.8)\n'
    t += f'project({name})\n\n'
    for part in ('MAJOR', 'MINOR', 'PATCH'):
        t += f'set({name}_{part}_VERSION 0)\n'
    t += (f'set({name}_VERSION\n  ${{{name}_MAJOR_VERSION}}.${{{name}_MINOR_VERSION}}'
          f'.${{{name}_PATCH_VERSION}})\n\n')
    t += _COMPILE_OPTIONS + '\n'
    if deps:
        t += '\n# find dependencies\n' + ''.join(f'find_package({d} REQUIRED)\n' for d in deps)
    else:
        t += _MANUAL_DEPS
    dep_includes = ''.join(f'  PUBLIC ${{{d}_INCLUDE_DIRS}}\n' for d in deps)
    dep_libs = ''.join(f' ${{{d}_LIBRARIES}}\n' for d in deps)
    if library_name:
        lib = library_name
        t += (f'\nadd_library({lib} SHARED src/{lib}.cpp)\n'
              f'target_compile_features({lib} ' + _CXX17 +
              f'target_include_directories({lib} PUBLIC\n' + _INCLUDE_DIRS + '\n' +
              dep_includes + ')\n')
        if deps:
            t += f'target_link_libraries({lib}\n' + dep_libs + ')\n'
        t += ('\n# Causes the visibility macros to use dllexport rather than dllimport,\n'
              '# which is appropriate when building the dll but not consuming it.\n'
              f'target_compile_definitions({lib} PRIVATE "{name.upper()}_BUILDING_LIBRARY")\n'
              '\ninstall(\n  DIRECTORY include/\n  DESTINATION include\n)\n'
              f'install(\n  TARGETS {lib}\n  EXPORT export_{name}\n'
              '  ARCHIVE DESTINATION lib\n  LIBRARY DESTINATION lib\n'
              '  RUNTIME DESTINATION bin)\n')
    if node_name:
        t += f'\nadd_executable({node_name} src/{node_name}.cpp)\n'
        if deps:
            t += (f'target_include_directories({node_name} PUBLIC\n' + _INCLUDE_DIRS + '\n' +
                  dep_includes + ')\n')
        if library_name:
            t += f'target_link_libraries({node_name} {library_name})\n'
        else:
            t += f'target_compile_features({node_name} ' + _CXX17
            if deps:
                t += f'target_link_libraries({node_name}\n' + dep_libs + ')\n'
        t += (f'\ninstall(\n  TARGETS {node_name}\n  EXPORT export_{name}\n'
              '  DESTINATION lib/${PROJECT_NAME})\n')
    if library_name or node_name:
        t += '\n# export targets\n'
        if library_name:
            t += f'set(export_targets ${{export_targets}};{library_name})\n'
        if node_name:
            t += f'set(export_targets ${{export_targets}};{node_name})\n'
        t += (f'export(EXPORT export_{name}\n'
              f'  FILE "${{PROJECT_BINARY_DIR}}/export_{name}.cmake")\n'
              f'\n# Create the {name}Config.cmake\n'
              'set(CONF_INCLUDE_DIRS "${CMAKE_INSTALL_PREFIX}/include")\n'
              f'configure_file({name}Config.cmake.in\n'
              f'  "${{PROJECT_BINARY_DIR}}/${{CMAKE_FILES_DIRECTORY}}/{name}Config.cmake" @ONLY)\n'
              f'\n# Create the {name}ConfigVersion.cmake\n'
              f'configure_file({name}ConfigVersion.cmake.in\n'
              f'  "${{PROJECT_BINARY_DIR}}/{name}ConfigVersion.cmake" @ONLY)\n'
              '\ninstall(FILES\n'
              f'  "${{PROJECT_BINARY_DIR}}/${{CMAKE_FILES_DIRECTORY}}/{name}Config.cmake"\n'
              f'  "${{PROJECT_BINARY_DIR}}/{name}ConfigVersion.cmake"\n'
              '  DESTINATION "share/${PROJECT_NAME}/cmake" COMPONENT dev)\n'
              f'install(EXPORT export_{name}\n'
              '  DESTINATION "share/${PROJECT_NAME}/cmake"\n'
              f'  FILE export_{name}.cmake\n'
              '  COMPONENT dev)\n')
    return t


def cmake_config_in(name, node_name=None, library_name=None):
    t = (f'# - Config file for the {name} package\n'
         '# It defines the following variables\n'
         f'#  {name}_INCLUDE_DIRS - include directories for FooBar\n'
         f'#  {name}_LIBRARIES    - libraries to link against\n'
         f'#  {name}_EXECUTABLE   - the bar executable\n'
         '\n'
         f'set({name}_INCLUDE_DIRS "@CONF_INCLUDE_DIRS@")\n'
         '\n'
         '# Our library dependencies (contains definitions for IMPORTED targets)\n'
         f'include("${{{name}_DIR}}/export_{name}.cmake")\n'
         '\n'
         f'# These are IMPORTED targets created by {name}Targets.cmake\n')
    # the template's `@[end if]` keeps its newline: one blank line after each block
    t += (f'set({name}_LIBRARIES {library_name})\n' if library_name else '') + '\n'
    t += (f'set({name}_EXECUTABLE {node_name})\n' if node_name else '') + '\n'
    return t


def cmake_config_version_in(name):
    return (f'set(PACKAGE_VERSION "@{name}_VERSION@")\n'
            '\n'
            '# Check whether the requested PACKAGE_FIND_VERSION is compatible\n'
            'if("${PACKAGE_VERSION}" VERSION_LESS "${PACKAGE_FIND_VERSION}")\n'
            '  set(PACKAGE_VERSION_COMPATIBLE FALSE)\n'
            'else()\n'
            '  set(PACKAGE_VERSION_COMPATIBLE TRUE)\n'
            '  if ("${PACKAGE_VERSION}" VERSION_EQUAL "${PACKAGE_FIND_VERSION}")\n'
            '    set(PACKAGE_VERSION_EXACT TRUE)\n'
            '  endif()\n'
            'endif()\n')


# ----------------------------------------------------------------------------- C++ sources

def cpp_main(package_name):
    return ('#include <cstdio>\n\n'
            'int main(int argc, char ** argv)\n{\n'
            '  (void) argc;\n  (void) argv;\n\n'
            f'  printf("hello world {package_name} package\\n");\n'
            '  return 0;\n}\n')


def class_name_of(library_name):
    """my_lib -> MyLib, as ros2pkg names the library's class."""
    return ''.join(library_name.replace('_', ' ').title().split())


def cpp_header(package_name, library_name):
    guard = f'{package_name.upper()}__{library_name.upper()}_HPP_'
    cls = class_name_of(library_name)
    return (f'#ifndef {guard}\n#define {guard}\n\n'
            f'#include "{package_name}/visibility_control.h"\n\n'
            f'namespace {package_name}\n{{\n\n'
            f'class {cls}\n{{\npublic:\n  {cls}();\n\n  virtual ~{cls}();\n}};\n\n'
            f'}}  // namespace {package_name}\n\n'
            f'#endif  // {guard}\n')


def cpp_library(package_name, library_name):
    cls = class_name_of(library_name)
    return (f'#include "{package_name}/{library_name}.hpp"\n\n'
            f'namespace {package_name}\n{{\n\n'
            f'{cls}::{cls}()\n{{\n}}\n\n'
            f'{cls}::~{cls}()\n{{\n}}\n\n'
            f'}}  // namespace {package_name}\n')


def visibility_control(package_name):
    p = package_name.upper()
    return (
        f'#ifndef {p}__VISIBILITY_CONTROL_H_\n'
        f'#define {p}__VISIBILITY_CONTROL_H_\n'
        '\n'
        '// This logic was borrowed (then namespaced) from the examples on the gcc wiki:\n'
        '//     https://gcc.gnu.org/wiki/Visibility\n'
        '\n'
        '#if defined _WIN32 || defined __CYGWIN__\n'
        '  #ifdef __GNUC__\n'
        f'    #define {p}_EXPORT __attribute__ ((dllexport))\n'
        f'    #define {p}_IMPORT __attribute__ ((dllimport))\n'
        '  #else\n'
        f'    #define {p}_EXPORT __declspec(dllexport)\n'
        f'    #define {p}_IMPORT __declspec(dllimport)\n'
        '  #endif\n'
        f'  #ifdef {p}_BUILDING_LIBRARY\n'
        f'    #define {p}_PUBLIC {p}_EXPORT\n'
        '  #else\n'
        f'    #define {p}_PUBLIC {p}_IMPORT\n'
        '  #endif\n'
        f'  #define {p}_PUBLIC_TYPE {p}_PUBLIC\n'
        f'  #define {p}_LOCAL\n'
        '#else\n'
        f'  #define {p}_EXPORT __attribute__ ((visibility("default")))\n'
        f'  #define {p}_IMPORT\n'
        '  #if __GNUC__ >= 4\n'
        f'    #define {p}_PUBLIC __attribute__ ((visibility("default")))\n'
        f'    #define {p}_LOCAL  __attribute__ ((visibility("hidden")))\n'
        '  #else\n'
        f'    #define {p}_PUBLIC\n'
        f'    #define {p}_LOCAL\n'
        '  #endif\n'
        f'  #define {p}_PUBLIC_TYPE\n'
        '#endif\n'
        '\n'
        f'#endif  // {p}__VISIBILITY_CONTROL_H_\n'
    )
