"""labkit's view against rqt_graph's own filtering code (humble), recorded by
make_rqt_reference.py into data/rqt_graph_reference.json."""
import json
import os

import pytest

from labkit.viz._graph_filter import ViewOptions, build_view
from labkit.viz._graph_model import GraphSnapshot
from rqt_scenarios import OPTION_SETS, SCENARIOS

REFERENCE = json.load(open(os.path.join(os.path.dirname(__file__), "data",
                                        "rqt_graph_reference.json")))
SHAPES = {"node": "ellipse", "topic": "box", "tf": "box3d"}


@pytest.mark.parametrize("scenario", sorted(SCENARIOS))
@pytest.mark.parametrize("option_set", sorted(OPTION_SETS))
def test_same_picture_as_rqt_graph(scenario, option_set):
    expected = REFERENCE[scenario][option_set]
    view = build_view(GraphSnapshot.from_dict(SCENARIOS[scenario]),
                      ViewOptions(**OPTION_SETS[option_set][1]))
    assert sorted([v.name, SHAPES[v.kind]] for v in view.vertices) == expected["vertices"]
    assert [list(e) for e in view.edges(labels=True)] == expected["edges"]
    assert sorted(view.clusters) == expected["clusters"]


def test_reference_covers_every_scenario_and_option_set():
    assert set(REFERENCE) == set(SCENARIOS)
    assert all(set(REFERENCE[s]) == set(OPTION_SETS) for s in REFERENCE)
    # the reference is not trivial: rqt_graph drew topics and arrows
    assert sum(len(r["edges"]) for s in REFERENCE.values() for r in s.values()) > 100
