"""The harmonic pipeline: mesh → Laplacian (L, M) → eigensolver → HarmonicBasis → motion.

Modules: `mesh` (load, check, clean, normalise), `contacts` (where pieces touch),
`laplacian` (L and M, pieces coupled), `lanczos` and
`eigensolver` (the k lowest eigenpairs, band by band), `cache` (a disk cache of arrays), `basis`
(HarmonicBasis), `deform` (X + U((φ − 1) ⊙ X̃)), `motion` (positions over a song).
See docs/design.md#harmonic-pipeline.
"""
