"""Show mode: a set list of cues, the state every control changes, OSC in and out and Ableton
Link (docs/design.md#show)."""
