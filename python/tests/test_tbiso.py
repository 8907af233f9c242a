"""TBISO on grids and tetrahedral meshes: exact results in the singular cases
(zero sets on grid layers), volumes converging, closed and oriented output,
creases and corners, smoothing keeping them, and bad input raising."""

import itertools
import math

import numpy as np
import pytest

import boolean_isosurfacing as bi
from conftest import assert_closed_oriented, edge_report

BOX = (-1.0, -1.0, -1.0, 1.0, 1.0, 1.0)


def half_space_fields(P, h=0.5):
    """Six fields whose zero sets are the planes x, y, z = +-h; with h = 0.5
    on a 5^3 grid of [-1, 1]^3 they lie exactly on grid layers."""
    x, y, z = P[:, 0], P[:, 1], P[:, 2]
    return np.stack([x - h, -x - h, y - h, -y - h, z - h, -z - h], axis=1)


def test_grid_points_are_x_fastest():
    P = bi.grid_points((3, 4, 5), (0, 0, 0, 2, 3, 4))
    assert P.shape == (60, 3)
    assert np.array_equal(P[1], [1, 0, 0]) and np.array_equal(P[3], [0, 1, 0]) and np.array_equal(P[12], [0, 0, 1])
    assert np.array_equal(P[-1], [2, 3, 4])


def test_cube_of_planes_on_grid_layers_is_exact():
    grid = (5, 5, 5)
    P = bi.grid_points(grid, BOX)
    V, polygons, labels, creases, corners, info = bi.boolean_isosurface(
        grid=grid, box=BOX, fields=half_space_fields(P), expr="f0 & f1 & f2 & f3 & f4 & f5")
    assert info["closed"]
    assert_closed_oriented(polygons)
    assert info["volume"] == pytest.approx(1.0, abs=1e-14)
    # every vertex on the surface of the cube [-0.5, 0.5]^3, exactly
    assert np.all(np.max(np.abs(V), axis=1) == 0.5)
    # one label per face of the cube, on the polygons of that face
    assert sorted(set(labels.tolist())) == [0, 1, 2, 3, 4, 5]
    for p, l in zip(polygons, labels):
        axis, sign = divmod(int(l), 2)
        assert np.all(V[p, axis] == (0.5 if sign == 0 else -0.5))
    # 8 corners exactly at the cube's corners, 12 crease polylines between them
    expected = {c for c in itertools.product((-0.5, 0.5), repeat=3)}
    assert {tuple(V[c]) for c in corners} == expected
    assert len(creases) == 12
    for line in creases:
        assert line[0] in corners and line[-1] in corners
        ends = V[[line[0], line[-1]]]
        assert np.sum(ends[0] != ends[1]) == 1  # along one axis: a cube edge


def test_close_at_domain_boundary_gives_the_exact_half_box():
    grid = (5, 5, 5)
    P = bi.grid_points(grid, BOX)
    f = (P[:, 0] - 0.5)[:, None]
    V, polygons, labels, creases, corners, info = bi.boolean_isosurface(grid=grid, box=BOX, fields=f, expr="f0")
    assert not info["closed"] and info["volume"] is None
    assert edge_report(polygons)[0] > 0  # the plane ends on the domain boundary
    V, polygons, labels, creases, corners, info = bi.boolean_isosurface(grid=grid, box=BOX, fields=f, expr="f0",
                                                                        close=True)
    assert info["closed"]
    assert_closed_oriented(polygons)
    assert info["volume"] == pytest.approx(1.5 * 2 * 2, abs=1e-13)
    assert set(labels.tolist()) == {-1, 0}
    # a half box: the square where the plane meets the domain boundary and the
    # box's own edges below it are creases (closing faces of different boundary
    # planes meet at creases): 8 corners, 12 crease polylines
    assert len(corners) == 8
    assert len(creases) == 12
    assert np.sum(V[corners, 0] == 0.5) == 4


def test_sphere_volume_converges():
    ball = 4 / 3 * math.pi * 0.7 ** 3
    errors = []
    for n in (9, 17, 33):
        P = bi.grid_points((n, n, n), BOX)
        f = np.linalg.norm(P, axis=1) - 0.7
        V, polygons, labels, creases, corners, info = bi.boolean_isosurface(grid=(n, n, n), box=BOX, fields=f,
                                                                            expr="f0")
        assert info["closed"]
        assert_closed_oriented(polygons)
        assert len(creases) == 0 and len(corners) == 0
        errors.append(abs(info["volume"] - ball))
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] / ball < 1e-2


def test_output_does_not_depend_on_threads_or_slabs():
    n = 21
    P = bi.grid_points((n, n, n), BOX)
    f = np.stack([np.linalg.norm(P - 0.2, axis=1) - 0.6, np.linalg.norm(P + 0.2, axis=1) - 0.6, P[:, 2] - 0.1], 1)
    runs = [bi.boolean_isosurface(grid=(n, n, n), box=BOX, fields=f, expr="(f0 | f1) & f2", **kw)
            for kw in ({"threads": 1}, {"threads": 0}, {"slab_layers": 3})]
    for V, polygons, labels, *_ in runs[1:]:
        assert np.array_equal(V, runs[0][0])
        assert np.array_equal(labels, runs[0][2])
        assert all(np.array_equal(p, q) for p, q in zip(polygons, runs[0][1]))


def kuhn_cube_mesh():
    """The unit cube as 6 tetrahedra around its main diagonal."""
    X = np.array([[(c >> a) & 1 for a in range(3)] for c in range(8)], dtype=float)
    T = []
    for perm in itertools.permutations(range(3)):
        c = 0
        tet = [0]
        for a in perm:
            c |= 1 << a
            tet.append(c)
        T.append(tet)
    return X, np.array(T, dtype=np.int64)


def test_tet_mesh_domain_with_a_linear_field_is_exact():
    X, T = kuhn_cube_mesh()
    f = X[:, 2] - 0.25  # linear: exact on every tetrahedron
    V, polygons, labels, creases, corners, info = bi.boolean_isosurface(mesh=(X, T), fields=f, expr="f0",
                                                                        close=True)
    assert info["number_of_tetrahedra"] == 6
    assert info["closed"]
    assert_closed_oriented(polygons)
    assert info["volume"] == pytest.approx(0.25, abs=1e-15)
    # the cube's edges below the plane are creases too: 8 corners, 12 polylines
    assert len(corners) == 8 and len(creases) == 12
    assert np.sum(V[corners, 2] == 0.25) == 4


def test_smoothing_keeps_corners_and_creases():
    n = 17
    P = bi.grid_points((n, n, n), BOX)
    f = np.stack([np.linalg.norm(P, axis=1) - 0.8, P[:, 2] - 0.25, -P[:, 0] - 0.3], axis=1)
    kwargs = dict(grid=(n, n, n), box=BOX, fields=f, expr="f0 & f1 & f2")
    V0, polygons, labels, creases, corners, info0 = bi.boolean_isosurface(**kwargs)
    V1, polygons1, labels1, creases1, corners1, info1 = bi.boolean_isosurface(smooth=10, **kwargs)
    assert info0["closed"] and info1["closed"]
    assert len(corners) == 2  # where the two planes and the sphere meet
    assert np.array_equal(corners, corners1)
    assert np.array_equal(V0[corners], V1[corners])  # corners do not move
    moved = np.linalg.norm(V1 - V0, axis=1)
    assert moved.max() > 1e-4  # the smoothing did something
    # vertices of the plane-plane crease stay on both planes
    for line in creases:
        on_both = [v for v in line if abs(V0[v, 2] - 0.25) < 1e-15 and abs(V0[v, 0] + 0.3) < 1e-15]
        if len(on_both) == len(line):
            assert np.allclose(V1[line, 2], 0.25, atol=1e-12) and np.allclose(V1[line, 0], -0.3, atol=1e-12)
    # the same through the free function
    V2 = bi.smooth_with_creases(V0, polygons, labels, iterations=10)
    assert np.array_equal(V1, V2)
    creases2, corners2 = bi.crease_network(V0, polygons, labels)
    assert np.array_equal(corners2, corners)
    assert len(creases2) == len(creases)


def test_triangulate_fans_polygons():
    n = 9
    P = bi.grid_points((n, n, n), BOX)
    V, polygons, labels, creases, corners, info = bi.boolean_isosurface(grid=(n, n, n), box=BOX,
                                                                        fields=half_space_fields(P), expr=
                                                                        "f0 & f1 & f2 & f3 & f4 & f5")
    F, face_labels = bi.triangulate(polygons, labels)
    assert len(F) == sum(len(p) - 2 for p in polygons)
    assert bi.surveyor_volume(V, F) == pytest.approx(1.0, abs=1e-14)
    assert set(face_labels.tolist()) == set(labels.tolist())


@pytest.mark.parametrize("case", ["nan", "rows", "unknown_field", "parse", "two_domains", "no_domain", "tet_index",
                                  "tet_negative", "flat_tet", "grid_too_small", "box", "smooth"])
def test_bad_input_raises_value_error(case):
    grid = (5, 5, 5)
    P = bi.grid_points(grid, BOX)
    f = half_space_fields(P)[:, :2].copy()
    kwargs = dict(grid=grid, box=BOX, fields=f, expr="f0 & f1")
    error, match = bi.InvalidInputError, ""
    X, T = kuhn_cube_mesh()
    if case == "nan":
        f[17, 1] = np.nan
        error, match = bi.NonFiniteValueError, "field 1"
    elif case == "rows":
        kwargs["fields"], match = f[:-1], "124 vertices but the domain has 125"
    elif case == "unknown_field":
        kwargs["expr"], match = "f0 & f3", "f3"
    elif case == "parse":
        kwargs["expr"], error = "f0 &", bi.ParseError
    elif case == "two_domains":
        kwargs["mesh"], match = (X, T), "exactly one domain"
    elif case == "no_domain":
        del kwargs["grid"]
        match = "exactly one domain"
    elif case in ("tet_index", "tet_negative", "flat_tet"):
        T = T.copy()
        if case == "tet_index":
            T[2, 3], match = 8, "refers to vertex 8"
        elif case == "tet_negative":
            T[2, 3], match = -2, "negative"
        else:
            X = X.copy()
            X[7] = X[0]  # tetrahedra through corners 0 and 7 become flat
            match = ""
        del kwargs["grid"]
        kwargs.update(mesh=(X, T), fields=X[:, :1] - 0.5, expr="f0")
    elif case == "grid_too_small":
        kwargs["grid"], match = (1, 5, 5), "at least 2 vertices"
    elif case == "box":
        kwargs["box"], match = (0, 0, 0, -1, 1, 1), "x0 < x1"
    else:
        kwargs["smooth"], match = -1, "smooth"
    with pytest.raises(error, match=match):
        bi.boolean_isosurface(**kwargs)


def test_smoothing_a_non_manifold_surface_raises():
    # f0 xor f1 where the two zero sets cross: the regions touch along a
    # curve, which no polygon mesh can represent.
    n = 9
    P = bi.grid_points((n, n, n), BOX)
    f = np.stack([P[:, 0] - 0.01, P[:, 1] - 0.02], axis=1)
    V, polygons, labels, creases, corners, info = bi.boolean_isosurface(grid=(n, n, n), box=BOX, fields=f,
                                                                        expr="f0 & !f1 | !f0 & f1", close=True)
    with pytest.raises(bi.InvalidInputError, match="smoothing: cannot make a polygon mesh"):
        bi.boolean_isosurface(grid=(n, n, n), box=BOX, fields=f, expr="f0 & !f1 | !f0 & f1", close=True, smooth=2)


def test_triangulate_small_polygons_in_order():
    F, l = bi.triangulate([np.array([0, 1, 2]), np.array([3, 4, 5, 6, 7]), [8, 9, 10, 11]], [5, 6, 7])
    assert F.tolist() == [[0, 1, 2], [3, 4, 5], [3, 5, 6], [3, 6, 7], [8, 9, 10], [8, 10, 11]]
    assert l.tolist() == [5, 6, 6, 6, 7, 7]
    with pytest.raises(ValueError, match="at least 3"):
        bi.triangulate([[0, 1]])


def test_boolean_isosurface_can_be_interrupted():
    import _thread
    import threading
    import time

    n = 161
    P = bi.grid_points((n, n, n), BOX)
    f = np.stack([np.linalg.norm(P - 0.1, axis=1) - 0.6, np.sin(7 * P[:, 0]) * np.cos(5 * P[:, 1]) + P[:, 2]], 1)
    start = time.perf_counter()
    bi.boolean_isosurface(grid=(n, n, n), box=BOX, fields=f, expr="f0 & f1")
    full = time.perf_counter() - start
    timer = threading.Timer(0.02, _thread.interrupt_main)
    start = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        bi.boolean_isosurface(grid=(n, n, n), box=BOX, fields=f, expr="f0 & f1")
        time.sleep(60)  # reached only if the call was not interrupted
    interrupted = time.perf_counter() - start
    timer.join()
    assert interrupted < 0.5 * full, (interrupted, full)
