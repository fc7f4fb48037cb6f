"""Presets: named dances kept in a folder the user can back up (docs/design.md#presets).

A preset is a mapping (or a rig's palette) with its look, tags, a favourite mark and a
thumbnail. `presets.store` keeps them (one JSON file per preset, written atomically, and its
PNG); `presets.resample` makes a preset made on one model fit another (harmonics by frequency,
modes by rank).
"""
