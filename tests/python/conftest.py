"""Shared fixtures of the Python module's tests (registered with CTest by tests/CMakeLists.txt, which sets
PYTHONPATH to <build>/python and SYMCONTACT_CLI to the command-line program)."""

import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


@pytest.fixture(scope="module")  # one pytest process per test file (CTest)
def cli():
    """Runs the command-line program: cli("run", file, "--out", dir, env={...}) -> CompletedProcess."""
    path = os.environ.get("SYMCONTACT_CLI")
    if not path:
        pytest.fail("SYMCONTACT_CLI is not set (CTest sets it: ctest --test-dir build -L python)")

    def run(*args, env=None):
        """env: variables added to this process's environment for the run."""
        return subprocess.run([path, *map(str, args)], capture_output=True, text=True,
                              env=None if env is None else dict(os.environ, **env))

    return run


def ink(png):
    """The fraction of a picture's pixels that are not the white background (0: an empty picture)."""
    import matplotlib.image

    pixels = matplotlib.image.imread(str(png))[..., :3]
    return float((pixels.min(axis=-1) < 0.9).mean())


def run_python(script, *args, cwd=None):
    """Runs a Python script of the repository with this interpreter and the module of this build."""
    import sys

    return subprocess.run([sys.executable, str(script), *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, env=dict(os.environ, MPLBACKEND="Agg"))
