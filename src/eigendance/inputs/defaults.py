"""The defaults every front end shares: `serve`, `demo`, `animate`, `render`, `export`,
`gallery`, `basis` and `batch` (docs/design.md#defaults).

k = 150 harmonics: what the page solves and plays, so that a mapping made in the page dances
the same under the command line without a second solve; the page's eight tiles stay
interactive with it (the gallery of the bunny at k = 300 draws 4.9 frames/s against the cat's
13.2 at k = 150 in headless Chromium) and a solve takes half the time and memory of k = 300.
A mapping records the k it was made on (`inputs.mapping`), which wins over this default.
"""

DEFAULT_K = 150  # harmonics of a mesh's basis
DEFAULT_FPS = 30.0  # frames per second of animations, exports, videos
