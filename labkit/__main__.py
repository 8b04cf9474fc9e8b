"""`python -m labkit exec FILE ...` is the same as the `labkit` console command."""
import sys

from labkit.cli.main import main

if __name__ == '__main__':
    sys.exit(main())
