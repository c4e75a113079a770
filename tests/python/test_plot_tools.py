"""The picture tools of tools/ on the output of a 3D frictional example (examples/inclined_3d) and of a 2D
one with open nodes: each writes a picture that is not empty, and the legends say what is drawn."""

import collections
import csv
import sys

import pytest

import symcontact
from conftest import EXAMPLES, ROOT, ink, run_python

sys.path.insert(0, str(ROOT / "tools"))
import plot_contact  # noqa: E402
import plot_vtu  # noqa: E402


@pytest.fixture(scope="module")
def inclined_3d(tmp_path_factory):
    out = tmp_path_factory.mktemp("inclined_3d")
    symcontact.Problem(EXAMPLES / "inclined_3d" / "inclined.toml").run(out_dir=out)
    return out


def csv_status_counts(path):
    counts = collections.defaultdict(collections.Counter)
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            counts[row["side"]][row["status"]] += 1
    return counts


def drawn_markers(ax):
    """status -> number of nodes drawn with its marker style (rims left out), from the axes' lines."""
    drawn = collections.Counter()
    for line in ax.get_lines():
        if line.get_linestyle() != "None" or line.get_markeredgecolor() == "w":
            continue
        hollow = line.get_markerfacecolor() == "none"
        for status, (marker, filled, _) in plot_contact.STATUS_STYLE.items():
            if line.get_marker() == marker and filled != hollow and status in ("open", "slip"):
                drawn[status] += len(line.get_xdata())
        if line.get_marker() == "o" and not hollow:
            drawn["in contact"] += len(line.get_xdata())
    return drawn


def legend_counts(ax):
    counts = {}
    for text in ax.get_legend().get_texts():
        name, _, number = text.get_text().rpartition(": ")
        if number.isdigit():
            counts[name] = int(number)
    return counts


def check_contact_picture(argv, csv_file, tmp_path):
    _, fig, _ = plot_contact.render(argv)
    expected = csv_status_counts(csv_file)
    legends = [ax for ax in fig.axes if ax.get_legend() is not None]
    total = collections.Counter()
    for ax in legends:
        total.update(legend_counts(ax))
        drawn = drawn_markers(ax)
        names = {v[2]: k for k, v in plot_contact.STATUS_STYLE.items()}
        legend = {names[k]: n for k, n in legend_counts(ax).items()}
        assert drawn["open"] == legend.get("open", 0)
        assert drawn["slip"] == legend.get("slip", 0)
        assert drawn["in contact"] == legend.get("stick", 0) + legend.get("contact", 0)
    names = {v[2]: k for k, v in plot_contact.STATUS_STYLE.items()}
    in_csv = sum((expected[s] for s in expected), collections.Counter())
    assert {names[k]: n for k, n in total.items()} == dict(in_csv)
    png = tmp_path / "contact.png"
    assert plot_contact.main([str(png)] + argv[1:]) == 0
    assert ink(png) > 0.05


def test_plot_contact_3d_maps_with_the_statuses_in_the_legend(inclined_3d, tmp_path):
    csv_file = inclined_3d / "contact_interface_0010.csv"
    assert csv_status_counts(csv_file)["a"]["slip"] > 0  # gross slip on the friction side
    check_contact_picture([str(tmp_path / "x.png"), str(csv_file)], csv_file, tmp_path)
    csv_file = inclined_3d / "contact_interface_0003.csv"  # sticking
    check_contact_picture([str(tmp_path / "x.png"), str(csv_file)], csv_file, tmp_path)


def test_plot_contact_2d_draws_open_nodes_hollow(tmp_path):
    symcontact.Problem(EXAMPLES / "hertz_2d" / "cylinder_on_plane.toml").run(out_dir=tmp_path / "hertz")
    csv_file = tmp_path / "hertz" / "contact_floor_0001.csv"
    counts = csv_status_counts(csv_file)["a"]
    assert counts["open"] > 0 and counts["contact"] > 0
    check_contact_picture([str(tmp_path / "x.png"), str(csv_file), "--hertz", "0.107641,0.059143"], csv_file,
                          tmp_path)


def test_plot_reactions_3d_takes_the_normal_and_tangential_components(inclined_3d, tmp_path):
    png = tmp_path / "reactions.png"
    out = run_python(ROOT / "tools" / "plot_reactions.py", png, inclined_3d / "summary.json", "--body", "upper",
                     "--boundary", "upper_top", "--steady", "8", "10", "--ratio", "0.306122")
    assert out.returncode == 0, out.stderr
    assert "normal component y, tangential xz" in out.stdout
    ratio = float(out.stdout.split("over steps 8-10 = ")[1].split()[0])
    assert abs(ratio / 0.306122 - 1) < 0.005  # docs/validation-friction.md V5, 3D: -0.15 %
    assert ink(png) > 0.02


def test_plot_vtu_3d_shows_the_contact_faces(inclined_3d, tmp_path):
    files = [inclined_3d / "lower_0010.vtu", inclined_3d / "upper_0010.vtu"]
    for f in files:
        assert plot_vtu.contact_faces(plot_vtu.Body(str(f)))  # the interface faces are found
    png = tmp_path / "vtu.png"
    out = run_python(ROOT / "tools" / "plot_vtu.py", png, *files)
    assert out.returncode == 0, out.stderr
    assert ink(png) > 0.1
    import matplotlib.image

    height, width = matplotlib.image.imread(str(png)).shape[:2]
    assert height > width  # the main view and, below it, one panel per contact face
