"""A URDF whose joints do not make one tree fails with urdfdom's own words (parseURDF's
"Failed to build tree: " / "Failed to find root link: " and the ParseError texts of
urdf_model's initTree / initRoot), joints and links taken in name order as std::map does."""
import pytest

from labkit.robots.urdf import URDFError, load


def _robot(links, joints):
    body = ''.join(f'<link name="{n}"/>' for n in links)
    for name, parent, child in joints:
        body += (f'<joint name="{name}" type="fixed"><parent link="{parent}"/>'
                 f'<child link="{child}"/></joint>')
    return f'<robot name="r">{body}</robot>'


def _error(links, joints):
    with pytest.raises(URDFError) as exc:
        load(_robot(links, joints))
    return str(exc.value)


def test_missing_child_link():
    assert _error(['base'], [('j', 'base', 'ghost')]) == \
        'Failed to build tree: child link [ghost] of joint [j] not found'


def test_child_is_looked_up_before_the_parent():
    assert _error(['base'], [('j', 'nobody', 'ghost')]) == \
        'Failed to build tree: child link [ghost] of joint [j] not found'


def test_missing_parent_link():
    assert _error(['arm'], [('j', 'ghost', 'arm')]) == (
        'Failed to build tree: parent link [ghost] of joint [j] not found.  This is not '
        'valid according to the URDF spec. Every link you refer to from a joint needs to be '
        'explicitly defined in the robot description. To fix this problem you can either '
        'remove this joint [j] from your urdf file, or add "<link name="ghost" />" to your '
        'urdf file.')


def test_joints_in_name_order():
    # b_joint is written first, but std::map visits a_joint first
    assert _error(['base'], [('b_joint', 'base', 'ghost_b'), ('a_joint', 'base', 'ghost_a')]) \
        == 'Failed to build tree: child link [ghost_a] of joint [a_joint] not found'


def test_two_roots():
    assert _error(['zeta', 'base', 'arm'], [('j', 'base', 'arm')]) == \
        'Failed to find root link: Two root links found: [base] and [zeta]'


def test_no_root():
    assert _error(['a', 'b'], [('j1', 'a', 'b'), ('j2', 'b', 'a')]) == \
        'Failed to find root link: No root link found. The robot xml is not a valid tree.'


def test_a_good_tree_still_loads():
    model = load(_robot(['base', 'arm'], [('j', 'base', 'arm')]))
    assert model.root == 'base'
