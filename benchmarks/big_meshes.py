"""Large meshes for the benchmarks of the reduced basis (bench_reduced, bench_web, bench_render):
a shared scan subdivided (midpoint, 4× the triangles per step) and moved along its normals by
Gaussian noise of a tenth of the mean edge length, so that it has detail at every scale. The
messy ones (ogre, beetle) are subdivided as the file holds them, so that their defects
(degenerate and repeated faces, non-manifold edges, loose vertices) grow with them.

The meshes are built once and kept as .npz in $EIGENDANCE_BENCH_MESHES (default
/tmp/eigendance-bench-meshes).
"""

from __future__ import annotations

import os

import numpy as np

from shared_data import shared_path

FOLDER = os.environ.get("EIGENDANCE_BENCH_MESHES", "/tmp/eigendance-bench-meshes")
NOISE = 0.1  # of the mean edge length, along the vertex normals
MESSY = ("ogre.obj", "beetle.obj")

# name: (shared mesh, subdivisions) with the vertex count it gives
MESHES = {
    "armadillo-173k": ("armadillo.obj", 1),      # 172,966 v, closed scan
    "camelhead-182k": ("camelhead.off", 2),      # 181,941 v, open boundary
    "ogre-248k": ("ogre.obj", 1),                # 44 parts, degenerate faces
    "cat-508k": ("cat_lowres.obj", 3),           # 508,674 v
    "armadillo-692k": ("armadillo.obj", 2),      # 691,858 v
    "fertility-1.15M": ("fertility.off", 4),     # 1,151,994 v, genus 4
    "ogre-995k": ("ogre.obj", 2),                # many parts and degenerate faces at 1 M
    "lionstatue-127k": ("lionstatue.obj", 1),
    "bunny-139k": ("bunny_stanford.obj", 1),
    "bunny-557k": ("bunny_stanford.obj", 2),
    "beetle-294k": ("beetle.obj", 4),            # non-manifold edges, 2 parts
}


def detailed(name: str, seed: int = 0):
    """(vertices, faces) of MESHES[name], noise drawn with `seed` (another seed: the same shape
    with other detail of the same size)."""
    path = os.path.join(FOLDER, f"{name}-{seed}.npz")
    if os.path.exists(path):
        with np.load(path) as data:
            return data["vertices"], data["faces"]
    import trimesh

    from eigendance.harmonic.mesh import load_mesh

    source, steps = MESHES[name]
    if source in MESSY:  # as the file holds it: its defects are what is being measured
        loaded = trimesh.load(shared_path("meshes", source), force="mesh", process=False)
        vertices, faces = np.asarray(loaded.vertices), np.asarray(loaded.faces)
    else:
        mesh = load_mesh(shared_path("meshes", source))
        vertices, faces = mesh.original_vertices, mesh.faces
    for _ in range(steps):
        vertices, faces = trimesh.remesh.subdivide(vertices, faces)
    surface = trimesh.Trimesh(vertices, faces, process=False)
    edge = float(surface.edges_unique_length.mean())
    shift = np.random.default_rng(seed).normal(0.0, NOISE * edge, len(vertices))
    vertices = vertices + surface.vertex_normals * shift[:, None]
    os.makedirs(FOLDER, exist_ok=True)
    np.savez(path + ".part.npz", vertices=vertices, faces=faces)
    os.replace(path + ".part.npz", path)
    return vertices, faces


def detailed_obj(name: str, seed: int = 0) -> str:
    """The mesh written as an OBJ file (for the command line and the server), built once."""
    path = os.path.join(FOLDER, f"{name}-{seed}.obj")
    if not os.path.exists(path):
        vertices, faces = detailed(name, seed)
        with open(path + ".part", "w") as file:
            np.savetxt(file, vertices, fmt="v %.7g %.7g %.7g")
            np.savetxt(file, faces + 1, fmt="f %d %d %d")
        os.replace(path + ".part", path)
    return path
