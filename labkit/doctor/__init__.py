"""ros2doctor on labkit: `ros2 doctor` checks and `ros2 doctor --report`.

The checks and reports keep ros2doctor's categories, names, order and output
shape, but look at what labkit really is: an in-process graph that sends no
packets, emulating Humble on whatever OS and Python run it.
"""


def register():
    """The plugins hook: the `doctor` noun (and its alias `wtf`), the rqt_console executable."""
    from labkit import executables
    from labkit.plugins import register_noun
    register_noun('doctor', 'labkit.doctor.command', 'Check ROS setup and other potential issues')
    register_noun('wtf', 'labkit.doctor.command', 'Use `wtf` as alias to `doctor`')
    executables.register('rqt_console', 'rqt_console', 'labkit.viz.console:main')
