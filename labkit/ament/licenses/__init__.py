"""The licenses `ros2 pkg create --license` knows (ament_copyright's), by SPDX id.

A known id makes `pkg create` write a LICENSE file with the license's standard
text (the `.txt` files beside this module); any other string is only put into
package.xml, with a warning.
"""
import os

# SPDX id -> text file; ament_copyright registers them as entry points, which
# Humble lists sorted by entry-point name (apache2, boost1, bsd2, bsd_2clause, ...).
_FILES = {
    'Apache-2.0': 'apache2.txt',
    'BSL-1.0': 'boost1.txt',
    'BSD-2.0': 'bsd2.txt',
    'BSD-2-Clause': 'bsd_2clause.txt',
    'BSD-3-Clause': 'bsd_3clause.txt',
    'GPL-3.0-only': 'gplv3.txt',
    'LGPL-3.0-only': 'lgplv3.txt',
    'MIT': 'mit.txt',
    'MIT-0': 'mit0.txt',
}


def identifiers():
    """The SPDX ids in the order `ros2 pkg create` prints them."""
    return list(_FILES)


def license_text(spdx):
    """The LICENSE file content for a known id; KeyError otherwise."""
    with open(os.path.join(os.path.dirname(__file__), _FILES[spdx]), encoding='utf-8') as f:
        return f.read()
