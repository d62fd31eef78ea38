"""rdmesh: tetrahedral meshes of domains bounded by piecewise smooth surfaces.

Delaunay refinement of Rineau & Yvinec (INRIA RR-7912) driven by exact oracles.

    import rdmesh
    m = rdmesh.mesh("part.step", size=2.0)   # any input the CLI reads; keywords = CLI options
    m = rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=(-1.2,) * 3 + (1.2,) * 3, size=0.1)
    m = rdmesh.mesh_domain("domain.json")
    m.points, m.tets, m.tet_labels, m.triangles, m.triangle_labels, m.report
    m.write("out.msh")

Options are the command line's (rdmesh --help), with underscores: size,
edge_size, facet_size, cell_size, facet_distance, facet_angle, radius_edge,
min_size, max_elements, features ("protect" or "refine"), surface_only, heal,
feature_angle, exude (default True; False is --no-exude), exude_time_limit, exude_bound,
optimize (default True; False is --no-optimize), threads (0: all cores; the
mesh is the same for any number),
time_limit, keep_bad_mesh, check ("cheap" or "full"), order (1, or 2: 10-node
tetrahedra), partitions (METIS), size_on ("face:12=0.5", or a list of them),
sizes (a .json file), grade, curvature (elements per turn); and what the run writes,
as the CLI: output (a .msh/.mesh/.vtu file; none by default, Mesh.write writes
later), binary, ascii, format ("msh41" or "msh22"), report (a .json file;
Mesh.report has it anyway),
picture (a .png), view, picture_size, cut. They are parsed by the CLI's own
parser, with its defaults, its checks and its error messages; the run is the
CLI's (the default sizes of CAD models, the fidelity check, the report).

Errors raise rdmesh.InputError (bad input or options, the CLI's exit code 2,
same one-line message), rdmesh.OutputError, rdmesh.FidelityError (the mesh does
not match the model, has inverted tetrahedra, or the time limit stopped it: the
CLI's exit code 4),
rdmesh.OracleError and rdmesh.InternalError, all derived from rdmesh.Error.
Ctrl-C (KeyboardInterrupt) stops a run at the next progress point.
The run's warnings (the CLI's "rdmesh: warning: ..." lines) are issued as
RuntimeWarning and kept in Mesh.warnings.

progress(dict) is called as each phase starts ("reading ...", "checking the
criteria", "protecting sharp features", "refining", "exuding slivers",
"improving the tetrahedra",
"checking the mesh against the model", "writing ...", as the CLI's progress
line) with phase, vertices, edge_queue, facet_queue, cell_queue and
elapsed_seconds, and every few thousand insertions while refining.
"""

import json as _json
import numbers
import os as _os

from . import _rdmesh
from ._rdmesh import (Error, FidelityError, InputError, InternalError, Mesh, Oracle,
                      OracleError, OutputError, __version__)

__all__ = ["mesh", "mesh_implicit", "mesh_domain", "mesh_oracle", "to_meshio", "Mesh",
           "Oracle", "Error", "InputError", "OracleError", "OutputError", "InternalError",
           "FidelityError"]

# Python keyword -> (CLI long name, takes a value); exude=False is --no-exude,
# optimize=False --no-optimize.
_OPTIONS = {name.replace("-", "_"): (name, takes_value)
            for name, takes_value in _rdmesh._option_names()}
for _flag in ("exude", "optimize"):
    _OPTIONS.pop("no_" + _flag, None)
    _OPTIONS[_flag] = ("no-" + _flag, None)


def _cli_args(options):
    """Keyword options as the command line's arguments."""
    args = []
    for key, value in options.items():
        if key not in _OPTIONS:
            raise TypeError(f"unknown option {key!r} (options: {', '.join(sorted(_OPTIONS))})")
        name, takes_value = _OPTIONS[key]
        if takes_value is None:  # exude, optimize
            if not isinstance(value, bool):
                raise TypeError(f"{key} must be True or False")
            if not value:
                args.append("--" + name)
        elif not takes_value:
            if not isinstance(value, bool):
                raise TypeError(f"{key} must be True or False")
            if value:
                args.append("--" + name)
        elif isinstance(value, (list, tuple)) and name == "size-on":  # repeatable
            args.extend(f"--{name}={v}" for v in value)
        else:
            if isinstance(value, bool):
                raise TypeError(f"{key} takes a value, not {value!r}")
            if isinstance(value, numbers.Integral):
                text = str(int(value))
            elif isinstance(value, numbers.Real):
                text = repr(float(value))  # round-trips exactly
            else:
                text = _os.fspath(value) if isinstance(value, _os.PathLike) else str(value)
            args.append(f"--{name}={text}")
    return args


def mesh(path, progress=None, **options):
    """Meshes a file as `rdmesh PATH` does: .step/.stp/.brep/.iges/.igs, .off/.stl/.obj/.ply
    or a .json domain file. `progress(dict)`: see the module's documentation."""
    return _rdmesh._mesh_file(_os.fspath(path), _cli_args(options), progress)


def mesh_domain(domain, progress=None, **options):
    """Meshes an implicit domain in the .json format: a path, or the document as a dict
    (or a JSON string). Keys of the document are defaults that options override."""
    if isinstance(domain, dict):
        return _rdmesh._mesh_json(_json.dumps(domain), "<domain>", {}, {}, _cli_args(options),
                                  progress)
    if isinstance(domain, str) and domain.lstrip().startswith("{"):
        return _rdmesh._mesh_json(domain, "<domain>", {}, {}, _cli_args(options), progress)
    return mesh(domain, progress=progress, **options)


_HINTS = ("size", "edge_size", "facet_size", "cell_size")


def mesh_implicit(f, bbox, subdomains=None, curves=None, vectorized=True, progress=None,
                  **options):
    """Meshes the domain where the function f is negative, inside `bbox`
    (xmin, ymin, zmin, xmax, ymax, zmax).

    f is an expression string of x, y, z (the .json syntax), a Python callable,
    or a dict name -> string or callable for several functions, whose domains
    `subdomains` combines as in the .json format ([{"name": ..., "inside": [...],
    "outside": [...]}, ...]; several functions need it).

    A callable is called as f(x, y, z). Batch contract: with vectorized=True
    (the default) the box sampling calls it once with three float64 numpy arrays
    of shape (n,) (the grid, n = 49**3) and expects an (n,) array back (or one
    number); every other query is a single point, called with three Python
    floats and expecting one number. A numpy expression such as
    np.sqrt(x*x + y*y) - 1 serves both; both calls must give the same values.
    vectorized=False: floats only. The function is negative inside, must be
    deterministic and is called with the GIL held.

    curves: sharp curves as in the .json format ({"name", "points": [[x, y, z],
    ...]} polylines, {"name", "x", "y", "z", "t": [t0, t1]} expressions of t), or
    {"name", "gamma": callable, "t": [t0, t1]} with gamma(t) -> (x, y, z) for a
    float t.

    size, edge_size, facet_size and cell_size may be numbers or expression
    strings of x, y, z; every other keyword is an option as for mesh()."""
    if isinstance(f, dict):
        named = dict(f)
    else:
        named = {"domain": f}
    doc = {"bbox": [float(v) for v in bbox], "functions": {}}
    functions = {}
    for name, g in named.items():
        if isinstance(g, str):
            doc["functions"][name] = g
        else:
            doc["functions"][name] = {"external": name}
            functions[name] = (g, bool(vectorized))
    if subdomains is not None:
        doc["subdomains"] = list(subdomains)
    external_curves = {}
    if curves is not None:
        doc["curves"] = []
        for i, c in enumerate(curves):
            c = dict(c)
            if "gamma" in c:
                name = c.get("name", f"curve_{i + 1}")
                t = c.get("t")
                if t is None or len(t) != 2:
                    raise InputError(f"mesh_implicit: curve '{name}': 't' must be [t0, t1]")
                external_curves[name] = (c["gamma"], float(t[0]), float(t[1]))
                doc["curves"].append({"name": name, "external": name})
            else:
                if "points" in c:
                    c["points"] = [[float(v) for v in p] for p in c["points"]]
                doc["curves"].append(c)
    for key in _HINTS:
        if isinstance(options.get(key), str):
            doc[key] = options.pop(key)
    return _rdmesh._mesh_json(_json.dumps(doc), "mesh_implicit", functions, external_curves,
                              _cli_args(options), progress)


def mesh_oracle(oracle, progress=None, **options):
    """Meshes a domain written in Python: an instance of a subclass of rdmesh.Oracle."""
    if not isinstance(oracle, Oracle):
        raise TypeError("mesh_oracle needs an instance of a subclass of rdmesh.Oracle")
    return _rdmesh._mesh_oracle(oracle, _cli_args(options), progress)


def to_meshio(m):
    """The mesh as a meshio.Mesh (needs meshio): cell blocks tetra, triangle, line and
    vertex (corners); tetra10, triangle6 and line3 for order=2; with cell data "subdomain", "patch", "curve" and "corner" (0 on
    the blocks a label does not apply to)."""
    import meshio
    import numpy as np

    if len(m.tet_mid_nodes) or len(m.triangle_mid_nodes):  # order=2
        mid = np.asarray(m.tet_mid_nodes)
        blocks = [("tetra10", np.hstack([m.tets, mid[:, [0, 1, 2, 3, 5, 4]]]), "subdomain",
                   m.tet_labels),  # VTK's edge order: 01, 12, 20, 03, 13, 23
                  ("triangle6", np.hstack([m.triangles, m.triangle_mid_nodes]), "patch",
                   m.triangle_labels),
                  ("line3", np.hstack([m.edges, np.asarray(m.edge_mid_nodes).reshape(-1, 1)]),
                   "curve", m.edge_labels)]
    else:
        blocks = [("tetra", m.tets, "subdomain", m.tet_labels),
                  ("triangle", m.triangles, "patch", m.triangle_labels),
                  ("line", m.edges, "curve", m.edge_labels)]
    blocks.append(("vertex", m.corners.reshape(-1, 1), "corner", m.corner_labels))
    blocks = [b for b in blocks if len(b[1]) > 0]
    cells = [(kind, np.array(conn)) for kind, conn, _, _ in blocks]
    cell_data = {}
    for key in ("subdomain", "patch", "curve", "corner"):
        cell_data[key] = [np.array(labels) if k == key else np.zeros(len(conn), dtype=np.int32)
                          for _, conn, k, labels in blocks]
    if len(m.tet_partition):  # partitions=N: the tetrahedra's, 0 on the other blocks
        cell_data["partition"] = [np.array(m.tet_partition) if k == "subdomain"
                                  else np.zeros(len(conn), dtype=np.int32)
                                  for _, conn, k, _ in blocks]
    return meshio.Mesh(np.array(m.points), cells, cell_data=cell_data)


def _write(m, path, binary=False, ascii=False, format=None):
    """Writes .msh (Gmsh 4.1, or 2.2 with format="msh22"), .mesh (Medit) or .vtu (VTK) as
    the CLI's -o does, atomically, never over the input file; binary=True / ascii=True are
    --binary / --ascii (default: binary above 1e6 elements)."""
    args = (["--binary"] if binary else []) + (["--ascii"] if ascii else [])
    if format is not None:
        args.append(f"--format={format}")
    m._write(path, args)


Mesh.to_meshio = to_meshio
Mesh.write = _write
