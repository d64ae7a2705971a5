"""impact3d.solve_batch against impact3d.solve row by row, on seeded random collisions drawn as the NumPy
peer draws them (bench/naive/pc_crash.py: full inertia tensors, tilted bodies and contact frames).

Tolerance: the lanes' sines, cosines and fused multiply-adds round differently from the scalar path, but
each is within its rounding bound of the exact impulse of the row (the result's rounding_bound, 32 eps A
with A the row's amplification; tests/check_batch.cpp), so the two are within twice that of each other."""
import json
import sys

import numpy as np
import pytest

import impact3d
from conftest import SOURCE

sys.path.insert(0, str(SOURCE / "bench" / "naive"))
import pc_crash as peer  # noqa: E402


def case_of(d, i):
    def vehicle(k):
        J = [[float(d[f"J{p}{q}_{k}"][i]) for q in range(3)] for p in range(3)]
        return {"name": f"vehicle {k}", "mass": float(d[f"mass_{k}"][i]), "inertia": J,
                "orientation_deg": {a: float(d[f"{a}_{k}"][i]) for a in ("yaw", "pitch", "roll")},
                "velocity": [float(d[f"v{p}_{k}"][i]) for p in range(3)],
                "angular_velocity": [float(d[f"w{p}_{k}"][i]) for p in range(3)],
                "impulse_center": [float(d[f"r{p}_{k}"][i]) for p in range(3)]}
    return {"name": f"row {i}", "units": "SI", "vehicles": [vehicle(1), vehicle(2)],
            "contact": {"normal_yaw_deg": float(d["normal_yaw"][i]), "normal_pitch_deg": float(d["normal_pitch"][i]),
                        "tangent_roll_deg": float(d["tangent_roll"][i])},
            "restitution": float(d["restitution"][i]), "strategy": [{"name": "pc-crash", "mu": float(d["mu"][i])}]}


@pytest.mark.parametrize("velocities", [False, True])
def test_rows_equal_solve(velocities):
    d = peer.random_collisions(300, 5)
    d["mu"] = np.random.default_rng(6).uniform(0.05, 1.2, len(d["mu"]))  # both regimes
    n = len(d["mu"])
    r = impact3d.solve_batch(velocities=velocities, **d)
    assert r["P_C"].shape == (n, 3) and not r["problems"]
    regimes, checked = set(), 0
    for i in range(n):
        s = impact3d.solve(case_of(d, i))["results"][0]
        assert impact3d.STATUSES[r["status"][i]] == "solved"
        assert impact3d.REGIMES[r["regime"][i]] == s["regime"]
        bound = 2 * s["rounding_bound"]
        P = np.array(s["impulse"]["contact"])
        assert np.max(np.abs(r["P_C"][i] - P)) <= bound * np.max(np.abs(P)), i
        # The lean path's warning codes are solve's but energy_gained, which it does not compute.
        assert (r["warnings"][i] == 0) == (not [w for w in s["warnings"] if "energy gained" not in w]), i
        if velocities:
            PW = np.array(s["impulse"]["world"])
            assert np.max(np.abs(r["P_W"][i] - PW)) <= bound * np.max(np.abs(P))
            # v after = v + P_W / m, w after = w + J^-1 (r x R^T P_W): the impulses' difference carried
            # through, and the sum's rounding.
            for k, name in ((0, "_1"), (1, "_2")):
                v, w = np.array(s["vehicles"][k]["velocity"]), np.array(s["vehicles"][k]["angular_velocity"])
                assert np.max(np.abs(r["v" + name][i] - v)) <= bound * (np.max(np.abs(v)) + np.max(np.abs(P)) / d[f"mass{name}"][i])
                assert np.max(np.abs(r["w" + name][i] - w)) <= bound * (np.max(np.abs(w)) + np.max(np.abs(r["w" + name][i] - [d[f"w{p}{name}"][i] for p in range(3)])))
        regimes.add(s["regime"])
        checked += 1
    assert checked == n == 300
    assert regimes == {"full", "sliding"}


def test_bad_rows_are_flagged_not_dropped():
    d = peer.random_collisions(40, 9)
    d["mass_1"][3] = -1500
    d["J11_2"][7] = np.nan
    d["J01_1"][11] = d["J10_1"][11] = 1e6  # symmetric, not positive definite
    d["J21_2"][17] = d["J12_2"][17] + 1  # not symmetric
    d["restitution"] = np.full(40, 0.1)
    d["restitution"][13] = 1.5
    d["mu"] = 0.5  # a number for every row
    r = impact3d.solve_batch(**d)
    assert len(r["status"]) == 40
    assert r["problems"] == {3: "mass_1: not positive", 7: "J11_2: not a finite number",
                             11: "J_1: not positive definite", 13: "restitution: outside [0, 1]",
                             17: "J_2: not symmetric"}
    for i in range(40):
        if i in r["problems"]:
            assert impact3d.STATUSES[r["status"][i]] == "invalid" and np.isnan(r["P_C"][i]).all()
            assert r["regime"][i] == 255
        else:
            assert impact3d.STATUSES[r["status"][i]] == "solved" and np.isfinite(r["P_C"][i]).all()
    # The case reader refuses them too (a NaN has no JSON).
    d["mu"] = np.full(40, 0.5)
    for i in (3, 11, 13, 17):
        with pytest.raises(impact3d.CaseError):
            impact3d.read_case(case_of(d, i))


def test_columns_are_checked():
    d = peer.random_collisions(10, 3)
    with pytest.raises(TypeError, match="no column"):
        impact3d.solve_batch(mass_3=1.0, **d)
    del d["mu"]
    with pytest.raises(TypeError, match="required"):
        impact3d.solve_batch(**d)
    d = peer.random_collisions(10, 3)
    d["mu"] = np.full(9, 0.5)
    with pytest.raises(ValueError, match="rows"):
        impact3d.solve_batch(**d)
    assert impact3d.solve_batch(**{k: v[:0] for k, v in peer.random_collisions(10, 3).items()})["P_C"].shape == (0, 3)


def test_the_same_at_any_number_of_threads():
    d = peer.random_collisions(20000, 4)
    one, two = impact3d.solve_batch(jobs=1, **d), impact3d.solve_batch(jobs=2, **d)
    assert np.array_equal(one["P_C"], two["P_C"], equal_nan=True) and np.array_equal(one["status"], two["status"])


def test_values_the_case_reader_refuses_are_invalid_rows():
    d = peer.random_collisions(6, 12)
    d["mass_1"][0] = 1e300
    d["yaw_2"][1] = 1e13
    d["r2_1"][2] = 1e-300
    d["v0_2"][3] = np.inf
    r = impact3d.solve_batch(**d)
    assert r["problems"][0].startswith("mass_1: out of range: magnitude")
    assert r["problems"][1].startswith("yaw_2: out of range: magnitude")
    assert r["problems"][2].startswith("r2_1: out of range:") and "not zero but below" in r["problems"][2]
    assert r["problems"][3] == "v0_2: not a finite number"
    assert sorted(r["problems"]) == [0, 1, 2, 3]


def test_columns_that_are_not_real_numbers_are_refused():
    d = peer.random_collisions(5, 13)
    for bad in (np.full(5, "0.5"), np.full(5, 0.5 + 0j), None, np.ma.masked_array(np.full(5, 0.5), mask=[1, 0, 0, 0, 0]),
                np.full(5, np.datetime64("2020-01-01"))):
        with pytest.raises(TypeError, match="mu is not real numbers"):
            impact3d.solve_batch(**{**d, "mu": bad})
    ints = impact3d.solve_batch(**{**d, "mass_1": d["mass_1"].round().astype(np.int64)})
    assert (np.array(ints["status"]) == 0).all()
    with pytest.raises(ValueError, match="jobs at most 1024"):
        impact3d.solve_batch(jobs=1025, **d)
