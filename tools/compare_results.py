#!/usr/bin/env python3
"""Compares two folders of symcontact results, case by case (tools/run_examples.sh writes them).

For every case folder of BEFORE: the same exit code, and in summary.json and every CSV file the same
strings, the same integers and numbers equal to a relative tolerance (default 1e-10):

    |a - b| <= tol * scale,

where scale is the largest magnitude in the same numeric array (a force vector, a change history) or
CSV column, max(|a|, |b|) for a lone number, and 1 for the dimensionless check figures (residuals and
ratios already relative to the problem's scales; see CHECK_FIGURES). Timings are not compared.
Exit 0 when everything agrees, 1 otherwise (each difference printed), 2 on bad arguments.
"""
import argparse
import csv
import json
import math
import os
import sys

# Timings and paths that differ between two runs of the same code.
SKIPPED_KEYS = {"timings", "wall_time", "problem", "output_folder"}
# Figures already relative to the problem's own scales; compared with scale 1.
CHECK_FIGURES = {"equilibrium_residual", "max_penetration_ratio", "coulomb_change_history",
                 "last_solve_geometry_change_history", "friction_law_excess"}


def is_number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


class Comparison:
    def __init__(self, tol):
        self.tol = tol
        self.differences = []
        self.values = 0

    def number(self, where, a, b, scale):
        self.values += 1
        if isinstance(a, int) and isinstance(b, int):
            if a != b:
                self.differences.append(f"{where}: {a} != {b}")
            return
        a, b = float(a), float(b)
        if math.isnan(a) and math.isnan(b):
            return
        if a == b:
            return
        if not (abs(a - b) <= self.tol * scale):
            rel = abs(a - b) / scale if scale > 0 else math.inf
            self.differences.append(f"{where}: {a!r} != {b!r} (difference {rel:.3g} of {scale:.3g})")

    def json_value(self, where, a, b, unit_scale=False):
        if isinstance(a, dict) and isinstance(b, dict):
            if set(a) - SKIPPED_KEYS != set(b) - SKIPPED_KEYS:
                self.differences.append(f"{where}: keys {sorted(set(a) ^ set(b))} in one only")
            for k in a:
                if k in SKIPPED_KEYS or k not in b:
                    continue
                self.json_value(f"{where}.{k}", a[k], b[k], k in CHECK_FIGURES)
        elif isinstance(a, list) and isinstance(b, list):
            if len(a) != len(b):
                self.differences.append(f"{where}: {len(a)} entries != {len(b)}")
                return
            numbers = [abs(float(v)) for v in a + b if is_number(v) and not math.isnan(float(v))]
            scale = 1.0 if unit_scale else max(numbers, default=0.0)
            for i, (x, y) in enumerate(zip(a, b)):
                if is_number(x) and is_number(y):
                    self.number(f"{where}[{i}]", x, y, scale)
                else:
                    self.json_value(f"{where}[{i}]", x, y, unit_scale)
        elif is_number(a) and is_number(b):
            self.number(where, a, b, 1.0 if unit_scale else max(abs(float(a)), abs(float(b))))
        elif a != b:
            self.differences.append(f"{where}: {a!r} != {b!r}")

    def csv_file(self, where, path_a, path_b):
        with open(path_a, newline="") as fa, open(path_b, newline="") as fb:
            ra, rb = list(csv.reader(fa)), list(csv.reader(fb))
        if len(ra) != len(rb) or (ra and ra[0] != rb[0]):
            self.differences.append(f"{where}: {len(ra)} rows != {len(rb)}, or other columns")
            return
        if not ra:
            return
        header, rows_a, rows_b = ra[0], ra[1:], rb[1:]
        for c, name in enumerate(header):
            col_a = [r[c] if c < len(r) else "" for r in rows_a]
            col_b = [r[c] if c < len(r) else "" for r in rows_b]
            num_a, num_b = [to_float(v) for v in col_a], [to_float(v) for v in col_b]
            finite = [abs(v) for v in num_a + num_b if v is not None and not math.isnan(v)]
            scale = max(finite, default=0.0)
            for i, (x, y, sx, sy) in enumerate(zip(num_a, num_b, col_a, col_b)):
                if x is not None and y is not None:
                    self.number(f"{where} row {i + 2} {name}", x, y, scale)
                elif sx != sy:
                    self.differences.append(f"{where} row {i + 2} {name}: {sx!r} != {sy!r}")


def to_float(text):
    try:
        return float(text)
    except ValueError:
        return None


def read_text(path):
    with open(path) as f:
        return f.read().strip()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--tol", type=float, default=1e-10)
    parser.add_argument("--show", type=int, default=20, help="differences printed per case")
    args = parser.parse_args()
    if not os.path.isdir(args.before) or not os.path.isdir(args.after):
        print("compare_results: both arguments must be folders", file=sys.stderr)
        return 2
    cases = sorted(d for d in os.listdir(args.before) if os.path.isdir(os.path.join(args.before, d)))
    if not cases:
        print(f"compare_results: no case folders in {args.before}", file=sys.stderr)
        return 2
    failed = 0
    for case in cases:
        cmp = Comparison(args.tol)
        a_dir, b_dir = os.path.join(args.before, case), os.path.join(args.after, case)
        exit_a, exit_b = os.path.join(args.before, case + ".exit"), os.path.join(args.after, case + ".exit")
        if not os.path.isdir(b_dir):
            cmp.differences.append("missing in " + args.after)
        else:
            if os.path.exists(exit_a) and os.path.exists(exit_b) and read_text(exit_a) != read_text(exit_b):
                cmp.differences.append(f"exit code {read_text(exit_a)} != {read_text(exit_b)}")
            files = sorted(f for f in os.listdir(a_dir) if f.endswith((".json", ".csv")))
            for f in files:
                pa, pb = os.path.join(a_dir, f), os.path.join(b_dir, f)
                if not os.path.exists(pb):
                    cmp.differences.append(f"{f}: missing")
                elif f.endswith(".json"):
                    with open(pa) as fa, open(pb) as fb:
                        cmp.json_value(f, json.load(fa), json.load(fb))
                else:
                    cmp.csv_file(f, pa, pb)
        status = "same" if not cmp.differences else f"{len(cmp.differences)} difference(s)"
        print(f"{case}: {cmp.values} values, {status}")
        for d in cmp.differences[: args.show]:
            print("  " + d)
        failed += bool(cmp.differences)
    print(f"{len(cases) - failed} of {len(cases)} cases agree to {args.tol:g}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
