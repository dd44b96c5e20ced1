"""``python -m thermobearing``: the same command line as ``thermobearing``."""

import sys

from .cli import main

sys.exit(main())
