#!/usr/bin/env python3
"""Hertz 2D, cylinder on a rigid plane: the error of the peak pressure against the element size h
(docs/validation.md, V1), log-log, with the fitted slope.

What it solves. examples/hertz_2d/cylinder_on_plane.toml (a cylinder R = 1, E = 1, nu = 0.3, plane
strain, half model, pressed on a rigid plane by P = 0.01 per unit thickness) with the element size h near
the contact point set to 0.032, 0.016, ..., 0.002: each mesh is a two-line .geo in a temporary folder that
sets h and includes the example's cylinder_on_plane.geo (which keeps an h defined before it), and the
problem's body[0].mesh is pointed at it.

What to expect. The peak nodal pressure against the closed form p0 = 2 P / (pi a) = 0.059143,
a = sqrt(4 P R / (pi E*)) = 0.107641: -1.9 % at h = 0.032, -0.37 % at h = 0.008, then a floor near
-0.17 % (h = 0.004: -0.181 %, 0.002: -0.169 %, as docs/validation.md V1 states) that refinement does not
remove. The slope is fitted over h >= 0.008, where the discretisation error dominates: 1.17. The
script prints one line per mesh and writes the picture (a few seconds in Release).

How to run (from the repository root, after building):
    PYTHONPATH=build/python python3 examples/python/hertz_convergence.py hertz_convergence.png
"""

import argparse
import math
import pathlib
import sys
import tempfile

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import symcontact  # noqa: E402

EXAMPLE = pathlib.Path(__file__).resolve().parents[1] / "hertz_2d" / "cylinder_on_plane.toml"
P, R, E, NU = 0.01, 1.0, 1.0, 0.3
E_STAR = E / (1.0 - NU**2)
A = math.sqrt(4.0 * P * R / (math.pi * E_STAR))
P0 = 2.0 * P / (math.pi * A)
FIT_FROM = 0.008  # the slope is fitted over h >= this


def peak_pressure(problem, h, folder):
    geo = pathlib.Path(folder) / f"cylinder_h{h:g}.geo"
    geo.write_text(f'h = {h!r};\nInclude "{EXAMPLE.parent / "cylinder_on_plane.geo"}";\n')
    problem["body.0.mesh"] = str(geo)
    result = problem.run()
    return result.contact["floor"][-1]["pressure"].max(), result.summary["num_dofs"]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", nargs="?", default="hertz_convergence.png", help="picture to write")
    args = ap.parse_args(argv)

    problem = symcontact.Problem(EXAMPLE)
    hs = np.array([0.032, 0.016, 0.008, 0.004, 0.002])
    errors = []
    with tempfile.TemporaryDirectory() as folder:
        for h in hs:
            p, dofs = peak_pressure(problem, float(h), folder)
            errors.append(abs(p / P0 - 1.0))
            print(f"h = {h:.3f} ({dofs:.0f} DOFs): peak pressure {p:.6f}, p0 {P0:.6f}, error {100 * (p / P0 - 1):+.3f} %")
    errors = np.array(errors)
    fit = hs >= FIT_FROM
    slope, log_c = np.polyfit(np.log(hs[fit]), np.log(errors[fit]), 1)
    print(f"fitted slope over h >= {FIT_FROM}: {slope:.2f}")

    fig, ax = plt.subplots(figsize=(6.5, 4.5), dpi=120)
    ax.loglog(hs, 100 * errors, "o-", color="tab:blue", label="|peak pressure / $p_0$ - 1|")
    ax.loglog(hs[fit], 100 * np.exp(log_c) * hs[fit] ** slope, "k--", linewidth=1.0,
              label=f"fit over h $\\geq$ {FIT_FROM}: slope {slope:.2f}")
    ax.set_xlabel("element size h at the contact point")
    ax.set_ylabel("error of the peak pressure (%)")
    ax.set_title(f"Hertz 2D, cylinder on a plane: $p_0$ = {P0:.6f}, a = {A:.6f}", fontsize=10)
    ax.grid(True, which="both", linewidth=0.4, alpha=0.5)
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(args.out)
    print(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
