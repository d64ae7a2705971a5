#!/usr/bin/env bash
# `impact3d batch` end to end (BENCHMARKS.md): N generated pc-crash cases (bench/batch_cases.py) in, the
# result documents out, every core; wall time and peak memory by /usr/bin/time.
# Usage: bash bench/batch.sh [BUILD_DIR] [N]   (N defaults to 1000000)
set -euo pipefail
build=${1:-build-bench}
n=${2:-1000000}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$here/batch_cases.py" "$n" "$here/../examples/fig8_side_impact.json" >"$work/cases.jsonl"
echo "input: $n cases, $(du -h "$work/cases.jsonl" | cut -f1)"
/usr/bin/time -f "wall %e s, user %U s, peak memory %M KiB" "$build/cli/impact3d" batch "$work/cases.jsonl" -o "$work/results.jsonl"
echo "output: $(wc -l <"$work/results.jsonl") rows, $(du -h "$work/results.jsonl" | cut -f1)"
