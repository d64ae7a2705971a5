"""Bad input raises impact3d.CaseError (a ValueError) whose message is the command line's line: for every
file of the bad-input corpus (tests/program/bad_input/, whose expected.tsv holds each line the CLI prints after
"impact3d: error: FILE: ", reviewed by hand and checked against the CLI by exam_bad_input), at double and
at 100 digits; bad options raise ValueError."""
import pytest

import impact3d
from conftest import SOURCE

BAD = SOURCE / "tests" / "program" / "bad_input"


def expected_lines():
    lines = {}
    for line in (BAD / "expected.tsv").read_text(encoding="utf-8").splitlines():
        if line and not line.startswith("#"):
            name, text = line.split("\t", 1)
            lines[name] = text
    return lines


@pytest.mark.parametrize("precision", ["double", "100"])
def test_the_bad_input_corpus_raises_the_clis_messages(precision):
    expected = expected_lines()
    files = sorted(BAD.glob("*.json"))
    assert len(files) == len(expected) > 50
    for f in files:
        with pytest.raises(impact3d.CaseError) as raised:
            impact3d.solve(str(f), precision=precision)
        assert isinstance(raised.value, ValueError)
        assert str(raised.value) == f"{f}: {expected[f.name]}", f.name


def test_a_dict_is_named_by_its_json_path():
    with pytest.raises(impact3d.CaseError) as raised:
        impact3d.read_case({"name": "x", "units": "SI", "vehicles": []})
    assert str(raised.value).startswith("$.vehicles")


def test_bad_options(fig8):
    with pytest.raises(ValueError, match="^precision: "):
        impact3d.solve(fig8, precision="bogus")
    with pytest.raises(ValueError, match="^engine: "):
        impact3d.solve(fig8, engine="fast")
    with pytest.raises(ValueError, match="^units: "):
        impact3d.solve(fig8, units="furlongs")
    with pytest.raises(impact3d.CaseError, match=r"--strategy\[0\]"):
        impact3d.solve(fig8, strategies="pc-crash:mu=-1")
    with pytest.raises(TypeError):
        impact3d.read_case(42)


def test_a_dict_with_no_json_form_is_named_by_its_path(fig8):
    import json
    case = json.loads(fig8.read_text())
    case["vehicles"][0]["mass"] = float("nan")
    with pytest.raises(impact3d.CaseError, match=r"^\$\.vehicles\[0\]\.mass: not a finite number"):
        impact3d.read_case(case)
    case["vehicles"][0]["mass"] = object()
    with pytest.raises(impact3d.CaseError, match=r"^\$\.vehicles\[0\]\.mass: object has no JSON form"):
        impact3d.read_case(case)


def test_decimals_and_numpy_numbers_in_a_dict_keep_their_value(fig8):
    import json
    from decimal import Decimal
    import numpy as np
    case = json.loads(fig8.read_text())
    case["restitution"] = Decimal("0.1")           # the file's literal, digit for digit
    case["vehicles"][0]["mass"] = np.int64(1560)
    case["vehicles"][1]["mass"] = np.float64(2600.0)
    assert impact3d.solve(case, precision="100") == impact3d.solve(fig8, precision="100")


def test_a_dict_nested_past_the_readers_limit_is_a_case_error_naming_it():
    deep = {}
    inner = deep
    for _ in range(100000):
        inner["a"] = {}
        inner = inner["a"]
    with pytest.raises(impact3d.CaseError, match=r"nested deeper than 32 levels$"):
        impact3d.read_case(deep)
    itself = {"name": "x"}
    itself["vehicles"] = [itself]
    with pytest.raises(impact3d.CaseError, match=r"^\$(\.vehicles\[0\])+: nested deeper than 32 levels$"):
        impact3d.read_case(itself)
    # 32 levels are the reader's to judge: its own message, not the package's.
    shallow = {"name": "x", "units": "SI", "vehicles": [], "x": [[[[[]]]]]}
    with pytest.raises(impact3d.CaseError) as raised:
        impact3d.read_case(shallow)
    assert "nested deeper" not in str(raised.value)


def test_a_key_that_is_no_identifier_is_escaped_in_the_path():
    with pytest.raises(impact3d.CaseError) as raised:
        impact3d.read_case({"name": "x", "a\nb": {"c": float("nan")}})
    assert str(raised.value) == '$["a\\nb"].c: not a finite number: nan'

