#!/usr/bin/env python3
"""The cost of reading CAD files in an isolated child process (CadOptions::isolate).

usage: cad_read_bench.py BUILD_DIR [DATA_DIR] [--repeat R]

For each file of DATA_DIR/step and DATA_DIR/brep (default: ../shared/data beside the
checkout, or $RDMESH_DATA_DIR), `rdmesh_cad_tool load in-process|isolated FILE` loads it
(read, sew, check, build the oracle) R times each way, alternately (default 3); the
fastest of each counts. Prints a Markdown table with the difference and the median over
the files of the extra seconds and of (isolated - in-process) / in-process: what a run
pays for the isolation. The anchor is the in-process read of the same file in the same run.
"""
import argparse
import glob
import os
import statistics
import subprocess
import sys


def load_seconds(tool, mode, path):
    p = subprocess.run([tool, "load", mode, path], capture_output=True, text=True, timeout=300)
    if p.returncode != 0:
        return None
    return float(p.stdout.strip())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    here = os.path.dirname(os.path.abspath(__file__))
    default_data = os.environ.get("RDMESH_DATA_DIR",
                                  os.path.join(here, "..", "..", "shared", "data"))
    ap.add_argument("data", nargs="?", default=default_data)
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    tool = os.path.join(a.build, "cad", "rdmesh_cad_tool")
    files = sorted(glob.glob(os.path.join(a.data, "step", "*")) +
                   glob.glob(os.path.join(a.data, "brep", "*")))
    if not files:
        sys.exit("no CAD files under %s" % a.data)
    print("| file | in-process (s) | isolated (s) | extra (s) | extra |")
    print("|---|---|---|---|---|")
    ratios, extras = [], []
    for f in files:
        best = {"in-process": None, "isolated": None}
        for _ in range(a.repeat):
            for mode in best:
                t = load_seconds(tool, mode, f)
                if t is not None and (best[mode] is None or t < best[mode]):
                    best[mode] = t
        if None in best.values():
            print("| %s | failed | | |" % os.path.basename(f))
            continue
        extra = (best["isolated"] - best["in-process"]) / best["in-process"]
        ratios.append(extra)
        extras.append(best["isolated"] - best["in-process"])
        print("| %s | %.3f | %.3f | %+.3f | %+.1f%% |" %
              (os.path.basename(f), best["in-process"], best["isolated"], extras[-1], 100 * extra))
    print("\nmedian over %d files: %+.3f s, %+.1f%% of the in-process load" %
          (len(ratios), statistics.median(extras), 100 * statistics.median(ratios)))


if __name__ == "__main__":
    main()
