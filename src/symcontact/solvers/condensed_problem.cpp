#include "symcontact/solvers/condensed_problem.hpp"

#include <algorithm>
#include <stdexcept>

#include "symcontact/core/error.hpp"

namespace symcontact {

namespace {
/// Records the DOFs of every block added.
class SupportSink : public MatrixSink {
 public:
  void add(const Index* dofs, int n, const double*) override { dofs_.insert(dofs_.end(), dofs, dofs + n); }
  std::vector<Index> take() {
    std::sort(dofs_.begin(), dofs_.end());
    dofs_.erase(std::unique(dofs_.begin(), dofs_.end()), dofs_.end());
    return std::move(dofs_);
  }

 private:
  std::vector<Index> dofs_;
};
}  // namespace

std::vector<Index> support_of(const EnergyTerm& term, const VectorXd& u) {
  SupportSink sink;
  term.add_hessian(u, sink);
  return sink.take();
}

CondensedLoad condense_load(ReducedProblem& bulk, const StaticCondensation& sc) {
  const Index n = bulk.num_free();
  if (sc.size() != n) throw std::invalid_argument("condense_load: sizes of the problem and the condensation differ");
  CondensedLoad l;
  const VectorXd zero = VectorXd::Zero(n);
  bulk.gradient(zero, l.r0);
  const double e0 = bulk.objective(zero);
  // w = K_II⁻¹ r₀_I;  ĝ = r₀_B − (K w)_B;  f₀ = E₀ − ½ r₀ · w  (w_B = 0)
  l.w = sc.solve_interior(l.r0);
  const VectorXd& w = l.w;
  const VectorXd kw = sc.matrix().selfadjointView<Eigen::Lower>() * w;
  const auto& B = sc.boundary();
  l.g_hat.resize(static_cast<Index>(B.size()));
  for (std::size_t k = 0; k < B.size(); ++k) l.g_hat[k] = l.r0[B[k]] - kw[B[k]];
  l.f0 = e0 - 0.5 * l.r0.dot(w);
  return l;
}

CondensedProblem::CondensedProblem(ReducedProblem& bulk, const StaticCondensation& condensation,
                                   std::shared_ptr<const CondensedLoad> load,
                                   std::vector<std::shared_ptr<const EnergyTerm>> extras, const SparseMatrix& A,
                                   const VectorXd& b, const VectorXd& x_reference)
    : bulk_(bulk), sc_(condensation), extras_(std::move(extras)), load_(std::move(load)), x_ref_(x_reference), b_(b) {
  const Index n = bulk_.num_free();
  if (sc_.size() != n || x_reference.size() != n || A.cols() != n || !load_ ||
      load_->g_hat.size() != static_cast<Index>(sc_.boundary().size()))
    throw std::invalid_argument("CondensedProblem: sizes of the condensation, load, reference and constraints differ");
  const auto& B = sc_.boundary();
  // A_B: the constraints' columns in B order.
  const auto& pos = sc_.boundary_position();
  std::vector<Triplet> t;
  t.reserve(A.nonZeros());
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      if (pos[j] < 0) {
        if (it.value() == 0.0) continue;
        throw std::invalid_argument("CondensedProblem: a constraint touches a DOF outside the condensed set");
      }
      t.emplace_back(static_cast<int>(it.row()), static_cast<int>(pos[j]), it.value());
    }
  A_.resize(A.rows(), static_cast<Index>(B.size()));
  A_.setFromTriplets(t.begin(), t.end());
  const auto& free_index = bulk_.free_index();
  dof_to_b_.assign(free_index.size(), -1);
  b_dof_.resize(B.size());
  for (std::size_t d = 0; d < free_index.size(); ++d)
    if (free_index[d] >= 0 && pos[free_index[d]] >= 0) {
      dof_to_b_[d] = pos[free_index[d]];
      b_dof_[pos[free_index[d]]] = static_cast<Index>(d);
    }
  if (!extras_.empty()) {
    u_ = bulk_.expand(x_ref_);
    gu_ = VectorXd::Zero(u_.size());
    for (const auto& term : extras_) {
      const std::vector<Index> s = support_of(*term, u_);
      support_.insert(support_.end(), s.begin(), s.end());
    }
    std::sort(support_.begin(), support_.end());
    support_.erase(std::unique(support_.begin(), support_.end()), support_.end());
  }
}

VectorXd boundary_values(const StaticCondensation& sc, const VectorXd& x) {
  const auto& B = sc.boundary();
  VectorXd y(static_cast<Index>(B.size()));
  for (std::size_t k = 0; k < B.size(); ++k) y[k] = x[B[k]];
  return y;
}

VectorXd with_boundary_values(const StaticCondensation& sc, VectorXd x, const VectorXd& y) {
  const auto& B = sc.boundary();
  for (std::size_t k = 0; k < B.size(); ++k) x[B[k]] = y[k];
  return x;
}

VectorXd expand_condensed(const StaticCondensation& sc, const CondensedLoad& load, const VectorXd& y) {
  if (y.size() != static_cast<Index>(sc.boundary().size()) || load.w.size() != sc.size())
    throw std::invalid_argument("expand_condensed: sizes of y, the load and the condensation differ");
  const VectorXd xb = with_boundary_values(sc, VectorXd::Zero(sc.size()), y);
  // x_I = −K_II⁻¹ (r₀_I + K_IB x_B) = −w_I − K_II⁻¹ K_IB x_B: the load part once per load (CondensedLoad::w),
  // the boundary part by one backward solve (StaticCondensation::boundary_response()).
  return with_boundary_values(sc, sc.boundary_response(xb) - load.w, y);
}

VectorXd CondensedProblem::restrict(const VectorXd& x) const { return boundary_values(sc_, x); }

VectorXd CondensedProblem::expand(const VectorXd& y) const { return expand_condensed(sc_, *load_, y); }

VectorXd CondensedProblem::with_boundary(VectorXd x, const VectorXd& y) const {
  return with_boundary_values(sc_, std::move(x), y);
}

VectorXd CondensedProblem::surface_displacement(const VectorXd& y) const { return bulk_.expand(with_boundary(x_ref_, y)); }

VectorXd CondensedProblem::surface_force(const VectorXd& y, const VectorXd& multipliers) {
  VectorXd g = VectorXd::Zero(y.size());
  add_extras_gradient(y, g);
  g = A_.transpose() * multipliers - g;
  VectorXd f = VectorXd::Zero(static_cast<Index>(dof_to_b_.size()));
  for (std::size_t k = 0; k < b_dof_.size(); ++k) f[b_dof_[k]] = g[static_cast<Index>(k)];
  return f;
}

const VectorXd& CondensedProblem::full_dofs(const VectorXd& y) {
  for (std::size_t k = 0; k < b_dof_.size(); ++k) u_[b_dof_[k]] = y[k];
  return u_;
}

double CondensedProblem::objective(const VectorXd& y) {
  const SparseMatrix& S = sc_.schur_lower();
  double v = load_->f0 + load_->g_hat.dot(y) + 0.5 * y.dot(S.selfadjointView<Eigen::Lower>() * y);
  if (!extras_.empty()) {
    const VectorXd& u = full_dofs(y);
    for (const auto& t : extras_) v += t->value(u);
  }
  return v;
}

void CondensedProblem::gradient(const VectorXd& y, VectorXd& g) {
  const SparseMatrix& S = sc_.schur_lower();
  g = load_->g_hat + S.selfadjointView<Eigen::Lower>() * y;
  add_extras_gradient(y, g);
}

void CondensedProblem::add_extras_gradient(const VectorXd& y, VectorXd& g) {
  if (extras_.empty()) return;
  const VectorXd& u = full_dofs(y);
  for (const auto& t : extras_) t->add_gradient(u, gu_);
  for (const Index d : support_) {
    if (dof_to_b_[d] >= 0) g[dof_to_b_[d]] += gu_[d];
    gu_[d] = 0.0;
  }
  SYMCONTACT_ASSERT(gu_.isZero(0.0));  // the extras touched nothing outside their support
}

void CondensedProblem::hessian_lower(const VectorXd& y, SparseMatrix& H) {
  const SparseMatrix& S = sc_.schur_lower();
  if (extras_.empty()) {
    H = S;
    return;
  }
  const VectorXd& u = full_dofs(y);
  ReducedTripletSink sink(dof_to_b_);
  for (const auto& t : extras_) t->add_hessian(u, sink);
  H = S + sink.to_lower_matrix(static_cast<Index>(sc_.boundary().size()));
}

void CondensedProblem::add_hessian_lower(const VectorXd& y, double s, Eigen::Ref<MatrixXd> M) {
  const SparseMatrix& S = sc_.schur_lower();
  for (Index j = 0; j < S.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(S, j); it; ++it) M(it.row(), j) += s * it.value();  // S is lower
  if (extras_.empty()) return;
  const VectorXd& u = full_dofs(y);
  DenseLowerSink sink(dof_to_b_, s, M.data(), M.outerStride());
  for (const auto& t : extras_) t->add_hessian(u, sink);
}

void CondensedProblem::hessian_product(const VectorXd& y, const VectorXd& v, VectorXd& out) {
  const SparseMatrix& S = sc_.schur_lower();
  out = S.selfadjointView<Eigen::Lower>() * v;
  if (extras_.empty()) return;
  const VectorXd& u = full_dofs(y);
  ProductSink sink(dof_to_b_, v, out);
  for (const auto& t : extras_) t->add_hessian(u, sink);
}

}  // namespace symcontact
