#!/usr/bin/env python3
"""impact3d.solve_batch against the NumPy peer (bench/naive/pc_crash.py) on the same 10^6 collisions, in one
run (BENCHMARKS.md). Usage: PYTHONPATH=BUILD/python python3 bench/python_batch.py [N]

Prints, for each, the best of 3 wall-clock times and ns per collision; solve_batch on every core (jobs=0)
and on one (jobs=1); and the largest difference between the two results relative to the impulse (the
peer is held to 1e-12 by tests/mechanics/check_naive_peers.cpp)."""
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "naive"))
import impact3d  # noqa: E402
import pc_crash as peer  # noqa: E402


def best_of(f, runs=3):
    best = float("inf")
    for _ in range(runs):
        t = time.perf_counter()
        out = f()
        best = min(best, time.perf_counter() - t)
    return best, out


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 10**6
    d = peer.random_collisions(n, 11)
    n = len(d["mu"])
    print(f"{n} collisions, pc-crash, mu = 0.5, eps = 0.1; impact3d on {impact3d.BATCH_SIMD}, {os.cpu_count()} cores; "
          f"NumPy {np.__version__}")
    rows = []
    t_all, ours = best_of(lambda: impact3d.solve_batch(**d))
    rows.append(("impact3d.solve_batch, every core", t_all))
    t_one, _ = best_of(lambda: impact3d.solve_batch(jobs=1, **d))
    rows.append(("impact3d.solve_batch, one core", t_one))
    t_vel, _ = best_of(lambda: impact3d.solve_batch(velocities=True, **d))
    rows.append(("impact3d.solve_batch(velocities=True), every core", t_vel))
    t_np, (P, _) = best_of(lambda: peer.pc_crash(d))
    rows.append(("NumPy peer (bench/naive/pc_crash.py)", t_np))
    for name, t in rows:
        print(f"{name:55s} {t:8.3f} s  {t / n * 1e9:8.1f} ns per collision  {t_np / t:6.1f}x NumPy")
    diff = np.max(np.abs(ours["P_C"] - P) / np.max(np.abs(P), axis=1, keepdims=True))
    print(f"largest difference from the peer, relative to the impulse: {diff:.2e}")


if __name__ == "__main__":
    main()
