#include "symcontact/energy/hyperelastic_energy.hpp"

#include <stdexcept>

#include "symcontact/core/error.hpp"
#include "symcontact/fem/cell_dispatch.hpp"
#include "symcontact/fem/element_geometry.hpp"

namespace symcontact {

namespace {

/// Element kernel (no assembly; STYLE.md §3). X: reference coordinates (D × NN), U: nodal displacements
/// (D × NN). What = 0: energy only; 1: + local gradient g (D·NN); 2: + local Hessian K (D·NN square).
/// Returns the first quadrature point with a reference Jacobian det ≤ 0, or −1; a det F ≤ 0 at a point
/// propagates the material's EvaluationError.
template <int D, int NN, int What>
int hyperelastic_element(const Eigen::Matrix<double, D, NN>& X, const Eigen::Matrix<double, D, NN>& U,
                         const Tabulation& tab, const Hyperelastic& material, double& e,
                         Eigen::Matrix<double, D * NN, 1>& g, Eigen::Matrix<double, D * NN, D * NN>& K) {
  e = 0.0;
  if constexpr (What >= 1) g.setZero();
  if constexpr (What >= 2) K.setZero();
  Eigen::Matrix<double, NN, D> G;
  Eigen::Matrix<double, D, D> P;
  Eigen::Matrix<double, D * D, D * D> A;
  for (int q = 0; q < tab.rule.size(); ++q) {
    const double det = physical_gradients<D, NN>(X, tab.dN_at(q), G);
    if (!(det > 0)) return q;
    const double w = tab.rule.weights[q] * det;
    // H = ∇_X u = Σ_a u_a ⊗ G_a; F = I + H is formed inside the material (keeps small H accurate).
    const Eigen::Matrix<double, D, D> H = U * G;
    e += w * material.evaluate_displacement_gradient<D>(H, What >= 1 ? &P : nullptr, What >= 2 ? &A : nullptr);
    if constexpr (What >= 1) {
      const Eigen::Matrix<double, D, NN> PG = P * G.transpose();  // (i, a) = P_iJ G_aJ
      for (int a = 0; a < NN; ++a)
        for (int i = 0; i < D; ++i) g[D * a + i] += w * PG(i, a);
    }
    if constexpr (What >= 2) {
      // B(iJ, (b,k)) = A_iJkL G_bL, then K_(a,i),(b,k) += w G_aJ B(iJ, (b,k)).
      Eigen::Matrix<double, D * D, D * NN> B;
      for (int b = 0; b < NN; ++b)
        for (int k = 0; k < D; ++k)
          for (int r = 0; r < D * D; ++r) {
            double s = 0.0;
            for (int L = 0; L < D; ++L) s += A(r, D * k + L) * G(b, L);
            B(r, D * b + k) = s;
          }
      for (int a = 0; a < NN; ++a)
        for (int i = 0; i < D; ++i)
          for (int J = 0; J < D; ++J) K.row(D * a + i) += (w * G(a, J)) * B.row(D * i + J);
    }
  }
  return -1;
}

/// The axisymmetric kernel (D = 2; header: F with F_θθ = 1 + u_r/R, weights × 2πR), same contract.
template <int NN, int What>
int hyperelastic_element_axisymmetric(const Eigen::Matrix<double, 2, NN>& X, const Eigen::Matrix<double, 2, NN>& U,
                                      const Tabulation& tab, const Hyperelastic& material, double& e,
                                      Eigen::Matrix<double, 2 * NN, 1>& g,
                                      Eigen::Matrix<double, 2 * NN, 2 * NN>& K) {
  e = 0.0;
  if constexpr (What >= 1) g.setZero();
  if constexpr (What >= 2) K.setZero();
  Eigen::Matrix<double, NN, 2> G;
  Eigen::Matrix3d P;
  Eigen::Matrix<double, 9, 9> A;
  Eigen::Matrix<double, 9, 2 * NN> B = Eigen::Matrix<double, 9, 2 * NN>::Zero();  // ∂ vec F / ∂u, row 3i + J
  for (int q = 0; q < tab.rule.size(); ++q) {
    const double det = physical_gradients<2, NN>(X, tab.dN_at(q), G);
    if (!(det > 0)) return q;
    const Eigen::Map<const Eigen::Matrix<double, NN, 1>> N(tab.N_at(q));
    const double R = X.row(0).dot(N);
    if (!(R > 0)) return q;
    const double w = tab.rule.weights[q] * det * section_measure(AnalysisModel::kAxisymmetric, R);
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    H.topLeftCorner<2, 2>() = U * G;
    H(2, 2) = U.row(0).dot(N) / R;
    e += w * material.evaluate_displacement_gradient<3>(H, What >= 1 ? &P : nullptr, What >= 2 ? &A : nullptr);
    if constexpr (What >= 1) {
      for (int b = 0; b < NN; ++b) {
        for (int k = 0; k < 2; ++k)
          for (int L = 0; L < 2; ++L) B(3 * k + L, 2 * b + k) = G(b, L);
        B(8, 2 * b) = N[b] / R;
      }
      const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> P_rows = P;  // vec P in the rows' order 3i + J
      g.noalias() += w * B.transpose() * Eigen::Map<const Eigen::Matrix<double, 9, 1>>(P_rows.data());
    }
    if constexpr (What >= 2) K.noalias() += w * B.transpose() * A * B;
  }
  return -1;
}

}  // namespace

HyperelasticEnergy::HyperelasticEnergy(const Mesh& mesh, const DofMap& dofs, int body,
                                       const Hyperelastic& material, std::string label, AnalysisModel model)
    : HyperelasticEnergy(mesh, dofs, body, std::vector<Hyperelastic>{material}, {}, std::move(label), model) {}

HyperelasticEnergy::HyperelasticEnergy(const Mesh& mesh, const DofMap& dofs, int body,
                                       std::vector<Hyperelastic> materials, std::vector<int> cell_material,
                                       std::string label, AnalysisModel model)
    : mesh_(mesh),
      offset_(dofs.offset(body)),
      materials_(std::move(materials), std::move(cell_material), mesh.num_cells()),
      label_(std::move(label)),
      model_(model) {
  if (mesh.dim != 2 && mesh.dim != 3)
    throw std::logic_error("HyperelasticEnergy: a 2D (plane strain) or 3D mesh is required");
  // Same rule as LinearElasticEnergy (see the header for why).
  for (const CellBlock& b : mesh.cell_blocks)
    tabs_.push_back(tabulate(b.type, cell_quadrature(b.type, stiffness_quadrature_degree(b.type, model))));
  // Validates every reference cell once (at u = 0, F = I everywhere).
  for_each_cell<0>(VectorXd::Zero(offset_ + dofs.num_body_dofs(body)), [](const Index*, double, const auto&,
                                                                          const auto&) {});
}

template <int What, class Fn>
void HyperelasticEnergy::for_each_cell(const VectorXd& u, Fn&& f) const {
  for (std::size_t b = 0; b < tabs_.size(); ++b) {
    const CellBlock& block = mesh_.cell_blocks[b];
    const Tabulation& tab = tabs_[b];
    dispatch_cell(block.type, [&](auto Dc, auto NNc) {
      constexpr int D = decltype(Dc)::value, NN = decltype(NNc)::value;
      if constexpr (D < 2) {
        throw std::logic_error("HyperelasticEnergy: a 2D (plane strain) or 3D mesh is required");
      } else {
        Eigen::Matrix<double, D * NN, 1> g;
        Eigen::Matrix<double, D * NN, D * NN> K;
        Eigen::Matrix<double, D, NN> U;
        Index dofs[D * NN];
        double e = 0.0;
        for (Index c = block.begin; c < block.end; ++c) {
          const Index* n = mesh_.cell(c);
          for (int a = 0; a < NN; ++a)
            for (int i = 0; i < D; ++i) {
              dofs[D * a + i] = offset_ + D * n[a] + i;
              U(i, a) = u[dofs[D * a + i]];
            }
          const auto X = gather_coordinates<D, NN>(mesh_.x, n);
          int bad = -1;
          try {
            const Hyperelastic& material = materials_.of(c);
            if constexpr (D == 2)
              bad = model_ == AnalysisModel::kAxisymmetric
                        ? hyperelastic_element_axisymmetric<NN, What>(X, U, tab, material, e, g, K)
                        : hyperelastic_element<D, NN, What>(X, U, tab, material, e, g, K);
            else
              bad = hyperelastic_element<D, NN, What>(X, U, tab, material, e, g, K);
          } catch (const EvaluationError& err) {
            throw EvaluationError(name() + ": " + mesh_.cell_label(c) + ": " + err.what());
          }
          if (bad >= 0) throw InputError("", label_ + ": " + mesh_.cell_label(c), bad_cell_message(model_));
          f(static_cast<const Index*>(dofs), e, g, K);
        }
      }
    });
  }
}

double HyperelasticEnergy::value(const VectorXd& u) const {
  double total = 0.0;
  for_each_cell<0>(u, [&](const Index*, double e, const auto&, const auto&) { total += e; });
  return total;
}

void HyperelasticEnergy::add_gradient(const VectorXd& u, VectorXd& g) const {
  for_each_cell<1>(u, [&](const Index* dofs, double, const auto& ge, const auto&) {
    for (int k = 0; k < ge.size(); ++k) g[dofs[k]] += ge[k];
  });
}

void HyperelasticEnergy::add_hessian(const VectorXd& u, MatrixSink& sink) const {
  for_each_cell<2>(u, [&](const Index* dofs, double, const auto&, const auto& K) {
    sink.add(dofs, static_cast<int>(K.rows()), K.data());
  });
}

}  // namespace symcontact
