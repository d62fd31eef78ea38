#!/usr/bin/env bash
# Fuzzes the readers with libFuzzer (fuzz/): builds the targets into build-fuzz
# with clang, ASan and UBSan, then runs each target for SECONDS (default 60),
# one process at a time, and prints a table. Exits 1 on any finding (crash,
# leak, undefined behaviour, timeout, out-of-memory, an exception other than
# InputError); the inputs are in build-fuzz/findings/TARGET/.
#
#   bash scripts/fuzz.sh [SECONDS] [TARGET...]
#
# Default targets: off stl obj ply domain_json expression. The CAD targets step
# and brep run only when named: OpenCASCADE reads in the fuzzing process, where
# its crashes are expected until the CAD reading runs in an isolated child.
# Seeds are gathered at run time (samples/, ../shared/data or $RDMESH_DATA_DIR,
# fuzz/seeds/); the corpus each run grows stays in build-fuzz/corpus/TARGET.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
[ $# -gt 0 ] && shift
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(off stl obj ply domain_json expression)
data=${RDMESH_DATA_DIR:-../shared/data}
dir=build-fuzz

# Longest input per target: enough for small meshes and domain files, short
# enough to keep executions fast. domain_json stays far below the nesting depth
# (10^5 brackets) that overflows the stack in the JSON parser (a known open bug).
declare -A max_len=([off]=16384 [stl]=16384 [obj]=8192 [ply]=8192 [domain_json]=4096
                    [expression]=512 [step]=65536 [brep]=65536)

bash scripts/install-deps.sh --fuzz
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DRDMESH_FUZZ=ON -DRDMESH_SANITIZE=ON -DRDMESH_BUILD_TESTS=OFF >/dev/null
cmake --build "$dir" -j "${RDMESH_JOBS:-2}" --target "${targets[@]/#/rdmesh_fuzz_}" >/dev/null

# Copies the existing files among "$@" into the seed folder $seeds.
add_seeds() {
  local f
  for f in "$@"; do [ -f "$f" ] && cp "$f" "$seeds/"; done
  return 0
}

# Writes every expression of the sample domain files into $seeds, one per file.
expression_seeds() {
  python3 - "$seeds" samples/*.json <<'EOF'
import json, re, sys
out, n = sys.argv[1], 0
for path in sys.argv[2:]:
    text = re.sub(r"//[^\n]*", "", open(path).read())
    def walk(v):
        global n
        if isinstance(v, dict): [walk(x) for x in v.values()]
        elif isinstance(v, list): [walk(x) for x in v]
        elif isinstance(v, str) and any(c in v for c in "xyzt"):
            n += 1
            open(f"{out}/sample{n}.txt", "w").write(v)
    walk(json.loads(text))
EOF
}

status=0
rows=()
for t in "${targets[@]}"; do
  seeds=$dir/seeds/$t corpus=$dir/corpus/$t findings=$dir/findings/$t
  rm -rf "$seeds" && mkdir -p "$seeds" "$corpus" "$findings"
  [ -d "fuzz/seeds/$t" ] && add_seeds fuzz/seeds/"$t"/*
  case $t in
    off) add_seeds "$data"/mesh/*.off ;;
    stl) add_seeds "$data"/mesh/*.stl ;;
    # bad/junk.ply (an element of 9e18 items without properties) hangs the PLY
    # reader: a known open bug; seed it again once it is fixed.
    ply) for f in "$data"/bad/*.ply; do [ "${f##*/}" = junk.ply ] || add_seeds "$f"; done ;;
    domain_json) add_seeds samples/*.json ;;
    expression) expression_seeds ;;
    step) add_seeds "$data"/step/* "$data"/bad/*.st[ep]* samples/*.step ;;
    brep) add_seeds "$data"/brep/* "$data"/bad/*.brep ;;
  esac
  dict=()
  [ -f "fuzz/dicts/$t.dict" ] && dict=(-dict="fuzz/dicts/$t.dict")
  log=$dir/fuzz-$t.log
  before=$(find "$findings" -type f ! -name 'slow-unit-*' | wc -l)
  echo "fuzz: $t for ${seconds}s" >&2
  rc=0
  "$dir/fuzz/rdmesh_fuzz_$t" -max_total_time="$seconds" -max_len="${max_len[$t]}" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$findings/" "${dict[@]}" \
    "$corpus" "$seeds" >"$log" 2>&1 || rc=$?
  found=$(($(find "$findings" -type f ! -name 'slow-unit-*' | wc -l) - before))
  if [ "$rc" -ne 0 ] && [ "$found" -eq 0 ]; then found=1; fi
  if [ "$found" -ne 0 ]; then
    status=1
    echo "fuzz: $t: finding, see $log and $findings/" >&2
    grep -E '^(==[0-9]+==ERROR|SUMMARY|rdmesh fuzz:|.*runtime error)' "$log" | head -5 >&2 || true
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  rows+=("$t ${runs:-?} ${speed:-?} $(find "$corpus" -type f | wc -l) $found")
done

printf '%-12s %12s %8s %8s %9s\n' target executions exec/s corpus findings
for r in "${rows[@]}"; do
  # shellcheck disable=SC2086  # a row is five words
  printf '%-12s %12s %8s %8s %9s\n' $r
done
exit "$status"
