"""The layer-4+ rooms announce themselves here.

Each room listed in ROOMS may define `register()` in its package: it adds
import aliases (compat.register_alias), ros2 nouns (`plugins.register_noun`),
magics (`plugins.register_magic`) and executables. It must be cheap (no heavy
imports: those happen when the thing is used). `register_all()` runs each once;
the import hook, the ros2 CLI and `ros2 run` call it before they look anything up.

The registries live here, not in labkit.cli: a room tells the house what it
offers and the CLI (the top floor) reads it; no room imports the CLI. A room
that must *run* a top-floor program (a launch file's `ros2 topic pub ...`,
`ign gazebo` as a background job) finds it by name with `entry()`, as a real
tool finds `ros2` on the PATH.
"""
import importlib

NOUNS = {}    # `ros2 <noun>` -> (module path, one-line doc); the CLI adds its own nouns here too
MAGICS = {}   # IPython line magic name -> function(line)
_magic_listeners = []

# top-floor programs by name -> "module" or "module:attribute" (resolved when used)
ENTRY_POINTS = {
    "ros2": "labkit.cli.ros2:run_command",
    "ros2 jobs": "labkit.cli.ros2.jobs",
}


def register_noun(name, module, doc):
    """Add a `ros2 <name>` command: `module` defines add_arguments(parser, cli_name)."""
    NOUNS[name] = (module, doc)


def register_magic(name, function):
    """Add (or replace) a line magic (`%name ...`); a loaded IPython gets it at once."""
    MAGICS[name] = function
    for listener in list(_magic_listeners):
        listener(name, function)


def on_magic(listener):
    """`listener(name, function)` hears of every magic registered from now on."""
    _magic_listeners.append(listener)


def entry(name):
    """The program (module or function) registered as `name` in ENTRY_POINTS."""
    module, _, attribute = ENTRY_POINTS[name].partition(":")
    target = importlib.import_module(module)
    return getattr(target, attribute) if attribute else target

ROOMS = ("labkit.ament", "labkit.launch", "labkit.bag", "labkit.tf2", "labkit.robots",
         "labkit.vision", "labkit.doctor", "labkit.sims")

_done = False


def register_all():
    global _done
    if _done:
        return
    _done = True
    for name in ROOMS:
        try:
            room = importlib.import_module(name)
        except ModuleNotFoundError as exc:
            if exc.name == name:      # a room not written yet
                continue
            raise
        hook = getattr(room, "register", None)
        if hook is not None:
            hook()
