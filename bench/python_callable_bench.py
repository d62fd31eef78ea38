"""rdmesh.mesh_implicit: a numpy-vectorised Python callable against the same domain
given as an expression string (the anchor), in the same run.

The issue's goal: the callable within 3x of the expression. Both sides mesh the
same function with the same criteria; the expression is compiled (muparser) and
evaluated in C++, the callable is called through the batch contract (the box
sampling's grid as one numpy call, every other query with three floats).

Run (after the normal build):
  PYTHONPATH=build/python python3 bench/python_callable_bench.py [--repeat N] [--case NAME]
      [--oracle]
Prints a Markdown table: median seconds of N runs per side (the sides alternate),
evaluations of the callable, and the ratio callable / expression.
"""

import argparse
import importlib.util
import math
import pathlib
import statistics
import sys
import time

import numpy as np

import rdmesh

CASES = {
    # name: (expression, numpy callable, math-module callable (vectorized=False), bbox, size)
    "sphere-0.05": ("x^2 + y^2 + z^2 - 1",
                    lambda x, y, z: x * x + y * y + z * z - 1,
                    lambda x, y, z: x * x + y * y + z * z - 1,
                    (-1.2, -1.2, -1.2, 1.2, 1.2, 1.2), 0.05),
    "torus-0.05": ("(sqrt(x^2 + y^2) - 1)^2 + z^2 - 0.16",
                   lambda x, y, z: (np.sqrt(x * x + y * y) - 1) ** 2 + z * z - 0.16,
                   lambda x, y, z: (math.sqrt(x * x + y * y) - 1) ** 2 + z * z - 0.16,
                   (-1.6, -1.6, -0.6, 1.6, 1.6, 0.6), 0.05),
}


def timed(f, bbox, size, vectorized=True):
    start = time.perf_counter()
    m = rdmesh.mesh_implicit(f, bbox=bbox, size=size, vectorized=vectorized)
    return time.perf_counter() - start, len(m.tets)


def counting(f):
    calls = [0]

    def g(x, y, z):
        calls[0] += 1
        return f(x, y, z)

    return g, calls


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--case", action="append", choices=sorted(CASES))
    ap.add_argument("--oracle", action="store_true",
                    help="also samples/python_oracle.py's Ball against the expression")
    args = ap.parse_args()
    print("| case | expression s (anchor) | numpy callable s | ratio | math callable s | ratio "
          "| callable calls | tets expr / callable |")
    print("|---|---|---|---|---|---|---|---|")
    worst = 0.0
    for name in args.case or list(CASES):
        expr, vec, scalar, bbox, size = CASES[name]
        times = {"expr": [], "vec": [], "scalar": []}
        tets = {}
        for r in range(args.repeat):
            order = ["expr", "vec", "scalar"] if r % 2 == 0 else ["scalar", "vec", "expr"]
            for side in order:
                f = {"expr": expr, "vec": vec, "scalar": scalar}[side]
                t, n = timed(f, bbox, size, vectorized=side != "scalar")
                times[side].append(t)
                tets[side] = n
                print(f"{name} {side} run {r + 1}: {t:.3f} s, {n} tets", file=sys.stderr)
        g, calls = counting(vec)
        rdmesh.mesh_implicit(g, bbox=bbox, size=size)
        med = {k: statistics.median(v) for k, v in times.items()}
        ratio_vec = med["vec"] / med["expr"]
        ratio_scalar = med["scalar"] / med["expr"]
        worst = max(worst, ratio_vec)
        print(f"| {name} | {med['expr']:.3f} | {med['vec']:.3f} | {ratio_vec:.2f} | "
              f"{med['scalar']:.3f} | {ratio_scalar:.2f} | {calls[0]} | "
              f"{tets['expr']} / {tets['vec']} |")
    print(f"\nworst numpy-callable / expression ratio: {worst:.2f} (goal: <= 3)")
    if args.oracle:
        oracle_table(args.repeat)


def oracle_table(repeat):
    """samples/python_oracle.py's Ball (an rdmesh.Oracle subclass) against the same ball
    as an expression, same criteria, same run."""
    path = pathlib.Path(__file__).resolve().parents[1] / "samples" / "python_oracle.py"
    spec = importlib.util.spec_from_file_location("python_oracle", path)
    sample = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(sample)
    size = 0.1
    box = (-1.2, -1.2, -1.2, 1.2, 1.2, 1.2)
    times = {"expr": [], "oracle": []}
    tets = {}
    for r in range(repeat):
        for side in (["expr", "oracle"] if r % 2 == 0 else ["oracle", "expr"]):
            start = time.perf_counter()
            if side == "expr":
                m = rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=box, size=size)
            else:
                m = rdmesh.mesh_oracle(sample.Ball((0, 0, 0), 1.0), size=size)
            times[side].append(time.perf_counter() - start)
            tets[side] = len(m.tets)
    e, o = statistics.median(times["expr"]), statistics.median(times["oracle"])
    print("\n| ball r=1, size 0.1 | expression s (anchor) | rdmesh.Oracle subclass s | ratio "
          "| tets expr / oracle |")
    print("|---|---|---|---|---|")
    print(f"| sphere | {e:.3f} | {o:.3f} | {o / e:.1f} | {tets['expr']} / {tets['oracle']} |")


if __name__ == "__main__":
    main()
