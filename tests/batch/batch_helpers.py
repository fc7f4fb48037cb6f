"""Helpers of the batch tests: songs made here, plans written from Python values, the writers
holding locks on temporary files."""

import os

import numpy as np
import soundfile


def song(path, seconds=2.0, rate=22050, seed=0):
    """A song of `seconds`: tones whose loudness pulses at a beat, so every band moves."""
    t = np.arange(int(seconds * rate)) / rate
    rng = np.random.default_rng(seed)
    pulse = 0.5 + 0.5 * np.sin(2 * np.pi * (2 + seed) * t) ** 2
    tones = sum(np.sin(2 * np.pi * f * t + rng.uniform(0, 6)) for f in (110, 440, 1760, 7040))
    soundfile.write(path, (0.2 * pulse * tones).astype(np.float32), rate)
    return path


def write_plan(folder, **settings) -> str:
    """plan.toml in `folder`, from TOML values written as Python literals."""
    lines = []
    for key, value in settings.items():
        text = value if isinstance(value, str) and value.startswith("@") else repr(value)
        lines.append(f"{key} = {text.lstrip('@')}".replace("'", '"'))
    path = os.path.join(folder, "plan.toml")
    with open(path, "w") as file:
        file.write("\n".join(lines) + "\n")
    return path


def lock_holders(folder) -> dict[str, int]:
    """{temporary file in `folder`: pid of the process holding its lock} (Linux /proc/locks)."""
    inodes = {}
    for name in os.listdir(folder):
        if name.startswith(".eigendance-"):
            try:
                inodes[os.stat(os.path.join(folder, name)).st_ino] = name
            except OSError:
                pass
    holders = {}
    with open("/proc/locks") as file:
        for line in file:
            fields = line.split()
            if "FLOCK" in fields:
                pid, device = int(fields[4]), fields[5]
                inode = int(device.split(":")[-1])
                if inode in inodes:
                    holders[inodes[inode]] = pid
    return holders


def temporaries(folder) -> list[str]:
    """The temporary files of writers in `folder` (none must be left)."""
    return [name for name in os.listdir(folder) if name.startswith(".eigendance-")]
