"""symcontact.Problem.run: the results equal the command line's files to the last digit; progress, the
GIL, output folders and errors."""

import csv
import json
import math
import os
import threading
import time

import numpy as np
import pytest

import symcontact
from conftest import EXAMPLES

INCLINED = EXAMPLES / "inclined_2d" / "inclined_reference.toml"  # 2 bodies, Coulomb friction, 0.6 s


def without_times(summary):
    """summary.json without what differs between two runs of the same problem: the timings."""
    s = {k: v for k, v in summary.items() if k not in ("timings", "wall_time")}
    s["steps"] = [{k: v for k, v in step.items() if k != "timings"} for step in summary["steps"]]
    return s


def same(a, b):
    return a == b or (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b))


@pytest.fixture(scope="module")
def runs(tmp_path_factory, cli):
    """The example through the command line and through Python (which also writes a folder), on the same
    OpenBLAS kernels: the command line on this process's (it would otherwise move from OpenBLAS's fallback
    kernels to better ones, src/symcontact/core/blas_kernels.hpp)."""
    cli_dir = tmp_path_factory.mktemp("cli")
    py_dir = tmp_path_factory.mktemp("py") / "out"
    core = symcontact.blas_kernels()["core"]
    out = cli("run", INCLINED, "--out", cli_dir, "-q", env={"OPENBLAS_CORETYPE": core} if core else None)
    assert out.returncode == 0, out.stderr
    result = symcontact.Problem(INCLINED).run(out_dir=py_dir)
    return cli_dir, py_dir, result


def test_summary_equals_the_command_lines_to_the_last_digit(runs):
    cli_dir, py_dir, result = runs
    cli_summary = json.loads((cli_dir / "summary.json").read_text())
    assert result.ok and result.steps_done == 10
    assert without_times(result.summary) == without_times(cli_summary)
    assert without_times(json.loads((py_dir / "summary.json").read_text())) == without_times(cli_summary)
    # The conveniences read the same numbers.
    upper = sum(np.array(r["force"]) for r in cli_summary["steps"][-1]["reactions"] if r["boundary"] == "upper_top")
    assert np.array_equal(result.reaction("upper", "upper_top")[-1], upper)
    assert list(result.iterations["ipopt_iterations"]) == [s["ipopt_iterations"] for s in cli_summary["steps"]]
    assert set(result.timings) >= {"optimizer", "wall_time"}


def test_contact_tables_equal_the_csv_files_to_the_last_digit(runs):
    cli_dir, py_dir, result = runs
    tables = result.contact["interface"]
    assert len(tables) == 10
    for step, table in enumerate(tables, start=1):
        name = f"contact_interface_{step:04d}.csv"
        assert (py_dir / name).read_bytes() == (cli_dir / name).read_bytes()
        with open(cli_dir / name, newline="") as f:
            rows = list(csv.reader(f))
        assert list(table) == rows[0]  # the same columns, in the same order
        for j, column in enumerate(rows[0]):
            values = [r[j] for r in rows[1:]]
            if column in ("side", "surface", "status"):
                assert list(table[column]) == values
            elif column == "node":
                assert list(table[column]) == [int(v) for v in values]
            else:
                assert all(same(float(a), float(b)) for a, b in zip(table[column], values)), (name, column)
    assert set(tables[-1]["status"]) <= {"open", "contact", "stick", "slip"}


def test_displacements_agree_with_the_contact_tables(runs):
    _, _, result = runs
    assert result.displacement["upper"].shape == (10, len(result.nodes["upper"]), 2)
    assert result.stress["upper"].shape == (10, len(result.nodes["upper"]), 6)
    t = result.contact["interface"][-1]
    for body, side in (("upper", "a"), ("lower", "b")):
        rows = t["side"] == side
        u = result.displacement[body][-1][t["node"][rows] - 1]
        assert np.array_equal(u[:, 0], t["ux"][rows]) and np.array_equal(u[:, 1], t["uy"][rows])
        assert np.array_equal(result.nodes[body][t["node"][rows] - 1][:, 0], t["x_ref"][rows])


def test_no_folder_unless_asked_and_progress_with_the_gil_released(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    problem = symcontact.Problem(INCLINED)
    problem["problem.mesh_size"] = 0.1
    calls, ticks = [], []
    running = threading.Event()

    def ticker():  # runs only while the solve has released the GIL
        while not running.is_set():
            time.sleep(0.001)
        while running.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    thread = threading.Thread(target=ticker)
    thread.start()
    running.set()
    start = time.perf_counter()
    result = problem.run(progress=lambda step, n, message: calls.append((step, n, message)))
    end = time.perf_counter()
    running.clear()
    thread.join()
    assert [c[:2] for c in calls] == [(k, 10) for k in range(1, 11)]
    assert "optimizer iterations" in calls[0][2]
    middle = [t for t in ticks if start + 0.2 * (end - start) < t < end - 0.2 * (end - start)]
    assert len(middle) > 5, f"{len(middle)} ticks in the middle of a {end - start:.2f} s run"
    assert list(tmp_path.iterdir()) == []  # nothing written
    assert result.summary["status"] == "ok"


def test_a_progress_callback_that_raises_ends_the_run():
    def stop(step, n, message):
        if step == 2:
            raise KeyboardInterrupt

    problem = symcontact.Problem(INCLINED)
    problem["problem.mesh_size"] = 0.1
    with pytest.raises(KeyboardInterrupt):
        problem.run(progress=stop)


def test_a_failed_solve_raises_solve_error_with_the_finished_steps(tmp_path):
    problem = symcontact.Problem(INCLINED)
    problem.update({"problem.mesh_size": 0.1, "contact_solver.max_coulomb_iterations": 2})
    with pytest.raises(symcontact.SolveError) as e:
        problem.run(out_dir=tmp_path / "out")
    assert e.value.exit_code == 3 and str(e.value).startswith("load step ")
    r = e.value.result
    assert r.status == "solve_failed" and r.summary["status"] == "solve_failed"
    assert len(r.displacement["upper"]) == r.steps_done == len(r.steps)
    assert json.loads((tmp_path / "out" / "summary.json").read_text())["message"] == str(e.value)
    assert problem.run(check=False).status == "solve_failed"


def test_input_errors_leave_no_folder(tmp_path):
    problem = symcontact.Problem(INCLINED)
    problem["body.0.group"] = "no_such_group"  # found when the mesh is read, in run()
    with pytest.raises(symcontact.InputError) as e:
        problem.run(out_dir=tmp_path / "out")
    assert e.value.key == "body[0].group" and e.value.exit_code == 2
    assert not (tmp_path / "out").exists()
    (tmp_path / "file").write_text("")
    with pytest.raises(symcontact.InputError, match="out_dir: the output folder"):
        symcontact.Problem(INCLINED).run(out_dir=tmp_path / "file")
    with pytest.raises(symcontact.InputError, match="mesh_size"):
        symcontact.Problem(INCLINED).run(mesh_size=-1)


def test_the_linear_solver_is_chosen_by_the_command_lines_rule_and_said(capfd):
    """The module runs the direct solver only: it says so at "verbose" (the rule of
    src/symcontact/app/linear_solver_choice.hpp, here for a pair of elastic bodies, which its cost
    part does not weigh), and refuses "iterative"."""
    symcontact.Problem(INCLINED).run(verbosity="verbose")
    err = capfd.readouterr().err
    assert "linear solver: direct (automatic: no cost estimate: contact[0] is between elastic bodies" in err, err
    problem = symcontact.Problem(INCLINED)
    problem["contact_solver.linear_solver"] = "iterative"
    with pytest.raises(symcontact.InputError) as e:
        problem.run()
    assert e.value.key == "contact_solver.linear_solver" and "direct" in str(e.value)


def test_ctrl_c_during_a_solve_ends_the_run_after_its_step():
    import os
    import signal

    problem = symcontact.Problem(INCLINED)
    problem["problem.mesh_size"] = 0.1
    steps = []

    def interrupt_during_step_3(step, n, message):
        steps.append(step)
        if step == 2:  # SIGINT as Ctrl-C sends it, while step 3 is being solved (the GIL released)
            threading.Timer(0.02, os.kill, (os.getpid(), signal.SIGINT)).start()

    with pytest.raises(KeyboardInterrupt):
        problem.run(progress=interrupt_during_step_3)
    assert steps[:2] == [1, 2] and len(steps) <= 4  # not the 10 steps of the whole run


def test_blas_kernels_name_the_family_and_the_command_lines_choice(cli):
    kernels = symcontact.blas_kernels()
    assert kernels["better"] in ("", "SkylakeX", "Haswell")
    if not kernels["core"]:
        pytest.skip("the BLAS is not OpenBLAS")
    assert not (kernels["better"] and kernels["better"] == kernels["core"])
    out = cli("-v", "check", INCLINED)
    assert out.returncode == 0, out.stderr
    chosen = "OPENBLAS_CORETYPE" in os.environ
    expected = f"running with OPENBLAS_CORETYPE={kernels['better']}"
    assert (expected in out.stderr) == bool(kernels["better"] and not chosen), out.stderr
