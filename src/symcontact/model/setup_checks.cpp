#include "symcontact/model/setup_checks.hpp"

#include <algorithm>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "symcontact/contact/contact_surface.hpp"
#include "symcontact/contact/penetration.hpp"
#include "symcontact/core/error.hpp"

namespace symcontact {

namespace {

void check_obstacle_orientation(const Model& model) {
  const ContactSet& cs = model.contacts();
  const ProblemSpec& spec = model.spec();
  for (std::size_t p = 0; p < cs.pairs.size(); ++p) {
    const ContactPair& pair = cs.pairs[p];
    if (pair.obstacle >= 0 || pair.surface_b < 0 || !cs.surfaces[pair.surface_b].is_rigid()) continue;
    const ContactSurface& a = cs.surfaces[pair.surface_a];
    const ContactSurface& ob = cs.surfaces[pair.surface_b];
    const Eigen::VectorXd d = signed_distances(ob, ob.X, a.X);
    Index front = 0, behind = 0;
    for (Index k = 0; k < d.size(); ++k) {
      if (d[k] > 0) ++front;
      if (d[k] < 0) ++behind;
    }
    if (behind <= front) continue;
    const ContactSpec& c = spec.contacts[p];
    throw InputError(spec.file, c.obstacle ? c.obstacle->key : c.key,
                     "contact '" + c.name + "': the obstacle's facets (group '" +
                         (c.obstacle ? c.obstacle->boundary : "") +
                         "') face away from body '" + model.bodies()[a.body]->name + "': " + std::to_string(behind) +
                         " of the nodes of '" + a.name + "' lie behind them and " + std::to_string(front) +
                         " in front; the facets' normals must point towards the body (reverse the orientation of "
                         "the obstacle's curves or surfaces in the mesh, e.g. Reverse Curve/Surface in Gmsh)");
  }
}

/// Displacement of rigid motion j at point x (dim), about centre c, rotations divided by the size L.
Eigen::VectorXd rigid_mode(int dim, int j, const Eigen::VectorXd& x, const Eigen::VectorXd& c, double L) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(dim);
  if (j < dim) {
    v[j] = 1.0;
    return v;
  }
  const Eigen::VectorXd r = (x - c) / L;
  if (dim == 2) return Eigen::Vector2d(-r[1], r[0]);
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
  axis[j - dim] = 1.0;
  return axis.cross(Eigen::Vector3d(r[0], r[1], r[2]));
}

std::string mode_name(int dim, int j) {
  static const char* xyz[] = {"x", "y", "z"};
  if (j < dim) return std::string("translation in ") + xyz[j];
  return dim == 2 ? "rotation about z" : std::string("rotation about ") + xyz[j - dim];
}

/// The rigid motions of a body, as indices j of rigid_mode(): every translation and rotation, but for an
/// axisymmetric section only the translation along the axis (y): a radial motion strains the hoop.
std::vector<int> rigid_motions(AnalysisModel model, int dim) {
  if (model == AnalysisModel::kAxisymmetric) return {1};
  std::vector<int> all(dim == 2 ? 3 : 6);
  for (int j = 0; j < static_cast<int>(all.size()); ++j) all[j] = j;
  return all;
}

/// The rigid motions `modes` (rigid_motions()) that G (Σ rowᵀ row of the constraints, over those modes) leaves
/// free, by name: first the single motions (a translation or a rotation about the centroid) that nothing
/// resists, then, when the null space of G holds more, "a combination of ..." naming the motions of one more
/// null vector. Empty when none.
std::string free_motions(const Eigen::MatrixXd& G, int dim, const std::vector<int>& modes) {
  const int nm = static_cast<int>(G.rows());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(G);
  const double top = eig.eigenvalues().maxCoeff();
  const double small = 1e-9 * top;
  std::vector<int> null;
  for (int j = 0; j < nm; ++j)
    if (!(eig.eigenvalues()[j] > small)) null.push_back(j);
  std::string out;
  std::vector<char> single(nm, 0);
  int count = 0;
  for (int j = 0; j < nm; ++j)
    if (!(G(j, j) > small)) {
      single[j] = 1;
      ++count;
      out += (out.empty() ? "" : "; ") + mode_name(dim, modes[j]);
    }
  if (static_cast<int>(null.size()) > count) {
    // A null vector with the single free motions taken out.
    Eigen::VectorXd best;
    for (int j : null) {
      Eigen::VectorXd v = eig.eigenvectors().col(j);
      for (int k = 0; k < nm; ++k)
        if (single[k]) v[k] = 0.0;
      if (best.size() == 0 || v.norm() > best.norm()) best = v;
    }
    std::string combination;
    for (int k = 0; k < nm; ++k)
      if (std::abs(best[k]) > 0.1 * best.cwiseAbs().maxCoeff())
        combination += (combination.empty() ? "" : " + ") + mode_name(dim, modes[k]);
    out += (out.empty() ? "" : "; ") + ("a combination of " + combination);
  }
  return out;
}

void check_rigid_motions(const Model& model) {
  const int D = model.dim();
  const std::vector<int> modes = rigid_motions(model.spec().model, D);
  const int nm = static_cast<int>(modes.size());
  const DofMap& dofs = model.dofs();
  const ContactSet& cs = model.contacts();
  const FixedDofs fixed = model.fixed_dofs(0);
  std::vector<Index> free_index;
  fixed.free_numbering(dofs.num_dofs(), free_index);
  for (int b = 0; b < dofs.num_bodies(); ++b) {
    const Body& body = *model.bodies()[b];
    const Eigen::MatrixXd& X = body.mesh.x;
    const Eigen::VectorXd c = X.rowwise().mean();
    const double L = std::max((X.rowwise().maxCoeff() - X.rowwise().minCoeff()).norm(), 1e-300);
    Eigen::MatrixXd G = Eigen::MatrixXd::Zero(nm, nm);  // Σ rowᵀ row over the constraints that resist
    auto add_row = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& direction) {
      Eigen::VectorXd row(nm);
      for (int j = 0; j < nm; ++j) row[j] = rigid_mode(D, modes[j], x, c, L).dot(direction);
      G += row * row.transpose();
    };
    for (Index v = 0; v < body.mesh.num_nodes(); ++v)
      for (int i = 0; i < D; ++i)
        if (free_index[dofs.dof(b, v, i)] < 0) add_row(X.col(v), Eigen::VectorXd::Unit(D, i));
    std::string contacts;
    for (const ContactPair& pair : cs.pairs)
      for (int s : {pair.surface_a, pair.surface_b}) {
        if (s < 0 || cs.surfaces[s].body != b) continue;
        const ContactSurface& surf = cs.surfaces[s];
        contacts += (contacts.empty() ? "'" : ", '") + pair.name + "'";
        const Eigen::MatrixXd n = nodal_normals(surf, surf.X);
        for (Index k = 0; k < surf.num_nodes(); ++k) {
          if (pair.friction != FrictionLaw::kNone)
            for (int i = 0; i < D; ++i) add_row(surf.X.col(k), Eigen::VectorXd::Unit(D, i));
          else
            add_row(surf.X.col(k), n.col(k));
        }
      }
    const std::string motion = free_motions(G, D, modes);
    if (motion.empty()) continue;
    throw InputError(model.spec().file, body.spec->key,
                     "body '" + body.name + "': rigid motion left free: " + motion +
                         ". No Dirichlet condition holds it" +
                         (contacts.empty() ? std::string()
                                           : " and none of its contacts (" + contacts +
                                                 ") resists it: frictionless contact resists only along the normals "
                                                 "of the contact surface") +
                         ". Its stiffness is singular and the solve cannot converge; hold that motion with a "
                         "[[body.dirichlet]] (a point or a symmetry line), or give the contact friction");
  }
}

void check_overlap(const Model& model) {
  std::vector<const Mesh*> meshes;
  for (const auto& b : model.bodies()) meshes.push_back(&b->mesh);
  const ContactSet& cs = model.contacts();
  const std::vector<Penetration> found =
      find_penetrations(cs, meshes, model.dofs(), VectorXd::Zero(model.dofs().num_dofs()));
  auto it = std::find_if(found.begin(), found.end(), [](const Penetration& p) { return p.exceeds(); });
  if (it == found.end()) return;
  const Penetration& p = *it;
  const ContactSurface& slave = cs.surfaces[p.slave];
  std::ostringstream s;
  s.precision(4);
  s << "contact '" << cs.pairs[p.pair].name << "': the bodies overlap at the start: "
    << model.bodies()[slave.body]->mesh.node_label(slave.nodes[p.node]) << " of '" << slave.name << "' lies "
    << p.depth << " inside " << (p.master < 0 ? std::string("the obstacle") : "'" + cs.surfaces[p.master].name + "'")
    << " (" << 100.0 * p.depth / p.size << " % of the element size " << p.size << "; at most "
    << 100.0 * kPenetrationRelativeTolerance << " % is tolerated)";
  throw InputError(model.spec().file, model.spec().contacts[p.pair].key, s.str());
}

}  // namespace

void check_setup(const Model& model) {
  if (!model.contacts().empty()) check_obstacle_orientation(model);
  check_rigid_motions(model);
  if (!model.contacts().empty()) check_overlap(model);
}

}  // namespace symcontact
