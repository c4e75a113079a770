#!/usr/bin/env python3
"""Draws several symcontact results side by side in one PNG: one panel per case, every body of a case in
its panel, all on the same displacement amplification and the same colour scale.

    tools/plot_side_by_side.py OUT.png --panel TITLE FILE.vtu [FILE.vtu ...] --panel TITLE FILE.vtu ...
                               [--scale S [S ...]] [--field von_mises] [--title T] [--dpi N] [--slip-arrows]

For example the three inclined-interface cases of scripts/demo (VALIDATION.md, V5), at amplification 5:

    tools/plot_side_by_side.py inclined.png --scale 5 \\
        --panel "mu = 0"   mu0/lower_0010.vtu   mu0/upper_0010.vtu \\
        --panel "mu = 0.1" mu0.1/lower_0010.vtu mu0.1/upper_0010.vtu \\
        --panel "mu = 0.2" mu0.2/lower_0010.vtu mu0.2/upper_0010.vtu

Each panel shows the mesh moved by `--scale` times the point data "displacement" (default 5; `auto`:
the largest displacement drawn as 10 % of the model size), coloured by a point or cell field (default
"von_mises"; vectors and tensors by their norm), and the undeformed outline in grey. Several scales
(`--scale 5 200`) give one row of panels per scale, in the same PNG: small displacements (as in the
inclined-interface cases) are invisible at the talk's amplification 5 and plain at 200. With
`--slip-arrows` each panel also gets, at mid-height of every body, an arrow of the body's mean
displacement drawn at the same amplification (how far and which way each body moved). 2D meshes only.
The .vtu files are read with tools/plot_vtu.py (ASCII VTK XML UnstructuredGrid, as `symcontact run`
writes them).

Needs only python3, numpy and matplotlib (Debian: python3-numpy python3-matplotlib).
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_vtu  # noqa: E402  (the .vtu reader and the 2D drawing)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def _scale(text):
    if text == "auto":
        return None
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number or 'auto', got {text!r}")
    if not value >= 0.0:
        raise argparse.ArgumentTypeError(f"expected a non-negative amplification, got {text!r}")
    return value


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("out", metavar="OUT.png", help="picture to write")
    ap.add_argument("--panel", nargs="+", action="append", required=True, metavar="TITLE FILE.vtu",
                    help="one panel: its title, then one .vtu file per body (repeat for every panel)")
    ap.add_argument("--field", default="von_mises", help="point or cell data to colour by (default: von_mises)")
    ap.add_argument("--scale", type=_scale, nargs="+", default=[5.0],
                    help="displacement amplification, the same for every panel; several values: one row "
                         "of panels each (default 5; 'auto': the largest displacement of all panels drawn "
                         "as 10%% of the model size)")
    ap.add_argument("--title", default=None, help="title over the panels")
    ap.add_argument("--dpi", type=int, default=110, help="resolution of the PNG (default 110)")
    ap.add_argument("--slip-arrows", action="store_true",
                    help="draw every body's mean displacement as an arrow (at the same amplification)")
    args = ap.parse_args(argv)

    panels = []
    try:
        for spec in args.panel:
            if len(spec) < 2:
                raise plot_vtu.VtuError(f"--panel {spec[0]!r}: expected a title and at least one .vtu file")
            bodies = [plot_vtu.Body(f) for f in spec[1:]]
            if any(b.dim != 2 for b in bodies):
                raise plot_vtu.VtuError(f"--panel {spec[0]!r}: only 2D meshes can be drawn side by side")
            panels.append((spec[0], bodies, [b.field(args.field) for b in bodies]))
    except plot_vtu.VtuError as e:
        print(f"plot_side_by_side: {e}", file=sys.stderr)
        return 2

    every_body = [b for _, bodies, _ in panels for b in bodies]
    scales = [plot_vtu.default_scale(every_body) if v is None else v for v in args.scale]
    values = np.concatenate([v for _, _, fields in panels for v, _ in fields])
    lo, hi = float(values.min()), float(values.max())
    if hi - lo <= 1e-6 * max(abs(lo), abs(hi)):
        mid = 0.5 * (lo + hi)
        half = 0.05 * abs(mid) if mid != 0.0 else 1.0
        lo, hi = mid - half, mid + half
    norm = matplotlib.colors.Normalize(vmin=lo, vmax=hi)
    cmap = plt.get_cmap("viridis")

    # One row of panels per scale, every panel with the same limits; the figure sized to the drawing.
    pts = np.vstack([np.vstack([b.points[:, :2], b.points[:, :2] + s * b.u[:, :2]])
                     for b in every_body for s in scales])
    (x_lo, y_lo), (x_hi, y_hi) = pts.min(axis=0), pts.max(axis=0)
    pad = 0.04 * max(x_hi - x_lo, y_hi - y_lo)
    x_lo, x_hi, y_lo, y_hi = x_lo - pad, x_hi + pad, y_lo - pad, y_hi + pad
    ncol, nrow = len(panels), len(scales)
    width = 3.6 * ncol + 1.0
    height = nrow * (3.1 * (y_hi - y_lo) / max(x_hi - x_lo, 1e-300) + 0.45) + 0.8
    fig, axes = plt.subplots(nrow, ncol, figsize=(width, height), dpi=args.dpi, squeeze=False, sharex=True,
                             sharey=True, layout="constrained")
    mappable = None
    for row, scale in enumerate(scales):
        for ax, (title, bodies, fields) in zip(axes[row], panels):
            mappable = plot_vtu.draw_2d(ax, bodies, fields, scale, norm, cmap)
            if args.slip_arrows:
                for b in bodies:
                    c = b.points[:, :2].mean(axis=0)
                    d = scale * b.u[:, :2].mean(axis=0)
                    if np.linalg.norm(d) > 0:
                        ax.annotate("", xy=c + d, xytext=c, zorder=5,
                                    arrowprops=dict(arrowstyle="->", color="crimson", lw=1.5))
            ax.set_xlim(x_lo, x_hi)
            ax.set_ylim(y_lo, y_hi)
            ax.set_aspect("equal")
            ax.set_title(f"{title}, displacement x {scale:.3g}" if nrow > 1 else title, fontsize=10)
        axes[row][0].set_ylabel("y")
    for ax in axes[-1]:
        ax.set_xlabel("x")
    fig.colorbar(mappable, ax=axes.ravel().tolist(), shrink=0.9, aspect=30, label=args.field)
    title = args.title or "deformed states"
    shown = " and ".join(f"x {s:.3g}" for s in scales)
    fig.suptitle(f"{title}\n(displacement {shown}; undeformed outline in grey)", fontsize=12)
    try:
        fig.savefig(args.out, bbox_inches="tight")
    except OSError as e:
        print(f"plot_side_by_side: cannot write {args.out}: {e}", file=sys.stderr)
        return 1
    print(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
