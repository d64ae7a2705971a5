"""Issue 11's targets against one round of bench/targets.sh: measured, target, met or not.

Usage: targets.py BENCH_JSON NUMPY_TXT BATCH_TXT BATCH_TENTH_TXT; exits 1 unless every target is met.

Times per case come from each repetition's own rows (Google Benchmark's JSON): the cases of an iteration
are items_per_second x cpu_time, so a repetition's real time per case is its real time over them. Each
route is given by its median repetition and its least beside it; a verdict rests on the median, since
this host's load only adds time and a least repetition flatters every route alike. The NumPy peer prints
only its best of five runs (naive/pc_crash.py), which makes the ratio to it the harder one. Ratios are
within the round. Every target is always listed: one whose route did not run (an instruction set this
CPU lacks, a missing peer, a batch of another size) says so and counts as not met.
"""
import json
import re
import statistics
import sys

BATCH_ROWS = 1_000_000
BATCH_LIMITS = {"JSON Lines in, JSON Lines out": 10, "CSV in, CSV out": 5}
# Memory is flat when the peak grows by less than this many bytes per row from a tenth of the rows to all
# of them. A row kept would cost at least its input (about 400 bytes as CSV, 800 as JSON Lines); the
# fourteenth session measured 3 to 10 bytes a row for JSON Lines out, under 2 for CSV (BENCHMARKS.md).
FLAT_BYTES_PER_ROW = 16
LEAN = "pc_crash_lean<Engine::generated, Want::impulse>"
DIRECT = "pc_crash_lean<Engine::direct, Want::impulse>"
NAIVE, P100 = "pc_crash_naive", "pc_crash_lean_100_digits"


def per_case(bench_json):
    """{run name: [real ns per case of each repetition]} and {run name: label}."""
    runs, labels = {}, {}
    for b in json.load(open(bench_json))["benchmarks"]:
        if b.get("run_type") != "iteration" or b.get("error_occurred"):
            continue
        if b["time_unit"] != "ns":
            sys.exit(f"targets.py: {b['name']} is timed in {b['time_unit']}, not ns")
        cases = round(b["items_per_second"] * b["cpu_time"] * 1e-9)
        if cases not in (64, 1024):
            sys.exit(f"targets.py: {b['name']}: {cases} cases an iteration, not 64 or 1024")
        runs.setdefault(b["run_name"], []).append(b["real_time"] / cases)
        labels[b["run_name"]] = b.get("label", "")
    return runs, labels


def batch_runs(path):
    """The case count and {label: (wall s, peak KiB)} of bench/batch.sh's runs."""
    rows, runs, label = None, {}, None
    for line in open(path):
        if m := re.match(r"input: (\d+) cases", line):
            rows = int(m.group(1))
        if line.endswith(":\n") and not line.startswith(" "):
            label = line[:-2]
        if m := re.search(r"wall ([0-9.]+) s, .* peak memory (\d+) KiB", line):
            runs[label] = (float(m.group(1)), int(m.group(2)))
    return rows, runs


def main(bench_json, numpy_txt, batch_txt, tenth_txt):
    runs, labels = per_case(bench_json)
    med = {k: statistics.median(v) for k, v in runs.items()}
    least = {k: min(v) for k, v in runs.items()}
    found = re.search(r"pc_crash_numpy: (\d+) ns", open(numpy_txt).read())
    numpy = int(found.group(1)) if found else None
    rows = []

    def row(what, target, value=None, met=False):
        rows.append((what, "not measured" if value is None else value, target, "met" if met else "NOT met"))

    def timed(what, name, limit, scale=1.0, digits=1):
        if name in med:
            shown = f"{med[name] / scale:.{digits}f} (least {least[name] / scale:.{digits}f})"
            row(what, f"<= {limit:g}", shown, med[name] <= limit * scale)
        else:
            row(what, f"<= {limit:g}")

    def ratio(what, slower, faster, at_least, note=""):
        if slower is not None and faster is not None:
            row(what, f">= {at_least}x", f"{slower / faster:.2f}x{note}", slower / faster >= at_least)
        else:
            row(what, f">= {at_least}x")

    simd = min((k for k in med if k.startswith("pc_crash_simd/")), key=med.get, default=None)
    timed(f"SIMD lanes ({labels[simd]}), ns a case" if simd else "SIMD lanes, ns a case", simd, 50)
    simd_time = med.get(simd)
    ratio("  naive C++ peer / SIMD", med.get(NAIVE), simd_time, 3,
          f" (peer {med[NAIVE]:.1f} ns)" if NAIVE in med else "")
    ratio("  NumPy peer (best of 5) / SIMD", numpy, simd_time, 35, f" (peer {numpy} ns)")
    timed("scalar lean path, ns a case", LEAN, 200)
    ratio("direct / generated engine, lean path", med.get(DIRECT), med.get(LEAN), 3)
    timed("100 digits, us a case", P100, 30, scale=1e3, digits=2)

    n, whole = batch_runs(batch_txt)
    n_tenth, tenth = batch_runs(tenth_txt)
    for label, limit in BATCH_LIMITS.items():
        what = f"batch of {BATCH_ROWS:,} rows, {label}, s"
        if n == BATCH_ROWS and label in whole:
            row(what, f"<= {limit}", f"{whole[label][0]:.2f}", whole[label][0] <= limit)
        else:
            row(what, f"<= {limit}")
    if n == BATCH_ROWS and n_tenth == n // 10 and len(whole) == 3 and whole.keys() == tenth.keys():
        growth = max((whole[k][1] - tenth[k][1]) * 1024 / (n - n_tenth) for k in whole)
        peaks = ", ".join(f"{tenth[k][1] // 1024}->{whole[k][1] // 1024}" for k in whole)
        row("batch memory growth, bytes a row", f"< {FLAT_BYTES_PER_ROW} (flat)",
            f"{growth:.1f} (MiB {peaks})", growth < FLAT_BYTES_PER_ROW)
    else:
        row("batch memory growth, bytes a row", f"< {FLAT_BYTES_PER_ROW} (flat)")

    met, total = sum(r[3] == "met" for r in rows), len(rows)
    if NAIVE in med:
        rows.append(("(host: naive C++ peer, ns a case)", f"{med[NAIVE]:.1f} (least {least[NAIVE]:.1f})", "", ""))
    width = max(len(r[0]) for r in rows)
    for what, value, target, verdict in rows:
        print(f"  {what:<{width}}  {value:<32} {target:<12} {verdict}")
    print(f"  {met} of {total} targets met")
    return 0 if met == total else 1


if __name__ == "__main__":
    if len(sys.argv) != 5:
        sys.exit(__doc__.splitlines()[2])
    sys.exit(main(*sys.argv[1:5]))
