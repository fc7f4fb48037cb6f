"""The music pipeline shared by both halves: decoding → Spectrogram → Mapping → gallery, breeding.

Modules: `decode` (any audio file to mono PCM), `spectrogram` (banded loudness), `mapping`
(transfer, amplification and the filter φ), `dancer` (what a gallery needs of a model, and how
much a mapping moves it), `gallery` (the initial gallery), `breeding` (the next generation),
`demo_music` (the built-in track). See docs/design.md#music-pipeline.
"""
