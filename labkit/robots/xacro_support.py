"""xacro (the PyPI package) with `$(find pkg)` resolved through labkit's package index.

`process(path, mappings)` returns the expanded URDF text; errors become
`URDFError` naming the file and what xacro complained about.
"""
import contextlib
import io
import sys

from labkit.robots.urdf import URDFError


@contextlib.contextmanager
def _labkit_find():
    from xacro import substitution_args
    from labkit.robots import packages
    original = substitution_args._eval_find
    substitution_args._eval_find = packages.share_directory
    try:
        yield
    finally:
        substitution_args._eval_find = original


def process(path, mappings=None):
    """Expand a .xacro file (like `xacro path arg:=value`) into URDF text."""
    import xacro
    err = io.StringIO()
    with _labkit_find(), contextlib.redirect_stderr(err):
        try:
            doc = xacro.process_file(str(path), mappings=dict(mappings or {}))
        except Exception as exc:   # xacro raises XacroException, XML errors, NameError ...
            detail = " ".join(str(exc).split()) or type(exc).__name__
            error = URDFError(f"Error processing xacro file '{_shown(path)}': {_shown(detail)}")
            error.detail = detail
            raise error from None
    # xacro's banner names the file: a bundled package's file as it lies under /opt/ros/humble
    return doc.toprettyxml(indent="  ").replace(f"from {path} ", f"from {_shown(path)} ", 1)


def _shown(text):
    from labkit.ament import index
    return index.shown(text)


def main(args=None):
    """`xacro FILE [name:=value ...] [-o OUT]`: print the expanded URDF, like the xacro command."""
    argv = list(sys.argv if args is None else args)[1:]      # args[0] is the program
    out = None
    if "-o" in argv:
        i = argv.index("-o")
        out = argv[i + 1]
        del argv[i:i + 2]
    files = [a for a in argv if ":=" not in a and a != "--ros-args"]
    mappings = dict(a.split(":=", 1) for a in argv if ":=" in a)
    if len(files) != 1:
        sys.stderr.write("usage: xacro [-o OUT] input [mappings ...]\n")
        return 2
    try:
        text = process(files[0], mappings)
    except URDFError as exc:        # the xacro command prints xacro's own message
        report = io.StringIO()
        with contextlib.redirect_stderr(report):
            _report(exc.__context__ or exc)
        sys.stderr.write(_shown(report.getvalue()))
        return 2
    if out:
        with open(out, "w", encoding="utf-8") as handle:
            handle.write(text)
    else:
        sys.stdout.write(text)
    return 0


def _report(error):
    """Print a failure the way the xacro command does (its wording and location lines)."""
    import xml.parsers.expat
    import xacro
    if isinstance(error, xml.parsers.expat.ExpatError):
        xacro.error("XML parsing error: %s" % error, alt_text=None)
        xacro.print_location()
        sys.stderr.write('\nCheck that:\n - Your XML is well-formed\n'
                         ' - You have the xacro xmlns declaration: '
                         'xmlns:xacro="http://www.ros.org/wiki/xacro"\n')
    else:
        xacro.error(str(error) or repr(error))
        xacro.print_location()


def run(command_line):
    """(returncode, stdout, stderr) of a `xacro ...` command line: what launch's
    `Command(['xacro ', model])` substitution needs without a shell."""
    from labkit import oslayer
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(oslayer.split_args(command_line))
    return code, out.getvalue(), err.getvalue()
