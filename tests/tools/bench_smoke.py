#!/usr/bin/env python3
"""The benchmark programs run end to end on small sizes and write what docs/performance.md reads from them.

symcontact-bench on the cases whose paths the tests elsewhere do not reach through it: a 2D pad dragged on a
rigid plane (the dense interior point; its top's |R_t/R_n| equals mu = 0.3: the whole face slides), the 3D
clamped plates (a symmetric pair with friction: IPOPT, here on the condensed problem) and a problem file
(`--case problem`: each load step solved as `symcontact run` solves it). Each must exit 0 and write one CSV
row per size with every cell filled, a positive floor, a finite ratio to it, and iteration counts > 0. Then,
where it was built, symcontact-bench-distributed on a sliding block (Coulomb mu = 0.2: R_x/R_n = 0.2 to the
Poisson effect's 0.1 %).

Usage: bench_smoke.py SYMCONTACT_BENCH EXAMPLES WORK [SYMCONTACT_BENCH_DISTRIBUTED]
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

FAILED = []


def check(condition, message):
    print(("ok    " if condition else "FAIL  ") + message)
    if not condition:
        FAILED.append(message)


def bench_rows(command, csv_path):
    r = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    label = " ".join(os.path.basename(c) for c in command[:3])
    check(r.returncode == 0, f"{label}: exit {r.returncode}" + ("" if r.returncode == 0 else "\n" + r.stdout[-3000:]))
    if r.returncode != 0 or not os.path.exists(csv_path):
        return []
    with open(csv_path) as f:
        return list(csv.DictReader(f))


def check_rows(label, rows, sizes):
    check(len(rows) == sizes, f"{label}: {len(rows)} CSV rows, {sizes} expected")
    for row in rows:
        blank = [k for k, v in row.items() if v is None or v.strip() == ""]
        check(not blank, f"{label}: no blank cell (blank: {blank})")
        floor, ratio = float(row["floor_s"]), float(row["ratio"])
        check(floor > 0.0 and math.isfinite(ratio) and ratio > 0.0, f"{label}: floor {floor:g} s, ratio {ratio:g}")
        iterations = int(row["ipopt_iterations"]) + int(row["newton_iterations"])
        check(int(row["contact_solves"]) > 0 and iterations > 0,
              f"{label}: {row['contact_solves']} solves, {iterations} optimizer iterations")


def main():
    bench, examples, work = sys.argv[1:4]
    distributed = sys.argv[4] if len(sys.argv) > 4 else ""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)

    path = os.path.join(work, "pad.csv")
    rows = bench_rows([bench, "--case", "pad-flat-2d", "--h", "0.04", "0.02", "--csv", path], path)
    check_rows("pad-flat-2d", rows, 2)
    for row in rows:
        ratio = float(row["reaction_ratio"])
        check(abs(ratio - 0.3) <= 1e-4, f"pad-flat-2d: |R_t/R_n| = {ratio}, mu = 0.3")

    path = os.path.join(work, "plates.csv")
    rows = bench_rows([bench, "--case", "clamped-plates", "--h", "0.12", "--csv", path], path)
    check_rows("clamped-plates", rows, 1)
    for row in rows:
        ratio = float(row["reaction_ratio"])
        check(0.0 < ratio < 0.3, f"clamped-plates: |R_t/R_n| = {ratio:g}, below mu = 0.3 (the plates stick)")

    path = os.path.join(work, "problem.csv")
    block = os.path.join(examples, "friction_block", "block.toml")
    rows = bench_rows([bench, "--case", "problem", "--problem", block, "--csv", path], path)
    check_rows("problem friction_block", rows, 1)
    for row in rows:
        check(int(row["steps"]) == 11, f"problem friction_block: {row['steps']} load steps, 11 in the file")

    if distributed:
        r = subprocess.run([distributed, "--problem", "sliding", "--dim", "2", "--divisions", "12"],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        check(r.returncode == 0, f"symcontact-bench-distributed --problem sliding: exit {r.returncode}")
        rows = [line.split() for line in r.stdout.splitlines() if re.match(r"^\s*12\s", line)]
        check(len(rows) == 1, "symcontact-bench-distributed: one row for 12 divisions")
        if rows:
            ratio = float(rows[0][-2])  # the row ends with R_x/R_n and the peak RSS
            check(abs(ratio - 0.2) <= 2e-4, f"symcontact-bench-distributed: R_x/R_n = {ratio}, mu = 0.2")
    sys.exit(1 if FAILED else 0)


if __name__ == "__main__":
    main()
