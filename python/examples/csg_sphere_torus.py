#!/usr/bin/env python3
"""The README's main job in Python: Marching Cubes CSG of a sphere and a torus
that cuts through it (union, intersection, difference), with the volumes, and
a picture of the three results.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/csg_sphere_torus.py [--cells 128] [-o csg.png]

The sphere and the torus are the csg tool's demo pair (`csg --demo`): an
icosphere of radius 1 (4 subdivisions, 5120 triangles) and a torus centred at
(0.9, 0, 0) with radii 0.8 and 0.35 (96 x 48 segments, 9216 triangles).
"""

import argparse
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

import boolean_isosurfacing as bi  # noqa: E402


def shaded(ax, V, F, colour):
    """Draws the triangles with a simple Lambert shading (a fixed light)."""
    T = V[F]
    n = np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0])
    n /= np.linalg.norm(n, axis=1, keepdims=True) + 1e-300
    light = np.array([0.4, -0.5, 0.75])
    light /= np.linalg.norm(light)
    intensity = 0.25 + 0.75 * np.clip(n @ light, 0, 1)
    colours = np.clip(np.outer(intensity, colour), 0, 1)
    ax.add_collection3d(Poly3DCollection(T, facecolors=colours, edgecolors="none", linewidths=0))
    # the bounding box of the pair, equal scales on the three axes
    ax.set_xlim(-1.05, 2.1)
    ax.set_ylim(-1.2, 1.2)
    ax.set_zlim(-1.05, 1.05)
    ax.set_box_aspect((3.15, 2.4, 2.1), zoom=1.45)
    ax.view_init(elev=32, azim=-58)
    ax.set_axis_off()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cells", type=int, default=128, help="lattice cells along the longest side (default 128)")
    parser.add_argument("-o", "--output", default="csg_sphere_torus.png", help="picture file (default %(default)s)")
    args = parser.parse_args()

    sphere = bi.icosphere((0, 0, 0), 1.0, 4)
    torus = bi.torus((0.9, 0, 0), 0.8, 0.35, 96, 48)
    print(f"Marching Cubes CSG of a sphere (A, {len(sphere[1])} triangles) and a torus through it "
          f"(B, {len(torus[1])} triangles), {args.cells} cells, TBB {'on' if bi.parallel else 'off'}")
    print(f"  input volumes: sphere {bi.surveyor_volume(*sphere):.6f}, torus {bi.surveyor_volume(*torus):.6f}\n")

    fig = plt.figure(figsize=(13.5, 4.6))
    colours = {"union": (0.35, 0.6, 0.95), "intersection": (0.95, 0.55, 0.3), "difference": (0.45, 0.8, 0.45)}
    for k, op in enumerate(("union", "intersection", "difference")):
        start = time.perf_counter()
        V, F, info = bi.csg([sphere, torus], op, cells=args.cells)
        seconds = time.perf_counter() - start
        volume = bi.surveyor_volume(V, F)
        n = info["lattice_points"]
        print(f"{op} ({info['expression']})")
        print(f"  lattice {n[0]} x {n[1]} x {n[2]} points, spacing {info['spacing']:.6g}")
        print(f"  classification {info['seconds_classification']:.3f} s, edge points {info['seconds_edges']:.3f} s, "
              f"triangulation {info['seconds_triangulation']:.3f} s ({info['crossings']} crossings), "
              f"call {seconds:.3f} s")
        print(f"  output {len(V)} vertices, {len(F)} triangles, {'closed' if info['closed'] else 'OPEN'}")
        print(f"  volume {volume:.6f}\n")
        ax = fig.add_subplot(1, 3, k + 1, projection="3d")
        shaded(ax, V, F, np.array(colours[op]))
        ax.set_title(f"{op}  ({info['expression']})\nvolume {volume:.4f}, {len(F)} triangles", fontsize=11, pad=0)
    fig.subplots_adjust(left=0, right=1, bottom=0, top=0.88, wspace=0)
    fig.savefig(args.output, dpi=110)
    print(f"picture: {args.output}")


if __name__ == "__main__":
    main()
