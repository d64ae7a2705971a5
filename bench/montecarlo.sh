#!/usr/bin/env bash
# `impact3d montecarlo` end to end (BENCHMARKS.md): the Figure 8 case's uncertainty file
# (examples/uncertainty/fig8_side_impact.json, eight inputs, one correlation) with N samples, on every
# core; wall time and peak memory by /usr/bin/time. Two runs: one pc-crash strategy (the issue's
# target), and the case's four strategies.
# Usage: bash bench/montecarlo.sh [BUILD_DIR] [N]   (N defaults to 1000000)
set -euo pipefail
build=${1:-build-bench}
n=${2:-1000000}
here=$(cd "$(dirname "$0")" && pwd)
case_file="$here/../examples/fig8_side_impact.json"
uncertainty="$here/../examples/uncertainty/fig8_side_impact.json"
run() {  # label, options
  echo "$1:"
  /usr/bin/time -f "  wall %e s, user %U s, system %S s, peak memory %M KiB" \
    "$build/cli/impact3d" montecarlo "$case_file" --uncertainty "$uncertainty" --samples "$n" --format json "${@:2}" >/dev/null
}
run "$n samples, pc-crash mu = 0.4" --strategy pc-crash:mu=0.4
run "$n samples, the case's four strategies"
