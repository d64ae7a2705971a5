"""impact3d.reconstruct against the command line's document on the bundled Figure 8 evidence, from a
path and from a dict; its errors are the command line's."""
import json

import pytest

import impact3d
from conftest import SOURCE, cli, cli_error

EVIDENCE = SOURCE / "examples" / "evidence" / "fig8_side_impact.json"


def test_reconstruct_equals_the_cli(fig8):
    ours = impact3d.reconstruct(fig8, EVIDENCE, strategy="pc-crash:mu=0.4")
    theirs = json.loads(cli("reconstruct", fig8, "--evidence", EVIDENCE, "--strategy", "pc-crash:mu=0.4", "--format", "json"))
    assert ours == theirs
    assert ours["regime"] == "sliding" and ours["identifiable"] is True
    assert type(ours["dof"]) is int and ours["dof"] == 8
    # The same evidence as a dict, and the strategy as a dict: the same document.
    evidence = json.loads(EVIDENCE.read_text())
    assert impact3d.reconstruct(fig8, evidence, strategy={"name": "pc-crash", "mu": 0.4}) == ours


def test_an_undetermined_speed_is_none(fig8):
    doc = impact3d.reconstruct(fig8, {"unknowns": [{"speed": 0}, {"speed": 1}],
                                      "evidence": [{"output": "vehicles[0].speed_after", "value": 11, "sd": 0.5}]},
                               strategy="pc-crash:mu=0.4")
    assert doc["identifiable"] is False
    assert len(doc["undetermined"]) == 1
    assert all(e["value"] is None and e["sd"] is None for e in doc["estimates"])


def test_reconstruct_errors_are_the_clis(fig8, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"unknowns": [{"speed": 2}], "evidence": [{"speed": 0, "value": 1, "sd": 1}]}')
    with pytest.raises(impact3d.CaseError) as raised:
        impact3d.reconstruct(fig8, bad, strategy="pc-crash:mu=0.4")
    assert str(raised.value) == cli_error("reconstruct", fig8, "--evidence", bad, "--strategy", "pc-crash:mu=0.4")
    with pytest.raises(impact3d.CaseError) as raised:
        impact3d.reconstruct(fig8, EVIDENCE)
    assert str(raised.value) == cli_error("reconstruct", fig8, "--evidence", EVIDENCE)
    with pytest.raises(impact3d.CaseError, match=r"^\$\.unknowns\[0\]\.speed: "):
        impact3d.reconstruct(fig8, {"unknowns": [{"speed": 5}], "evidence": []}, strategy="pc-crash:mu=0.4")
