"""Issue 11's targets against one round of bench/targets.sh: measured, target, met or not.

Usage: targets.py BENCH_JSON NUMPY_TXT BATCH_TXT BATCH_TENTH_TXT

Times per case come from each repetition's own rows (Google Benchmark's JSON): the cases of an iteration
are items_per_second x cpu_time, so a repetition's real time per case is its real time over them. Each
route is given by its median and its least repetition; a verdict rests on the median, since this host's
load only adds time and a least repetition flatters every route alike. Ratios are of medians in the same
run. A route that did not run (an instruction set this CPU lacks) is left out; a target with nothing to
judge it says so and counts as not met.
"""
import json
import re
import statistics
import sys


def per_case(bench_json):
    """{run name: [real ns per case of each repetition]} and {run name: label}."""
    runs, labels = {}, {}
    for b in json.load(open(bench_json))["benchmarks"]:
        if b.get("run_type") != "iteration" or b.get("error_occurred"):
            continue
        cases = round(b["items_per_second"] * b["cpu_time"] * 1e-9)
        runs.setdefault(b["run_name"], []).append(b["real_time"] / cases)
        labels[b["run_name"]] = b.get("label", "")
    return runs, labels


def batch_runs(path):
    """[(label, wall s, peak KiB)] of bench/batch.sh's three runs."""
    out, label = [], None
    for line in open(path):
        if line.endswith(":\n") and not line.startswith(" "):
            label = line[:-2]
        m = re.search(r"wall ([0-9.]+) s, .* peak memory (\d+) KiB", line)
        if m:
            out.append((label, float(m.group(1)), int(m.group(2))))
    return out


def main(bench_json, numpy_txt, batch_txt, tenth_txt):
    runs, labels = per_case(bench_json)
    med = {k: statistics.median(v) for k, v in runs.items()}
    least = {k: min(v) for k, v in runs.items()}
    numpy = re.search(r"pc_crash_numpy: (\d+) ns", open(numpy_txt).read())
    rows, judged = [], []

    def row(what, value, target, met):
        rows.append((what, value, target, "met" if met else "NOT met"))
        judged.append(met)

    simd = sorted((med[k], k) for k in med if k.startswith("pc_crash_simd/"))
    lean, direct = "pc_crash_lean<Engine::generated, Want::impulse>", "pc_crash_lean<Engine::direct, Want::impulse>"
    naive, p100 = "pc_crash_naive", "pc_crash_lean_100_digits"

    def have(*names):
        return all(k in med for k in names)

    if simd and have(naive) and numpy:
        s, k = simd[0]
        row(f"SIMD lanes ({labels[k]}), ns a case", f"{s:.1f} (least {least[k]:.1f})", "<= 50", s <= 50)
        row("  naive C++ peer / SIMD", f"{med[naive] / s:.1f}x (peer {med[naive]:.1f} ns)", ">= 3x", med[naive] / s >= 3)
        row("  NumPy peer / SIMD", f"{int(numpy.group(1)) / s:.1f}x (peer {numpy.group(1)} ns)", ">= 35x",
            int(numpy.group(1)) / s >= 35)
    else:
        row("SIMD lanes and their peers", "not measured", "", False)
    if have(lean):
        row("scalar lean path, ns a case", f"{med[lean]:.1f} (least {least[lean]:.1f})", "<= 200", med[lean] <= 200)
    else:
        row("scalar lean path", "not measured", "", False)
    if have(lean, direct):
        row("direct / generated engine, lean path", f"{med[direct] / med[lean]:.2f}x", ">= 3x", med[direct] / med[lean] >= 3)
    if have(p100):
        row("100 digits, us a case", f"{med[p100] / 1e3:.1f} (least {least[p100] / 1e3:.1f})", "<= 30",
            med[p100] <= 30e3)
    else:
        row("100 digits", "not measured", "", False)
    whole, tenth = batch_runs(batch_txt), batch_runs(tenth_txt)
    limits = {"JSON Lines in, JSON Lines out": 10, "CSV in, CSV out": 5}
    for label, wall, peak in whole:
        if label in limits:
            row(f"batch, {label}, s", f"{wall:.2f}", f"<= {limits[label]}", wall <= limits[label])
    if len(whole) == len(tenth) == 3:
        growth = max(p / q for (_, _, p), (_, _, q) in zip(whole, tenth))
        row("batch peak memory, all rows / a tenth", f"{growth:.2f}x", "flat (<= 1.5x)", growth <= 1.5)
    else:
        row("batch", "not measured", "", False)
    if have(naive):
        rows.append(("(host: naive C++ peer, ns a case)", f"{med[naive]:.1f} (least {least[naive]:.1f})", "", ""))
    width = max(len(r[0]) for r in rows)
    for what, value, target, verdict in rows:
        print(f"  {what:<{width}}  {value:<28} {target:<15} {verdict}")
    print(f"  {sum(judged)} of {len(judged)} targets met")


if __name__ == "__main__":
    main(*sys.argv[1:5])
