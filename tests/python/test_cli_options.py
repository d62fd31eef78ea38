"""The command line's options as keywords: the same parser, defaults, messages and
outputs as `rdmesh INPUT ...` (run/ is shared by both)."""

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import rdmesh
from shared_data import needed, shared_data

SAMPLES = pathlib.Path(__file__).resolve().parents[2] / "samples"
BOX = (-1.2, -1.2, -1.2, 1.2, 1.2, 1.2)
STEP = "step/cadquery_red_cube_blue_cylinder.step"


def cli():
    path = os.environ.get("RDMESH_CLI")
    if not path:
        needed("RDMESH_CLI (the rdmesh executable)")
    return path


def cli_error(*args):
    """The CLI's one-line error for `args`, without its "rdmesh: error: " prefix."""
    r = subprocess.run([cli(), *map(str, args)], capture_output=True, text=True)
    assert r.returncode == 2 and r.stdout == "", r
    lines = r.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("rdmesh: error: "), r.stderr
    return lines[0][len("rdmesh: error: "):]


@pytest.mark.parametrize("keywords, argv", [
    ({"features": "sometimes"}, ["--features", "sometimes"]),
    ({"radius_edge": 1.0}, ["--radius-edge", "1.0"]),
    ({"order": 3}, ["--order", "3"]),
    ({"grade": "steep"}, ["--grade", "steep"]),
    ({"format": "msh3"}, ["--format", "msh3"]),
    ({"check": "thorough"}, ["--check", "thorough"]),
    ({"size_on": "edge:1=0.5"}, ["--size-on", "edge:1=0.5"]),
])
def test_bad_option_has_the_cli_message(keywords, argv):
    sample = SAMPLES / "sphere.json"
    with pytest.raises(rdmesh.InputError) as e:
        rdmesh.mesh(sample, size=0.4, **keywords)
    assert str(e.value) == cli_error(sample, "--size", "0.4", *argv, "-o", "/tmp/never.msh")


def test_outputs_as_the_cli_writes_them(tmp_path):
    sample = SAMPLES / "cube.json"
    subprocess.run([cli(), sample, "-q", "--size", "0.3", "-o", tmp_path / "cli.msh", "--binary",
                    "--picture", tmp_path / "cli.png", "--view", "x", "--picture-size", "480x320",
                    "--report", tmp_path / "cli.json"], check=True)
    m = rdmesh.mesh(sample, size=0.3, output=tmp_path / "py.msh", binary=True,
                    picture=tmp_path / "py.png", view="x", picture_size="480x320",
                    report=tmp_path / "py.json")
    assert (tmp_path / "py.msh").read_bytes() == (tmp_path / "cli.msh").read_bytes()
    assert b"$MeshFormat\n4.1 1 8\n" in (tmp_path / "py.msh").read_bytes()[:40]  # binary
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()
    py, ref = (json.loads((tmp_path / f"{n}.json").read_text()) for n in ("py", "cli"))
    for key in ("rdmesh_version", "input_sha256", "criteria", "vertices", "tets", "fidelity",
                "refinement", "patches", "subdomains"):
        assert py[key] == ref[key], key
    assert py["rdmesh_version"] == cli_version() == rdmesh.__version__
    assert py["command_line"].startswith("python: rdmesh ") and "--binary" in py["command_line"]
    assert m.report["criteria"] == py["criteria"] and m.report["tets"] == len(m.tets)


def cli_version():
    out = subprocess.run([cli(), "--version"], capture_output=True, text=True, check=True)
    return out.stdout.split()[-1]


def test_write_format_and_encoding(tmp_path):
    m = rdmesh.mesh_domain(SAMPLES / "sphere.json", size=0.4)
    m.write(tmp_path / "old.msh", format="msh22")
    assert (tmp_path / "old.msh").read_text().startswith("$MeshFormat\n2.2 0 8\n")
    m.write(tmp_path / "text.vtu", ascii=True)
    m.write(tmp_path / "packed.vtu", binary=True)
    assert 'format="ascii"' in (tmp_path / "text.vtu").read_text()
    assert b'format="binary"' in (tmp_path / "packed.vtu").read_bytes()
    with pytest.raises(rdmesh.InputError, match="text only"):
        m.write(tmp_path / "x.mesh", binary=True)
    with pytest.raises(rdmesh.InputError, match="--format"):
        m.write(tmp_path / "x.msh", format="msh3")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["old.msh", "packed.vtu", "text.vtu"]


def test_bad_output_refused_before_meshing(tmp_path):
    seen = []
    with pytest.raises(rdmesh.InputError, match="unknown output extension"):
        rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, size=0.3,
                             output=tmp_path / "out.xyz", progress=seen.append)
    assert seen == []  # refused before any phase started
    assert list(tmp_path.iterdir()) == []


def test_report_of_a_callable_has_no_input_digest():
    m = rdmesh.mesh_implicit(lambda x, y, z: x * x + y * y + z * z - 1, bbox=BOX, size=0.3)
    assert m.report["input_sha256"] is None and m.report["input"] == "mesh_implicit"
    m = rdmesh.mesh_domain(SAMPLES / "sphere.json", size=0.3)
    assert len(m.report["input_sha256"]) == 64


def test_progress_reports_the_cli_phases():
    phases = []
    rdmesh.mesh(SAMPLES / "cube.json", size=0.3, order=2,
                progress=lambda p: phases.append(p["phase"]) if p["vertices"] == 0 else None)
    for expected in ("reading", "checking the criteria", "protecting sharp features",
                     "refining", "exuding slivers", "checking the mesh against the model",
                     "making second-order elements"):
        assert any(p.startswith(expected) for p in phases), (expected, phases)
    assert phases.index("checking the criteria") < phases.index("refining")


def test_entity_sizes_on_cad_defaults(tmp_path):
    step = shared_data(STEP)
    m = rdmesh.mesh(step, size=3, size_on=["face:1=1", "solid:red_cube=2"], grade=1.5)
    sizes = m.report["entity_sizes"]
    assert [s["entity"] for s in sizes] == ["face:1", "solid:red_cube"]
    assert m.report["criteria"]["facet_distance"]  # the CAD default, resolved
    (tmp_path / "sizes.json").write_text(json.dumps({"face:1": 1, "grade": 1.5}))
    n = rdmesh.mesh(step, size=3, sizes=tmp_path / "sizes.json")
    assert n.report["entity_sizes"][0]["entity"] == "face:1"


def test_one_version_everywhere():
    import tomllib

    root = pathlib.Path(__file__).resolve().parents[2]
    project = tomllib.loads((root / "pyproject.toml").read_text())["project"]
    assert project["version"] == rdmesh.__version__ == cli_version()


def test_curvature_sizes_as_the_cli(tmp_path):
    # Torus of minor radius 0.3: its largest principal curvature is 1 / 0.3, so with 24
    # elements per turn no boundary edge should be longer than 2 pi 0.3 / 24 (the README's
    # bound; a few percent over it where the sizes meet), far below what --size 0.3 and the
    # sample's facet distance give alone.
    sample = SAMPLES / "torus.json"
    subprocess.run([cli(), sample, "-q", "--size", "0.3", "--curvature", "24",
                    "-o", tmp_path / "cli.mesh"], check=True)
    m = rdmesh.mesh(sample, size=0.3, curvature=24, output=tmp_path / "py.mesh")
    assert (tmp_path / "py.mesh").read_bytes() == (tmp_path / "cli.mesh").read_bytes()

    def longest_boundary_edge(mesh):
        p = np.asarray(mesh.points)
        t = np.asarray(mesh.triangles)
        return max(np.linalg.norm(p[t[:, i]] - p[t[:, (i + 1) % 3]], axis=1).max()
                   for i in range(3))

    bound = 2 * np.pi * 0.3 / 24
    assert longest_boundary_edge(m) <= 1.1 * bound
    reported = m.report["curvature_sizes"]
    assert reported["facet_max_ratio"] == pytest.approx(longest_boundary_edge(m) / bound, rel=0.05)
    assert longest_boundary_edge(rdmesh.mesh(sample, size=0.3)) > 2 * bound
