#!/usr/bin/env bash
# Checks that every C++ file of the repository is formatted as .clang-format says
# (clang-format 14, Debian 12's). CI runs it first; `git clang-format` formats a
# change before it is committed, `bash scripts/check-format.sh --fix` formats all.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --format
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [ "${1:-}" = "--fix" ]; then
  clang-format-14 -i "${files[@]}"
  exit 0
fi
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if ! clang-format-14 --dry-run -Werror "${files[@]}" 2>"$log"; then
  grep -E '^[^ ].*(warning|error):' "$log" | cut -d: -f1 | sort | uniq -c >&2
  echo "rdmesh: these files are not formatted: bash scripts/check-format.sh --fix" >&2
  exit 1
fi
echo "format: ${#files[@]} files formatted as .clang-format says"
