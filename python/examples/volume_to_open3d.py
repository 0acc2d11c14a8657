"""A shadow volume handed to Open3D (or trimesh), straight from numpy arrays.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/volume_to_open3d.py [scene.json] [out.ply]

Captures the light's depth map (Embree), builds the refined volume, and checks it with Open3D's
mesh predicates when Open3D is installed (Debian: python3-open3d), else with trimesh; the signed
volume comes from numpy. Writes the volume in double precision (default: shadow_volume.ply).
"""

import sys

import numpy as np

import shadowvol as sv


def main():
    scene = sv.load_scene(sys.argv[1]) if len(sys.argv) > 1 else sv.default_scene()
    out = sys.argv[2] if len(sys.argv) > 2 else "shadow_volume.ply"
    depth = sv.capture_depth(scene, 256, 256, capture="back")
    V, F, stats = sv.build_volume(depth, refine=6, scene=scene)
    print(f"{scene.source}: {len(V)} vertices, {len(F)} triangles, {stats['raysCast']} refinement rays, "
          f"{stats['ms']['total']:.1f} ms")
    sv.export(V, F, out, double_precision=True)
    a, b, c = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    print(f"signed volume {np.einsum('ij,ij->i', a, np.cross(b, c)).sum() / 6:.4f} (positive: outward)")
    try:
        import open3d as o3d

        mesh = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(V), o3d.utility.Vector3iVector(F))
        # Not is_watertight(): it adds Open3D's tolerance-based self-intersection test, which
        # reports the long, nearly parallel walls of refined volumes that exact arithmetic finds
        # apart (README "Python module").
        print(f"Open3D {o3d.__version__}: edge manifold {mesh.is_edge_manifold()}, "
              f"vertex manifold {mesh.is_vertex_manifold()}, orientable {mesh.is_orientable()}")
    except ImportError:
        try:
            import trimesh

            mesh = trimesh.Trimesh(vertices=V, faces=F, process=False)
            print(f"trimesh: watertight {mesh.is_watertight}, winding consistent {mesh.is_winding_consistent}")
        except ImportError:
            print("neither Open3D nor trimesh is installed (Debian: python3-open3d)")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
