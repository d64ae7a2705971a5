"""impact3d: three-dimensional rigid-body impact mechanics for automobile collisions (Marine), from
Python.

    case = impact3d.read_case("examples/fig8_side_impact.json")   # or a dict in the case format
    result = impact3d.solve(case)                                  # the contract's result document
    result["results"][0]["vehicles"][1]["delta_v_magnitude"]      # m/s for an SI case

- read_case, solve: one case, as `impact3d solve CASE --format json` (docs/case-format.md).
- solve_batch: pc-crash, Wach or Brach on many collisions held as NumPy columns, on every core, the GIL
  released.
- montecarlo, sensitivity: many-cases.md's documents, as `impact3d montecarlo` and `impact3d
  sensitivity` print them; montecarlo can also hand every sample over as arrays.
- reconstruct: pre-impact speeds and other unknowns from post-impact evidence, as `impact3d
  reconstruct` prints them.

Units are the case's (SI: m, kg, kg m^2, m/s, rad/s, N s, J; US: ft, lb, slug ft^2, mph, deg/s, lbf s,
ft lbf) unless `units` asks for others; angles are in degrees. Bad input raises CaseError (a
ValueError) whose message is the command line's one-line message: the file, the JSON path, the problem.
"""
import os
import warnings
from numbers import Integral

from . import _convert
from . import _impact3d
from ._impact3d import (BATCH_COLUMNS, BATCH_SIMD, PRECISIONS, REGIMES, STATUSES, WARNINGS, Case,
                        CaseError)

__all__ = ["read_case", "solve", "solve_batch", "montecarlo", "sensitivity", "reconstruct", "Case", "CaseError",
           "PRECISIONS", "REGIMES", "STATUSES", "WARNINGS", "BATCH_COLUMNS", "BATCH_SIMD"]


_MAX_JOBS = _impact3d.MAX_JOBS
_MAX_SEED = 2**64 - 1


def _whole(value, name, low, high, words):
    """`value` as an int from `low` to `high`, checked here rather than by the binding, whose refusal of
    a negative or huge int is a many-line TypeError: a bool or a float is a TypeError, a value out of
    range a ValueError, each one line in the command line's words."""
    if isinstance(value, bool) or not isinstance(value, Integral):
        raise TypeError(f"{name}: an int, not {type(value).__name__}")
    if not low <= value <= high:
        raise ValueError(f"{name}: {words}, not {int(value)}")
    return int(value)


def _json_text(value, what):
    try:
        return _convert.case_json(value)
    except _convert.InputError as e:
        raise CaseError(f"{what}: {e}" if what != "case" else str(e)) from None


def read_case(case):
    """The case `case`, read and checked: a path to a case file, a dict in the case format
    (docs/case-format.md; numbers as ints, floats, Decimals, which keep every digit, or NumPy scalars),
    or a Case already read. Raises CaseError for a case the command line would refuse, with its message;
    for a dict, the JSON path of the problem ("$.vehicles[0].mass: ...")."""
    if isinstance(case, Case):
        return case
    if isinstance(case, dict):
        return _impact3d.read_case_text(_json_text(case, "case"), "")
    if isinstance(case, (str, os.PathLike)):
        return _impact3d.read_case_file(os.fspath(case))
    raise TypeError(f"read_case: a path, a dict or a Case, not {type(case).__name__}")


def _strategies(strategies):
    if strategies is None:
        return []
    if isinstance(strategies, (str, dict)):
        strategies = [strategies]
    return [s if isinstance(s, str) else _json_text(s, "strategies") for s in strategies]


def solve(case, strategies=None, engine="generated", precision="double", units=None):
    """Solves `case` (anything read_case takes) and returns the contract's result document as
    `impact3d solve CASE --format json` prints it, as Python objects.

    strategies: replace the case's, each as --strategy takes it ("pc-crash:mu=0.4",
        "wach:mu=0.4,limit=gir") or as a dict ({"name": "pc-crash", "mu": 0.4}).
    engine: "generated" (the derived closed forms) or "direct" (3x3 solves).
    precision: one of PRECISIONS ("double", "long-double", "float128", "50", "100", "exact"), or
        "certified" / "certified:BITS" (ball arithmetic; adds "enclosures" and each result's
        "decisions"). Numbers are floats at double; Decimals, with every digit written, at the others;
        the exact precision's "exact" quantities are Fractions.
    units: "SI", "US" or "metric-kmh" (SI with km/h and deg/s); default the case's.

    Raises CaseError (bad input, or a strategy with no solution) and ValueError (a bad option)."""
    c = read_case(case)
    return _convert.document(_impact3d.solve_json(c, _strategies(strategies), engine, precision, units), precision)


def solve_batch(jobs=0, velocities=False, strategy="pc-crash", limit=None, **columns):
    """pc-crash, Wach or Brach on many collisions at once, the double precision's generated engine on
    SIMD lanes (BATCH_SIMD names the instruction set), on `jobs` threads (0: every core) with the GIL
    released. `strategy` is "pc-crash" (the default), "wach" (`limit` its cap, "cir", the default, or
    "gir") or "brach".

    Columns, in SI units, each a 1-D array (one row per collision) or a number for every row; their
    names are BATCH_COLUMNS, those of the NumPy peer bench/naive/pc_crash.py. For vehicle i = 1, 2:
        mass_i [kg]; Jpq_i [kg m^2], the inertia tensor about the CG in body axes (p, q = 0..2 for x, y,
            z; the upper triangle is read, and J10_i, J20_i, J21_i, when given, must equal it);
        yaw_i, pitch_i, roll_i [deg], body to world (z-y'-x'');
        v0_i, v1_i, v2_i [m/s], the CG velocity in world axes; w0_i, w1_i, w2_i [rad/s], the angular
            velocity in body axes; r0_i, r1_i, r2_i [m], the impulse centre in body axes;
    and normal_yaw, normal_pitch, tangent_roll [deg] (the contact frame), restitution; and the
    strategy's ratios: mu for pc-crash and Wach, mu_t and mu_z for Brach (signed; an absent one is
    critical on every row, eqs 25-27). Required: mass_i, J00_i, J11_i, J22_i, yaw_i, v0_i, v1_i, r0_i,
    r1_i, normal_yaw, restitution, and mu for pc-crash and Wach; the rest default to 0.

    Returns a dict of arrays, one row per input row:
        P_C (n, 3) [N s], the impulse on vehicle 1 in contact axes (n, t, z); NaN unless solved;
        status: index into STATUSES (solved, not approaching, singular, invalid);
        regime: index into REGIMES, or 255 for a row not solved; warnings: bit k set for WARNINGS[k];
        problems: {row: why} for each invalid row (it is flagged, not dropped);
    and with velocities=True (the scalar path, row by row) also P_W (n, 3) [N s] in world axes, v_1,
    v_2 (n, 3) [m/s] the CG velocities after (world) and w_1, w_2 (n, 3) [rad/s] the angular velocities
    after (body). Rows agree with solve's result for the same strategy within twice its rounding bound.

    Columns must be real numbers (integers, floats or booleans; not strings, complex numbers, dates or
    masked arrays). The call reads the caller's arrays in place while other Python threads run: do not
    change them until it returns. A row is invalid, as the case reader would refuse it, when a value is not
    finite or beyond the case format's magnitudes (1e12, and non-zero below 1e-100), a mass is not
    positive, an inertia tensor is not symmetric positive definite, restitution is outside [0, 1] or mu
    is negative. An unknown strategy or limit raises ValueError, one that is not a str TypeError."""
    jobs = _whole(jobs, "solve_batch: jobs", 0, _MAX_JOBS, f"from 0 (every core) to {_MAX_JOBS}")
    if not isinstance(strategy, str):
        raise TypeError(f"solve_batch: strategy: a str, not {type(strategy).__name__}")
    if limit is not None and not isinstance(limit, str):
        raise TypeError(f"solve_batch: limit: a str or None, not {type(limit).__name__}")
    return _impact3d._solve_batch(columns, jobs, velocities, strategy, limit)


def _uncertainty(uncertainty):
    if isinstance(uncertainty, dict):
        return _impact3d.Uncertainty(_json_text(uncertainty, "uncertainty"), "")
    if isinstance(uncertainty, (str, os.PathLike)):
        return _impact3d.read_uncertainty_file(os.fspath(uncertainty))
    raise TypeError(f"uncertainty: a path or a dict, not {type(uncertainty).__name__}")


def montecarlo(case, uncertainty, strategies=None, precision="double", engine="generated", jobs=0,
               samples=None, seed=None, keep_samples=False):
    """A Monte Carlo run of `case` over the inputs `uncertainty` makes uncertain (a path to, or a dict
    of, many-cases.md's U.json), as `impact3d montecarlo --format json` prints it: per strategy, each
    output's mean, sd, percentiles and their standard errors (in the case's units), the regimes', warnings'
    and rejections' counts, and the first-order propagation beside them. Reproducible: sample i is the
    same at any `jobs` (0: every core). `samples`, `seed` override the file's.

    Counts and the seed are ints, the statistics floats. keep_samples=True adds "sampled": {"inputs": {path: array}, "results": [{"regime": int8 array (REGIMES
    index, -1 not solved), "rejected": uint16 array (0 none, r + 1 reasons[r]), output path: array
    (NaN where rejected or undefined)}], "reasons": [...]}.

    Raises CaseError with the command line's messages."""
    jobs = _whole(jobs, "jobs", 0, _MAX_JOBS, f"from 0 (every core) to {_MAX_JOBS}")
    if samples is not None:
        samples = _whole(samples, "samples", 1, _impact3d.MAX_SAMPLES, f"from 1 to {_impact3d.MAX_SAMPLES}")
    if seed is not None:
        seed = _whole(seed, "seed", 0, _MAX_SEED, f"must be a whole number from 0 to {_MAX_SEED}")
    c = read_case(case)
    text, sampled = _impact3d.montecarlo(c, _uncertainty(uncertainty), _strategies(strategies), precision, engine,
                                         jobs, samples, seed, keep_samples)
    doc = _convert.summary(text)
    for k, r in enumerate(doc["results"]):  # as the command line warns
        if 2 * r["solved"] < doc["samples"]:
            warnings.warn(f"montecarlo: results[{k}] solved {r['solved']} of {doc['samples']} samples: its summary "
                          "describes only those", stacklevel=2)
    if sampled is not None:
        doc["sampled"] = sampled
    return doc


def sensitivity(case, strategies=None, engine="generated"):
    """The exact derivative and the elasticity of every reported output with respect to every numeric
    input of `case` (forward-mode automatic differentiation at double, the regime held fixed), with
    each regime's margin to its switch, as `impact3d sensitivity --format json` prints it
    (many-cases.md). Derivatives are in the case's units (output unit per input unit)."""
    c = read_case(case)
    return _convert.summary(_impact3d.sensitivity_json(c, _strategies(strategies), engine))


def reconstruct(case, evidence, strategy=None, engine="generated"):
    """Solves for the unknowns `evidence` names (a path to, or a dict of, many-cases.md's E.json: each
    vehicle's pre-impact speed, its heading, or any numeric input of the case) from what is known after
    the impact, by weighted least squares on the forward model of the case's one strategy (or
    `strategy`, as --strategy takes it), as `impact3d reconstruct --format json` prints it: the estimates
    with their standard errors and correlation, each evidence component's residual, chi2, its degrees
    of freedom and p-value, the regime at the fit, identifiability and the other admissible fits.
    Values are in the case's units; an unknown the evidence cannot determine has value and sd None.

    Raises CaseError with the command line's messages."""
    c = read_case(case)
    if isinstance(evidence, dict):
        text, source = _json_text(evidence, "evidence"), ""
    elif isinstance(evidence, (str, os.PathLike)):
        source = os.fspath(evidence)
        text = _impact3d.read_input_file(source)
    else:
        raise TypeError(f"evidence: a path or a dict, not {type(evidence).__name__}")
    if strategy is not None and not isinstance(strategy, str):
        strategy = _json_text(strategy, "strategy")
    return _convert.summary(_impact3d.reconstruct_json(c, text, source, strategy or "", engine))
