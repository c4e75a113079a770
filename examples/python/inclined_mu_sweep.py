#!/usr/bin/env python3
"""Sliding on an inclined interface: |R_x / R_y| against the friction coefficient mu (docs/validation-friction.md, V5).

What it solves. examples/inclined_2d/inclined_reference.toml (two elastic blocks cut by the line
y = 0.45 + 0.1 x, tan(a) = 0.1; the top pressed down, then pushed up the slope; Coulomb friction; contact
written in the reference configuration, geometry = "reference", the small-sliding problem the closed form
assumes) on a coarse mesh (mesh_size 0.1), for mu = 0, 0.1, ..., 0.4, each through the Python module.

What to expect. In gross slip (every node of the friction side in contact slipping, the last load step)
the upper block is held by its top-edge reaction R and the interface force N n - mu N t, so
    |R_x / R_y| = (tan a + mu) / (1 - mu tan a) = tan(a + phi),  tan(phi) = mu,
met to about 1e-8 relative (the regularisation alpha and the solver tolerances; measured 2.8e-9 at most).
Up to mu = 0.4 the push of the example (U = 0.03) reaches gross slip; at mu = 0.5 two nodes still stick.
The script prints one line per mu and writes the picture (a few seconds in Release).

How to run (from the repository root, after building):
    PYTHONPATH=build/python python3 examples/python/inclined_mu_sweep.py inclined_mu_sweep.png
"""

import argparse
import math
import pathlib
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import symcontact  # noqa: E402

EXAMPLE = pathlib.Path(__file__).resolve().parents[1] / "inclined_2d" / "inclined_reference.toml"
TAN_A = 0.1  # the interface's slope


def exact_ratio(mu):
    return (TAN_A + mu) / (1.0 - mu * TAN_A)


def solve(problem, mu):
    """|R_x / R_y| on the upper top edge at the last step, and whether every friction-side node in
    contact slips there."""
    problem["contact.0.mu"] = mu
    result = problem.run()
    rx, ry = result.reaction("upper", "upper_top")[-1]
    table = result.contact["interface"][-1]
    friction_side = np.isin(table["status"], ("stick", "slip"))
    gross_slip = bool(np.all(table["status"][friction_side] == "slip"))
    return abs(rx / ry), gross_slip


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", nargs="?", default="inclined_mu_sweep.png", help="picture to write")
    ap.add_argument("--mesh-size", type=float, default=0.1, help="largest element size (default 0.1)")
    args = ap.parse_args(argv)

    problem = symcontact.Problem(EXAMPLE)
    problem["problem.mesh_size"] = args.mesh_size
    mus = np.round(np.arange(0.0, 0.401, 0.1), 2)
    ratios, worst = [], 0.0
    for mu in mus:
        ratio, gross_slip = solve(problem, float(mu))
        deviation = ratio / exact_ratio(mu) - 1.0
        worst = max(worst, abs(deviation))
        ratios.append(ratio)
        print(f"mu = {mu:.2f}: |R_x/R_y| = {ratio:.10f}, exact {exact_ratio(mu):.10f} ({deviation:+.1e}), "
              f"{'gross slip' if gross_slip else 'NOT in gross slip'}")
    print(f"largest relative deviation from the exact law: {worst:.1e}")

    fig, ax = plt.subplots(figsize=(6.5, 4.5), dpi=120)
    mu_line = np.linspace(0.0, mus[-1], 200)
    ax.plot(mu_line, exact_ratio(mu_line), "k-", linewidth=1.0,
            label=r"exact: $(\tan\alpha + \mu)/(1 - \mu\tan\alpha)$")
    ax.plot(mus, ratios, "o", color="tab:red", markersize=6, label="symcontact (last load step)")
    ax.set_xlabel(r"friction coefficient $\mu$")
    ax.set_ylabel(r"$|R_x / R_y|$ on the upper top edge")
    ax.set_title(rf"Inclined interface, $\tan\alpha$ = {TAN_A}: gross slip (largest deviation {worst:.0e})",
                 fontsize=10)
    ax.grid(True, linewidth=0.4, alpha=0.5)
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(args.out)
    print(args.out)
    return 0 if all(math.isfinite(r) for r in ratios) else 1


if __name__ == "__main__":
    sys.exit(main())
