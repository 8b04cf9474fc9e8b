"""The built book's search in headless Chromium: the Latin terms the book
uses (QoS, DDS, tf2 ...) and Chinese phrases typed as a reader types them
("工作空间的话题", "话题的QoS") find the pages that teach them.

Before book/_static/labkit_search.js kept short words unstemmed, "QoS" and
"DDS" found nothing: the browser stemmed them to "qo"/"dd" while the index
holds "qos"/"dds"."""

from __future__ import annotations

import json
from urllib.parse import quote

import pytest

# query -> a page (path without .html) that must be among the results
QUERIES = {
    "QoS": "part1_basics/ch03_topics",
    "qos": "part1_basics/ch03_topics",
    "DDS": "connect_real_ros",
    "tf2": "part3_tools/ch22_tf2",
    "URDF": "part3_tools/ch23_urdf",
    "xacro": "part3_tools/ch23_urdf",
    "rosdep": "part3_tools/ch17_rosdep",
    "colcon": "part3_tools/ch16_colcon",
    "rclpy": "part2_facer/ch13_nodes",
    "launch": "part3_tools/ch21_launch",
    "rosbag2": "part3_tools/ch20_bag",
    "bag": "part3_tools/ch20_bag",
    "Gazebo": "part3_tools/ch24_gazebo",
    "rviz2": "part3_tools/ch23_urdf",
    "话题": "part1_basics/ch03_topics",
    "话题的QoS": "part1_basics/ch03_topics",
    "QoS 兼容": "part1_basics/ch03_topics",
    "工作空间的话题": "part1_basics/ch08_workspaces_packages",
}

RESULTS = """(() => {
  const items = document.querySelectorAll('#search-results ul.search li a');
  // The summary line ("搜索完成，匹配到 8 页。") appears when the search is over.
  const summary = document.querySelector('#search-results .search-summary');
  if (!summary || !summary.innerText.trim()) return null;
  return JSON.stringify(Array.from(items).map(a => a.getAttribute('href')));
})()"""


def search(page, served, query: str) -> list[str]:
    page.open(served("book", "search.html?q=" + quote(query)))
    hrefs = json.loads(page.wait_for(RESULTS, timeout=30))
    return [h.split("?")[0].split("#")[0].removesuffix(".html") for h in hrefs]


@pytest.mark.parametrize("query", list(QUERIES))
def test_search_finds_the_page(page, served, query):
    found = search(page, served, query)
    assert QUERIES[query] in found, f"{query!r} found {len(found)} pages: {found[:10]}"
