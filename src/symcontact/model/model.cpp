#include "symcontact/model/model.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

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

/// Throws when `group` of body b lost facets to duplicate nodes (Mesh::incomplete_groups).
void require_complete(const ProblemSpec& spec, const Body& b, const std::string& group, const std::string& key) {
  if (auto in = b.mesh.incomplete_groups.find(group); in != b.mesh.incomplete_groups.end())
    throw InputError(spec.file, key,
                     "body '" + b.name + "' (mesh " + b.spec->mesh_file + "), group '" + group + "': " + in->second);
}

const FacetGroup& require_facets(const ProblemSpec& spec, const Body& b, const std::string& group,
                                 const std::string& key) {
  const std::string where = "body '" + b.name + "' (mesh " + b.spec->mesh_file + ")";
  require_complete(spec, b, group, key);
  if (auto in = b.mesh.interior_facet_groups.find(group); in != b.mesh.interior_facet_groups.end())
    throw InputError(spec.file, key, where + ", group '" + group + "': " + in->second);
  auto it = b.mesh.facet_groups.find(group);
  if (it == b.mesh.facet_groups.end())
    throw InputError(spec.file, key,
                     where + " has no boundary group '" + group + "'; its groups: " + available_groups(b.mesh));
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

/// The finite-strain law of a hyperelastic material (materials/hyperelastic.hpp); none for linear elasticity.
std::optional<Hyperelastic> hyperelastic_law(const MaterialSpec& ms) {
  if (ms.model == "linear_elastic") return std::nullopt;
  const HyperelasticLaw law = ms.model == "neo_hookean" ? HyperelasticLaw::kNeoHookean : HyperelasticLaw::kMooneyRivlin;
  if (!ms.own_constants) return Hyperelastic::from_young_poisson(law, ms.young, ms.poisson);
  return law == HyperelasticLaw::kNeoHookean ? Hyperelastic::neo_hookean(ms.mu, ms.lambda)
                                             : Hyperelastic::mooney_rivlin(ms.c1, ms.c2, ms.kappa);
}

/// What the problem declares about body `bs` that lets its mesh be cut or in pieces (mesh_topology.hpp):
/// its self-contacts (pairs with both sides on it), its contact surfaces and its Dirichlet boundaries.
TopologyAllowances topology_allowances(const ProblemSpec& spec, const BodySpec& bs) {
  TopologyAllowances allow;
  allow.body = bs.name;
  const auto add = [](std::vector<std::string>& names, const std::string& name) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  };
  for (const ContactSpec& cs : spec.contacts) {
    const bool on_a = cs.body_a == bs.name, on_b = !cs.obstacle && cs.body_b == bs.name;
    if (on_a) add(allow.contact_surfaces, cs.boundary_a);
    if (on_b) add(allow.contact_surfaces, cs.boundary_b);
    if (on_a && on_b) allow.self_contacts.emplace_back(cs.boundary_a, cs.boundary_b);
  }
  for (const DirichletSpec& ds : bs.dirichlet) add(allow.dirichlet_boundaries, ds.group);
  return allow;
}

/// The strain energy of a body: linear elastic, or finite-strain hyperelastic, each cell with its material.
std::unique_ptr<EnergyTerm> elastic_energy(const Body& body, const DofMap& dofs, int b) {
  if (body.hyperelastic.empty())
    return std::make_unique<LinearElasticEnergy>(body.mesh, dofs, b, body.materials, body.cell_material, body.name);
  return std::make_unique<HyperelasticEnergy>(body.mesh, dofs, b, body.hyperelastic, body.cell_material, body.name,
                                              body.materials.front().model);
}

/// The extent of a mesh along x (the radius of an axisymmetric section): the scale of "on the axis".
double section_width(const Mesh& mesh) { return mesh.x.row(0).maxCoeff() - mesh.x.row(0).minCoeff(); }

/// An axisymmetric section lies in r = x ≥ 0: throws InputError(problem file, the body's mesh key) naming
/// the node farthest on the other side. A node at −1e-12 × the section's width counts as on the axis.
void check_axisymmetric_section(const ProblemSpec& spec, const BodySpec& bs, const Mesh& mesh) {
  if (spec.model != AnalysisModel::kAxisymmetric || mesh.num_nodes() == 0) return;
  Index worst = 0;
  for (Index v = 1; v < mesh.num_nodes(); ++v)
    if (mesh.x(0, v) < mesh.x(0, worst)) worst = v;
  if (mesh.x(0, worst) >= -1e-12 * section_width(mesh)) return;
  std::ostringstream s;
  s << "body '" << bs.name << "' (mesh " << bs.mesh_file << ") has a node at x = r = " << mesh.x(0, worst)
    << " (y = " << mesh.x(1, worst) << "); an axisymmetric section (problem.model = \"axisymmetric\") lies in "
    << "x >= 0, the axis of revolution being x = 0";
  throw InputError(spec.file, bs.key + ".mesh", s.str());
}

/// The laws of a body's materials (Body::materials, Body::hyperelastic).
void set_material_laws(const ProblemSpec& spec, Body& body) {
  for (const MaterialSpec& ms : body.spec->materials) {
    body.materials.push_back(LinearElastic::from_young_poisson(ms.young, ms.poisson, spec.model));
    if (std::optional<Hyperelastic> law = hyperelastic_law(ms)) body.hyperelastic.push_back(*law);
  }
}

/// Body::cell_material from the groups of the body's materials: every cell in exactly one material's group.
/// A body of one material without a group leaves it empty. Throws InputError(problem file, key of the
/// material) for a group that is not a group of the body's cells, a cell in two materials' groups, or a
/// cell in none (naming the cell by its element tag and counting the others).
void assign_cell_materials(const ProblemSpec& spec, Body& body) {
  const std::vector<MaterialSpec>& materials = body.spec->materials;
  if (materials.size() == 1 && materials[0].group.empty()) return;
  const Mesh& mesh = body.mesh;
  const std::string where = "body '" + body.name + "' (mesh " + body.spec->mesh_file + ")";
  body.cell_material.assign(mesh.num_cells(), -1);
  for (int r = 0; r < static_cast<int>(materials.size()); ++r) {
    const MaterialSpec& ms = materials[r];
    if (ms.group.empty())
      throw InputError(spec.file, ms.key + ".group",
                       "missing required key (a body of several materials needs the group of each)");
    auto it = mesh.cell_groups.find(ms.group);
    if (it == mesh.cell_groups.end()) {
      std::string known;
      for (const auto& [name, cells] : mesh.cell_groups) known += (known.empty() ? "'" : ", '") + name + "'";
      throw InputError(spec.file, ms.key + ".group",
                       where + " has no physical group '" + ms.group + "' of dimension " + std::to_string(mesh.dim) +
                           " among its cells; its groups of cells: " + (known.empty() ? "none" : known));
    }
    for (Index c : it->second) {
      if (body.cell_material[c] >= 0)
        throw InputError(spec.file, ms.key + ".group",
                         where + ": " + mesh.cell_label(c) + " is in group '" + ms.group + "' and in group '" +
                             materials[body.cell_material[c]].group + "' (" + materials[body.cell_material[c]].key +
                             "): each cell takes one material");
      body.cell_material[c] = r;
    }
  }
  const auto uncovered = std::count(body.cell_material.begin(), body.cell_material.end(), -1);
  if (uncovered == 0) return;
  const Index first = std::find(body.cell_material.begin(), body.cell_material.end(), -1) - body.cell_material.begin();
  throw InputError(spec.file, body.spec->key + ".material",
                   where + ": " + mesh.cell_label(first) + (uncovered > 1 ? " and " + std::to_string(uncovered - 1) +
                                                                                " other cells are"
                                                                          : " is") +
                       " in no material's group: every cell of the body needs a material");
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
    // Bodies from the same file with the same mesh parameters share one read.
    std::map<std::pair<std::string, std::map<std::string, double>>, MeshFile> files;
    for (const auto& bs : spec.bodies) {
      auto it = files.find({bs.mesh_path, bs.mesh_parameters});
      if (it == files.end()) {
        log.detail("reading mesh " + bs.mesh_path);
        MeshReadOptions body_options = mesh_options;
        body_options.geo_parameters = bs.mesh_parameters;
        try {
          MeshFile file = read_mesh_file(bs.mesh_path, body_options);
          it = files.emplace(std::make_pair(bs.mesh_path, bs.mesh_parameters), std::move(file)).first;
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
        body->mesh = extract_body(it->second, spec.dim, bs.group, bs.key + ".group", topology_allowances(spec, bs));
      } catch (const InputError& e) {
        if (e.key() == bs.key + ".group")
          throw InputError(spec.file, e.key(), e.message() + " (mesh " + bs.mesh_file + ")");
        // A fault of the mesh itself (an inverted element, a facet off the boundary): name the problem
        // file, the body and the mesh file.
        throw InputError(spec.file, bs.key + ".mesh",
                         "body '" + bs.name + "', mesh " + bs.mesh_file + ": " + (e.key().empty() ? "" : e.key() + ": ") +
                             e.message());
      }
      check_axisymmetric_section(spec, bs, body->mesh);
      set_material_laws(spec, *body);
      assign_cell_materials(spec, *body);
      m->dofs_.add_body(body->mesh.num_nodes());
      std::ostringstream s;
      s << "body '" << bs.name << "': " << body->mesh.num_nodes() << " nodes, " << body->mesh.num_cells() << " "
        << body->mesh.cell_types_label() << " cells";
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
    for (const auto& ds : bs.dirichlet) m->add_dirichlet(b, ds);
  }
  m->warn_free_axis_nodes(log);
  m->build_contacts(log, mesh_options);
  m->set_step(0);
  return m;
}

namespace {
/// The load factors a value given by `factors` meets: 0 (the unloaded start), 1 and those of the steps.
std::vector<double> factors_met(const std::vector<double>& own, const std::vector<double>& global) {
  std::vector<double> t{0.0, 1.0};
  for (int k = 0; k < static_cast<int>(global.size()); ++k) t.push_back(step_factor(own, global, k));
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

/// Compiles a value of the problem file (`key` names it) and, for an expression, checks that it is finite
/// at every node of `nodes` at every load factor of `factors`.
CompiledValue compile_value(const ProblemSpec& spec, const LoadValue& v, const std::string& key, const Mesh& mesh,
                            const std::vector<Index>& nodes, const std::vector<double>& factors) {
  CompiledValue c{v.number, nullptr};
  if (!v.is_expression()) return c;
  try {
    c.expression = std::make_shared<const Expression>(v.expression);
  } catch (const ExpressionError& e) {
    throw InputError(spec.file, key, "expected a number or an expression of x, y, z, t; " + e.message());
  }
  for (double t : factors_met(factors, spec.load_factors))
    for (Index node : nodes) {
      const double value = c.at(&mesh.x(0, node), mesh.dim, t);
      if (std::isfinite(value)) continue;
      std::ostringstream s;
      s << "the expression \"" << v.expression << "\" is " << (std::isnan(value) ? "NaN" : value > 0 ? "inf" : "-inf")
        << " at t = " << t << ", at the node (x, y, z) = (" << mesh.x(0, node) << ", " << mesh.x(1, node) << ", "
        << (mesh.dim > 2 ? mesh.x(2, node) : 0.0)
        << "); expected a finite value at every node of the group at every load factor (0, 1 and the steps')";
      throw InputError(spec.file, key, s.str());
    }
  return c;
}
}  // namespace

void Model::add_surface_load(int b, const std::string& group, const std::string& key,
                             const std::vector<LoadValue>& values, const std::vector<double>& factors,
                             SurfaceLoad kind) {
  const Body& body = *bodies_[b];
  const FacetGroup& g = require_facets(spec_, body, group, key + ".boundary");
  const std::vector<Index> nodes = body.mesh.group_nodes(group);
  const std::string name = kind == SurfaceLoad::kPressure ? "pressure" : "traction";
  std::vector<CompiledValue> v;
  bool any_expression = false;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string value_key = key + "." + name + (kind == SurfaceLoad::kPressure ? "" : "[" + std::to_string(i) + "]");
    v.push_back(compile_value(spec_, values[i], value_key, body.mesh, nodes, factors));
    any_expression = any_expression || values[i].is_expression();
  }
  const int D = dim();
  const Mesh& mesh = body.mesh;
  const DofMap& dofs = dofs_;
  // f(t)_(a,i) = ∫_Γ t_i(X, t) N_a: t_i = v_i(X, t) for a traction, −p(X, t) n_i for a pressure.
  const AnalysisModel model = spec_.model;
  auto assemble = [&mesh, &dofs, &g, b, D, v, kind, model](double t) {
    return boundary_load_vector(
        mesh, dofs, b, g,
        [&](const double* x, const double* n, double* out) {
          for (int i = 0; i < D; ++i)
            out[i] = kind == SurfaceLoad::kPressure ? -v[0].at(x, D, t) * n[i] : v[i].at(x, D, t);
        },
        model);
  };
  auto* term = energy_.add(std::make_unique<LinearLoad>(body.name + "." + name + "." + group, assemble(1.0)));
  loads_.push_back({term, factors, any_expression ? std::function<VectorXd(double)>(assemble) : nullptr});
}

/// Symmetry asks u_r = 0 on the axis of revolution; the integrals never divide by r (their points are inside
/// the cells), so a section whose axis nodes keep u_r free still solves, but those nodes may move off the axis:
/// a hole opens, or material crosses to r < 0. Each body with such nodes gets one warning naming it, the number
/// of nodes and the first one. A node counts as on the axis within 1e-10 × the section's width.
void Model::warn_free_axis_nodes(const Logger& log) {
  if (spec_.model != AnalysisModel::kAxisymmetric) return;
  for (int b = 0; b < static_cast<int>(bodies_.size()); ++b) {
    const Mesh& mesh = bodies_[b]->mesh;
    if (mesh.num_nodes() == 0) continue;
    std::vector<char> held(mesh.num_nodes(), 0);
    for (const DirichletBoundary& d : boundaries_)
      if (d.body == b && d.values[0])
        for (Index v : d.nodes) held[v] = 1;
    const double on_axis = 1e-10 * section_width(mesh);
    Index first = -1, count = 0;
    for (Index v = 0; v < mesh.num_nodes(); ++v)
      if (std::abs(mesh.x(0, v)) <= on_axis && !held[v]) {
        if (first < 0) first = v;
        ++count;
      }
    if (count == 0) continue;
    std::ostringstream s;
    s << "body '" << bodies_[b]->name << "': " << count << " node" << (count > 1 ? "s" : "")
      << " on the axis (x = r = 0) with u_r free, the first " << mesh.node_label(first) << " at y = "
      << mesh.x(1, first) << "; symmetry asks u_r = 0 there: add a [[body.dirichlet]] with ux = 0 on the axis";
    log.warning(s.str());
    warnings_.push_back(s.str());
  }
}

void Model::add_dirichlet(int b, const DirichletSpec& ds) {
  const Body& body = *bodies_[b];
  require_complete(spec_, body, ds.group, ds.key + ".boundary");
  if (!body.mesh.has_group(ds.group))
    throw InputError(spec_.file, ds.key + ".boundary",
                     "body '" + body.name + "' (mesh " + body.spec->mesh_file + ") has no group '" + ds.group +
                         "'; its groups: " + available_groups(body.mesh));
  DirichletBoundary boundary{b, ds.group, body.mesh.group_nodes(ds.group), &ds, {}};
  constexpr const char* components[3] = {"ux", "uy", "uz"};
  for (int i = 0; i < 3; ++i)
    if (ds.value[i])
      boundary.values[i] = compile_value(spec_, *ds.value[i], ds.key + "." + components[i], body.mesh, boundary.nodes,
                                         ds.factors);
  boundaries_.push_back(std::move(boundary));
}

void Model::add_loads(int b) {
  const ProblemSpec& spec = spec_;
  const Body& body = *bodies_[b];
  const BodySpec& bs = *body.spec;
  const int D = spec.dim;
  auto add = [&](const std::string& name, VectorXd f, const std::vector<double>& factors) {
    auto* term = energy_.add(std::make_unique<LinearLoad>(bs.name + "." + name, std::move(f)));
    loads_.push_back({term, factors, nullptr});
  };
  if (!bs.body_force.empty()) {
    const std::vector<double> bf = bs.body_force;
    add("body_force",
        body_force_vector(
            body.mesh, dofs_, b, [&](const double*, double* out) { for (int i = 0; i < D; ++i) out[i] = bf[i]; },
            spec.model),
        bs.body_force_factors);
  }
  for (const auto& ts : bs.tractions) {
    std::vector<LoadValue> tv = ts.traction;
    if (ts.input == TractionInput::kTotalForce) {
      // t = F / |Γ_h| with |Γ_h| from boundary_load_vector()'s own quadrature: Σ f = F to round-off.
      const FacetGroup& g = require_facets(spec, body, ts.group, ts.key + ".boundary");
      const double measure = facet_group_measure(body.mesh, g, nullptr, spec.model);
      for (LoadValue& c : tv) c.number /= measure;
    }
    add_surface_load(b, ts.group, ts.key, tv, ts.factors, SurfaceLoad::kTraction);
  }
  for (const auto& ps : bs.pressures)
    add_surface_load(b, ps.group, ps.key, {ps.pressure}, ps.factors, SurfaceLoad::kPressure);
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
    require_facets(spec, *bodies_[b], group, key);
    const std::string name = body + "." + group;
    for (int s = 0; s < static_cast<int>(contacts_.surfaces.size()); ++s)
      if (contacts_.surfaces[s].name == name) return s;
    contacts_.surfaces.push_back(make_contact_surface(mesh, group, b, name, spec_.model));
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
        contacts_.surfaces.push_back(
            make_contact_surface(rigid_meshes_.back(), os.boundary, -1, cs.name + ".obstacle", spec_.model));
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
      pair.regularisation = cs.alpha > 0 ? FrictionRegularisation::kGivenLength : FrictionRegularisation::kElementFraction;
      pair.alpha = cs.alpha;
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
    if (pair.friction == FrictionLaw::kTresca) s << ", Tresca friction tau = " << pair.tau;
    if (pair.friction == FrictionLaw::kCoulomb) s << ", Coulomb friction mu = " << pair.mu;
    if (pair.regularisation == FrictionRegularisation::kGivenLength && pair.friction != FrictionLaw::kNone)
      s << ", alpha = " << pair.alpha;
    else if (pair.friction != FrictionLaw::kNone)
      s << ", alpha automatic (" << kAlphaPerElement << " of the local facet size)";
    log.info(s.str());
    contacts_.pairs.push_back(pair);
  }
  contacts_.finalize();
}

void Model::set_step(int step, double fraction) {
  for (auto& l : loads_) {
    const double t = step_factor(l.factors, spec_.load_factors, step, fraction);
    if (!l.at) {
      l.term->set_scale(t);
      continue;
    }
    l.term->set_load(l.at(t));
    l.term->set_scale(1.0);
  }
}

FixedDofs Model::fixed_dofs(int step, double fraction) const {
  FixedDofs fixed;
  for (std::size_t k = 0; k < boundaries_.size(); ++k) {
    const DirichletBoundary& db = boundaries_[k];
    const Mesh& mesh = bodies_[db.body]->mesh;
    const double t = step_factor(db.spec->factors, spec_.load_factors, step, fraction);
    for (Index node : db.nodes)
      for (int i = 0; i < dim(); ++i)
        if (db.values[i])
          fixed.fix(dofs_.dof(db.body, node, i), db.values[i]->at(&mesh.x(0, node), dim(), t), static_cast<int>(k));
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
