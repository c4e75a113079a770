// Patch tests (Irons; Zienkiewicz & Taylor, The Finite Element Method, vol. 1, §9): a uniform stress
// field σ must be reproduced exactly on any mesh. Displacement u = ε x, ε = C⁻¹ σ, imposed on one face,
// traction σ n on all the others; meshes distorted (structured with moved interior nodes) or
// unstructured from Gmsh, with curved P2 edges on the disk.
#include <gtest/gtest.h>
#include <gmsh.h>
#include <unistd.h>

#include <filesystem>

#include "symcontact/energy/energy_sum.hpp"
#include "symcontact/energy/external_load.hpp"
#include "symcontact/energy/linear_elastic_energy.hpp"
#include "symcontact/mesh/gmsh_io.hpp"
#include "symcontact/mesh/structured.hpp"
#include "symcontact/post/stress_recovery.hpp"
#include "symcontact/solvers/equilibrium_solver.hpp"

using namespace symcontact;

namespace {

/// Strain of a uniform stress under isotropic elasticity: ε = (σ − λ*/(2μ + dλ*) tr σ I)/(2μ),
/// computed by solving C ε = σ on the in-plane (2D) or full (3D) components.
Eigen::Matrix3d strain_of(const LinearElastic& mat, const Eigen::Matrix3d& sigma, int dim) {
  const double tr = sigma.topLeftCorner(dim, dim).trace();
  Eigen::Matrix3d eps = Eigen::Matrix3d::Zero();
  eps.topLeftCorner(dim, dim) =
      (sigma.topLeftCorner(dim, dim) -
       mat.lambda / (2 * mat.mu + dim * mat.lambda) * tr * Eigen::MatrixXd::Identity(dim, dim)) /
      (2 * mat.mu);
  return eps;
}

/// Solves the patch problem on `m`, holding `fixed_face` and loading every other facet group;
/// returns the max displacement error relative to max |u| and the max cell-stress error relative to |σ|.
std::pair<double, double> patch_errors(const Mesh& m, const std::string& fixed_face) {
  const int dim = m.dim;
  const auto mat = LinearElastic::from_young_poisson(1.0, 0.3, dim == 2 ? AnalysisModel::kPlaneStrain : AnalysisModel::kThreeD);
  Eigen::Matrix3d sigma;
  sigma << 1.2, 0.4, -0.3, 0.4, -0.7, 0.25, -0.3, 0.25, 0.5;
  if (dim == 2) sigma.row(2).setZero(), sigma.col(2).setZero();
  const Eigen::Matrix3d eps = strain_of(mat, sigma, dim);
  DofMap dofs(dim);
  dofs.add_body(m.num_nodes());
  EnergySum energy;
  energy.add(std::make_unique<LinearElasticEnergy>(m, dofs, 0, mat, "patch"));
  for (const auto& [name, g] : m.facet_groups) {
    if (name == fixed_face) continue;
    energy.add(std::make_unique<LinearLoad>(
        name, boundary_load_vector(m, dofs, 0, g, [&](const double*, const double* n, double* t) {
          for (int i = 0; i < dim; ++i) {
            t[i] = 0;
            for (int j = 0; j < dim; ++j) t[i] += sigma(i, j) * n[j];
          }
        })));
  }
  auto exact = [&](Index v) {
    Vec3 x = Vec3::Zero();
    x.head(dim) = m.x.col(v);
    return Vec3(eps * x + Vec3(0.01, -0.02, 0.03));
  };
  FixedDofs fixed;
  for (Index v : m.group_nodes(fixed_face))
    for (int i = 0; i < dim; ++i) fixed.fix(dofs.dof(0, v, i), exact(v)[i]);
  VectorXd u = VectorXd::Zero(dofs.num_dofs());
  solve_equilibrium(energy, fixed, u);
  double err = 0, umax = 0;
  for (Index v = 0; v < m.num_nodes(); ++v)
    for (int i = 0; i < dim; ++i) {
      err = std::max(err, std::abs(u[dofs.dof(0, v, i)] - exact(v)[i]));
      umax = std::max(umax, std::abs(exact(v)[i]));
    }
  const BodyFields f = recover_fields(m, dofs, 0, mat, u);
  const Eigen::Matrix<double, 6, 1> s6 = to_voigt6(dim == 2 ? mat.stress(eps) : sigma);
  double serr = 0;
  for (Index c = 0; c < m.num_cells(); ++c) serr = std::max(serr, (f.cell_stress.col(c) - s6).cwiseAbs().maxCoeff());
  return {err / umax, serr / sigma.norm()};
}

/// patch_errors() of m held at `fixed`, printed, both within 1e-10.
void expect_patch_exact(const Mesh& m, const std::string& fixed) {
  const auto [eu, es] = patch_errors(m, fixed);
  std::printf("  %s: displacement error %.2e, cell stress error %.2e\n", m.cell_types_label().c_str(), eu, es);
  EXPECT_LT(eu, 1e-10) << m.cell_types_label();
  EXPECT_LT(es, 1e-10) << m.cell_types_label();
}

}  // namespace

TEST(PatchTest, DistortedStructuredMeshes) {
  for (int order = 1; order <= 2; ++order) {
    Mesh r = rectangle_mesh(0, 0, 2, 1, 6, 4, order);
    perturb_interior_nodes(r, 0.25, 0.3, 42);
    auto [eu, es] = patch_errors(r, "left");
    EXPECT_LT(eu, 1e-10) << "2D P" << order;
    EXPECT_LT(es, 1e-10) << "2D P" << order;
    Mesh b = box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), 3, 3, 3, order);
    perturb_interior_nodes(b, 1.0 / 3, 0.25, 43);
    std::tie(eu, es) = patch_errors(b, "xmin");
    EXPECT_LT(eu, 1e-10) << "3D P" << order;
    EXPECT_LT(es, 1e-10) << "3D P" << order;
  }
}

// Quadrilaterals and hexahedra of every type, interior vertices moved, edge, face and centre nodes on the
// multilinear map of their cell's vertices (perturb_interior_nodes()).
TEST(PatchTest, DistortedQuadrilateralsAndHexahedra) {
  for (CellType t : {CellType::kQuad4, CellType::kQuad8, CellType::kQuad9, CellType::kHex8, CellType::kHex20,
                     CellType::kHex27}) {
    const bool plane = cell_dim(t) == 2;
    Mesh m = plane ? tensor_mesh(t, Vec3(0, 0, 0), Vec3(2, 1, 0), 6, 4) : tensor_mesh(t, Vec3(0, 0, 0), Vec3(1, 1, 1), 3, 3, 3);
    perturb_interior_nodes(m, plane ? 0.25 : 1.0 / 3, 0.25, 44);
    expect_patch_exact(m, plane ? "left" : "xmin");
  }
}

// Prisms: structured boxes of 6- and 18-node ones, interior vertices moved; and one body of prisms under
// tetrahedra read from Gmsh (tests/data/geo/prism_layer.geo), conforming on their common triangles.
TEST(PatchTest, DistortedPrismsAndPrismsUnderTetrahedra) {
  for (CellType t : {CellType::kPrism6, CellType::kPrism15, CellType::kPrism18}) {
    Mesh m = prism_mesh(t, Vec3(0, 0, 0), Vec3(1, 1, 1), 3, 3, 3);
    perturb_interior_nodes(m, 1.0 / 3, 0.25, 45);
    expect_patch_exact(m, "xmin");
  }
  MeshReadOptions o3;
  o3.dim = 3;
  Mesh layer = extract_body(read_mesh_file(std::string(SYMCONTACT_TEST_DATA) + "/geo/prism_layer.geo", o3), 3,
                            "block", "g");
  ASSERT_TRUE(layer.mixed());
  // "sides" holds facets of two types: a node group (a Dirichlet condition may hold it), not a load.
  EXPECT_EQ(layer.facet_groups.count("sides"), 0u);
  EXPECT_EQ(layer.node_groups.count("sides"), 1u);
  EXPECT_NE(layer.interior_facet_groups.at("sides").find("two types"), std::string::npos);
  EXPECT_EQ(layer.facet_type_of(layer.facet_groups.at("sides_prisms")), CellType::kQuad4);
  EXPECT_EQ(layer.facet_type_of(layer.facet_groups.at("sides_tets")), CellType::kTri3);
  expect_patch_exact(layer, "zmin");
}

TEST(PatchTest, UnstructuredGmshMeshesIncludingCurvedP2) {
  const std::string geo = std::string(SYMCONTACT_TEST_DATA) + "/geo/";
  for (int order = 1; order <= 2; ++order) {
    MeshReadOptions o2;
    o2.dim = 2;
    o2.order = order;
    Mesh sq = extract_body(read_mesh_file(geo + "square.geo", o2), 2, "square", "g");
    auto [eu, es] = patch_errors(sq, "bottom");
    EXPECT_LT(eu, 1e-10) << "square P" << order;
    EXPECT_LT(es, 1e-10) << "square P" << order;
    Mesh disk = extract_body(read_mesh_file(geo + "disk.geo", o2), 2, "disk", "g");
    // Hold the rim's nodes with x > 0.5 through a node group; load the whole rim (the held part's
    // traction goes into the reaction).
    std::vector<Index> held;
    for (Index v : disk.group_nodes("rim"))
      if (disk.x(0, v) > 0.5) held.push_back(v);
    disk.node_groups["held"] = held;
    std::tie(eu, es) = patch_errors(disk, "held");
    EXPECT_LT(eu, 1e-10) << "disk P" << order;
    EXPECT_LT(es, 1e-10) << "disk P" << order;
    MeshReadOptions o3;
    o3.dim = 3;
    o3.order = order;
    o3.mesh_size = 0.35;
    Mesh cube = extract_body(read_mesh_file(geo + "cube.geo", o3), 3, "cube", "g");
    std::tie(eu, es) = patch_errors(cube, "zmin");
    EXPECT_LT(eu, 1e-10) << "cube P" << order;
    EXPECT_LT(es, 1e-10) << "cube P" << order;
  }
}

// Pyramids: structured boxes of 5-, 13- and 14-node ones (six per box), interior vertices moved; and one
// body of hexahedra, pyramids and tetrahedra (tests/data/geo/hex_tet.geo) at order 1, at order 2 (Hex27,
// Pyramid14, Tet10) and at incomplete order 2 (Hex20, Pyramid13, Tet10). Gmsh 4.8 builds pyramids once per
// process (gmsh_io.cpp): the geometry is meshed once, written at the three orders, and read back.
TEST(PatchTest, DistortedPyramidsAndHexahedraWithTetrahedra) {
  for (CellType t : {CellType::kPyramid5, CellType::kPyramid13, CellType::kPyramid14}) {
    Mesh m = pyramid_mesh(t, Vec3(0, 0, 0), Vec3(1, 1, 1), 3, 3, 3);
    perturb_interior_nodes(m, 1.0 / 3, 0.25, 46);
    expect_patch_exact(m, "xmin");
  }
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("symcontact_hex_tet_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string names[3] = {(dir / "order1.msh").string(), (dir / "order2.msh").string(), (dir / "order2i.msh").string()};
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(std::string(SYMCONTACT_TEST_DATA) + "/geo/hex_tet.geo");
  gmsh::model::mesh::generate(3);
  gmsh::write(names[0]);
  gmsh::model::mesh::setOrder(2);
  gmsh::write(names[1]);
  gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 1);
  gmsh::model::mesh::setOrder(1);
  gmsh::model::mesh::setOrder(2);
  gmsh::write(names[2]);
  gmsh::finalize();
  const CellType pyramids[3] = {CellType::kPyramid5, CellType::kPyramid14, CellType::kPyramid13};
  for (int variant = 0; variant < 3; ++variant) {
    MeshReadOptions o;
    o.dim = 3;
    o.order = variant == 0 ? 1 : 2;
    Mesh m = extract_body(read_mesh_file(names[variant], o), 3, "block", "g");
    const auto counts = m.cell_type_counts();
    ASSERT_EQ(counts.size(), 3u) << m.cell_types_label();
    bool has_pyramids = false;
    for (const auto& [type, n] : counts) has_pyramids = has_pyramids || type == pyramids[variant];
    EXPECT_TRUE(has_pyramids) << m.cell_types_label();
    EXPECT_EQ(m.node_groups.count("sides"), 1u);
    expect_patch_exact(m, "zmin");
  }
  std::filesystem::remove_all(dir);
}
