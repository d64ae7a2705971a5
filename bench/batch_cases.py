#!/usr/bin/env python3
"""N generated pc-crash cases as JSON Lines on stdout, for `impact3d batch` end to end (bench/batch.sh):
the bundled Figure 8 case with its strategy replaced by pc-crash (mu 0.5) and the speeds, the impulse
centre and the restitution varied by a seeded generator, so that both regimes occur."""
import json
import random
import sys

def main():
    n = int(sys.argv[1])
    case = json.load(open(sys.argv[2]))
    case.pop("_source", None)
    case["strategy"] = [{"name": "pc-crash", "mu": 0.5}]
    rng = random.Random(11)
    out = sys.stdout
    for _ in range(n):
        c = json.loads(json.dumps(case))
        for v in c["vehicles"]:
            v["velocity"] = [round(x * rng.uniform(0.7, 1.3), 6) for x in v["velocity"]]
            v["impulse_center"] = [round(x + rng.uniform(-0.2, 0.2), 6) for x in v["impulse_center"]]
        c["restitution"] = round(rng.uniform(0.0, 0.4), 6)
        out.write(json.dumps(c, separators=(",", ":")) + "\n")

if __name__ == "__main__":
    main()
