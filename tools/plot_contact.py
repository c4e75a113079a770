#!/usr/bin/env python3
"""Plots the contact pressure along a contact interface from symcontact's contact CSV files.

    tools/plot_contact.py OUT.png contact_<pair>_<step>.csv [more.csv ...] [--x x|x_ref|...] [--hertz a,p0]
                          [--xlim LO,HI] [--side a|b|both] [--title T]

Reads the files `symcontact run` writes for every contact pair and load step, with the header

    side,surface,node,x,y[,z],x_ref,y_ref[,z_ref],gap,pressure,...,slip_x,slip_y[,slip_z],...,status

(one row per contact-surface node: `side` is "a" or "b", `x, y, z` the current position, `x_ref, ...`
the reference position, `pressure` the nodal contact pressure, `slip_*` the slip increment of the step,
`status` one of "open", "contact" (in contact, no friction on that side), "stick" or "slip").

2D: draws the pressure against one coordinate (`--x`, default "x", or "x_ref" with `--hertz`), one
series (colour) per file and side; each node's marker says its status: a filled circle in contact
(sticking, or no friction on that side), a filled triangle slipping, a hollow circle open. The legend
lists the statuses present with their node counts.

3D: one row per file and side, two maps of the contact surface seen along its normal (the unit normal
of the plane fitted to the side's reference nodes, printed in the panel title): the contact pressure,
and the magnitude of the slip increment of the step with its direction as arrows (a side without
friction says so). The node markers and the legend are those of 2D. `--x`, `--hertz` and `--xlim` are
for 2D.

The legend's counts are printed too ("plot_contact: FILE side a: stick 12, slip 30, open 6").

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
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.tri import Triangulation  # noqa: E402

REQUIRED = ("side", "x", "y", "pressure", "status")
STATUSES = ("open", "contact", "stick", "slip")
# How each status is drawn (marker, filled) and named in the legend.
STATUS_STYLE = {
    "contact": ("o", True, "in contact (no friction on this side)"),
    "stick": ("o", True, "in contact, sticking"),
    "slip": ("^", True, "in contact, slipping"),
    "open": ("o", False, "open"),
}


class CsvError(Exception):
    pass


def read_contact_csv(path):
    """{side: list of row dicts}: every numeric column as a float (NaN where undefined), "status",
    "surface", in file order."""
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            header = reader.fieldnames or []
            missing = [c for c in REQUIRED if c not in header]
            if missing:
                raise CsvError(f"{path}: not a symcontact contact CSV (missing columns {', '.join(missing)}; "
                               f"header: {','.join(header)})")
            numeric = [c for c in header if c not in ("side", "surface", "node", "status")]
            sides = {}
            for line, row in enumerate(reader, start=2):
                try:
                    rec = {k: float(row[k]) for k in numeric if row.get(k) not in (None, "")}
                except (TypeError, ValueError) as e:
                    raise CsvError(f"{path}: line {line}: not a number ({e})")
                if row["status"] not in STATUSES:
                    raise CsvError(f"{path}: line {line}: status {row['status']!r} is none of {', '.join(STATUSES)}")
                rec.setdefault("z", 0.0)
                rec["status"] = row["status"]
                rec["surface"] = row.get("surface") or ""
                sides.setdefault(row["side"], []).append(rec)
    except OSError as e:
        raise CsvError(f"{path}: cannot read: {e}")
    if not sides:
        raise CsvError(f"{path}: no rows")
    return sides


def is_3d(sides):
    return any("z_ref" in r or "slip_z" in r or "tz" in r for rows in sides.values() for r in rows)


def hertz(x, a, p0):
    return p0 * math.sqrt(1.0 - (x / a) ** 2) if abs(x) < a else 0.0


def pair_of_numbers(text, what):
    try:
        lo, hi = (float(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{what}: expected two numbers separated by a comma, got {text!r}")
    return lo, hi


def status_counts(rows):
    return {s: sum(r["status"] == s for r in rows) for s in STATUSES if any(r["status"] == s for r in rows)}


def draw_status_markers(ax, xs, ys, statuses, colour, size=4, zorder=3, rim=None):
    """Each node's marker by its status (STATUS_STYLE): filled or hollow in `colour`; `rim`: a thin outline
    of that colour around each marker (visible on a colour map)."""
    for status, (marker, filled, _) in STATUS_STYLE.items():
        sel = [i for i, s in enumerate(statuses) if s == status]
        if not sel:
            continue
        x, y = [xs[i] for i in sel], [ys[i] for i in sel]
        if rim:
            ax.plot(x, y, marker, linestyle="none", markerfacecolor="none", markeredgecolor=rim,
                    markeredgewidth=2.6, markersize=size, zorder=zorder)
        ax.plot(x, y, marker, linestyle="none", color=colour, markerfacecolor=colour if filled else "none",
                markeredgewidth=1.0, markersize=size, zorder=zorder + 1)


def status_legend_handles(counts):
    """Legend entries (black markers) for the statuses drawn, with their node counts."""
    handles = []
    for status, (marker, filled, name) in STATUS_STYLE.items():
        if counts.get(status):
            handles.append(Line2D([], [], marker=marker, linestyle="none", color="k",
                                  markerfacecolor="k" if filled else "none", markersize=5,
                                  label=f"{name}: {counts[status]}"))
    return handles


def selected(data, side_choice):
    """[(label, rows)] of every file and side to draw."""
    out = []
    for path, sides in data:
        label_file = os.path.splitext(os.path.basename(path))[0]
        for side, rows in sorted(sides.items()):
            if side_choice != "both" and side != side_choice:
                continue
            label = f"{label_file}, side {side}" + (f" ({rows[0]['surface']})" if rows[0]["surface"] else "")
            out.append((label, rows))
    return out


def render_2d(args, series):
    fig, ax = plt.subplots(figsize=(8, 5), dpi=120)
    xs_contact, pmax, reports, total = [], 0.0, [], {}
    for label, rows in series:
        rows = sorted(rows, key=lambda r: r[args.coord])
        x = [r[args.coord] for r in rows]
        p = [r["pressure"] for r in rows]
        st = [r["status"] for r in rows]
        xs_contact += [xi for xi, s in zip(x, st) if s != "open"]
        pmax = max([pmax] + p)
        line, = ax.plot(x, p, "-", linewidth=0.8, alpha=0.7, label=label)
        draw_status_markers(ax, x, p, st, line.get_color())
        for k, n in status_counts(rows).items():
            total[k] = total.get(k, 0) + n
        if args.hertz:
            a, p0 = args.hertz
            pk = max(p)
            half_width = max([abs(xi) for xi, s in zip(x, st) if s != "open"] + [0.0])
            reports.append(f"{label}: peak pressure {pk:.6g} (Hertz p0 {p0:.6g}, {100 * (pk / p0 - 1):+.2f} %), "
                           f"contact zone |{args.coord}| <= {half_width:.6g} (Hertz a {a:.6g})")
    all_x = [r[args.coord] for _, rows in series for r in rows]
    if args.xlim:
        lo, hi = args.xlim
    elif xs_contact or args.hertz:
        span = max([abs(v) for v in xs_contact] + ([args.hertz[0]] if args.hertz else []))
        lo = -1.3 * span if xs_contact and min(xs_contact) < -1e-12 * span else 0.0
        hi = 1.3 * span
        if span == 0.0:
            lo, hi = min(all_x), max(all_x)
    else:  # nothing in contact: the whole surface
        lo, hi = min(all_x), max(all_x)
    if hi <= lo:
        lo, hi = lo - 0.5, hi + 0.5
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
    handles, _ = ax.get_legend_handles_labels()
    ax.legend(handles=handles + status_legend_handles(total), fontsize=8, loc="upper right")
    ax.set_title(args.title or "Contact pressure along the interface", fontsize=11)
    return fig


def plane_basis(points):
    """Unit vectors (e1, e2, n) of the plane fitted to `points` (n × 3): n the direction of least spread,
    oriented towards +z, +y or +x (the first that is not ~0); e1 along the largest spread, its largest
    component positive; e2 = n × e1."""
    import numpy as np

    centred = points - points.mean(axis=0)
    _, _, vt = np.linalg.svd(centred, full_matrices=False)
    e1, n = vt[0], vt[2]
    for axis in (2, 1, 0):
        if abs(n[axis]) > 1e-8:
            if n[axis] < 0:
                n = -n
            break
    if e1[np.argmax(np.abs(e1))] < 0:
        e1 = -e1
    return e1, np.cross(n, e1), n


def surface_map(fig, ax, tri, values, label, cmap, markers):
    """A colour map of nodal `values` over the projected surface, with the status markers (u, v, statuses)."""
    pc = ax.tripcolor(tri, values, shading="gouraud", cmap=cmap)
    fig.colorbar(pc, ax=ax, label=label, fraction=0.04, pad=0.02)
    u, v, statuses = markers
    draw_status_markers(ax, u, v, statuses, "k", size=5, zorder=3, rim="w")


def render_3d(args, series):
    import numpy as np

    panels, heights = [], []  # (label, rows, what) per row of the figure
    for label, rows in series:
        ref = np.array([[r.get("x_ref", r["x"]), r.get("y_ref", r["y"]), r.get("z_ref", r["z"])] for r in rows])
        e1, e2, n = plane_basis(ref)
        u, v = ref @ e1, ref @ e2
        aspect = (np.ptp(v) or 1.0) / (np.ptp(u) or 1.0)
        slip = np.array([[r.get("slip_x", np.nan), r.get("slip_y", np.nan), r.get("slip_z", np.nan)] for r in rows])
        geometry = (u, v, e1, e2, n, slip)
        panels.append((label, rows, "pressure", geometry))
        if np.isfinite(slip).all(axis=1).any():
            panels.append((label, rows, "slip", geometry))
        heights += [float(np.clip(7.5 * aspect, 1.4, 6.0)) + 1.3] * (len(panels) - len(heights))
    fig, axes = plt.subplots(len(panels), 1, figsize=(9, sum(heights) + 0.6), dpi=110, squeeze=False,
                             gridspec_kw={"height_ratios": heights})
    for (label, rows, what, (u, v, e1, e2, n, slip)), (ax,) in zip(panels, axes):
        tri = Triangulation(u, v)
        statuses = [r["status"] for r in rows]
        normal = "n = ({:.3g}, {:.3g}, {:.3g})".format(*(0.0 if abs(c) < 1e-12 else c for c in n))
        if what == "pressure":
            surface_map(fig, ax, tri, np.array([r["pressure"] for r in rows]), "contact pressure", "viridis",
                        (u, v, statuses))
            friction = "" if np.isfinite(slip).all(axis=1).any() else "; no friction on this side"
            ax.set_title(f"{label}\ncontact pressure, seen along {normal}{friction}", fontsize=9)
            ax.legend(handles=status_legend_handles(status_counts(rows)), fontsize=7, loc="upper left",
                      bbox_to_anchor=(0.0, -0.12 if len(panels) > 1 else -0.18), ncol=4, framealpha=0.9)
        else:
            ok = np.isfinite(slip).all(axis=1)
            magnitude = np.where(ok, np.linalg.norm(np.nan_to_num(slip), axis=1), 0.0)
            surface_map(fig, ax, tri, magnitude, "|slip increment|", "magma", (u, v, statuses))
            ax.quiver(u[ok], v[ok], (slip @ e1)[ok], (slip @ e2)[ok], color="c", angles="xy", width=0.003,
                      zorder=5)
            ax.set_title(f"{label}\nslip increment of the step (arrows: its direction), seen along {normal}",
                         fontsize=9)
        ax.set_aspect("equal")
        ax.set_xlabel("along e1 = ({:.2g}, {:.2g}, {:.2g})".format(*e1), fontsize=8)
        ax.set_ylabel("along e2 = ({:.2g}, {:.2g}, {:.2g})".format(*e2), fontsize=8)
        ax.margins(0.03)
    fig.suptitle(args.title or "Contact over the surface", fontsize=11)
    fig.tight_layout()
    return fig


def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", metavar="OUT.png", help="picture to write")
    ap.add_argument("files", metavar="FILE.csv", nargs="+", help="contact_<pair>_<step>.csv files")
    ap.add_argument("--x", dest="coord", default=None, choices=("x", "y", "z", "x_ref", "y_ref", "z_ref"),
                    help="2D: coordinate along the interface (default: x, or x_ref with --hertz)")
    ap.add_argument("--side", default="both", choices=("a", "b", "both"), help="which side(s) to draw")
    ap.add_argument("--hertz", type=lambda s: pair_of_numbers(s, "--hertz"), default=None, metavar="a,p0",
                    help="2D: draw the Hertz closed form with half-width a and peak pressure p0")
    ap.add_argument("--xlim", type=lambda s: pair_of_numbers(s, "--xlim"), default=None, metavar="LO,HI",
                    help="2D: range of the horizontal axis (default: the contact zone and a margin)")
    ap.add_argument("--title", default=None, help="picture title")
    return ap.parse_args(argv)


def render(argv):
    """The figure for the command line `argv` (without the program name), and the drawn series
    [(label, rows)]. Raises CsvError for unreadable files, ValueError for options that do not apply."""
    args = parse_args(argv)
    data = [(f, read_contact_csv(f)) for f in args.files]
    three_d = {is_3d(sides) for _, sides in data}
    if len(three_d) != 1:
        raise ValueError("the files mix 2D and 3D contact tables")
    series = selected(data, args.side)
    if not series:
        raise ValueError(f"--side {args.side}: no such side in the files")
    if three_d.pop():
        if args.hertz or args.xlim or args.coord:
            raise ValueError("--x, --hertz and --xlim are for 2D contact tables")
        return args, render_3d(args, series), series
    has_ref = all("x_ref" in r for _, rows in series for r in rows)
    if args.coord is None:
        args.coord = "x_ref" if args.hertz and has_ref else "x"
    elif args.coord.endswith("_ref") and not has_ref:
        raise ValueError(f"--x {args.coord}: the files have no reference positions (written by an older "
                         f"symcontact); use --x {args.coord[0]}")
    return args, render_2d(args, series), series


def main(argv=None):
    try:
        args, fig, series = render(sys.argv[1:] if argv is None else argv)
    except (CsvError, ValueError) as e:
        print(f"plot_contact: {e}", file=sys.stderr)
        return 2
    for label, rows in series:
        print(f"plot_contact: {label}: " + ", ".join(f"{k} {n}" for k, n in status_counts(rows).items()))
    try:
        fig.savefig(args.out)
    except OSError as e:
        print(f"plot_contact: cannot write {args.out}: {e}", file=sys.stderr)
        return 1
    print(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
