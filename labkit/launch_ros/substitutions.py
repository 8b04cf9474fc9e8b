"""launch_ros.substitutions: where a package is installed (through the ament index)."""
from labkit.launch.substitution import Substitution
from labkit.launch.utilities import normalize_to_list_of_substitutions, perform_substitutions


class FindPackagePrefix(Substitution):
    def __init__(self, package):
        self.package = normalize_to_list_of_substitutions(package)

    def describe(self):
        return 'Pkg(pkg={})'.format(' + '.join(s.describe() for s in self.package))

    def find(self, name):
        from labkit.ament.index import get_package_prefix
        return get_package_prefix(name)

    def perform(self, context):
        return self.find(perform_substitutions(context, self.package))


class FindPackageShare(FindPackagePrefix):
    def find(self, name):
        from labkit.ament.index import get_package_share_directory
        return get_package_share_directory(name)


class ExecutableInPackage(Substitution):
    def __init__(self, executable, package):
        self.executable = normalize_to_list_of_substitutions(executable)
        self.package = normalize_to_list_of_substitutions(package)

    def perform(self, context):
        import os
        from labkit.launch_ros.actions import executable_path
        pkg = perform_substitutions(context, self.package)
        exe = perform_substitutions(context, self.executable)
        return os.path.join(executable_path(pkg, exe))
