#!/usr/bin/python3
"""Renders an OFF or ASCII PLY polygon mesh to a PNG with matplotlib.

Faces are coloured by the PLY `field` label (grey for -1, the faces closing
the set on the domain boundary) and shaded by their normal; crease polylines
(CGAL polylines text, as `tbiso --creases` writes) and corners (`x y z` lines)
can be drawn on top.

  /usr/bin/python3 scripts/render_mesh.py MESH.ply OUT.png [--creases F] [--corners F]
                   [--view ELEV,AZIM] [--up x|y|z] [--size INCHES] [--zoom Z] [--title T]
  /usr/bin/python3 scripts/render_mesh.py --points SAMPLES.pts OUT.png [...]

With --points the input is a point set (`x y z [nx ny nz]` lines, as `contour`
reads), drawn as dots; --edges draws the mesh edges (to show the facets).
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402


def read_mesh(path):
    with open(path) as f:
        first = f.readline().strip()
        labels = None
        if first == "OFF":
            line = f.readline().split()
            while not line or line[0].startswith("#"):
                line = f.readline().split()
            nv, nf = int(line[0]), int(line[1])
            # CGAL's writer puts a blank line after the counts: skip blank lines.
            rows = (r for r in (line.split() for line in f) if r and not r[0].startswith("#"))
            points = np.array([list(map(float, next(rows)[:3])) for _ in range(nv)])
            faces = []
            for _ in range(nf):
                t = next(rows)
                faces.append(list(map(int, t[1 : 1 + int(t[0])])))
            return points, faces, labels
        if first != "ply":
            raise SystemExit(f"{path}: not an OFF or PLY file")
        nv = nf = 0
        face_properties = []
        element = None
        while True:
            line = f.readline().split()
            if not line:
                continue
            if line[0] == "format" and line[1] != "ascii":
                raise SystemExit(f"{path}: only ASCII PLY is supported")
            if line[0] == "element":
                element = line[1]
                if element == "vertex":
                    nv = int(line[2])
                elif element == "face":
                    nf = int(line[2])
            if line[0] == "property" and element == "face":
                face_properties.append(line[-1])
            if line[0] == "end_header":
                break
        points = np.array([list(map(float, f.readline().split()[:3])) for _ in range(nv)])
        faces, labels = [], []
        has_field = "field" in face_properties
        for _ in range(nf):
            t = f.readline().split()
            n = int(t[0])
            faces.append(list(map(int, t[1 : 1 + n])))
            if has_field:
                labels.append(int(t[1 + n + face_properties[1:].index("field")]))
        return points, faces, (labels if has_field else None)


def read_polylines(path):
    lines = []
    for line in open(path):
        v = list(map(float, line.split()))
        if v:
            lines.append(np.array(v[1:]).reshape(-1, 3))
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("mesh", nargs="?")
    parser.add_argument("png")
    parser.add_argument("--creases")
    parser.add_argument("--corners")
    parser.add_argument("--view", default="25,-60")
    parser.add_argument("--up", default="z", choices="xyz", help="the axis drawn upwards")
    parser.add_argument("--points", help="draw this point set instead of a mesh")
    parser.add_argument("--edges", action="store_true", help="draw the mesh edges")
    parser.add_argument("--size", type=float, default=8, help="figure size in inches (100 dpi)")
    parser.add_argument("--title")
    parser.add_argument("--zoom", type=float, default=1.0, help="magnify the scene (matplotlib >= 3.6)")
    args = parser.parse_args()
    if (args.mesh is None) == (args.points is None):
        parser.error("give either a MESH or --points")
    # A cyclic permutation of the axes that puts `up` last (keeps orientation).
    order = {"x": [1, 2, 0], "y": [2, 0, 1], "z": [0, 1, 2]}[args.up]
    if args.points:
        points = np.array([list(map(float, line.split()[:3])) for line in open(args.points) if line.split()])
        faces, labels = [], None
    else:
        points, faces, labels = read_mesh(args.mesh)
    points = points[:, order]
    polygons = [points[f] for f in faces]
    palette = plt.get_cmap("tab10")
    light = np.array([0.3, -0.5, 0.8])
    light /= np.linalg.norm(light)
    colours = []
    for i, q in enumerate(polygons):
        n = np.zeros(3)
        for k in range(1, len(q) - 1):
            n += np.cross(q[k] - q[0], q[k + 1] - q[0])
        n /= max(np.linalg.norm(n), 1e-300)
        shade = 0.35 + 0.65 * abs(float(n @ light))
        label = labels[i] if labels else 0
        base = np.array([0.6, 0.6, 0.6]) if label < 0 else np.array(palette(label % 10)[:3])
        colours.append(np.clip(base * shade, 0, 1))
    fig = plt.figure(figsize=(args.size, args.size))
    ax = fig.add_subplot(projection="3d")
    if args.points:
        ax.scatter(points[:, 0], points[:, 1], points[:, 2], color="#1f77b4", s=1.5, depthshade=True, linewidths=0)
    else:
        edges = dict(edgecolors=(0, 0, 0, 0.35), linewidths=0.2) if args.edges else dict(edgecolors="none")
        ax.add_collection3d(Poly3DCollection(polygons, facecolors=colours, **edges))
    if args.title:
        ax.set_title(args.title)
    if args.creases:
        lines = [line[:, order] for line in read_polylines(args.creases)]
        ax.add_collection3d(Line3DCollection(lines, colors="k", linewidths=1.5))
    if args.corners:
        c = np.array([list(map(float, line.split())) for line in open(args.corners) if line.split()])
        if c.size:
            c = c[:, order]
            # Drawn last and on top (matplotlib's depth sort would hide the
            # corners, which lie on the surface, behind its polygons).
            ax.computed_zorder = False
            ax.scatter(c[:, 0], c[:, 1], c[:, 2], color="red", s=30, depthshade=False, zorder=10)
    lo, hi = points.min(0), points.max(0)
    centre, half = (lo + hi) / 2, (hi - lo).max() / 2
    for axis, set_lim in zip(range(3), (ax.set_xlim, ax.set_ylim, ax.set_zlim)):
        set_lim(centre[axis] - half, centre[axis] + half)
    elev, azim = map(float, args.view.split(","))
    ax.view_init(elev=elev, azim=azim)
    if args.zoom != 1.0:
        ax.set_box_aspect((1, 1, 1), zoom=args.zoom)
    else:
        ax.set_box_aspect((1, 1, 1))
    ax.set_axis_off()
    fig.savefig(args.png, dpi=100, bbox_inches="tight")


if __name__ == "__main__":
    main()
