"""launch_yaml.launch_description_sources.YAMLLaunchDescriptionSource."""
from labkit.launch import frontend
from labkit.launch.launch_description_sources import FrontendLaunchDescriptionSource


class YAMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """A YAML launch file, for IncludeLaunchDescription, read by the YAML parser alone."""

    _load = staticmethod(frontend.yaml_launch_description)
