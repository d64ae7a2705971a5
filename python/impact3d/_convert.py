"""The result documents' numbers as Python numbers, as their precision allows: floats at double (17
significant digits read back exactly), Decimals at the other precisions (every digit written), and the
exact precision's rational quantities (its "exact" object, strings p/q) as Fractions. Nothing goes
through a double that was not one.
"""
import json
from decimal import Decimal
from fractions import Fraction


def _fractions(node):
    if isinstance(node, dict):
        return {k: _fractions(v) for k, v in node.items()}
    if isinstance(node, list):
        return [_fractions(v) for v in node]
    if isinstance(node, str):
        try:
            return Fraction(node)
        except ValueError:
            return node  # a note, or why a quantity is not rational
    return node


def document(text, precision="double"):
    """The JSON document `text`, written at `precision`, with its numbers as that precision allows."""
    if precision == "double":
        return json.loads(text, parse_int=float)
    doc = json.loads(text, parse_float=Decimal, parse_int=Decimal)
    if precision == "exact" and "exact" in doc:
        doc["exact"] = _fractions(doc["exact"])
    if precision.startswith("certified") and "enclosures" in doc:
        doc["enclosures"] = {path: [None if b is None else Decimal(b) for b in bounds]
                             for path, bounds in doc["enclosures"].items()}
    return doc
