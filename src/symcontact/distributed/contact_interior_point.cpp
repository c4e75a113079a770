#include "symcontact/distributed/contact_interior_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "symcontact/distributed/petsc_support.hpp"

namespace symcontact {

using petsc::check;
using petsc::Owned;

namespace {

/// A search direction: Δu (distributed), Δs and Δλ (whole on every rank).
struct Direction {
  VectorXd ds, dl;
};

// Regularised Tresca friction at the rows' friction points, from V (dim × m: the points' relative
// displacements B_j u); with s = P (v − v⁰) (P = I − n nᵀ, v⁰ the slip origin) and r = √(|s|² + α²) ≥ α:
// j_j = g r, ∂j_j/∂v = g s / r, ∂²j_j/∂v² = g (P − s sᵀ / r²) / r (P s = s); ∇j = Σ_j B_jᵀ ∂j_j/∂v and
// ∇²j = Σ_j B_jᵀ ∂²j_j/∂v² B_j. Nothing divides by the slip itself.
//
// Along the slip the curvature g α² / r³ is tiny once |s| ≫ α: at a point that slips at the iterate and sticks
// at the answer, Newton's step along s is (r / α)² times too long, and the line search cuts the step of every
// DOF to match (two cylinders pressed together, V8: steps of 1–3 % for 80 iterations). The interior point
// therefore linearises the friction law in primal-dual form (Chan, Golub & Mulet, SIAM J. Sci. Comput. 20,
// 1999, for total variation; the same function of the slip): w = s / r held as a variable of its own, |w| ≤ 1,
// r w − s = 0 linearised in (s, w) gives Δw = ((I − w sᵀ / r) Δs + s − r w) / r, and the curvature of j_j in
// the Newton matrix becomes g (P − (w sᵀ + s wᵀ) / 2r) / r, the exact one where w = s / r, positive
// semidefinite whenever |w| ≤ 1, and g / r along s while w lags behind a slip that has just grown.

VectorXd slip(const NodalConstraints& c, const Eigen::MatrixXd& V, Index j) {
  const VectorXd d = c.slip_origin.size() > 0 ? VectorXd(V.col(j) - c.slip_origin.col(j)) : VectorXd(V.col(j));
  return d - c.normal.col(j) * c.normal.col(j).dot(d);
}

double friction_energy(const NodalConstraints& c, const Eigen::MatrixXd& V) {
  double e = 0.0;
  for (Index j = 0; j < c.size(); ++j)
    e += c.friction_bound[j] * std::sqrt(slip(c, V, j).squaredNorm() + c.friction_alpha[j] * c.friction_alpha[j]);
  return e;
}

Eigen::MatrixXd friction_gradient(const NodalConstraints& c, const Eigen::MatrixXd& V) {
  Eigen::MatrixXd G(V.rows(), V.cols());
  for (Index j = 0; j < c.size(); ++j) {
    const VectorXd s = slip(c, V, j);
    G.col(j) = c.friction_bound[j] / std::sqrt(s.squaredNorm() + c.friction_alpha[j] * c.friction_alpha[j]) * s;
  }
  return G;
}

/// Point j's block of ∇²j, or with W (dim × m, the points' dual slip directions w) the primal-dual block.
Eigen::MatrixXd friction_hessian(const NodalConstraints& c, const Eigen::MatrixXd& V, Index j,
                                 const Eigen::MatrixXd* W = nullptr) {
  const Index dim = V.rows();
  const VectorXd n = c.normal.col(j), s = slip(c, V, j);
  const double r2 = s.squaredNorm() + c.friction_alpha[j] * c.friction_alpha[j], r = std::sqrt(r2);
  const Eigen::MatrixXd P = Eigen::MatrixXd::Identity(dim, dim) - n * n.transpose();
  if (!W) return c.friction_bound[j] / r * (P - s * s.transpose() / r2);
  const VectorXd w = W->col(j);
  return c.friction_bound[j] / r * (P - 0.5 * (w * s.transpose() + s * w.transpose()) / r);
}

/// The complementarity (over the tolerance) below which the bounds stop following the iterates (run()).
constexpr double kFollowAbove = 1e-3;
/// The complementarity (max_j min(s_j / L, λ_j / F)) and the scaled dual and primal residuals, over the
/// tolerance, below which the polish is first tried. The polish balances the forces itself, so r_d need not
/// meet the tolerance first: on two rings wholly in contact (one-pass) it lagged a step behind the others,
/// and that step's Newton system, Σ at 1e12 F/L, broke conjugate gradients down.
constexpr double kPolishBelow = 1e3;
/// What a polish must reach, as fractions of the tolerance: the forces balanced to `forces` tol F, the active
/// rows closed to `gaps` tol L.
struct PolishAccuracy {
  double forces, gaps;
};
/// The polish during the iterations and at their end (as the header says): the contact forces are recovered
/// from K u − f, which multiplies an error in u by K (on V1 its largest entry is 3·10³ F/L), hence the gaps'
/// 10⁻⁴: V1's pressures then agree with the serial solver's to 1e-8 of their scale (at 10⁻², to 3e-8 at the
/// edge of the zone). The method of multipliers gains about two digits a step: a step or two more.
constexpr PolishAccuracy kEarly{1e-2, 1e-4};
/// The rescue before giving up: the interior point's own test.
constexpr PolishAccuracy kRescue{1.0, 1.0};

/// How the method of multipliers on one active set ends (InteriorPoint::polish_on).
enum class PolishOutcome {
  kClosed,           ///< the rows of S closed and the forces balanced, to the accuracy asked
  kRowsCannotClose,  ///< ‖c_S‖ stopped halving: S holds rows that no point closes together
  kFailed,           ///< out of steps, or the Krylov solve broke down
};

/// An iterate (u, s, λ) with the result's figures at it: what a polish that is not accepted gives back.
struct Iterate {
  Owned<Vec, VecDestroy> u;
  VectorXd s, lambda;
  double dual_residual = 0.0, primal_residual = 0.0, complementarity = 0.0;
  std::string reason;
};

class InteriorPoint {
 public:
  InteriorPoint(const SparseMatrix& K_share, const VectorXd& f, const std::vector<Index>& fixed,
                const VectorXd& fixed_values, const Eigen::MatrixXd& x, const NodalConstraints& c,
                const ContactInteriorPointOptions& options, const VectorXd* start);
  ContactInteriorPointResult run(const FollowBounds* follow);

 private:
  void assemble(const SparseMatrix& K_share, const VectorXd& f, const std::vector<Index>& fixed,
                const VectorXd& fixed_values, const Eigen::MatrixXd& x);
  void build_rows(const std::vector<Index>& fixed, const VectorXd& fixed_values, Index n);
  void create_constraint_scatter();
  void set_scales(const VectorXd& fixed_values, double max_diagonal);
  void create_solver();
  VectorXd gather(Vec v);
  Eigen::MatrixXd slip_values(const VectorXd& g) const;
  void add_gathered(const VectorXd& w, Vec out);
  void add_transpose(const VectorXd& w, Vec out);
  VectorXd residuals(const VectorXd& g, const Eigen::MatrixXd& V);
  double merit(double alpha, const Direction& d, double target, double nu, const Eigen::MatrixXd& V,
               const Eigen::MatrixXd& dV, const VectorXd& rp);
  double line_search(double alpha, const Direction& d, double target, const VectorXd& rp, const Eigen::MatrixXd& V);
  SparseMatrix newton_pattern(const SparseMatrix& K_share) const;
  void zero_fixed_rows(Vec v);
  SparseMatrix slip_map(Index n) const;
  void update_newton_matrix(const Eigen::MatrixXd& V, const VectorXd& sigma, const Eigen::MatrixXd* W = nullptr);
  void update_friction_direction(double alpha, const Eigen::MatrixXd& V);
  bool solve_newton(double eta, double atol);
  bool solve_direction(const VectorXd& rc, const VectorXd& rp, double eta, Direction& d);
  void save(Iterate& to);
  void restore(const Iterate& from);
  bool polished(const PolishAccuracy& accuracy);
  bool rescued();
  bool polish(const PolishAccuracy& accuracy);
  double gap_tolerance(const PolishAccuracy& accuracy) const;
  PolishOutcome polish_on(std::vector<char>& in_set, VectorXd& nu, const PolishAccuracy& accuracy);
  bool polish_inequalities(const PolishAccuracy& accuracy);
  bool minimise_augmented(const VectorXd& nu, double rho, double force_tol, VectorXd& c);
  double augmented_step(const VectorXd& nu, double rho, const VectorXd& c, const Eigen::MatrixXd& V);
  double true_residual();
  double largest_step(const Direction& d) const;
  bool converged(double rd, double rp);
  bool step(const VectorXd& rp, double rd, double mu0, const Eigen::MatrixXd& V, Direction& d);
  void end_with_polish(double& polish_below);

  ContactInteriorPointOptions options_;
  NodalConstraints c_;
  int dim_;
  Index m_;
  petsc::RowRange mine_;
  std::vector<PetscInt> fixed_owned_;
  Owned<Mat, MatDestroy> K_, N_;
  Owned<Vec, VecDestroy> u_, b_, rd_, rhs_, du_, Kdu_, gathered_;
  Owned<VecScatter, VecScatterDestroy> to_constrained_;
  /// The DOFs the constraints read (A's free columns, the constrained nodes' DOFs and, with friction, the slip
  /// map's free columns), sorted: A_ is A on them, S_ the slip map (NodalConstraints::slip_map, its fixed
  /// columns moved into the slip origin) on them.
  std::vector<PetscInt> gathered_dofs_;
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> A_, S_;
  std::unique_ptr<SubspaceCorrection> correction_;
  Owned<KSP, KSPDestroy> ksp_;
  VectorXd s_, lambda_;
  /// With friction, the dual slip directions w (dim × m) of the primal-dual linearisation; 0 at the start.
  Eigen::MatrixXd W_;
  /// The last iterate that met the dual and primal tests (frictionless only), polished before giving up.
  Iterate rescue_;
  double F_ = 0.0, L_ = 0.0, max_diagonal_ = 0.0;
  double coordinate_scale_ = 0.0;  ///< max |x|
  ContactInteriorPointResult result_;
};

InteriorPoint::InteriorPoint(const SparseMatrix& K_share, const VectorXd& f, const std::vector<Index>& fixed,
                             const VectorXd& fixed_values, const Eigen::MatrixXd& x, const NodalConstraints& c,
                             const ContactInteriorPointOptions& options, const VectorXd* start)
    : options_(options), c_(c), dim_(static_cast<int>(x.rows())), m_(c.size()),
      mine_(petsc::my_rows(static_cast<int>(x.rows()), x.cols())) {
  const Index n = dim_ * x.cols();
  if (K_share.rows() != n || f.size() != n || fixed_values.size() != static_cast<Index>(fixed.size()) ||
      c.normal.rows() != dim_ || c.normal.cols() != m_ || c.lower.size() != m_ || m_ == 0 ||
      (c.rows.size() > 0 && (c.rows.rows() != m_ || c.rows.cols() != n)) ||
      (c.frictional() && (c.friction_bound.size() != m_ || c.friction_alpha.size() != m_ ||
                          c.friction_bound.minCoeff() < 0.0 || c.friction_alpha.minCoeff() <= 0.0)) ||
      (c.slip_origin.size() > 0 && (c.slip_origin.rows() != dim_ || c.slip_origin.cols() != m_)) ||
      (c.slip_map.size() > 0 && (c.slip_map.rows() != dim_ * m_ || c.slip_map.cols() != n)) ||
      (start && start->size() != n))
    throw std::invalid_argument("solve_contact_interior_point: K, f, the fixed values, the coordinates and the "
                                "constraints do not match (or there is no constraint)");
  std::vector<char> is_fixed(static_cast<std::size_t>(n), 0);
  for (const Index i : fixed) is_fixed[static_cast<std::size_t>(i)] = 1;
  for (const Index i : fixed)
    if (mine_.owns(i)) fixed_owned_.push_back(static_cast<PetscInt>(i));
  coordinate_scale_ = x.size() ? x.cwiseAbs().maxCoeff() : 0.0;
  build_rows(fixed, fixed_values, n);
  assemble(K_share, f, fixed, fixed_values, x);
  if (start) {  // u = the start on the free DOFs, ū on the fixed ones
    for (Index i = mine_.row0(); i < mine_.row1(); ++i)
      if (!is_fixed[static_cast<std::size_t>(i)])
        check(VecSetValue(u_.object, static_cast<PetscInt>(i), (*start)[i], INSERT_VALUES), "VecSetValue");
    check(VecAssemblyBegin(u_.object), "VecAssemblyBegin");
    check(VecAssemblyEnd(u_.object), "VecAssemblyEnd");
  }
  create_constraint_scatter();
  create_solver();
}

/// K (fixed rows and columns made identity), b, u = ū, N a copy of K's pattern with the rigid-body modes.
void InteriorPoint::assemble(const SparseMatrix& K_share, const VectorXd& f, const std::vector<Index>& fixed,
                             const VectorXd& fixed_values, const Eigen::MatrixXd& x) {
  check(MatCreate(PETSC_COMM_WORLD, &K_.object), "MatCreate");
  petsc::assemble_symmetric(newton_pattern(K_share), mine_, K_.object);
  check(MatCreateVecs(K_.object, &u_.object, &b_.object), "MatCreateVecs");
  PetscReal max_diagonal = 0.0;
  check(MatGetDiagonal(K_.object, b_.object), "MatGetDiagonal");
  check(VecNorm(b_.object, NORM_INFINITY, &max_diagonal), "VecNorm");
  petsc::impose_fixed(f, fixed, fixed_values, mine_, K_.object, u_.object, b_.object);
  check(MatDuplicate(K_.object, MAT_COPY_VALUES, &N_.object), "MatDuplicate");
  petsc::set_rigid_body_modes(x, mine_, N_.object);
  for (Vec* v : {&rd_.object, &rhs_.object, &du_.object, &Kdu_.object}) check(VecDuplicate(b_.object, v), "VecDuplicate");
  set_scales(fixed_values, max_diagonal);
}

/// F = ‖b‖_∞ over the free rows (options' force_scale where given; L × K's largest diagonal entry when it is 0),
/// L = max(‖ū‖_∞, max |l_j|, F / K's largest diagonal entry).
void InteriorPoint::set_scales(const VectorXd& fixed_values, double max_diagonal) {
  if (options_.force_scale > 0.0) {
    F_ = options_.force_scale;
  } else {
    check(VecCopy(b_.object, rd_.object), "VecCopy");
    zero_fixed_rows(rd_.object);
    check(VecNorm(rd_.object, NORM_INFINITY, &F_), "VecNorm");
  }
  max_diagonal_ = max_diagonal;
  L_ = std::max(fixed_values.size() ? fixed_values.cwiseAbs().maxCoeff() : 0.0, c_.lower.cwiseAbs().maxCoeff());
  if (F_ == 0.0 && L_ == 0.0)
    throw std::invalid_argument("solve_contact_interior_point: no load, no fixed value and no gap: u = 0");
  if (F_ == 0.0) F_ = L_ * max_diagonal;
  // Not below the displacement the largest load makes at the stiffest DOF: gaps of faces that coincide up
  // to round-off (1e-16) are no length scale.
  L_ = std::max(L_, F_ / max_diagonal);
  result_.force_scale = F_;
  result_.length_scale = L_;
}

/// A on the free DOFs (the fixed ones' entries times ū moved into the lower bounds), on the gathered DOFs.
void InteriorPoint::build_rows(const std::vector<Index>& fixed, const VectorXd& fixed_values, Index n) {
  SparseMatrix rows = c_.rows;
  if (rows.size() == 0) {
    std::vector<Eigen::Triplet<double>> t;
    for (Index j = 0; j < m_; ++j)
      for (int k = 0; k < dim_; ++k)
        if (c_.normal(k, j) != 0.0)
          t.emplace_back(static_cast<int>(j), static_cast<int>(dim_ * c_.node[j] + k), c_.normal(k, j));
    rows.resize(m_, n);
    rows.setFromTriplets(t.begin(), t.end());
  }
  VectorXd ubar = VectorXd::Zero(n);
  std::vector<char> is_fixed(static_cast<std::size_t>(n), 0);
  for (std::size_t k = 0; k < fixed.size(); ++k) {
    ubar[fixed[k]] = fixed_values[static_cast<Index>(k)];
    is_fixed[static_cast<std::size_t>(fixed[k])] = 1;
  }
  c_.lower -= rows * ubar;
  auto free_columns = [&](Index, Index col, double) { return !is_fixed[static_cast<std::size_t>(col)]; };
  rows.prune(free_columns);
  SparseMatrix slips;
  if (c_.frictional()) {
    slips = slip_map(n);
    const VectorXd fixed_part = slips * ubar;
    if (c_.slip_origin.size() == 0) c_.slip_origin = Eigen::MatrixXd::Zero(dim_, m_);
    c_.slip_origin -= Eigen::Map<const Eigen::MatrixXd>(fixed_part.data(), dim_, m_);
    slips.prune(free_columns);
  }
  for (const SparseMatrix* M : {&rows, &slips})
    for (int col = 0; col < M->outerSize(); ++col)
      if (M->col(col).nonZeros() > 0) gathered_dofs_.push_back(col);
  for (const Index p : c_.node)
    for (int k = 0; k < dim_; ++k) gathered_dofs_.push_back(static_cast<PetscInt>(dim_ * p + k));
  std::sort(gathered_dofs_.begin(), gathered_dofs_.end());
  gathered_dofs_.erase(std::unique(gathered_dofs_.begin(), gathered_dofs_.end()), gathered_dofs_.end());
  auto on_gathered = [&](const SparseMatrix& M) {
    std::vector<Eigen::Triplet<double>> t;
    for (int col = 0; col < M.outerSize(); ++col) {
      const auto at = std::lower_bound(gathered_dofs_.begin(), gathered_dofs_.end(), static_cast<PetscInt>(col));
      for (SparseMatrix::InnerIterator it(M, col); it; ++it)
        t.emplace_back(static_cast<int>(it.row()), static_cast<int>(at - gathered_dofs_.begin()), it.value());
    }
    Eigen::SparseMatrix<double, Eigen::RowMajor, int> out(M.rows(), static_cast<Index>(gathered_dofs_.size()));
    out.setFromTriplets(t.begin(), t.end());
    return out;
  };
  A_ = on_gathered(rows);
  S_ = on_gathered(slips);
}

/// B of the friction term (NodalConstraints::slip_map, or the nodes' own DOFs where it is empty), n DOFs.
SparseMatrix InteriorPoint::slip_map(Index n) const {
  if (c_.slip_map.size() > 0) return c_.slip_map;
  std::vector<Eigen::Triplet<double>> t;
  for (Index j = 0; j < m_; ++j)
    for (int k = 0; k < dim_; ++k)
      t.emplace_back(static_cast<int>(dim_ * j + k), static_cast<int>(dim_ * c_.node[j] + k), 1.0);
  SparseMatrix B(dim_ * m_, n);
  B.setFromTriplets(t.begin(), t.end());
  return B;
}

/// K's share with explicit zeros where Aᵀ Σ A and ∇²j = Sᵀ H S (H block diagonal, dim × dim blocks) add
/// entries outside K's pattern (this rank's rows), so that N = K + ∇²j + Aᵀ Σ A keeps K's pattern.
SparseMatrix InteriorPoint::newton_pattern(const SparseMatrix& K_share) const {
  std::vector<Eigen::Triplet<double>> t;
  std::vector<int> columns;
  auto add = [&](const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& M, Index block) {
    for (Index first = 0; first < M.rows(); first += block) {
      columns.clear();
      for (Index row = first; row < first + block; ++row)
        for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(M, row); it; ++it)
          columns.push_back(gathered_dofs_[static_cast<std::size_t>(it.col())]);
      for (const int r : columns)
        for (const int c : columns)
          if (r >= c && mine_.owns(r)) t.emplace_back(r, c, 0.0);
    }
  };
  add(A_, 1);
  add(S_, dim_);
  SparseMatrix Z(K_share.rows(), K_share.cols());
  Z.setFromTriplets(t.begin(), t.end());
  return K_share + Z;
}

/// The gathered DOFs' scatter: their values whole on every rank.
void InteriorPoint::create_constraint_scatter() {
  Owned<IS, ISDestroy> is;
  check(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(gathered_dofs_.size()), gathered_dofs_.data(),
                        PETSC_COPY_VALUES, &is.object),
        "ISCreateGeneral");
  check(VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(gathered_dofs_.size()), &gathered_.object),
        "VecCreateSeq");
  check(VecScatterCreate(u_.object, is.object, gathered_.object, nullptr, &to_constrained_.object),
        "VecScatterCreate");
}

/// CG on the unpreconditioned residual, preconditioned as the options say; PETSc options with the prefix
/// newton_ (and filter_ for the subspace solve) may change it.
void InteriorPoint::create_solver() {
  std::vector<PetscInt> subspace;  // the gathered DOFs this rank owns (sorted)
  for (const PetscInt i : gathered_dofs_)
    if (mine_.owns(i)) subspace.push_back(i);
  correction_ = std::make_unique<SubspaceCorrection>(subspace);
  check(KSPCreate(PETSC_COMM_WORLD, &ksp_.object), "KSPCreate");
  check(KSPSetOptionsPrefix(ksp_.object, "newton_"), "KSPSetOptionsPrefix");
  check(KSPSetType(ksp_.object, KSPCG), "KSPSetType");
  check(KSPSetNormType(ksp_.object, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  check(KSPSetOperators(ksp_.object, N_.object, N_.object), "KSPSetOperators");
  PC pc = nullptr;
  check(KSPGetPC(ksp_.object, &pc), "KSPGetPC");
  configure_newton_preconditioner(pc, options_.preconditioner, correction_.get());
  check(KSPSetFromOptions(ksp_.object), "KSPSetFromOptions");
}

/// The gathered DOFs' values of v, on every rank.
VectorXd InteriorPoint::gather(Vec v) {
  check(VecScatterBegin(to_constrained_.object, v, gathered_.object, INSERT_VALUES, SCATTER_FORWARD),
        "VecScatterBegin");
  check(VecScatterEnd(to_constrained_.object, v, gathered_.object, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  const PetscScalar* g = nullptr;
  check(VecGetArrayRead(gathered_.object, &g), "VecGetArrayRead");
  VectorXd out = Eigen::Map<const VectorXd>(g, static_cast<Index>(gathered_dofs_.size()));
  check(VecRestoreArrayRead(gathered_.object, &g), "VecRestoreArrayRead");
  return out;
}

/// S g for the gathered values g, dim × m (column j: row j's friction point); empty without friction.
Eigen::MatrixXd InteriorPoint::slip_values(const VectorXd& g) const {
  const VectorXd v = S_ * g;
  return Eigen::Map<const Eigen::MatrixXd>(v.data(), dim_, v.size() / dim_);
}

/// out += w on the gathered DOFs (each rank its own).
void InteriorPoint::add_gathered(const VectorXd& w, Vec out) {
  PetscScalar* a = nullptr;
  check(VecGetArray(out, &a), "VecGetArray");
  for (std::size_t i = 0; i < gathered_dofs_.size(); ++i)
    if (mine_.owns(gathered_dofs_[i])) a[gathered_dofs_[i] - mine_.row0()] += w[static_cast<Index>(i)];
  check(VecRestoreArray(out, &a), "VecRestoreArray");
}

/// out += Aᵀ w.
void InteriorPoint::add_transpose(const VectorXd& w, Vec out) { add_gathered(A_.transpose() * w, out); }

void InteriorPoint::zero_fixed_rows(Vec v) {
  PetscScalar* a = nullptr;
  check(VecGetArray(v, &a), "VecGetArray");
  for (const PetscInt i : fixed_owned_) a[i - mine_.row0()] = 0.0;
  check(VecRestoreArray(v, &a), "VecRestoreArray");
}

/// N = K + ∇²j(u) + Aᵀ Σ A, ∇²j = Sᵀ H S with H the friction points' dim × dim blocks at V = S u (with W, the
/// primal-dual blocks of friction_hessian()); sigma Σ's diagonal (λ_j / s_j in the interior point).
void InteriorPoint::update_newton_matrix(const Eigen::MatrixXd& V, const VectorXd& sigma, const Eigen::MatrixXd* W) {
  check(MatCopy(K_.object, N_.object, SAME_NONZERO_PATTERN), "MatCopy");
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> B = A_.transpose() * sigma.asDiagonal() * A_;
  if (c_.frictional()) {
    std::vector<Eigen::Triplet<double>> t;
    for (Index j = 0; j < m_; ++j) {
      const Eigen::MatrixXd block = friction_hessian(c_, V, j, W);
      for (int a = 0; a < dim_; ++a)
        for (int b = 0; b < dim_; ++b)
          t.emplace_back(static_cast<int>(dim_ * j + a), static_cast<int>(dim_ * j + b), block(a, b));
    }
    Eigen::SparseMatrix<double, Eigen::RowMajor, int> H(dim_ * m_, dim_ * m_);
    H.setFromTriplets(t.begin(), t.end());
    B += Eigen::SparseMatrix<double, Eigen::RowMajor, int>(S_.transpose() * H * S_);
  }
  std::vector<PetscInt> columns;
  std::vector<PetscScalar> values;
  for (Index r = 0; r < B.outerSize(); ++r) {
    const PetscInt row = gathered_dofs_[static_cast<std::size_t>(r)];
    if (!mine_.owns(row)) continue;
    columns.clear();
    values.clear();
    for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(B, r); it; ++it) {
      columns.push_back(gathered_dofs_[static_cast<std::size_t>(it.col())]);
      values.push_back(it.value());
    }
    check(MatSetValues(N_.object, 1, &row, static_cast<PetscInt>(columns.size()), columns.data(), values.data(),
                       ADD_VALUES),
          "MatSetValues");
  }
  check(MatAssemblyBegin(N_.object, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(N_.object, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  check(KSPSetOperators(ksp_.object, N_.object, N_.object), "KSPSetOperators");
  check(KSPSetUp(ksp_.object), "KSPSetUp");
  PC pc = nullptr;
  check(KSPGetPC(ksp_.object, &pc), "KSPGetPC");
  set_up_newton_preconditioner(pc);
}

/// The direction for the complementarity target rc (see the header); false when the Krylov solve broke down.
bool InteriorPoint::solve_direction(const VectorXd& rc, const VectorXd& rp, double eta, Direction& d) {
  const VectorXd sigma = lambda_.cwiseQuotient(s_);
  check(VecCopy(rd_.object, rhs_.object), "VecCopy");
  check(VecScale(rhs_.object, -1.0), "VecScale");
  add_transpose(-(rc.cwiseQuotient(s_) + sigma.cwiseProduct(rp)), rhs_.object);
  if (!solve_newton(eta, 0.1 * options_.tolerance * F_)) return false;
  zero_fixed_rows(du_.object);
  d.ds = A_ * gather(du_.object) + rp;
  d.dl = -(rc + lambda_.cwiseProduct(d.ds)).cwiseQuotient(s_);
  return true;
}

/// N Δu = rhs_ by conjugate gradients into du_, to ‖residual‖₂ ≤ max(η ‖rhs‖₂, atol); false (reason set) when
/// the solve broke down.
bool InteriorPoint::solve_newton(double eta, double atol) {
  PetscReal rhs_norm = 0.0;
  check(VecNorm(rhs_.object, NORM_2, &rhs_norm), "VecNorm");
  if (rhs_norm <= atol) {  // Δu = 0 meets the test (and PETSc takes no relative tolerance of 1)
    check(VecSet(du_.object, 0.0), "VecSet");
    result_.krylov_iterations.push_back(0);
    return true;
  }
  check(KSPSetTolerances(ksp_.object, std::max(eta, atol / std::max(rhs_norm, atol)), atol, PETSC_DEFAULT,
                         options_.max_krylov_iterations),
        "KSPSetTolerances");
  const auto t0 = std::chrono::steady_clock::now();
  PetscInt its = 0;
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  // A breakdown (pᵀNp or rᵀM⁻¹r ≤ 0 in floating point: N spans the contrasts of Σ = Λ S⁻¹ and of stuck
  // and slipping friction nodes) loses the Krylov space, not the iterate: CG restarts from it, from its
  // true residual, at most kRestarts times.
  constexpr int kRestarts = 3;
  check(KSPSetInitialGuessNonzero(ksp_.object, PETSC_FALSE), "KSPSetInitialGuessNonzero");
  for (int restart = 0; restart <= kRestarts; ++restart) {
    check(KSPSolve(ksp_.object, rhs_.object, du_.object), "KSPSolve");
    PetscInt n = 0;
    check(KSPGetIterationNumber(ksp_.object, &n), "KSPGetIterationNumber");
    check(KSPGetConvergedReason(ksp_.object, &reason), "KSPGetConvergedReason");
    its += n;
    if (reason != KSP_DIVERGED_INDEFINITE_MAT && reason != KSP_DIVERGED_INDEFINITE_PC) break;
    check(KSPSetInitialGuessNonzero(ksp_.object, PETSC_TRUE), "KSPSetInitialGuessNonzero");
  }
  check(KSPSetInitialGuessNonzero(ksp_.object, PETSC_FALSE), "KSPSetInitialGuessNonzero");
  result_.krylov_seconds += petsc::seconds_since(t0);
  result_.krylov_iterations.push_back(static_cast<int>(its));
  // An inexact Newton direction is a direction still (the stopping test is on the iterate, not on it): the
  // last iterate after the iteration limit, and after a breakdown at the round-off floor of the Krylov solve
  // (pᵀNp or rᵀM⁻¹r ≤ 0 from round-off once the residual is far below the right-hand side, as with
  // the stick/slip contrasts of friction) where its true residual is within the loosest forcing term, 0.01.
  const bool breakdown = reason == KSP_DIVERGED_INDEFINITE_MAT || reason == KSP_DIVERGED_INDEFINITE_PC;
  if (reason < 0 && reason != KSP_DIVERGED_ITS && !(breakdown && true_residual() <= 0.01 * rhs_norm)) {
    result_.reason = std::string("conjugate gradients: ") + KSPConvergedReasons[reason];
    return false;
  }
  return true;
}

void InteriorPoint::save(Iterate& to) {
  if (!to.u.object) check(VecDuplicate(u_.object, &to.u.object), "VecDuplicate");
  check(VecCopy(u_.object, to.u.object), "VecCopy");
  to.s = s_;
  to.lambda = lambda_;
  to.dual_residual = result_.dual_residual;
  to.primal_residual = result_.primal_residual;
  to.complementarity = result_.complementarity;
  to.reason = result_.reason;
}

void InteriorPoint::restore(const Iterate& from) {
  check(VecCopy(from.u.object, u_.object), "VecCopy");
  s_ = from.s;
  lambda_ = from.lambda;
  result_.dual_residual = from.dual_residual;
  result_.primal_residual = from.primal_residual;
  result_.complementarity = from.complementarity;
  result_.reason = from.reason;
  const VectorXd g = gather(u_.object);
  residuals(g, slip_values(g));  // r_d of the restored iterate, which the next step's right-hand side reads
}

/// The polish to `accuracy` (without friction the active-set polish, and where it fails the method of
/// multipliers on the inequalities from the same iterate; with friction the latter), kept where its point passes
/// the stopping test (the residuals and the result's figures at it). False where it was not kept (the iterate
/// as it was).
bool InteriorPoint::polished(const PolishAccuracy& accuracy) {
  Iterate before;
  save(before);
  bool on_inequalities = false, ok = false;
  if (!c_.frictional()) {
    ok = polish(accuracy);
    if (!ok) restore(before);
  }
  if (!ok) ok = on_inequalities = polish_inequalities(accuracy);
  if (ok) {
    const VectorXd g = gather(u_.object);
    const VectorXd rp = residuals(g, slip_values(g));
    PetscReal rd = 0.0;
    check(VecNorm(rd_.object, NORM_INFINITY, &rd), "VecNorm");
    if (converged(rd, rp.lpNorm<Eigen::Infinity>())) {
      ++result_.polishes;
      if (on_inequalities) ++result_.inequality_polishes;
      return true;
    }
  }
  ++result_.polishes_rejected;
  restore(before);
  return false;
}

/// Before giving up: the polish, to the tolerance, from the last iterate that met the dual and primal tests
/// (with friction: came within kPolishBelow of them; rescue_, saved by run(); none: false). The interior
/// point's last iterate stays where it is not accepted.
bool InteriorPoint::rescued() {
  if (!rescue_.u.object) return false;
  Iterate last;
  save(last);
  restore(rescue_);
  if (polished(kRescue)) return true;
  restore(last);
  return false;
}

/// The active-set polish (see the header): S = {j : λ_j / F ≥ s_j / L}, then rounds that drop the rows of S
/// whose multiplier comes out negative and add the rows outside S that the answer violates (the primal-dual
/// active set update: Hintermüller, Ito & Kunisch, SIAM J. Optim. 13, 2003; as solvers/active_set_polish.cpp).
/// Accepted, with s = c(u)⁺ and λ = ν⁺ on S, 0 elsewhere, at a set that needs no change: a KKT point of the
/// program to `accuracy`. Otherwise false, u and λ where the last attempt left them (polished() restores them).
bool InteriorPoint::polish(const PolishAccuracy& accuracy) {
  constexpr int kRounds = 5;
  const double tol = accuracy.forces * options_.tolerance;
  std::vector<char> in_set(static_cast<std::size_t>(m_));
  for (Index j = 0; j < m_; ++j) in_set[static_cast<std::size_t>(j)] = lambda_[j] / F_ >= s_[j] / L_;
  VectorXd nu = lambda_;
  for (int round = 0; round < kRounds; ++round) {
    const PolishOutcome outcome = polish_on(in_set, nu, accuracy);
    if (outcome == PolishOutcome::kFailed) break;
    // Rows that cannot close together (the two nearly dependent families of a symmetric pair, one of each
    // pair held open by the meshes' mismatch): the method of multipliers meets them halfway, the row that
    // should stay open still open, its partner pushed past closed. The rows of S still open leave it, and no
    // row joins before S has closed (a row that should have stayed is then violated and joins again).
    const bool closed = outcome == PolishOutcome::kClosed;
    const double open = closed ? std::numeric_limits<double>::infinity() : gap_tolerance(accuracy);
    const VectorXd c = A_ * gather(u_.object) - c_.lower;
    bool changed = false;
    for (Index j = 0; j < m_; ++j) {
      char& in = in_set[static_cast<std::size_t>(j)];
      if ((in && (nu[j] < -0.1 * tol * F_ || c[j] > open)) || (closed && !in && c[j] < -0.1 * tol * L_)) {
        in = !in;
        nu[j] = 0.0;
        changed = true;
      }
    }
    if (!closed && !changed) break;
    if (changed) continue;
    s_ = c.cwiseMax(0.0);
    for (Index j = 0; j < m_; ++j) lambda_[j] = in_set[static_cast<std::size_t>(j)] ? std::max(nu[j], 0.0) : 0.0;
    return true;
  }
  return false;
}

/// The method of multipliers on the inequalities themselves (Rockafellar, J. Optim. Theory Appl. 12, 1973;
/// Nocedal & Wright §17.4), where the active-set polish fails: from ν = λ on the rows the interior point
/// tells active (λ_j/F ≥ s_j/L), 0 elsewhere, rounds of
///     u ← argmin ½ uᵀKu − bᵀu + j(u) + ‖max(0, ν − ρ c(u))‖² / (2ρ),   ν ← max(0, ν − ρ c(u)).
/// It guesses no set of equalities: the rows of a symmetric pair on unmatched flat meshes, nearly dependent
/// everywhere, on which the active set cycles, keep whatever multipliers the optimal set allows. Its rate is
/// linear, about 1/(1 + ρ σ) with σ the rows' compliance: ρ = 10⁴ × K's largest diagonal entry gains about
/// 40 % a round on V5's interface (10² about 5 %; at 10⁶ conjugate gradients broke down). Accepted, with s =
/// c(u)⁺ and λ = ν, when no row is violated beyond the gap tolerance, min(c_j/L, ν_j/F) ≤ accuracy.gaps tol
/// for every j and the forces balance to accuracy.forces tol F; false after kRounds rounds or when an inner
/// problem is not solved. With friction, j(u) joins each inner problem (the thresholds fixed).
bool InteriorPoint::polish_inequalities(const PolishAccuracy& accuracy) {
  constexpr int kRounds = 40;
  const double rho = 1e4 * max_diagonal_, force_tol = accuracy.forces * options_.tolerance * F_;
  const double gap_tol = gap_tolerance(accuracy), tol = accuracy.gaps * options_.tolerance;
  VectorXd nu = lambda_;
  for (Index j = 0; j < m_; ++j)
    if (lambda_[j] / F_ < s_[j] / L_) nu[j] = 0.0;
  VectorXd c;
  for (int round = 0; round < kRounds; ++round) {
    if (!minimise_augmented(nu, rho, force_tol, c)) return false;
    nu = lambda_;  // max(0, ν − ρ c(u)) at the inner problem's answer
    bool done = -c.minCoeff() <= gap_tol;
    for (Index j = 0; j < m_ && done; ++j) done = std::min(c[j] / L_, nu[j] / F_) <= tol;
    if (done) {
      s_ = c.cwiseMax(0.0);
      return true;
    }
  }
  return false;
}

/// One round's inner problem of polish_inequalities(), min ψ(u) = ½ uᵀKu − bᵀu + j(u) + ‖w‖² / (2ρ) with
/// w = max(0, ν − ρ c(u)), by semismooth Newton (∇ψ = K u − b + ∇j − Aᵀw, piecewise smooth; a generalised
/// Hessian K + ∇²j + ρ A_Wᵀ A_W, W = {j : w_j > 0}):
///     (K + ∇²j + ρ A_Wᵀ A_W) Δu = −∇ψ(u),   u ← u + α Δu,
/// to ‖∇ψ‖∞ ≤ 0.1 force_tol (a tenth of what the round must meet: the next round starts from it). Without
/// friction α = 1 (W unchanged between two steps makes the step exact); with it, α halved until ψ decreases
/// enough (Armijo: ψ is convex and C¹). On return λ = w and c = c(u); false after kSteps steps or when the
/// Krylov solve broke down.
bool InteriorPoint::minimise_augmented(const VectorXd& nu, double rho, double force_tol, VectorXd& c) {
  constexpr int kSteps = 30;
  VectorXd active(m_);
  for (int k = 0;; ++k) {
    const VectorXd g = gather(u_.object);
    const Eigen::MatrixXd V = slip_values(g);
    c = A_ * g - c_.lower;
    lambda_ = (nu - rho * c).cwiseMax(0.0);
    residuals(g, V);
    PetscReal rd = 0.0;
    check(VecNorm(rd_.object, NORM_INFINITY, &rd), "VecNorm");
    if (rd <= 0.1 * force_tol) return true;
    if (k == kSteps) return false;
    for (Index j = 0; j < m_; ++j) active[j] = lambda_[j] > 0.0 ? 1.0 : 0.0;
    update_newton_matrix(V, rho * active);
    check(VecCopy(rd_.object, rhs_.object), "VecCopy");
    check(VecScale(rhs_.object, -1.0), "VecScale");
    if (!solve_newton(0.0, 0.01 * force_tol)) return false;
    zero_fixed_rows(du_.object);
    const double alpha = c_.frictional() ? augmented_step(nu, rho, c, V) : 1.0;
    check(VecAXPY(u_.object, alpha, du_.object), "VecAXPY");
  }
}

/// The step along Δu of minimise_augmented() with friction: 1 halved until ψ(u + α Δu) ≤ ψ(u) + 10⁻⁴ α ∇ψᵀΔu
/// (1 where Δu is no descent direction, the Krylov solve being inexact). c = c(u), V = S u; r_d holds ∇ψ(u).
/// ψ's quadratic part along Δu is α Δuᵀ(K u − b) + ½ α² ΔuᵀKΔu, K u − b = ∇ψ − ∇j + Aᵀw.
double InteriorPoint::augmented_step(const VectorXd& nu, double rho, const VectorXd& c, const Eigen::MatrixXd& V) {
  const VectorXd du = gather(du_.object);
  const VectorXd dc = A_ * du;
  const Eigen::MatrixXd dV = slip_values(du);
  PetscScalar slope = 0.0, du_Kdu = 0.0;
  check(VecDot(du_.object, rd_.object, &slope), "VecDot");
  if (slope >= 0.0) return 1.0;
  check(MatMult(K_.object, du_.object, Kdu_.object), "MatMult");
  check(VecDot(du_.object, Kdu_.object, &du_Kdu), "VecDot");
  const double linear = slope - friction_gradient(c_, V).cwiseProduct(dV).sum() + dc.dot(lambda_);
  const auto rest = [&](double alpha) {  // ψ − its quadratic part at u + α Δu
    return friction_energy(c_, V + alpha * dV) + (nu - rho * (c + alpha * dc)).cwiseMax(0.0).squaredNorm() / (2 * rho);
  };
  const double psi0 = rest(0.0);
  double alpha = 1.0;
  for (int k = 0; k < 40; ++k, alpha *= 0.5)
    if (alpha * linear + 0.5 * alpha * alpha * du_Kdu + rest(alpha) <= psi0 + 1e-4 * alpha * slope) break;
  return alpha;
}

/// The gaps a polish closes its rows to: accuracy.gaps tol L, not below the round-off of gaps computed from the
/// coordinates (the gap rows' constants), 10 ε max |x|.
double InteriorPoint::gap_tolerance(const PolishAccuracy& accuracy) const {
  return std::max(accuracy.gaps * options_.tolerance * L_,
                  10.0 * std::numeric_limits<double>::epsilon() * coordinate_scale_);
}

/// min ½ uᵀKu − bᵀu subject to c_j(u) = 0 for j in S, from u and the multipliers ν of S, by the method of
/// multipliers (Hestenes 1969; Nocedal & Wright §17.3), which converges whatever the rank of A_S:
///     (K + ρ A_Sᵀ A_S) Δu = −(K u − b − A_Sᵀ ν) − ρ A_Sᵀ c_S(u),   u ← u + Δu,   ν_S ← ν_S − ρ c_S(u),
/// ρ = 10² × K's largest diagonal entry (the rows are lengths of unit entries: ρ A_SᵀA_S is 10² times as stiff
/// as the stiffest DOF; at 10³ the round-off of the Newton matrix, ε ρ ‖u‖, kept ‖K u − b − A_Sᵀ ν‖∞ above
/// 10⁻¹¹ F on a contact patch test). Closed when ‖c_S‖∞ ≤ accuracy.gaps tol L (at least 10 ε max |x|) and
/// ‖K u − b − A_Sᵀ ν‖∞ ≤ accuracy.forces tol F; rows that cannot close when ‖c_S‖∞ stops halving at each
/// step (the nearly dependent families of a curved symmetric pair: polish() then drops the rows still
/// open); failed after kIterations steps or when the Krylov solve broke down. Frictionless only.
PolishOutcome InteriorPoint::polish_on(std::vector<char>& in_set, VectorXd& nu, const PolishAccuracy& accuracy) {
  constexpr int kIterations = 12;
  const double rho = 1e2 * max_diagonal_, force_tol = accuracy.forces * options_.tolerance * F_;
  const double gap_tol = gap_tolerance(accuracy);
  VectorXd mask(m_);
  for (Index j = 0; j < m_; ++j) mask[j] = in_set[static_cast<std::size_t>(j)] ? 1.0 : 0.0;
  update_newton_matrix(Eigen::MatrixXd(), rho * mask);
  double last_closing = 0.0;
  for (int k = 0;; ++k) {
    const VectorXd g = gather(u_.object);
    lambda_ = nu.cwiseProduct(mask);
    const VectorXd c_S = (A_ * g - c_.lower).cwiseProduct(mask);
    residuals(g, Eigen::MatrixXd());
    PetscReal rd = 0.0;
    check(VecNorm(rd_.object, NORM_INFINITY, &rd), "VecNorm");
    const double closing = c_S.lpNorm<Eigen::Infinity>();
    if (closing <= gap_tol && rd <= force_tol) return PolishOutcome::kClosed;
    if (k >= 2 && closing > 0.5 * last_closing) return PolishOutcome::kRowsCannotClose;
    last_closing = closing;
    if (k == kIterations) return PolishOutcome::kFailed;
    check(VecCopy(rd_.object, rhs_.object), "VecCopy");
    check(VecScale(rhs_.object, -1.0), "VecScale");
    add_transpose(-rho * c_S, rhs_.object);
    if (!solve_newton(0.0, 0.1 * force_tol)) return PolishOutcome::kFailed;
    zero_fixed_rows(du_.object);
    check(VecAXPY(u_.object, 1.0, du_.object), "VecAXPY");
    nu -= rho * (A_ * gather(u_.object) - c_.lower).cwiseProduct(mask);
  }
}

/// ‖rhs − N Δu‖₂ of the Krylov solve's last iterate.
double InteriorPoint::true_residual() {
  check(MatMult(N_.object, du_.object, Kdu_.object), "MatMult");
  check(VecAYPX(Kdu_.object, -1.0, rhs_.object), "VecAYPX");
  PetscReal norm = 0.0;
  check(VecNorm(Kdu_.object, NORM_2, &norm), "VecNorm");
  return norm;
}

/// The largest α ≤ 1 with s + α Δs ≥ 0 and λ + α Δλ ≥ 0.
double InteriorPoint::largest_step(const Direction& d) const {
  double alpha = 1.0;
  for (Index j = 0; j < m_; ++j) {
    if (d.ds[j] < 0.0) alpha = std::min(alpha, -s_[j] / d.ds[j]);
    if (d.dl[j] < 0.0) alpha = std::min(alpha, -lambda_[j] / d.dl[j]);
  }
  return alpha;
}

bool InteriorPoint::converged(double rd, double rp) {
  result_.dual_residual = rd / F_;
  result_.primal_residual = rp / L_;
  result_.complementarity = (s_ / L_).cwiseMin(lambda_ / F_).maxCoeff();
  const double tol = options_.tolerance;
  return result_.dual_residual <= tol && result_.primal_residual <= tol && result_.complementarity <= tol;
}

/// r_d = K u − f + ∇j(u) − Aᵀ λ into rd_; returns r_p = c(u) − s. g: u's gathered values, V = S g.
VectorXd InteriorPoint::residuals(const VectorXd& g, const Eigen::MatrixXd& V) {
  check(MatMult(K_.object, u_.object, rd_.object), "MatMult");
  check(VecAXPY(rd_.object, -1.0, b_.object), "VecAXPY");
  add_transpose(-lambda_, rd_.object);
  if (c_.frictional()) {
    const Eigen::MatrixXd G = friction_gradient(c_, V);
    add_gathered(S_.transpose() * Eigen::Map<const VectorXd>(G.data(), G.size()), rd_.object);
  }
  return A_ * g - c_.lower - s_;
}

/// The terms of the merit function (the header's φ) beyond the elastic energy, at the step α: j(u + α Δu),
/// the barrier of s + α Δs and ν ‖c − s‖₁ = ν (1 − α) ‖r_p‖₁ (c is linear). V, dV: S u and S Δu.
double InteriorPoint::merit(double alpha, const Direction& d, double target, double nu, const Eigen::MatrixXd& V,
                            const Eigen::MatrixXd& dV, const VectorXd& rp) {
  return friction_energy(c_, V + alpha * dV) - target * (s_ + alpha * d.ds).array().log().sum() +
         nu * (1.0 - alpha) * rp.lpNorm<1>();
}

/// The step from `alpha` halved until the merit function decreases enough (Armijo); alpha itself without
/// friction, or when the direction is not one of descent for the merit function. V = S u.
double InteriorPoint::line_search(double alpha, const Direction& d, double target, const VectorXd& rp,
                                  const Eigen::MatrixXd& V) {
  if (!c_.frictional()) return alpha;
  const Eigen::MatrixXd dV = slip_values(gather(du_.object));
  const Eigen::MatrixXd grad_j = friction_gradient(c_, V);
  PetscScalar du_rd = 0.0, du_Kdu = 0.0;
  check(VecDot(du_.object, rd_.object, &du_rd), "VecDot");  // Δuᵀ(K u − f) = Δuᵀ r_d + (AΔu)ᵀλ − Δuᵀ∇j
  check(MatMult(K_.object, du_.object, Kdu_.object), "MatMult");
  check(VecDot(du_.object, Kdu_.object, &du_Kdu), "VecDot");
  const double dj = grad_j.cwiseProduct(dV).sum();
  const double g = du_rd + (d.ds - rp).dot(lambda_) - dj;
  const double nu = 2.0 * std::max(lambda_.lpNorm<Eigen::Infinity>(), (lambda_ + alpha * d.dl).lpNorm<Eigen::Infinity>());
  const double slope = g + dj - target * d.ds.cwiseQuotient(s_).sum() - nu * rp.lpNorm<1>();
  if (slope >= 0.0) return alpha;
  const double phi0 = merit(0.0, d, target, nu, V, dV, rp);
  for (int k = 0; k < 40; ++k, alpha *= 0.5)
    if (alpha * g + 0.5 * alpha * alpha * du_Kdu + merit(alpha, d, target, nu, V, dV, rp) <=
        phi0 + 1e-4 * alpha * slope)
      break;
  return alpha;
}

/// One interior-point step from the current iterate (rp, rd: its primal residual and ‖r_d‖∞; V = S u): Newton
/// matrix, predictor, Mehrotra's corrector, step length; false when a Krylov solve broke down.
bool InteriorPoint::step(const VectorXd& rp, double rd, double mu0, const Eigen::MatrixXd& V, Direction& d) {
  const auto t_setup = std::chrono::steady_clock::now();
  update_newton_matrix(V, lambda_.cwiseQuotient(s_), c_.frictional() ? &W_ : nullptr);
  result_.setup_seconds += petsc::seconds_since(t_setup);
  const double mu = s_.dot(lambda_) / static_cast<double>(m_);
  const double eta = std::min(0.01, mu / mu0);
  // Predictor (affine scaling), then Mehrotra's centring and second-order correction.
  if (!solve_direction(s_.cwiseProduct(lambda_), rp, eta, d)) return false;
  const double alpha_affine = largest_step(d);
  const double mu_affine = (s_ + alpha_affine * d.ds).dot(lambda_ + alpha_affine * d.dl) / static_cast<double>(m_);
  // Mehrotra's σμ; with friction (f not quadratic) not below a tenth of μ while the stationarity and
  // feasibility are behind it (as solvers/dense_primal_interior_point.cpp): complementarity run ahead of
  // them drives s_j to 1e-20 L on active rows, and Σ = λ/s past what the Newton systems can resolve.
  double target = std::pow(mu_affine / mu, 3) * mu;
  if (c_.frictional())
    target = std::max(target, 0.1 * std::min(mu, L_ * F_ * std::max(rd / F_, rp.lpNorm<Eigen::Infinity>() / L_)));
  const VectorXd rc = s_.cwiseProduct(lambda_) + d.ds.cwiseProduct(d.dl) - VectorXd::Constant(m_, target);
  if (!solve_direction(rc, rp, eta, d)) return false;
  const double alpha = line_search(std::min(1.0, 0.995 * largest_step(d)), d, target, rp, V);
  check(VecAXPY(u_.object, alpha, du_.object), "VecAXPY");
  s_ += alpha * d.ds;
  lambda_ += alpha * d.dl;
  if (c_.frictional()) update_friction_direction(alpha, V);
  return true;
}

/// w_j ← w_j + α Δw_j for the step α along Δu (du_) from u, V = S u (Δw: the comment above friction_hessian),
/// then scaled back onto the unit ball where it left it (the projection of Chan, Golub & Mulet).
void InteriorPoint::update_friction_direction(double alpha, const Eigen::MatrixXd& V) {
  const Eigen::MatrixXd dV = slip_values(gather(du_.object));
  for (Index j = 0; j < m_; ++j) {
    const VectorXd n = c_.normal.col(j), s = slip(c_, V, j);
    const VectorXd ds = dV.col(j) - n * n.dot(dV.col(j));
    const double r = std::sqrt(s.squaredNorm() + c_.friction_alpha[j] * c_.friction_alpha[j]);
    const VectorXd w = W_.col(j);
    const VectorXd dw = (ds - w * s.dot(ds) / r) / r + s / r - w;
    VectorXd next = w + alpha * dw;
    const double norm = next.norm();
    if (norm > 1.0) next /= norm;
    W_.col(j) = next;
  }
}

/// The polishes at the current iterate, whose figures converged() has set (result_.converged among them),
/// updating it; polish_below is the complementarity below which the next early polish is tried.
void InteriorPoint::end_with_polish(double& polish_below) {
  // Without friction, the exact answer on the active rows once the interior point tells them apart (see
  // kPolishBelow), tried again each time the complementarity has fallen a hundredfold (to a hundredth of the
  // tolerance: as accurate as the interior point's own end, whose last step overshoots its test); and, from
  // the last iterate that met the dual and primal tests, to the tolerance itself before giving up. With
  // friction only the latter, from the last iterate within kPolishBelow of them: on a symmetric pair the
  // complementarity stalls at the meshes' mismatch and the Krylov solve breaks down before the dual residual
  // meets the tolerance (V5's interface with Coulomb friction on two ranks: 3e-9 against 1e-9).
  const bool feasible = result_.dual_residual <= options_.tolerance && result_.primal_residual <= options_.tolerance;
  const bool near = std::max(result_.dual_residual, result_.primal_residual) <= kPolishBelow * options_.tolerance;
  if (c_.frictional() ? near : feasible) save(rescue_);
  if (!result_.converged && !c_.frictional() && near && result_.complementarity <= polish_below) {
    polish_below = 0.01 * result_.complementarity;
    result_.converged = polished(kEarly);
  }
  // At the interior point's own end, the exact answer on its active set where that closes: the same point
  // whatever path led there (ranks, Krylov tolerances), to a hundredth of the tolerance.
  if (result_.converged && result_.polishes == 0 && !c_.frictional()) polished(kEarly);
}

ContactInteriorPointResult InteriorPoint::run(const FollowBounds* follow) {
  const auto t_start = std::chrono::steady_clock::now();
  s_ = (A_ * gather(u_.object) - c_.lower).cwiseMax(L_);
  lambda_ = VectorXd::Constant(m_, F_);
  if (c_.frictional()) W_ = Eigen::MatrixXd::Zero(dim_, m_);
  const double mu0 = s_.dot(lambda_) / static_cast<double>(m_);
  double polish_below = kPolishBelow * options_.tolerance;
  Direction d;
  for (result_.iterations = 0;; ++result_.iterations) {
    const VectorXd g = gather(u_.object);
    const Eigen::MatrixXd V = slip_values(g);
    VectorXd rp = residuals(g, V);
    PetscReal rd = 0.0;
    check(VecNorm(rd_.object, NORM_INFINITY, &rd), "VecNorm");
    result_.converged = converged(rd, rp.lpNorm<Eigen::Infinity>());
    // Followed bounds set at u: a point that then passes the stopping test solves the problem of its own bounds.
    // Not once the complementarity is a thousandth of the tolerance: bounds that keep moving then hold the
    // dual residual above it while s runs to zero on the active rows (a 3D pad dragged over a rigid sphere:
    // s = 1e-20 L, Σ = 1e17 K's diagonal, and the Krylov solve broke down); the Coulomb loop around the solve
    // checks the bounds at its end. Where the bounds settle, they do so before that (a pad dragged on a plane:
    // by 1e-2 of the tolerance; stopping at the tolerance itself tripled the Coulomb re-solves there).
    if (follow && result_.complementarity > kFollowAbove * options_.tolerance &&
        std::max({result_.dual_residual, result_.primal_residual, result_.complementarity}) <= options_.follow_below) {
      if (std::optional<VectorXd> bound = (*follow)(petsc::gather_to_all(u_.object), lambda_)) {
        c_.friction_bound = std::move(*bound);
        rp = residuals(g, V);
        check(VecNorm(rd_.object, NORM_INFINITY, &rd), "VecNorm");
        result_.converged = converged(rd, rp.lpNorm<Eigen::Infinity>());
      }
    }
    end_with_polish(polish_below);
    if (result_.converged) break;
    if (result_.iterations == options_.max_iterations) {
      result_.reason = "no convergence in " + std::to_string(options_.max_iterations) + " iterations";
      result_.converged = rescued();
      break;
    }
    if (!step(rp, rd, mu0, V, d)) {
      result_.converged = rescued();
      break;
    }
  }
  if (result_.converged) result_.reason.clear();
  result_.u = petsc::gather_to_all(u_.object);
  result_.lambda = lambda_;
  result_.total_seconds = petsc::seconds_since(t_start);
  return result_;
}

}  // namespace

ContactInteriorPointResult solve_contact_interior_point(const SparseMatrix& K_share, const VectorXd& f,
                                                        const std::vector<Index>& fixed, const VectorXd& fixed_values,
                                                        const Eigen::MatrixXd& x, const NodalConstraints& constraints,
                                                        const ContactInteriorPointOptions& options,
                                                        const VectorXd* start, const FollowBounds* follow) {
  const auto t0 = std::chrono::steady_clock::now();
  InteriorPoint ip(K_share, f, fixed, fixed_values, x, constraints, options, start);
  const double setup = petsc::seconds_since(t0);
  ContactInteriorPointResult r = ip.run(follow);
  r.setup_seconds += setup;
  r.total_seconds += setup;
  return r;
}

CoulombInteriorPointResult solve_coulomb_interior_point(const SparseMatrix& K_share, const VectorXd& f,
                                                        const std::vector<Index>& fixed, const VectorXd& fixed_values,
                                                        const Eigen::MatrixXd& x, NodalConstraints constraints,
                                                        double mu, double coulomb_tolerance,
                                                        int max_coulomb_iterations,
                                                        const ContactInteriorPointOptions& options) {
  const VectorXd alpha = constraints.friction_alpha;
  constraints.friction_bound.resize(0);
  constraints.friction_alpha.resize(0);
  CoulombInteriorPointResult c;
  for (;;) {
    c.last = solve_contact_interior_point(K_share, f, fixed, fixed_values, x, constraints, options);
    c.all.iterations += c.last.iterations;
    c.all.krylov_iterations.insert(c.all.krylov_iterations.end(), c.last.krylov_iterations.begin(),
                                   c.last.krylov_iterations.end());
    c.all.setup_seconds += c.last.setup_seconds;
    c.all.krylov_seconds += c.last.krylov_seconds;
    c.all.total_seconds += c.last.total_seconds;
    if (!c.last.converged) return c;
    const VectorXd bound = mu * c.last.lambda.cwiseMax(0.0);
    if (constraints.frictional()) {
      c.bound_change = (bound - constraints.friction_bound).lpNorm<Eigen::Infinity>() / bound.maxCoeff();
      if ((c.converged = c.bound_change <= coulomb_tolerance)) return c;
    }
    if (c.coulomb_iterations == max_coulomb_iterations) return c;
    ++c.coulomb_iterations;
    constraints.friction_bound = bound;
    constraints.friction_alpha = alpha;
  }
}

}  // namespace symcontact
