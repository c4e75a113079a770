#include "symcontact/app/run.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "symcontact/core/error.hpp"
#include "symcontact/core/progress_clock.hpp"
#include "symcontact/core/interrupt.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/io/atomic_file.hpp"
#include "symcontact/io/json_writer.hpp"
#include "symcontact/io/pvd_writer.hpp"
#include "symcontact/io/vtu_writer.hpp"
#include "symcontact/mesh/hilbert_curve.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/model/setup_checks.hpp"
#include "symcontact/post/contact_results.hpp"
#include "symcontact/post/contact_table.hpp"
#include "symcontact/post/step_checks.hpp"
#include "symcontact/post/stress_recovery.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"

namespace symcontact {

namespace {

const char* model_name(AnalysisModel m) {
  switch (m) {
    case AnalysisModel::kPlaneStrain: return "plane_strain";
    case AnalysisModel::kPlaneStress: return "plane_stress";
    case AnalysisModel::kAxisymmetric: return "axisymmetric";
    case AnalysisModel::kThreeD: return "3d";
  }
  return "";
}

/// What the forces of the outputs (reactions, loads, contact forces) are: per unit thickness of a plane
/// section, for the whole ring of an axisymmetric one (2π r in every integral), or the 3D body's own.
const char* force_basis(AnalysisModel m) {
  switch (m) {
    case AnalysisModel::kPlaneStrain:
    case AnalysisModel::kPlaneStress: return "per_unit_thickness";
    case AnalysisModel::kAxisymmetric: return "whole_ring";
    case AnalysisModel::kThreeD: return "total";
  }
  return "";
}

Json timings_json(const PhaseTimes& t) {
  Json j = Json::object();
  for (const auto& [phase, s] : t.entries()) j[phase] = s;
  return j;
}

std::vector<double> to_vector(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

std::string step_file(const std::string& body, int step, const char* ext = "vtu") {
  char buf[48];
  std::snprintf(buf, sizeof buf, "_%04d.%s", step, ext);
  return body + buf;
}

/// Writes `table` as CSV (contact_table.hpp gives the columns): numbers with 17 significant digits, NaN as
/// "nan" (numpy reads it).
void write_contact_csv(const ContactTable& table, const std::string& path) {
  write_file_atomically(path, [&](std::ostream& os) {
    os << "side,surface,node";
    for (const std::string& name : table.numeric_names) os << ',' << name;
    os << ",status\n";
    os.precision(17);
    for (Index row = 0; row < table.rows(); ++row) {
      os << table.side[row] << ',' << table.surface[row] << ',' << table.node[row];
      for (Index c = 0; c < table.numeric.cols(); ++c) {
        const double v = table.numeric(row, c);
        os << ',';
        if (std::isnan(v))
          os << "nan";
        else
          os << v;
      }
      os << ',' << table.status[row] << '\n';
    }
  });
}

/// Contact fields of one body at its nodes, summed over the pairs (zero away from contact surfaces; status −1 there,
/// else the largest over the pairs).
struct BodyContactFields {
  Eigen::VectorXd pressure, gap, status;
  Eigen::MatrixXd force;       ///< 3 × n
  Eigen::MatrixXd tangential;  ///< 3 × n tangential traction
  Eigen::MatrixXd slip;        ///< 3 × n slip increment of the step (friction side; 0 elsewhere)
  Eigen::VectorXd accumulated; ///< accumulated slip (friction side)
};

BodyContactFields body_contact_fields(const Model& model, int b, const std::vector<ContactPairResult>& results,
                                      const std::vector<std::vector<Eigen::VectorXd>>& accumulated) {
  const Index n = model.bodies()[b]->mesh.num_nodes();
  BodyContactFields f{Eigen::VectorXd::Zero(n),    Eigen::VectorXd::Zero(n),    Eigen::VectorXd::Constant(n, -1.0),
                      Eigen::MatrixXd::Zero(3, n), Eigen::MatrixXd::Zero(3, n), Eigen::MatrixXd::Zero(3, n),
                      Eigen::VectorXd::Zero(n)};
  for (std::size_t pi = 0; pi < results.size(); ++pi)
    for (std::size_t side_index = 0; side_index < results[pi].sides.size(); ++side_index) {
      const auto& side = results[pi].sides[side_index];
      const ContactSurface& s = model.contacts().surfaces[side.surface];
      if (s.body != b) continue;
      for (Index k = 0; k < s.num_nodes(); ++k) {
        const Index v = s.nodes[k];
        f.pressure[v] += side.pressure[k];  // each pair reports its own force: a node's pressure is their sum
        f.gap[v] = std::isfinite(side.gap[k]) ? side.gap[k] : 0.0;
        f.status[v] = std::max(f.status[v], static_cast<double>(side.status[k]));
        f.force.col(v).head(s.dim) += side.force.col(k);
        f.tangential.col(v).head(s.dim) += side.tangential.col(k);
        if (side.slip.col(k).allFinite()) f.slip.col(v).head(s.dim) = side.slip.col(k);
        if (pi < accumulated.size() && side_index < accumulated[pi].size() && k < accumulated[pi][side_index].size())
          f.accumulated[v] = std::max(f.accumulated[v], accumulated[pi][side_index][k]);
      }
    }
  return f;
}

BodyFields body_fields(const Body& body, const DofMap& dofs, int b, const VectorXd& u) {
  return recover_fields(body, dofs, b, u);
}

/// The name of the first field of `f` holding a NaN or an infinity, or "" when all are finite.
std::string first_non_finite(const BodyFields& f) {
  const std::pair<const char*, const Eigen::MatrixXd*> matrices[] = {
      {"displacement", &f.displacement}, {"strain", &f.strain}, {"stress", &f.stress}, {"stress", &f.cell_stress}};
  for (const auto& [name, m] : matrices)
    if (!m->allFinite()) return name;
  const std::pair<const char*, const Eigen::VectorXd*> vectors[] = {{"von_mises", &f.von_mises},
                                                                    {"von_mises", &f.cell_von_mises},
                                                                    {"J", &f.volume_ratio},
                                                                    {"J", &f.cell_volume_ratio}};
  for (const auto& [name, v] : vectors)
    if (!v->allFinite()) return name;
  return "";
}

/// The VTU of one body: its fields, and the contact fields when `contact` is given.
VtuWriter body_vtu(const Body& body, const BodyFields& f, const BodyContactFields* contact = nullptr) {
  VtuWriter w(body.mesh);
  if (contact) {
    w.add_point_data("contact_pressure", contact->pressure);
    w.add_point_data("contact_gap", contact->gap);
    w.add_point_data("contact_status", contact->status);
    w.add_point_data("contact_force", contact->force);
    w.add_point_data("contact_tangential_traction", contact->tangential);
    w.add_point_data("slip_increment", contact->slip);
    w.add_point_data("accumulated_slip", contact->accumulated);
  }
  w.add_point_data("displacement", f.displacement);
  w.add_point_data("strain", f.strain, {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
  w.add_point_data("stress", f.stress, {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
  w.add_point_data("von_mises", f.von_mises);
  w.add_cell_data("stress", f.cell_stress, {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
  w.add_cell_data("von_mises", f.cell_von_mises);
  w.add_point_data("J", f.volume_ratio);
  w.add_cell_data("J", f.cell_volume_ratio);
  return w;
}

/// Process `parallel.rank`'s piece of `w` (the file `stem`.vtu of a serial run): of the n cells ordered along a
/// Hilbert curve through their centres (mesh/hilbert_curve.hpp), the run [n r / P, n (r + 1) / P) (P the
/// processes), in the body's order — a compact region, whose border points alone repeat in the next piece — with
/// the point data "node" (the body's node number of each of its points) and the cell data "cell" (the body's
/// cell number of each of its cells), written as `stem`_p<r>.vtu; then the first process writes `stem`.pvtu
/// naming every piece, once all are written. Returns the .pvtu's name. Collective; a process that cannot write
/// its piece makes every one throw.
std::string write_parallel_vtu(const VtuWriter& w, const std::string& stem, const std::string& out_dir,
                               const ParallelOutput& parallel) {
  namespace fs = std::filesystem;
  const auto piece_name = [&](int rank) { return stem + "_p" + std::to_string(rank) + ".vtu"; };
  const Index n = w.num_cells();
  const std::vector<Index> order = hilbert_order(w.cell_centres());
  std::vector<Index> cells(order.begin() + n * parallel.rank / parallel.size,
                           order.begin() + n * (parallel.rank + 1) / parallel.size);
  std::sort(cells.begin(), cells.end());
  std::vector<Index> used;
  VtuWriter piece = w.piece(cells, used);
  const auto as_data = [](const std::vector<Index>& v) {
    using Indices = Eigen::Matrix<Index, Eigen::Dynamic, 1>;
    return Eigen::Map<const Indices>(v.data(), static_cast<Index>(v.size())).cast<double>().eval();
  };
  piece.add_point_data("node", as_data(used));
  piece.add_cell_data("cell", as_data(cells));
  std::string error;
  try {
    ensure_directory(out_dir);  // the first process makes it before the first step; this one may be earlier
    piece.write((fs::path(out_dir) / piece_name(parallel.rank)).string());
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!parallel.all_ranks(error.empty()))
    throw std::runtime_error(error.empty() ? "another process could not write its piece of " + stem + ".pvtu" : error);
  std::vector<std::string> pieces;
  for (int r = 0; r < parallel.size; ++r) pieces.push_back(piece_name(r));
  if (parallel.rank == 0) piece.write_parallel((fs::path(out_dir) / (stem + ".pvtu")).string(), pieces);
  return stem + ".pvtu";
}

/// The "contact" entry of a step in summary.json, one object per pair, each pair's contact table in `tables`
/// and, with OutputFiles::kWrite, its CSV in the output folder; adds the step's slip to `accumulated_slip`
/// (per pair, per side: Σ over steps of |slip increment| at each node).
Json contact_step_json(const Model& model, const std::vector<ContactPairResult>& cres, int step,
                       const RunOptions& options, std::vector<std::vector<Eigen::VectorXd>>& accumulated_slip,
                       std::vector<ContactTable>& tables) {
  Json pairs = Json::array();
  tables.clear();
  accumulated_slip.resize(cres.size());
  for (std::size_t pi = 0; pi < cres.size(); ++pi) {
    const auto& r = cres[pi];
    // Accumulated slip: Σ over steps of |slip increment| at each node.
    accumulated_slip[pi].resize(r.sides.size());
    for (std::size_t side = 0; side < r.sides.size(); ++side) {
      auto& acc = accumulated_slip[pi][side];
      if (acc.size() == 0) acc = Eigen::VectorXd::Zero(r.sides[side].slip.cols());
      for (Index k = 0; k < acc.size(); ++k) {
        const double sk = r.sides[side].slip.col(k).norm();
        if (std::isfinite(sk)) acc[k] += sk;
      }
    }
    Json jp = Json::object();
    jp["name"] = r.name;
    jp["total_force"] = to_vector(r.total_force);
    jp["normal_force"] = to_vector(r.normal_force);
    jp["tangential_force"] = to_vector(r.tangential_force);
    jp["normal_load"] = r.normal_load;
    jp["max_pressure"] = r.max_pressure;
    jp[model.dim() == 2 ? "contact_length" : "contact_area"] = r.contact_measure;
    const std::string csv = "contact_" + step_file(r.name, step + 1, "csv");
    tables.push_back(contact_table(model.contacts().surfaces, model.dim(), r, accumulated_slip[pi]));
    if (options.files == OutputFiles::kWrite)
      write_contact_csv(tables.back(), (std::filesystem::path(options.out_dir) / csv).string());
    jp["csv"] = csv;  // named also when not written, so that the summary is the same either way
    pairs.push_back(jp);
  }
  return pairs;
}

/// The solver statistics of a step in summary.json: the contact solve's (`contact` not null) or Newton's.
void add_solver_statistics(Json& js, const SolveReport* contact, const EquilibriumReport& newton) {
  if (!contact) {
    js["newton_iterations"] = newton.iterations;
    js["residual"] = newton.residual;
    js["num_free_dofs"] = static_cast<double>(newton.num_free);
    return;
  }
  const SolveReport& r = *contact;
  js["geometry_iterations"] = r.geometry_iterations;
  js["ipopt_iterations"] = r.ipopt_iterations;
  js["coulomb_iterations"] = r.coulomb_iterations;
  js["step_cuts"] = r.cuts;
  js["substeps"] = r.substeps;  // end fraction of each converged sub-step ([1]: solved whole)
  js["coulomb_change_history"] = r.coulomb_change;
  js["coulomb_relaxation_history"] = r.coulomb_relaxation;
  // 0: converged to coulomb_tolerance; else the change a stagnated fixed point was accepted at.
  js["coulomb_accepted_at_noise_floor"] = r.accepted_at_noise_floor;
  js["last_solve_ipopt_iterations_per_geometry_iteration"] =
      std::vector<double>(r.ipopt_per_iteration.begin(), r.ipopt_per_iteration.end());
  js["last_solve_geometry_change_history"] = r.change_history;
  js["ipopt_status"] = r.ipopt_status;
  js["num_constraints"] = static_cast<double>(r.num_constraints);
  js["num_free_dofs"] = static_cast<double>(r.num_free);
}

/// The progress line's account of a step: the contact solve's iterations (`contact` not null) or Newton's.
/// The step warning of a Coulomb fixed point accepted at the noise floor of its inner solves (`change`: the
/// relative change of the thresholds it was accepted at; lagged_fixed_point.hpp).
std::string noise_floor_warning(double change) {
  std::ostringstream m;
  m << "the Coulomb fixed point was accepted at the noise floor of its inner solves: the friction law holds to "
    << change << " of the thresholds' size (above contact_solver.coulomb_tolerance)";
  return m.str();
}

std::string progress_text(const SolveReport* contact, const EquilibriumReport& newton) {
  std::ostringstream s;
  if (contact)
    s << "geometry iterations " << contact->geometry_iterations << ", optimizer iterations " << contact->ipopt_iterations
      << (contact->coulomb_iterations ? ", Coulomb iterations " + std::to_string(contact->coulomb_iterations)
                                      : std::string())
      << (contact->cuts ? ", " + std::to_string(contact->substeps.size()) + " sub-steps" : std::string());
  else
    s << "iterations " << newton.iterations << ", residual " << newton.residual;
  return s.str();
}

/// The reactions of summary.json: ∇E(u) at the Dirichlet boundaries' nodes, per boundary.
Json reactions_json(const Model& model, const FixedDofs& fixed, const VectorXd& u) {
  VectorXd g = VectorXd::Zero(model.dofs().num_dofs());
  model.energy().add_gradient(u, g);
  Json reactions = Json::array();
  const std::vector<Eigen::VectorXd> r = model.reactions(fixed, g);
  for (std::size_t k = 0; k < r.size(); ++k) {
    const auto& db = model.dirichlet_boundaries()[k];
    Json jr = Json::object();
    jr["body"] = model.bodies()[db.body]->name;
    jr["boundary"] = db.name;
    jr["force"] = to_vector(r[k]);
    reactions.push_back(jr);
  }
  return reactions;
}

/// summary.json before the first step: the problem, its sizes, "status": "running" and no steps yet.
Json summary_header(const ProblemSpec& spec, const Model& model) {
  const DofMap& dofs = model.dofs();
  Json summary = Json::object();
  summary["symcontact_version"] = SYMCONTACT_VERSION;
  summary["problem"] = spec.file;
  summary["title"] = spec.title;
  summary["status"] = "running";
  summary["dimension"] = spec.dim;
  summary["model"] = model_name(spec.model);
  summary["forces"] = force_basis(spec.model);
  summary["order"] = spec.order;
  summary["num_dofs"] = static_cast<double>(dofs.num_dofs());
  Json bodies = Json::array();
  for (int b = 0; b < dofs.num_bodies(); ++b) {
    const Body& body = *model.bodies()[b];
    Json jb = Json::object();
    jb["name"] = body.name;
    jb["cell_type"] = body.mesh.cell_types_label();
    jb["num_nodes"] = static_cast<double>(body.mesh.num_nodes());
    jb["num_cells"] = static_cast<double>(body.mesh.num_cells());
    jb["num_dofs"] = static_cast<double>(dofs.num_body_dofs(b));
    bodies.push_back(jb);
  }
  summary["bodies"] = bodies;
  summary["warnings"] = Json::array();  // of the input (Model::warnings); each step has its own
  for (const std::string& w : model.warnings()) summary["warnings"].push_back(w);
  summary["steps"] = Json::array();
  return summary;
}

/// The last iterate of a failed step, one VTU per body whose fields are finite (not part of the collection);
/// returns the names written.
Json write_failed_iterates(const Model& model, const VectorXd& u, int step, const std::string& out_dir) {
  Json failed = Json::array();
  for (int b = 0; b < model.dofs().num_bodies(); ++b) {
    const Body& body = *model.bodies()[b];
    const BodyFields f = body_fields(body, model.dofs(), b, u);
    if (!first_non_finite(f).empty()) continue;
    const std::string name = body.name + "_failed_step" + std::to_string(step + 1) + ".vtu";
    body_vtu(body, f).write((std::filesystem::path(out_dir) / name).string());
    failed.push_back(name);
  }
  return failed;
}

/// One VTU per body for load step `step` (0-based), with the contact fields when `contact` is given, or on several
/// processes its piece and the .pvtu (write_parallel_vtu); added to the collection, written anew, where `collection`.
void write_step_vtu(const Model& model, const std::vector<BodyFields>& fields,
                    const std::vector<ContactPairResult>* contact,
                    const std::vector<std::vector<Eigen::VectorXd>>& accumulated_slip, int step,
                    const RunOptions& options, bool collection, PvdCollection& pvd) {
  for (int b = 0; b < model.dofs().num_bodies(); ++b) {
    const Body& body = *model.bodies()[b];
    const BodyContactFields cf = contact ? body_contact_fields(model, b, *contact, accumulated_slip) : BodyContactFields{};
    const VtuWriter w = body_vtu(body, fields[b], contact ? &cf : nullptr);
    std::string name = step_file(body.name, step + 1);
    if (options.parallel.size > 1)
      name = write_parallel_vtu(w, name.substr(0, name.size() - 4), options.out_dir, options.parallel);
    else
      w.write((std::filesystem::path(options.out_dir) / name).string());
    if (collection) pvd.add(step + 1, b, name, body.name);
  }
  if (collection) pvd.write();
}

}  // namespace

SummaryOnError::~SummaryOnError() {
  if (std::uncaught_exceptions() <= uncaught_) return;
  try {
    summary_["status"] = "internal_error";
    summary_["message"] = "an internal error stopped the run during load step " + std::to_string(steps_done_ + 1) +
                          " (the program's message names it)";
    write_();
  } catch (...) {
  }
}

RunResult run_problem(const ProblemSpec& spec, const RunOptions& options, const Logger& log,
                      const StepSolver& solve_step) {
  namespace fs = std::filesystem;
  PhaseTimes times;
  const double t_start = wall_seconds();
  // Everything that can fail on input happens here, before the output folder is touched.
  std::unique_ptr<Model> model = Model::build(spec, log, times, options.meshing);
  check_setup(*model);
  const DofMap& dofs = model->dofs();
  if (options.on_model) options.on_model(*model);

  const bool write_files = options.files == OutputFiles::kWrite;
  if (write_files) {
    ensure_directory(options.out_dir);
    const int stale = remove_stale_temporaries(options.out_dir);
    if (stale > 0) log.detail("removed " + std::to_string(stale) + " temporary files left by an earlier run");
  }
  if (options.signals == SignalHandling::kStopCleanly) install_interrupt_handlers();
  const std::string summary_path = (fs::path(options.out_dir) / "summary.json").string();
  PvdCollection pvd((fs::path(options.out_dir) / "results.pvd").string());
  const bool vtu = (write_files || options.parallel.size > 1) && options.write_vtu && spec.output.vtu;

  RunResult result;
  Json summary = summary_header(spec, *model);
  auto write_summary = [&]() {
    summary["timings"] = timings_json(times);
    summary["wall_time"] = wall_seconds() - t_start;
    result.summary = summary;
    if (write_files && spec.output.summary)
      write_file_atomically(summary_path, [&](std::ostream& os) { os << summary.dump(2) << '\n'; });
  };
  write_summary();

  const SummaryOnError on_error(summary, write_summary, result.steps_done);
  VectorXd u = VectorXd::Zero(dofs.num_dofs());
  std::vector<std::vector<Eigen::VectorXd>> accumulated_slip;  ///< per pair, per side
  const int nsteps = model->num_steps();
  FrictionState previous_friction;  ///< the thresholds the last step converged to (Coulomb warm start)
  // Ends the run at `step` (0-based) without its results: summary.json gets `status` and `message`; the
  // last iterate is written for inspection (not part of the collection) when it is finite.
  auto stop_run = [&](int step, RunStatus status, const std::string& message) {
    result.status = status;
    result.message = message;
    result.signal = status == RunStatus::kInterrupted ? interrupt_signal() : 0;
    summary["status"] = status == RunStatus::kInterrupted ? "interrupted" : "solve_failed";
    summary["message"] = message;
    if (status == RunStatus::kSolveFailed && write_files)
      summary["failed_iterate_files"] = write_failed_iterates(*model, u, step, options.out_dir);
    write_summary();
    return result;
  };
  auto interrupted_message = [](int step) {
    return std::string("interrupted by ") + (interrupt_signal() == SIGINT ? "SIGINT" : "SIGTERM") + " before load step " +
           std::to_string(step + 1) + " finished";
  };
  const ProgressClock clock;  // elapsed and time left on the progress lines of long runs
  for (int step = 0; step < nsteps; ++step) {
    if (interrupt_requested()) return stop_run(step, RunStatus::kInterrupted, interrupted_message(step));
    PhaseTimes st;
    model->set_step(step);
    const FixedDofs fixed = model->fixed_dofs(step);
    const bool has_contact = !model->contacts().empty();
    EquilibriumReport rep;
    SolveReport lrep;
    StepCheckFigures checks;
    try {
      if (has_contact)
        lrep = solve_step(*model, step, u, previous_friction);
      else
        rep = solve_equilibrium(model->energy(), fixed, u);
      checks = check_step(*model, u, fixed, has_contact ? &lrep : nullptr);
    } catch (const SolveError& e) {
      // A signal stops IPOPT (interrupt.hpp), which the solver reports as a failure.
      if (interrupt_requested()) return stop_run(step, RunStatus::kInterrupted, interrupted_message(step));
      return stop_run(step, RunStatus::kSolveFailed, "load step " + std::to_string(step + 1) + ": " + e.what());
    }
    // Overflow (a tiny E, a huge load) gives infinities that no file format holds: a failed solve.
    std::vector<BodyFields> fields;
    for (int b = 0; b < dofs.num_bodies(); ++b) {
      fields.push_back(body_fields(*model->bodies()[b], dofs, b, u));
      const std::string bad = first_non_finite(fields.back());
      if (!bad.empty())
        return stop_run(step, RunStatus::kSolveFailed,
                        "the solve produced non-finite values in body '" + model->bodies()[b]->name + "' at step " +
                            std::to_string(step + 1) + " (" + bad +
                            "): the loads, the material constants or their units are out of range");
    }
    Json js = Json::object();
    js["step"] = step + 1;
    js["load_factor"] = spec.load_factors[step];
    js["equilibrium_residual"] = checks.equilibrium;  // post/step_checks.hpp
    js["max_penetration_ratio"] = checks.penetration;
    js["warnings"] = Json::array();
    for (const std::string& w : checks.warnings) {
      log.warning("load step " + std::to_string(step + 1) + ": " + w);
      js["warnings"].push_back(w);
    }
    if (has_contact && lrep.accepted_at_noise_floor > 0.0)  // logged by the loop (lagged_fixed_point.hpp)
      js["warnings"].push_back(noise_floor_warning(lrep.accepted_at_noise_floor));
    st.merge(has_contact ? lrep.times : rep.times);
    add_solver_statistics(js, has_contact ? &lrep : nullptr, rep);
    std::vector<ContactPairResult> cres;
    std::vector<ContactTable> tables;
    if (has_contact) {
      ScopedPhase t(st, "output");
      cres = contact_results(model->contacts(), dofs, u, lrep);
      js["contact"] = contact_step_json(*model, cres, step, options, accumulated_slip, tables);
    }
    js["reactions"] = reactions_json(*model, fixed, u);
    const VectorXd f = model->external_load();
    Eigen::VectorXd applied = Eigen::VectorXd::Zero(spec.dim);
    for (Index d = 0; d < f.size(); ++d) applied[d % spec.dim] += f[d];
    js["applied_load"] = to_vector(applied);
    if (vtu) {
      ScopedPhase t(st, "output");
      write_step_vtu(*model, fields, has_contact ? &cres : nullptr, accumulated_slip, step, options, write_files, pvd);
    }
    js["timings"] = timings_json(st);
    times.merge(st);
    summary["steps"].push_back(js);
    result.steps_done = step + 1;
    write_summary();
    const std::string text = progress_text(has_contact ? &lrep : nullptr, rep);
    if (options.on_step) options.on_step(StepRecord{step + 1, nsteps, *model, js, fields, tables, text});
    log.progress("load step", step + 1, nsteps, text + clock.suffix(step + 1, nsteps));
  }
  summary["status"] = "ok";
  write_summary();
  return result;
}

}  // namespace symcontact
