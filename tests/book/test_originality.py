"""Our code is our own (issue 12 §1): no run of 200 characters of a book code cell or a
file labkit ships may be identical to the official ROS 2 tutorials and sources.

Excepted: import lines, what `ros2 pkg create` generates, license texts, and in labkit's
implementation (not the examples it ships) the string literals, which hold the real
programs' output and usage texts. Interface definitions (.msg/.srv/.action) must be
identical to the real ones and are not compared.

In CI the texts are compared with FINGERPRINTS of the official sources (hashes of
200-character windows, see tools/originality.py; no upstream text is committed). With
LABKIT_REF_DIR pointing at a folder of the official sources (one sub-folder per
repository), the last test also measures every run exactly.
"""
import os
import random
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / 'tools'))
import originality as o  # noqa: E402

LIMIT = 200


@pytest.fixture(scope='module')
def fingerprints():
    return o.load()


@pytest.fixture(scope='module')
def grams():
    return o.allowed_grams(o.allowed_texts())


@pytest.fixture(scope='module')
def ours():
    shown = o.shown_texts()
    return shown, o.source_texts(shown=[label for label, _ in shown])


def test_fingerprint_file_is_small_and_holds_no_text():
    data = Path(o.FINGERPRINTS).read_bytes()
    assert 0 < len(data) < 2 * 1024 * 1024
    assert len(data) % o.HASH_BYTES == 0
    # hashes, sorted and distinct: no readable text hides in there
    values = [data[i:i + o.HASH_BYTES] for i in range(0, len(data), o.HASH_BYTES)]
    assert values == sorted(set(values))
    longest_printable = max(len(m) for m in re.findall(rb'[ -~]+', data))
    assert longest_printable < 16


def test_winnowing_finds_every_long_enough_copy():
    rng = random.Random(12)
    words = ['node', 'self', 'msg', 'topic', 'publish', '(', ')', '=', 'timer', 'data', ':']
    theirs = ' '.join(rng.choice(words) + str(rng.randrange(99)) for _ in range(3000))
    kept = o.winnow(o.window_hashes(o.normalise(theirs)))
    mine = ' '.join(rng.choice(words) + str(rng.randrange(99)) for _ in range(100))
    guaranteed = o.WINDOW + o.SPAN - 1
    for start in range(0, len(theirs) - guaranteed, 997):
        copied = theirs[start:start + guaranteed]
        runs = o.shared_runs(o.normalise(f'{mine} {copied} {mine}'), kept)
        assert runs, f'a copy of {guaranteed} characters at {start} went unnoticed'
    # a run shorter than a window is never reported
    short = theirs[500:500 + o.WINDOW - 1]
    assert not o.shared_runs(o.normalise(f'{mine} {short} {mine}'), kept)


def test_fingerprints_recognise_real_upstream_texts(fingerprints):
    # the Apache-2.0 text is in the official repositories (and excepted in ours as a
    # license); static_transform_publisher's usage text is the real tool's
    apache = (ROOT / 'labkit' / 'ament' / 'licenses' / 'apache2.txt').read_text()
    assert o.shared_runs(o.normalise(apache), fingerprints)
    tool = (ROOT / 'labkit' / 'tf2' / 'static_transform_publisher.py').read_text()
    assert o.shared_runs(o.normalise(tool), fingerprints)
    # ... and both pass once the exceptions apply
    assert not o.shared_runs(o.normalise(o.without_strings(tool)), fingerprints)


def test_exceptions_mask_only_templates_and_licenses(grams):
    # what pkg create writes is excepted, our own lines next to it are not
    setup = ("from setuptools import setup\n\npackage_name = 'my_package'\n\nsetup(\n"
             "    name=package_name,\n    version='0.0.0',\n")
    flat = o.mask_allowed(o.normalise(setup), grams)
    assert o.MASK in flat
    ours = 'def chase(self, carrot): return self.steer_towards(carrot.position, gain=0.8)'
    assert o.MASK not in o.mask_allowed(o.normalise(ours), grams)


def _report(found):
    return '\n'.join(f'{label}: {length}+ characters from {excerpt!r}...'
                     for label, runs in sorted(found.items()) for length, excerpt in runs)


def test_book_cells_and_shipped_files_are_our_own(ours, fingerprints, grams):
    shown, _ = ours
    assert len(shown) > 500 and any(' cell ' in label for label, _ in shown)
    found = o.check(shown, fingerprints, grams)
    assert not found, 'identical to the official sources:\n' + _report(found)


def test_labkit_code_is_our_own(ours, fingerprints, grams):
    _, source = ours
    assert len(source) > 100
    found = o.check(source, fingerprints, grams)
    assert not found, 'identical to the official sources:\n' + _report(found)


@pytest.mark.skipif(not os.environ.get('LABKIT_REF_DIR'),
                    reason='set LABKIT_REF_DIR to a folder of the official sources '
                           '(ros2_documentation, examples, demos, geometry2, ...) to measure '
                           'every shared run exactly')
def test_exact_longest_runs_against_reference_dir(ours, grams):
    import longest_run
    folders = sorted(str(p) for p in Path(os.environ['LABKIT_REF_DIR']).iterdir()
                     if p.is_dir())
    texts = [(label, o.mask_allowed(o.normalise(text), grams))
             for label, text in ours[0] + ours[1]]
    references = ((name, o.normalise(text)) for name, text in o.reference_texts(folders))
    best = longest_run.longest_runs(texts, references)
    over = {label: run for label, run in best.items() if run[0] >= LIMIT}
    assert not over, '\n'.join(f'{n} {label} ~ {ref}' for label, (n, ref, _) in over.items())
