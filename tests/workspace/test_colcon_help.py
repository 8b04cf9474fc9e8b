"""`colcon --help` prints the text of the real tool a Humble user has, not labkit's parser."""
from labkit.ament import colcon

VERBS = ('build', 'extension-points', 'extensions', 'graph', 'info', 'list', 'metadata',
         'mixin', 'test', 'test-result', 'version-check')


def test_help_lists_every_verb_of_the_real_tool():
    for flag in ('-h', '--help'):
        r = colcon.run_command(flag)
        assert r.returncode == 0
        lines = r.stdout.splitlines()
        assert lines[1].strip() == '{' + ','.join(VERBS) + '}'
        for verb in VERBS:
            assert any(line.startswith(f'  {verb} ') for line in lines), verb
        assert 'Environment variables:' in lines
        assert lines[-1] == 'For more help and usage tips, see https://colcon.readthedocs.io'
        # argparse's own description line is not part of the real help
        assert 'extensible command line tool' not in r.stdout


def test_no_verb_prints_the_same_usage_and_an_error():
    r = colcon.run_command('')
    assert r.returncode == 1
    assert r.stdout == colcon.USAGE + '\n' and r.stderr.strip() == 'Error: No verb provided'
    assert colcon.HELP.startswith(colcon.USAGE)


def test_an_unknown_argument_prints_the_real_usage():
    r = colcon.run_command('test --cmake-args tests')
    assert r.returncode == 2
    assert r.stderr == colcon.USAGE + 'colcon: error: unrecognized arguments: --cmake-args tests\n'
    # the verbs keep their own usage line
    assert colcon.run_command('build --help').stdout.startswith('usage: colcon build [-h]')
