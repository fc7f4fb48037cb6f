"""What the fork server of the server's worker processes imports once, before it forks any
(`server.workers.PRELOAD`, docs/design.md#server): the analysis and the eigen-solver, so that
every worker process starts in a few tens of milliseconds with them, and librosa's numba
kernels compiled (`spectrogram.warm_up`), so that a worker decoding a song does not compile
them again (2-15 s). Only the fork server imports this module.
"""

from __future__ import annotations

import eigendance.harmonic.eigensolver  # noqa: F401 - imported for the worker processes
import eigendance.server.analysis  # noqa: F401
from eigendance.music.spectrogram import warm_up

warm_up()  # in the fork server, once: its worker processes inherit the compiled kernels
