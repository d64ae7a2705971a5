"""impact3d.solve against the command line's JSON: every example, every precision, both engines, field
by field, with the numbers of each precision as the precision writes them (the CLI's output is read here
on its own, not by the package's converter)."""
from decimal import Decimal
from fractions import Fraction

import pytest

import impact3d
from conftest import EXAMPLES, SOURCE, cli, cli_document

PRECISIONS = ["double", "long-double", "float128", "50", "100", "exact", "certified:128"]


def test_examples_are_there():
    assert len(EXAMPLES) == 4


@pytest.mark.parametrize("precision", PRECISIONS)
@pytest.mark.parametrize("engine", ["generated", "direct"])
def test_solve_equals_the_cli(precision, engine):
    compared = 0
    for case in EXAMPLES:
        ours = impact3d.solve(case, engine=engine, precision=precision)
        theirs = cli_document(cli("solve", case, "--format", "json", "--engine", engine, "--precision", precision), precision)
        assert ours == theirs, case.name
        compared += 1
    assert compared == 4


def test_number_types_follow_the_precision(fig8):
    P = lambda doc: doc["results"][0]["impulse"]["contact"][0]
    assert type(P(impact3d.solve(fig8))) is float
    at100 = impact3d.solve(fig8, precision="100")
    assert type(P(at100)) is Decimal and len(P(at100).as_tuple().digits) > 90  # every digit, none through a double
    exact = impact3d.solve(SOURCE / "verification" / "cases" / "exact_rational_rotations.json", precision="exact")
    # m' = m1 m2 / (m1 + m2) of the case's 1550 kg and 2450 kg, by hand: 7595/8.
    assert exact["exact"]["coefficients"]["m_prime"] == Fraction(7595, 8)


def test_options_are_the_clis(fig8):
    ours = impact3d.solve(fig8, strategies=["pc-crash:mu=0.3", {"name": "wach", "mu": 0.3, "limit": "gir"}], units="US")
    theirs = cli_document(cli("solve", fig8, "--format", "json", "--strategy", "pc-crash:mu=0.3", "--strategy",
                              '{"name": "wach", "mu": 0.3, "limit": "gir"}', "--units", "US"), "double")
    assert ours == theirs
    assert len(ours["results"]) == 2


def test_a_case_as_a_dict_is_the_file(fig8):
    import json
    assert impact3d.solve(json.loads(fig8.read_text())) == impact3d.solve(fig8)
    case = impact3d.read_case(fig8)
    assert case.name.startswith("Figure 8") and case.source == str(fig8)
    assert impact3d.solve(case) == impact3d.solve(fig8)


@pytest.mark.parametrize("precision", ["double", "50", "100"])
def test_stronge_equals_the_cli(precision):
    """Stronge's integration through the package: the example that integrates it, its events, swerve and
    normal work included, the CLI's document field by field."""
    case = SOURCE / "examples" / "stronge" / "fig8_through_the_impact.json"
    ours = impact3d.solve(case, precision=precision)
    theirs = cli_document(cli("solve", case, "--format", "json", "--precision", precision), precision)
    assert ours == theirs
    integrated = [r for r in ours["results"] if r["strategy"]["name"] == "stronge"]
    assert len(integrated) == 3
    assert all(r["events"][0]["kind"] == "slip" and r["events"][-1]["kind"] == "end" for r in integrated)


def test_exact_arithmetic_refuses_stronge(fig8):
    with pytest.raises(impact3d.CaseError, match="stronge has no exact or certified form"):
        impact3d.solve(fig8, strategies=["stronge:mu=0.4"], precision="exact")
