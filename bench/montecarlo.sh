#!/usr/bin/env bash
# `impact3d montecarlo` end to end (BENCHMARKS.md): the Figure 8 case's uncertainty file
# (examples/uncertainty/fig8_side_impact.json, eight inputs, one correlation) with N samples, on every
# core; wall time and peak memory by /usr/bin/time. Two runs: the case with one pc-crash strategy
# (the issue's target; the file's input on the second strategy's mu left out), and the case's four
# strategies with the whole file.
# Usage: bash bench/montecarlo.sh [BUILD_DIR] [N]   (N defaults to 1000000)
set -euo pipefail
build=${1:-build-bench}
n=${2:-1000000}
here=$(cd "$(dirname "$0")" && pwd)
case_file="$here/../examples/fig8_side_impact.json"
uncertainty="$here/../examples/uncertainty/fig8_side_impact.json"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 - "$case_file" "$uncertainty" "$work" <<'PY'
import json, sys
case, u = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
case["strategy"] = [{"name": "pc-crash", "mu": 0.4}]
u["inputs"] = [i for i in u["inputs"] if not i["path"].startswith("$.strategy")]
json.dump(case, open(sys.argv[3] + "/case.json", "w"))
json.dump(u, open(sys.argv[3] + "/u.json", "w"))
PY
run() {  # label, case, uncertainty
  echo "$1:"
  /usr/bin/time -f "  wall %e s, user %U s, system %S s, peak memory %M KiB" \
    "$build/cli/impact3d" montecarlo "$2" --uncertainty "$3" --samples "$n" --format json >/dev/null
}
run "$n samples, pc-crash mu = 0.4, seven inputs" "$work/case.json" "$work/u.json"
run "$n samples, the case's four strategies, eight inputs" "$case_file" "$uncertainty"
