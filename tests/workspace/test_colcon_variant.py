"""colcon_test.test_variant: a package's tests run on a changed copy (how the book checks
that a learner's tests really test the node)."""
import os

import pytest

from labkit.ament import colcon_test, files


@pytest.fixture
def pkg(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    root = tmp_path / 'src' / 'adder'
    (root / 'adder').mkdir(parents=True)
    (root / 'test').mkdir()
    (root / 'resource').mkdir()
    (root / 'resource' / 'adder').write_text('')
    (root / 'adder' / '__init__.py').write_text('')
    (root / 'adder' / 'maths.py').write_text('def add(a, b):\n    return a + b\n')
    (root / 'package.xml').write_text(
        '<?xml version="1.0"?>\n<package format="3"><name>adder</name><version>0.0.0</version>'
        '<description>d</description><maintainer email="dev@example.com">dev</maintainer>'
        '<license>MIT</license><export><build_type>ament_python</build_type></export>'
        '</package>\n')
    (root / 'setup.py').write_text("from setuptools import setup\nsetup(name='adder')\n")
    return root


EDIT = {'adder/maths.py': [('a + b', 'a - b')]}


def test_a_real_test_fails_on_the_broken_copy_and_the_original_is_untouched(pkg):
    (pkg / 'test' / 'test_add.py').write_text(
        'from adder.maths import add\n\n\ndef test_add():\n    assert add(2, 3) == 5\n')
    broken = colcon_test.test_variant(str(pkg), EDIT)
    assert broken.tests == 1 and broken.failures == 1
    assert (pkg / 'adder' / 'maths.py').read_text().endswith('return a + b\n')
    assert not (pkg.parent.parent / 'build').exists()      # the learner's workspace untouched
    assert os.getcwd() == str(pkg.parent.parent)


def test_a_test_that_tests_nothing_passes_on_the_broken_copy(pkg):
    (pkg / 'test' / 'test_add.py').write_text('def test_nothing():\n    assert True\n')
    broken = colcon_test.test_variant(str(pkg), EDIT)
    assert broken.tests == 1 and broken.failures == 0


def test_an_edit_that_does_not_apply_is_an_error(pkg):
    with pytest.raises(ValueError):
        colcon_test.test_variant(str(pkg), {'adder/maths.py': [('a * b', 'a')]})


def test_a_whole_file_replaces_or_adds_a_file(pkg):
    (pkg / 'test' / 'test_add.py').write_text('def test_nothing():\n    assert True\n')
    hidden = 'from adder.maths import add\n\n\ndef test_hidden():\n    assert add(1, 1) == 2\n'
    result = colcon_test.test_variant(str(pkg), {
        'test/test_hidden.py': hidden, 'adder/maths.py': 'def add(a, b):\n    return 3\n'})
    assert result.tests == 2 and result.failures == 1
    assert not (pkg / 'test' / 'test_hidden.py').exists()
