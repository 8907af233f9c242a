"""Shared helpers: small closed meshes made with numpy, and mesh checks."""

import os

import numpy as np
import pytest


def cube_mesh(lo=(0.0, 0.0, 0.0), hi=(1.0, 1.0, 1.0)):
    """An axis-aligned box as 12 outward triangles."""
    lo = np.asarray(lo, dtype=float)
    hi = np.asarray(hi, dtype=float)
    V = np.array([[(hi if (c >> a) & 1 else lo)[a] for a in range(3)] for c in range(8)])
    # corner c has bit a set when coordinate a is at hi
    quads = [
        (0, 2, 3, 1),  # z = lo
        (4, 5, 7, 6),  # z = hi
        (0, 1, 5, 4),  # y = lo
        (2, 6, 7, 3),  # y = hi
        (0, 4, 6, 2),  # x = lo
        (1, 3, 7, 5),  # x = hi
    ]
    F = []
    for a, b, c, d in quads:
        F.append((a, b, c))
        F.append((a, c, d))
    return V, np.array(F, dtype=np.int64)


def sphere_mesh(center=(0.0, 0.0, 0.0), radius=1.0, rings=24, segments=48):
    """A UV sphere: closed, outward, genus 0."""
    cx, cy, cz = center
    V = [(cx, cy, cz + radius)]
    for i in range(1, rings):
        theta = np.pi * i / rings
        for j in range(segments):
            phi = 2 * np.pi * j / segments
            V.append((cx + radius * np.sin(theta) * np.cos(phi), cy + radius * np.sin(theta) * np.sin(phi),
                      cz + radius * np.cos(theta)))
    V.append((cx, cy, cz - radius))
    V = np.array(V)
    bottom = len(V) - 1

    def ring(i, j):
        return 1 + (i - 1) * segments + (j % segments)

    F = []
    for j in range(segments):
        F.append((0, ring(1, j), ring(1, j + 1)))
    for i in range(1, rings - 1):
        for j in range(segments):
            a, b, c, d = ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)
            F.append((a, b, c))
            F.append((a, c, d))
    for j in range(segments):
        F.append((bottom, ring(rings - 1, j + 1), ring(rings - 1, j)))
    return V, np.array(F, dtype=np.int64)


def torus_mesh(center=(0.0, 0.0, 0.0), R=0.8, r=0.35, n=64, m=32):
    """A torus around the z axis: closed, outward, genus 1."""
    cx, cy, cz = center
    u = 2 * np.pi * np.arange(n) / n
    v = 2 * np.pi * np.arange(m) / m
    U, W = np.meshgrid(u, v, indexing="ij")
    X = cx + (R + r * np.cos(W)) * np.cos(U)
    Y = cy + (R + r * np.cos(W)) * np.sin(U)
    Z = cz + r * np.sin(W)
    V = np.stack([X.ravel(), Y.ravel(), Z.ravel()], axis=1)
    F = []
    for i in range(n):
        for j in range(m):
            a = i * m + j
            b = ((i + 1) % n) * m + j
            c = ((i + 1) % n) * m + (j + 1) % m
            d = i * m + (j + 1) % m
            F.append((a, b, c))
            F.append((a, c, d))
    return V, np.array(F, dtype=np.int64)


def edge_report(polygons):
    """(border, non_manifold, inconsistent) edge counts of a polygon soup:
    closed and oriented iff all three are 0 (every undirected edge in exactly
    two polygons, which use it in opposite directions)."""
    uses = {}
    for poly in polygons:
        poly = [int(x) for x in poly]
        for k in range(len(poly)):
            a, b = poly[k], poly[(k + 1) % len(poly)]
            key = (min(a, b), max(a, b))
            uses.setdefault(key, []).append(a < b)
    border = sum(1 for u in uses.values() if len(u) == 1)
    non_manifold = sum(1 for u in uses.values() if len(u) > 2)
    inconsistent = sum(1 for u in uses.values() if len(u) == 2 and u[0] == u[1])
    return border, non_manifold, inconsistent


def assert_closed_oriented(polygons):
    assert len(polygons) > 0
    assert edge_report(polygons) == (0, 0, 0)


def assert_closed_oriented_triangles(F):
    """Vectorised check for big triangle arrays: every directed edge once,
    and its reverse present."""
    F = np.asarray(F)
    assert F.ndim == 2 and F.shape[1] == 3 and len(F) > 0
    directed = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    assert len(np.unique(directed, axis=0)) == len(directed), "a directed edge is used twice"
    forward = {tuple(e) for e in directed.tolist()}
    assert all((b, a) in forward for a, b in directed.tolist()), "a border edge"


@pytest.fixture(scope="session")
def shared_data():
    path = os.environ.get("BISO_SHARED_DATA_DIR",
                          os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "data"))
    if not os.path.isdir(path):
        pytest.skip("shared data not found (set BISO_SHARED_DATA_DIR)")
    return path
