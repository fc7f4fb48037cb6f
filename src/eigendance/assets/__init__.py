"""Reading models as artists have them: every mesh node, rig and material of a file.

Modules: `appearance` (the data model of a model's look: materials, images, drawn vertices and
the drawn → welded index map), `gltf` (a glTF 2.0 document: buffers, accessors, Draco, images),
`scene` (the default scene's mesh nodes with their world transforms, skins and meshes attached
to bones), `materials` (glTF and trimesh materials as `Material`), `other_formats` (OBJ with its
MTL, PLY colours, OFF, STL through trimesh; files to convert through Blender), `model` (`Model`,
a file as drawn, and `combine`), `reader` (`read_model`, one entry for every format). See
docs/design.md#appearance.
"""
