"""`ign gazebo ...` and `ign topic ...`, for labkit's 2D stand-in of Gazebo (Fortress).

`ign gazebo [-v N] [-r] WORLD` starts the simulator as a background labkit
process (paused unless -r, as Gazebo does); `ign topic -l` lists the Gazebo
transport topics, `ign topic -i -t TOPIC` shows one. Not Gazebo: there is
no 3D scene or GUI; pictures come from render.py.
"""
import shlex
import sys

from labkit import oslayer

from . import transport as gz


def gazebo_main(args=None):
    """The server process: args as a command line ('ign', 'gazebo', options..., world)."""
    from . import world as world2d
    from .sim import Simulation
    argv = list(args or [])[2:]
    verbosity, run, world_name = 1, False, None
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("-v", "--verbose"):
            if i + 1 < len(argv) and argv[i + 1].isdigit():
                verbosity = int(argv[i + 1])
                i += 1
            else:
                verbosity = 1
        elif a.startswith("-v") and a[2:].isdigit():
            verbosity = int(a[2:])
        elif a in ("-r",):
            run = True
        elif a in ("-s", "-g", "--headless-rendering"):
            pass
        elif a.startswith("-"):
            print(f"Unknown option: {a}", file=sys.stderr)
            return 1
        else:
            world_name = a
        i += 1
    world_name = world_name or "empty.sdf"
    try:
        path = world2d.find(world_name)
    except FileNotFoundError:
        print(f"[Err] [Server.cc:142] Unable to find or download file[{world_name}]",
              file=sys.stderr, flush=True)
        return 255
    world = world2d.load(path)
    if verbosity >= 3:
        print("[Msg] Ignition Gazebo Server v6 (labkit 2D stand-in: a flat world, no 3D, no GUI)")
        print(f"[Msg] Loading SDF world file[{world_name}].")
        for vehicle in world.vehicles:
            print(f"[Msg] DiffDrive subscribing to twist messages on "
                  f"[/model/{vehicle.name}/cmd_vel]")
        print(f"[Msg] World [{world.name}] initialized with "
              f"[1ms] physics profile.", flush=True)
    sim = Simulation(world, running=run)
    # started from a terminal (live time) without -s: the GUI's place is a browser window
    window = None if "-s" in argv else _terminal_window(sim)
    try:
        sim.run()
    finally:
        if window is not None:
            window.close()
    return 0


def _terminal_window(sim):
    from labkit.viz import window
    if not window.ENABLED:
        return None
    from . import render
    return window.open_window(
        "Gazebo", lambda: render.image(sim),
        lambda: (sim.paused, tuple(tuple(v.pose) for v in sim.vehicles)),
        lambda text: print(f"[Msg] {text}", flush=True))


def topic_command(argv, out=None):
    """`ign topic -l` / `-i -t TOPIC`; returns an exit code."""
    out = out or sys.stdout
    if "-l" in argv or "--list" in argv:
        for name in gz.TRANSPORT.topics():
            out.write(name + "\n")
        return 0
    if "-i" in argv or "--info" in argv:
        try:
            topic = argv[argv.index("-t") + 1]
        except (ValueError, IndexError):
            out.write("Topic name required\n")
            return 1
        info = gz.TRANSPORT.info(topic)
        out.write("Publishers [Address, Message Type]:\n")
        if info and info[1]:
            out.write(f"  inprocess, {info[0]}\n")
        else:
            out.write("No publishers on topic [%s]\n" % topic)
        return 0
    out.write("labkit's ign topic knows -l and -i -t TOPIC\n")
    return 1


def ign_magic(line):
    """%ign gazebo -v 4 -r visualize_lidar.sdf | %ign topic -l"""
    result = run(line)
    if result is not None and hasattr(result, "stdout") and not hasattr(result, "process"):
        from labkit.commands import emit      # a start that failed at once: show its output
        emit(result)


def run(line):
    """Run an `ign` command line; `gazebo` returns its background job (or, if it failed at
    once, a finished command with returncode/stdout/stderr)."""
    argv = oslayer.split_args(line)
    if not argv:
        print("usage: ign gazebo|topic ...", file=sys.stderr)
        return None
    if argv[0] in ("gazebo", "sim"):
        return start_gazebo(argv)
    if argv[0] == "topic":
        topic_command(argv[1:])
        return None
    print(f"labkit's ign knows `gazebo` and `topic`, not `{argv[0]}`", file=sys.stderr)
    return None


def start_gazebo(argv):
    """Start `ign gazebo ...` as a background job (`%ros2 jobs` lists it)."""
    from labkit.plugins import entry
    jobs = entry("ros2 jobs")      # the CLI's background jobs, found by name
    command = "ign " + " ".join(shlex.quote(a) for a in argv)
    return jobs.start(argv, command, lambda sink: jobs.start_process(
        argv, "ign_gazebo", target=lambda args=None: gazebo_main(["ign", *argv]), sink=sink))
