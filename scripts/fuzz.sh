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
# and brep run only when named: they read through the isolated child process
# (a fork per input, so few executions and no coverage guidance inside
# OpenCASCADE): a check that no input takes rdmesh down, not a campaign.
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

# libfreeimage (through OpenCASCADE's XCAF) frees with free() what it allocated
# with new, at exit: not ours (see scripts/test.sh).
export ASAN_OPTIONS=alloc_dealloc_mismatch=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}
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

# Open findings another engineer is fixing right now, as "TARGET;;REGEX;;...":
# an input whose replayed report matches every REGEX (grep -E) counts as
# "known", not as a failure, so CI stays usable while they are fixed. Remove an
# entry with its fix.
known_open=(
  # None open: the PLY list count cast (fuzz_regressions/ply/nan_list_length.ply)
  # and the element of 10^11 items without properties (bad/junk.ply) are fixed.
)

# True when target $1 has a known open finding.
has_known_open() {
  local entry
  for entry in "${known_open[@]}"; do [ "${entry%%;;*}" = "$1" ] && return 0; done
  return 1
}

# True when the report $2 of target $1 shows a known open finding.
is_known_open() {
  local entry rest regex matched regexes
  for entry in "${known_open[@]}"; do
    [ "${entry%%;;*}" = "$1" ] || continue
    rest=${entry#*;;} matched=1
    IFS=$'\x01' read -r -a regexes <<<"${rest//;;/$'\x01'}"
    for regex in "${regexes[@]}"; do grep -qE "$regex" "$2" || matched=0; done
    [ "$matched" -eq 1 ] && return 0
  done
  return 1
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
    ply) add_seeds "$data"/bad/*.ply ;;
    domain_json) add_seeds samples/*.json ;;
    expression) expression_seeds ;;
    # Not bad/*.st[ep]* nor bad/*.brep: they crash or hang OpenCASCADE at once
    # (what the isolation of the CAD reading is for), which would end the run.
    step) add_seeds "$data"/step/* samples/*.step ;;
    brep) add_seeds "$data"/brep/* ;;
  esac
  dict=()
  [ -f "fuzz/dicts/$t.dict" ] && dict=(-dict="fuzz/dicts/$t.dict")
  log=$dir/fuzz-$t.log
  # A target with a known open finding fuzzes on past crashes, timeouts and
  # out-of-memory inputs (-fork=1: still one fuzzing process at a time, in a child).
  mode=()
  has_known_open "$t" && mode=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  touch "$log.start"
  echo "fuzz: $t for ${seconds}s" >&2
  rc=0
  "$dir/fuzz/rdmesh_fuzz_$t" -max_total_time="$seconds" -max_len="${max_len[$t]}" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$findings/" "${mode[@]}" \
    "${dict[@]}" "$corpus" "$seeds" >"$log" 2>&1 || rc=$?
  # Each new input is replayed: a finding unless its report is a known open one.
  # (A shorter timeout: an input that took 10 s under fuzzing may take 9 alone.)
  found=0 known=0
  while IFS= read -r input; do
    "$dir/fuzz/rdmesh_fuzz_$t" -timeout=5 -rss_limit_mb=2048 "$input" >"$input.log" 2>&1 || true
    if is_known_open "$t" "$input.log"; then
      known=$((known + 1))
    else
      found=$((found + 1))
      echo "fuzz: $t: finding $input" >&2
      grep -E '^(==[0-9]+==ERROR|SUMMARY|rdmesh fuzz:|.*runtime error)' "$input.log" | head -5 >&2 || true
    fi
  done < <(find "$findings" -type f -newer "$log.start" ! -name '*.log' ! -name 'slow-unit-*')
  if [ "$rc" -ne 0 ] && [ $((found + known)) -eq 0 ]; then
    found=1
    echo "fuzz: $t: libFuzzer failed (exit $rc), see $log" >&2
  fi
  [ "$found" -eq 0 ] || status=1
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  if [ -z "$runs" ]; then  # fork mode: the parent's last status line
    runs=$(grep -oE '^#[0-9]+: cov' "$log" | tail -1 | tr -dc 0-9) || true
    speed=$(grep -oE 'exec/s:? [0-9]+' "$log" | tail -1 | tr -dc 0-9) || true
  fi
  rows+=("$t ${runs:-?} ${speed:-?} $(find "$corpus" -type f | wc -l) $found $known")
done

printf '%-12s %12s %8s %8s %9s %6s\n' target executions exec/s corpus findings known
for r in "${rows[@]}"; do
  # shellcheck disable=SC2086  # a row is six words
  printf '%-12s %12s %8s %8s %9s %6s\n' $r
done
exit "$status"
