#!/usr/bin/python3
"""Log-log plot of time against DOFs for the side-by-side Hertz benchmark (symcontact, FreeFEM + ff-Ipopt,
and the CHOLMOD floor of the same stiffness), from the CSV of `symcontact-bench --case hertz2d-freefem`.

    tools/plot_freefem_peer.py hertz2d_freefem.csv hertz2d_freefem.png [--title T] [--wall] [--dpi N]
                               [--markdown]

--markdown also prints the two tables of docs/performance.md ("Side by side with FreeFEM + IPOPT": times
and ratios, then accuracy) from the same CSV.

Plotted per size (CPU seconds by default, as the table's ratios use them; `--wall` plots wall-clock times):
  symcontact      solve_contact() (geometry fixed point, IPOPT, polish)        sym_solve_cpu_s  / sym_solve_wall_s
  FreeFEM+IPOPT   the IPOPT() call in FreeFEM (CPU clock())                     ff_ipopt_cpu_s   / (same)
  FreeFEM process the whole FreeFem++ run (start-up, mesh, assembly, IPOPT)     ff_process_cpu_s / ff_wall_s
  floor           CHOLMOD analyze + factorize + solve of K_ff                   floor_cpu_s      / floor_s
and a reference slope N^1.35 (the floor's growth measured in 2D). Rows without FreeFEM (it was skipped)
leave its curves out. Lines starting with '#' are ignored.

Needs only /usr/bin/python3 with matplotlib (Debian: python3-matplotlib); no numpy.
"""

import argparse
import csv
import math
import sys


def read_rows(path):
    with open(path, newline="") as f:
        lines = [line for line in f if line.strip() and not line.startswith("#")]
    return list(csv.DictReader(lines))


def number(row, key):
    try:
        v = float(row.get(key, "nan"))
    except ValueError:
        return math.nan
    return v


def fmt(v, spec):
    return "-" if not math.isfinite(v) else spec % v


def markdown_tables(rows):
    """The docs tables: times and ratios (CPU, with wall beside), then accuracy of both tools."""
    n = lambda r, k: number(r, k)
    out = ["| h | DOFs | constraints sym / FF | geom. it. / IPOPT it. sym | IPOPT it. FF | floor CPU [s] "
           "| symcontact CPU [s] (wall) | FreeFEM IPOPT CPU [s] | FreeFEM process CPU [s] (wall) "
           "| **sym / FF** | sym / floor | FF / floor |",
           "|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|"]
    for r in rows:
        out.append("| %s | %s | %s / %s | %s / %s | %s | %s | %s (%s) | %s | %s (%s) | **%s** | %s | %s |" % (
            "%g" % n(r, "h"), "{:,}".format(int(n(r, "dofs"))),
            fmt(n(r, "sym_constraints"), "%d"), fmt(n(r, "ff_candidates"), "%d"),
            fmt(n(r, "sym_geometry_iterations"), "%d"), fmt(n(r, "sym_ipopt_iterations"), "%d"),
            fmt(n(r, "ff_ipopt_iterations"), "%d"), fmt(n(r, "floor_cpu_s"), "%.3f"),
            fmt(n(r, "sym_solve_cpu_s"), "%.2f"), fmt(n(r, "sym_solve_wall_s"), "%.2f"),
            fmt(n(r, "ff_ipopt_cpu_s"), "%.2f"), fmt(n(r, "ff_process_cpu_s"), "%.2f"),
            fmt(n(r, "ff_wall_s"), "%.2f"), fmt(n(r, "sym_over_ff"), "%.2f"),
            fmt(n(r, "sym_over_floor"), "%.1f"), fmt(n(r, "ff_over_floor"), "%.1f")))
    out.append("")
    out.append("| h | DOFs | sym a_last [a_next] | sym err(a_fit) | sym err(p_max) | sym \\|2Σf/P−1\\| "
               "| FF a_last [a_next] | FF err(a_fit) | FF err(p_max) | FF \\|2Σf/P−1\\| |")
    out.append("|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    for r in rows:
        acc = []
        for t in ("sym", "ff"):
            acc += ["%s [%s]" % (fmt(n(r, t + "_a_last"), "%.5f"), fmt(n(r, t + "_a_next"), "%.5f")),
                    fmt(n(r, t + "_a_fit_error_pct"), "%+.2f %%"),
                    fmt(n(r, t + "_p_max_error_pct"), "%+.2f %%"), fmt(n(r, t + "_force_error"), "%.0e")]
        out.append("| %g | %s | %s |" % (n(r, "h"), "{:,}".format(int(n(r, "dofs"))), " | ".join(acc)))
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("csv")
    ap.add_argument("png")
    ap.add_argument("--title", default="Hertz 2D quarter model (peers' mesh), one BLAS thread")
    ap.add_argument("--wall", action="store_true", help="plot wall-clock times instead of CPU times")
    ap.add_argument("--dpi", type=int, default=120)
    ap.add_argument("--markdown", action="store_true", help="also print the docs tables (Markdown)")
    args = ap.parse_args()

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = sorted(read_rows(args.csv), key=lambda r: number(r, "dofs"))
    if not rows:
        sys.exit("plot_freefem_peer.py: no rows in " + args.csv)
    dofs = [number(r, "dofs") for r in rows]
    series = [  # label, CSV column, style, colour, annotate the points with their times
        ("symcontact (solve_contact)", "sym_solve_wall_s" if args.wall else "sym_solve_cpu_s", "o-", "C0", True),
        ("FreeFEM + ff-Ipopt (IPOPT call)", "ff_ipopt_cpu_s", "s-", "C3", True),
        ("FreeFEM process (whole run)", "ff_wall_s" if args.wall else "ff_process_cpu_s", "s:", "C1", False),
        ("CHOLMOD floor (factor + solve)", "floor_s" if args.wall else "floor_cpu_s", "^-", "k", True),
    ]
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    for label, key, style, color, annotate in series:
        pts = [(n, number(r, key)) for n, r in zip(dofs, rows)]
        pts = [(n, t) for n, t in pts if math.isfinite(t) and t > 0]
        if pts:
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], style, color=color, label=label)
            for n, t in pts if annotate else []:
                ax.annotate("%.3g" % t, (n, t), textcoords="offset points", xytext=(4, -10), fontsize=7,
                            color=color)
    floor = [(n, number(r, "floor_s" if args.wall else "floor_cpu_s")) for n, r in zip(dofs, rows)]
    floor = [(n, t) for n, t in floor if math.isfinite(t) and t > 0]
    if len(floor) >= 2:
        n0, t0 = floor[0]
        n1 = floor[-1][0]
        ax.loglog([n0, n1], [t0 / 2, t0 / 2 * (n1 / n0) ** 1.35], "--", color="0.6", lw=0.8,
                  label="slope N^1.35")
    ax.set_xlabel("DOFs")
    ax.set_ylabel("wall-clock time [s]" if args.wall else "CPU time [s]")
    ax.set_title(args.title, fontsize=10)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.png, dpi=args.dpi)
    print("wrote " + args.png)
    if args.markdown:
        print(markdown_tables(rows))


if __name__ == "__main__":
    main()
