"""Contouring point samples, and the readers and writers: round trips, the
shared data, and bad files raising OSError (cannot open) or ValueError
(malformed)."""

import math
import os

import numpy as np
import pytest

import boolean_isosurfacing as bi
from conftest import assert_closed_oriented_triangles, cube_mesh, sphere_mesh


def fibonacci_sphere(n, radius=1.0):
    i = np.arange(n) + 0.5
    phi = np.arccos(1 - 2 * i / n)
    theta = math.pi * (1 + 5 ** 0.5) * i
    N = np.stack([np.cos(theta) * np.sin(phi), np.sin(theta) * np.sin(phi), np.cos(phi)], axis=1)
    return radius * N, N


@pytest.mark.parametrize("with_normals", [False, True])
def test_contour_of_sphere_samples_is_closed_with_the_ball_volume(with_normals):
    P, N = fibonacci_sphere(3000)
    V, F, info = bi.contour(P, N if with_normals else None)
    assert_closed_oriented_triangles(F)
    assert info["skipped_cubes"] == 0 and info["border_exits"] == 0
    assert not info["input_normals_rejected"]
    volume = bi.surveyor_volume(V, F)  # raises if inward
    assert volume == pytest.approx(4 / 3 * math.pi, rel=0.03)
    # every vertex near the unit sphere
    assert np.abs(np.linalg.norm(V, axis=1) - 1).max() < 0.05


def test_contour_inward_normals_are_rejected_and_the_result_is_outward():
    P, N = fibonacci_sphere(2000)
    V, F, info = bi.contour(P, -N)
    assert info["input_normals_rejected"]
    assert bi.surveyor_volume(V, F) > 0


@pytest.mark.parametrize("with_normals", [False, True])
def test_contour_output_does_not_depend_on_the_number_of_threads(with_normals):
    P, N = fibonacci_sphere(4000)
    V1, F1, i1 = bi.contour(P, N if with_normals else None, threads=1)
    V2, F2, i2 = bi.contour(P, N if with_normals else None, threads=0)
    assert np.array_equal(V1, V2) and np.array_equal(F1, F2)
    assert len(F1) > 1000


def test_contour_finer_cells_give_more_triangles():
    P, N = fibonacci_sphere(2000)
    _, F1, i1 = bi.contour(P, cells=20)
    _, F2, i2 = bi.contour(P, cells=40)
    assert i2["cell_size"] == pytest.approx(i1["cell_size"] / 2)
    assert len(F2) > 3 * len(F1)


@pytest.mark.parametrize("case", ["nan", "few", "coplanar", "collinear", "shape", "normals_rows", "k", "rho"])
def test_contour_bad_input_raises_value_error(case):
    P, N = fibonacci_sphere(500)
    args, kwargs, error, match = [P], {}, bi.InvalidInputError, ""
    if case == "nan":
        P[10, 2], error, match = np.nan, bi.NonFiniteValueError, "10"
    elif case == "few":
        args, match = [P[:5]], "fewer points"
    elif case == "coplanar":
        P[:, 2] = 0
        match = "one plane"
    elif case == "collinear":
        P[:, 1:] = 0
        match = "one line"
    elif case == "shape":
        args, match = [P[:, :2]], "shape"
    elif case == "normals_rows":
        args, match = [P, N[:-1]], "rows"
    elif case == "k":
        kwargs, match = {"k": 2}, "at least 3"
    else:
        kwargs, match = {"rho": -1.0}, "sampling_density"
    with pytest.raises(error, match=match):
        bi.contour(*args, **kwargs)


# ---------------------------------------------------------------- files

def test_mesh_round_trip(tmp_path):
    V, F = sphere_mesh(rings=8, segments=16)
    for ext in ("off", "obj", "ply", "stl"):
        path = str(tmp_path / f"s.{ext}")
        bi.write_mesh(path, V, F)
        V2, F2 = bi.read_mesh(path)
        assert bi.surveyor_volume(V2, F2) == pytest.approx(bi.surveyor_volume(V, F), rel=1e-6 if ext == "stl" else 1e-15)
        if ext in ("off", "obj"):
            assert np.array_equal(V, V2) and np.array_equal(F, F2)


def test_read_mesh_refuses_an_open_file_unless_asked(tmp_path):
    V, F = cube_mesh()
    path = str(tmp_path / "open.off")
    bi.write_mesh(path, V, F[:-1])
    with pytest.raises(bi.OpenMeshError):
        bi.read_mesh(path)
    V2, F2 = bi.read_mesh(path, closed=False)
    assert len(F2) == 11


def test_points_round_trip(tmp_path):
    P, N = fibonacci_sphere(100)
    path = str(tmp_path / "s.pts")
    bi.write_points(path, P, N)
    P2, N2 = bi.read_points(path)
    assert np.array_equal(P, P2) and np.array_equal(N, N2)
    bi.write_points(path, P)
    P3, N3 = bi.read_points(path)
    assert np.array_equal(P, P3) and N3 is None


def test_tris_round_trip(tmp_path):
    V, F = cube_mesh()
    path = str(tmp_path / "c.tris")
    bi.write_tris(path, V, F)
    T, N = bi.read_tris(path)
    assert T.shape == (12, 3, 3) and N.shape == (12, 3)
    assert np.array_equal(T, V[F])
    assert np.allclose(np.linalg.norm(N, axis=1), 1)


def test_tetrahedral_mesh_and_fields_round_trip(tmp_path):
    X = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], dtype=float)
    T = np.array([[0, 1, 2, 3], [1, 2, 3, 4]])
    path = str(tmp_path / "t.mesh")
    bi.write_tetrahedral_mesh(path, X, T)
    X2, T2 = bi.read_tetrahedral_mesh(path)
    assert np.array_equal(X, X2)
    assert len(T2) == 2
    fields = np.random.default_rng(1).normal(size=(5, 3))
    for ext in ("f64", "txt"):
        p = str(tmp_path / f"f.{ext}")
        bi.write_fields(p, fields)
        back = bi.read_fields(p, 5, 3) if ext == "f64" else bi.read_fields(p)
        assert np.array_equal(back, fields)
    p = str(tmp_path / "f.f32")
    bi.write_fields(p, fields)
    assert np.array_equal(bi.read_fields(p, 5, 3), fields.astype(np.float32).astype(float))


def test_isosurface_files(tmp_path):
    n = 9
    box = (-1, -1, -1, 1, 1, 1)
    P = bi.grid_points((n, n, n), box)
    f = np.stack([np.linalg.norm(P, axis=1) - 0.8, P[:, 2] - 0.2], axis=1)
    V, polygons, labels, creases, corners, info = bi.boolean_isosurface(grid=(n, n, n), box=box, fields=f,
                                                                        expr="f0 & f1")
    for binary in (False, True):
        path = str(tmp_path / f"s{int(binary)}.ply")
        bi.write_isosurface_ply(path, V, polygons, labels, binary=binary)
        V2, polygons2, labels2 = bi.read_isosurface_ply(path)
        assert np.array_equal(V, V2) and np.array_equal(labels, labels2)
        assert all(np.array_equal(p, q) for p, q in zip(polygons, polygons2))
    bi.write_creases(str(tmp_path / "c.polylines.txt"), V, creases)
    lines = open(tmp_path / "c.polylines.txt").read().split("\n")
    assert len([l for l in lines if l]) == len(creases) == 1
    bi.write_corners(str(tmp_path / "c.xyz"), V, corners)
    assert open(tmp_path / "c.xyz").read() == ""  # a closed crease circle has no corner


@pytest.mark.parametrize("reader", [bi.read_mesh, bi.read_points, bi.read_tris, bi.read_tetrahedral_mesh,
                                    bi.read_fields, bi.read_isosurface_ply])
def test_missing_files_raise_file_not_found(tmp_path, reader):
    with pytest.raises(FileNotFoundError):
        reader(str(tmp_path / "missing.file"))
    with pytest.raises(OSError):
        reader(str(tmp_path))  # a directory


def test_unwritable_paths_raise_os_error(tmp_path):
    V, F = cube_mesh()
    with pytest.raises(OSError):
        bi.write_mesh(str(tmp_path / "no" / "such" / "dir.off"), V, F)
    with pytest.raises(OSError):
        bi.write_tetrahedral_mesh(str(tmp_path / "no" / "t.mesh"), V, np.array([[0, 1, 2, 4]]))
    with pytest.raises(ValueError, match="format"):
        bi.write_mesh(str(tmp_path / "c.unknown"), V, F)


def test_malformed_files_raise_value_error(tmp_path):
    bad = tmp_path / "bad.pts"
    bad.write_text("0 0 0\n1 1 x\n")
    with pytest.raises(bi.ParseError, match="line 2"):
        bi.read_points(str(bad))
    bad = tmp_path / "bad.mesh"
    bad.write_text("MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0 zero 0\nEnd\n")
    with pytest.raises(ValueError):
        bi.read_tetrahedral_mesh(str(bad))
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n")
    with pytest.raises(ValueError):
        bi.read_mesh(str(bad))


# ---------------------------------------------------------------- shared data

def test_shared_meshes_volumes(shared_data):
    V, F = bi.read_mesh(os.path.join(shared_data, "meshes", "cube.obj"))
    assert bi.surveyor_volume(V, F) == pytest.approx(1.0, rel=4e-15)
    V, F = bi.read_mesh(os.path.join(shared_data, "meshes", "ico4_sphere.obj"))
    assert bi.surveyor_volume(V, F) == pytest.approx(4.1526849, rel=1e-7)  # the data README's value


def test_shared_tet_mesh_tbiso(shared_data):
    X, T = bi.read_tetrahedral_mesh(os.path.join(shared_data, "tet", "bunny.mesh"))
    c = X.mean(axis=0)
    f = (X[:, 1] - c[1])[:, None]
    V, polygons, labels, creases, corners, info = bi.boolean_isosurface(mesh=(X, T), fields=f, expr="f0",
                                                                        close=True)
    assert info["closed"]
    assert_closed_oriented_triangles(bi.triangulate(polygons))
    assert info["volume"] > 0
