"""``python -m thermobearing``: the same command line as ``thermobearing``."""

import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
