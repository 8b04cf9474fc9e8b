"""`labkit teacher VERB ...` (also `python -m labkit.teacher VERB ...`)."""
import sys


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    verbs = ("collect", "domain", "nbgrader")
    if not argv or argv[0] not in verbs:
        print("usage: labkit teacher {collect,domain,nbgrader} ...", file=sys.stderr)
        return 2
    if argv[0] == "collect":
        from labkit.teacher.collect import main as run
        return run(argv[1:])
    if argv[0] == "domain":
        from labkit.teacher.domain import main as run
        return run(argv[1:])
    from labkit.teacher.nbgrader_export import main as run
    return run(argv[1:])


if __name__ == "__main__":
    sys.exit(main())
