"""What Open3D's watertight check says of shadowvol's volumes (README, "Volume mesh"): the default
scene's exact-cap volume at 256^2, unrefined and refined (refine 6), as double arrays, read back
from a float PLY and from a double PLY. Needs Debian's python3-open3d.

    PYTHONPATH=build/python /usr/bin/python3 scripts/open3d_watertight.py
"""

import tempfile
from pathlib import Path

import numpy as np
import open3d as o3d

import shadowvol as sv


def describe(mesh):
    pairs = len(np.asarray(mesh.get_self_intersecting_triangles()))
    return (f"watertight {mesh.is_watertight()}, edge manifold {mesh.is_edge_manifold()}, "
            f"vertex manifold {mesh.is_vertex_manifold()}, self-intersecting pairs {pairs}")


def main():
    scene = sv.default_scene()
    depth = sv.capture_depth(scene, 256, 256)
    with tempfile.TemporaryDirectory() as tmp:
        for refine in (0, 6):
            V, F, _ = sv.build_volume(depth, refine=refine, scene=scene)
            arrays = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(V), o3d.utility.Vector3iVector(F))
            print(f"refine {refine}, double arrays: {describe(arrays)}")
            for double in (False, True):
                path = Path(tmp) / "v.ply"
                sv.export(V, F, path, double_precision=double)
                read = o3d.io.read_triangle_mesh(str(path))
                print(f"refine {refine}, {'double' if double else 'float'} PLY: {describe(read)}")


if __name__ == "__main__":
    main()
