"""Boolean Isosurfacing for CGAL, on numpy arrays.

Four capabilities of the C++ package, with the GIL released and TBB threads
where the library runs in parallel:

- ``surveyor_volume(V, F)``: certified volume of a closed triangle mesh;
- ``csg(meshes, expr, cells=None, spacing=None)``: Marching Cubes CSG of
  closed meshes, exact classification, N-ary Boolean expressions;
- ``contour(points, normals=None)``: Hoppe's contouring of point samples;
- ``boolean_isosurface(fields=..., expr=..., grid=... | mesh=...)``: TBISO,
  exact Boolean isosurfaces of scalar fields with creases and corners;

plus ``smooth_with_creases``, ``crease_network`` and the readers and writers
of meshes, point samples, ``.tris``, tetrahedral meshes, scalar fields and
labelled PLY surfaces.

Input errors raise ``InvalidInputError`` (a ``ValueError``) or one of its
subclasses with the library's message; files that cannot be opened raise
``OSError``.
"""

from ._core import (  # noqa: F401
    EmptyInputError,
    InvalidInputError,
    InwardOrientedMeshError,
    LatticeTooLargeError,
    NonFiniteValueError,
    NonTriangleFaceError,
    OpenMeshError,
    ParseError,
    SelfIntersectingMeshError,
    boolean_isosurface,
    contour,
    crease_network,
    csg,
    grid_points,
    icosphere,
    parallel,
    read_fields,
    read_isosurface_ply,
    read_mesh,
    read_points,
    read_tetrahedral_mesh,
    read_tris,
    smooth_with_creases,
    surveyor_volume,
    torus,
    taubin_default_lambda,
    taubin_default_mu,
    taubin_default_number_of_iterations,
    write_corners,
    write_creases,
    write_fields,
    write_isosurface_ply,
    write_mesh,
    write_points,
    write_tetrahedral_mesh,
    write_tris,
)

__version__ = "0.1.0"


def triangulate(polygons, labels=None):
    """Fan-triangulates convex polygons (as returned by ``boolean_isosurface``).

    Returns ``F``, an (m, 3) int64 array, or ``(F, face_labels)`` when
    ``labels`` is given (each triangle carries its polygon's label).
    Polygon p with vertices v0 ... vk gives the triangles (v0, vi, vi+1), in
    order, so F is ordered by polygon.
    """
    import numpy as np

    if isinstance(polygons, np.ndarray) and polygons.ndim == 2:
        polygons = list(polygons)
    lengths = np.fromiter((len(p) for p in polygons), dtype=np.int64, count=len(polygons))
    if np.any(lengths < 3):
        p = int(np.argmax(lengths < 3))
        raise ValueError(f"polygons[{p}] has {lengths[p]} vertices; a polygon needs at least 3")
    flat = (np.concatenate([np.asarray(p, dtype=np.int64).ravel() for p in polygons])
            if len(polygons) else np.empty(0, dtype=np.int64))
    starts = np.cumsum(lengths) - lengths
    fans = lengths - 2
    owner = np.repeat(np.arange(len(polygons)), fans)
    # position of each triangle inside its polygon's fan: 0, 1, ..., k - 3
    within = np.arange(len(owner)) - np.repeat(np.cumsum(fans) - fans, fans)
    first = starts[owner]
    F = np.stack([flat[first], flat[first + 1 + within], flat[first + 2 + within]], axis=1)
    if labels is None:
        return F
    labels = np.asarray(labels)
    if len(labels) != len(polygons):
        raise ValueError(f"labels has {len(labels)} entries but there are {len(polygons)} polygons")
    return F, labels[owner]


__all__ = [name for name in dir() if not name.startswith("_")]
