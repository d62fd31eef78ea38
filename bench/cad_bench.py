#!/usr/bin/env python3
"""CAD benchmark: rdmesh vs Gmsh (Delaunay and HXT) on STEP/BREP files at the same target size.

usage: cad_bench.py BUILD_DIR [DATA_DIR] [--timeout S] [--divisions N] [--repeat R] [--out TABLE.md]

For each file of DATA_DIR/step and DATA_DIR/brep: the target size is h = bbox
diagonal / N (default 20). rdmesh runs with its defaults when N is 20 (that is its
default size; on CAD models its sizes then also follow slender parts), else with
`--size h`; an exit 4 (the mesh failed rdmesh's fidelity check against the model)
is a failure. Gmsh runs `gmsh FILE -3 -nt 1 -clmax h` (its default 3D algorithm,
Delaunay) and the same with `-algo hxt`. All outputs are read back here (Gmsh .msh
4.1 ASCII, pure Python): tets, min dihedral angle and volume error against
OpenCASCADE's exact volume (rdmesh_cad_tool info).

Times are wall clock of the whole command (process start, reading the file,
meshing, writing .msh). rdmesh also writes its quality report (--report: the
distance of every boundary triangle to its exact face, a check Gmsh does not
make); its own timer for that step is subtracted, and the ratio column is
rdmesh / Gmsh on those times (< 1: rdmesh faster). Each file is meshed R times
by each tool, alternately (default 3), and the fastest run of each counts: on a
shared machine a single run of either can be 30% slow. The last lines summarise
successes and the median ratio over the files both meshers succeeded on.
"""
import argparse
import glob
import json
import math
import os
import subprocess
import sys
import tempfile
import time


def run(cmd, timeout):
    t0 = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, time.monotonic() - t0, "timeout after %.0f s" % timeout
    dt = time.monotonic() - t0
    if p.returncode != 0:
        lines = (p.stderr.strip() or p.stdout.strip()).splitlines()
        return None, dt, "exit %d: %s" % (p.returncode, lines[-1] if lines else "")
    return p, dt, ""


def read_msh_tets(path):
    """Nodes and 4-node tetrahedra of an ASCII Gmsh 4.1 file."""
    nodes, tets = {}, []
    with open(path) as f:
        lines = iter(f.read().split("\n"))
    for line in lines:
        if line == "$Nodes":
            nblocks = int(next(lines).split()[0])
            for _ in range(nblocks):
                _, _, _, n = map(int, next(lines).split())
                tags = [int(next(lines)) for _ in range(n)]
                for t in tags:
                    nodes[t] = tuple(map(float, next(lines).split()[:3]))
        elif line == "$Elements":
            nblocks = int(next(lines).split()[0])
            for _ in range(nblocks):
                _, _, etype, n = map(int, next(lines).split())
                for _ in range(n):
                    v = list(map(int, next(lines).split()))
                    if etype == 4:
                        tets.append(v[1:5])
    return nodes, tets


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def tet_measures(nodes, tets):
    """(total |volume|, min dihedral angle in degrees)."""
    vol, min_dih = 0.0, 180.0
    faces = ((1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1))
    for t in tets:
        p = [nodes[i] for i in t]
        v6 = dot(sub(p[1], p[0]), cross(sub(p[2], p[0]), sub(p[3], p[0])))
        vol += abs(v6) / 6
        n = [cross(sub(p[b], p[a]), sub(p[c], p[a])) for a, b, c in faces]
        for k in range(4):
            for l in range(k + 1, 4):
                nk, nl = n[k], n[l]
                d = math.sqrt(dot(nk, nk) * dot(nl, nl))
                if d == 0:
                    min_dih = 0.0
                    continue
                c = max(-1.0, min(1.0, dot(nk, nl) / d))  # outward normals: both flip together
                min_dih = min(min_dih, 180 - math.degrees(math.acos(c)))
    return vol, min_dih


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    # The shared data beside the checkout (../shared/data), or $RDMESH_DATA_DIR.
    data = os.environ.get("RDMESH_DATA_DIR") or os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "data")
    ap.add_argument("data_dir", nargs="?", default=os.path.normpath(data))
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--divisions", type=float, default=20)
    ap.add_argument("--repeat", type=int, default=3,
                    help="runs of each tool per file, alternately; the fastest counts")
    ap.add_argument("--out", default="")
    args = ap.parse_args()
    rdmesh = os.path.join(args.build, "cli", "rdmesh")
    tool = os.path.join(args.build, "cad", "rdmesh_cad_tool")
    files = sorted(glob.glob(os.path.join(args.data_dir, "step", "*.st*p"))) + sorted(
        glob.glob(os.path.join(args.data_dir, "brep", "*.brep")))
    rows = []
    tmp = tempfile.mkdtemp(prefix="rdmesh_cad_bench_")
    gmsh_algos = (("delaunay", []), ("hxt", ["-algo", "hxt"]))
    for path in files:
        name = os.path.basename(path)
        info_p, _, err = run([tool, "info", path], args.timeout)
        if info_p is None:
            rows.append([name, "-"] + ["fail: " + err] * 3 + ["-", "-"])
            print(name, "info failed:", err, file=sys.stderr)
            continue
        info = json.loads(info_p.stdout)
        h = info["diagonal"] / args.divisions
        exact = info["volume"]
        out, rep = os.path.join(tmp, "r.msh"), os.path.join(tmp, "r.json")
        r_cmd = [rdmesh, path, "-o", out, "-q", "--report", rep]
        if args.divisions != 20:
            r_cmd += ["--size", repr(h)]
        times = {"rdmesh": None, "delaunay": None, "hxt": None}
        errors = {k: "" for k in times}
        for _ in range(max(1, args.repeat)):
            if not errors["rdmesh"]:  # without its quality report's distances
                p, dt, errors["rdmesh"] = run(r_cmd, args.timeout)
                if p is not None:
                    dt -= json.load(open(rep))["seconds"].get("report", 0.0)
                    times["rdmesh"] = dt if times["rdmesh"] is None else min(times["rdmesh"], dt)
            for algo, flags in gmsh_algos:
                if errors[algo]:
                    continue
                gout = os.path.join(tmp, algo + ".msh")
                p, dt, errors[algo] = run(["gmsh", path, "-3", "-nt", "1", "-clmax", repr(h)] +
                                          flags + ["-format", "msh41", "-o", gout], args.timeout)
                if p is not None:
                    times[algo] = dt if times[algo] is None else min(times[algo], dt)
        cells = []
        if errors["rdmesh"]:
            times["rdmesh"] = None
            cells.append("fail: " + errors["rdmesh"])
        else:
            r = json.load(open(rep))
            v = sum(s["volume"] for s in r["subdomains"])
            notes = []
            if r["guard"]["fired"]:
                notes.append("guard")
            if r.get("protection", {}).get("conflicts", 0):
                notes.append("%d ball conflicts" % r["protection"]["conflicts"])
            cells.append("%.2f s, %d tets, %.1f deg, %.2f%%%s" % (
                times["rdmesh"], r["tets"], r["min_dihedral_deg"], 100 * abs(v - exact) / exact,
                (" (" + ", ".join(notes) + ")") if notes else ""))
        for algo, _ in gmsh_algos:
            if errors[algo]:
                times[algo] = None
                cells.append("fail: " + errors[algo])
                continue
            nodes, tets = read_msh_tets(os.path.join(tmp, algo + ".msh"))
            if not tets:
                times[algo] = None
                cells.append("fail: no tetrahedron")
                continue
            v, dih = tet_measures(nodes, tets)
            cells.append("%.2f s, %d tets, %.1f deg, %.2f%%" % (times[algo], len(tets), dih,
                                                               100 * abs(v - exact) / exact))
        ratios = ["%.2f" % (times["rdmesh"] / times[a]) if times["rdmesh"] is not None and times[a]
                  else "-" for a, _ in gmsh_algos]
        rows.append([name, "%.4g" % h] + cells + ratios)
        print(" | ".join(rows[-1]), file=sys.stderr, flush=True)
    table = ["| file | h | rdmesh (time, tets, min dihedral, volume error) | gmsh -3 -nt 1 (same) "
             "| gmsh -3 -algo hxt -nt 1 (same) | ratio to gmsh | ratio to hxt |",
             "|---|---|---|---|---|---|---|"]
    table += ["| " + " | ".join(r) + " |" for r in rows]
    ok = [sum(1 for r in rows if not r[k].startswith("fail")) for k in (2, 3, 4)]
    summary = "rdmesh succeeded on %d of %d files, Gmsh on %d, HXT on %d." % (ok[0], len(rows),
                                                                          ok[1], ok[2])
    for k, label in ((3, "Gmsh"), (4, "HXT")):
        missed = [r[0] for r in rows if r[2].startswith("fail") and not r[k].startswith("fail")]
        ratios = sorted(float(r[k + 2]) for r in rows if r[k + 2] != "-")
        median = "-"
        if ratios:
            n = len(ratios)
            median = "%.2f" % (ratios[n // 2] if n % 2 else
                               0.5 * (ratios[n // 2 - 1] + ratios[n // 2]))
        summary += " rdmesh failed where %s succeeded: %s. Median time ratio rdmesh/%s over " \
                   "%d files: %s." % (label, ", ".join(missed) if missed else "none", label,
                                      len(ratios), median)
    table += ["", summary]
    text = "\n".join(table) + "\n"
    if args.out:
        open(args.out, "w").write(text)
    print(text)


if __name__ == "__main__":
    main()
