"""Raw single key presses from the controlling terminal, for the teleop programs
(turtle_teleop_key, teleop_twist_keyboard) when they run in a real terminal.
termios on Linux and macOS, msvcrt on Windows: labkit.oslayer.terminal_keys."""
from labkit import oslayer


def open_terminal_keys(press, done, **options):
    """The key reader (`.close()` restores the terminal) when stdin is a terminal, else
    None. `press(char)` gets what a Linux terminal sends (arrows as ESC [ A..D)."""
    return oslayer.terminal_keys(press, done, **options)
