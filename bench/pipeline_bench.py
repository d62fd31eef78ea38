#!/usr/bin/env python3
"""Whole-pipeline benchmark: rdmesh with 1 and 2 threads vs Gmsh HXT and CGAL Mesh_3.

usage: pipeline_bench.py BUILD_DIR [DATA_DIR] [--repeat R] [--large] [--cgal PATH]
                         [--cgal-repeat C] [--out TABLE.md]

Cases: the unit sphere (samples/sphere.json for rdmesh, an OpenCASCADE sphere
for Gmsh) at rdmesh sizes 0.05 and 0.025 (about 150 k and 1.1 M tetrahedra;
--large adds 0.0125, about 9.5 M), and two shared STEP files (DATA_DIR/step:
gmsh_Zylkopf.stp and occtsample_ANC101.step) with rdmesh's default sizes. Gmsh
runs at the size that gives about as many tets as rdmesh (issue 19 compares at
the same element count): one calibration run at rdmesh's size (STEP: diagonal /
20), scaled once by the cube root of the two counts; the case name gives the
sphere's Gmsh (and CGAL) size. The table has both counts, and microseconds per tet.

CGAL Mesh_3 rows come from bench/rdmesh_cgal_pipeline (--cgal PATH, default
BUILD_DIR/bench/rdmesh_cgal_pipeline, built in a -DRDMESH_BUILD_BENCH=ON tree;
without it the CGAL rows are left out): make_mesh_3 with its default perturb and
exude, sequential, and with CGAL::Parallel_tag on 2 TBB threads when the binary
was built with TBB. Its size is calibrated to rdmesh's count as Gmsh's is. The
sphere is the implicit x^2 + y^2 + z^2 - 1 in sphere.json's box [-1.2, 1.2]^3.
CGAL cannot read STEP: its STEP rows mesh a closed triangle surface that Gmsh
makes once per case, untimed (`gmsh FILE -2 -clmax h/3`, sharp edges above 60
degrees protected), so they mesh a tessellation, not the exact B-rep, and the
tessellation's time is not in CGAL's wall time.

Each command is the whole run as a user starts it (read, mesh, write a Medit
.mesh file; rdmesh also writes no report): `rdmesh IN -o OUT.mesh -q --threads
N`, `gmsh IN -3 -algo hxt -nt N -o OUT.mesh` and `rdmesh_cgal_pipeline IN --size
H [--parallel --threads 2] -o OUT.mesh`. The commands of a case run one after
the other, R times (default 3), alternating, and the fastest wall time of each
counts; the CGAL rows run in the first C of those rounds only (--cgal-repeat C,
1 <= C, default R: CGAL's sequential run of the 9.5 M sphere alone takes 8-9
minutes; its calibration run, before the rounds, is not skipped). Peak memory
is the child's maximum resident set (/usr/bin/time -f %M). Tets and the minimum
dihedral angle are read back from each .mesh file here, the same way for every
tool (numpy; not timed). A tool that fails
has a row "failed: " and its last line of stderr. The md5 column is the digest
of rdmesh's output file of each thread count: equal digests across thread
counts and repeats are the determinism claim. The ratio column is rdmesh's wall
time over Gmsh HXT's with the same thread count (< 1: rdmesh faster). Needs
numpy (Debian python3-numpy, installed by scripts/install-deps.sh) to read the
meshes back.
"""
import argparse
import collections
import hashlib
import math
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy


def run(cmd, cwd):
    """Wall time (s), peak RSS (MB) and exit status of `cmd`.

    The peak comes from /usr/bin/time -f %M: the child's own rusage (/usr/bin/time -f %M)
    starts at this process's resident size, which grows as it reads meshes back."""
    with tempfile.TemporaryFile() as stderr, tempfile.NamedTemporaryFile("r") as peak:
        t0 = time.monotonic()
        p = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", peak.name] + cmd, cwd=cwd,
                           stdout=subprocess.DEVNULL, stderr=stderr)
        wall = time.monotonic() - t0
        stderr.seek(0)
        err = stderr.read().decode(errors="replace").strip().splitlines()
        text = peak.read().strip().splitlines()
        rss = float(text[-1]) / 1024.0 if text and text[-1].isdigit() else float("nan")
    return wall, rss, p.returncode, (err[-1] if err else "")


def read_medit_tets(path):
    """Vertices (n x 3 floats) and tetrahedra (m x 4, 0-based) of an ASCII Medit .mesh file.

    Each section's numbers are parsed by numpy in one call: a 9.5 M-tet file
    takes seconds, where splitting it into Python strings took minutes and
    gigabytes."""
    with open(path, "rb") as f:
        data = f.read()

    def section(key, width):
        m = re.search(rb"^\s*" + key + rb"\s+(\d+)\s*$", data, re.MULTILINE)
        if not m:
            return numpy.zeros((0, width))
        n = int(m.group(1))
        # The section's rows, up to the next keyword (a line starting with a letter).
        nxt = re.compile(rb"^[ \t]*[A-Za-z]", re.MULTILINE).search(data, m.end())
        body = data[m.end():nxt.start() if nxt else len(data)]
        values = numpy.array(body.split(), dtype=numpy.float64)
        return values[:n * width].reshape(n, width)

    vertices = section(b"Vertices", 4)[:, :3]
    tets = section(b"Tetrahedra", 5)[:, :4].astype(numpy.int64) - 1
    return vertices, tets


def min_dihedral_deg(vertices, tets, chunk=1 << 20):
    """The smallest dihedral angle over all tets (degrees), from outward face normals."""
    if len(tets) == 0:
        return 0.0
    faces = ((1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2))
    worst = -1.0
    for start in range(0, len(tets), chunk):
        p = vertices[tets[start:start + chunk]]  # (m, 4, 3)
        normals = []
        for k, (a, b, c) in enumerate(faces):
            n = numpy.cross(p[:, b] - p[:, a], p[:, c] - p[:, a])
            inward = numpy.einsum("ij,ij->i", n, p[:, k] - p[:, a]) > 0
            n[inward] *= -1
            length = numpy.linalg.norm(n, axis=1)
            if numpy.any(length == 0):
                return 0.0
            normals.append(n / length[:, None])
        for k in range(4):
            for l in range(k + 1, 4):
                c = -numpy.einsum("ij,ij->i", normals[k], normals[l])
                worst = max(worst, float(c.max()))
    return math.degrees(math.acos(max(-1.0, min(1.0, worst))))


def md5(path):
    h = hashlib.md5()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def exit_status(cmd):
    """The exit status of cmd, its output discarded (calibration runs, not timed)."""
    return subprocess.run(cmd, capture_output=True).returncode


def rdmesh_reference(args, rd_args, out):
    """rdmesh with rd_args on 2 threads into out: the count every tool is
    calibrated on. False, with a line on stderr, when it fails."""
    p = subprocess.run([args.rdmesh] + rd_args + ["-q", "--threads", "2", "-o", out],
                       capture_output=True, text=True)
    if p.returncode != 0:
        print("%s: rdmesh failed (%s): skipped" % (os.path.basename(rd_args[0]), p.stderr.strip()),
              file=sys.stderr)
    return p.returncode == 0


def calibrated_h(tool_run, h, target, out):
    """The size h scaled once by the cube root of the counts, so that a tool
    makes about `target` tets (h itself when that run fails or is empty).
    tool_run(h, out) runs the tool once at size h and returns its exit status."""
    if tool_run(h, out) == 0:
        got = len(read_medit_tets(out)[1])
        if got > 0:
            h *= (got / target) ** (1.0 / 3.0)
    return h


# One case of the table: each tool's arguments before its output options. cgal is
# None when there are no CGAL rows or CGAL cannot run (cgal_error says why).
Case = collections.namedtuple("Case", "name rdmesh gmsh cgal cgal_error")
# One row of the table; a tool that failed has only `failed`, why.
Row = collections.namedtuple("Row", "case tool wall tets angle rss ratio digest failed",
                             defaults=(None,) * 7)


def cgal_args(args, cgal_input, h, target, out):
    """CGAL's arguments at the size calibrated on rdmesh's `target` tets (one
    sequential run at rdmesh's size h)."""
    ch = calibrated_h(lambda size, dest: exit_status(
        [args.cgal, cgal_input, "--size", repr(size), "-o", dest]), h, target, out)
    return [cgal_input, "--size", repr(ch)]


def cgal_surface(args, step, h, surface):
    """Gmsh's closed triangle surface of a STEP file at -clmax h / 3, for CGAL (it
    cannot read STEP); made once per case, not timed. "" or why it failed."""
    p = subprocess.run([args.gmsh, step, "-2", "-clmax", repr(h / 3), "-o", surface],
                       capture_output=True, text=True)
    if p.returncode != 0 or not os.path.exists(surface):
        lines = p.stderr.strip().splitlines() or p.stdout.strip().splitlines() or [""]
        return "gmsh tessellation: exit %d %s" % (p.returncode, lines[-1])
    return ""


def cases(args, repo, scratch):
    """Yields the Cases: Gmsh and CGAL at the sizes that give about as many tets
    as rdmesh (issue 19 compares at the same element count)."""
    sphere = os.path.join(repo, "samples", "sphere.json")
    out = os.path.join(scratch, "calibrate.mesh")
    sizes = [0.05, 0.025] + ([0.0125] if args.large else [])
    for h in sizes:
        geo = os.path.join(scratch, "sphere_%g.geo" % h)

        def write_geo(size):
            with open(geo, "w") as f:
                f.write('SetFactory("OpenCASCADE");\nSphere(1) = {0, 0, 0, 1};\n'
                        "Mesh.CharacteristicLengthMax = %r;\nMesh.CharacteristicLengthMin = %r;\n"
                        % (size, size))

        def gmsh_sphere(size, out):
            write_geo(size)
            return exit_status([args.gmsh, geo, "-3", "-algo", "hxt", "-nt", "2", "-o", out])

        rd_args = [sphere, "--size", str(h)]
        if not rdmesh_reference(args, rd_args, out):
            continue
        target = len(read_medit_tets(out)[1])
        gh = calibrated_h(gmsh_sphere, h, target, out)
        write_geo(gh)
        name = "sphere h=%g (gmsh %.4g)" % (h, gh)
        cgal = None
        if args.cgal:
            # shapes.h's sphere: sphere.json's function in sphere.json's box.
            cgal = cgal_args(args, "sphere", h, target, out)
            name = name[:-1] + ", cgal %.4g)" % float(cgal[-1])
        yield Case(name, rd_args, [geo], cgal, "")
    for name in ("gmsh_Zylkopf.stp", "occtsample_ANC101.step"):
        path = os.path.join(args.data_dir, "step", name)
        if not os.path.exists(path):
            print("missing %s: skipped" % path, file=sys.stderr)
            continue
        # From diagonal / 20 (rdmesh's CAD sizes also follow curvature and thin
        # parts, Gmsh's -clmax alone does not).
        if not rdmesh_reference(args, [path], out):
            continue
        vertices, tets = read_medit_tets(out)
        target = len(tets)
        h = float(numpy.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0))) / 20
        gh = calibrated_h(lambda size, out: exit_status(
            [args.gmsh, path, "-3", "-algo", "hxt", "-nt", "2", "-clmax", repr(size), "-o", out]),
            h, target, out)
        cgal, cgal_error = None, ""
        if args.cgal:
            surface = os.path.join(scratch, os.path.splitext(name)[0] + ".stl")
            cgal_error = cgal_surface(args, path, h, surface)
            if not cgal_error:
                cgal = cgal_args(args, surface, h, target, out)
        yield Case(name, [path], [path, "-clmax", repr(gh)], cgal, cgal_error)


def find_cgal(args):
    """args.cgal: the rdmesh_cgal_pipeline binary (absolute: the tools run in the
    scratch folder), None when absent; args.cgal_parallel: built with TBB."""
    args.cgal = os.path.abspath(args.cgal or os.path.join(args.build_dir, "bench",
                                                          "rdmesh_cgal_pipeline"))
    args.cgal_parallel = False
    if not os.path.exists(args.cgal):
        print("warning: no %s (bench/README.md says how to build it): no CGAL rows" % args.cgal,
              file=sys.stderr)
        args.cgal = None
        return
    version = subprocess.run([args.cgal, "--version"], capture_output=True, text=True)
    print("rdmesh_cgal_pipeline: %s" % version.stdout.strip(), file=sys.stderr)
    args.cgal_parallel = "Parallel_tag" in version.stdout
    if not args.cgal_parallel:
        print("CGAL parallel (Parallel_tag on TBB) is unavailable in this build: no "
              "'cgal mesh_3 par' rows", file=sys.stderr)


def tools_of(args, case):
    """(label, threads, command of the output file or None: cannot run) per row."""
    tools = []
    for n in (1, 2):
        tools.append(("rdmesh -t%d" % n, n, lambda out, n=n: [args.rdmesh] + case.rdmesh +
                      ["-q", "--threads", str(n), "-o", out]))
    for n in (1, 2):
        tools.append(("gmsh hxt -nt%d" % n, n, lambda out, n=n: [args.gmsh] + case.gmsh +
                      ["-3", "-algo", "hxt", "-nt", str(n), "-o", out]))
    if args.cgal:
        variants = [("cgal mesh_3 seq", 1, [])]
        if args.cgal_parallel:
            variants.append(("cgal mesh_3 par -t2", 2, ["--parallel", "--threads", "2"]))
        for label, n, extra in variants:
            cmd = None if case.cgal is None else (
                lambda out, extra=extra: [args.cgal] + case.cgal + extra + ["-o", out])
            tools.append((label, n, cmd))
    return tools


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    data = os.environ.get("RDMESH_DATA_DIR") or os.path.join(here, "..", "..", "shared", "data")
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build_dir")
    ap.add_argument("data_dir", nargs="?", default=os.path.normpath(data))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--large", action="store_true", help="also the sphere at ~9.5 M tets")
    ap.add_argument("--gmsh", default="gmsh")
    ap.add_argument("--cgal", help="rdmesh_cgal_pipeline (default: "
                    "BUILD_DIR/bench/rdmesh_cgal_pipeline; absent: no CGAL rows)")
    ap.add_argument("--cgal-repeat", type=int, help="run the CGAL rows in the first C rounds "
                    "only (default: --repeat)")
    ap.add_argument("--out", help="also write the table to this Markdown file")
    args = ap.parse_args()
    if args.repeat < 1:
        ap.error("--repeat must be at least 1")
    if args.cgal_repeat is not None and args.cgal_repeat < 1:
        ap.error("--cgal-repeat must be at least 1")
    args.cgal_repeat = min(args.cgal_repeat or args.repeat, args.repeat)
    args.rdmesh = os.path.abspath(os.path.join(args.build_dir, "cli", "rdmesh"))
    find_cgal(args)
    repo = os.path.normpath(os.path.join(here, ".."))
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for case in list(cases(args, repo, scratch)):
            name = case.name
            tools = tools_of(args, case)
            best = {}
            digests = {}
            failures = {label: case.cgal_error for label, _, cmd in tools if cmd is None}
            for r in range(args.repeat):
                for label, n, cmd in tools:
                    if cmd is None or (label.startswith("cgal") and r >= args.cgal_repeat):
                        continue
                    out = os.path.join(scratch, "%s_%d.mesh" % (label.replace(" ", "_"), r))
                    wall, rss, code, err = run(cmd(out), scratch)
                    if code != 0:
                        print("%s %s: exit %d %s" % (name, label, code, err), file=sys.stderr)
                        failures[label] = "exit %d %s" % (code, err)
                        continue
                    if label.startswith("rdmesh"):
                        digests.setdefault(label, set()).add(md5(out))
                    if label not in best or wall < best[label][0]:
                        if label in best and best[label][2] != out:
                            os.remove(best[label][2])
                        best[label] = (wall, rss, out)
                    else:
                        os.remove(out)
                    print("%s %s run %d: %.2f s, %.0f MB" % (name, label, r + 1, wall, rss),
                          file=sys.stderr)
            for label, n, _ in tools:
                if label not in best:
                    rows.append(Row(name, label, failed=failures.get(label, "")))
                    continue
                wall, rss, out = best[label]
                vertices, tets = read_medit_tets(out)
                anchor = best.get("gmsh hxt -nt%d" % n)
                ratio = wall / anchor[0] if anchor and label.startswith("rdmesh") else None
                digest = ",".join(sorted(d[:8] for d in digests.get(label, ())))
                rows.append(Row(name, label, wall, len(tets), min_dihedral_deg(vertices, tets), rss,
                                ratio, digest))
    lines = ["| case | tool | wall s | tets | us/tet | min dihedral deg | peak MB "
             "| / HXT same threads | md5 |",
             "|---|---|---:|---:|---:|---:|---:|---:|---|"]
    for row in rows:
        if row.failed is not None:
            lines.append("| %s | %s | failed: %s | | | | | | |"
                         % (row.case, row.tool, row.failed.replace("|", "/")[:120]))
            continue
        lines.append("| %s | %s | %.2f | %d | %.2f | %.2f | %.0f | %s | %s |" % (
            row.case, row.tool, row.wall, row.tets, 1e6 * row.wall / max(row.tets, 1), row.angle,
            row.rss, "%.2f" % row.ratio if row.ratio else "", row.digest))
    table = "\n".join(lines)
    print(table)
    if args.out:
        with open(args.out, "w") as f:
            f.write(table + "\n")


if __name__ == "__main__":
    main()
