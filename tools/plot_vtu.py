#!/usr/bin/env python3
"""Draws the deformed mesh of one or more symcontact .vtu files into a PNG.

    tools/plot_vtu.py OUT.png FILE.vtu|FILE.pvtu [...] [--field von_mises] [--scale S] [--title T]
                      [--xlim LO,HI] [--ylim LO,HI]

Reads the ASCII VTK XML UnstructuredGrid files written by `symcontact run` (inline ASCII DataArrays), and the
.pvtu of a run on several processes with its pieces.
The mesh is moved by `--scale` times the point data "displacement" (default: the factor that makes the
largest displacement 10 % of the model size), coloured by a point (or cell) data field (default
"von_mises"; vector and tensor fields are shown by their Euclidean norm), with a colour bar, a title and
the undeformed outline in grey. Every file is one body in the same picture, on a shared colour scale.
In 2D, `--xlim` and `--ylim` zoom on a window (for example the contact zone); the colour scale is then
that of the nodes inside the window.

2D: triangles and quadrilaterals, linear or quadratic (quadratic cells are drawn by their vertices).
3D: tetrahedra and hexahedra, linear or quadratic (drawn by their vertices); the boundary faces are drawn
in an orthographic view. Below it, when the files carry contact results (point data "contact_status",
written for runs with [[contact]]), each body's contact face, which the bodies hide from each other in the
main view: its boundary faces whose nodes all lie on a contact surface, deformed, seen from outside the
body along their mean outward normal, on the same colour scale.

Needs only python3, numpy and matplotlib (Debian: python3-numpy python3-matplotlib).
"""

import argparse
import os
import re
import sys
import xml.etree.ElementTree as ET

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402
from matplotlib.tri import Triangulation  # noqa: E402
from mpl_toolkits.axes_grid1 import make_axes_locatable  # noqa: E402

# VTK cell type -> (dimension, number of vertex nodes, number of nodes). Vertex nodes come first.
CELL_TYPES = {
    5: (2, 3, 3),    # triangle
    22: (2, 3, 6),   # quadratic triangle
    9: (2, 4, 4),    # quad
    23: (2, 4, 8),   # quadratic quad
    28: (2, 4, 9),   # biquadratic quad
    10: (3, 4, 4),   # tetrahedron
    24: (3, 4, 10),  # quadratic tetrahedron
    12: (3, 8, 8),   # hexahedron
    25: (3, 8, 20),  # quadratic hexahedron
    29: (3, 8, 27),  # triquadratic hexahedron
}
# Faces of a tetrahedron and of a hexahedron (vertex indices) and a vertex off each.
TET_FACES = (((0, 2, 1), 3), ((0, 1, 3), 2), ((1, 2, 3), 0), ((0, 3, 2), 1))
HEX_FACES = (((0, 3, 2, 1), 4), ((4, 5, 6, 7), 0), ((0, 1, 5, 4), 3), ((1, 2, 6, 5), 0), ((2, 3, 7, 6), 1),
             ((3, 0, 4, 7), 1))


class VtuError(Exception):
    pass


def _xml_root(path, kind):
    try:
        root = ET.parse(path).getroot()
    except (ET.ParseError, OSError) as e:
        raise VtuError(f"{path}: cannot read as XML: {e}")
    if root.get("type") != kind:
        raise VtuError(f"{path}: not a VTK {kind} file (type={root.get('type')!r})")
    return root


def _read_grid(path):
    """Points (N x 3), connectivity, offsets, types, point data and cell data of one .vtu file."""
    pieces = _xml_root(path, "UnstructuredGrid").findall("./UnstructuredGrid/Piece")
    if len(pieces) != 1:
        raise VtuError(f"{path}: expected one <Piece>, found {len(pieces)}")
    piece = pieces[0]
    npts = int(piece.get("NumberOfPoints"))
    ncells = int(piece.get("NumberOfCells"))
    points = _array(path, piece.find("./Points/DataArray"), "Points").reshape(npts, -1)
    cells = piece.find("Cells")
    conn = _named(path, cells, "connectivity").astype(np.int64)
    offsets = _named(path, cells, "offsets").astype(np.int64)
    types = _named(path, cells, "types").astype(np.int64)
    if len(offsets) != ncells or len(types) != ncells:
        raise VtuError(f"{path}: {ncells} cells declared but {len(offsets)} offsets and {len(types)} types")
    return points, conn, offsets, types, _data(path, piece.find("PointData"), npts), _data(path, piece.find("CellData"),
                                                                                            ncells)


def _read_parallel(path):
    """The same of a .pvtu (a run on several processes), its pieces put back together: each piece's points are the
    body's nodes of its point data "node", its cells the body's cells of its cell data "cell" (without it, they
    follow the previous piece's)."""
    sources = [p.get("Source") for p in _xml_root(path, "PUnstructuredGrid").findall("./PUnstructuredGrid/Piece")]
    parts = [_read_grid(os.path.join(os.path.dirname(path), s)) for s in sources]
    if not parts or any("node" not in p[4] for p in parts):
        raise VtuError(f"{path}: expected pieces with the point data 'node' (written by symcontact)")
    nodes = [p[4]["node"].astype(np.int64) for p in parts]
    count = 1 + max(int(n.max(initial=-1)) for n in nodes)
    points = np.zeros((count, parts[0][0].shape[1]))
    point_data = {k: np.zeros((count,) + v.shape[1:]) for k, v in parts[0][4].items() if k != "node"}
    conn, offsets, end = [], [], 0
    for (pts, c, o, _, pd, _), n in zip(parts, nodes):
        points[n] = pts
        for k in point_data:
            point_data[k][n] = pd[k]
        conn.append(n[c])
        offsets.append(o + end)
        end += len(c)
    cell_data = {k: np.concatenate([p[5][k] for p in parts]) for k in parts[0][5]}
    conn, offsets, types = np.concatenate(conn), np.concatenate(offsets), np.concatenate([p[3] for p in parts])
    ids = cell_data.pop("cell", None)
    if ids is not None:  # the pieces' cells back in the body's order
        order = np.argsort(ids.astype(np.int64), kind="stable")
        starts = np.concatenate([[0], offsets[:-1]])
        cells = [conn[starts[i]:offsets[i]] for i in order]
        conn = np.concatenate(cells) if cells else conn
        offsets = np.cumsum([len(c) for c in cells]).astype(offsets.dtype)
        types = types[order]
        cell_data = {k: v[order] for k, v in cell_data.items()}
    return points, conn, offsets, types, point_data, cell_data


class Body:
    """One body: points (N x 3), cells by vertex nodes, point and cell data by name."""

    def __init__(self, path):
        self.path = path
        # "<body>_<step>.vtu" (or .pvtu) as written by symcontact: the body's name.
        self.name = re.sub(r"_[0-9]+$", "", os.path.splitext(os.path.basename(path))[0])
        read = _read_parallel if path.endswith(".pvtu") else _read_grid
        self.points, conn, offsets, types, self.point_data, self.cell_data = read(path)
        npts = len(self.points)

        # Cells grouped by their vertex count; quadratic cells keep their vertices only.
        unknown = sorted(set(types.tolist()) - set(CELL_TYPES))
        if unknown:
            raise VtuError(f"{path}: unsupported VTK cell types {unknown} (supported: {sorted(CELL_TYPES)})")
        dims = {CELL_TYPES[t][0] for t in types.tolist()}
        if len(dims) != 1:
            raise VtuError(f"{path}: mixes 2D and 3D cells")
        self.dim = dims.pop()
        starts = np.concatenate(([0], offsets[:-1]))
        self.cells = []  # list of (cell index array, vertex array [n x nv])
        for t in sorted(set(types.tolist())):
            _, nv, nn = CELL_TYPES[t]
            idx = np.nonzero(types == t)[0]
            if np.any(offsets[idx] - starts[idx] != nn):
                raise VtuError(f"{path}: cells of VTK type {t} must have {nn} nodes")
            verts = np.stack([conn[starts[idx] + k] for k in range(nv)], axis=1)
            self.cells.append((idx, verts))

        disp = self.point_data.get("displacement")
        if disp is None:
            self.u = np.zeros_like(self.points)
        else:
            self.u = disp.reshape(npts, -1)

    def field(self, name):
        """(values, 'point'|'cell'); vectors and tensors by their norm."""
        for where, data in (("point", self.point_data), ("cell", self.cell_data)):
            if name in data:
                v = data[name]
                return (v if v.ndim == 1 else np.linalg.norm(v, axis=1)), where
        available = sorted(set(self.point_data) | set(self.cell_data))
        raise VtuError(f"{self.path}: no point or cell data named {name!r} (available: {', '.join(available)})")

    def boundary_polygons(self):
        """Boundary of the body: 2D -> list of edges (i, j); 3D -> list of (cell, face vertices (3 or 4), a vertex
        of the cell off the face), that vertex telling which side is outside."""
        if self.dim == 2:
            count = {}
            for _, verts in self.cells:
                nv = verts.shape[1]
                for row in verts:
                    for k in range(nv):
                        a, b = int(row[k]), int(row[(k + 1) % nv])
                        key = (min(a, b), max(a, b))
                        count[key] = count.get(key, 0) + 1
            return [e for e, c in count.items() if c == 1]
        faces = {}
        for idx, verts in self.cells:
            for c, row in zip(idx, verts):
                for f, opposite in (TET_FACES if verts.shape[1] == 4 else HEX_FACES):
                    face = tuple(int(row[k]) for k in f)
                    key = tuple(sorted(face))
                    faces[key] = None if key in faces else (int(c), face, int(row[opposite]))
        return [v for v in faces.values() if v is not None]


def _array(path, element, what):
    if element is None:
        raise VtuError(f"{path}: missing {what} DataArray")
    fmt = element.get("format", "ascii")
    if fmt != "ascii":
        raise VtuError(f"{path}: {what} is stored as format={fmt!r}; only ASCII .vtu files are supported")
    text = element.text or ""
    try:
        return np.array(text.split(), dtype=float)
    except ValueError as e:
        raise VtuError(f"{path}: {what}: not a list of numbers ({e})")


def _named(path, parent, name):
    if parent is not None:
        for a in parent.findall("DataArray"):
            if a.get("Name") == name:
                return _array(path, a, f"Cells/{name}")
    raise VtuError(f"{path}: missing Cells DataArray {name!r}")


def _data(path, parent, count):
    out = {}
    if parent is None:
        return out
    for a in parent.findall("DataArray"):
        name = a.get("Name")
        ncomp = int(a.get("NumberOfComponents", "1"))
        v = _array(path, a, f"data array {name!r}")
        if v.size != ncomp * count:
            raise VtuError(f"{path}: data array {name!r} has {v.size} values, expected {ncomp} x {count}")
        out[name] = v if ncomp == 1 else v.reshape(count, ncomp)
    return out


def default_scale(bodies):
    pts = np.vstack([b.points for b in bodies])
    size = float(np.max(pts.max(axis=0) - pts.min(axis=0)))
    umax = max(float(np.max(np.linalg.norm(b.u, axis=1))) if len(b.u) else 0.0 for b in bodies)
    if umax <= 0.0 or size <= 0.0:
        return 1.0
    return 0.1 * size / umax


def view_basis():
    """Orthographic projection for 3D: screen x, screen y and the direction towards the viewer."""
    az, el = np.radians(-60.0), np.radians(25.0)
    towards = np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])
    right = np.cross([0.0, 0.0, 1.0], towards)
    right /= np.linalg.norm(right)
    up = np.cross(towards, right)
    return right, up, towards


def draw_2d(ax, bodies, fields, scale, norm, cmap):
    mappable = None
    for b, (values, where) in zip(bodies, fields):
        x0 = b.points[:, :2]
        x = x0 + scale * b.u[:, :2]
        outline = [(x0[i], x0[j]) for i, j in b.boundary_polygons()]
        ax.add_collection(LineCollection(outline, colors="0.6", linewidths=0.8, zorder=1))
        for idx, verts in b.cells:
            if verts.shape[1] == 4:  # split quads for the triangulation
                tris = np.vstack([verts[:, [0, 1, 2]], verts[:, [0, 2, 3]]])
                cell_of = np.concatenate([idx, idx])
            else:
                tris, cell_of = verts, idx
            tri = Triangulation(x[:, 0], x[:, 1], tris)
            if where == "point":
                mappable = ax.tripcolor(tri, values, shading="gouraud", cmap=cmap, norm=norm, zorder=2)
            else:
                mappable = ax.tripcolor(tri, facecolors=values[cell_of], cmap=cmap, norm=norm, zorder=2)
            ax.triplot(tri, color="k", linewidth=0.2, alpha=0.35, zorder=3)
    return mappable


def draw_3d(ax, bodies, fields, scale, norm, cmap):
    right, up, towards = view_basis()
    polys, colours, depths, outline = [], [], [], []
    for b, (values, where) in zip(bodies, fields):
        x0 = b.points[:, :3]
        x = x0 + scale * b.u[:, :3]
        for cell, tri, opposite in b.boundary_polygons():
            t = list(tri)
            p = x[t]
            normal = np.cross(p[1] - p[0], p[2] - p[0])
            if normal @ (p[0] - x[opposite]) < 0.0:  # make it point out of the body
                normal = -normal
            outline.append([(x0[k] @ right, x0[k] @ up) for k in t])
            if normal @ towards <= 0.0:  # faces turned away from the viewer are hidden
                continue
            polys.append([(q @ right, q @ up) for q in p])
            colours.append(values[t].mean() if where == "point" else values[cell])
            depths.append((p @ towards).mean())
    ax.add_collection(PolyCollection(outline, facecolors="none", edgecolors="0.7", linewidths=0.3, zorder=1))
    order = np.argsort(depths)  # painter's algorithm: far faces first
    pc = PolyCollection([polys[i] for i in order], array=np.asarray(colours)[order], cmap=cmap, norm=norm,
                        edgecolors="k", linewidths=0.15, zorder=2)
    ax.add_collection(pc)
    return pc


def outward_faces(x, faces):
    """[(cell, vertex triple, outward normal)] of 3D boundary faces at positions x."""
    out = []
    for cell, tri, opposite in faces:
        p = x[list(tri)]
        normal = np.cross(p[1] - p[0], p[2] - p[0])
        if normal @ (p[0] - x[opposite]) < 0.0:
            normal = -normal
        out.append((cell, tri, normal))
    return out


def contact_faces(body):
    """The boundary faces of a 3D body whose vertices all lie on a contact surface (contact_status >= 0)."""
    status = body.point_data.get("contact_status")
    if status is None:
        return []
    return [f for f in body.boundary_polygons() if all(status[k] >= 0 for k in f[1])]


def draw_contact_face(ax, body, faces, field, scale, norm, cmap):
    """The faces, deformed, seen from outside the body along their mean outward normal n."""
    values, where = field
    x = body.points[:, :3] + scale * body.u[:, :3]
    oriented = outward_faces(x, faces)
    n = sum(f[2] for f in oriented)
    n = n / np.linalg.norm(n)
    # e1: the face's direction of largest spread in the plane normal to n, its largest component positive.
    pts = x[sorted({k for _, tri, _ in oriented for k in tri})]
    pts = pts - pts.mean(axis=0)
    pts = pts - np.outer(pts @ n, n)
    e1 = np.linalg.svd(pts, full_matrices=False)[2][0]
    if e1[np.argmax(np.abs(e1))] < 0:
        e1 = -e1
    e2 = np.cross(n, e1)  # (e1, e2, n) right-handed: the viewer is on the +n side
    polys = [[(q @ e1, q @ e2) for q in x[list(tri)]] for _, tri, _ in oriented]
    colours = [values[list(tri)].mean() if where == "point" else values[cell] for cell, tri, _ in oriented]
    ax.add_collection(PolyCollection(polys, array=np.asarray(colours), cmap=cmap, norm=norm, edgecolors="k",
                                     linewidths=0.15))
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_axis_off()
    ax.set_title(f"contact face of {body.name}, seen from outside along n = ({n[0]:.2g}, {n[1]:.2g}, {n[2]:.2g})",
                 fontsize=9)


def _limits(text):
    try:
        lo, hi = (float(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected two numbers separated by a comma, got {text!r}")
    if not lo < hi:
        raise argparse.ArgumentTypeError(f"expected LO < HI, got {text!r}")
    return lo, hi


def _in_window(body, values, where, scale, xlim, ylim):
    """The field values of the nodes (or cells, by their first vertex) whose deformed position lies in the
    window; all of them when there is no window."""
    if xlim is None and ylim is None:
        return values
    x = body.points[:, :2] + scale * body.u[:, :2]
    inside = np.ones(len(x), dtype=bool)
    if xlim:
        inside &= (x[:, 0] >= xlim[0]) & (x[:, 0] <= xlim[1])
    if ylim:
        inside &= (x[:, 1] >= ylim[0]) & (x[:, 1] <= ylim[1])
    if where == "point":
        return values[inside]
    keep = np.zeros(len(values), dtype=bool)
    for idx, verts in body.cells:
        keep[idx] = inside[verts[:, 0]]
    return values[keep]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", metavar="OUT.png", help="picture to write")
    ap.add_argument("files", metavar="FILE.vtu", nargs="+", help="one .vtu (or .pvtu) file per body")
    ap.add_argument("--field", default="von_mises", help="point or cell data to colour by (default: von_mises)")
    ap.add_argument("--scale", type=float, default=None,
                    help="displacement amplification (default: largest displacement = 10%% of the model size)")
    ap.add_argument("--title", default=None, help="picture title")
    ap.add_argument("--xlim", type=_limits, default=None, metavar="LO,HI",
                    help="2D: horizontal range to show (write --xlim=-1,1 when LO is negative)")
    ap.add_argument("--ylim", type=_limits, default=None, metavar="LO,HI", help="2D: vertical range to show")
    args = ap.parse_args(argv)

    try:
        bodies = [Body(f) for f in args.files]
        dims = {b.dim for b in bodies}
        if len(dims) != 1:
            raise VtuError("the files mix 2D and 3D meshes")
        dim = dims.pop()
        fields = [b.field(args.field) for b in bodies]
    except VtuError as e:
        print(f"plot_vtu: {e}", file=sys.stderr)
        return 2

    if dim == 3 and (args.xlim or args.ylim):
        print("plot_vtu: --xlim and --ylim are for 2D meshes", file=sys.stderr)
        return 2
    scale = default_scale(bodies) if args.scale is None else args.scale
    shown = [_in_window(b, v, where, scale, args.xlim, args.ylim) for b, (v, where) in zip(bodies, fields)]
    shown = [v for v in shown if v.size] or [v for v, _ in fields]
    lo = min(float(v.min()) for v in shown)
    hi = max(float(v.max()) for v in shown)
    if hi - lo <= 1e-6 * max(abs(lo), abs(hi)):
        # A uniform field (as in a patch test): show it as one colour, not its round-off.
        mid = 0.5 * (lo + hi)
        half = 0.05 * abs(mid) if mid != 0.0 else 1.0
        lo, hi = mid - half, mid + half
    norm = matplotlib.colors.Normalize(vmin=lo, vmax=hi)
    cmap = plt.get_cmap("viridis")

    faces = [contact_faces(b) for b in bodies] if dim == 3 else []
    with_faces = [(b, f, field) for b, f, field in zip(bodies, faces, fields) if f]
    if with_faces:
        fig = plt.figure(figsize=(8, 9), dpi=120)
        grid = fig.add_gridspec(1 + len(with_faces), 1, height_ratios=[2.4] + [1.0] * len(with_faces))
        ax = fig.add_subplot(grid[0])
        for k, (b, f, field) in enumerate(with_faces):
            draw_contact_face(fig.add_subplot(grid[1 + k]), b, f, field, scale, norm, cmap)
    else:
        fig, ax = plt.subplots(figsize=(8, 6), dpi=120)
    draw = draw_2d if dim == 2 else draw_3d
    mappable = draw(ax, bodies, fields, scale, norm, cmap)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.margins(0.05)
    if args.xlim:
        ax.set_xlim(*args.xlim)
    if args.ylim:
        ax.set_ylim(*args.ylim)
    if dim == 3:
        ax.set_axis_off()
    else:
        ax.set_xlabel("x")
        ax.set_ylabel("y")
    # Fit the figure to the drawing's aspect ratio, then a colour bar as tall as the axes.
    x_lo, x_hi = ax.get_xlim()
    y_lo, y_hi = ax.get_ylim()
    aspect = (y_hi - y_lo) / max(x_hi - x_lo, 1e-300)
    height = float(np.clip(6.4 * aspect + 1.6, 3.0, 9.0))
    fig.set_size_inches(8.0, height * (1.0 + 0.4 * len(with_faces)))
    cax = make_axes_locatable(ax).append_axes("right", size="3%", pad=0.15)
    fig.colorbar(mappable, cax=cax, label=args.field)
    title = args.title or ", ".join(b.name for b in bodies)
    ax.set_title(f"{title}\n(displacement x {scale:.3g}; undeformed in grey)", fontsize=11)
    fig.tight_layout()
    try:
        fig.savefig(args.out)
    except OSError as e:
        print(f"plot_vtu: cannot write {args.out}: {e}", file=sys.stderr)
        return 1
    print(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
