"""Compare with what real rclpy produced (tests/interfaces/data/rclpy_reference.json).

The fixture was recorded with rclpy from the Jazzy wheels (tools/make_rclpy_reference.py),
restricted to behaviour Humble shares: assertion texts, repr, class metadata, CDR.
"""
import array  # noqa: F401 (used by the recorded expressions)
import json
import os

import numpy  # noqa: F401
import pytest

import labkit.interfaces as li
from ifc_paths import DATA

with open(os.path.join(DATA, 'rclpy_reference.json'), encoding='utf-8') as f:
    REF = json.load(f)


@pytest.mark.parametrize('sample', REF['samples'], ids=lambda s: s['type'])
def test_cdr_and_repr_match_rclpy(test_msgs, sample):
    cls = li.get_type(sample['type'])
    theirs = bytes.fromhex(sample['cdr'])
    msg = li.deserialize(theirs, cls)
    assert repr(msg) == sample['repr']
    # rmw leaves padding and slack bytes uninitialised: equal wherever ours is not zero
    ours = li.rmw_serialize(msg)
    assert len(ours) == len(theirs)
    assert all(a == b or a == 0 for a, b in zip(ours, theirs))
    wire = li.serialize(msg)
    assert ours.startswith(wire) and not ours[len(wire):].strip(b'\0')
    assert li.deserialize(wire, cls) == msg


@pytest.mark.parametrize('case', REF['errors'], ids=lambda c: '%s.%s=%s' % (
    c['type'].split('/')[-1], c['field'], c['expr']))
def test_assertion_texts_match_rclpy(test_msgs, case):
    msg = li.get_type(case['type'])()
    value = eval(case['expr'])
    if case['error'] is None:
        setattr(msg, case['field'], value)
    else:
        with pytest.raises(AssertionError) as info:
            setattr(msg, case['field'], value)
        assert str(info.value) == case['error']


@pytest.mark.parametrize('name', sorted(REF['classes']))
def test_class_metadata_matches_rclpy(test_msgs, name):
    cls = li.get_type(name)
    ref = REF['classes'][name]
    assert cls.__module__ == ref['module']
    assert cls.__name__ == cls.__qualname__ == ref['name']
    assert cls.__slots__ == ref['slots']
    assert cls.get_fields_and_field_types() == ref['fields']
    constants = {k: repr(v) for k, v in vars(cls).items()
                 if k.isupper() and not k.endswith('__DEFAULT') and k != 'SLOT_TYPES'}
    assert constants == ref['constants']
    assert repr(cls()) == ref['repr_default']


def test_action_and_service_parts_match_rclpy(test_msgs):
    fib = li.get_type('test_msgs/action/Fibonacci')
    arrays = li.get_type('test_msgs/srv/Arrays')
    got = {}
    for attr in ('Goal', 'Result', 'Feedback'):
        c = getattr(fib, attr)
        got['Fibonacci.' + attr] = [c.__module__, c.__name__, repr(c())]
    for attr in ('SendGoalService', 'GetResultService', 'FeedbackMessage',
                 'CancelGoalService', 'GoalStatusMessage'):
        c = getattr(fib.Impl, attr)
        got['Fibonacci.Impl.' + attr] = [c.__module__, c.__name__]
    for attr in ('Request', 'Response'):
        c = getattr(fib.Impl.SendGoalService, attr)
        got['Fibonacci.Impl.SendGoalService.' + attr] = [c.__module__, c.__name__, repr(c())]
        c = getattr(arrays, attr)
        got['Arrays.' + attr] = [c.__module__, c.__name__]
    got['Fibonacci.Impl.FeedbackMessage()'] = repr(fib.Impl.FeedbackMessage())
    assert got == REF['derived']
