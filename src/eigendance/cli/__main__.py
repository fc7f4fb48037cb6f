"""`python -m eigendance.cli`: the command line (as the `eigendance` command)."""

import sys

from eigendance.cli.main import main

sys.exit(main())
