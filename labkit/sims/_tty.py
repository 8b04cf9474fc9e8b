"""Raw single key presses from the controlling terminal, for the teleop programs
(turtle_teleop_key, teleop_twist_keyboard) when they run in a real terminal."""
import os
import sys
import threading


class TerminalKeys:
    """Reads keys on a thread and calls `press(char)` until `done()`; `close()` restores
    the terminal. With `pass_ctrl_c`, Ctrl-C arrives as the key '\\x03' (the program
    handles it) instead of a signal."""

    def __init__(self, press, done, *, pass_ctrl_c=False, name="teleop-tty"):
        import termios
        self.press = press
        self.done = done
        self.fd = sys.stdin.fileno()
        self.cooked = termios.tcgetattr(self.fd)
        raw = termios.tcgetattr(self.fd)
        raw[3] &= ~(termios.ICANON | termios.ECHO | (termios.ISIG if pass_ctrl_c else 0))
        raw[6][termios.VMIN] = 0
        raw[6][termios.VTIME] = 1          # read() returns after 0.1 s without a key
        termios.tcsetattr(self.fd, termios.TCSANOW, raw)
        self.thread = threading.Thread(target=self._loop, name=name, daemon=True)
        self.thread.start()

    def _loop(self):
        while not self.done():
            data = os.read(self.fd, 1)
            if data:
                self.press(data.decode("latin-1"))

    def close(self):
        import termios
        termios.tcsetattr(self.fd, termios.TCSANOW, self.cooked)


def open_terminal_keys(press, done, **options):
    """TerminalKeys when stdin is a terminal, else None."""
    try:
        if sys.stdin is not None and sys.stdin.isatty():
            return TerminalKeys(press, done, **options)
    except (OSError, ValueError, ImportError):
        pass
    return None
