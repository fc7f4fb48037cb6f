"""Imported by the fork server of the worker processes (`processes.PRELOAD`), once: librosa's
numba kernels are compiled (or loaded from numba's disk cache) here, by `spectrogram.warm_up`,
so that a worker forked from it decodes and analyses a song without compiling them again
(2–15 s each on a loaded 2-core machine: the server's song workers and a batch's). Only a fork
server imports this module: importing it runs the warm-up.
"""

from __future__ import annotations

from eigendance.music.spectrogram import warm_up

SECONDS = warm_up()  # how long the warm-up took in this fork server
