#!/usr/bin/env python3
"""A mutation campaign against the rdmesh command line, as a hostile user would run it.

usage: cli_campaign.py RDMESH SEED... [--runs N] [--timeout S] [--seed K] [--keep DIR]

Each run takes one seed file, applies one to three random mutations to its bytes
(a line deleted, duplicated or swapped; a number replaced by INF, NaN, 1E-320,
1E308, -0, 2^63 or a huge count; an entity or keyword renamed as another one of
the file; the file truncated; bytes flipped) and runs

    RDMESH MUTANT -o out.mesh -q --no-exude --time-limit 10

in an empty directory, with a wall-clock limit. A run keeps the contract when it
exits 0 (a mesh), 2 (one line "rdmesh: error: FILE: ..." on stderr, no output
file) or 4 (refused by the fidelity check or the time limit, no output file), and
leaves no temporary file. A signal, exit 3, a time-out, a second stderr line on
exit 2, or a leftover file is a finding: the mutant is kept in --keep (default
build-fuzz/cli_findings). The table per input extension goes to stdout; the exit
code is 1 when anything was found. libFuzzer's targets (fuzz/, scripts/fuzz.sh)
cover the readers in-process; this covers the whole CLI, the isolated CAD reader
included.
"""
import argparse
import collections
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

NUMBERS = [b"INF", b"-INF", b"NAN", b"1.E-320", b"1.E308", b"-0.", b"9223372036854775808",
           b"4294967295", b"1000000000000", b"0", b"-1"]
NUMBER = re.compile(rb"-?\d+\.?\d*(?:[eE][-+]?\d+)?")
WORD = re.compile(rb"[A-Z_][A-Z_0-9]{2,}")


def mutate(data, rng):
    lines = data.split(b"\n")
    kind = rng.randrange(7)
    if kind == 0 and len(lines) > 2:  # delete a line
        del lines[rng.randrange(len(lines))]
    elif kind == 1 and len(lines) > 2:  # duplicate a line
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
    elif kind == 2 and len(lines) > 2:  # swap two lines
        i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
    elif kind == 3:  # a number becomes something hostile
        i = rng.randrange(len(lines))
        spots = list(NUMBER.finditer(lines[i]))
        if spots:
            m = rng.choice(spots)
            lines[i] = lines[i][:m.start()] + rng.choice(NUMBERS) + lines[i][m.end():]
    elif kind == 4:  # an entity or keyword renamed as another of the file
        words = WORD.findall(data)
        if words:
            i = rng.randrange(len(lines))
            spots = list(WORD.finditer(lines[i]))
            if spots:
                m = rng.choice(spots)
                lines[i] = lines[i][:m.start()] + rng.choice(words) + lines[i][m.end():]
    elif kind == 5:  # truncated
        return data[:rng.randrange(len(data) + 1)]
    else:  # bytes flipped
        b = bytearray(data)
        for _ in range(rng.randrange(1, 8)):
            if b:
                b[rng.randrange(len(b))] = rng.randrange(256)
        return bytes(b)
    return b"\n".join(lines)


def run_one(rdmesh, seed_path, data, timeout, workdir):
    ext = os.path.splitext(seed_path)[1]
    for name in os.listdir(workdir):
        os.remove(os.path.join(workdir, name))
    inputdir = tempfile.mkdtemp(prefix="in_", dir=os.path.dirname(workdir))
    path = os.path.join(inputdir, "mutant" + ext)
    with open(path, "wb") as f:
        f.write(data)
    cmd = [rdmesh, path, "-o", "out.mesh", "-q", "--no-exude", "--time-limit", "10"]
    try:
        p = subprocess.run(cmd, cwd=workdir, capture_output=True, timeout=timeout)
        code, err = p.returncode, p.stderr.decode(errors="replace")
    except subprocess.TimeoutExpired:
        code, err = "hang", ""
    left = sorted(os.listdir(workdir))
    shutil.rmtree(inputdir)
    problem = ""
    if code == "hang":
        problem = "hang"
    elif code < 0:
        problem = "signal %d" % -code
    elif code == 3:
        problem = "exit 3: " + err.strip()[:200]
    elif code == 2 and (err.count("\n") != 1 or not err.startswith("rdmesh: error: ")):
        problem = "exit 2 without one error line"
    elif code in (2, 4) and left:
        problem = "exit %d left %s" % (code, left)
    elif code == 0 and left != ["out.mesh"]:
        problem = "exit 0 left %s" % left
    elif code not in (0, 2, 4):
        problem = "exit %d" % code
    return code, problem


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("rdmesh")
    ap.add_argument("seeds", nargs="+")
    ap.add_argument("--runs", type=int, default=1000)
    ap.add_argument("--timeout", type=float, default=30)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--keep", default="build-fuzz/cli_findings")
    args = ap.parse_args()
    rng = random.Random(args.seed)
    seeds = [(p, open(p, "rb").read()) for p in args.seeds]
    base = tempfile.mkdtemp(prefix="rdmesh_cli_campaign_")
    workdir = os.path.join(base, "work")
    os.makedirs(workdir)
    table = collections.defaultdict(collections.Counter)
    findings = 0
    for k in range(args.runs):
        seed_path, data = rng.choice(seeds)
        for _ in range(rng.randrange(1, 4)):
            data = mutate(data, rng)
        ext = os.path.splitext(seed_path)[1].lower()
        code, problem = run_one(args.rdmesh, seed_path, data, args.timeout, workdir)
        table[ext]["runs"] += 1
        table[ext]["exit %s" % code] += 1
        if problem:
            findings += 1
            table[ext]["findings"] += 1
            os.makedirs(args.keep, exist_ok=True)
            name = os.path.join(args.keep, "finding_%d%s" % (k, ext))
            with open(name, "wb") as f:
                f.write(data)
            print("finding: %s: %s" % (name, problem), file=sys.stderr, flush=True)
        if (k + 1) % 500 == 0:
            print_table(table, sys.stderr)
    shutil.rmtree(base)
    print_table(table, sys.stdout)
    return 1 if findings else 0


def print_table(table, out):
    columns = ["runs", "exit 0", "exit 2", "exit 4", "exit 3", "hang", "findings"]
    print("| input | " + " | ".join(columns) + " | other |", file=out)
    print("|---" * (len(columns) + 2) + "|", file=out)
    for ext, c in sorted(table.items()):
        other = sum(v for key, v in c.items() if key not in columns)  # signals, exit 1
        print("| %s | %s | %d |" % (ext, " | ".join(str(c[col]) for col in columns), other),
              file=out, flush=True)


if __name__ == "__main__":
    sys.exit(main())
