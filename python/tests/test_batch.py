"""impact3d.solve_batch against impact3d.solve row by row, on seeded random collisions drawn as the NumPy
peer draws them (bench/naive/pc_crash.py: full inertia tensors, tilted bodies and contact frames).

Tolerance: the lanes' sines, cosines and fused multiply-adds round differently from the scalar path, but
each is within its rounding bound of the exact impulse of the row (the result's rounding_bound, 32 eps A
with A the row's amplification; tests/mechanics/check_batch.cpp), so the two are within twice that of each other."""
import json
import re
import sys

import numpy as np
import pytest

import impact3d
from conftest import SOURCE

sys.path.insert(0, str(SOURCE / "bench" / "naive"))
import pc_crash as peer  # noqa: E402


def case_of(d, i, strategy=None):
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
            "restitution": float(d["restitution"][i]),
            "strategy": [strategy(d, i) if strategy else {"name": "pc-crash", "mu": float(d["mu"][i])}]}


# Each text solve writes for a warning, by the name of its code (impact3d.WARNINGS); the texts are the
# library's (strategies/limits.hpp and the strategies, post_impact.hpp, precision_warnings.hpp,
# analysis.hpp). A text that matches no pattern, or two, fails the test.
WARNING_TEXTS = {
    "tensile normal impulse": r"normal impulse P_n <= 0: .*",
    "energy gained": r"kinetic energy gained: .*",
    "plane undefined": r"phi(_FI)? \(eq \d+\) is undefined: .*",
    "negative ratio": r".+ used is negative: the contact-plane impulse acts along the initial sliding",
    "non-physical limit": r".+ is undefined: the normal impulse of the solution that defines it is zero",
    "not finite": r"(not finite: |a quantity of the case ).*",
    "rounding": r"(rounding: |wide enclosure: ).*",
    "undecided": r"undecided: .*",
}


def warning_bits(texts):
    """The lean path's warning set for solve's texts: energy gained and the momentum balance are left out,
    since the lean path computes neither the energies nor the post-impact momenta."""
    bits = 0
    for text in texts:
        if "momentum balance" in text:
            continue
        codes = [name for name, pattern in WARNING_TEXTS.items() if re.fullmatch(pattern, text)]
        assert len(codes) == 1, (text, codes)
        if codes[0] != "energy gained":
            bits |= 1 << impact3d.WARNINGS.index(codes[0])
    return bits


def compare_rows(d, r, velocities, strategy=None):
    """Each row of solve_batch's result `r` against solve of the same row (with `strategy`, else
    pc-crash): the status, the regime, the warning codes, the impulse within twice solve's rounding bound,
    and with velocities the post-impact states. Returns the regimes seen, the rows compared, and how many
    of them had a warning code."""
    regimes, checked, warned = set(), 0, 0
    for i in range(len(r["status"])):
        s = impact3d.solve(case_of(d, i, strategy))["results"][0]
        assert impact3d.STATUSES[r["status"][i]] == "solved"
        assert impact3d.REGIMES[r["regime"][i]] == s["regime"]
        bound = 2 * s["rounding_bound"]
        P = np.array(s["impulse"]["contact"])
        assert np.max(np.abs(r["P_C"][i] - P)) <= bound * np.max(np.abs(P)), i
        bits = warning_bits(s["warnings"])
        assert int(r["warnings"][i]) == bits, (i, s["warnings"])
        warned += bits != 0
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
    return regimes, checked, warned


@pytest.mark.parametrize("velocities", [False, True])
def test_rows_equal_solve(velocities):
    d = peer.random_collisions(300, 5)
    d["mu"] = np.random.default_rng(6).uniform(0.05, 1.2, len(d["mu"]))  # both regimes
    n = len(d["mu"])
    r = impact3d.solve_batch(velocities=velocities, **d)
    assert r["P_C"].shape == (n, 3) and not r["problems"]
    regimes, checked, warned = compare_rows(d, r, velocities)
    assert checked == n == 300
    assert regimes == {"full", "sliding"}
    assert warned > 0  # 11 rows of the 300 have a tensile normal impulse


# Wach and Brach (solve_batch's strategy), each form against solve with the same strategy in the case.
def ratio(d, name, i):
    return float(d[name][i]) if name in d else "critical"


OTHER_STRATEGIES = [
    ("wach", "cir", ("mu",), lambda d, i: {"name": "wach", "mu": float(d["mu"][i]), "limit": "cir"}),
    ("wach", "gir", ("mu",), lambda d, i: {"name": "wach", "mu": float(d["mu"][i]), "limit": "gir"}),
    ("brach", None, ("mu_t", "mu_z"), lambda d, i: {"name": "brach", "mu_t": ratio(d, "mu_t", i), "mu_z": ratio(d, "mu_z", i)}),
    ("brach", None, ("mu_z",), lambda d, i: {"name": "brach", "mu_t": ratio(d, "mu_t", i), "mu_z": ratio(d, "mu_z", i)}),
    ("brach", None, ("mu_t",), lambda d, i: {"name": "brach", "mu_t": ratio(d, "mu_t", i), "mu_z": ratio(d, "mu_z", i)}),
    ("brach", None, (), lambda d, i: {"name": "brach", "mu_t": "critical", "mu_z": "critical"}),
]


@pytest.mark.parametrize("form", range(len(OTHER_STRATEGIES)))
@pytest.mark.parametrize("velocities", [False, True])
def test_wach_and_brach_rows_equal_solve(form, velocities):
    name, limit, ratios, strategy = OTHER_STRATEGIES[form]
    d = peer.random_collisions(120, 20 + form)
    rng = np.random.default_rng(form)
    mu = d.pop("mu")
    if "mu" in ratios:
        d["mu"] = rng.uniform(0.05, 1.2, len(mu))  # below and above the cap
    if "mu_t" in ratios:
        d["mu_t"] = rng.uniform(-0.3, 0.9, len(mu))  # Brach's ratios are signed
    if "mu_z" in ratios:
        d["mu_z"] = rng.uniform(-0.3, 0.3, len(mu))
    n = len(mu)
    r = impact3d.solve_batch(velocities=velocities, strategy=name, limit=limit, **d)
    assert r["P_C"].shape == (n, 3) and not r["problems"]
    regimes, checked, warned = compare_rows(d, r, velocities, strategy)
    assert checked == n == 120
    assert regimes == ({"capped", "sliding"} if name == "wach" else {"as-given"})
    if name == "wach":
        assert warned > 0  # 6 and 11 rows: negative ratios, some with a tensile normal impulse besides


def test_strategy_and_its_columns_are_checked():
    d = peer.random_collisions(10, 3)
    with pytest.raises(ValueError, match="strategy"):
        impact3d.solve_batch(strategy="wach-cir", **d)
    with pytest.raises(ValueError, match="limit is wach's"):
        impact3d.solve_batch(limit="gir", **d)
    with pytest.raises(ValueError, match="limit"):
        impact3d.solve_batch(strategy="wach", limit="critical", **d)
    with pytest.raises(TypeError, match="strategy: a str, not int"):
        impact3d.solve_batch(strategy=3, **d)
    with pytest.raises(TypeError, match="limit: a str or None, not bytes"):
        impact3d.solve_batch(strategy="wach", limit=b"cir", **d)
    with pytest.raises(TypeError, match="mu is not a column of brach"):
        impact3d.solve_batch(strategy="brach", **d)
    with pytest.raises(TypeError, match="mu_t is not a column of pc-crash"):
        impact3d.solve_batch(mu_t=0.2, **d)
    mu = d.pop("mu")
    # Brach with a negative ratio is a row like any other; pc-crash's mu must not be negative.
    assert not impact3d.solve_batch(strategy="brach", mu_t=-0.2, **d)["problems"]
    assert impact3d.solve_batch(mu=-mu, **d)["problems"][0] == "mu: negative"


def test_jobs_is_checked_in_one_line_before_the_binding():
    d = peer.random_collisions(4, 3)
    for jobs, error, text in ((-1, ValueError, "solve_batch: jobs: from 0 (every core) to 1024, not -1"),
                              (1025, ValueError, "solve_batch: jobs: from 0 (every core) to 1024, not 1025"),
                              (1.5, TypeError, "solve_batch: jobs: an int, not float")):
        with pytest.raises(error) as raised:
            impact3d.solve_batch(jobs=jobs, **d)
        assert str(raised.value) == text


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
