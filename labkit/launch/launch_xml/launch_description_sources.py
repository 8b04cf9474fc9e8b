"""launch_xml.launch_description_sources.XMLLaunchDescriptionSource."""
from labkit.launch.launch_description_sources import FrontendLaunchDescriptionSource


class XMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """An XML launch file, for IncludeLaunchDescription."""
