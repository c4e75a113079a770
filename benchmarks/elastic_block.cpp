#include "elastic_block.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <string>
#include <limits>

#include "symcontact/core/error.hpp"
#include "symcontact/energy/external_load.hpp"
#include "symcontact/fem/matrix_sink.hpp"
#include "symcontact/materials/linear_elastic.hpp"
#include "symcontact/mesh/structured.hpp"
#include "symcontact/solvers/cholesky.hpp"

#include "bench_support.hpp"

namespace symcontact::bench {

namespace {

constexpr double kYoung = 1.0, kPoisson = 0.3, kPressure = 1e-3;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

void check_factor_fits(double nnz_factor, double other_bytes) {
  const double available = available_memory_bytes();
  const double need = 8.0 * nnz_factor + other_bytes;
  if (available > 0 && need > available)
    throw FactorTooLarge("the factor needs " + std::to_string(8.0 * nnz_factor / (1 << 30)) + " GiB for nnz(L) = " +
                         std::to_string(static_cast<long long>(nnz_factor)) +
                         (other_bytes > 0 ? " (plus " + std::to_string(other_bytes / (1 << 30)) + " GiB)" : "") +
                         " but only " + std::to_string(available / (1 << 30)) + " GiB are available");
}

namespace {

/// K_ff: the energy's Hessian at 0 (constant) assembled over the free DOFs, lower triangle.
SparseMatrix assemble_free_stiffness(const EnergyTerm& energy, const std::vector<Index>& free_index, Index num_free,
                                     Index* num_triplets = nullptr) {
  ReducedTripletSink sink(free_index);
  energy.add_hessian(VectorXd::Zero(static_cast<Index>(free_index.size())), sink);  // K does not depend on u
  if (num_triplets) *num_triplets = static_cast<Index>(sink.triplets().size());
  return sink.to_lower_matrix(num_free);
}

}  // namespace

Index block_dofs(int dim, int order, int divisions) {
  const Index side = static_cast<Index>(order) * divisions + 1;
  Index nodes = 1;
  for (int d = 0; d < dim; ++d) nodes *= side;
  return dim * nodes;
}

int block_divisions(int dim, int order, double target_dofs) {
  const double side = std::pow(target_dofs / dim, 1.0 / dim);  // nodes per side
  int best = std::max(1, static_cast<int>(std::lround((side - 1) / order)));
  // The rounding above is on the side; pick the neighbour nearest in DOFs.
  for (const int n : {best - 1, best + 1})
    if (n >= 1 && std::abs(block_dofs(dim, order, n) - target_dofs) <
                      std::abs(block_dofs(dim, order, best) - target_dofs))
      best = n;
  return best;
}

ElasticBlock::ElasticBlock(int dim_, int order_, int divisions_)
    : dim(dim_), order(order_), divisions(divisions_), dofs(dim_) {
  auto t0 = std::chrono::steady_clock::now();
  mesh = dim == 2 ? rectangle_mesh(0, 0, 1, 1, divisions, divisions, order)
                  : box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), divisions, divisions, divisions, order);
  mesh_seconds = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  const int body = dofs.add_body(mesh.num_nodes());
  for (const Index node : mesh.group_nodes(dim == 2 ? "bottom" : "zmin"))
    for (int i = 0; i < dim; ++i) fixed.fix(dofs.dof(body, node, i), 0.0);
  num_free = fixed.free_numbering(dofs.num_dofs(), free_index);

  const int d = dim;
  const VectorXd f = boundary_load_vector(mesh, dofs, body, mesh.facet_groups.at(dim == 2 ? "top" : "zmax"),
                                          [d](const double*, const double* n, double* t) {
                                            for (int i = 0; i < d; ++i) t[i] = -kPressure * n[i];
                                          });
  load_free.resize(num_free);
  for (Index k = 0; k < f.size(); ++k)
    if (free_index[k] >= 0) load_free[free_index[k]] = f[k];

  const auto material = LinearElastic::from_young_poisson(
      kYoung, kPoisson, dim == 2 ? AnalysisModel::kPlaneStrain : AnalysisModel::kThreeD);
  energy_ = std::make_unique<LinearElasticEnergy>(mesh, dofs, body, material, "block");
  setup_seconds = seconds_since(t0);
}

CholeskyFloor measure_cholesky_floor(const ElasticBlock& block, int repeat) {
  return measure_cholesky_floor(block.energy(), block.free_index, block.num_free, block.load_free, repeat);
}

CholeskyFloor measure_cholesky_floor(const EnergyTerm& energy, const std::vector<Index>& free_index, Index num_free,
                                     const VectorXd& load_free, int repeat) {
  CholeskyFloor r;
  constexpr double inf = std::numeric_limits<double>::infinity();
  r.assembly = r.gradient = r.analyze = r.factorize = r.solve = r.cpu_factor_and_solve = inf;
  const Index n = num_free;
  const auto num_dofs = static_cast<Index>(free_index.size());
  VectorXd u_free;
  for (int rep = 0; rep < std::max(1, repeat); ++rep) {
    SparseMatrix K;
    auto t0 = std::chrono::steady_clock::now();
    K = assemble_free_stiffness(energy, free_index, n, &r.num_triplets);
    r.assembly = std::min(r.assembly, seconds_since(t0));

    CholeskySolver chol;
    const double cpu0 = process_cpu_seconds();
    t0 = std::chrono::steady_clock::now();
    chol.analyze(K);
    r.analyze = std::min(r.analyze, seconds_since(t0));
    check_factor_fits(chol.factor_nonzeros());
    t0 = std::chrono::steady_clock::now();
    chol.factorize(K);
    r.factorize = std::min(r.factorize, seconds_since(t0));
    t0 = std::chrono::steady_clock::now();
    u_free = chol.solve(load_free);
    r.solve = std::min(r.solve, seconds_since(t0));
    r.cpu_factor_and_solve = std::min(r.cpu_factor_and_solve, process_cpu_seconds() - cpu0);
    r.nnz_factor = chol.factor_nonzeros();

    r.nnz_lower = K.nonZeros();
    r.nnz_full = 2 * r.nnz_lower - n;
    const VectorXd res = K.selfadjointView<Eigen::Lower>() * u_free - load_free;
    r.relative_residual = res.norm() / load_free.norm();
    r.max_displacement = u_free.cwiseAbs().maxCoeff();
  }

  // The gradient at the solution (its value does not matter for the time, but it is a real state).
  VectorXd u = VectorXd::Zero(num_dofs), g(u.size());
  for (Index k = 0; k < u.size(); ++k)
    if (free_index[k] >= 0) u[k] = u_free[free_index[k]];
  // A finite-strain energy may not be evaluable there (the linear response inverts cells): then at a
  // small multiple of it.
  try {
    energy.add_gradient(u, g);
  } catch (const EvaluationError&) {
    u *= 1e-6 / std::max(u.cwiseAbs().maxCoeff(), 1e-300);
  }
  for (int rep = 0; rep < std::max(1, repeat); ++rep) {
    g.setZero();
    const auto t0 = std::chrono::steady_clock::now();
    energy.add_gradient(u, g);
    r.gradient = std::min(r.gradient, seconds_since(t0));
  }
  return r;
}

}  // namespace symcontact::bench
