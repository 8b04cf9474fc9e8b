"""launch_xml.launch_description_sources.XMLLaunchDescriptionSource."""
from labkit.launch import frontend
from labkit.launch.launch_description_sources import FrontendLaunchDescriptionSource


class XMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """An XML launch file, for IncludeLaunchDescription, read by the XML parser alone."""

    _load = staticmethod(frontend.xml_launch_description)
