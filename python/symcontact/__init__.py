"""symcontact: frictional contact by interior point, from Python.

    import symcontact
    problem = symcontact.Problem("examples/inclined_2d/inclined_reference.toml")
    problem["contact.0.mu"] = 0.1            # any key of docs/input.md, checked as the file would be
    result = problem.run()                   # no output folder unless out_dir is given
    print(result.reaction("upper", "upper_top")[-1])   # R at the last load step

The reference is docs/python.md. Errors raise InputError (exit code 2 of the command line), SolveError (3)
or InternalError (4), all SymcontactError, with the command line's messages.
"""

import json
import os

import numpy as np

from . import _symcontact
from ._symcontact import InputError, InternalError, SolveError, SymcontactError

__all__ = ["Problem", "Result", "InputError", "SolveError", "InternalError", "SymcontactError", "__version__",
           "blas_kernels"]
__version__ = _symcontact.__version__


def blas_kernels():
    """{"core": the OpenBLAS kernel family this process runs, "better": the family the command line would
    restart with on this CPU, or ""}. OpenBLAS chooses when it is loaded: on a CPU newer than it knows
    (docs/performance.md, "Machine") set OPENBLAS_CORETYPE to "better" before Python starts."""
    return dict(_symcontact.blas_kernels())


class Problem:
    """A problem file (docs/input.md) as an editable TOML document.

    Problem(path) reads a file as `symcontact run` does; Problem.from_string(text, base_dir) reads TOML
    text whose mesh paths are relative to base_dir. Keys are paths as in the error messages,
    "contact[0].mu", or with dots only, "contact.0.mu". Every change is checked by the same reader as the
    file: a bad value raises InputError with the command line's message, and the problem keeps its
    previous value.
    """

    def __init__(self, path=None, *, _doc=None):
        if _doc is not None:
            self._doc = _doc
        elif path is None:
            raise TypeError("Problem(path): give a problem file, or use Problem.from_string(text, base_dir)")
        else:
            self._doc = _symcontact.Problem.from_file(os.fspath(path))

    @classmethod
    def from_string(cls, text, base_dir=".", name="<string>"):
        """A problem from TOML text; relative mesh paths are resolved against base_dir; `name` stands for
        the file in messages."""
        return cls(_doc=_symcontact.Problem.from_string(text, os.fspath(base_dir), name))

    def get(self, key, default=None):
        return self._doc.get(key) if key in self._doc else default

    def set(self, key, value):
        """Sets `key` (creating missing tables; an array index equal to the length appends)."""
        self._doc.set(key, value)

    def remove(self, key):
        self._doc.remove(key)

    def update(self, changes=None, **keys):
        """Several changes checked together (all or nothing): {key: value}, a value None removes the key.
        For changes only valid together, e.g. steps.load_factors and every `factors` array."""
        self._doc.update(dict(changes or {}, **keys))

    def __getitem__(self, key):
        return self._doc.get(key)

    def __setitem__(self, key, value):
        self._doc.set(key, value)

    def __delitem__(self, key):
        self._doc.remove(key)

    def __contains__(self, key):
        return key in self._doc

    def to_dict(self):
        return self._doc.to_dict()

    @property
    def toml(self):
        """The document as TOML text (keys sorted, comments dropped)."""
        return self._doc.toml

    @property
    def name(self):
        return self._doc.name

    @property
    def base_dir(self):
        return self._doc.base_dir

    @property
    def dimension(self):
        return self._doc.dimension

    @property
    def num_steps(self):
        return self._doc.num_steps

    def run(self, out_dir=None, progress=None, *, mesh_size=None, allow_large_mesh=False,
            allow_geo_commands=False, write_vtu=True, verbosity="quiet", threads=None, check=True):
        """Solves the problem and returns a Result.

        out_dir: None (default) writes nothing; a folder gets what `symcontact run --out` writes.
        progress: None, or progress(step, num_steps, message) after each load step (an exception it
          raises ends the run and propagates).
        mesh_size, allow_large_mesh, allow_geo_commands: as the command line's options.
        verbosity: "quiet", "normal", "verbose" or "debug" (the log on stderr).
        threads: BLAS threads of the factorisations, as the command line's --threads (default: 1, or
          OPENBLAS_NUM_THREADS when set; for a process-wide setting).
        check: a failed solve raises SolveError (its `result` holds the finished steps); False returns
          the Result with status "solve_failed".
        """
        raw = _symcontact.run(self._doc, None if out_dir is None else os.fspath(out_dir), progress,
                              0.0 if mesh_size is None else float(mesh_size), allow_large_mesh,
                              allow_geo_commands, write_vtu, verbosity, 0 if threads is None else int(threads))
        result = Result(raw)
        if check and result.status != "ok":
            error = SolveError(result.message)
            error.result = result
            raise error
        return result

    def __repr__(self):
        return f"symcontact.Problem({self.name!r})"


def _contact_table(raw):
    """A step's contact table: column name -> numpy array, in the CSV's column order."""
    table = {}
    for name in raw["columns"]:
        value = raw[name]
        table[name] = np.asarray(value) if isinstance(value, list) else value
    return table


class Result:
    """What a run produced (docs/python.md). Arrays are indexed by load step first (0 = step 1)."""

    def __init__(self, raw):
        self.status = raw["status"]            # "ok" or "solve_failed"
        self.message = raw["message"]
        self.steps_done = raw["steps_done"]
        self.summary = json.loads(raw["summary"])  # what summary.json holds
        self.bodies = [b["name"] for b in raw["bodies"]]
        self.nodes = {b["name"]: b["nodes"] for b in raw["bodies"]}
        self.displacement = {b["name"]: b["displacement"] for b in raw["bodies"]}
        self.stress = {b["name"]: b["stress"] for b in raw["bodies"]}
        self.von_mises = {b["name"]: b["von_mises"] for b in raw["bodies"]}
        self.contact = {p["name"]: [_contact_table(t) for t in p["steps"]] for p in raw["contact"]}

    @property
    def ok(self):
        return self.status == "ok"

    @property
    def steps(self):
        """summary.json's "steps": one dict per finished load step."""
        return self.summary["steps"]

    @property
    def load_factors(self):
        return np.array([s["load_factor"] for s in self.steps])

    @property
    def reactions(self):
        """Per Dirichlet condition, in the order of summary.json: (body, boundary, forces steps × dim)."""
        count = len(self.steps[0]["reactions"]) if self.steps else 0
        return [(self.steps[0]["reactions"][k]["body"], self.steps[0]["reactions"][k]["boundary"],
                 np.array([s["reactions"][k]["force"] for s in self.steps])) for k in range(count)]

    def reaction(self, body, boundary):
        """The reaction on a boundary per step (steps × dim): the sum over the Dirichlet conditions on it
        (each holds its own components)."""
        found = [f for b, g, f in self.reactions if b == body and g == boundary]
        if not found:
            raise KeyError(f"no Dirichlet condition on {body}.{boundary}")
        return sum(found)

    @property
    def iterations(self):
        """Iteration counts per step: name -> array (ipopt_iterations, geometry_iterations,
        coulomb_iterations, step_cuts with contact; newton_iterations without)."""
        names = ("ipopt_iterations", "geometry_iterations", "coulomb_iterations", "step_cuts", "newton_iterations")
        return {n: np.array([s[n] for s in self.steps], dtype=int) for n in names if self.steps and n in self.steps[0]}

    @property
    def timings(self):
        """Seconds per phase of the whole run (summary.json "timings") and "wall_time"."""
        return dict(self.summary["timings"], wall_time=self.summary["wall_time"])

    def __repr__(self):
        return f"<symcontact.Result {self.status}, {self.steps_done} steps, bodies {self.bodies}>"
