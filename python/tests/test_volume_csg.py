"""The surveyor's volume and Marching Cubes CSG: the properties the C++ tests
check (exact and converging volumes, closed and oriented output, parallel
output identical to sequential, bad input raising), on small inputs."""

import math
import threading
import time

import numpy as np
import pytest

import boolean_isosurfacing as bi
from conftest import assert_closed_oriented_triangles, cube_mesh, sphere_mesh, torus_mesh


# ---------------------------------------------------------------- volume

def test_unit_cube_volume_is_exact():
    V, F = cube_mesh()
    assert bi.surveyor_volume(V, F) == 1.0


def test_cube_far_from_origin_keeps_its_digits():
    # The sum against the centroid and the certified bound keep the relative
    # error below 4e-15 where a sum against the origin loses about 12 digits.
    V, F = cube_mesh((1e6, -1e6, 1e6), (1e6 + 1, -1e6 + 1, 1e6 + 1))
    assert abs(bi.surveyor_volume(V, F) - 1.0) <= 4e-15


def test_box_volume_and_signed_inward_box():
    V, F = cube_mesh((-1.0, 0.0, 2.0), (2.0, 0.5, 6.0))
    assert bi.surveyor_volume(V, F) == pytest.approx(3 * 0.5 * 4, rel=4e-15)
    inward = F[:, ::-1].copy()
    with pytest.raises(bi.InwardOrientedMeshError):
        bi.surveyor_volume(V, inward)
    assert bi.surveyor_volume(V, inward, signed=True) == pytest.approx(-6.0, rel=4e-15)


def test_sphere_volume_converges_to_the_ball():
    ball = 4 / 3 * math.pi
    errors = [abs(bi.surveyor_volume(*sphere_mesh(rings=r, segments=2 * r)) - ball) for r in (8, 16, 32, 64)]
    assert all(b < a for a, b in zip(errors, errors[1:]))
    # second order: halving the edge length divides the error by about 4
    assert errors[-2] / errors[-1] > 3.5
    assert errors[-1] / ball < 2e-3


def test_volume_reads_int32_and_float32_inputs():
    V, F = cube_mesh()
    assert bi.surveyor_volume(V.astype(np.float32), F.astype(np.int32)) == 1.0
    assert bi.surveyor_volume(V.tolist(), F.tolist()) == 1.0


@pytest.mark.parametrize("case", ["open", "nan", "index", "negative", "shape", "float_indices", "empty", "degenerate"])
def test_volume_bad_input_raises_value_error(case):
    V, F = cube_mesh()
    if case == "open":
        F, error, match = F[:-1], bi.OpenMeshError, "not closed"
    elif case == "nan":
        V[3, 1], error, match = np.nan, bi.NonFiniteValueError, ""
    elif case == "index":
        F[5, 2], error, match = 8, bi.InvalidInputError, "refers to point 8"
    elif case == "negative":
        F[5, 2], error, match = -1, bi.InvalidInputError, "refers to point -1"
    elif case == "shape":
        V, error, match = V[:, :2], bi.InvalidInputError, r"shape \(n, 3\)"
    elif case == "float_indices":
        F, error, match = F.astype(float), bi.InvalidInputError, "integers"
    elif case == "empty":
        F, error, match = np.empty((0, 3), dtype=np.int64), bi.EmptyInputError, "no face"
    else:
        F[0] = (0, 0, 1)
        error, match = bi.InvalidInputError, "repeats a vertex"
    with pytest.raises(error, match=match):
        bi.surveyor_volume(V, F)
    assert issubclass(error, ValueError)


# ---------------------------------------------------------------- CSG

def test_csg_of_one_box_is_the_box_exactly_when_its_faces_are_off_the_lattice():
    # A box whose faces lie between lattice planes: Marching Cubes puts each
    # face vertex on the face, and the edges of the box are cut by at most
    # one cell, so the output volume is within the cells the box's edges cross.
    V, F = cube_mesh((0.1, 0.2, 0.3), (1.1, 1.2, 1.3))
    V2, F2, info = bi.csg([(V, F)], "A", cells=40)
    assert info["closed"]
    assert_closed_oriented_triangles(F2)
    h = info["spacing"]
    v = bi.surveyor_volume(V2, F2)
    assert v <= 1.0 + 1e-12
    assert 1.0 - v < 12 * 1.0 * h * h  # the 12 box edges, each chamfered by at most h^2 / 2
    assert np.all(V2.min(axis=0) >= V.min(axis=0) - 1e-12) and np.all(V2.max(axis=0) <= V.max(axis=0) + 1e-12)


def test_csg_sharp_features_make_a_box_difference_exact():
    # A box minus a box moved by a non-lattice offset: every edge and corner
    # of the exact result is a feature, its faces are flat, so with features
    # the volume is exact up to rounding; plain Marching Cubes chamfers it.
    b = np.array([0.5137, 0.4419, 0.6271])
    A, B = cube_mesh((0, 0, 0), (2, 2, 2)), cube_mesh(b, b + 2)
    exact = 8 - np.prod(2 - b)
    V, F, info = bi.csg([A, B], "difference", cells=32)
    assert info["closed"]
    assert_closed_oriented_triangles(F)
    assert bi.surveyor_volume(V, F) == pytest.approx(exact, rel=1e-9)
    assert info["corner_vertices"] == 14  # 7 of A, 1 of B, 3 + 3 where edges cross faces
    assert info["crease_edges"] > 0
    V2, F2, info2 = bi.csg([A, B], "difference", cells=32, features=False)
    assert info2["feature_vertices"] == 0 and info2["crease_edges"] == 0
    assert abs(bi.surveyor_volume(V2, F2) - exact) > 1e-4 * exact


def test_csg_feature_angle_is_checked():
    A = cube_mesh()
    with pytest.raises(bi.InvalidInputError):
        bi.csg([A], "A", cells=8, feature_angle=0.0)
    with pytest.raises(bi.InvalidInputError):
        bi.csg([A], "A", cells=8, feature_angle=180.0)


def test_csg_reports_a_slab_thinner_than_the_spacing():
    # [1.5, 2] x [0, 1] x [0.1, 0.14] next to the unit box, at 16 cells
    # (r = 0.125): no lattice point inside the slab, so it is missing.
    A, B = cube_mesh(), cube_mesh((1.5, 0.0, 0.1), (2.0, 1.0, 0.14))
    V, F, info = bi.csg([A, B], "union", cells=16)
    assert [(c["mesh"], c["component"]) for c in info["under_resolved_components"]] == [(1, 0)]
    c = info["under_resolved_components"][0]
    assert c["volume"] == pytest.approx(0.02) and c["lattice_volume"] == 0
    assert 0 < c["suggested_spacing"] < info["spacing"]
    V2, F2, info2 = bi.csg([A, B], "union", spacing=c["suggested_spacing"])
    assert info2["under_resolved_components"] == []
    assert bi.surveyor_volume(V2, F2) == pytest.approx(1.02, rel=1e-3)


def test_csg_warns_about_a_difference_thinner_than_the_spacing():
    # A box minus a box 0.02 smaller on every side: a shell 0.02 thick, which
    # a lattice of spacing ~1/16 cannot see, though each box alone is resolved.
    outer, inner = cube_mesh(), cube_mesh((0.02, 0.02, 0.02), (0.98, 0.98, 0.98))
    V, F, info = bi.csg([outer, inner], "difference", cells=16)
    assert info["under_resolved_components"] == []
    assert info["thin_result_fraction"] > 0.5
    assert 0 < info["thin_result_suggested_spacing"] < info["spacing"]
    assert any("thinner than a cell" in w for w in info["warnings"])
    V2, F2, info2 = bi.csg([outer, inner], "difference", cells=128)
    assert info2["thin_result_fraction"] == 0 and info2["warnings"] == []
    assert bi.surveyor_volume(V2, F2) == pytest.approx(1 - 0.96 ** 3, rel=0.05)


def test_csg_sphere_volume_converges():
    S = sphere_mesh(rings=64, segments=128)
    mesh_volume = bi.surveyor_volume(*S)
    errors = []
    for cells in (16, 32, 64):
        V, F, info = bi.csg([S], "A", cells=cells)
        assert info["closed"]
        assert_closed_oriented_triangles(F)
        errors.append(abs(bi.surveyor_volume(V, F) - mesh_volume))
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] / mesh_volume < 5e-3


@pytest.fixture(scope="module")
def sphere_and_torus():
    return sphere_mesh(rings=32, segments=64), torus_mesh(center=(0.9, 0.0, 0.0))


def test_csg_union_intersection_difference_are_closed_and_consistent(sphere_and_torus):
    A, B = sphere_and_torus
    vA, vB = bi.surveyor_volume(*A), bi.surveyor_volume(*B)
    volumes = {}
    for op in ("union", "intersection", "difference"):
        V, F, info = bi.csg([A, B], op, cells=64)
        assert info["closed"], op
        assert_closed_oriented_triangles(F)
        volumes[op] = bi.surveyor_volume(V, F)
    # inclusion-exclusion and A = (A - B) + (A & B), up to the lattice error
    assert volumes["union"] + volumes["intersection"] == pytest.approx(vA + vB, rel=1e-2)
    assert volumes["difference"] + volumes["intersection"] == pytest.approx(vA, rel=1e-2)
    assert max(vA, vB) < volumes["union"] < vA + vB
    assert 0 < volumes["intersection"] < min(vA, vB)


def test_csg_expression_equals_the_named_operation(sphere_and_torus):
    A, B = sphere_and_torus
    V1, F1, _ = bi.csg([A, B], "difference", cells=24)
    V2, F2, _ = bi.csg([A, B], "A & !B", cells=24)
    assert np.array_equal(V1, V2) and np.array_equal(F1, F2)


def test_csg_output_does_not_depend_on_the_number_of_threads(sphere_and_torus):
    A, B = sphere_and_torus
    V1, F1, _ = bi.csg([A, B], "A | B", cells=48, threads=1)
    V2, F2, _ = bi.csg([A, B], "A | B", cells=48, threads=0)
    assert np.array_equal(V1, V2) and np.array_equal(F1, F2)


def test_csg_outputs_own_their_buffers_without_copies(sphere_and_torus):
    A, _ = sphere_and_torus
    V, F, _ = bi.csg([A], "A", cells=16)
    assert V.dtype == np.float64 and F.dtype == np.int64
    assert V.flags.c_contiguous and F.flags.c_contiguous
    # the arrays view the library's vectors (owned by a capsule), not a copy
    assert not V.flags.owndata and not F.flags.owndata
    assert F.min() >= 0 and F.max() < len(V)


def test_csg_releases_the_gil(sphere_and_torus):
    A, B = sphere_and_torus
    ticks = 0
    done = threading.Event()

    def run():
        bi.csg([A, B], "A | B", cells=160)
        done.set()

    worker = threading.Thread(target=run)
    start = time.perf_counter()
    worker.start()
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    worker.join()
    elapsed = time.perf_counter() - start
    # With the GIL held during the C++ call this thread could not run at all.
    assert elapsed > 0.05
    assert ticks > 10


@pytest.mark.parametrize("case", ["open", "inward", "nan", "index", "parse", "too_many_variables", "both_sizes",
                                  "not_a_pair", "difference_of_three", "empty"])
def test_csg_bad_input_raises_value_error(sphere_and_torus, case):
    A, B = sphere_and_torus
    V, F = B
    meshes, expr, kwargs, error, match = [A, B], "A | B", {}, bi.InvalidInputError, ""
    if case == "open":
        meshes, error, match = [A, (V, F[:-2])], bi.OpenMeshError, r"mesh 1 \(B\): "
    elif case == "inward":
        meshes, error, match = [A, (V, F[:, ::-1])], bi.InwardOrientedMeshError, r"mesh 1 \(B\)"
    elif case == "nan":
        V = V.copy()
        V[7, 0] = np.nan
        meshes, error = [A, (V, F)], bi.NonFiniteValueError
    elif case == "index":
        F = F.copy()
        F[3, 1] = len(V) + 5
        meshes, match = [A, (V, F)], "refers to point"
    elif case == "parse":
        expr, error = "A & (B", bi.ParseError
    elif case == "too_many_variables":
        expr, match = "A | C", "3 inputs but 2 meshes"
    elif case == "both_sizes":
        kwargs, match = {"cells": 10, "spacing": 0.1}, "at most one"
    elif case == "not_a_pair":
        meshes, match = [A, V], r"\(V, F\) pair"
    elif case == "difference_of_three":
        meshes, expr, match = [A, B, A], "difference", "exactly two"
    else:
        meshes, error = [], bi.EmptyInputError
    with pytest.raises(error, match=match):
        bi.csg(meshes, expr, **kwargs)


# ---------------------------------------------------------------- generators

def test_icosphere_and_torus_are_closed_with_converging_volumes():
    ball = 4 / 3 * math.pi
    errors = []
    for s in (2, 3, 4):
        V, F = bi.icosphere((0, 0, 0), 1.0, s)
        assert len(F) == 20 * 4 ** s
        assert_closed_oriented_triangles(F)
        v = bi.surveyor_volume(V, F)
        assert v < ball  # inscribed
        errors.append(ball - v)
    assert errors[0] > 3.5 * errors[1] > 3.5 * 3.5 * errors[2]
    V, F = bi.torus((0.9, 0, 0), 0.8, 0.35, 96, 48)
    assert len(F) == 2 * 96 * 48
    assert_closed_oriented_triangles(F)
    assert bi.surveyor_volume(V, F) == pytest.approx(2 * math.pi ** 2 * 0.8 * 0.35 ** 2, rel=5e-3)
    with pytest.raises(bi.InvalidInputError, match="major_radius > minor_radius"):
        bi.torus((0, 0, 0), 0.3, 0.35)


def test_non_contiguous_and_fortran_arrays_are_converted():
    V, F = cube_mesh()
    assert bi.surveyor_volume(np.asfortranarray(V), np.asfortranarray(F)) == 1.0
    wide = np.zeros((8, 6))
    wide[:, ::2] = V
    assert bi.surveyor_volume(wide[:, ::2], F) == 1.0


def test_volume_reads_contiguous_inputs_in_place():
    # numpy reports its allocations to tracemalloc: a converted copy of the
    # inputs would show up in the peak, a view does not.
    import tracemalloc

    V, F = sphere_mesh(rings=200, segments=400)  # 80K vertices: a copy of V is 1.9 MB, of F 3.8 MB
    assert V.flags.c_contiguous and V.dtype == np.float64 and F.dtype == np.int64
    tracemalloc.start()
    try:
        tracemalloc.reset_peak()
        bi.surveyor_volume(V, F)
        _, in_place = tracemalloc.get_traced_memory()
        F32 = F.astype(np.int32)
        tracemalloc.reset_peak()
        bi.surveyor_volume(V, F32)
        _, converted = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert in_place < 1_000_000
    assert converted > F.nbytes  # the int32 indices were converted to int64 (the check can fail)


def test_csg_can_be_interrupted(sphere_and_torus):
    # Ctrl-C: the library's progress callback lets Python handle signals
    # between batches of work.  The interrupted call must end well before an
    # uninterrupted one would.
    import _thread

    A, B = sphere_and_torus
    start = time.perf_counter()
    bi.csg([A, B], "A | B", cells=256)
    full = time.perf_counter() - start
    timer = threading.Timer(0.02, _thread.interrupt_main)
    start = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        bi.csg([A, B], "A | B", cells=256)
        time.sleep(60)  # reached only if the call was not interrupted: the interrupt then lands here
    interrupted = time.perf_counter() - start
    timer.join()
    assert interrupted < 0.5 * full, (interrupted, full)
