#!/usr/bin/env bash
# Issue 11's targets, every one in the same run, ROUNDS times (BENCHMARKS.md): the pc-crash benchmarks
# (impact3d's SIMD lanes and scalar lean path, both engines, the naive C++ peer, 100 digits; their
# repetitions interleaved, so that a drift of the host's speed falls on all of them), the NumPy peer, and
# `impact3d batch` on N cases (bench/batch.sh) and on N/10, whose peak memories show whether memory stays
# flat in the rows. bench/targets.py reads each round and prints measured against target.
# Usage: bash bench/targets.sh [BUILD_DIR] [ROUNDS] [N]   (defaults: build-bench, 1, 1000000)
# Exit status 0 when every target was met in some round. A step that fails ends the run.
set -euo pipefail
build=${1:-build-bench}
rounds=${2:-1}
n=${3:-1000000}
[[ $rounds =~ ^[1-9][0-9]*$ && $n =~ ^[1-9][0-9]*$ ]] || { echo "usage: $0 [BUILD_DIR] [ROUNDS] [N]" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "host: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores"
status=1
for ((r = 1; r <= rounds; ++r)); do
  "$build/bench/impact3d-bench" --benchmark_filter='pc_crash_simd|pc_crash_lean<.*impulse>|pc_crash_naive|pc_crash_lean_100' \
    --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true \
    --benchmark_out="$work/bench.json" --benchmark_out_format=json >/dev/null
  /usr/bin/python3 "$here/naive/pc_crash.py" --benchmark 100000 >"$work/numpy.txt"
  bash "$here/batch.sh" "$build" "$n" >"$work/batch.txt" 2>&1
  bash "$here/batch.sh" "$build" $((n / 10)) >"$work/batch_tenth.txt" 2>&1
  echo "round $r of $rounds, $(date -u +%FT%TZ):"
  if /usr/bin/python3 -B "$here/targets.py" "$work/bench.json" "$work/numpy.txt" "$work/batch.txt" "$work/batch_tenth.txt"; then
    status=0
  fi
done
exit "$status"
