"""Shared by the tests: where the sources and the command-line program are (ctest sets IMPACT3D_CLI and
IMPACT3D_SOURCE_DIR), and the program run as a user runs it."""
import json
import os
import subprocess
from decimal import Decimal
from fractions import Fraction
from pathlib import Path

import pytest

SOURCE = Path(os.environ.get("IMPACT3D_SOURCE_DIR", Path(__file__).resolve().parents[2]))
CLI = os.environ.get("IMPACT3D_CLI", str(SOURCE / "build" / "cli" / "impact3d"))
EXAMPLES = sorted((SOURCE / "examples").glob("*.json"))


def cli(*args):
    """The program's standard output, read as JSON; fails the test on a non-zero status."""
    r = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    return r.stdout


def cli_document(text, precision):
    """The CLI's JSON read independently of the package: floats at double, Decimals from the literals
    elsewhere, the exact object's p/q strings as Fractions."""
    if precision == "double":
        return json.loads(text, parse_int=float)
    doc = json.loads(text, parse_float=Decimal, parse_int=Decimal)

    def fractions(node):
        if isinstance(node, dict):
            return {k: fractions(v) for k, v in node.items()}
        if isinstance(node, list):
            return [fractions(v) for v in node]
        if isinstance(node, str) and node.replace("/", "").lstrip("-").isdigit():
            return Fraction(node)
        return node

    if "exact" in doc:
        doc["exact"] = fractions(doc["exact"])
    if "enclosures" in doc:
        doc["enclosures"] = {p: [None if b is None else Decimal(b) for b in v] for p, v in doc["enclosures"].items()}
    return doc


def cli_error(*args):
    """The program's one error line after "impact3d: error: ", for a run that must fail on bad input."""
    r = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=600)
    assert r.returncode == 1 and r.stdout == "", r.stderr
    prefix = "impact3d: error: "
    assert r.stderr.startswith(prefix) and r.stderr.count("\n") == 1
    return r.stderr[len(prefix):-1]


@pytest.fixture
def fig8():
    return SOURCE / "examples" / "fig8_side_impact.json"
