"""Figure 8's collision with uncertain inputs: a Monte Carlo run from Python, and each vehicle's Delta-V
as a histogram. Notebook-style: run it whole, or cell by cell (# %%) in Jupyter or an editor.

    PYTHONPATH=build/python python3 examples/python/montecarlo_fig8.py [OUT.png]
"""
# %% The case and the uncertainty: the paper's Figure 8, and ranges a reconstructionist might give it
import sys
from pathlib import Path

import matplotlib
if len(sys.argv) > 1:
    matplotlib.use("Agg")  # writing a file: no window
import matplotlib.pyplot as plt
import numpy as np

import impact3d

here = Path(__file__).resolve().parent.parent
case = impact3d.read_case(here / "fig8_side_impact.json")
uncertainty = here / "uncertainty" / "fig8_side_impact.json"
print(case.name)

# %% 20 000 samples on every core; keep each sample's outputs as arrays
run = impact3d.montecarlo(case, uncertainty, samples=20000, keep_samples=True)
strategy = 0  # pc-crash at mu = 1.0
result = run["results"][strategy]
print(f"{run['samples']} samples, seed {run['seed']}: {result['solved']} solved")

# %% Delta-V of each vehicle (m/s): the samples, and the summary impact3d gives of them
fig, ax = plt.subplots(figsize=(7, 4))
for k, vehicle in enumerate(("Malibu", "Suburban")):
    path = f"vehicles[{k}].delta_v_magnitude"
    dv = run["sampled"]["results"][strategy][path]
    dv = dv[~np.isnan(dv)]
    summary = result["outputs"][path]
    ax.hist(dv, bins=60, alpha=0.6, label=f"{vehicle}: mean {summary['mean']:.2f} m/s, sd {summary['sd']:.2f}")
    print(f"{vehicle}: Delta-V mean {summary['mean']:.3f} m/s (sd {summary['sd']:.3f})")
ax.set_xlabel("Delta-V (m/s)")
ax.set_ylabel("samples")
ax.set_title("Figure 8, pc-crash at mu = 1.0: Delta-V over the input uncertainty")
ax.legend()
fig.tight_layout()

# %% Show it, or write it where asked
if len(sys.argv) > 1:
    fig.savefig(sys.argv[1], dpi=100)
else:
    plt.show()
