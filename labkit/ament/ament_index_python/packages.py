"""ament_index_python.packages: where a package is installed."""
from labkit.ament.index import (BUNDLED_PREFIX, PackageNotFoundError,  # noqa: F401
                                bundled_package_names, get_package_prefix,
                                get_package_share_directory, get_resources)


def get_packages_with_prefixes():
    """name -> prefix of every package (workspaces first, then the bundled ones)."""
    found = {name: get_package_prefix(name) for name in bundled_package_names()}
    found.update(get_resources('packages'))
    return found


def get_package_share_path(package_name):
    import pathlib
    return pathlib.Path(get_package_share_directory(package_name))
