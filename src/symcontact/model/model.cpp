#include "symcontact/model/model.hpp"

#include <map>
#include <sstream>

#include "symcontact/core/error.hpp"
#include "symcontact/energy/hyperelastic_energy.hpp"
#include "symcontact/energy/linear_elastic_energy.hpp"
#include "symcontact/mesh/gmsh_io.hpp"

namespace symcontact {

double step_factor(const std::vector<double>& own, const std::vector<double>& global, int step) {
  if (step < 0) return 0.0;
  return own.empty() ? global.at(step) : own.at(step);
}

double step_factor(const std::vector<double>& own, const std::vector<double>& global, int step, double fraction) {
  const double end = step_factor(own, global, step);
  if (fraction >= 1.0) return end;
  const double start = step_factor(own, global, step - 1);
  return start + fraction * (end - start);
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

/// The nodes of the physical point group `group` of body b (Gmsh dimension 0), for a point load.
const std::vector<Index>& require_points(const ProblemSpec& spec, const Body& b, const std::string& group,
                                         const std::string& key) {
  const Mesh& mesh = b.mesh;
  const std::string where = "body '" + b.name + "' (mesh " + b.spec->mesh_file + ")";
  if (mesh.facet_groups.count(group))
    throw InputError(spec.file, key,
                     "expected a physical point group, got '" + group + "', a boundary group (dimension " +
                         std::to_string(mesh.dim - 1) + ") of " + where);
  auto it = mesh.node_groups.find(group);
  if (it == mesh.node_groups.end())
    throw InputError(spec.file, key, where + " has no physical point group '" + group +
                                         "'; its groups: " + available_groups(mesh));
  auto d = mesh.node_group_dims.find(group);
  if (d != mesh.node_group_dims.end() && d->second != 0)
    throw InputError(spec.file, key,
                     "expected a physical point group, got '" + group + "', a group of dimension " +
                         std::to_string(d->second) + " of " + where);
  return it->second;
}

/// The finite-strain law of a hyperelastic body (materials/hyperelastic.hpp); none for linear elasticity.
std::optional<Hyperelastic> hyperelastic_law(const MaterialSpec& ms) {
  if (ms.model == "linear_elastic") return std::nullopt;
  const HyperelasticLaw law = ms.model == "neo_hookean" ? HyperelasticLaw::kNeoHookean : HyperelasticLaw::kMooneyRivlin;
  if (!ms.own_constants) return Hyperelastic::from_young_poisson(law, ms.young, ms.poisson);
  return law == HyperelasticLaw::kNeoHookean ? Hyperelastic::neo_hookean(ms.mu, ms.lambda)
                                             : Hyperelastic::mooney_rivlin(ms.c1, ms.c2, ms.kappa);
}

/// The strain energy of a body: linear elastic, or finite-strain hyperelastic.
std::unique_ptr<EnergyTerm> elastic_energy(const Body& body, const DofMap& dofs, int b) {
  if (!body.hyperelastic) return std::make_unique<LinearElasticEnergy>(body.mesh, dofs, b, body.material, body.name);
  return std::make_unique<HyperelasticEnergy>(body.mesh, dofs, b, *body.hyperelastic, body.name);
}
}  // namespace

std::unique_ptr<Model> Model::build(const ProblemSpec& spec, const Logger& log, PhaseTimes& times,
                                    const MeshingOverrides& meshing) {
  std::unique_ptr<Model> m(new Model(spec));
  m->dofs_ = DofMap(spec.dim);
  MeshReadOptions mesh_options;
  mesh_options.dim = spec.dim;
  mesh_options.order = spec.order;
  mesh_options.mesh_size = meshing.mesh_size > 0 ? meshing.mesh_size : spec.mesh_size;
  mesh_options.mesh_size_key = meshing.mesh_size > 0 ? "--mesh-size" : "problem.mesh_size";
  mesh_options.max_predicted_cells = meshing.max_predicted_cells;
  mesh_options.geo_commands = meshing.geo_commands;
  mesh_options.verbose = log.level() >= Verbosity::kDebug;
  {
    ScopedPhase t(times, "meshing");
    // Bodies from the same file share one read.
    std::map<std::string, MeshFile> files;
    for (const auto& bs : spec.bodies) {
      auto it = files.find(bs.mesh_path);
      if (it == files.end()) {
        log.detail("reading mesh " + bs.mesh_path);
        try {
          it = files.emplace(bs.mesh_path, read_mesh_file(bs.mesh_path, mesh_options)).first;
        } catch (const InputError& e) {
          // A malformed mesh file: name the problem file, the body that reads it, the mesh file and
          // where in it ("line L" from the structural check).
          throw InputError(spec.file, bs.key + ".mesh",
                           "body '" + bs.name + "', mesh " + e.file() + (e.key().empty() ? "" : ", " + e.key()) +
                               ": " + e.message());
        }
      }
      auto body = std::make_unique<Body>();
      body->name = bs.name;
      body->spec = &bs;
      try {
        body->mesh = extract_body(it->second, spec.dim, bs.group, bs.key + ".group");
      } catch (const InputError& e) {
        if (e.key() == bs.key + ".group")
          throw InputError(spec.file, e.key(), e.message() + " (mesh " + bs.mesh_file + ")");
        // A fault of the mesh itself (an inverted element, a facet off the boundary): name the problem
        // file, the body and the mesh file.
        throw InputError(spec.file, bs.key + ".mesh",
                         "body '" + bs.name + "', mesh " + bs.mesh_file + ": " + (e.key().empty() ? "" : e.key() + ": ") +
                             e.message());
      }
      body->material = LinearElastic::from_young_poisson(bs.material.young, bs.material.poisson, spec.model);
      body->hyperelastic = hyperelastic_law(bs.material);
      m->dofs_.add_body(body->mesh.num_nodes());
      std::ostringstream s;
      s << "body '" << bs.name << "': " << body->mesh.num_nodes() << " nodes, " << body->mesh.num_cells() << " "
        << cell_name(body->mesh.cell_type) << " cells";
      log.info(s.str());
      m->bodies_.push_back(std::move(body));
    }
  }
  ScopedPhase t(times, "setup");
  for (int b = 0; b < static_cast<int>(m->bodies_.size()); ++b) {
    const Body& body = *m->bodies_[b];
    const BodySpec& bs = *body.spec;
    m->energy_.add(elastic_energy(body, m->dofs_, b));
    m->add_loads(b);
    for (const auto& ds : bs.dirichlet) {
      if (!body.mesh.has_group(ds.group))
        throw InputError(spec.file, ds.key + ".boundary",
                         "body '" + body.name + "' (mesh " + bs.mesh_file + ") has no group '" + ds.group +
                             "'; its groups: " + available_groups(body.mesh));
      m->boundaries_.push_back({b, ds.group, body.mesh.group_nodes(ds.group)});
    }
  }
  m->build_contacts(log, mesh_options);
  m->set_step(0);
  return m;
}

void Model::add_loads(int b) {
  const ProblemSpec& spec = spec_;
  const Body& body = *bodies_[b];
  const BodySpec& bs = *body.spec;
  const int D = spec.dim;
  auto add = [&](const std::string& name, VectorXd f, const std::vector<double>& factors) {
    auto* term = energy_.add(std::make_unique<LinearLoad>(bs.name + "." + name, std::move(f)));
    loads_.push_back({term, factors});
  };
  if (!bs.body_force.empty()) {
    const std::vector<double> bf = bs.body_force;
    add("body_force", body_force_vector(body.mesh, dofs_, b, [&](const double*, double* out) {
          for (int i = 0; i < D; ++i) out[i] = bf[i];
        }), bs.body_force_factors);
  }
  for (const auto& ts : bs.tractions) {
    const FacetGroup& g = require_facets(spec, body, ts.group, ts.key + ".boundary");
    std::vector<double> tv = ts.traction;
    if (ts.input == TractionInput::kTotalForce) {
      // t = F / |Γ_h| with |Γ_h| from boundary_load_vector()'s own quadrature: Σ f = F to round-off.
      const double measure = facet_group_measure(body.mesh, g);
      for (double& c : tv) c /= measure;
    }
    add("traction." + ts.group, boundary_load_vector(body.mesh, dofs_, b, g, [&](const double*, const double*, double* out) {
          for (int i = 0; i < D; ++i) out[i] = tv[i];
        }), ts.factors);
  }
  for (const auto& ps : bs.pressures) {
    const FacetGroup& g = require_facets(spec, body, ps.group, ps.key + ".boundary");
    const double p = ps.pressure;
    add("pressure." + ps.group, boundary_load_vector(body.mesh, dofs_, b, g, [&](const double*, const double* n, double* out) {
          for (int i = 0; i < D; ++i) out[i] = -p * n[i];
        }), ps.factors);
  }
  for (const auto& pl : bs.point_loads) {
    const std::vector<Index>& nodes = require_points(spec, body, pl.group, pl.key + ".group");
    add("point_load." + pl.group, point_load_vector(dofs_, b, nodes, pl.force.data()), pl.factors);
  }
}

int Model::body_index(const std::string& name) const {
  for (int b = 0; b < static_cast<int>(bodies_.size()); ++b)
    if (bodies_[b]->name == name) return b;
  return -1;
}

void Model::build_contacts(const Logger& log, const MeshReadOptions& mesh_options) {
  const ProblemSpec& spec = spec_;
  const int D = spec.dim;
  auto surface = [&](const std::string& body, const std::string& group, const std::string& key) {
    const int b = body_index(body);
    if (b < 0) throw InputError(spec.file, key, "no body named '" + body + "'");
    const Mesh& mesh = bodies_[b]->mesh;
    if (!mesh.facet_groups.count(group))
      throw InputError(spec.file, key,
                       "body '" + body + "' (mesh " + bodies_[b]->spec->mesh_file + ") has no boundary group '" + group +
                           "'; its groups: " + available_groups(mesh));
    const std::string name = body + "." + group;
    for (int s = 0; s < static_cast<int>(contacts_.surfaces.size()); ++s)
      if (contacts_.surfaces[s].name == name) return s;
    contacts_.surfaces.push_back(make_contact_surface(mesh, group, b, name));
    return static_cast<int>(contacts_.surfaces.size()) - 1;
  };
  auto vec3 = [&](const std::vector<double>& v) {
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    for (int i = 0; i < D && i < static_cast<int>(v.size()); ++i) r[i] = v[i];
    return r;
  };
  rigid_meshes_.reserve(spec.contacts.size());
  for (const ContactSpec& cs : spec.contacts) {
    ContactPair pair;
    pair.name = cs.name;
    pair.surface_a = surface(cs.body_a, cs.boundary_a, cs.key + ".a");
    pair.mode = cs.mode == "one-pass" ? ContactMode::kOnePass : ContactMode::kSymmetric;
    pair.slave_is_b = cs.slave == "b";
    pair.geometry = cs.geometry;
    const ContactSurface* other = nullptr;
    if (cs.obstacle) {
      const ObstacleSpec& os = *cs.obstacle;
      if (os.type == "mesh") {
        MeshFile f;
        try {
          f = read_mesh_file(os.mesh_path, mesh_options);
        } catch (const InputError& e) {
          throw InputError(spec.file, os.key + ".mesh",
                           "obstacle mesh " + e.file() + (e.key().empty() ? "" : ", " + e.key()) + ": " + e.message());
        }
        rigid_meshes_.push_back(extract_surface(f, D, os.boundary, os.key + ".boundary"));
        contacts_.surfaces.push_back(make_contact_surface(rigid_meshes_.back(), os.boundary, -1, cs.name + ".obstacle"));
        pair.surface_b = static_cast<int>(contacts_.surfaces.size()) - 1;
        pair.mode = ContactMode::kOnePass;  // a rigid surface carries no multipliers of its own
        pair.slave_is_b = false;
        other = &contacts_.surfaces.back();
      } else {
        Obstacle ob;
        ob.name = cs.name;
        if (os.type == "plane") {
          ob.kind = Obstacle::Kind::kPlane;
          ob.point = vec3(os.point);
          ob.normal = vec3(os.normal).normalized();
        } else {
          ob.kind = Obstacle::Kind::kSphere;
          ob.point = vec3(os.center);
          ob.radius = os.radius;
          ob.inside = os.inside;
        }
        contacts_.obstacles.push_back(ob);
        pair.obstacle = static_cast<int>(contacts_.obstacles.size()) - 1;
      }
    } else {
      pair.surface_b = surface(cs.body_b, cs.boundary_b, cs.key + ".b");
      other = &contacts_.surfaces[pair.surface_b];
    }
    pair.friction = cs.friction == "tresca"    ? FrictionLaw::kTresca
                    : cs.friction == "coulomb" ? FrictionLaw::kCoulomb
                                               : FrictionLaw::kNone;
    pair.mu = cs.mu;
    pair.tau = cs.tau;
    if (pair.friction != FrictionLaw::kNone) {
      // Automatic regularisation: 1e-6 × the diagonal of the pair's bounding box (docs/input.md).
      const ContactSurface& sa = contacts_.surfaces[pair.surface_a];
      Eigen::VectorXd lo = sa.X.rowwise().minCoeff(), hi = sa.X.rowwise().maxCoeff();
      if (other) {
        lo = lo.cwiseMin(other->X.rowwise().minCoeff());
        hi = hi.cwiseMax(other->X.rowwise().maxCoeff());
      }
      pair.alpha = cs.alpha > 0 ? cs.alpha : 1e-6 * (hi - lo).norm();
    }
    pair.search_distance = cs.search_distance > 0
                               ? cs.search_distance
                               : ContactSet::automatic_search_distance(contacts_.surfaces[pair.surface_a], other);
    std::ostringstream s;
    s << "contact '" << cs.name << "': " << contacts_.surfaces[pair.surface_a].name << " / "
      << (pair.obstacle >= 0 ? std::string("obstacle") : contacts_.surfaces[pair.surface_b].name) << ", "
      << (pair.obstacle >= 0 ? "obstacle" : pair.mode == ContactMode::kSymmetric ? "symmetric" : "one-pass")
      << ", search distance " << pair.search_distance
      << (pair.geometry == ContactGeometry::kReference ? ", reference geometry (small sliding)" : "");
    if (pair.friction == FrictionLaw::kTresca) s << ", Tresca friction tau = " << pair.tau << ", alpha = " << pair.alpha;
    if (pair.friction == FrictionLaw::kCoulomb) s << ", Coulomb friction mu = " << pair.mu << ", alpha = " << pair.alpha;
    log.info(s.str());
    contacts_.pairs.push_back(pair);
  }
  contacts_.finalize();
}

void Model::set_step(int step, double fraction) {
  for (auto& l : loads_) l.term->set_scale(step_factor(l.factors, spec_.load_factors, step, fraction));
}

FixedDofs Model::fixed_dofs(int step, double fraction) const {
  FixedDofs fixed;
  std::size_t k = 0;
  for (int b = 0; b < static_cast<int>(bodies_.size()); ++b) {
    for (const auto& ds : bodies_[b]->spec->dirichlet) {
      const double s = step_factor(ds.factors, spec_.load_factors, step, fraction);
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
