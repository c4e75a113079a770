#include "symcontact/app/run.hpp"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "symcontact/core/error.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/io/atomic_file.hpp"
#include "symcontact/io/json_writer.hpp"
#include "symcontact/io/pvd_writer.hpp"
#include "symcontact/io/vtu_writer.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/post/stress_recovery.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"

namespace symcontact {

namespace {

const char* model_name(AnalysisModel m) {
  switch (m) {
    case AnalysisModel::kPlaneStrain: return "plane_strain";
    case AnalysisModel::kPlaneStress: return "plane_stress";
    case AnalysisModel::kThreeD: return "3d";
  }
  return "";
}

Json timings_json(const PhaseTimes& t) {
  Json j = Json::object();
  for (const auto& [phase, s] : t.entries()) j[phase] = s;
  return j;
}

std::vector<double> to_vector(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

std::string step_file(const std::string& body, int step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "_%04d.vtu", step);
  return body + buf;
}

void write_body_vtu(const Body& body, const DofMap& dofs, int b, const VectorXd& u, const std::string& path) {
  const BodyFields f = recover_fields(body.mesh, dofs, b, body.material, u);
  VtuWriter w(body.mesh);
  w.add_point_data("displacement", f.displacement);
  w.add_point_data("strain", f.strain, {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
  w.add_point_data("stress", f.stress, {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
  w.add_point_data("von_mises", f.von_mises);
  w.add_cell_data("stress", f.cell_stress, {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
  w.add_cell_data("von_mises", f.cell_von_mises);
  w.write(path);
}

}  // namespace

RunResult run_problem(const ProblemSpec& spec, const RunOptions& options, const Logger& log) {
  namespace fs = std::filesystem;
  PhaseTimes times;
  const double t_start = wall_seconds();
  // Everything that can fail on input happens here, before the output folder is touched.
  std::unique_ptr<Model> model = Model::build(spec, log, times, options.mesh_size);
  const DofMap& dofs = model->dofs();

  ensure_directory(options.out_dir);
  const std::string summary_path = (fs::path(options.out_dir) / "summary.json").string();
  PvdCollection pvd((fs::path(options.out_dir) / "results.pvd").string());
  const bool vtu = options.write_vtu && spec.output.vtu;

  Json summary = Json::object();
  summary["symcontact_version"] = SYMCONTACT_VERSION;
  summary["problem"] = spec.file;
  summary["title"] = spec.title;
  summary["status"] = "running";
  summary["dimension"] = spec.dim;
  summary["model"] = model_name(spec.model);
  summary["order"] = spec.order;
  summary["num_dofs"] = static_cast<double>(dofs.num_dofs());
  Json bodies = Json::array();
  for (int b = 0; b < dofs.num_bodies(); ++b) {
    const Body& body = *model->bodies()[b];
    Json jb = Json::object();
    jb["name"] = body.name;
    jb["cell_type"] = cell_name(body.mesh.cell_type);
    jb["num_nodes"] = static_cast<double>(body.mesh.num_nodes());
    jb["num_cells"] = static_cast<double>(body.mesh.num_cells());
    jb["num_dofs"] = static_cast<double>(dofs.num_body_dofs(b));
    bodies.push_back(jb);
  }
  summary["bodies"] = bodies;
  summary["steps"] = Json::array();
  auto write_summary = [&]() {
    summary["timings"] = timings_json(times);
    summary["wall_time"] = wall_seconds() - t_start;
    if (spec.output.summary)
      write_file_atomically(summary_path, [&](std::ostream& os) { os << summary.dump(2) << '\n'; });
  };
  write_summary();

  RunResult result;
  VectorXd u = VectorXd::Zero(dofs.num_dofs());
  const int nsteps = model->num_steps();
  for (int step = 0; step < nsteps; ++step) {
    PhaseTimes st;
    model->set_step(step);
    const FixedDofs fixed = model->fixed_dofs(step);
    EquilibriumReport rep;
    try {
      rep = solve_equilibrium(model->energy(), fixed, u);
    } catch (const SolveError& e) {
      result.status = RunStatus::kSolveFailed;
      result.message = "load step " + std::to_string(step + 1) + ": " + e.what();
      summary["status"] = "solve_failed";
      summary["message"] = result.message;
      write_summary();
      return result;
    }
    st.merge(rep.times);
    Json js = Json::object();
    js["step"] = step + 1;
    js["load_factor"] = spec.load_factors[step];
    js["newton_iterations"] = rep.iterations;
    js["residual"] = rep.residual;
    js["num_free_dofs"] = static_cast<double>(rep.num_free);
    // Reactions: ∇E(u) at the Dirichlet boundaries' nodes.
    VectorXd g = VectorXd::Zero(dofs.num_dofs());
    model->energy().add_gradient(u, g);
    Json reactions = Json::array();
    const std::vector<Eigen::VectorXd> r = model->reactions(fixed, g);
    for (std::size_t k = 0; k < r.size(); ++k) {
      const auto& db = model->dirichlet_boundaries()[k];
      Json jr = Json::object();
      jr["body"] = model->bodies()[db.body]->name;
      jr["boundary"] = db.name;
      jr["force"] = to_vector(r[k]);
      reactions.push_back(jr);
    }
    js["reactions"] = reactions;
    const VectorXd f = model->external_load();
    Eigen::VectorXd applied = Eigen::VectorXd::Zero(spec.dim);
    for (Index d = 0; d < f.size(); ++d) applied[d % spec.dim] += f[d];
    js["applied_load"] = to_vector(applied);
    if (vtu) {
      ScopedPhase t(st, "output");
      for (int b = 0; b < dofs.num_bodies(); ++b) {
        const Body& body = *model->bodies()[b];
        const std::string name = step_file(body.name, step + 1);
        write_body_vtu(body, dofs, b, u, (fs::path(options.out_dir) / name).string());
        pvd.add(step + 1, b, name, body.name);
      }
      pvd.write();
    }
    js["timings"] = timings_json(st);
    times.merge(st);
    summary["steps"].push_back(js);
    result.steps_done = step + 1;
    write_summary();
    std::ostringstream s;
    s << "iterations " << rep.iterations << ", residual " << rep.residual;
    log.progress("load step", step + 1, nsteps, s.str());
  }
  summary["status"] = "ok";
  write_summary();
  return result;
}

}  // namespace symcontact
