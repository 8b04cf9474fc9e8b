"""The plumbing every command line shares (layer 3): results, output recording, argparse.

`ros2` (labkit/cli), `colcon`, `rosdep` (labkit/ament), `ros2 bag` (labkit/bag),
`ros2 doctor`, ... all parse a command line, print into two recorded streams and
end with a `CompletedCommand`. That is plumbing, not the CLI: it lives here, one
floor below every tool, so that no tool has to reach up into `labkit.cli`
(the CLI only assembles the verbs; see ARCHITECTURE.md, "The house").

Verbs are written like ros2cli's: `main(args, io)` prints through `io`
(a `Streams`), and returns None/0 (success), an int (exit code) or a str
(one error line, exit 1).
"""
import argparse
import io
import sys
import threading

__all__ = ['CompletedCommand', 'Recorder', 'Streams', 'CliError', 'ParserExit', 'Parser',
           'set_parse_streams', 'add_verbs', 'emit']


class CompletedCommand:
    """What a finished command left behind (like subprocess.CompletedProcess)."""

    def __init__(self, args, returncode, stdout='', stderr='', exception=None, chunks=None):
        self.args = args
        self.returncode = returncode
        self.stdout = stdout
        self.stderr = stderr
        self.exception = exception  # an unexpected internal error, kept for debugging
        # [(stream name, text)] in the order printed, so a terminal-like view interleaves them
        self.chunks = chunks if chunks is not None else \
            [c for c in (('stdout', stdout), ('stderr', stderr)) if c[1]]

    def check_returncode(self):
        if self.returncode:
            import subprocess
            raise subprocess.CalledProcessError(
                self.returncode, self.args, self.stdout, self.stderr)

    def text(self):
        return ''.join(text for _, text in self.chunks)

    def __str__(self):
        return self.text()

    def __repr__(self):
        # a notebook shows the command's output, as a terminal would
        return self.text().rstrip('\n')

    def _repr_pretty_(self, p, cycle):
        p.text(self.__repr__())


class Recorder(io.StringIO):
    """One output stream of a command, also noting each write in the shared order."""

    def __init__(self, name, chunks, echo=None):
        super().__init__()
        self.name = name
        self.chunks = chunks
        self.echo = echo

    def write(self, text):
        if text:
            self.chunks.append((self.name, text))
            if self.echo is not None:
                self.echo(self.name, text)
        return super().write(text)


class CliError(Exception):
    """A user mistake: one line on stderr, exit code 1 (ros2cli raises RuntimeError)."""


class ParserExit(Exception):
    def __init__(self, status):
        super().__init__(status)
        self.status = status


class Streams:
    """Where a verb prints: captured text for short verbs, the process sink for jobs."""

    def __init__(self, out, err):
        self.out = out
        self.err = err

    def print(self, *values, sep=' ', end='\n'):
        print(*values, sep=sep, end=end, file=self.out)

    def eprint(self, *values, sep=' ', end='\n'):
        print(*values, sep=sep, end=end, file=self.err)


_parsing = threading.local()  # .streams: the Streams of the command this thread parses


def set_parse_streams(streams):
    _parsing.streams = streams


class Parser(argparse.ArgumentParser):
    """argparse that prints into the command's streams and never calls sys.exit."""

    def _get_formatter(self):
        # a notebook has no terminal: help is laid out for 80 columns, the same every run
        return self.formatter_class(prog=self.prog, width=78)

    def _print_message(self, message, file=None):
        if not message:
            return
        streams = _parsing.streams
        target = streams.err if (file is not None and file is not sys.stdout) else streams.out
        target.write(message)

    def exit(self, status=0, message=None):
        if message:
            self._print_message(message, sys.stderr)
        raise ParserExit(status)


def add_verbs(noun_parser, cli_name, verbs):
    """Add one subparser per verb: `verbs` is [(name, help, add_arguments, main), ...]."""
    description = ''
    width = max(len(v[0]) for v in verbs)
    for name, doc, _, _ in verbs:
        description += f'{name.ljust(width)}  {doc}\n'
    sub = noun_parser.add_subparsers(
        title='Commands', description=description,
        metavar=f'Call `{cli_name} <command> -h` for more detailed usage.',
        parser_class=Parser)
    sub.dest = ' verb'
    sub.required = False
    for name, doc, add_arguments, main in verbs:
        p = sub.add_parser(name, description=doc,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        p.set_defaults(_verb=main)
        if add_arguments is not None:
            add_arguments(p)
    return sub


def emit(result, target=None, mode='w'):
    """Print a finished command as a terminal would: in the order it printed.

    With `target`, stdout goes to that file (`>` / `>>`) and only stderr is shown.
    """
    chunks = getattr(result, 'chunks', None)
    if chunks is None:
        chunks = [('stdout', result.stdout), ('stderr', result.stderr)]
    merged = []  # one write per run of the same stream keeps stored notebooks small
    for name, text in chunks:
        if merged and merged[-1][0] == name:
            merged[-1] = (name, merged[-1][1] + text)
        elif text:
            merged.append((name, text))
    chunks = merged
    if target is not None:
        with open(target, mode) as f:
            f.write(''.join(text for name, text in chunks if name == 'stdout'))
    for name, text in chunks:
        if name == 'stdout' and target is not None:
            continue
        stream = sys.stdout if name == 'stdout' else sys.stderr
        stream.write(text)
        stream.flush()
