"""Batches: many songs × many models from one plan, on local processes or a Ray cluster
(docs/design.md#batch).

`plan` (the TOML plan, checked, expanded into jobs), `names` (safe, unique output names),
`content` (the content keys of inputs and outputs), `record` (the resumable record and the
report), `shared` (prepared inputs shared by every local worker without copying), `work` (what
a worker runs), `engines` (local processes, Ray) and `run` (the driver).
"""
