#!/usr/bin/env python3
"""The pc-crash impulse from raw parameters, vectorized over many collisions with NumPy: the peer of
bench/naive/pc_crash.hpp written as an analyst would write it in Python. Not part of impact3d;
tests/mechanics/check_naive_peers.cpp holds it to impact3d.

As a program: reads a CSV of collisions (the columns of COLUMNS, one row each) on standard input and
writes P_n, P_t, P_z and the regime (1 Full Impact, 0 Sliding Impact) per row on standard output.
With --benchmark N: times pc_crash on N random approaching collisions, drawn as bench/peer_collisions.hpp
draws them, at mu = 0.5 and eps = 0.1 as bench/bench_peers.cpp times them; prints the best of 5 runs in
ns per collision.
"""
import sys

import numpy as np

VEHICLE = ["mass"] + [f"J{p}{q}" for p in range(3) for q in range(3)] + ["yaw", "pitch", "roll"] + \
    [f"{k}{p}" for k in ("v", "w", "r") for p in range(3)]
COLUMNS = [f"{c}_{i}" for i in (1, 2) for c in VEHICLE] + \
    ["normal_yaw", "normal_pitch", "tangent_roll", "restitution", "mu"]


def rotation(yaw, pitch, roll):
    """Rz(yaw) Ry(pitch) Rx(roll), angles in degrees; shape (n, 3, 3)."""
    y, p, r = np.radians(yaw), np.radians(pitch), np.radians(roll)
    cy, sy, cp, sp, cr, sr = np.cos(y), np.sin(y), np.cos(p), np.sin(p), np.cos(r), np.sin(r)
    return np.stack([np.stack([cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr], -1),
                     np.stack([sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr], -1),
                     np.stack([-sp, cp * sr, cp * cr], -1)], -2)


def skew(r):
    z = np.zeros(r.shape[0])
    return np.stack([np.stack([z, -r[:, 2], r[:, 1]], -1),
                     np.stack([r[:, 2], z, -r[:, 0]], -1),
                     np.stack([-r[:, 1], r[:, 0], z], -1)], -2)


def pc_crash(d):
    """d: a dict of column name -> array. Returns (P of shape (n, 3), full of shape (n,))."""
    n = len(d["mu"])
    RC = rotation(d["normal_yaw"], d["normal_pitch"], d["tangent_roll"])
    m = [d[f"mass_{i}"] for i in (1, 2)]
    mp = m[0] * m[1] / (m[0] + m[1])
    K = np.broadcast_to(np.eye(3), (n, 3, 3)).copy()
    V = np.zeros((n, 3))
    for i, sign in ((1, -1.0), (2, 1.0)):
        J = np.stack([np.stack([d[f"J{p}{q}_{i}"] for q in range(3)], -1) for p in range(3)], -2)
        R = rotation(d[f"yaw_{i}"], d[f"pitch_{i}"], d[f"roll_{i}"])
        v, w, r = (np.stack([d[f"{k}{p}_{i}"] for p in range(3)], -1) for k in ("v", "w", "r"))
        T = np.transpose(RC, (0, 2, 1)) @ R
        S = skew(r)
        K += mp[:, None, None] * (T @ np.transpose(S, (0, 2, 1)) @ np.linalg.inv(J) @ S @ np.transpose(T, (0, 2, 1)))
        V += sign * (v + np.einsum("npq,nq->np", R, np.cross(w, r)))
    Vc = np.einsum("nqp,nq->np", RC, V)
    f = mp * (1 + d["restitution"])
    P = np.linalg.solve(K, (f[:, None] * Vc)[..., None])[..., 0]
    Pcp = np.hypot(P[:, 1], P[:, 2])
    full = d["mu"] >= Pcp / P[:, 0]
    c, s = P[:, 1] / Pcp, P[:, 2] / Pcp
    Pn = f * Vc[:, 0] / (K[:, 0, 0] + d["mu"] * (K[:, 0, 1] * c + K[:, 0, 2] * s))
    sliding = np.stack([Pn, d["mu"] * c * Pn, d["mu"] * s * Pn], -1)
    return np.where(full[:, None], P, sliding), full


def random_collisions(n, seed):
    """As bench/peer_collisions.hpp draws them; the approaching ones are kept."""
    g = np.random.default_rng(seed)
    m = 4 * n
    d = {}
    for i in (1, 2):
        d[f"mass_{i}"] = g.uniform(700, 3500, m)
        ixx, iyy = g.uniform(300, 1500, m), g.uniform(1200, 6000, m)
        izz = iyy + g.uniform(0.5, 1.0, m) * ixx
        Q = rotation(g.uniform(-15, 15, m), g.uniform(-15, 15, m), g.uniform(-15, 15, m))
        J = Q @ (np.stack([ixx, iyy, izz], -1)[:, :, None] * np.transpose(Q, (0, 2, 1)))
        J = (J + np.transpose(J, (0, 2, 1))) / 2
        for p in range(3):
            for q in range(3):
                d[f"J{p}{q}_{i}"] = J[:, p, q]
        d[f"yaw_{i}"], d[f"pitch_{i}"], d[f"roll_{i}"] = g.uniform(-180, 180, m), g.uniform(-12, 12, m), g.uniform(-12, 12, m)
        for k, lo, hi in (("v", (-25, -25, -1), (25, 25, 1)), ("w", (-0.3, -0.3, -1.5), (0.3, 0.3, 1.5)),
                          ("r", (-2.6, -1.0, -0.5), (2.6, 1.0, 0.4))):
            for p in range(3):
                d[f"{k}{p}_{i}"] = g.uniform(lo[p], hi[p], m)
    d["normal_yaw"], d["normal_pitch"], d["tangent_roll"] = g.uniform(-180, 180, m), g.uniform(-25, 25, m), g.uniform(-30, 30, m)
    d["restitution"], d["mu"] = np.full(m, 0.1), np.full(m, 0.5)
    # Approaching: the normal relative velocity, as pc_crash computes it, above 1 m/s.
    RC = rotation(d["normal_yaw"], d["normal_pitch"], d["tangent_roll"])
    V = np.zeros((m, 3))
    for i, sign in ((1, -1.0), (2, 1.0)):
        R = rotation(d[f"yaw_{i}"], d[f"pitch_{i}"], d[f"roll_{i}"])
        v, w, r = (np.stack([d[f"{k}{p}_{i}"] for p in range(3)], -1) for k in ("v", "w", "r"))
        V += sign * (v + np.einsum("npq,nq->np", R, np.cross(w, r)))
    keep = np.nonzero(np.einsum("nq,nq->n", RC[:, :, 0], V) > 1.0)[0][:n]
    return {k: a[keep] for k, a in d.items()}


def benchmark(n):
    import time
    d = random_collisions(n, 11)
    best = float("inf")
    for _ in range(5):
        t = time.perf_counter()
        pc_crash(d)
        best = min(best, time.perf_counter() - t)
    print(f"pc_crash_numpy: {best / len(d['mu']) * 1e9:.0f} ns per collision ({len(d['mu'])} collisions, best of 5, "
          f"NumPy {np.__version__})")


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--benchmark":
        benchmark(int(sys.argv[2]))
        return
    header = sys.stdin.readline().strip().split(",")
    if header != COLUMNS:
        sys.exit("pc_crash.py: the header must be " + ",".join(COLUMNS))
    data = np.loadtxt(sys.stdin, delimiter=",", ndmin=2)
    P, full = pc_crash({name: data[:, k] for k, name in enumerate(COLUMNS)})
    for p, f in zip(P, full):
        print(f"{float(p[0])!r},{float(p[1])!r},{float(p[2])!r},{int(f)}")


if __name__ == "__main__":
    main()
