"""`python -m eigendance` runs the command line."""

import sys

from eigendance.cli import main

sys.exit(main())
