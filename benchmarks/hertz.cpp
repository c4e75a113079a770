#include "hertz.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "bench_support.hpp"
#include "symcontact/app/run.hpp"
#include "symcontact/contact/contact_points.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/model/problem_reader.hpp"
#include "symcontact/post/contact_results.hpp"

namespace symcontact::bench {

namespace {

/// Replaces every occurrence of `from` in `s` by `to`; throws if there is none.
void replace_all(std::string& s, const std::string& from, const std::string& to) {
  std::size_t count = 0;
  for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size(), ++count)
    s.replace(at, from.size(), to);
  if (count == 0) throw std::runtime_error("'" + from + "' not found in the example's problem file");
}

struct HertzExample {
  const char* dir;   ///< under examples/
  const char* stem;  ///< <stem>.toml reads <stem>.geo
};

HertzExample example_of(HertzCase c) {
  switch (c) {
    case HertzCase::kCylinderOnPlane: return {"hertz_2d", "cylinder_on_plane"};
    case HertzCase::kTwoCylinders: return {"hertz_2d", "two_cylinders"};
    case HertzCase::kSphereOnPlane: return {"hertz_3d", "sphere_on_plane"};
    case HertzCase::kTwoSpheres: return {"hertz_3d", "two_spheres"};
  }
  throw std::logic_error("example_of: unknown Hertz case");
}

}  // namespace

std::string hertz_case_name(HertzCase c) {
  switch (c) {
    case HertzCase::kCylinderOnPlane: return "hertz2d";
    case HertzCase::kTwoCylinders: return "hertz2d-cylinders";
    case HertzCase::kSphereOnPlane: return "hertz3d";
    case HertzCase::kTwoSpheres: return "hertz3d-spheres";
  }
  throw std::logic_error("hertz_case_name: unknown Hertz case");
}

std::string hertz_case_description(HertzCase c) {
  switch (c) {
    case HertzCase::kCylinderOnPlane: return "cylinder on a rigid plane, plane strain, P1, half model";
    case HertzCase::kTwoCylinders: return "two elastic cylinders, plane strain, P1, half model";
    case HertzCase::kSphereOnPlane: return "sphere on a rigid plane, 3D, P1 (Tet4), quarter model";
    case HertzCase::kTwoSpheres: return "two elastic spheres, 3D, P1 (Tet4), quarter model";
  }
  throw std::logic_error("hertz_case_description: unknown Hertz case");
}

int hertz_dimension(HertzCase c) {
  return c == HertzCase::kSphereOnPlane || c == HertzCase::kTwoSpheres ? 3 : 2;
}

int hertz_symmetry_factor(HertzCase c) { return hertz_dimension(c) == 3 ? 4 : 2; }

HertzReference hertz_reference(HertzCase c, double load) {
  constexpr double E = 1.0, nu = 0.3, R = 1.0;
  const double e_star = E / (1 - nu * nu);
  HertzReference r;
  r.load = load;
  if (hertz_dimension(c) == 2) {
    r.a = std::sqrt(4 * load * R / (M_PI * e_star));
    r.p0 = 2 * load / (M_PI * r.a);
  } else {
    r.a = std::cbrt(3 * load * R / (4 * e_star));
    r.p0 = 3 * load / (2 * M_PI * r.a * r.a);
  }
  return r;
}

double HertzRun::contact_seconds() const {
  return report.times.get("search") + report.times.get("assembly") + report.times.get("optimizer") +
         report.times.get("polish") + report.times.get("condensation");
}

std::unique_ptr<HertzRun> solve_hertz(HertzCase which, double h, const std::string& examples_dir,
                                      const std::string& work_dir, bool condense, double search_distance,
                                      const BeforeSolve& before_solve, SubproblemSolver dual) {
  auto run = std::make_unique<HertzRun>();
  run->which = which;
  run->h = h;
  const HertzExample ex = example_of(which);
  const std::string stem = ex.stem;
  const std::string example = examples_dir + "/" + ex.dir + "/" + stem;

  std::filesystem::create_directories(work_dir);
  char h_line[64];
  std::snprintf(h_line, sizeof h_line, "h = %.9g;\n", h);
  const std::string geo_name = stem + "_h.geo";
  write_file(work_dir + "/" + geo_name,
             std::string(h_line) + "Include \"" + std::filesystem::absolute(example + ".geo").string() + "\";\n");
  std::string toml = read_file(example + ".toml");
  replace_all(toml, stem + ".geo", geo_name);
  if (search_distance > 0) {
    char line[80];
    std::snprintf(line, sizeof line, "[[contact]]\nsearch_distance = %.9g\n", search_distance);
    replace_all(toml, "[[contact]]\n", line);
  }

  run->spec = parse_problem(toml, stem + ".toml", work_dir);
  if (run->spec.dim != hertz_dimension(which))
    throw std::runtime_error(stem + ".toml: expected dimension " + std::to_string(hertz_dimension(which)));
  solve_hertz_model(*run, condense, before_solve, dual);
  return run;
}

void solve_hertz_model(HertzRun& run, bool condense, const BeforeSolve& before_solve, SubproblemSolver dual) {
  std::ostringstream quiet;
  const Logger log(quiet, Verbosity::kQuiet);
  run.model = Model::build(run.spec, log, run.build_times);
  Model& model = *run.model;
  if (model.num_steps() != 1) throw std::runtime_error(run.spec.file + ": expected a single load step");
  model.set_step(0);
  run.fixed = model.fixed_dofs(0);
  if (before_solve) before_solve(run);

  // The solver settings exactly as `symcontact run` derives them from the problem file.
  ContactSolveOptions opt = contact_options(run.spec, log).friction.contact;
  opt.lazy_interior = false;  // one solve, outside a Coulomb loop: u whole on return
  opt.static_condensation = opt.static_condensation && condense;
  // The cheaper of the file's choice and `dual` (the enum runs from the primal to the dense interior point).
  opt.subproblem_solver = std::min(opt.subproblem_solver, dual);
  run.u = VectorXd::Zero(model.dofs().num_dofs());
  const double cpu0 = process_cpu_seconds();
  const double t0 = wall_seconds();
  run.report = solve_contact(model.energy(), run.fixed, model.contacts(), model.dofs(), run.u, opt, log);
  run.solve_wall = wall_seconds() - t0;
  run.solve_cpu = process_cpu_seconds() - cpu0;

  const int dim = model.dim();
  const int vertical = dim - 1;
  const double symmetry = hertz_symmetry_factor(run.which);
  const VectorXd f = model.external_load();
  double resultant = 0.0;
  for (Index d = vertical; d < f.size(); d += dim) resultant -= f[d];  // node-major DOFs (dof_map.hpp)
  run.load = symmetry * resultant;

  const std::vector<ContactPairResult> pairs = contact_results(model.contacts(), model.dofs(), run.u, run.report);
  const ContactSideResult& side = pairs.at(0).sides.at(0);
  run.p0 = 0.0;
  run.a = 0.0;
  for (Index k = 0; k < side.pressure.size(); ++k) run.p0 = std::max(run.p0, side.pressure[k]);
  for (Index k = 0; k < side.pressure.size(); ++k)
    // At the reference positions, the frame of the small-strain closed form (and of the FreeFEM
    // comparison); the current positions sit ~2-3 % of a inward at this load (test_hertz_2d.cpp).
    if (side.pressure[k] > 1e-3 * run.p0) run.a = std::max(run.a, side.X.col(k).head(dim - 1).norm());
  run.force = std::abs(pairs[0].total_force[vertical]);
  const ContactLinearization& lin = run.report.linearization;
  run.min_constraint = (lin.A * run.u + lin.b).minCoeff();
  const ContactPair& pair = model.contacts().pairs.at(0);
  run.search_distance = pair.search_distance;
  run.surface_nodes = run.surface_facets = 0;
  for (const int s : {pair.surface_a, pair.surface_b})
    if (s >= 0) {
      run.surface_nodes += model.contacts().surfaces[s].num_nodes();
      run.surface_facets += model.contacts().surfaces[s].num_facets();
    }
}

double time_contact_search(const HertzRun& run, int repeat) {
  const ContactSet& contacts = run.model->contacts();
  const DofMap& dofs = run.model->dofs();
  std::size_t points = 0;  // used, so that the search cannot be optimised away
  const double best = min_time(repeat, [&] {
    for (const ContactFamily& fam : contacts.families()) {
      const ContactPair& pair = contacts.pairs[fam.pair];
      ContactSearchOptions opt;
      opt.search_distance = pair.search_distance;
      const ContactSurface& slave = contacts.surfaces[fam.slave];
      const Eigen::MatrixXd xs = current_positions(slave, dofs, run.u);
      if (fam.master >= 0) {
        const ContactSurface& ms = contacts.surfaces[fam.master];
        const MasterGeometry master = prepare_master(ms, current_positions(ms, dofs, run.u));
        points += contact_points(slave, xs, master, opt).size();
      } else {
        points += contact_points(slave, xs, contacts.obstacles[pair.obstacle], opt).size();
      }
    }
  });
  if (points == 0) throw std::runtime_error("time_contact_search: the search found no contact point");
  return best;
}

namespace {

/// The floor's free numbering (measure_hertz_floor): the problem's, with the vertical component also
/// fixed at the node(s) at the origin. Returns the number of free DOFs.
Index hertz_floor_numbering(const HertzRun& run, std::vector<Index>& free_index, int& pinned) {
  const Model& model = *run.model;
  FixedDofs fixed = run.fixed;
  pinned = 0;
  for (int b = 0; b < static_cast<int>(model.bodies().size()); ++b) {
    const Mesh& mesh = model.bodies()[b]->mesh;
    for (Index node = 0; node < mesh.num_nodes(); ++node)
      if (mesh.x.col(node).norm() < 1e-12) {
        fixed.fix(model.dofs().dof(b, node, model.dim() - 1), 0.0);
        ++pinned;
      }
  }
  if (pinned == 0) throw std::runtime_error("measure_hertz_floor: no mesh node at the contact point (the origin)");
  return fixed.free_numbering(model.dofs().num_dofs(), free_index);
}

}  // namespace

double check_hertz_fits(const HertzRun& run) {
  std::vector<Index> free_index;
  int pinned = 0;
  const Index num_free = hertz_floor_numbering(run, free_index, pinned);
  const double nnz = predict_factor_nonzeros(run.model->energy(), free_index, num_free);
  const ContactPair& pair = run.model->contacts().pairs.at(0);
  double m = 0.0;
  for (const int s : {pair.surface_a, pair.surface_b})
    if (s >= 0) m += static_cast<double>(run.model->contacts().surfaces[s].num_nodes());
  // solvers/memory_prediction.hpp's model; check_factor_fits() adds 8 · nnz(L).
  const double dofs = static_cast<double>(run.model->dofs().num_dofs());
  check_factor_fits(nnz, predicted_direct_peak_bytes(nnz, dofs, m) - 8.0 * nnz);
  return nnz;
}

CholeskyFloor measure_hertz_floor(const HertzRun& run, int repeat, Index& num_free, int& pinned) {
  const Model& model = *run.model;
  std::vector<Index> free_index;
  num_free = hertz_floor_numbering(run, free_index, pinned);
  const VectorXd f = model.external_load();
  VectorXd load_free(num_free);
  for (Index d = 0; d < f.size(); ++d)
    if (free_index[d] >= 0) load_free[free_index[d]] = f[d];
  return measure_cholesky_floor(model.energy(), free_index, num_free, load_free, repeat);
}

}  // namespace symcontact::bench
