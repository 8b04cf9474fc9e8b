"""The layer-4+ rooms announce themselves here.

Each room listed in ROOMS may define `register()` in its package: it adds
import aliases (compat.register_alias), ros2 nouns (register_noun), magics and
executables. It must be cheap (no heavy imports: those happen when the
thing is used). `register_all()` runs each once; the import hook, the ros2
CLI and `ros2 run` call it before they look anything up.
"""
import importlib

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
