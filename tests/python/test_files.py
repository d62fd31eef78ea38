"""rdmesh.mesh on the shared real inputs, and the Mesh object's outputs."""

import os
import pathlib
import subprocess

import numpy as np
import pytest

import rdmesh
from mesh_checks import boundary_is_closed, signed_volumes, volume_per_label
from shared_data import needed, needed_module, shared_data

SAMPLES = pathlib.Path(__file__).resolve().parents[2] / "samples"
STEP = "step/cadquery_red_cube_blue_cylinder.step"
OFF = "mesh/cgal_tripod.off"


def test_step_solids_names_and_volumes():
    m = rdmesh.mesh(shared_data(STEP))
    assert m.subdomain_names == ["blue_cylinder", "red_cube"]
    assert len(m.patch_names) == 9 and len(m.curve_names) == 14 and len(m.corners) == 8
    assert (signed_volumes(m) > 0).all()
    fidelity = m.report["fidelity"]
    assert fidelity["passed"] is True
    # The cube is 10 x 10 x 10 mm; its faces are planes, so the mesh is exact.
    assert volume_per_label(m)[2] == pytest.approx(1000.0, rel=1e-9)
    assert not m.failed


def test_same_mesh_as_the_command_line(tmp_path):
    cli = os.environ.get("RDMESH_CLI")
    if not cli:
        needed("RDMESH_CLI (the rdmesh executable)")
    step = shared_data(STEP)
    subprocess.run([cli, str(step), "-o", str(tmp_path / "cli.mesh"), "-q", "--size", "3",
                    "--facet-distance", "0.2", "--no-exude"], check=True)
    m = rdmesh.mesh(step, size=3, facet_distance=0.2, exude=False)
    m.write(tmp_path / "py.mesh")
    assert (tmp_path / "py.mesh").read_bytes() == (tmp_path / "cli.mesh").read_bytes()


def test_triangle_mesh():
    m = rdmesh.mesh(shared_data(OFF), feature_angle=50)
    assert len(m.tets) > 0 and (signed_volumes(m) > 0).all()
    assert boundary_is_closed(m)
    assert m.report["fidelity"]["passed"] is True
    assert len(m.curve_names) > 0 and len(m.edges) > 0


def test_write_and_meshio_round_trip(tmp_path):
    meshio = needed_module("meshio")
    m = rdmesh.mesh_domain(SAMPLES / "cube.json", size=0.25)
    assert len(m.corners) == 8 and len(m.curve_names) == 12
    for ext in ("msh", "vtu", "mesh"):
        path = tmp_path / f"out.{ext}"
        m.write(path)
        back = meshio.read(path)
        assert np.allclose(back.points, m.points)
        tetra = np.concatenate([c.data for c in back.cells if c.type == "tetra"])
        assert len(tetra) == len(m.tets)
    mm = m.to_meshio()
    assert isinstance(mm, meshio.Mesh)
    assert np.array_equal(mm.points, m.points)
    kinds = [c.type for c in mm.cells]
    assert kinds == ["tetra", "triangle", "line", "vertex"]
    assert np.array_equal(mm.cell_data["subdomain"][0], m.tet_labels)
    assert np.array_equal(mm.cell_data["patch"][1], m.triangle_labels)
    assert np.array_equal(mm.cell_data["curve"][2], m.edge_labels)
    assert np.array_equal(mm.cell_data["corner"][3], m.corner_labels)
    assert np.array_equal(mm.cells[3].data[:, 0], m.corners)
    assert not mm.cell_data["subdomain"][1].any()
    mm.write(tmp_path / "meshio.vtu")
    back = meshio.read(tmp_path / "meshio.vtu")
    assert np.array_equal(back.cell_data["subdomain"][0], m.tet_labels)


def test_arrays_are_read_only_views_that_outlive_nothing():
    m = rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=(-1.2,) * 3 + (1.2,) * 3, size=0.3)
    points = m.points
    with pytest.raises(ValueError):
        points[0, 0] = 1.0
    assert points.base is not None  # a view, no copy
    del m
    assert np.isfinite(points).all()  # the view keeps the mesh alive


def test_report_is_the_cli_report():
    m = rdmesh.mesh_domain(SAMPLES / "sphere.json", size=0.3)
    r = m.report
    for key in ("vertices", "tets", "criteria", "refinement", "guard", "exudation",
                "seconds", "subdomains", "patches"):
        assert key in r, key
    assert r["tets"] == len(m.tets) and r["vertices"] == len(m.points)


def test_picture(tmp_path):
    m = rdmesh.mesh_domain(SAMPLES / "sphere.json", size=0.3)
    m.picture(tmp_path / "sphere.png", view="z", picture_size="640x400")
    data = (tmp_path / "sphere.png").read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    assert int.from_bytes(data[16:20], "big") == 640 and int.from_bytes(data[20:24], "big") == 400


def test_partitions(tmp_path):
    m = rdmesh.mesh_domain(SAMPLES / "sphere.json", size=0.2, partitions=4)
    assert set(np.unique(m.tet_partition)) == {1, 2, 3, 4}
    assert m.report["partitions"]["parts"] == 4
    with pytest.raises(rdmesh.InputError, match="Medit"):
        m.write(tmp_path / "parts.mesh")
    m.write(tmp_path / "parts.vtu")
    meshio = needed_module("meshio")
    assert np.array_equal(m.to_meshio().cell_data["partition"][0], m.tet_partition)
    with pytest.raises(rdmesh.InputError, match="surface-only"):
        rdmesh.mesh_domain(SAMPLES / "sphere.json", partitions=2, surface_only=True)
