"""What the fork server of the server's worker processes imports once, before it forks any
(`server.workers.PRELOAD`, docs/design.md#server): the analysis and the eigen-solver, so that
every worker process starts in a few tens of milliseconds with them. Only the fork server
imports this module.
"""

from __future__ import annotations

import eigendance.harmonic.eigensolver  # noqa: F401 - imported for the worker processes
import eigendance.server.analysis  # noqa: F401
