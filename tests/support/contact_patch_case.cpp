#include "support/contact_patch_case.hpp"

#include "support/temp_folder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

namespace symcontact::testing {

namespace {

constexpr double kP = 0.01, kNu = 0.3;

/// The blocks' names, bottom to top, and their bottom and top face groups.
std::vector<std::string> block_names(int n3) {
  return n3 > 0 ? std::vector<std::string>{"lower", "middle", "upper"} : std::vector<std::string>{"lower", "upper"};
}
std::string bottom_group(const std::vector<std::string>& names, std::size_t i) {
  return i == 0 ? "bottom" : names[i] + "_bottom";
}
std::string top_group(const std::vector<std::string>& names, std::size_t i) {
  return i + 1 == names.size() ? "top" : names[i] + "_top";
}

}  // namespace

std::string contact_patch_geo(int n1, int n2, int dim, int n3, bool one_body) {
  const std::vector<std::string> names = block_names(n3);
  const std::vector<int> n = n3 > 0 ? std::vector<int>{n1, n2, n3} : std::vector<int>{n1, n2};
  const auto nb = static_cast<int>(names.size());
  std::ostringstream g;
  g.precision(17);
  if (dim == 3) {
    // OpenCASCADE boxes: faces 6k+1..6k+6 of box k+1 are xmin, xmax, ymin, ymax, zmin, zmax. The boxes are
    // not fused, so the two faces at each interface are meshed independently (non-matching).
    g << "\nSetFactory(\"OpenCASCADE\");\ne = 1e-6;\n";
    for (int i = 0; i < nb; ++i) g << "Box(" << i + 1 << ") = {0, 0, " << i << ", 1, 1, 1};\n";
    for (int i = 0; i < nb; ++i) g << "MeshSize{PointsOf{Volume{" << i + 1 << "};}} = 1.0 / " << n[i] << ";\n";
    for (int i = 0; i < nb; ++i) g << "Physical Volume(\"" << names[i] << "\") = {" << i + 1 << "};\n";
    for (int i = 0; i < nb; ++i) {
      g << "Physical Surface(\"" << bottom_group(names, i) << "\") = {" << 6 * i + 5 << "};\n";
      g << "Physical Surface(\"" << top_group(names, i) << "\") = {" << 6 * i + 6 << "};\n";
    }
    auto box_point = [&g](const std::string& name, int x, int z) {
      g << "Physical Point(\"" << name << "\") = Point In BoundingBox{" << x << " - e, -e, " << z << " - e, " << x
        << " + e, e, " << z << " + e};\n";
    };
    box_point("origin", 0, 0);
    box_point("lower_x", 1, 0);
    for (int i = 1; i < nb; ++i) {
      box_point(names[i] + "_corner", 0, i + 1);
      box_point(names[i] + "_x", 1, i + 1);
    }
    return g.str();
  }
  // Block i: points and lines 4i+1..4i+4 (bottom, right, top, left), structured triangles.
  g << "\n";
  for (int i = 0; i < nb; ++i)
    g << "Point(" << 4 * i + 1 << ") = {0, " << i << ", 0}; Point(" << 4 * i + 2 << ") = {1, " << i << ", 0}; Point("
      << 4 * i + 3 << ") = {1, " << i + 1 << ", 0}; Point(" << 4 * i + 4 << ") = {0, " << i + 1 << ", 0};\n";
  for (int i = 0; i < nb; ++i)
    for (int k = 1; k <= 4; ++k)
      g << "Line(" << 4 * i + k << ") = {" << 4 * i + k << ", " << 4 * i + k % 4 + 1 << "};\n";
  for (int i = 0; i < nb; ++i)
    g << "Transfinite Curve{" << 4 * i + 1 << ", " << 4 * i + 2 << ", " << 4 * i + 3 << ", " << 4 * i + 4
      << "} = " << n[i] + 1 << ";\n";
  for (int i = 0; i < nb; ++i)
    g << "Curve Loop(" << i + 1 << ") = {" << 4 * i + 1 << ", " << 4 * i + 2 << ", " << 4 * i + 3 << ", " << 4 * i + 4
      << "}; Plane Surface(" << i + 1 << ") = {" << i + 1 << "}; Transfinite Surface{" << i + 1 << "};\n";
  for (int i = 0; i < nb; ++i) g << "Physical Surface(\"" << names[i] << "\") = {" << i + 1 << "};\n";
  for (int i = 0; i < nb; ++i) {
    g << "Physical Curve(\"" << bottom_group(names, i) << "\") = {" << 4 * i + 1 << "};\n";
    g << "Physical Curve(\"" << top_group(names, i) << "\") = {" << 4 * i + 3 << "};\n";
  }
  g << "Physical Point(\"origin\") = {1};\n";
  for (int i = 1; i < nb; ++i) g << "Physical Point(\"" << names[i] << "_corner\") = {" << 4 * i + 4 << "};\n";
  if (one_body) g << "Physical Surface(\"blocks\") = {1, 2};\nPhysical Curve(\"interface\") = {3, 5};\n";
  return g.str();
}

namespace {

/// The .geo of the case: contact_patch_geo() with its quad_blocks recombined: 2D surface i + 1 is block i;
/// in 3D box i + 1 (curves 12i + 1..12i + 12, faces 6i + 1..6i + 6) becomes n_i³ transfinite hexahedra.
std::string patch_geo(const ContactPatchCase& c) {
  std::string g = contact_patch_geo(c.n1, c.n2, c.dim, c.n3, c.one_body);
  const std::vector<std::string> names = block_names(c.n3);
  const int n[3] = {c.n1, c.n2, c.n3};
  for (const std::string& q : c.quad_blocks) {
    const auto it = std::find(names.begin(), names.end(), q);
    if (it == names.end()) {
      ADD_FAILURE() << "no block named " << q;
      continue;
    }
    const int i = static_cast<int>(it - names.begin());
    if (c.dim == 2) {
      g += "Recombine Surface{" + std::to_string(i + 1) + "};\n";
      continue;
    }
    const std::string curves = std::to_string(12 * i + 1) + ":" + std::to_string(12 * i + 12);
    const std::string faces = std::to_string(6 * i + 1) + ":" + std::to_string(6 * i + 6);
    g += "Transfinite Curve{" + curves + "} = " + std::to_string(n[i] + 1) + ";\nTransfinite Surface{" + faces +
         "};\nRecombine Surface{" + faces + "};\nTransfinite Volume{" + std::to_string(i + 1) +
         "};\nRecombine Volume{" + std::to_string(i + 1) + "};\n";
  }
  if (c.serendipity) g += "Mesh.SecondOrderIncomplete = 1;\n";
  return g;
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

bool second_material(const ContactPatchCase& c) { return c.upper_E != 1.0 || c.upper_nu != kNu; }

/// Which nodes of `body` belong to the upper block of the two-block case: its every node when the body is
/// "upper", the nodes of the cells of group "upper" when it is the one body of both (coincident nodes at
/// y = 1 are the two blocks' own), none otherwise.
std::vector<char> upper_block_nodes(const ContactPatchCase& c, const Body& body) {
  const Mesh& mesh = body.mesh;
  std::vector<char> upper(mesh.num_nodes(), body.name == "upper" && c.n3 == 0);
  auto it = mesh.cell_groups.find("upper");
  if (c.one_body && it != mesh.cell_groups.end())
    for (Index cell : it->second)
      for (int a = 0; a < mesh.nodes_per_cell(cell); ++a) upper[mesh.cell(cell)[a]] = 1;
  return upper;
}

/// The problem file of the one-body case (ContactPatchCase::one_body).
std::string one_body_toml(const ContactPatchCase& c) {
  const std::string materials =
      !second_material(c) ? "[body.material]\nE = 1.0\nnu = 0.3\n"
                          : "[[body.material]]\ngroup = \"lower\"\nE = 1.0\nnu = 0.3\n[[body.material]]\ngroup = "
                            "\"upper\"\nE = " + number(c.upper_E) + "\nnu = " + number(c.upper_nu) + "\n";
  return "[problem]\ndimension = 2\norder = " + std::to_string(c.order) +
         "\n\n[[body]]\nname = \"blocks\"\nmesh = \"blocks.geo\"\ngroup = \"blocks\"\n" + materials +
         "[[body.dirichlet]]\nboundary = \"bottom\"\nuy = 0.0\n"
         "[[body.dirichlet]]\nboundary = \"origin\"\nux = 0.0\n"
         "[[body.dirichlet]]\nboundary = \"upper_corner\"\nux = 0.0\n"
         "[[body.pressure]]\nboundary = \"top\"\npressure = 0.01\n"
         "[[contact]]\nname = \"interface\"\na = \"blocks.interface\"\nb = \"blocks.interface\"\n" +
         (c.geometry != "current" ? "geometry = \"" + c.geometry + "\"\n" : std::string());
}

}  // namespace

std::string contact_patch_toml(const ContactPatchCase& c) {
  if (c.one_body) return one_body_toml(c);
  const std::vector<std::string> names = block_names(c.n3);
  const std::size_t nb = names.size();
  auto body = [&](std::size_t i) {
    const bool upper = names[i] == "upper" && c.n3 == 0;
    std::string t = "\n[[body]]\nname = \"" + names[i] + "\"\nmesh = \"blocks.geo\"\ngroup = \"" + names[i] +
                    "\"\n[body.material]\nE = " + number(upper ? c.upper_E : 1.0) +
                    "\nnu = " + number(upper ? c.upper_nu : kNu) + "\n";
    if (i == 0) {
      t += c.dim == 3 ? "[[body.dirichlet]]\nboundary = \"bottom\"\nuz = 0.0\n"
                        "[[body.dirichlet]]\nboundary = \"origin\"\nux = 0.0\nuy = 0.0\n"
                        "[[body.dirichlet]]\nboundary = \"lower_x\"\nuy = 0.0\n"
                      : "[[body.dirichlet]]\nboundary = \"bottom\"\nuy = 0.0\n"
                        "[[body.dirichlet]]\nboundary = \"origin\"\nux = 0.0\n";
    } else {
      t += "[[body.dirichlet]]\nboundary = \"" + names[i] + "_corner\"\nux = 0.0\n";
      if (c.dim == 3) t += "uy = 0.0\n[[body.dirichlet]]\nboundary = \"" + names[i] + "_x\"\nuy = 0.0\n";
    }
    if (i + 1 == nb) t += "[[body.pressure]]\nboundary = \"top\"\npressure = 0.01\n";
    return t;
  };
  auto pair = [&](std::size_t j) {  // between block j and block j + 1
    std::string a = names[j] + "." + top_group(names, j), b = names[j + 1] + "." + bottom_group(names, j + 1);
    if (c.swap) std::swap(a, b);
    std::string t = "[[contact]]\nname = \"" + (nb == 2 ? std::string("interface") : names[j] + "_" + names[j + 1]) +
                    "\"\na = \"" + a + "\"\nb = \"" + b + "\"\nmode = \"" + c.mode + "\"\n";
    if (c.mode == "one-pass") t += "slave = \"b\"\n";
    if (c.geometry != "current") t += "geometry = \"" + c.geometry + "\"\n";
    if (c.mu >= 0) {
      t += "friction = \"coulomb\"\nmu = " + number(c.mu) + "\n";
      if (c.alpha > 0) t += "alpha = " + number(c.alpha) + "\n";
    }
    return t;
  };
  std::string t = "[problem]\ndimension = " + std::to_string(c.dim) + "\norder = " + std::to_string(c.order) + "\n";
  for (std::size_t k = 0; k < nb; ++k) t += body(c.swap ? nb - 1 - k : k);
  for (std::size_t k = 0; k + 1 < nb; ++k) t += pair(c.swap ? nb - 2 - k : k);
  return t;
}

std::unique_ptr<ModelCase> contact_patch_model(const ContactPatchCase& c, const std::filesystem::path& folder,
                                               FixedDofs& fixed) {
  write_text(folder / "blocks.geo", patch_geo(c));
  std::unique_ptr<ModelCase> m = build_model(contact_patch_toml(c), folder);
  m->model->set_step(0);
  fixed = m->model->fixed_dofs(0);
  return m;
}

std::unique_ptr<SolvedCase> contact_patch_solve(const ContactPatchCase& c) {
  const std::string dir = test_temp_dir(c.dim == 3 ? "contact_patch_3d" : "contact_patch");
  write_text(dir, "blocks.geo", patch_geo(c));
  return solve_case(contact_patch_toml(c), dir);
}

ContactPatchErrors contact_patch_errors(const ContactPatchCase& c) { return contact_patch_errors(c, *contact_patch_solve(c)); }

ContactPatchErrors contact_patch_errors(const ContactPatchCase& c, const SolvedCase& s) {
  ContactPatchErrors e;
  e.geometry_iterations = s.report.geometry_iterations;
  e.ipopt_iterations = s.report.ipopt_iterations;
  e.coulomb_iterations = s.report.coulomb_iterations;
  double umax = 0;
  const Model& m = *s.model;
  const VectorXd load = m.external_load();
  Eigen::Vector3d total_load = Eigen::Vector3d::Zero();
  for (int b = 0; b < m.dofs().num_bodies(); ++b) {
    const Mesh& mesh = m.bodies()[b]->mesh;
    const std::vector<char> upper = upper_block_nodes(c, *m.bodies()[b]);
    for (Index v = 0; v < mesh.num_nodes(); ++v) {
      Eigen::Vector3d exact;
      if (c.dim == 2) {
        // E = 1, ν below y = 1; above it, in the upper block, E_u and ν_u (ContactPatchCase::upper_E).
        const double x = mesh.x(0, v), y = mesh.x(1, v);
        if (upper[v])
          exact << c.upper_nu * (1 + c.upper_nu) * kP * x / c.upper_E,
              -(1 - kNu * kNu) * kP - (1 - c.upper_nu * c.upper_nu) * kP * (y - 1) / c.upper_E, 0.0;
        else
          exact << kNu * (1 + kNu) * kP * x, -(1 - kNu * kNu) * kP * y, 0.0;
      } else {
        exact << kNu * kP * mesh.x(0, v), kNu * kP * mesh.x(1, v), -kP * mesh.x(2, v);
      }
      for (int i = 0; i < c.dim; ++i) {
        e.displacement = std::max(e.displacement, std::abs(s.u[m.dofs().dof(b, v, i)] - exact[i]));
        umax = std::max(umax, std::abs(exact[i]));
        total_load[i] += load[m.dofs().dof(b, v, i)];
      }
    }
  }
  e.displacement /= umax;
  Eigen::Vector3d total_reaction = Eigen::Vector3d::Zero();
  for (const Eigen::VectorXd& r : s.reactions.back()) total_reaction.head(c.dim) += r;
  e.applied_load = total_load.norm();
  e.equilibrium = (total_reaction + total_load).norm() / e.applied_load;
  for (const ContactPairResult& pair : s.contact)
    for (const auto& side : pair.sides)
      for (Index k = 0; k < side.pressure.size(); ++k) {
        e.pressure = std::max(e.pressure, std::abs(side.pressure[k] - kP) / kP);
        e.tangential = std::max(e.tangential, side.tangential.col(k).norm() / kP);
      }
  return e;
}

std::string contact_patch_name(const ContactPatchCase& c) {
  std::string name = std::string(c.dim == 3 ? "3D_" : "") + "n" + std::to_string(c.n1) + "_" + std::to_string(c.n2) +
                     (c.n3 > 0 ? "_" + std::to_string(c.n3) : std::string()) + "_P" + std::to_string(c.order) + "_" +
                     (c.mode == "symmetric" ? std::string("symmetric") : std::string("onepass"));
  if (c.swap) name += "_swapped";
  if (c.mu >= 0) name += "_mu" + std::to_string(static_cast<int>(std::lround(10 * c.mu)));
  if (c.one_body) name += "_one_body";
  if (second_material(c)) name += c.upper_nu == kNu ? "_soft_upper" : "_soft_upper_same_spread";
  if (c.geometry != "current") name += "_" + c.geometry;
  if (!c.quad_blocks.empty()) name += c.dim == 3 ? (c.serendipity ? "_hex20" : "_hex") : (c.serendipity ? "_quad8" : "_quad");
  for (const std::string& q : c.quad_blocks) name += "_" + q;
  return name;
}

}  // namespace symcontact::testing
