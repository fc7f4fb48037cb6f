"""The modal pipeline: rig → Skeleton → ModalModel → motion → skinning.

Modules: `skeleton` (bodies, joints, skeleton JSON), `gltf_skin` (glTF 2.0 skins as skeletons),
`sample_rigs` (built-in rigs, `load_rig`), `model` (G, N, R, M, K and the vibration modes),
`rotations` (exp map), `motion` (music-driven coefficients, body poses), `skinning` (modal and
linear blend skinning). See docs/design.md#modal-pipeline.
"""
