"""The inputs layer: what a file given to eigendance is, checked and read once
(docs/design.md#inputs).

One module per input kind, shaped like librosa's `valid_audio` or potpourri3d's `validate_mesh`:
`model` (a mesh, its harmonics' `HarmonicProblem`, or a rig: one rule by content), `song` (an
audio file or a spectrogram file), `mapping` (a mapping file or document, and the basis it was
made on). `defaults` declares the one default k and fps of every command and of the server.
The command line, the server and the batch read their inputs through these modules only; each
documents what it raises.
"""
