#!/usr/bin/env python3
"""Plots the contact pressure along a contact interface from symcontact's contact CSV files.

    tools/plot_contact.py OUT.png contact_<pair>_<step>.csv [more.csv ...] [--x x|x_ref|...] [--hertz a,p0]
                          [--xlim LO,HI] [--side a|b|both] [--title T]

Reads the files `symcontact run` writes for every contact pair and load step, with the header

    side,surface,node,x,y[,z],x_ref,y_ref[,z_ref],gap,pressure,...,status

(one row per contact-surface node: `side` is "a" or "b", `x, y, z` the current position, `x_ref, ...`
the reference position, `pressure` the nodal contact pressure). Draws the pressure against one
coordinate (`--x`, default "x", or "x_ref" with `--hertz`), one series per file and side, the nodes in
contact filled and the open ones hollow.

`--hertz a,p0` adds the Hertz closed form p(x) = p0 sqrt(1 - x^2/a^2) for |x| <= a (0 outside), for
example `--hertz 0.107641,0.059143` for the 2D case of VALIDATION.md (V1), and prints, per series, the
peak nodal pressure against p0 and the extent of the nodes in contact against a (nodal: known to one
element). The closed form is small-strain theory, stated at the reference positions: with `--hertz`
the default coordinate is the reference one (x_ref; files without it fall back to x). At V1's load
the current positions of the contact zone sit about 2-3 % of a inward of the reference ones.

Needs only python3 and matplotlib (Debian: python3-matplotlib).
"""

import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

REQUIRED = ("side", "x", "y", "pressure", "status")


class CsvError(Exception):
    pass


def read_contact_csv(path):
    """{side: list of row dicts with float coordinates and pressure}, in file order."""
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            header = reader.fieldnames or []
            missing = [c for c in REQUIRED if c not in header]
            if missing:
                raise CsvError(f"{path}: not a symcontact contact CSV (missing columns {', '.join(missing)}; "
                               f"header: {','.join(header)})")
            sides = {}
            for line, row in enumerate(reader, start=2):
                try:
                    rec = {k: float(row[k]) for k in ("x", "y", "pressure")}
                    rec["z"] = float(row["z"]) if row.get("z") not in (None, "") else 0.0
                    for c in ("x_ref", "y_ref", "z_ref"):
                        if row.get(c) not in (None, ""):
                            rec[c] = float(row[c])
                except (TypeError, ValueError) as e:
                    raise CsvError(f"{path}: line {line}: not a number ({e})")
                rec["contact"] = row["status"] == "contact"
                rec["surface"] = row.get("surface") or ""
                sides.setdefault(row["side"], []).append(rec)
    except OSError as e:
        raise CsvError(f"{path}: cannot read: {e}")
    if not sides:
        raise CsvError(f"{path}: no rows")
    return sides


def hertz(x, a, p0):
    return p0 * math.sqrt(1.0 - (x / a) ** 2) if abs(x) < a else 0.0


def pair_of_numbers(text, what):
    try:
        lo, hi = (float(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{what}: expected two numbers separated by a comma, got {text!r}")
    return lo, hi


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", metavar="OUT.png", help="picture to write")
    ap.add_argument("files", metavar="FILE.csv", nargs="+", help="contact_<pair>_<step>.csv files")
    ap.add_argument("--x", dest="coord", default=None, choices=("x", "y", "z", "x_ref", "y_ref", "z_ref"),
                    help="coordinate along the interface (default: x, or x_ref with --hertz)")
    ap.add_argument("--side", default="both", choices=("a", "b", "both"), help="which side(s) to draw")
    ap.add_argument("--hertz", type=lambda s: pair_of_numbers(s, "--hertz"), default=None, metavar="a,p0",
                    help="draw the Hertz closed form with half-width a and peak pressure p0")
    ap.add_argument("--xlim", type=lambda s: pair_of_numbers(s, "--xlim"), default=None, metavar="LO,HI",
                    help="range of the horizontal axis (default: the contact zone and a margin)")
    ap.add_argument("--title", default=None, help="picture title")
    args = ap.parse_args(argv)

    try:
        data = [(f, read_contact_csv(f)) for f in args.files]
    except CsvError as e:
        print(f"plot_contact: {e}", file=sys.stderr)
        return 2
    has_ref = all("x_ref" in r for _, sides in data for rows in sides.values() for r in rows)
    if args.coord is None:
        args.coord = "x_ref" if args.hertz and has_ref else "x"
    elif args.coord.endswith("_ref") and not has_ref:
        print(f"plot_contact: --x {args.coord}: the files have no reference positions (written by an older "
              f"symcontact); use --x {args.coord[0]}", file=sys.stderr)
        return 2

    fig, ax = plt.subplots(figsize=(8, 5), dpi=120)
    markers = {"a": "o", "b": "s"}
    xs_contact, pmax, reports = [], 0.0, []
    for path, sides in data:
        label_file = os.path.splitext(os.path.basename(path))[0]
        for side, rows in sorted(sides.items()):
            if args.side != "both" and side != args.side:
                continue
            rows = sorted(rows, key=lambda r: r[args.coord])
            x = [r[args.coord] for r in rows]
            p = [r["pressure"] for r in rows]
            on = [r["contact"] for r in rows]
            xs_contact += [xi for xi, c in zip(x, on) if c]
            pmax = max([pmax] + p)
            label = f"{label_file}, side {side}" + (f" ({rows[0]['surface']})" if rows[0]["surface"] else "")
            line, = ax.plot(x, p, "-", linewidth=0.8, alpha=0.6)
            colour = line.get_color()
            ax.plot([xi for xi, c in zip(x, on) if c], [pi for pi, c in zip(p, on) if c], markers.get(side, "^"),
                    color=colour, markersize=4, label=label)
            ax.plot([xi for xi, c in zip(x, on) if not c], [pi for pi, c in zip(p, on) if not c],
                    markers.get(side, "^"), color=colour, markerfacecolor="none", markersize=4)
            if args.hertz:
                a, p0 = args.hertz
                pk = max(p)
                half_width = max([abs(xi) for xi, c in zip(x, on) if c] + [0.0])
                reports.append(f"{label}: peak pressure {pk:.6g} (Hertz p0 {p0:.6g}, {100 * (pk / p0 - 1):+.2f} %), "
                               f"contact zone |{args.coord}| <= {half_width:.6g} (Hertz a {a:.6g})")

    if args.xlim:
        lo, hi = args.xlim
    else:
        span = max([abs(v) for v in xs_contact] + ([args.hertz[0]] if args.hertz else []) + [1e-300])
        lo = -1.3 * span if xs_contact and min(xs_contact) < -1e-12 * span else 0.0
        hi = 1.3 * span
    if args.hertz:
        a, p0 = args.hertz
        n = 400
        xc = [lo + (hi - lo) * k / n for k in range(n + 1)]
        ax.plot(xc, [hertz(v, a, p0) for v in xc], "k--", linewidth=1.2,
                label=f"Hertz: $p_0\\sqrt{{1-x^2/a^2}}$, a = {a:.6g}, $p_0$ = {p0:.6g}")
        pmax = max(pmax, p0)
        for line in reports:
            print(f"plot_contact: {line}")
    ax.set_xlim(lo, hi)
    ax.set_ylim(0.0, 1.12 * pmax if pmax > 0 else 1.0)
    ax.set_xlabel(args.coord)
    ax.set_ylabel("contact pressure")
    ax.grid(True, linewidth=0.4, alpha=0.5)
    ax.legend(fontsize=8, loc="upper right")
    ax.set_title(args.title or "Contact pressure along the interface (filled: in contact)", fontsize=11)
    fig.tight_layout()
    try:
        fig.savefig(args.out)
    except OSError as e:
        print(f"plot_contact: cannot write {args.out}: {e}", file=sys.stderr)
        return 1
    print(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
