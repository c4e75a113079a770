#!/usr/bin/env python3
"""Plots the reaction-force history of a body (its components against the load step) from symcontact
summary.json files, one set of curves per file, and prints the mean ratio |R_t / R_n| of the tangential
to the normal reaction over a range of steps (for ironing: the steady-sliding ratio of the frictional
case, to set beside mu).

    tools/plot_reactions.py OUT.png SUMMARY.json [SUMMARY.json ...] [--labels L ...] --body die
                            [--boundary die_ends] [--normal y] [--tangential x] [--steady FIRST LAST]
                            [--ratio MU] [--title T]

The normal component n and the tangential component(s) t (one letter, or two for the length of that
pair, e.g. `--tangential xz`): by default y and x in 2D; in 3D n is the component of the largest
reaction (summed over the steps and files) and t the other two, so a sphere pressed along z gives
|R_t / R_n| = |(R_x, R_y)| / |R_z|. The choice is printed.

R is the sum of the "force" of every entry of steps[k].reactions whose "body" is `--body` (and, with
`--boundary`, whose "boundary" is that group), as in tools/plot_reaction_ratio.py. The force is the one
the supports exert on the body; the plot shows its opposite, the force the body exerts on its supports
(for a die pressed into a slab: positive R_y pushes up).

With `--ratio MU`, a second panel below shows |R_x / R_y| of every file against the load step, with the
friction coefficient MU as a dashed line (for frictional ironing: the ratio in steady sliding is MU plus
the ploughing of the groove).

Needs only python3 and matplotlib (Debian: python3-matplotlib).
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_reaction_ratio import SummaryError, reaction_vectors  # noqa: E402

AXES = "xyz"


def choose_components(series, normal, tangential):
    """(normal index, [tangential indices]) from the options, or the defaults (module docstring)."""
    dim = len(series[0][0][1])
    if normal is None:
        if dim == 2:
            normal = "y"
        else:
            size = [sum(abs(r[i]) for points in series for _, r in points) for i in range(dim)]
            normal = AXES[max(range(dim), key=lambda i: size[i])]
    if tangential is None:
        tangential = "".join(c for c in AXES[:dim] if c != normal)
    for c in normal + tangential:
        if c not in AXES[:dim]:
            raise SummaryError(f"component {c!r}: the reactions have {dim} components ({AXES[:dim]})")
    if len(normal) != 1 or not 1 <= len(tangential) <= 2 or normal in tangential:
        raise SummaryError(f"--normal {normal} --tangential {tangential}: expected one normal component and "
                           "one or two other tangential ones")
    return AXES.index(normal), [AXES.index(c) for c in tangential]


def tangential_normal(r, n, t):
    return sum(r[i] ** 2 for i in t) ** 0.5, r[n]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("out", metavar="OUT.png", help="picture to write")
    ap.add_argument("files", metavar="SUMMARY.json", nargs="+", help="summary.json of `symcontact run`")
    ap.add_argument("--labels", nargs="+", default=None, help="one legend label per file")
    ap.add_argument("--body", required=True, help="the body whose reactions are summed")
    ap.add_argument("--boundary", default=None, help="only the reactions of this boundary group")
    ap.add_argument("--normal", default=None, choices=tuple(AXES), help="the normal component (default: see above)")
    ap.add_argument("--tangential", default=None, metavar="C[C]",
                    help="the tangential component(s), e.g. x or xz (default: see above)")
    ap.add_argument("--steady", nargs=2, type=int, default=None, metavar=("FIRST", "LAST"),
                    help="steps over which the mean |R_x / R_y| is printed")
    ap.add_argument("--ratio", type=float, default=None, metavar="MU",
                    help="add a panel with the ratio |R_t / R_n| and a dashed line at MU")
    ap.add_argument("--ratio-label", default=None, help="legend of that line (default: friction coefficient MU)")
    ap.add_argument("--title", default=None, help="picture title")
    args = ap.parse_args(argv)
    if args.labels is not None and len(args.labels) != len(args.files):
        print(f"plot_reactions: --labels: expected {len(args.files)} values, got {len(args.labels)}", file=sys.stderr)
        return 2
    labels = args.labels or args.files
    try:
        series = [reaction_vectors(f, args.body, args.boundary) for f in args.files]
        n, t = choose_components(series, args.normal, args.tangential)
    except SummaryError as e:
        print(f"plot_reactions: {e}", file=sys.stderr)
        return 2
    t_name = "".join(AXES[i] for i in t)
    if len(t) == 1:
        ratio_name = f"|R_{t_name} / R_{AXES[n]}|"
    else:
        ratio_name = f"|(R_{AXES[t[0]]}, R_{AXES[t[1]]})| / |R_{AXES[n]}|"
    print(f"plot_reactions: normal component {AXES[n]}, tangential {t_name}: ratio {ratio_name}")

    if args.ratio is None:
        fig, ax = plt.subplots(figsize=(7.5, 4.6), dpi=130)
        ax_ratio = None
    else:
        fig, (ax, ax_ratio) = plt.subplots(2, 1, figsize=(7.5, 7.0), dpi=130, sharex=True,
                                           gridspec_kw={"height_ratios": [3, 2]})
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    styles = ["--", ":", "-."]
    for i, (label, points) in enumerate(zip(labels, series)):
        colour = colours[i % len(colours)]
        steps = [p[0] for p in points]
        ax.plot(steps, [-p[1][n] for p in points], "-", color=colour, label=f"{label}: $-R_{AXES[n]}$ (normal)")
        for k, j in enumerate(t):
            ax.plot(steps, [-p[1][j] for p in points], styles[k], color=colour,
                    label=f"{label}: $-R_{AXES[j]}$ (tangential)")
        pairs = [(step, *tangential_normal(r, n, t)) for step, r in points]
        sel = [p for p in pairs if p[2] != 0.0]
        if ax_ratio is not None:
            ax_ratio.plot([p[0] for p in sel], [abs(p[1] / p[2]) for p in sel], "-", color=colour, label=label)
        if args.steady:
            first, last = args.steady
            sel = [p for p in sel if first <= p[0] <= last]
            if sel:
                ratio = sum(abs(p[1] / p[2]) for p in sel) / len(sel)
                print(f"plot_reactions: {label}: mean {ratio_name} over steps {first}-{last} = {ratio:.4f}")
    ax.set_ylabel("force on the supports")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    if ax_ratio is None:
        ax.set_xlabel("load step")
    else:
        ax_ratio.axhline(args.ratio, color="k", ls="--", lw=1,
                         label=args.ratio_label or f"friction coefficient {args.ratio:g}")
        ax_ratio.set_xlabel("load step")
        ax_ratio.set_ylabel(ratio_name)
        ax_ratio.grid(True, alpha=0.3)
        ax_ratio.legend(loc="best", fontsize=8)
    ax.set_title(args.title or f"Reactions of body {args.body!r}", fontsize=11)
    fig.tight_layout()
    try:
        fig.savefig(args.out)
    except OSError as e:
        print(f"plot_reactions: cannot write {args.out}: {e}", file=sys.stderr)
        return 1
    print(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
