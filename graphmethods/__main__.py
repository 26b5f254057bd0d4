"""``python -m graphmethods`` is the command line."""

import sys

from graphmethods.cli import main

sys.exit(main())
