#!/usr/bin/env python3
"""Plots the regularised friction law of validation V4 from the CSV the test writes.

    tools/plot_friction_law.py friction_law.csv OUT.png [--title T]

The CSV is written by `symcontact_validation_tests --gtest_filter='V4FrictionLaw.TractionOpposes*'`
(path printed by the test, under the GoogleTest temporary folder). Its first line is a comment
`# V4 regularised friction law: mu = M, alpha = A, n = N`, then the header

    step,U,node,x,slip,ratio,pressure,tangential,end,du

one row per bottom node and load step: `slip` the node's slip increment of the step (weak nodal
average, signed along x), `ratio` = -sigma_T/sigma_n (nodal tangential traction over nodal pressure,
recovered from the nodal contact forces; the minus sign makes it positive for a positive slip),
`end` = 1 at the two end nodes of the contact zone.

Draws the solver's points (interior nodes and end nodes apart) over the curve mu u / sqrt(u^2 + alpha^2)
and the Coulomb limits +-mu, like the talk's figure (sigma_T/sigma_n against u_T). Prints the largest
distance of the points to the curve, interior and ends.

Needs only python3 and matplotlib (Debian: python3-matplotlib).
"""

import argparse
import csv
import math
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        first = f.readline()
        m_mu = re.search(r"mu = ([0-9.eE+-]+)", first)
        m_alpha = re.search(r"alpha = ([0-9.eE+-]+)", first)
        if not (first.startswith("#") and m_mu and m_alpha):
            sys.exit(f"{path}: line 1: expected '# ... mu = M, alpha = A', found {first.strip()!r}")
        rows = list(csv.DictReader(f))
    for key in ("slip", "ratio", "end"):
        if rows and key not in rows[0]:
            sys.exit(f"{path}: missing column {key!r}")
    return float(m_mu.group(1)), float(m_alpha.group(1)), rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv")
    ap.add_argument("out")
    ap.add_argument("--title", default=None)
    a = ap.parse_args()
    mu, alpha, rows = read(a.csv)
    if not rows:
        sys.exit(f"{a.csv}: no data rows")

    def law(u):
        return mu * u / math.sqrt(u * u + alpha * alpha)

    pts = {0: ([], []), 1: ([], [])}
    err = {0: 0.0, 1: 0.0}
    for r in rows:
        s, q, e = float(r["slip"]), float(r["ratio"]), int(r["end"])
        pts[e][0].append(s / alpha)
        pts[e][1].append(q)
        err[e] = max(err[e], abs(q - law(s)))
    smax = max(abs(v) for v in pts[0][0] + pts[1][0])
    lim = max(1.1 * smax, 3.0)
    n = 400
    us = [-lim + 2 * lim * i / (n - 1) for i in range(n)]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.axhline(mu, color="0.6", lw=0.8, ls="--")
    ax.axhline(-mu, color="0.6", lw=0.8, ls="--")
    ax.plot(us, [law(u * alpha) for u in us], "k-", lw=1.5, label=r"$\mu\, u/\sqrt{u^2+\alpha^2}$")
    ax.plot(pts[0][0], pts[0][1], "o", ms=3.5, mfc="none", color="C0", label="solver, interior nodes")
    ax.plot(pts[1][0], pts[1][1], "s", ms=4, color="C3", label="solver, the two end nodes")
    ax.set_xlim(-lim, lim)
    ax.set_xlabel(r"slip increment of the step $u_T / \alpha$")
    ax.set_ylabel(r"$-\sigma_T / \sigma_n$")
    ax.set_title(a.title or rf"V4: regularised Coulomb law, $\mu$ = {mu:g}, $\alpha$ = {alpha:g}")
    ax.legend(loc="lower right", fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)
    print(f"{len(rows)} points; max |ratio - law| / mu: interior {err[0] / mu:.3e}, ends {err[1] / mu:.3e}; "
          f"wrote {a.out}")


if __name__ == "__main__":
    main()
