"""In virtual time, a sleep in the notebook's own code is a virtual wait (the
graph lives that long), but the kernel's own pauses are not: ipykernel sleeps
0.5 ms after every cell, and that must not move the ROS clock."""
import time

import labkit.process  # noqa: F401  (installs the sleep patch)
from labkit.graph import world


def _run_as(module_name: str, seconds: float) -> None:
    code = compile("time.sleep(seconds)", f"<{module_name}>", "exec")
    exec(code, {"__name__": module_name, "time": time, "seconds": seconds})


def test_kernel_pause_does_not_move_virtual_time():
    assert world.mode() == "virtual"
    before = world.steady_ns()
    _run_as("ipykernel.kernelbase", 0.0005)
    assert world.steady_ns() == before


def test_a_cells_sleep_is_virtual_time():
    before = world.steady_ns()
    _run_as("__main__", 0.25)
    assert world.steady_ns() - before == 250_000_000
