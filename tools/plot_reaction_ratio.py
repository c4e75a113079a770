#!/usr/bin/env python3
"""Plots the ratio |R_x / R_y| of a body's Dirichlet reactions against the load step, from symcontact
summary.json files, one curve per file, with the exact limits as dashed lines.

    tools/plot_reaction_ratio.py OUT.png SUMMARY.json [SUMMARY.json ...] [--labels L ...]
                                 [--exact V ...] [--body upper] [--boundary B] [--title T]

R is the sum of the "force" of every entry of steps[k].reactions whose "body" is `--body` (default
"upper") and, with `--boundary`, whose "boundary" is that group: for the inclined interface
(examples/inclined_2d, VALIDATION.md V5) the upper body's top edge, whose u_x and u_y conditions each
carry one component. `--exact` gives one value per file (the gross-slip limit
(tan a + mu) / (1 - mu tan a)), drawn dashed in the curve's colour; the last step's ratio and its
error against it are printed, one line per file:

    plot_reaction_ratio: mu = 0.2: step 10 |Rx/Ry| = 0.305541, exact 0.306122 (-0.190 %)

Needs only python3 and matplotlib (Debian: python3-matplotlib).
"""

import argparse
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


class SummaryError(Exception):
    pass


def reaction_vectors(path, body, boundary):
    """[(step, R)] of one summary.json, R the summed reaction vector (2 or 3 components) of `body` (on
    `boundary`, if given)."""
    try:
        with open(path) as f:
            summary = json.load(f)
    except (OSError, ValueError) as e:
        raise SummaryError(f"{path}: cannot read as JSON: {e}")
    steps = summary.get("steps")
    if not isinstance(steps, list) or not steps:
        raise SummaryError(f"{path}: no steps (status {summary.get('status')!r})")
    out = []
    for k, step in enumerate(steps):
        total = None
        for r in step.get("reactions", []):
            if r.get("body") != body or (boundary and r.get("boundary") != boundary):
                continue
            force = r.get("force") or []
            if len(force) < 2:
                raise SummaryError(f"{path}: steps[{k}].reactions: a force with fewer than 2 components")
            total = list(force) if total is None else [a + b for a, b in zip(total, force)]
        if total is None:
            names = sorted({(r.get("body"), r.get("boundary")) for r in step.get("reactions", [])})
            raise SummaryError(f"{path}: steps[{k}]: no reaction of body {body!r}"
                               + (f" on {boundary!r}" if boundary else "") + f" (reactions: {names})")
        out.append((int(step.get("step", k + 1)), total))
    return out


def reaction_history(path, body, boundary):
    """[(step, R_x, R_y)] of one summary.json: the summed reactions of `body` (on `boundary`, if given)."""
    return [(step, r[0], r[1]) for step, r in reaction_vectors(path, body, boundary)]


def reaction_ratios(path, body, boundary):
    """[(step, |R_x / R_y|)] of one summary.json."""
    out = []
    for step, rx, ry in reaction_history(path, body, boundary):
        if ry == 0.0:
            raise SummaryError(f"{path}: step {step}: R_y = 0, the ratio is undefined")
        out.append((step, abs(rx / ry)))
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("out", metavar="OUT.png", help="picture to write")
    ap.add_argument("files", metavar="SUMMARY.json", nargs="+", help="summary.json of `symcontact run`")
    ap.add_argument("--labels", nargs="+", default=None, help="one legend label per file")
    ap.add_argument("--exact", nargs="+", type=float, default=None, help="one exact limit per file")
    ap.add_argument("--body", default="upper", help="the body whose reactions are summed (default: upper)")
    ap.add_argument("--boundary", default=None, help="only the reactions of this boundary group")
    ap.add_argument("--title", default=None, help="picture title")
    args = ap.parse_args(argv)
    for name, values in (("--labels", args.labels), ("--exact", args.exact)):
        if values is not None and len(values) != len(args.files):
            print(f"plot_reaction_ratio: {name}: expected {len(args.files)} values (one per file), "
                  f"got {len(values)}", file=sys.stderr)
            return 2
    labels = args.labels or args.files

    try:
        series = [reaction_ratios(f, args.body, args.boundary) for f in args.files]
    except SummaryError as e:
        print(f"plot_reaction_ratio: {e}", file=sys.stderr)
        return 2

    fig, ax = plt.subplots(figsize=(7, 4.6), dpi=130)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    last_step = max(s[-1][0] for s in series)
    for i, (label, points) in enumerate(zip(labels, series)):
        colour = colours[i % len(colours)]
        steps = [s for s, _ in points]
        ratios = [r for _, r in points]
        ax.plot(steps, ratios, "o-", color=colour, label=label)
        if args.exact:
            exact = args.exact[i]
            ax.axhline(exact, color=colour, linestyle="--", linewidth=1.0)
            ax.annotate(f"exact {exact:.6f}", xy=(last_step + 1.15, exact), xytext=(0, 2),
                        textcoords="offset points", ha="right", va="bottom", fontsize=8, color=colour)
            print(f"plot_reaction_ratio: {label}: step {steps[-1]} |Rx/Ry| = {ratios[-1]:.6f}, exact {exact:.6f} "
                  f"({100 * (ratios[-1] / exact - 1):+.3f} %)")
        else:
            print(f"plot_reaction_ratio: {label}: step {steps[-1]} |Rx/Ry| = {ratios[-1]:.6f}")
    ax.set_xlabel("load step")
    ax.set_ylabel("|R_x / R_y|")
    ax.set_xlim(0.5, last_step + 1.2)
    ax.set_ylim(bottom=0.0)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper left")
    title = args.title or f"|R_x / R_y| on body {args.body!r}"
    if args.exact:
        title += "\n(dashed: exact gross-slip limits)"
    ax.set_title(title, fontsize=11)
    fig.tight_layout()
    try:
        fig.savefig(args.out)
    except OSError as e:
        print(f"plot_reaction_ratio: cannot write {args.out}: {e}", file=sys.stderr)
        return 1
    print(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
