"""Exports of the motion to files other tools open and to videos (docs/design.md#exports).

Modules: `dance` (what moves: `HarmonicDance`, `RigDance`, and `Dance.window`, a part of the
song), `files` (`export_dance`: glTF, point cache or USD with the song beside), `gltf`,
`pointcache`, `usd` (the formats), `song` (the song beside, whole or cut to the window),
`renderer` and `video` (the MP4), `output` (all or nothing).
"""
