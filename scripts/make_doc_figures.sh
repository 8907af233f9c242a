#!/usr/bin/env bash
# Renders the manual's figures (doc/Boolean_isosurfacing_3/fig/*.png) from real
# outputs of the tools, on inputs made here or built into the tools (no file
# outside the repository is read).
#
#   bash scripts/make_doc_figures.sh BUILD_DIR [WORK_DIR]
#
# BUILD_DIR holds the built tools (cmake --build BUILD_DIR --target csg contour
# tbiso volume).  WORK_DIR (default a temporary directory) keeps the meshes.
# Needs Debian's /usr/bin/python3 with numpy and matplotlib.  The tools' output
# is printed, so the numbers quoted in the captions can be checked.
set -euo pipefail

if [[ $# -lt 1 ]]; then
  echo "usage: $0 BUILD_DIR [WORK_DIR]" >&2
  exit 2
fi
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
tools="$(cd "$1" && pwd)/tools/Boolean_isosurfacing_3"
work="${2:-$(mktemp -d)}"
mkdir -p "$work"
fig="$root/doc/Boolean_isosurfacing_3/fig"
mkdir -p "$fig"
py=/usr/bin/python3
render() { "$py" "$here/render_mesh.py" "$@"; }
for tool in csg contour tbiso; do
  [[ -x "$tools/$tool" ]] || { echo "$0: $tools/$tool is not built" >&2; exit 1; }
done

# Puts PNGs side by side (each with its title) in one PNG.
side_by_side() {
  local out="$1"; shift
  "$py" - "$out" "$@" <<'EOF'
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
out, items = sys.argv[1], sys.argv[2:]
pairs = list(zip(items[0::2], items[1::2]))
fig, axes = plt.subplots(1, len(pairs), figsize=(3.6 * len(pairs), 3.8))
for ax, (png, title) in zip(axes, pairs):
    ax.imshow(plt.imread(png))
    ax.set_title(title, fontsize=10)
    ax.set_axis_off()
fig.tight_layout()
fig.savefig(out, dpi=100)
EOF
}

# Shrinks a PNG to a palette of 128 colours (they are flat-shaded renders).
shrink() {
  "$py" - "$1" <<'EOF'
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.image as mpimg
import numpy as np
try:
    from PIL import Image
except ImportError:
    sys.exit(0)
img = Image.open(sys.argv[1]).convert("RGB")
img.quantize(colors=128, method=Image.Quantize.MEDIANCUT).save(sys.argv[1], optimize=True)
EOF
}

# ---- inputs made here -------------------------------------------------------
# A CAD-like pair: a plate (box) and a cylinder through it, plus oriented
# samples of a "peanut" (two blended spheres) for the contouring figure.
"$py" - "$work" <<'EOF'
import math, sys
import numpy as np
work = sys.argv[1]

def write_off(path, v, f):
    with open(path, "w") as out:
        out.write(f"OFF\n{len(v)} {len(f)} 0\n")
        for p in v:
            out.write(f"{p[0]:.17g} {p[1]:.17g} {p[2]:.17g}\n")
        for t in f:
            out.write(f"3 {t[0]} {t[1]} {t[2]}\n")

def box(lo, hi):
    v = [(x, y, z) for z in (lo[2], hi[2]) for y in (lo[1], hi[1]) for x in (lo[0], hi[0])]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    f = []
    for a, b, c, d in quads:  # outward, counter-clockwise seen from outside
        f += [(a, b, c), (a, c, d)]
    return v, f

def cylinder(cx, cy, r, z0, z1, n):
    v = [(cx + r * math.cos(2 * math.pi * i / n), cy + r * math.sin(2 * math.pi * i / n), z)
         for z in (z0, z1) for i in range(n)]
    v += [(cx, cy, z0), (cx, cy, z1)]
    b, t = 2 * n, 2 * n + 1
    f = []
    for i in range(n):
        j = (i + 1) % n
        f += [(i, j, n + j), (i, n + j, n + i), (b, j, i), (t, n + i, n + j)]
    return v, f

write_off(f"{work}/plate.off", *box((-1.0, -0.6, -0.2), (1.0, 0.6, 0.2)))
write_off(f"{work}/pin.off", *cylinder(0.35, 0.0, 0.3, -0.5, 0.5, 96))

# The peanut: the zero set of min(|p - a| - 0.6, |p - b| - 0.6) smoothed:
# f(p) = -log(exp(-k d_a) + exp(-k d_b)) / k.  Samples are projected onto it by
# Newton steps along the gradient, which is also the outward normal.
rng = np.random.default_rng(7)
a, b, k = np.array([-0.45, 0, 0]), np.array([0.45, 0, 0]), 6.0
def field(p):
    da = np.linalg.norm(p - a, axis=1) - 0.6
    db = np.linalg.norm(p - b, axis=1) - 0.6
    wa, wb = np.exp(-k * da), np.exp(-k * db)
    f = -np.log(wa + wb) / k
    ga = (p - a) / np.linalg.norm(p - a, axis=1)[:, None]
    gb = (p - b) / np.linalg.norm(p - b, axis=1)[:, None]
    g = (wa[:, None] * ga + wb[:, None] * gb) / (wa + wb)[:, None]
    return f, g
p = rng.normal(size=(6000, 3))
p = p / np.linalg.norm(p, axis=1)[:, None] * np.array([1.1, 0.7, 0.7])
for _ in range(30):
    f, g = field(p)
    p -= (f / np.sum(g * g, axis=1))[:, None] * g
f, g = field(p)
n = g / np.linalg.norm(g, axis=1)[:, None]
with open(f"{work}/peanut.pts", "w") as out:
    for q, m in zip(p, n):
        out.write(f"{q[0]:.9g} {q[1]:.9g} {q[2]:.9g} {m[0]:.9g} {m[1]:.9g} {m[2]:.9g}\n")
print(f"peanut.pts: {len(p)} samples, max |f| {np.abs(f).max():.1e}")

# Samples of the plate turned off the axes, area-uniform with the exact face
# normals, and the same points without normals, for the sharp-feature figure.
lo, hi = np.array([-1.0, -0.6, -0.2]), np.array([1.0, 0.6, 0.2])
c, s, c2, s2 = math.cos(0.5), math.sin(0.5), math.cos(0.3), math.sin(0.3)
turn = np.array([[c, -s, 0], [c2 * s, c2 * c, -s2], [s2 * s, s2 * c, c2]])
faces = []  # (axis, side, u, v, area)
for axis in range(3):
    u, v = [a for a in range(3) if a != axis]
    for side in (0, 1):
        faces.append((axis, side, u, v, (hi[u] - lo[u]) * (hi[v] - lo[v])))
areas = np.array([f[4] for f in faces])
choice = rng.choice(len(faces), size=8000, p=areas / areas.sum())
points, normals = [], []
for i in choice:
    axis, side, u, v, _ = faces[i]
    q = np.empty(3)
    q[axis] = hi[axis] if side else lo[axis]
    q[u] = rng.uniform(lo[u], hi[u])
    q[v] = rng.uniform(lo[v], hi[v])
    m = np.zeros(3)
    m[axis] = 1.0 if side else -1.0
    points.append(turn @ q)
    normals.append(turn @ m)
with open(f"{work}/plate_samples.pts", "w") as out, open(f"{work}/plate_samples_no_normals.pts", "w") as bare:
    for q, m in zip(points, normals):
        out.write(f"{q[0]:.9g} {q[1]:.9g} {q[2]:.9g} {m[0]:.9g} {m[1]:.9g} {m[2]:.9g}\n")
        bare.write(f"{q[0]:.9g} {q[1]:.9g} {q[2]:.9g}\n")
print(f"plate_samples.pts: {len(points)} samples of a turned 2 x 1.2 x 0.4 plate")
EOF

# ---- Marching Cubes CSG: CAD-like and organic pairs --------------------------
echo "== csg: plate minus pin (CAD-like pair)"
"$tools/csg" "$work/plate.off" "$work/pin.off" --op difference --cells 96 -o "$work/plate_minus_pin.off" \
  --creases "$work/plate_minus_pin_creases.txt" --corners "$work/plate_minus_pin_corners.xyz"
render "$work/plate_minus_pin.off" "$work/cad.png" --view 35,-60 --size 4 --zoom 1.4 \
  --creases "$work/plate_minus_pin_creases.txt" --corners "$work/plate_minus_pin_corners.xyz"
echo "== csg: the built-in sphere and torus (organic pair)"
# --demo writes the pair and prints the exact volumes; the figure's meshes are
# the same operations run again with their creases and corners written.
"$tools/csg" --demo "$work/organic" --cells 96
for op in union difference; do
  "$tools/csg" "$work/organic/A_sphere.off" "$work/organic/B_torus.off" --op $op --cells 96 \
    -o "$work/organic_$op.off" --creases "$work/organic_${op}_creases.txt" --corners "$work/organic_${op}_corners.xyz"
done
render "$work/organic_difference.off" "$work/organic_difference.png" --view 25,-15 --size 4 --zoom 1.3 \
  --creases "$work/organic_difference_creases.txt" --corners "$work/organic_difference_corners.xyz"
render "$work/organic_union.off" "$work/organic_union.png" --view 30,-70 --size 4 --zoom 1.3 \
  --creases "$work/organic_union_creases.txt" --corners "$work/organic_union_corners.xyz"
side_by_side "$fig/csg_pairs.png" \
  "$work/cad.png" "plate & !pin (96 cells)" \
  "$work/organic_union.png" "sphere | torus" \
  "$work/organic_difference.png" "sphere & !torus"

echo "== csg: plate minus pin post-processed (--remesh, --simplify)"
# The same pair at 48 cells, with the triangles drawn: as extracted, remeshed
# (edges of r, the creases and the other sharp edges kept) and simplified
# (0.1 r, then flat pairs flipped).
for mode in plain remesh simplify; do
  flag=(); [[ $mode != plain ]] && flag=(--$mode)
  "$tools/csg" "$work/plate.off" "$work/pin.off" --op difference --cells 48 "${flag[@]}" \
    -o "$work/post_$mode.off" --creases "$work/post_${mode}_creases.txt"
  render "$work/post_$mode.off" "$work/post_$mode.png" --view 35,-60 --size 4 --zoom 2.4 --edges \
    --creases "$work/post_${mode}_creases.txt"
done
side_by_side "$fig/csg_post_processing.png" \
  "$work/post_plain.png" "extracted (48 cells)" \
  "$work/post_remesh.png" "--remesh" \
  "$work/post_simplify.png" "--simplify"

# ---- contouring a point set ---------------------------------------------------
echo "== contour: peanut samples"
"$tools/contour" "$work/peanut.pts" -o "$work/peanut.off"
render --points "$work/peanut.pts" "$work/peanut_points.png" --view 25,-60 --size 4 --zoom 1.4
render "$work/peanut.off" "$work/peanut_mesh.png" --view 25,-60 --size 4 --zoom 1.4
side_by_side "$fig/contour_point_set.png" \
  "$work/peanut_points.png" "6,000 oriented samples" \
  "$work/peanut_mesh.png" "contour_point_set() output"

echo "== contour: samples of a plate, without and with their normals"
"$tools/contour" "$work/plate_samples_no_normals.pts" -o "$work/plate_hoppe.off"
"$tools/contour" "$work/plate_samples.pts" -o "$work/plate_sharp.off"
# A close-up of one corner: the faces within 0.3 of it (the corner of the
# turned plate at (1, -0.6, 0.2)).
for name in plate_hoppe plate_sharp; do
  "$py" - "$work/$name.off" "$work/${name}_corner.off" <<'EOF'
import math, sys
import numpy as np
src, dst = sys.argv[1], sys.argv[2]
c, s, c2, s2 = math.cos(0.5), math.sin(0.5), math.cos(0.3), math.sin(0.3)
corner = np.array([[c, -s, 0], [c2 * s, c2 * c, -s2], [s2 * s, s2 * c, c2]]) @ np.array([1.0, -0.6, 0.2])
with open(src) as f:
    f.readline()
    rows = (r for r in (line.split() for line in f) if r and not r[0].startswith("#"))
    nv, nf = map(int, next(rows)[:2])
    v = np.array([list(map(float, next(rows)[:3])) for _ in range(nv)])
    faces = [list(map(int, next(rows)[1:4])) for _ in range(nf)]
keep = [t for t in faces if np.linalg.norm(v[t].mean(axis=0) - corner) < 0.3]
used = sorted({i for t in keep for i in t})
index = {i: k for k, i in enumerate(used)}
with open(dst, "w") as out:
    out.write(f"OFF\n{len(used)} {len(keep)} 0\n")
    for i in used:
        out.write(f"{v[i][0]:.17g} {v[i][1]:.17g} {v[i][2]:.17g}\n")
    for t in keep:
        out.write(f"3 {index[t[0]]} {index[t[1]]} {index[t[2]]}\n")
EOF
  render "$work/${name}_corner.off" "$work/$name.png" --view 40,-20 --size 4 --zoom 1.2 --edges
done
side_by_side "$fig/contour_sharp_features.png" \
  "$work/plate_hoppe.png" "a corner, without normals" \
  "$work/plate_sharp.png" "the same, with normals"
shrink "$fig/contour_sharp_features.png"

# ---- TBISO and its crease network ---------------------------------------------
echo "== tbiso: at least two of four spheres (the demo)"
"$tools/tbiso" --demo "$work/tbiso"
render "$work/tbiso/tbiso_demo.ply" "$fig/tbiso_creases.png" \
  --creases "$work/tbiso/tbiso_demo_creases.polylines.txt" --corners "$work/tbiso/tbiso_demo_corners.xyz" \
  --view 25,-50 --size 5 --zoom 1.3

# ---- crease-preserving smoothing, before and after -----------------------------
# A sampled field with noise (a sphere's distance plus uniform noise of 0.3
# grid steps), cut by two exact planes: the extracted sphere patch is bumpy,
# smoothing removes the bumps and keeps the two creases and their corners.
echo "== tbiso: smoothing before / after (noisy sampled sphere, two planes)"
"$py" - "$work/noisy.f64" <<'EOF'
import sys
import numpy as np
n = 48
t = np.linspace(-1, 1, n)
z, y, x = np.meshgrid(t, t, t, indexing="ij")  # x fastest: vertex i + n (j + n k)
h = 2 / (n - 1)
noise = np.random.default_rng(3).uniform(-0.3 * h, 0.3 * h, size=x.shape)
f0 = np.sqrt(x * x + y * y + z * z) - 0.8 + noise
np.stack([f0, z - 0.35, x - 0.4], axis=-1).astype("<f8").tofile(sys.argv[1])
EOF
fields=(--cells 47 --fields "$work/noisy.f64" --field-count 3 --expr "f0 & f1 & f2")
"$tools/tbiso" "${fields[@]}" -o "$work/raw.ply" --creases "$work/raw_creases.txt" --corners "$work/raw_corners.xyz"
"$tools/tbiso" "${fields[@]}" --smooth 20 -o "$work/smooth.ply" \
  --creases "$work/smooth_creases.txt" --corners "$work/smooth_corners.xyz"
for s in raw smooth; do
  render "$work/$s.ply" "$work/$s.png" --creases "$work/${s}_creases.txt" --corners "$work/${s}_corners.xyz" \
    --view 15,-110 --size 4 --zoom 1.25
done
side_by_side "$fig/smoothing.png" \
  "$work/raw.png" "extracted (48^3 grid, noisy field)" \
  "$work/smooth.png" "smooth_with_creases(), 20 iterations"

for png in "$fig"/*.png; do shrink "$png"; done
ls -l "$fig"
echo "meshes in $work"
