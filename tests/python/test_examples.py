"""The studies of examples/python/ run, meet the figures their headers state, and write their pictures."""

import re

from conftest import EXAMPLES, ink, run_python


def test_inclined_mu_sweep_meets_the_exact_law(tmp_path):
    png = tmp_path / "sweep.png"
    out = run_python(EXAMPLES / "python" / "inclined_mu_sweep.py", png)
    assert out.returncode == 0, out.stderr
    assert out.stdout.count("gross slip") == 5 and "NOT" not in out.stdout
    worst = float(re.search(r"largest relative deviation from the exact law: (\S+)", out.stdout).group(1))
    assert worst < 1e-7
    assert ink(png) > 0.02


def test_hertz_convergence_falls_at_first_order(tmp_path):
    png = tmp_path / "hertz.png"
    out = run_python(EXAMPLES / "python" / "hertz_convergence.py", png)
    assert out.returncode == 0, out.stderr
    slope = float(re.search(r"fitted slope over h >= \S+: (\S+)", out.stdout).group(1))
    assert 1.0 < slope < 1.4
    errors = [abs(float(e)) for e in re.findall(r"error ([-+]\d+\.\d+) %", out.stdout)]
    assert len(errors) == 5 and errors == sorted(errors, reverse=True) and errors[-1] < 0.2
    assert ink(png) > 0.02
