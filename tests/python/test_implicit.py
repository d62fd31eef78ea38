"""rdmesh.mesh_implicit and rdmesh.mesh_domain on analytic domains with exact volumes."""

import math
import pathlib

import numpy as np
import pytest

import rdmesh
from mesh_checks import (boundary_is_closed, euler_characteristic, signed_volumes,
                         volume_per_label)
from shared_data import needed_module

SAMPLES = pathlib.Path(__file__).resolve().parents[2] / "samples"
BOX = (-1.2, -1.2, -1.2, 1.2, 1.2, 1.2)
SPHERE_VOLUME = 4.0 / 3.0 * math.pi


def volume_tolerance(m, area):
    """The fidelity check's bound: the facet distance times the boundary's area."""
    return m.report["criteria"]["facet_distance"] * area


def check_sphere(m):
    assert m.points.shape[1] == 3 and m.points.dtype == np.float64
    assert m.tets.shape[1] == 4 and len(m.tets) > 100
    assert (signed_volumes(m) > 0).all()
    assert set(np.unique(m.tet_labels)) == {1}
    assert set(np.unique(m.triangle_labels)) == {1}
    assert boundary_is_closed(m)
    assert euler_characteristic(m, [1]) == 2
    assert volume_per_label(m)[1] == pytest.approx(SPHERE_VOLUME,
                                                   abs=volume_tolerance(m, 4 * math.pi))


def test_expression_sphere():
    m = rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, size=0.2)
    check_sphere(m)
    assert m.subdomain_names == ["domain"]
    assert len(m.edges) == 0 and len(m.corners) == 0


def test_callable_sphere_and_batch_contract():
    calls = {"arrays": [], "floats": 0}

    def f(x, y, z):
        if isinstance(x, np.ndarray):
            calls["arrays"].append(x.shape)
        else:
            assert isinstance(x, float)
            calls["floats"] += 1
        return x * x + y * y + z * z - 1

    m = rdmesh.mesh_implicit(f, bbox=BOX, size=0.2)
    check_sphere(m)
    assert calls["arrays"] == [(49 ** 3,)]  # the sampling grid, once
    assert calls["floats"] > 1000


def test_not_vectorized_gets_floats_only():
    seen = set()

    def f(x, y, z):
        seen.add(type(x))
        return math.sqrt(x * x + y * y + z * z) - 1

    check_sphere(rdmesh.mesh_implicit(f, bbox=BOX, size=0.25, vectorized=False))
    assert seen == {float}


def test_callable_torus_volume_and_genus():
    R, r = 1.0, 0.4

    def torus(x, y, z):
        q = np.sqrt(x * x + y * y) - R
        return q * q + z * z - r * r

    m = rdmesh.mesh_implicit(torus, bbox=(-1.6, -1.6, -0.6, 1.6, 1.6, 0.6), size=0.1)
    assert (signed_volumes(m) > 0).all()
    assert euler_characteristic(m, [1]) == 0  # a torus
    area = 4 * math.pi ** 2 * R * r
    assert volume_per_label(m)[1] == pytest.approx(2 * math.pi ** 2 * R * r * r,
                                                   abs=volume_tolerance(m, area))


def test_callable_runs_are_identical():
    f = lambda x, y, z: x * x + y * y + z * z - 1  # noqa: E731
    a = rdmesh.mesh_implicit(f, bbox=BOX, size=0.3)
    b = rdmesh.mesh_implicit(f, bbox=BOX, size=0.3)
    assert np.array_equal(a.points, b.points) and np.array_equal(a.tets, b.tets)


def test_several_functions_and_names():
    m = rdmesh.mesh_implicit(
        {"outer": "x^2 + y^2 + z^2 - 1", "inner": lambda x, y, z: x * x + y * y + z * z - 0.25},
        bbox=BOX, size=0.15,
        subdomains=[{"name": "shell", "inside": ["outer"], "outside": ["inner"]},
                    {"name": "core", "inside": ["inner"]}])
    assert m.subdomain_names == ["shell", "core"]
    assert len(m.patch_names) == 2
    v = volume_per_label(m)
    assert v[2] == pytest.approx(SPHERE_VOLUME / 8, abs=volume_tolerance(m, math.pi))
    assert v[1] == pytest.approx(SPHERE_VOLUME * 7 / 8, abs=volume_tolerance(m, 5 * math.pi))


def test_curves_callable_and_polyline():
    def rim(z):
        return lambda t: (0.5 * math.cos(t), 0.5 * math.sin(t), z)

    bottom = [[0.5 * math.cos(t), 0.5 * math.sin(t), -0.6]
              for t in np.linspace(0, 2 * math.pi, 65)]
    m = rdmesh.mesh_implicit(
        {"side": lambda x, y, z: x * x + y * y - 0.25, "top": "z - 0.6", "bottom": "-z - 0.6"},
        bbox=(-0.8, -0.8, -0.9, 0.8, 0.8, 0.9), size=0.12,
        subdomains=[{"name": "cylinder", "inside": ["side", "top", "bottom"]}],
        curves=[{"name": "top_rim", "gamma": rim(0.6), "t": [0, 2 * math.pi]},
                {"name": "bottom_rim", "points": bottom}])
    assert m.curve_names == ["top_rim", "bottom_rim"]
    assert set(np.unique(m.edge_labels)) == {1, 2}
    # Each rim is one closed chain: every vertex of its edges appears twice.
    for c in (1, 2):
        _, counts = np.unique(m.edges[m.edge_labels == c], return_counts=True)
        assert (counts == 2).all()
    # The top rim's vertices lie on the circle.
    top = m.points[np.unique(m.edges[m.edge_labels == 1])]
    assert np.allclose(np.hypot(top[:, 0], top[:, 1]), 0.5, atol=1e-6)
    assert np.allclose(top[:, 2], 0.6, atol=1e-9)


def test_mesh_domain_path_and_dict():
    a = rdmesh.mesh_domain(SAMPLES / "nested_spheres.json")
    assert a.subdomain_names == ["shell", "core"]
    doc = {"bbox": list(BOX), "functions": {"ball": "x^2 + y^2 + z^2 - 1"}, "size": 0.2}
    b = rdmesh.mesh_domain(doc)
    check_sphere(b)
    assert b.subdomain_names == ["ball"]
    assert b.report["criteria"]["facet_size"] == 0.2


def test_options_override_and_reach_the_run():
    m = rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, size="0.2 + 0.1 * abs(x)",
                             cell_size=0.25, facet_distance=0.01, exude=False)
    c = m.report["criteria"]
    f = c["facet_size"]  # the expression, a hint of the document: 0.2 to 0.32 over the box
    assert f["varying"] is True and 0.2 <= f["min"] < 0.21 and 0.31 < f["max"] <= 0.32 + 1e-12
    assert c["cell_size"] == 0.25 and c["facet_distance"] == 0.01
    assert m.report["exudation"]["ran"] is False


def test_surface_only():
    m = rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, size=0.2, surface_only=True)
    assert len(m.tets) == 0 and len(m.triangles) > 50
    assert euler_characteristic(m, [1]) == 2


def test_second_order():
    m = rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, size=0.3, order=2)
    k = len(m.tets)
    assert m.tet_mid_nodes.shape == (k, 6) and m.triangle_mid_nodes.shape == (len(m.triangles), 3)
    assert m.report["second_order"]["mid_nodes"] > 0
    p = m.points
    # Mid-edge nodes near their edge's midpoint (in Gmsh's edge order) ...
    edges = [(0, 1), (1, 2), (2, 0), (3, 0), (3, 2), (3, 1)]
    for j, (a, b) in enumerate(edges):
        mid = 0.5 * (p[m.tets[:, a]] + p[m.tets[:, b]])
        length = np.linalg.norm(p[m.tets[:, a]] - p[m.tets[:, b]], axis=1)
        assert (np.linalg.norm(p[m.tet_mid_nodes[:, j]] - mid, axis=1) <= 0.25 * length).all()
    # ... and the boundary's on the exact sphere.
    radius = np.linalg.norm(p[np.unique(m.triangle_mid_nodes)], axis=1)
    assert np.allclose(radius, 1.0, atol=1e-8)
    meshio = needed_module("meshio")
    mm = m.to_meshio()
    assert [c.type for c in mm.cells] == ["tetra10", "triangle6"]
    # meshio's tetra10 is VTK's: nodes 4..9 on edges 01, 12, 02, 03, 13, 23.
    t10 = mm.cells[0].data
    for j, (a, b) in enumerate([(0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)]):
        mid = 0.5 * (p[t10[:, a]] + p[t10[:, b]])
        length = np.linalg.norm(p[t10[:, a]] - p[t10[:, b]], axis=1)
        assert (np.linalg.norm(p[t10[:, 4 + j]] - mid, axis=1) <= 0.25 * length).all()
    assert isinstance(mm, meshio.Mesh)
