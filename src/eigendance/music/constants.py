"""The analysis constants shared by the offline (Python) and live (the page's AudioWorklet)
definitions of docs/design.md#spectrogram and #rhythm, read from analysis.json.

The page's build reads the same file (web/src/live-analysis.ts imports it), so the window,
bands, floor, smoothing and onset settings have one source.
"""

from __future__ import annotations

import json
from pathlib import Path

ANALYSIS_FILE = Path(__file__).with_name("analysis.json")
ANALYSIS: dict = json.loads(ANALYSIS_FILE.read_text(encoding="utf-8"))
