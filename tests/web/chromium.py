"""Headless Chromium as the browser tests and the browser benchmarks launch it: its path and its
flags, in one place (the benchmarks put this folder on their path)."""

from __future__ import annotations

CHROMIUM = "/usr/bin/chromium"  # Playwright cannot download its own browser here
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run"]
AUTOPLAY = ["--autoplay-policy=no-user-gesture-required"]  # sound without a click
FAKE = ["--use-fake-device-for-media-stream", *AUTOPLAY]  # a fake microphone (and autoplay)
GRANT = "--use-fake-ui-for-media-stream"  # the microphone allowed without asking


def launch(browser_type, *flags: str):
    """Chromium launched by Playwright's `browser_type` (`playwright.chromium`) with the flags
    above and `flags` (e.g. AUTOPLAY, FAKE, `--use-file-for-fake-audio-capture=…`)."""
    return browser_type.launch(executable_path=CHROMIUM, args=[*CHROMIUM_ARGS, *flags])
