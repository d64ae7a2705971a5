"""The notebook-style example runs and draws its histogram (matplotlib without a display)."""
import os
import subprocess
import sys

from conftest import SOURCE


def test_montecarlo_example_draws_a_histogram(tmp_path):
    out = tmp_path / "dv.png"
    r = subprocess.run([sys.executable, str(SOURCE / "examples" / "python" / "montecarlo_fig8.py"), str(out)],
                       capture_output=True, text=True, timeout=600, env={**os.environ, "MPLBACKEND": "Agg"})
    assert r.returncode == 0, r.stderr
    assert "Malibu: Delta-V mean" in r.stdout
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and out.stat().st_size > 10000
