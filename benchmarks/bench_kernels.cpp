/// \file bench_kernels.cpp
/// Micro-benchmarks (Google Benchmark) of the per-element work behind the assembly times of
/// symcontact-bench:
///  - stiffness/<cell>: linear_elastic_stiffness() for one element (energy/elastic_kernel.hpp), with the
///    quadrature LinearElasticEnergy uses (degree 0 for P1, 3 for P2);
///  - scatter/<cell>: ReducedTripletSink::add() of one element block with all DOFs free (the other half
///    of an assembly);
///  - mortar3d/<n>: contact_points() of a 3D face against another (the search of every geometry iteration:
///    segmentation, quadrature points, their projections): the top face of a box of n × n × 1 cubes (six
///    tetrahedra each) as master, the bottom face of a box of (n + 1) × (n + 1) × 1 lying on it as slave,
///    non-matching. items_per_second there is slave facets per second, and the counter `points` the
///    contact points of one search;
///  - hyperelastic_tangent/<dim>: Hyperelastic::evaluate_displacement_gradient() of a Neo-Hookean point with
///    its stress and tangent (materials/hyperelastic.hpp), the material law of every quadrature point of a
///    finite-strain Hessian; 2: plane strain.
/// items_per_second is elements per second.
///
///   OPENBLAS_NUM_THREADS=1 symcontact_bench_kernels --benchmark_min_time=0.5

#include <benchmark/benchmark.h>

#include <numeric>
#include <string>
#include <vector>

#include "symcontact/contact/contact_points.hpp"
#include "symcontact/contact/contact_surface.hpp"
#include "symcontact/energy/elastic_kernel.hpp"
#include "symcontact/fem/cell_dispatch.hpp"
#include "symcontact/fem/matrix_sink.hpp"
#include "symcontact/fem/quadrature.hpp"
#include "symcontact/fem/shape_functions.hpp"
#include "symcontact/materials/hyperelastic.hpp"
#include "symcontact/materials/linear_elastic.hpp"
#include "symcontact/mesh/structured.hpp"

namespace {

using symcontact::CellType;

/// The reference element of `t` mapped by a fixed, well-shaped but non-trivial affine map (so
/// that no entry of J is 0 or 1) and scaled to size h = 0.01.
template <int D, int NN>
Eigen::Matrix<double, D, NN> sample_element(CellType t) {
  const std::vector<double> ref = symcontact::reference_nodes(t);
  Eigen::Matrix<double, D, D> A;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) A(i, j) = (i == j ? 1.0 : 0.15 * (i + 1) - 0.1 * j);
  Eigen::Matrix<double, D, NN> X;
  for (int a = 0; a < NN; ++a) {
    const Eigen::Map<const Eigen::Matrix<double, D, 1>> xi(ref.data() + a * D);
    X.col(a) = 0.01 * (A * xi) + Eigen::Matrix<double, D, 1>::Constant(0.3);
  }
  return X;
}

int quadrature_degree(CellType t) { return symcontact::cell_order(t) == 1 ? 0 : 3; }

symcontact::LinearElastic material(int dim) {
  return symcontact::LinearElastic::from_young_poisson(
      1.0, 0.3, dim == 2 ? symcontact::AnalysisModel::kPlaneStrain : symcontact::AnalysisModel::kThreeD);
}

void element_stiffness(benchmark::State& state, CellType t) {
  symcontact::dispatch_cell(t, [&](auto Dc, auto NNc) {
    constexpr int D = decltype(Dc)::value, NN = decltype(NNc)::value;
    const symcontact::Tabulation tab =
        symcontact::tabulate(t, symcontact::simplex_quadrature(D, quadrature_degree(t)));
    const auto mat = material(D);
    Eigen::Matrix<double, D, NN> X = sample_element<D, NN>(t);
    Eigen::Matrix<double, D * NN, D * NN> K;
    for (auto _ : state) {
      benchmark::DoNotOptimize(X.data());
      int bad = symcontact::linear_elastic_stiffness<D, NN>(X, tab, mat.lambda, mat.mu, mat.model, K);
      benchmark::DoNotOptimize(bad);
      benchmark::DoNotOptimize(K.data());
      benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["quad_points"] = tab.rule.size();
    state.counters["block"] = D * NN;
  });
}

void element_scatter(benchmark::State& state, CellType t) {
  symcontact::dispatch_cell(t, [&](auto Dc, auto NNc) {
    constexpr int D = decltype(Dc)::value, NN = decltype(NNc)::value;
    constexpr int n = D * NN;
    const symcontact::Tabulation tab =
        symcontact::tabulate(t, symcontact::simplex_quadrature(D, quadrature_degree(t)));
    const auto mat = material(D);
    Eigen::Matrix<double, n, n> K;
    symcontact::linear_elastic_stiffness<D, NN>(sample_element<D, NN>(t), tab, mat.lambda, mat.mu, mat.model, K);
    // A few thousand distinct elements' worth of DOFs, all free, scattered far apart like a real mesh.
    constexpr int kElements = 4096;
    std::vector<symcontact::Index> free_index(static_cast<std::size_t>(kElements) * n);
    std::iota(free_index.begin(), free_index.end(), symcontact::Index{0});
    std::vector<symcontact::Index> dofs(free_index.size());
    std::iota(dofs.begin(), dofs.end(), symcontact::Index{0});
    symcontact::ReducedTripletSink sink(free_index);
    sink.triplets().reserve(static_cast<std::size_t>(kElements) * n * (n + 1) / 2);
    int e = 0;
    for (auto _ : state) {
      sink.add(dofs.data() + static_cast<std::size_t>(e) * n, n, K.data());
      if (++e == kElements) {
        e = 0;
        sink.triplets().clear();  // keeps the capacity: no reallocation inside the timing
      }
    }
    benchmark::DoNotOptimize(sink.triplets().data());
    state.SetItemsProcessed(state.iterations());
  });
}

void mortar_search_3d(benchmark::State& state) {
  using symcontact::Vec3;
  const int n = static_cast<int>(state.range(0));
  const symcontact::Mesh lower = symcontact::box_mesh(Vec3(0, 0, -0.2), Vec3(1, 1, 0), n, n, 1);
  const symcontact::Mesh upper = symcontact::box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 0.2), n + 1, n + 1, 1);
  const auto model = symcontact::AnalysisModel::kThreeD;
  const symcontact::ContactSurface master = symcontact::make_contact_surface(lower, "zmax", 0, "lower", model);
  const symcontact::ContactSurface slave = symcontact::make_contact_surface(upper, "zmin", 1, "upper", model);
  const symcontact::MasterGeometry geometry = symcontact::prepare_master(master, master.X);
  symcontact::ContactSearchOptions options;
  options.search_distance = 0.5 / n;
  std::size_t points = 0;
  for (auto _ : state) {
    const std::vector<symcontact::ContactPoint> cp = symcontact::contact_points(slave, slave.X, geometry, options);
    points = cp.size();
    benchmark::DoNotOptimize(cp.data());
  }
  state.SetItemsProcessed(state.iterations() * slave.num_facets());
  state.counters["points"] = static_cast<double>(points);
}

template <int D>
void hyperelastic_tangent(benchmark::State& state) {
  const auto m = symcontact::Hyperelastic::from_young_poisson(symcontact::HyperelasticLaw::kNeoHookean, 1.0, 0.3);
  Eigen::Matrix<double, D, D> H;  // a displacement gradient of a few per cent, no entry 0
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) H(i, j) = 0.05 * (i + 1) - 0.03 * j + 0.01;
  Eigen::Matrix<double, D, D> P;
  Eigen::Matrix<double, D * D, D * D> A;
  for (auto _ : state) {
    benchmark::DoNotOptimize(m.evaluate_displacement_gradient<D>(H, &P, &A));
    benchmark::DoNotOptimize(A.data());
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

int main(int argc, char** argv) {
  for (const CellType t : {CellType::kTri3, CellType::kTri6, CellType::kTet4, CellType::kTet10}) {
    const std::string name = symcontact::cell_name(t);
    benchmark::RegisterBenchmark(("stiffness/" + name).c_str(), element_stiffness, t);
    benchmark::RegisterBenchmark(("scatter/" + name).c_str(), element_scatter, t);
  }
  benchmark::RegisterBenchmark("mortar3d", mortar_search_3d)->Arg(8)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("hyperelastic_tangent/2", hyperelastic_tangent<2>);
  benchmark::RegisterBenchmark("hyperelastic_tangent/3", hyperelastic_tangent<3>);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
