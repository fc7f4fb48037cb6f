"""The `eigendance` command line (docs/design.md#cli): one module per group of commands.

`main` runs a command (the `eigendance` entry point, `python -m eigendance`); `build_parser`
makes the argument parser of every command. The groups: `harmonics` (basis, spectrum, gallery,
animate), `rigs` (modes, animate-rig), `exports` (export, render) and `web` (serve, demo), over
`options` (argument types that check every number, shared inputs) and `main` (the parser, the
exit statuses). Nothing in the package imports `eigendance.cli`: it is the top of the graph.
"""

from eigendance.cli.main import build_parser, main

__all__ = ["build_parser", "main"]
