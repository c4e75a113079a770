#pragma once
/// \file study_run.hpp
/// Runs a problem for the Python module: run_problem() (app/run.hpp) with the GIL released, its step
/// reports gathered into arrays, and the progress callback called with the GIL held.

#include <string>

#include <pybind11/pybind11.h>

#include "problem.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/app/run.hpp"

namespace symcontact::python {

struct StudyOptions {
  std::string out_dir;                      ///< with OutputFiles::kWrite
  OutputFiles files = OutputFiles::kNone;
  MeshingOverrides meshing;
  bool write_vtu = true;
  Verbosity verbosity = Verbosity::kQuiet;  ///< of the log on stderr
  pybind11::object progress;                ///< None, or called as progress(step, num_steps, message)
};

/// The raw results, a dict (python/symcontact/__init__.py wraps it in a Result):
///   status ("ok" | "solve_failed"), message, steps_done, summary (summary.json's text),
///   bodies: [{name, nodes (n × dim), displacement (steps × n × dim), stress (steps × n × 6: XX YY ZZ
///   XY YZ XZ), von_mises (steps × n)}],
///   contact: [{name, steps: [{columns: [names in CSV order], side, surface, status (lists of str),
///   node (int array), <numeric column>: float array, ...}]}].
/// Input errors raise InputError before any folder is created; an exception of the progress callback, or
/// a KeyboardInterrupt from Ctrl-C (checked after each load step), ends the run and propagates.
pybind11::dict run_study(const Problem& problem, const StudyOptions& options);

}  // namespace symcontact::python
