"""Shared fixtures of the Python module's tests (registered with CTest by tests/CMakeLists.txt, which sets
PYTHONPATH to <build>/python and SYMCONTACT_CLI to the command-line program)."""

import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


@pytest.fixture(scope="session")
def cli():
    """Runs the command-line program: cli("run", file, "--out", dir) -> CompletedProcess."""
    path = os.environ.get("SYMCONTACT_CLI")
    if not path:
        pytest.fail("SYMCONTACT_CLI is not set (CTest sets it: ctest --test-dir build -L python)")

    def run(*args):
        return subprocess.run([path, *map(str, args)], capture_output=True, text=True)

    return run
