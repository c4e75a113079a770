#include "symcontact/energy/linear_elastic_energy.hpp"

#include "symcontact/core/error.hpp"
#include "symcontact/energy/elastic_kernel.hpp"
#include "symcontact/fem/cell_dispatch.hpp"

namespace symcontact {

LinearElasticEnergy::LinearElasticEnergy(const Mesh& mesh, const DofMap& dofs, int body,
                                         const LinearElastic& material, std::string label)
    : LinearElasticEnergy(mesh, dofs, body, std::vector<LinearElastic>{material}, {}, std::move(label)) {}

LinearElasticEnergy::LinearElasticEnergy(const Mesh& mesh, const DofMap& dofs, int body,
                                         std::vector<LinearElastic> materials, std::vector<int> cell_material,
                                         std::string label)
    : mesh_(mesh),
      offset_(dofs.offset(body)),
      materials_(std::move(materials), std::move(cell_material), mesh.num_cells()),
      label_(std::move(label)) {
  const AnalysisModel model = materials_.front().model;
  for (const CellBlock& b : mesh.cell_blocks)
    tabs_.push_back(tabulate(b.type, cell_quadrature(b.type, stiffness_quadrature_degree(b.type, model))));
  for_each_cell([](Index, const Index*, const auto&) {});  // validates every cell once
}

template <class F>
void LinearElasticEnergy::for_each_cell(F&& f) const {
  for (std::size_t b = 0; b < tabs_.size(); ++b) {
    const CellBlock& block = mesh_.cell_blocks[b];
    dispatch_cell(block.type, [&](auto Dc, auto NNc) {
      constexpr int D = decltype(Dc)::value, NN = decltype(NNc)::value;
      Eigen::Matrix<double, D * NN, D * NN> K;
      Index dofs[D * NN];
      for (Index c = block.begin; c < block.end; ++c) {
        const Index* n = mesh_.cell(c);
        const auto X = gather_coordinates<D, NN>(mesh_.x, n);
        const LinearElastic& m = materials_.of(c);
        if (linear_elastic_stiffness<D, NN>(X, tabs_[b], m.lambda, m.mu, m.model, K) >= 0)
          throw InputError("", label_ + ": " + mesh_.cell_label(c), bad_cell_message(m.model));
        for (int a = 0; a < NN; ++a)
          for (int i = 0; i < D; ++i) dofs[D * a + i] = offset_ + D * n[a] + i;
        f(c, static_cast<const Index*>(dofs), K);
      }
    });
  }
}

double LinearElasticEnergy::value(const VectorXd& u) const {
  double e = 0.0;
  for_each_cell([&](Index, const Index* dofs, const auto& K) {
    using Vec = Eigen::Matrix<double, std::decay_t<decltype(K)>::RowsAtCompileTime, 1>;
    Vec ue;
    for (int k = 0; k < ue.size(); ++k) ue[k] = u[dofs[k]];
    e += 0.5 * ue.dot(K * ue);
  });
  return e;
}

void LinearElasticEnergy::add_gradient(const VectorXd& u, VectorXd& g) const {
  for_each_cell([&](Index, const Index* dofs, const auto& K) {
    using Vec = Eigen::Matrix<double, std::decay_t<decltype(K)>::RowsAtCompileTime, 1>;
    Vec ue;
    for (int k = 0; k < ue.size(); ++k) ue[k] = u[dofs[k]];
    const Vec ge = K * ue;
    for (int k = 0; k < ue.size(); ++k) g[dofs[k]] += ge[k];
  });
}

void LinearElasticEnergy::add_hessian(const VectorXd&, MatrixSink& sink) const {
  for_each_cell([&](Index, const Index* dofs, const auto& K) {
    sink.add(dofs, static_cast<int>(K.rows()), K.data());
  });
}

}  // namespace symcontact
