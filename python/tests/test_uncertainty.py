"""impact3d.montecarlo and impact3d.sensitivity against the command line's documents on Figure 8, and the
kept samples against the summary they were summarized into."""
import numpy as np

import impact3d
import json

import pytest

from conftest import SOURCE, cli, cli_error

UNCERTAINTY = SOURCE / "examples" / "uncertainty" / "fig8_side_impact.json"


def test_montecarlo_equals_the_cli(fig8):
    ours = impact3d.montecarlo(fig8, UNCERTAINTY, samples=2000, seed=3, jobs=2)
    theirs = json.loads(cli("montecarlo", fig8, "--uncertainty", UNCERTAINTY, "--samples", 2000, "--seed", 3,
                            "--format", "json"))
    assert ours == theirs
    assert ours["samples"] == 2000 and type(ours["samples"]) is int and type(ours["seed"]) is int


def test_kept_samples_are_what_was_summarized(fig8):
    doc = impact3d.montecarlo(fig8, UNCERTAINTY, samples=3000, seed=5, keep_samples=True)
    sampled = doc.pop("sampled")
    assert list(sampled["inputs"]) == doc["inputs"]
    checked = 0
    for k, result in enumerate(doc["results"]):
        values = sampled["results"][k]["vehicles[1].delta_v_magnitude"]
        assert values.shape == (3000,)
        solved = values[~np.isnan(values)]
        summary = result["outputs"]["vehicles[1].delta_v_magnitude"]
        # The summary's mean is the same samples' mean: equal to rounding (n additions of values ~10 m/s).
        assert abs(np.mean(solved) - summary["mean"]) <= 3000 * np.finfo(float).eps * np.max(solved)
        checked += 1
    assert checked == 4


def test_sensitivity_equals_the_cli(fig8):
    assert impact3d.sensitivity(fig8) == json.loads(cli("sensitivity", fig8, "--format", "json"))


def test_an_uncertainty_dict_is_named_by_its_path(fig8):
    with pytest.raises(impact3d.CaseError, match=r"^\$\.inputs"):
        impact3d.montecarlo(fig8, {"samples": 10, "inputs": [{"path": "$.nowhere", "distribution": "normal", "mean": 1, "sd": 1}]})


def test_montecarlo_errors_are_the_clis(fig8):
    with pytest.raises(impact3d.CaseError) as raised:
        impact3d.montecarlo(fig8, UNCERTAINTY, strategies="pc-crash:mu=-1", samples=10)
    assert str(raised.value) == cli_error("montecarlo", fig8, "--uncertainty", UNCERTAINTY, "--strategy", "pc-crash:mu=-1",
                                          "--samples", 10)
    # The CLI refuses these as usage errors (exit 2); Python as ValueError, before any work.
    for bad in ({"samples": 0}, {"samples": 10**7 + 1}, {"samples": 2**62}, {"jobs": 1025}):
        with pytest.raises(ValueError, match="^(samples|jobs): "):
            impact3d.montecarlo(fig8, UNCERTAINTY, **bad)


def test_counts_and_seeds_are_checked_in_one_line_before_the_binding(fig8):
    # pybind11 refuses a negative or huge int with a many-line TypeError: the package checks first, in
    # the command line's words.
    for bad, error, start in (({"samples": -1}, ValueError, "samples: from 1 to 10000000, not -1"),
                              ({"samples": 10**30}, ValueError, "samples: from 1 to 10000000, not 10"),
                              ({"samples": 1.5}, TypeError, "samples: an int, not float"),
                              ({"seed": -1}, ValueError, "seed: must be a whole number from 0 to 18446744073709551615, not -1"),
                              ({"seed": 2**64}, ValueError, "seed: must be a whole number from 0 to 18446744073709551615, not 1844"),
                              ({"seed": True}, TypeError, "seed: an int, not bool"),
                              ({"jobs": -1}, ValueError, "jobs: from 0 (every core) to 1024, not -1"),
                              ({"jobs": 1.5}, TypeError, "jobs: an int, not float")):
        with pytest.raises(error) as raised:
            impact3d.montecarlo(fig8, UNCERTAINTY, **bad)
        assert str(raised.value).startswith(start), bad
        assert "\n" not in str(raised.value), bad
    # The largest seed is a seed.
    assert impact3d.montecarlo(fig8, UNCERTAINTY, samples=10, seed=2**64 - 1)["seed"] == 2**64 - 1


def test_a_run_that_solved_no_sample_raises(fig8):
    away = {"samples": 20, "inputs": [{"path": "$.vehicles[1].velocity[1]", "distribution": "uniform", "min": -30, "max": -20}]}
    with pytest.raises(impact3d.CaseError, match=r"^\$: pc-crash mu=1\.0 solved none of the 20 samples: 20 of them do not approach"):
        impact3d.montecarlo(fig8, away)


def test_a_run_that_solved_fewer_than_half_warns(fig8):
    few = {"samples": 200, "inputs": [{"path": "$.vehicles[1].velocity[1]", "distribution": "uniform", "min": -10, "max": 4}]}
    with pytest.warns(UserWarning, match=r"^montecarlo: results\[0\] solved \d+ of 200 samples"):
        doc = impact3d.montecarlo(fig8, few)
    assert doc["results"][0]["solved"] < 100

