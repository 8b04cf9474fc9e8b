"""launch_yaml.launch_description_sources.YAMLLaunchDescriptionSource."""
from labkit.launch.launch_description_sources import FrontendLaunchDescriptionSource


class YAMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """A YAML launch file, for IncludeLaunchDescription."""
