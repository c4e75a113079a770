#include "symcontact/model/model.hpp"

#include <map>
#include <sstream>

#include "symcontact/core/error.hpp"
#include "symcontact/energy/linear_elastic_energy.hpp"
#include "symcontact/mesh/gmsh_io.hpp"

namespace symcontact {

double step_factor(const std::vector<double>& own, const std::vector<double>& global, int step) {
  return own.empty() ? global.at(step) : own.at(step);
}

namespace {
std::string available_groups(const Mesh& m) {
  std::string s;
  for (const auto& n : m.group_names()) s += (s.empty() ? "'" : ", '") + n + "'";
  return s.empty() ? "none" : s;
}

const FacetGroup& require_facets(const ProblemSpec& spec, const Body& b, const std::string& group,
                                 const std::string& key) {
  auto it = b.mesh.facet_groups.find(group);
  if (it == b.mesh.facet_groups.end())
    throw InputError(spec.file, key,
                     "body '" + b.name + "' (mesh " + b.spec->mesh_file + ") has no boundary group '" + group +
                         "'; its groups: " + available_groups(b.mesh));
  return it->second;
}
}  // namespace

std::unique_ptr<Model> Model::build(const ProblemSpec& spec, const Logger& log, PhaseTimes& times,
                                    double mesh_size_override) {
  std::unique_ptr<Model> m(new Model(spec));
  m->dofs_ = DofMap(spec.dim);
  const double mesh_size = mesh_size_override > 0 ? mesh_size_override : spec.mesh_size;
  {
    ScopedPhase t(times, "meshing");
    // Bodies from the same file share one read.
    std::map<std::string, MeshFile> files;
    for (const auto& bs : spec.bodies) {
      auto it = files.find(bs.mesh_path);
      if (it == files.end()) {
        MeshReadOptions opt;
        opt.dim = spec.dim;
        opt.order = spec.order;
        opt.mesh_size = mesh_size;
        opt.verbose = log.level() >= Verbosity::kDebug;
        log.detail("reading mesh " + bs.mesh_path);
        it = files.emplace(bs.mesh_path, read_mesh_file(bs.mesh_path, opt)).first;
      }
      auto body = std::make_unique<Body>();
      body->name = bs.name;
      body->spec = &bs;
      try {
        body->mesh = extract_body(it->second, spec.dim, bs.group, bs.key + ".group");
      } catch (const InputError& e) {
        if (e.key() != bs.key + ".group") throw;
        throw InputError(spec.file, e.key(), e.message() + " (mesh " + bs.mesh_file + ")");
      }
      body->material = LinearElastic::from_young_poisson(bs.material.young, bs.material.poisson, spec.model);
      m->dofs_.add_body(body->mesh.num_nodes());
      std::ostringstream s;
      s << "body '" << bs.name << "': " << body->mesh.num_nodes() << " nodes, " << body->mesh.num_cells() << " "
        << cell_name(body->mesh.cell_type) << " cells";
      log.info(s.str());
      m->bodies_.push_back(std::move(body));
    }
  }
  ScopedPhase t(times, "setup");
  const int D = spec.dim;
  for (int b = 0; b < static_cast<int>(m->bodies_.size()); ++b) {
    const Body& body = *m->bodies_[b];
    const BodySpec& bs = *body.spec;
    m->energy_.add(std::make_unique<LinearElasticEnergy>(body.mesh, m->dofs_, b, body.material, body.name));
    if (!bs.body_force.empty()) {
      const std::vector<double> bf = bs.body_force;
      VectorXd f = body_force_vector(body.mesh, m->dofs_, b, [&](const double*, double* out) {
        for (int i = 0; i < D; ++i) out[i] = bf[i];
      });
      auto* term = m->energy_.add(std::make_unique<LinearLoad>(bs.name + ".body_force", std::move(f)));
      m->loads_.push_back({term, bs.body_force_factors});
    }
    for (const auto& ts : bs.tractions) {
      const FacetGroup& g = require_facets(spec, body, ts.group, ts.key + ".boundary");
      const std::vector<double> tv = ts.traction;
      VectorXd f = boundary_load_vector(body.mesh, m->dofs_, b, g, [&](const double*, const double*, double* out) {
        for (int i = 0; i < D; ++i) out[i] = tv[i];
      });
      auto* term = m->energy_.add(std::make_unique<LinearLoad>(bs.name + ".traction." + ts.group, std::move(f)));
      m->loads_.push_back({term, ts.factors});
    }
    for (const auto& ps : bs.pressures) {
      const FacetGroup& g = require_facets(spec, body, ps.group, ps.key + ".boundary");
      const double p = ps.pressure;
      VectorXd f = boundary_load_vector(body.mesh, m->dofs_, b, g, [&](const double*, const double* n, double* out) {
        for (int i = 0; i < D; ++i) out[i] = -p * n[i];
      });
      auto* term = m->energy_.add(std::make_unique<LinearLoad>(bs.name + ".pressure." + ps.group, std::move(f)));
      m->loads_.push_back({term, ps.factors});
    }
    for (const auto& ds : bs.dirichlet) {
      if (!body.mesh.has_group(ds.group))
        throw InputError(spec.file, ds.key + ".boundary",
                         "body '" + body.name + "' (mesh " + bs.mesh_file + ") has no group '" + ds.group +
                             "'; its groups: " + available_groups(body.mesh));
      m->boundaries_.push_back({b, ds.group, body.mesh.group_nodes(ds.group)});
    }
  }
  m->set_step(0);
  return m;
}

void Model::set_step(int step) {
  for (auto& l : loads_) l.term->set_scale(step_factor(l.factors, spec_.load_factors, step));
}

FixedDofs Model::fixed_dofs(int step) const {
  FixedDofs fixed;
  std::size_t k = 0;
  for (int b = 0; b < static_cast<int>(bodies_.size()); ++b) {
    for (const auto& ds : bodies_[b]->spec->dirichlet) {
      const double s = step_factor(ds.factors, spec_.load_factors, step);
      for (Index node : boundaries_[k].nodes)
        for (int i = 0; i < dim(); ++i)
          if (ds.value[i]) fixed.fix(dofs_.dof(b, node, i), *ds.value[i] * s, static_cast<int>(k));
      ++k;
    }
  }
  return fixed;
}

std::vector<Eigen::VectorXd> Model::reactions(const FixedDofs& fixed, const VectorXd& gradient) const {
  std::vector<Eigen::VectorXd> r(boundaries_.size(), Eigen::VectorXd::Zero(dim()));
  const std::vector<int> owner = fixed.owner_of(dofs_.num_dofs());
  for (Index d = 0; d < dofs_.num_dofs(); ++d)
    if (owner[d] >= 0) r[owner[d]][d % dim()] += gradient[d];  // node-major layout: component = d mod dim
  return r;
}

VectorXd Model::external_load() const {
  VectorXd f = VectorXd::Zero(dofs_.num_dofs());
  for (const auto& l : loads_) f += l.term->scale() * l.term->load();
  return f;
}

}  // namespace symcontact
