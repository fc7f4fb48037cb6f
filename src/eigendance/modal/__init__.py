"""The modal pipeline: rig → Skeleton → ModalModel → motion → skinning, behind one `Rig`.

Modules: `skeleton` (the `Skeleton` and its edits), `bodies` (bodies, joints, their frames and
ranges), `stiffness` (the default joint stiffness), `skeleton_file` (the skeleton JSON),
`gltf_skin` (glTF 2.0 skins as skeletons), `sample_rigs` (built-in rigs, `load_rig`), `model`
(G, N, R, M, K and the vibration modes), `rotations` (exp map), `palette` (the modes that play
and the default rule), `motion` (music-driven coefficients, body poses), `skinning` (modal and
linear blend skinning), `rig` (the `Rig` every caller queries), `rig_gallery` (the modes as a
gallery dancer). See docs/design.md#modal-pipeline.
"""
