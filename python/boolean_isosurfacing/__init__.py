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
    """
    import numpy as np

    rows = []
    owners = []
    for p, poly in enumerate(polygons):
        poly = np.asarray(poly, dtype=np.int64)
        if poly.ndim != 1 or len(poly) < 3:
            raise ValueError(f"polygons[{p}] is not a polygon of at least 3 vertices")
        k = len(poly) - 2
        fan = np.empty((k, 3), dtype=np.int64)
        fan[:, 0] = poly[0]
        fan[:, 1] = poly[1:-1]
        fan[:, 2] = poly[2:]
        rows.append(fan)
        owners.append(np.full(k, p, dtype=np.int64))
    F = np.concatenate(rows) if rows else np.empty((0, 3), dtype=np.int64)
    if labels is None:
        return F
    labels = np.asarray(labels)
    if len(labels) != len(polygons):
        raise ValueError(f"labels has {len(labels)} entries but there are {len(polygons)} polygons")
    owner = np.concatenate(owners) if owners else np.empty(0, dtype=np.int64)
    return F, labels[owner]


__all__ = [name for name in dir() if not name.startswith("_")]
