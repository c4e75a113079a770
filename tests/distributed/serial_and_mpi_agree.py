#!/usr/bin/env python3
"""`mpirun -np 2 symcontact run CASE` against the serial `symcontact run CASE` on validation examples, and
`symcontact run` of the same case with [contact_solver] linear_solver = "iterative" (one process), the two
ranks run again (the same files to the last bit, summary.json's timings aside), and the two ranks under OpenBLAS's baseline kernels (OPENBLAS_CORETYPE=Prescott, which every x86-64 CPU runs).

Both runs must end "ok" and write the same files (on two ranks a .pvtu and one piece per rank in place of each
.vtu, the pieces put back together to compare); every number of their summary.json, contact CSV and VTU
files must agree to REL relative to its quantity's scale: the largest magnitude of the same quantity in the
serial file (all components of a VTU array, of the reactions, of the force columns of a CSV together), so
that a component that is zero up to round-off in one run (a force along a symmetry plane) is compared at
the force's scale, not its own. Timings, iteration counts and the solver's name are not compared: the two
paths solve the same problem by different methods.

Then the same physical problem on two ranks in m–N–Pa and in other units (SYMCONTACT_RESCALE rewrites it),
compared in the same way once each quantity is converted.

Usage: serial_and_mpi_agree.py SYMCONTACT MPIEXEC EXAMPLES WORK SYMCONTACT_RESCALE
"""
import csv
import filecmp
import json
import math
import os
import re
import shutil
import subprocess
import sys

REL = 1e-8
# On a curved symmetric pair the answer is pinned only to what the serial path's own optimisers agree to: on V6
# the dense interior point and IPOPT on the dual part by 1.1e-6 of the forces' scale (7.6e-8 of the pressures',
# 2.6e-8 of the displacements') at the default tolerances, and by 1.5e-6 still with geometry_tolerance = 1e-10
# and IPOPT's tol = 1e-12; the two ranks by 2.1e-6 from the serial run.
REL_SYMMETRIC = 1e-5
# With Coulomb friction on a symmetric pair the share of the normal force between its families sets each friction
# point's threshold, and so the displacements too (CASES).
REL_FRICTION_SYMMETRIC = 1e-4

# (example, extra [contact_solver] keys, --mesh-size[, tolerance, REL where none]): VALIDATION.md's V1 and V2,
# elastic bodies on rigid planes, V1 in three load steps (the steps after the first reuse the first one's
# stiffness), and V4, the block pressed and dragged with Coulomb friction in 11 steps.
# Both paths stop the Coulomb fixed point at coulomb_tolerance from one fixed point, each on its own side: at the
# default 1e-6 they part by about 1e-7 of the forces' scale in the steps where the block starts to slip, so V4 runs
# with 1e-10; the same block with Tresca friction (TRESCA: no Coulomb loop); and in 3D, a pad pressed and dragged on a
# plane with Coulomb friction (pad_3d/pad.toml, a path of its own: os.path.join keeps it whole), and on a rigid sphere
# (pad_3d/pad_ball.toml). Between elastic bodies: V6's rings and V3's patch
# test (two blocks of quadrilaterals) with their pairs in one-pass mode, and the self-contact of a block with a
# crack, frictionless; V5's inclined interface in one-pass mode with Coulomb friction (each slave node slides
# against the other body), with coulomb_tolerance = 1e-9 (at 1e-8 the two loops stop up to 1.4e-8 of the
# forces apart, each on its own side); at 1e-10 the Coulomb loop reaches the inner solves' noise
# and asks them for 1e-12–1e-14, where conjugate gradients can break down in round-off. Friction on
# order-2 elements (each point's slip mixes the nodes of its facet: FrictionTerm's modified basis on 6-node
# triangles): V4's block and the 3D pad at order 2.
THREE_STEPS = "[steps]\nload_factors = [0.3, 0.6, 1.0]\n"
# V4's block with Tresca friction (τ = 0.002, below μ p = 0.003: it slides earlier) in place of Coulomb.
TRESCA = ('friction = "coulomb"\nmu = 0.3\n', 'friction = "tresca"\ntau = 0.002\n')  # (replaced, by)
# V5's Coulomb friction as inclined.toml writes it, for the case without friction.
OR_RUBBER = 'model = "mooney_rivlin"\nc1 = 0.4\nc2 = 0.1\nkappa = 50.0\n'  # the O-ring's rubber
V5_COULOMB = ('friction = "coulomb"\nmu = 0.2\nalpha = 1e-6                # small against the slip of a push step '
              '(about 1.5e-4)\n')
CASES = [
    ("hertz_2d/cylinder_on_plane.toml", "", None),
    ("hertz_3d/sphere_on_plane.toml", "", None),
    ("hertz_2d/cylinder_on_plane.toml", THREE_STEPS, None),
    ("friction_block/block.toml", "coulomb_tolerance = 1e-10\n", None),
    ("friction_block/block.toml", TRESCA, None),
    (os.path.join(os.path.dirname(os.path.abspath(__file__)), "pad_3d", "pad.toml"), "", None),
    (os.path.join(os.path.dirname(os.path.abspath(__file__)), "pad_3d", "pad_ball.toml"), "", None),
    ("rings_2d/rings.toml", ('b = "outer.outer_inside"\n', 'b = "outer.outer_inside"\nmode = "one-pass"\n'), None),
    ("quad_blocks_2d/quad_blocks.toml", ('b = "upper.upper_bottom"\n', 'b = "upper.upper_bottom"\nmode = "one-pass"\n'),
     None),
    ("cracked_block_2d/cracked_block.toml", "", None),
    ("inclined_2d/inclined.toml", [('mode = "symmetric"\n', 'mode = "one-pass"\n'),
                                   ("coulomb_tolerance = 1e-6\n", "coulomb_tolerance = 1e-9\n")], None),
    ("inclined_3d/inclined.toml", [('mode = "symmetric"\n', 'mode = "one-pass"\n'),
                                   ("coulomb_tolerance = 1e-6\n", "coulomb_tolerance = 1e-9\n")], None),
    ("friction_block/block.toml", ["coulomb_tolerance = 1e-10\n",
                                   ('model = "plane_strain"\n', 'model = "plane_strain"\norder = 2\n')], None),
    (os.path.join(os.path.dirname(os.path.abspath(__file__)), "pad_3d", "pad.toml"),
     [("mesh_size = 0.2\n", "mesh_size = 0.2\norder = 2\n")], None),
    # Symmetric pairs without friction, as the examples are written: V3's flat patch test, whose two families
    # close together, to REL; V6's curved rings, where one row of each nearly dependent pair is held open by the
    # meshes' mismatch, and V5's inclined interface without friction (flat, unmatched meshes: the active set
    # cycles, the method of multipliers on the inequalities polishes it), to REL_SYMMETRIC.
    ("quad_blocks_2d/quad_blocks.toml", "", None),
    ("rings_2d/rings.toml", "", None, REL_SYMMETRIC),
    ("inclined_2d/inclined.toml", (V5_COULOMB, 'friction = "none"\n'), None, REL_SYMMETRIC),
    # Symmetric pairs with Coulomb friction, as V5 and its 3D form are written. Each friction point's threshold is
    # mu times its own row's force, and how the nearly dependent families share the normal force is what the
    # optimisers leave open: the nodal forces of the two paths part by up to 2.7e-5 of their scale in 2D (one and
    # two ranks of the distributed path agree to 1e-6, the total force's direction to 1e-8).
    ("inclined_2d/inclined.toml", "", None, REL_FRICTION_SYMMETRIC),
    ("inclined_3d/inclined.toml", "", None, REL_SYMMETRIC),
    # V5 at coulomb_tolerance = 1e-8: on two ranks its Coulomb loop stagnates at 1.1e-8–1.3e-8 in the first two
    # steps and the solves tightened past that break down; the loop accepts the iterate they started from at the
    # noise floor (solvers/lagged_fixed_point.hpp), "ok" with a warning.
    ("inclined_2d/inclined.toml", ("coulomb_tolerance = 1e-6\n", "coulomb_tolerance = 1e-8\n"), None,
     REL_FRICTION_SYMMETRIC),
    # V8's cylinders (cattaneo_2d/cattaneo.toml): every contact node sticks as they are pressed together, with
    # alpha = 8e-6 against steps of 1e-2 (the primal-dual linearisation of the friction law in
    # contact_interior_point.hpp). Within 5e-5 of the forces' scale, one and two ranks to 1e-6.
    (os.path.join(os.path.dirname(os.path.abspath(__file__)), "cattaneo_2d", "cattaneo.toml"), "", None,
     REL_FRICTION_SYMMETRIC),
    # A Neo-Hookean ring crushed until its bore touches itself (a self-contact: two nearly dependent families of
    # rows) in 40 steps: each geometry iteration of the distributed path a Newton step, its Hessian shifted where
    # it is not positive definite (step 40). At the default tolerances the serial path's own answer moves by 1.5e-5
    # of the forces' scale when its tolerances are those below; there the two paths part by 2e-8 of the
    # displacements' scale and 1.8e-6 of the pressures' (the split between the families).
    ("crushed_ring_2d/ring.toml", ["geometry_tolerance = 1e-10\n", "[ipopt]\ntol = 1e-12\n"], None, REL_SYMMETRIC),
    # V2's sphere made Neo-Hookean (3D, a rigid plane, a pressure load): a Newton step per geometry iteration.
    ("hertz_3d/sphere_on_plane.toml", ("[body.material]\n", '[body.material]\nmodel = "neo_hookean"\n'), None),
    # A Neo-Hookean block turned rigidly by its edges, without contact: under mpirun as serially (no contact
    # step: the serial equilibrium solver on every rank).
    ("rotation_2d/rotation.toml", "", None),
    # The O-ring with a linear-elastic ring (E = 3, nu = 0.49), pressed by a steel lid that an imposed displacement
    # moves: the interior point's own force scale is 3e5 times the answer's forces (distributed_step.cpp,
    # answer_force_scale). The lid is a symmetric pair with Coulomb friction: REL_FRICTION_SYMMETRIC (4.3e-5).
    # At the default tolerances an edge node of the groove's contact closes in one path and not in the other from
    # step 6 (2e-4 apart); at these both loops end well inside their tolerances.
    ("oring_axisymmetric/oring.toml", [(OR_RUBBER, "E = 3.0\nnu = 0.49\n"), "coulomb_tolerance = 1e-9\n",
                                       "geometry_tolerance = 1e-10\n", "[ipopt]\ntol = 1e-12\n"], None,
     REL_FRICTION_SYMMETRIC),
]
# Cases whose Coulomb fixed point must settle on two ranks without a step accepted at the noise floor: the O-ring
# above took 21 Coulomb iterations in its first step and was accepted there while its interior point measured
# its tests against the lid's force.
SETTLES = ["oring_axisymmetric/oring.toml"]
# What neither path solves: a failed solve (exit 3) saying why, the same on both (none at present).
FAILED_SOLVES = []
# What the serial path solves and the distributed one does not close yet: a failed solve (exit 3) saying what to
# try. V6's rings at geometry_tolerance = 1e-10: the geometry fixed point cycles 3.2e-8 above it in the second
# step, told after ten iterations without a new low (docs/distributed.md). V4 with the block's left side held
# vertically: the bottom-left node's normal is along a fixed DOF; the distributed path's followed thresholds read
# no force there where its loop reads the multipliers' (the serial path reads it in both:
# V4FrictionLaw.ThresholdsFollowTheForceOnAFixedDofAsTheLoopReadsIt), and its Coulomb fixed point stagnates.
# (example, extra, what extra does, what the message must say)
DISTRIBUTED_FAILURES = [("rings_2d/rings.toml", "geometry_tolerance = 1e-10\n", "at geometry_tolerance = 1e-10",
                         "the geometry fixed point stagnated: no new low of its relative change in 10 iterations"),
                        ("friction_block/block.toml", '[[body.dirichlet]]\nboundary = "left"\nuy = 0.0\n',
                         "with the left side held vertically", "the Coulomb fixed point stagnated")]
# What the distributed path does not solve yet: an input error (exit 2) naming the key, no output folder (a
# hyperelastic body with friction).
UNSUPPORTED = [("oring_axisymmetric/oring.toml", "body[0].material.model")]
ITERATIVE = 'linear_solver = "iterative"\n'
# (example, extra as in CASES, dimension, length, force, units): solved on two ranks in m–N–Pa and in the other
# units, on the same mesh; every number must agree to REL of its quantity's scale once converted. V4 and V5's
# inclined interface in one-pass mode (friction between the bodies) with lengths × 1e3 and forces × 1e6
# (Coulomb, the tolerances of CASES).
UNITS = [("hertz_2d/cylinder_on_plane.toml", "", 2, 1e3, 1.0, "mm–N–MPa"),
         ("hertz_3d/sphere_on_plane.toml", "", 3, 1e3, 1e-3, "mm–kN–GPa"),
         ("friction_block/block.toml", "coulomb_tolerance = 1e-10\n", 2, 1e3, 1e6, "lengths × 1e3, forces × 1e6"),
         ("inclined_2d/inclined.toml", [('mode = "symmetric"\n', 'mode = "one-pass"\n'),
                                        ("coulomb_tolerance = 1e-6\n", "coulomb_tolerance = 1e-9\n")],
          2, 1e3, 1e6, "lengths × 1e3, forces × 1e6")]


def compare(serial, other, units=None, rel=REL):
    """The Comparison of two output folders to `rel` (`units`: other's units against serial's). A .pvtu of a run on
    several ranks stands for the .vtu of the same name, its pieces put together (pvtu_arrays)."""
    files_a, files_b = logical_files(serial), logical_files(other)
    c = Comparison(units, rel)
    for f in files_a:  # the run's scale of each quantity, over every step's files
        path = os.path.join(serial, f)
        if f.endswith(".vtu"):
            for name, values in vtu_arrays(path):
                if name != "contact_gap":  # gaps take the displacements' scale, not theirs (up to the search distance)
                    c.widen(VTU_SCALES.get(name), values)
        elif f.endswith(".csv"):
            rows = list(csv.DictReader(open(path)))
            for group, pattern in CSV_GROUPS:
                if group != "gap":
                    c.widen(CSV_SCALES.get(group), [float(r[k]) for r in rows for k in r if pattern.match(k)])
    if files_a != files_b:
        c.failures.append(f"files {files_a} != {files_b}")
    for f in files_a:
        if f not in files_b:
            continue
        a, b = os.path.join(serial, f), os.path.join(other, f)
        if f.endswith(".vtu"):
            c.vtu(f, a, b)
        elif f.endswith(".csv"):
            c.csv(f, a, b)
        elif f == "summary.json":
            c.summary(f, a, b)
    return c


PIECE = re.compile(r"_p\d+\.vtu$")


def logical_files(folder):
    """The files of an output folder, a .pvtu named as the .vtu it stands for, without its pieces."""
    names = [f for f in os.listdir(folder) if not PIECE.search(f)]
    return sorted(f.removesuffix(".pvtu") + ".vtu" if f.endswith(".pvtu") else f for f in names)


def noise_floor_steps(folder):
    """The steps of a run's summary.json whose Coulomb fixed point was accepted at the noise floor, and whether
    one of them lacks its warning (exit "ok" only with the warning that says so)."""
    steps = json.load(open(os.path.join(folder, "summary.json")))["steps"]
    accepted = [s for s in steps if s.get("coulomb_accepted_at_noise_floor", 0) > 0]
    unwarned = [s["step"] for s in accepted if not any("noise floor" in w for w in s["warnings"])]
    if unwarned:
        print(f"{folder}: steps accepted at the noise floor without a warning: {unwarned}")
    return len(accepted), bool(unwarned)


def check_parallel_files(folder):
    """Whether the output of a run on two ranks fails to be a .pvtu per body and step, with two pieces that exist,
    named by the collection in place of any .vtu."""
    names = os.listdir(folder)
    pvtu = [f for f in names if f.endswith(".pvtu")]
    whole = [f for f in names if f.endswith(".vtu") and not PIECE.search(f)]
    pieces = [p for f in pvtu for p in re.findall(r'<Piece Source="([^"]+)"/>', open(os.path.join(folder, f)).read())]
    listed = re.findall(r'file="([^"]+)"', open(os.path.join(folder, "results.pvd")).read())
    bad = (not pvtu or whole or len(pieces) != 2 * len(pvtu) or not all(p in names for p in pieces)
           or sorted(listed) != sorted(pvtu))
    if bad:
        print(f"{folder}: .pvtu {pvtu}, whole .vtu {whole}, pieces {pieces}, in results.pvd {listed}")
    return bool(bad)


def plot_tool_differs(serial, mpi):
    """Whether tools/plot_vtu.py reads a .pvtu of `mpi` otherwise than the serial .vtu it stands for: other points or
    cells, or data beyond REL of each array's largest magnitude."""
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
    import numpy as np
    import plot_vtu
    differ = False
    for f in sorted(f for f in os.listdir(mpi) if f.endswith(".pvtu")):
        a, b = plot_vtu.Body(os.path.join(serial, f.removesuffix(".pvtu") + ".vtu")), plot_vtu.Body(os.path.join(mpi, f))
        same_cells = len(a.cells) == len(b.cells) and all(
            np.array_equal(ia, ib) and np.array_equal(va, vb) for (ia, va), (ib, vb) in zip(a.cells, b.cells))
        data = [(d[k], e.get(k)) for d, e in ((a.point_data, b.point_data), (a.cell_data, b.cell_data)) for k in d]
        same_data = all(v is not None and np.abs(u - v).max(initial=0) <= REL * max(np.abs(u).max(initial=0), 1e-300)
                        for u, v in data)
        print(f"tools/plot_vtu.py on {f}: points {np.array_equal(a.points, b.points)}, cells {same_cells}, "
              f"data {same_data}")
        differ = differ or not (np.array_equal(a.points, b.points) and same_cells and same_data)
    return differ


def vtu_sections(path):
    """{section: [(name, components, values)]} of the Float64 arrays of a VTU file's PointData, CellData, Points."""
    text = open(path).read()
    out = {}
    for section in ("PointData", "CellData", "Points"):
        body = re.search(f"<{section}>(.*?)</{section}>", text, re.S)
        out[section] = [(n, int(k), [float(v) for v in t.split()]) for n, k, t in re.findall(
            r'<DataArray type="Float64" Name="([^"]+)" NumberOfComponents="(\d+)"[^>]*>([^<]*)</DataArray>',
            body.group(1) if body else "")]
    return out


def pvtu_arrays(path):
    """(name, values) of the VTU a .pvtu stands for, in a serial VTU's order: its pieces' point data put back in the
    body's node order by their "node" array, their cell data in the body's cell order by their "cell" array (both
    left out)."""
    folder = os.path.dirname(path)
    pieces = [vtu_sections(os.path.join(folder, f)) for f in re.findall(r'<Piece Source="([^"]+)"/>', open(path).read())]
    nodes = [[int(v) for n, _, vals in p["PointData"] if n == "node" for v in vals] for p in pieces]
    num_nodes = 1 + max(max(n, default=-1) for n in nodes)
    cells = [int(v) for p in pieces for n, _, vals in p["CellData"] if n == "cell" for v in vals]
    arrays = []
    for section in ("PointData", "CellData", "Points"):
        for k, (name, comps, _) in enumerate(pieces[0][section]):
            if section == "CellData":
                if name == "cell":
                    continue
                values = [v for p in pieces for v in p[section][k][2]]
                if cells:  # back in the body's order
                    values = [values[j * comps + c] for j in sorted(range(len(cells)), key=cells.__getitem__)
                              for c in range(comps)]
                arrays.append((name, values))
                continue
            if name == "node":
                continue
            values = [None] * (num_nodes * comps)
            for p, ids in zip(pieces, nodes):
                local = p[section][k][2]
                for j, node in enumerate(ids):
                    values[node * comps:(node + 1) * comps] = local[j * comps:(j + 1) * comps]
            arrays.append((name, values))
    return arrays

# CSV columns by quantity (the scale of each column is its group's largest magnitude).
CSV_GROUPS = [
    ("position", re.compile(r"^(x|y|z|x_ref|y_ref|z_ref)$")),
    ("gap", re.compile(r"^gap$")),
    ("pressure", re.compile(r"^(pressure|current_pressure|t[xyz]|t_tangential)$")),
    ("force", re.compile(r"^(f[xyz]|fn_[xyz]|ft_[xyz])$")),
    ("displacement", re.compile(r"^(u[xyz]|slip_[xyz]|accumulated_slip|slip_tangential)$")),
]
CSV_KINDS = {"position": "length", "gap": "length", "pressure": "stress", "force": "force", "displacement": "length"}
SKIPPED_SUMMARY_KEYS = {"timings", "wall_time", "ipopt_status", "ipopt_iterations", "geometry_iterations",
                        "last_solve_ipopt_iterations_per_geometry_iteration", "last_solve_geometry_change_history",
                        "num_constraints", "problem", "output_folder", "equilibrium_residual",
                        "max_penetration_ratio"}


def label_of(extra):
    """What a case's `extra` changes, for its output folders and the log."""
    if extra == THREE_STEPS:
        return " in three steps"
    if extra == TRESCA:
        return " with Tresca friction"
    replaced = [item[1] for item in (extra if isinstance(extra, list) else [extra]) if isinstance(item, tuple)]
    if any("one-pass" in new for new in replaced):
        return " in one-pass mode"
    if any("order = 2" in new for new in replaced):
        return " at order 2"
    if any('friction = "none"' in new for new in replaced):
        return " without friction"
    if any("neo_hookean" in new for new in replaced):
        return " Neo-Hookean"
    if any("E = 3.0" in new for new in replaced):
        return " with a linear-elastic ring"
    tolerance = [new.strip().replace(" = ", " ") for new in replaced if new.startswith("coulomb_tolerance")]
    if tolerance:
        return " at " + tolerance[0]
    return ""


def with_extra(text, name, extra):
    """`text` with `extra` added to its [contact_solver] table (a table of its own when it starts with "["; a pair
    (text, replacement): that text replaced; a list: each of its items in turn)."""
    if isinstance(extra, list):
        for item in extra:
            text = with_extra(text, name, item)
    elif isinstance(extra, tuple):
        assert extra[0] in text, f"{name} has no {extra[0]!r}"
        text = text.replace(*extra)
    elif extra.startswith("["):  # a table of its own
        text += "\n" + extra
    elif "[contact_solver]" in text:
        text = text.replace("[contact_solver]\n", "[contact_solver]\n" + extra, 1)
    else:
        text += "\n[contact_solver]\n" + extra
    return text


def case_file(examples, work, name, extra):
    """The example, or a copy of its folder in `work` with `extra` applied (with_extra)."""
    path = os.path.join(examples, name)
    if not extra:
        return path
    folder = os.path.join(work, "case_" + os.path.dirname(name))
    shutil.copytree(os.path.dirname(path), folder, dirs_exist_ok=True)
    copy = os.path.join(folder, os.path.basename(name))
    text = with_extra(open(copy).read(), name, extra)
    with open(copy, "w") as f:
        f.write(text)
    return copy


def run(command):
    r = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        print(r.stdout)
        raise SystemExit(f"FAIL: {' '.join(command)} exited {r.returncode}")


# The unit of each VTU array, as the quantity kinds of UnitChange.
VTU_KINDS = {"Points": "length", "displacement": "length", "accumulated_slip": "length", "slip_increment": "length",
             "contact_gap": "length", "contact_force": "force", "contact_pressure": "stress",
             "contact_tangential_traction": "stress", "stress": "stress", "von_mises": "stress"}


class UnitChange:
    """The factor by which each kind of quantity is multiplied when every length is multiplied by `length` and
    every force by `force` (tests/support/rescale_problem.hpp); in 2D a force is per unit thickness."""

    def __init__(self, length=1.0, force=1.0, dimension=3):
        self.exponents = {"length": (0, 1), "force": (1, dimension - 3), "stress": (1, -2)}
        self.length, self.force = length, force

    def factor(self, kind):
        f, l = self.exponents.get(kind, (0, 0))
        return self.force ** f * self.length ** l


# The quantities whose scale is also the run's: a displacement, gap or slip is compared at the largest
# displacement of the run, a traction at the largest stress, a force at the largest contact force, so that a
# step where one is zero up to round-off (the tangential traction of a frictionless first step, the gaps of a
# face wholly in contact) is not compared at the scale of its round-off.
VTU_SCALES = {"displacement": "length", "accumulated_slip": "length", "slip_increment": "length",
              "contact_gap": "length", "contact_pressure": "stress", "contact_tangential_traction": "stress",
              "stress": "stress", "von_mises": "stress", "contact_force": "force"}
CSV_SCALES = {"gap": "length", "displacement": "length", "pressure": "stress", "force": "force"}


def vtu_arrays(path):
    """(name, values) of every Float64 array of a VTU file, or of the VTU a .pvtu of the same name stands for."""
    if not os.path.exists(path) and os.path.exists(path.removesuffix(".vtu") + ".pvtu"):
        return pvtu_arrays(path.removesuffix(".vtu") + ".pvtu")
    return [(n, [float(v) for v in t.split()]) for n, t in
            re.findall(r'<DataArray type="Float64" Name="([^"]+)"[^>]*>([^<]*)</DataArray>', open(path).read())]


class Comparison:
    """Two runs' numbers; `units`: the second run's units against the first's (None: the same)."""

    def __init__(self, units=None, rel=REL):
        self.rel = rel
        self.count = 0
        self.failures = []
        self.units = units or UnitChange()
        self.run_scale = {}

    def widen(self, group, values):
        """The run's scale of `group` (None: a quantity compared at its own scale only) covers `values`."""
        if group:
            finite = [abs(v) for v in values if not math.isnan(v)]
            self.run_scale[group] = max([self.run_scale.get(group, 0.0)] + finite)

    def numbers(self, where, a, b, scale, kind=None, group=None):
        scale = max(scale, self.run_scale.get(group, 0.0))
        f = self.units.factor(kind)
        for i, (x, y) in enumerate(zip(a, b)):
            self.count += 1
            if math.isnan(x) and math.isnan(y):
                continue
            if not abs(f * x - y) <= self.rel * f * scale:
                self.failures.append(f"{where}[{i}]: {x!r} × {f:g} != {y!r} (scale {scale:.3g})")

    def vtu(self, where, a_path, b_path):
        a, b = vtu_arrays(a_path), vtu_arrays(b_path)
        if [n for n, _ in a] != [n for n, _ in b]:
            self.failures.append(f"{where}: different arrays")
            return
        for (name, va), (_, vb) in zip(a, b):
            finite = [abs(v) for v in va if not math.isnan(v)]
            self.numbers(f"{where} {name}", va, vb, max(finite, default=0.0) or 1.0, VTU_KINDS.get(name),
                         VTU_SCALES.get(name))

    def csv(self, where, a_path, b_path):
        ra, rb = list(csv.DictReader(open(a_path))), list(csv.DictReader(open(b_path)))
        if len(ra) != len(rb):
            self.failures.append(f"{where}: {len(ra)} rows != {len(rb)}")
            return
        for group, pattern in CSV_GROUPS:
            columns = [c for c in ra[0] if pattern.match(c)]
            values = [abs(float(r[c])) for r in ra for c in columns if not math.isnan(float(r[c]))]
            scale = max(values, default=0.0) or 1.0
            for c in columns:
                self.numbers(f"{where} {c}", [float(r[c]) for r in ra], [float(r[c]) for r in rb], scale,
                             CSV_KINDS[group], CSV_SCALES.get(group))
        for c in ("side", "surface", "node", "status"):
            if [r[c] for r in ra] != [r[c] for r in rb]:
                self.failures.append(f"{where}: column {c} differs")

    def summary(self, where, a_path, b_path):
        a, b = json.load(open(a_path)), json.load(open(b_path))
        for key in ("status",):
            if a[key] != b[key] or a[key] != "ok":
                self.failures.append(f"{where}: status {a[key]} / {b[key]}")
        for k, (sa, sb) in enumerate(zip(a["steps"], b["steps"])):
            forces = [x for r in sa["reactions"] for x in r["force"]] + sa["applied_load"]
            scale = max(abs(x) for x in forces) or 1.0
            for i, (ra, rb) in enumerate(zip(sa["reactions"], sb["reactions"])):
                self.numbers(f"{where} step {k + 1} reaction {i}", ra["force"], rb["force"], scale, "force")
            self.numbers(f"{where} step {k + 1} applied load", sa["applied_load"], sb["applied_load"], scale,
                         "force")
        if len(a["steps"]) != len(b["steps"]):
            self.failures.append(f"{where}: {len(a['steps'])} steps != {len(b['steps'])}")


def main():
    symcontact, mpiexec, examples, work, rescale = sys.argv[1:6]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    failed = False
    for k, (name, extra, mesh_size, *tolerance) in enumerate(CASES):
        rel = tolerance[0] if tolerance else REL
        path = case_file(examples, work, name, extra)
        case_label = label_of(extra)
        tag = name.replace("/", "_").removesuffix(".toml") + case_label.replace(" ", "_")
        serial, mpi = os.path.join(work, tag + "_serial"), os.path.join(work, tag + "_mpi")
        size = ["--mesh-size", str(mesh_size)] if mesh_size else []
        run([symcontact, "run", path, "-o", serial, "-q"] + size)
        run([mpiexec, "-n", "2", "--oversubscribe", symcontact, "run", path, "-o", mpi, "-q"] + size)
        runs = [("2 ranks", mpi)]
        failed = check_parallel_files(mpi) or failed
        accepted, unwarned = noise_floor_steps(mpi)
        if accepted:
            print(f"{name}{case_label}, 2 ranks: {accepted} step(s) accepted at the noise floor")
        failed = failed or unwarned or (accepted > 0 and name in SETTLES)
        if k == 0:  # the same two ranks again: equal to the last bit
            again = os.path.join(work, tag + "_mpi_again")
            run([mpiexec, "-n", "2", "--oversubscribe", symcontact, "run", path, "-o", again, "-q"] + size)
            differ = [f for f in sorted(os.listdir(mpi)) if not f.endswith(".json")
                      and not filecmp.cmp(os.path.join(mpi, f), os.path.join(again, f), shallow=False)]
            print(f"{name}, 2 ranks twice: files that differ: {differ}")
            failed = failed or bool(differ) or plot_tool_differs(serial, mpi)
        if k == 0:  # one process on the distributed path, chosen by the problem file
            single = os.path.join(work, tag + "_iterative")
            run([symcontact, "run", case_file(examples, work, name, extra + ITERATIVE), "-o", single, "-q"] + size)
            runs.append(("linear_solver = iterative", single))
        if k == 1:  # another BLAS kernel (restart_with_better_blas_kernels keeps a given one)
            baseline = os.path.join(work, tag + "_prescott")
            given = os.environ.get("OPENBLAS_CORETYPE")
            os.environ["OPENBLAS_CORETYPE"] = "Prescott"
            try:
                run([mpiexec, "-n", "2", "--oversubscribe", "-x", "OPENBLAS_CORETYPE", symcontact, "run", path,
                     "-o", baseline, "-q"] + size)
            finally:
                if given is None:
                    del os.environ["OPENBLAS_CORETYPE"]
                else:
                    os.environ["OPENBLAS_CORETYPE"] = given
            runs.append(("2 ranks, OPENBLAS_CORETYPE=Prescott", baseline))
        for label, folder in runs:
            c = compare(serial, folder, rel=rel)
            print(f"{name}{case_label}, {label}: {c.count} numbers, {len(c.failures)} beyond {rel:g} of their "
                  "quantity's scale")
            for line in c.failures[:20]:
                print("  " + line)
            failed = failed or bool(c.failures)
    for name, extra, dimension, length, force, label in UNITS:  # two ranks in other units (rescale_problem.hpp)
        folders = []
        for change in (UnitChange(), UnitChange(length, force, dimension)):
            tag = f"{name.replace('/', '_').removesuffix('.toml')}_units_{change.length:g}_{change.force:g}"
            problem = subprocess.run([rescale, case_file(examples, work, name, extra), os.path.join(work, tag),
                                      "--length", str(change.length), "--force", str(change.force)],
                                     stdout=subprocess.PIPE, text=True, check=True).stdout.strip()
            folders.append(os.path.join(work, tag + "_out"))
            run([mpiexec, "-n", "2", "--oversubscribe", symcontact, "run", problem, "-o", folders[-1], "-q"])
        c = compare(folders[0], folders[1], UnitChange(length, force, dimension))
        print(f"{name}, 2 ranks in {label}: {c.count} numbers, {len(c.failures)} beyond {REL:g} of their "
              "quantity's scale")
        for line in c.failures[:20]:
            print("  " + line)
        failed = failed or bool(c.failures) or c.count == 0
    for name, extra, reason in FAILED_SOLVES:
        path = case_file(examples, work, name, extra)
        for label, launch in (("serially", []), ("under mpirun", [mpiexec, "-n", "2", "--oversubscribe"])):
            out = os.path.join(work, "failed_solve_" + label.replace(" ", "_"))
            r = subprocess.run(launch + [symcontact, "run", path, "-o", out],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            ok = r.returncode == 3 and reason in r.stdout
            print(f"{name} with {extra.splitlines()[0]} {label}: exit {r.returncode}, {reason in r.stdout}")
            failed = failed or not ok
    for k, (name, extra, what, reason) in enumerate(DISTRIBUTED_FAILURES):
        out = os.path.join(work, f"distributed_failure_{k}")
        r = subprocess.run([mpiexec, "-n", "2", "--oversubscribe", symcontact, "run",
                            case_file(examples, work, name, extra), "-o", out],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        print(f"{name} {what} under mpirun: exit {r.returncode}, {reason in r.stdout}")
        failed = failed or r.returncode != 3 or reason not in r.stdout
    for name, key in UNSUPPORTED:
        out = os.path.join(work, "unsupported")
        r = subprocess.run([mpiexec, "-n", "2", "--oversubscribe", symcontact, "run", os.path.join(examples, name),
                            "-o", out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        ok = r.returncode == 2 and key in r.stdout and r.stdout.count("input error") == 1 and not os.path.exists(out)
        print(f"{name} under mpirun: exit {r.returncode}, {r.stdout.strip()!r}")
        failed = failed or not ok
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
