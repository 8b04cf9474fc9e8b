"""%colcon, %source and %rosdep read their line as bash does: a `# comment` after the
command is dropped (issue 18: a line with a trailing comment is a valid answer)."""
import labkit


def test_a_trailing_comment_is_not_an_argument(facer, capsys):
    from labkit.cli import magics
    magics.MAGICS['colcon']('build --packages-select facer_input   # 只构建这一个包')
    captured = capsys.readouterr()
    assert 'unrecognized arguments' not in captured.err
    assert captured.out.startswith('Starting >>> facer_input\n')
    magics.MAGICS['source']('install/setup.bash  # 让这个终端看见它')
    assert capsys.readouterr().err == ''
    assert labkit.ros2('pkg executables facer_input').stdout == 'facer_input capture_image\n'
    magics.MAGICS['rosdep']('install -i --from-path src --rosdistro humble -y # 装依赖')
    assert capsys.readouterr().out.endswith('#All required rosdeps installed successfully\n')


def test_source_with_only_a_comment_names_the_missing_file(facer, capsys):
    from labkit.cli import magics
    magics.MAGICS['source']('   # nothing but a comment')
    assert capsys.readouterr().err == 'bash: source: filename argument required\n'


def test_only_a_hash_that_begins_a_word_starts_the_comment():
    from labkit.ament.magics import _words
    assert _words('build --cmake-args -DX=a#b') == ['build', '--cmake-args', '-DX=a#b']
    assert _words('build "a # b" # c') == ['build', 'a # b']
    assert _words("build 'x#' #c") == ['build', 'x#']
    assert _words('build\t#tab') == ['build']
    assert _words('# all of it') == []


def test_ros2_magic_keeps_a_hash_inside_a_word():
    from labkit.cli.magics import split_redirect
    assert split_redirect('topic pub /t std_msgs/msg/String "data: a#b" --once # note') == \
        (['topic', 'pub', '/t', 'std_msgs/msg/String', 'data: a#b', '--once'], None, None)
    assert split_redirect('param set /n name a#b > out.txt  # keep a#b') == \
        (['param', 'set', '/n', 'name', 'a#b'], 'out.txt', 'w')
