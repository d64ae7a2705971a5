"""The program's JSON documents as Python objects, and Python objects as case JSON.

Result documents: floats at double (17 significant digits read back exactly; every number of a result
is a physical quantity, so an integral one written "975" is a float too), Decimals at the other
precisions (every digit written), and the exact precision's rational quantities (its "exact" object,
strings p/q) as Fractions. Nothing goes through a double that was not one. The Monte Carlo and
sensitivity documents also hold counts and seeds: integers there stay ints.
"""
import json
import math
import re
from decimal import Decimal
from fractions import Fraction
from numbers import Integral, Real

_RATIONAL = re.compile(r"-?[0-9]+(/[0-9]+)?")


def _fractions(node):
    if isinstance(node, dict):
        return {k: _fractions(v) for k, v in node.items()}
    if isinstance(node, list):
        return [_fractions(v) for v in node]
    if isinstance(node, str) and _RATIONAL.fullmatch(node):
        return Fraction(node)
    return node  # a note, or why a quantity is not rational


def document(text, precision="double"):
    """The result document `text`, written at `precision`, with its numbers as that precision allows."""
    if precision == "double":
        return json.loads(text, parse_int=float)
    doc = json.loads(text, parse_float=Decimal, parse_int=Decimal)
    if precision == "exact" and "exact" in doc:
        doc["exact"] = _fractions(doc["exact"])
    if precision.startswith("certified") and "enclosures" in doc:
        doc["enclosures"] = {path: [None if b is None else Decimal(b) for b in bounds]
                             for path, bounds in doc["enclosures"].items()}
    return doc


def summary(text):
    """A Monte Carlo or sensitivity document: floats, with its counts and seeds as ints."""
    return json.loads(text)


class InputError(ValueError):
    """A value with no JSON form, at its JSON path."""


# The case reader's nesting limit (case_format/limits.hpp, docs/limits-and-exit-status.md), checked before Python's own
# recursion limit is reached: a dict nested 100 000 deep, or one holding itself, is bad input.
MAX_DEPTH = 32


def _member(path, key):
    """`path.key`, or `path["key"]` with the key escaped (as the reader's messages write it) where it
    is not an identifier: a key holding a newline stays on one line."""
    if key.isascii() and key.isidentifier():
        return f"{path}.{key}"
    return f"{path}[{json.dumps(key)}]"


def case_json(value, path="$", depth=0):
    """`value` (dicts, lists, tuples, strings, booleans, None, ints, floats, Decimals, NumPy scalars) as
    JSON text; a Decimal keeps every digit. Raises InputError naming the path of what has no JSON form,
    or of a container nested deeper than MAX_DEPTH levels."""
    if isinstance(value, (dict, list, tuple)) and depth >= MAX_DEPTH:
        raise InputError(f"{path}: nested deeper than {MAX_DEPTH} levels")
    if isinstance(value, dict):
        items = []
        for k, v in value.items():
            if not isinstance(k, str):
                raise InputError(f"{path}: a key that is not a string: {k!r}")
            items.append(json.dumps(k) + ": " + case_json(v, _member(path, k), depth + 1))
        return "{" + ", ".join(items) + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(case_json(v, f"{path}[{i}]", depth + 1) for i, v in enumerate(value)) + "]"
    if value is None or isinstance(value, (bool, str)):
        return json.dumps(value)
    if type(value).__name__ == "bool_":  # NumPy's
        return "true" if value else "false"
    if isinstance(value, Decimal):
        if not value.is_finite():
            raise InputError(f"{path}: not a finite number: {value}")
        return str(value)
    if isinstance(value, Integral):
        return str(int(value))
    if isinstance(value, Real):
        x = float(value)
        if not math.isfinite(x):
            raise InputError(f"{path}: not a finite number: {x}")
        return repr(x)
    raise InputError(f"{path}: {type(value).__name__} has no JSON form")
