"""A domain id that Fast DDS (Humble's default rmw) cannot map to UDP ports: the first
node's participant is refused, one line on stdout, and the process ends with status 1
(PortParameters::getMulticastPort: 7400 + 250 * 233 > 65535). Checked on the real
wheels: rclpy.init(domain_id=240) succeeds, create_node prints the line and exits 1."""
import pytest

from labkit import process

LINE = ('Calculated port number is too high. Probably the domainId is over 232 '
        'or portBase is too high.')


def _main(domain):
    def main(args=None):
        import labkit.rclpy as rclpy
        rclpy.init(args=args, domain_id=domain)
        print('init ok')
        rclpy.create_node('far')
        print('node made')
    return main


def test_domain_233_refused_at_the_first_node(virtual):
    from labkit.graph.registry import GRAPH
    proc = process.start(main=_main(233), name='far', echo=False)
    proc.wait()
    assert proc.output == ['init ok', LINE]
    assert proc.returncode == 1
    assert not [n for n in GRAPH.nodes if n.name == 'far']


def test_domain_232_still_works(virtual):
    proc = process.start(main=_main(232), name='near', echo=False)
    proc.wait()
    assert proc.output == ['init ok', 'node made']
    assert proc.returncode == 0


def test_env_domain_in_the_main_process(virtual, monkeypatch, capsys):
    import labkit.rclpy as rclpy
    monkeypatch.setenv('ROS_DOMAIN_ID', '250')
    rclpy.init(args=[])
    try:
        with pytest.raises(SystemExit) as exc:
            rclpy.create_node('far')
        assert exc.value.code == 1
        assert capsys.readouterr().out == LINE + '\n'
    finally:
        rclpy.try_shutdown()


def test_labkit_exec_runs_until_the_first_node(tmp_path):
    """As on Humble: nothing refuses ROS_DOMAIN_ID=240 before the program makes a node."""
    import os
    import subprocess
    import sys
    path = tmp_path / 'far.py'
    path.write_text("import rclpy\nrclpy.init()\nprint('init ok', flush=True)\n"
                    "rclpy.create_node('far')\nprint('node made')\n", encoding='utf-8')
    env = dict(os.environ, ROS_DOMAIN_ID='240', LABKIT_TIME='live', LABKIT_DDS='on',
               PYTHONPATH=os.getcwd())
    done = subprocess.run([sys.executable, '-m', 'labkit', 'exec', str(path)], env=env,
                          capture_output=True, text=True, timeout=60)
    assert (done.returncode, done.stdout) == (1, 'init ok\n' + LINE + '\n'), done.stderr
