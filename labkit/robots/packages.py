"""Where robot packages live: a workspace the reader built and sourced first,
then labkit's bundled `facer_description` (labkit/robots/prefix, a read-only
install prefix), then whatever else the ament index knows."""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
PREFIX = os.path.join(HERE, "prefix")
SHARE = os.path.join(PREFIX, "share")
BUNDLED = ("facer_description",)


class PackageNotFoundError(KeyError):
    pass


def share_directory(package):
    """`get_package_share_directory(package)`, falling back to the bundled robot packages."""
    try:
        from labkit.ament import index
        workspace = index.get_resources("packages").get(package)
        if workspace is not None:
            return os.path.join(workspace, "share", package)
        if package not in BUNDLED:
            return index.get_package_share_directory(package)
    except ImportError:
        pass
    if package in BUNDLED:
        return os.path.join(SHARE, package)
    raise PackageNotFoundError(f"package '{package}' not found")


def resolve_uri(uri, base_dir=None):
    """A local path for a mesh `filename`: package://pkg/..., file://..., or relative."""
    if uri.startswith("package://"):
        package, _, rest = uri[len("package://"):].partition("/")
        return os.path.join(share_directory(package), rest)
    if uri.startswith("file://"):
        return uri[len("file://"):]
    if base_dir and not os.path.isabs(uri):
        return os.path.join(base_dir, uri)
    return uri
