#!/usr/bin/env bash
# pc-crash from raw parameters: impact3d, the naive C++ peer and the NumPy peer, one after the other in one
# run (BENCHMARKS.md). Usage: bash bench/peers.sh [BUILD_DIR]  (a build with -DIMPACT3D_BUILD_BENCH=ON)
set -euo pipefail
build=${1:-build-bench}
"$build/bench/impact3d-bench" --benchmark_filter='pc_crash|wach_brach' --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
/usr/bin/python3 "$(dirname "$0")/naive/pc_crash.py" --benchmark 100000
# The 100-digit route's MPFR operations, counted and timed alone: the floor under pc_crash_lean_100_digits.
"$build/bench/impact3d-mpfr-floor"
