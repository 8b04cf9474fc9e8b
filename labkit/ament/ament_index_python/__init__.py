"""`ament_index_python` on labkit's ament index (labkit/ament/index.py)."""
from labkit.ament.ament_index_python.packages import (  # noqa: F401
    PackageNotFoundError, get_package_prefix, get_package_share_directory,
    get_packages_with_prefixes)
from labkit.ament.index import get_resources, prefixes as get_search_paths  # noqa: F401
