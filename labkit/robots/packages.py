"""Where robot packages live: labkit's bundled `urdf_tutorial` and
`urdf_tutorial_r2d2` share folders, then whatever the ament index knows
(a workspace the reader built and sourced wins over the bundled copy)."""
import os

SHARE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "share")
BUNDLED = ("urdf_tutorial", "urdf_tutorial_r2d2")


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
