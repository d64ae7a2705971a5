#!/usr/bin/env python3
"""N generated pc-crash cases on stdout, for `impact3d batch` end to end (bench/batch.sh): the bundled
Figure 8 case with its strategy replaced by pc-crash (mu 0.5) and the speeds, the impulse centre and the
restitution varied by a seeded generator, so that both regimes occur. JSON Lines, or with --csv the same
cases as CSV (a header of case paths, docs/batch.md, "Cases as CSV")."""
import json
import random
import sys

def cases(n, case):
    case.pop("_source", None)
    case["strategy"] = [{"name": "pc-crash", "mu": 0.5}]
    rng = random.Random(11)
    for _ in range(n):
        c = json.loads(json.dumps(case))
        for v in c["vehicles"]:
            v["velocity"] = [round(x * rng.uniform(0.7, 1.3), 6) for x in v["velocity"]]
            v["impulse_center"] = [round(x + rng.uniform(-0.2, 0.2), 6) for x in v["impulse_center"]]
        c["restitution"] = round(rng.uniform(0.0, 0.4), 6)
        yield c

def leaves(value, path=""):
    """(path, value) of every number and string, paths spelled as the CSV header wants them."""
    if isinstance(value, dict):
        for k, v in value.items():
            yield from leaves(v, f"{path}.{k}" if path else k)
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from leaves(v, f"{path}[{i}]")
    else:
        yield path, value

def main():
    as_csv = "--csv" in sys.argv
    n, template = [a for a in sys.argv[1:] if a != "--csv"]
    out = sys.stdout
    if not as_csv:
        for c in cases(int(n), json.load(open(template))):
            out.write(json.dumps(c, separators=(",", ":")) + "\n")
        return
    for i, c in enumerate(cases(int(n), json.load(open(template)))):
        row = list(leaves(c))
        if i == 0:
            out.write(",".join(p for p, _ in row) + "\n")
        # Numbers unquoted (read as numbers), strings always quoted (read as strings).
        out.write(",".join(json.dumps(v) if not isinstance(v, str) else '"' + v.replace('"', '""') + '"' for _, v in row) + "\n")

if __name__ == "__main__":
    main()
