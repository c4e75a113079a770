#include "study_run.hpp"

#include <iostream>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "symcontact/app/linear_solver_choice.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/io/output_folder.hpp"

namespace py = pybind11;

namespace symcontact::python {

namespace {

/// What the step reports hold, per body (per step) and per pair (per step).
struct Gathered {
  int dim = 2;
  std::vector<std::string> body_names;
  std::vector<Eigen::MatrixXd> nodes;                       ///< dim × n
  std::vector<std::vector<Eigen::MatrixXd>> displacement;   ///< [body][step] dim × n
  std::vector<std::vector<Eigen::MatrixXd>> stress;         ///< [body][step] 6 × n
  std::vector<std::vector<Eigen::VectorXd>> von_mises;      ///< [body][step] n
  std::vector<std::vector<ContactTable>> tables;            ///< [pair][step]
  std::vector<std::string> pair_names;

  void start(const Model& model) {
    dim = model.dim();
    for (const auto& b : model.bodies()) {
      body_names.push_back(b->name);
      nodes.push_back(b->mesh.x);
    }
    displacement.resize(body_names.size());
    stress.resize(body_names.size());
    von_mises.resize(body_names.size());
    tables.resize(model.contacts().pairs.size());
    for (std::size_t p = 0; p < tables.size(); ++p) pair_names.push_back(model.contacts().pairs[p].name);
  }

  void add(const StepRecord& r) {
    const auto& bodies = r.model.bodies();
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      displacement[b].push_back(r.fields[b].displacement.topRows(dim));
      stress[b].push_back(r.fields[b].stress);
      von_mises[b].push_back(r.fields[b].von_mises);
    }
    for (std::size_t p = 0; p < r.contact.size(); ++p) tables[p].push_back(r.contact[p]);
  }
};

/// Matrices rows × n of each step (column-major: node-major) as an array steps × n × rows.
py::array_t<double> stack(const std::vector<Eigen::MatrixXd>& steps, Index rows, Index n) {
  py::array_t<double> a({static_cast<py::ssize_t>(steps.size()), static_cast<py::ssize_t>(n),
                         static_cast<py::ssize_t>(rows)});
  double* out = a.mutable_data();
  for (const Eigen::MatrixXd& m : steps) out = std::copy(m.data(), m.data() + m.size(), out);
  return a;
}

py::array_t<double> stack(const std::vector<Eigen::VectorXd>& steps, Index n) {
  py::array_t<double> a({static_cast<py::ssize_t>(steps.size()), static_cast<py::ssize_t>(n)});
  double* out = a.mutable_data();
  for (const Eigen::VectorXd& v : steps) out = std::copy(v.data(), v.data() + v.size(), out);
  return a;
}

py::dict table_dict(const ContactTable& t) {
  py::dict d;
  py::list columns;
  columns.append("side");
  columns.append("surface");
  columns.append("node");
  for (const std::string& name : t.numeric_names) columns.append(name);
  columns.append("status");
  d["columns"] = columns;
  d["side"] = py::cast(t.side);
  d["surface"] = py::cast(t.surface);
  d["node"] = py::array_t<std::int64_t>(static_cast<py::ssize_t>(t.node.size()), t.node.data());
  for (std::size_t c = 0; c < t.numeric_names.size(); ++c) {
    py::array_t<double> col(static_cast<py::ssize_t>(t.rows()));
    for (Index r = 0; r < t.rows(); ++r) col.mutable_at(r) = t.numeric(r, static_cast<Index>(c));
    d[py::str(t.numeric_names[c])] = col;
  }
  d["status"] = py::cast(t.status);
  return d;
}

py::dict results_dict(const Gathered& g, const RunResult& r) {
  py::dict out;
  out["status"] = r.status == RunStatus::kOk ? "ok" : (r.status == RunStatus::kSolveFailed ? "solve_failed" : "interrupted");
  out["message"] = r.message;
  out["steps_done"] = r.steps_done;
  out["summary"] = r.summary.dump(-1);
  py::list bodies;
  for (std::size_t b = 0; b < g.body_names.size(); ++b) {
    const Index n = g.nodes[b].cols();
    py::dict body;
    body["name"] = g.body_names[b];
    body["nodes"] = stack({g.nodes[b]}, g.nodes[b].rows(), n)[py::int_(0)];
    body["displacement"] = stack(g.displacement[b], g.dim, n);
    body["stress"] = stack(g.stress[b], 6, n);
    body["von_mises"] = stack(g.von_mises[b], n);
    bodies.append(body);
  }
  out["bodies"] = bodies;
  py::list pairs;
  for (std::size_t p = 0; p < g.tables.size(); ++p) {
    py::dict pair;
    pair["name"] = g.pair_names[p];
    py::list ts;
    for (const ContactTable& t : g.tables[p]) ts.append(table_dict(t));
    pair["steps"] = ts;
    pairs.append(pair);
  }
  out["contact"] = pairs;
  return out;
}

}  // namespace

py::dict run_study(const Problem& problem, const StudyOptions& options) {
  RunOptions opt;
  opt.files = options.files;
  opt.out_dir = options.out_dir;
  opt.meshing = options.meshing;
  opt.write_vtu = options.write_vtu;
  opt.signals = SignalHandling::kDefault;  // Python keeps its own handlers
  if (opt.files == OutputFiles::kWrite) {
    if (const std::string why = output_folder_problem(opt.out_dir); !why.empty())
      throw InputError("", "out_dir", "the output folder '" + opt.out_dir + "' " + why);
  }
  if (problem.spec().linear_solver == LinearSolverChoice::kIterative)
    throw InputError(problem.spec().file, "contact_solver.linear_solver",
                     "the Python module runs the serial (direct) solver; \"iterative\" is for `symcontact run` "
                     "and `mpirun symcontact run` (docs/distributed.md)");
  Gathered gathered;
  const py::object progress = options.progress;
  const Logger log(std::cerr, options.verbosity);
  opt.on_model = [&](const Model& model) {
    const LinearSolverDecision d = serial_only_choice(problem.spec(), model);  // InputError: it cannot
    if (d.basis == DecisionBasis::kDenseWork)
      log.info(d.reason);
    else
      log.detail(d.reason);
    gathered.start(model);
  };
  opt.on_step = [&](const StepRecord& r) {
    gathered.add(r);
    py::gil_scoped_acquire gil;
    // Ctrl-C (SIGINT: Python's handler only sets a flag while the solve runs) ends the run after the step.
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (!progress.is_none()) progress(r.step, r.num_steps, r.progress);
  };
  RunResult result;
  {
    py::gil_scoped_release release;
    result = run_problem(problem.spec(), opt, log);
  }
  return results_dict(gathered, result);
}

}  // namespace symcontact::python
