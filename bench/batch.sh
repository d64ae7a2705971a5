#!/usr/bin/env bash
# `impact3d batch` end to end (BENCHMARKS.md): N generated pc-crash cases (bench/batch_cases.py) in, the
# results out, every core; wall time and peak memory by /usr/bin/time. Three runs: JSON Lines in and
# out, JSON Lines in and CSV out, CSV in and out.
# Usage: bash bench/batch.sh [BUILD_DIR] [N]   (N defaults to 1000000)
set -euo pipefail
build=${1:-build-bench}
n=${2:-1000000}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
example="$here/../examples/fig8_side_impact.json"
/usr/bin/python3 "$here/batch_cases.py" "$n" "$example" >"$work/cases.jsonl"
/usr/bin/python3 "$here/batch_cases.py" "$n" "$example" --csv >"$work/cases.csv"
echo "input: $n cases, $(du -h "$work/cases.jsonl" | cut -f1) as JSON Lines, $(du -h "$work/cases.csv" | cut -f1) as CSV"
run() {  # label, input, output, options
  echo "$1:"
  # The last run's output, written back to the disk after it ended, is not this run's work.
  sync
  sleep 5
  /usr/bin/time -f "  wall %e s, user %U s, system %S s, peak memory %M KiB" "$build/cli/impact3d" batch "$2" -o "$3" "${@:4}"
  echo "  output: $(wc -l <"$3") lines, $(du -h "$3" | cut -f1)"
  rm -f "$3"
}
run "JSON Lines in, JSON Lines out" "$work/cases.jsonl" "$work/results.jsonl"
run "JSON Lines in, CSV out" "$work/cases.jsonl" "$work/results.csv" --format csv
run "CSV in, CSV out" "$work/cases.csv" "$work/results.csv" --format csv
