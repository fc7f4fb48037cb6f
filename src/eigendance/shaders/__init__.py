"""The GLSL both renderers compile (the `.glsl` files of this folder), and the rule from a
material to it (`shaders.programs`), docs/design.md#rendering."""
